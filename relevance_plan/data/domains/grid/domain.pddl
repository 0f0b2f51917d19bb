; Grid with keys and locks, untyped STRIPS (written for relevance-plan).
(define (domain grid)
  (:requirements :strips)
  (:predicates (place ?p) (key ?k) (shape ?s) (conn ?x ?y) (key-shape ?k ?s) (lock-shape ?p ?s)
               (at ?k ?p) (at-robot ?p) (locked ?p) (open ?p) (holding ?k) (arm-empty))
  (:action unlock
    :parameters (?cur ?lock ?k ?s)
    :precondition (and (place ?cur) (place ?lock) (key ?k) (shape ?s) (conn ?cur ?lock)
                       (key-shape ?k ?s) (lock-shape ?lock ?s) (at-robot ?cur) (locked ?lock) (holding ?k))
    :effect (and (open ?lock) (not (locked ?lock))))
  (:action move
    :parameters (?cur ?next)
    :precondition (and (place ?cur) (place ?next) (at-robot ?cur) (conn ?cur ?next) (open ?next))
    :effect (and (at-robot ?next) (not (at-robot ?cur))))
  (:action pickup
    :parameters (?cur ?k)
    :precondition (and (place ?cur) (key ?k) (at-robot ?cur) (at ?k ?cur) (arm-empty))
    :effect (and (holding ?k) (not (at ?k ?cur)) (not (arm-empty))))
  (:action pickup-and-lose
    :parameters (?cur ?new ?old)
    :precondition (and (place ?cur) (key ?new) (key ?old) (at-robot ?cur) (holding ?old) (at ?new ?cur))
    :effect (and (holding ?new) (at ?old ?cur) (not (holding ?old)) (not (at ?new ?cur))))
  (:action putdown
    :parameters (?cur ?k)
    :precondition (and (place ?cur) (key ?k) (at-robot ?cur) (holding ?k))
    :effect (and (arm-empty) (at ?k ?cur) (not (holding ?k)))))
