; Zenotravel with fuel (numeric fluents, written for relevance-plan): aircraft
; carry people between cities.  Flying slowly burns (slow-burn ?a) fuel per
; unit of distance, flying fast burns (fast-burn ?a) and is allowed with at
; most (zoom-limit ?a) people on board; refuel fills the tank to
; (capacity ?a).  The metric is the fuel used.
(define (domain zenotravel-numeric)
  (:requirements :strips :typing :numeric-fluents)
  (:types
    locatable city - object
    aircraft person - locatable)
  (:predicates
    (at ?x - locatable ?c - city)
    (in ?p - person ?a - aircraft))
  (:functions
    (fuel ?a - aircraft) - number
    (capacity ?a - aircraft) - number
    (slow-burn ?a - aircraft) - number
    (fast-burn ?a - aircraft) - number
    (onboard ?a - aircraft) - number
    (zoom-limit ?a - aircraft) - number
    (distance ?from - city ?to - city) - number
    (total-fuel-used) - number)

  (:action board
    :parameters (?p - person ?a - aircraft ?c - city)
    :precondition (and (at ?p ?c) (at ?a ?c))
    :effect (and (in ?p ?a) (not (at ?p ?c)) (increase (onboard ?a) 1)))

  (:action debark
    :parameters (?p - person ?a - aircraft ?c - city)
    :precondition (and (in ?p ?a) (at ?a ?c))
    :effect (and (at ?p ?c) (not (in ?p ?a)) (decrease (onboard ?a) 1)))

  (:action fly-slow
    :parameters (?a - aircraft ?from - city ?to - city)
    :precondition (and (at ?a ?from) (>= (fuel ?a) (* (distance ?from ?to) (slow-burn ?a))))
    :effect (and (at ?a ?to) (not (at ?a ?from))
                 (decrease (fuel ?a) (* (distance ?from ?to) (slow-burn ?a)))
                 (increase (total-fuel-used) (* (distance ?from ?to) (slow-burn ?a)))))

  (:action fly-fast
    :parameters (?a - aircraft ?from - city ?to - city)
    :precondition (and (at ?a ?from) (>= (fuel ?a) (* (distance ?from ?to) (fast-burn ?a)))
                       (<= (onboard ?a) (zoom-limit ?a)))
    :effect (and (at ?a ?to) (not (at ?a ?from))
                 (decrease (fuel ?a) (* (distance ?from ?to) (fast-burn ?a)))
                 (increase (total-fuel-used) (* (distance ?from ?to) (fast-burn ?a)))))

  (:action refuel
    :parameters (?a - aircraft ?c - city)
    :precondition (and (at ?a ?c) (< (fuel ?a) (capacity ?a)))
    :effect (assign (fuel ?a) (capacity ?a)))
)
