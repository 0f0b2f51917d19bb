; Driverlog with time (PDDL 2.1, written for relevance-plan): drivers walk
; along paths and drive trucks along roads to carry packages.  Driving and
; walking take the static times of the road or path; loading, unloading,
; boarding and getting off take fixed times while the truck stays put.
(define (domain driverlog-temporal)
  (:requirements :strips :typing :durative-actions :numeric-fluents)
  (:types
    locatable location - object
    driver truck package - locatable)
  (:predicates
    (at ?x - locatable ?l - location)
    (in ?p - package ?t - truck)
    (driving ?d - driver ?t - truck)
    (empty ?t - truck)
    (road ?from - location ?to - location)
    (path ?from - location ?to - location))
  (:functions
    (drive-time ?from - location ?to - location) - number
    (walk-time ?from - location ?to - location) - number)

  (:durative-action load-truck
    :parameters (?p - package ?t - truck ?l - location)
    :duration (= ?duration 2)
    :condition (and (at start (at ?t ?l)) (over all (at ?t ?l)) (at start (at ?p ?l)))
    :effect (and (at start (not (at ?p ?l))) (at end (in ?p ?t))))

  (:durative-action unload-truck
    :parameters (?p - package ?t - truck ?l - location)
    :duration (= ?duration 2)
    :condition (and (at start (at ?t ?l)) (over all (at ?t ?l)) (at start (in ?p ?t)))
    :effect (and (at start (not (in ?p ?t))) (at end (at ?p ?l))))

  (:durative-action board-truck
    :parameters (?d - driver ?t - truck ?l - location)
    :duration (= ?duration 1)
    :condition (and (at start (at ?t ?l)) (over all (at ?t ?l)) (at start (at ?d ?l)) (at start (empty ?t)))
    :effect (and (at start (not (at ?d ?l))) (at start (not (empty ?t))) (at end (driving ?d ?t))))

  (:durative-action leave-truck
    :parameters (?d - driver ?t - truck ?l - location)
    :duration (= ?duration 1)
    :condition (and (at start (at ?t ?l)) (over all (at ?t ?l)) (at start (driving ?d ?t)))
    :effect (and (at start (not (driving ?d ?t))) (at end (at ?d ?l)) (at end (empty ?t))))

  (:durative-action drive-truck
    :parameters (?t - truck ?from - location ?to - location ?d - driver)
    :duration (= ?duration (drive-time ?from ?to))
    :condition (and (at start (at ?t ?from)) (at start (road ?from ?to)) (over all (driving ?d ?t)))
    :effect (and (at start (not (at ?t ?from))) (at end (at ?t ?to))))

  (:durative-action walk
    :parameters (?d - driver ?from - location ?to - location)
    :duration (= ?duration (walk-time ?from ?to))
    :condition (and (at start (at ?d ?from)) (at start (path ?from ?to)))
    :effect (and (at start (not (at ?d ?from))) (at end (at ?d ?to))))
)
