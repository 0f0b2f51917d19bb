; Coffee world with time (PDDL 2.1, written for relevance-plan): the coffee
; world's objects and goal, with durative actions.  Moving takes the static
; (distance ?from ?to) between two places; manipulation takes fixed times.
; The robot must stay at the place (over all) while it picks, places, pours,
; stirs or serves, and must keep holding the source while pouring from it.
(define (domain coffee-temporal)
  (:requirements :strips :typing :negative-preconditions :durative-actions :numeric-fluents)
  (:types
    place item human - object
    surface container - place
    ; task roles
    cup coffee-source whitener stirrer - item
    ; optional extras a helpful assistant might bring
    sweetener napkin ice-holder tea drink - item
    ; general kitchenware
    plate bowl cookware utensil cutlery glassware board tray jar linen appliance food cleaning - item)
  (:predicates
    (robot-at ?p - place)
    (at ?i - item ?p - place)
    (on-base ?i - item)
    (on ?x - item ?y - item)
    (clear ?i - item)
    (holding ?i - item)
    (hand-empty)
    (accessible ?p - place)
    (human-at ?h - human ?p - place)
    (empty ?c - cup)
    (has-coffee ?c - cup)
    (has-whitener ?c - cup)
    (stirred ?c - cup)
    (coffee-served ?h - human))
  (:functions
    (distance ?from - place ?to - place) - number)

  (:durative-action move
    :parameters (?from - place ?to - place)
    :duration (= ?duration (distance ?from ?to))
    :condition (at start (robot-at ?from))
    :effect (and (at start (not (robot-at ?from))) (at end (robot-at ?to))))

  (:durative-action open
    :parameters (?c - container)
    :duration (= ?duration 2)
    :condition (and (over all (robot-at ?c)) (at start (hand-empty)) (over all (hand-empty))
                    (at start (not (accessible ?c))))
    :effect (at end (accessible ?c)))

  (:durative-action close
    :parameters (?c - container)
    :duration (= ?duration 2)
    :condition (and (over all (robot-at ?c)) (at start (hand-empty)) (over all (hand-empty)) (at start (accessible ?c)))
    :effect (at end (not (accessible ?c))))

  (:durative-action pick
    :parameters (?i - item ?p - place)
    :duration (= ?duration 2)
    :condition (and (over all (robot-at ?p)) (over all (accessible ?p)) (at start (at ?i ?p)) (at start (on-base ?i))
                    (at start (clear ?i)) (at start (hand-empty)))
    :effect (and (at start (not (hand-empty))) (at start (not (clear ?i)))
                 (at end (holding ?i)) (at end (not (at ?i ?p))) (at end (not (on-base ?i)))))

  (:durative-action put-down
    :parameters (?i - item ?p - place)
    :duration (= ?duration 2)
    :condition (and (over all (robot-at ?p)) (over all (accessible ?p)) (at start (holding ?i)))
    :effect (and (at start (not (holding ?i)))
                 (at end (at ?i ?p)) (at end (on-base ?i)) (at end (clear ?i)) (at end (hand-empty))))

  (:durative-action unstack
    :parameters (?x - item ?y - item ?p - place)
    :duration (= ?duration 2)
    :condition (and (over all (robot-at ?p)) (over all (accessible ?p)) (at start (at ?x ?p)) (at start (on ?x ?y))
                    (at start (clear ?x)) (at start (hand-empty)))
    :effect (and (at start (not (hand-empty))) (at start (not (clear ?x)))
                 (at end (holding ?x)) (at end (clear ?y)) (at end (not (on ?x ?y))) (at end (not (at ?x ?p)))))

  (:durative-action stack
    :parameters (?x - item ?y - item ?p - place)
    :duration (= ?duration 2)
    :condition (and (over all (robot-at ?p)) (over all (accessible ?p)) (at start (holding ?x)) (at start (at ?y ?p))
                    (at start (clear ?y)))
    :effect (and (at start (not (holding ?x))) (at start (not (clear ?y)))
                 (at end (on ?x ?y)) (at end (at ?x ?p)) (at end (clear ?x)) (at end (hand-empty))))

  (:durative-action pour-coffee
    :parameters (?s - coffee-source ?c - cup ?p - place)
    :duration (= ?duration 3)
    :condition (and (over all (robot-at ?p)) (over all (accessible ?p)) (at start (holding ?s)) (over all (holding ?s))
                    (at start (at ?c ?p)) (over all (at ?c ?p)) (at start (clear ?c)) (at start (empty ?c)))
    :effect (and (at start (not (empty ?c))) (at end (has-coffee ?c))))

  (:durative-action add-whitener
    :parameters (?w - whitener ?c - cup ?p - place)
    :duration (= ?duration 2)
    :condition (and (over all (robot-at ?p)) (over all (accessible ?p)) (at start (holding ?w)) (over all (holding ?w))
                    (at start (at ?c ?p)) (over all (at ?c ?p)) (at start (clear ?c)) (at start (has-coffee ?c)))
    :effect (at end (has-whitener ?c)))

  (:durative-action stir
    :parameters (?s - stirrer ?c - cup ?p - place)
    :duration (= ?duration 2)
    :condition (and (over all (robot-at ?p)) (over all (accessible ?p)) (at start (holding ?s)) (over all (holding ?s))
                    (at start (at ?c ?p)) (over all (at ?c ?p)) (at start (clear ?c)) (at start (has-whitener ?c)))
    :effect (at end (stirred ?c)))

  (:durative-action serve-coffee
    :parameters (?c - cup ?h - human ?p - place)
    :duration (= ?duration 2)
    :condition (and (over all (robot-at ?p)) (over all (human-at ?h ?p)) (at start (holding ?c)) (at start (stirred ?c)))
    :effect (and (at start (not (holding ?c)))
                 (at end (coffee-served ?h)) (at end (hand-empty))))
)
