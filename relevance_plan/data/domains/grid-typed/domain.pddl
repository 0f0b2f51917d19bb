; Grid with keys and locks, typed (written for relevance-plan).
(define (domain grid-typed)
  (:requirements :strips :typing)
  (:types place key shape)
  (:predicates (conn ?x ?y - place) (key-shape ?k - key ?s - shape) (lock-shape ?p - place ?s - shape)
               (at ?k - key ?p - place) (at-robot ?p - place) (locked ?p - place) (open ?p - place)
               (holding ?k - key) (arm-empty))
  (:action unlock
    :parameters (?cur ?lock - place ?k - key ?s - shape)
    :precondition (and (conn ?cur ?lock) (key-shape ?k ?s) (lock-shape ?lock ?s) (at-robot ?cur) (locked ?lock) (holding ?k))
    :effect (and (open ?lock) (not (locked ?lock))))
  (:action move
    :parameters (?cur ?next - place)
    :precondition (and (at-robot ?cur) (conn ?cur ?next) (open ?next))
    :effect (and (at-robot ?next) (not (at-robot ?cur))))
  (:action pickup
    :parameters (?cur - place ?k - key)
    :precondition (and (at-robot ?cur) (at ?k ?cur) (arm-empty))
    :effect (and (holding ?k) (not (at ?k ?cur)) (not (arm-empty))))
  (:action pickup-and-lose
    :parameters (?cur - place ?new ?old - key)
    :precondition (and (at-robot ?cur) (holding ?old) (at ?new ?cur))
    :effect (and (holding ?new) (at ?old ?cur) (not (holding ?old)) (not (at ?new ?cur))))
  (:action putdown
    :parameters (?cur - place ?k - key)
    :precondition (and (at-robot ?cur) (holding ?k))
    :effect (and (arm-empty) (at ?k ?cur) (not (holding ?k)))))
