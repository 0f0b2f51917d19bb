; Miconic elevator, untyped STRIPS (written for relevance-plan).
(define (domain miconic)
  (:requirements :strips)
  (:predicates (passenger ?p) (floor ?f) (origin ?p ?f) (destin ?p ?f) (above ?f1 ?f2)
               (boarded ?p) (not-boarded ?p) (served ?p) (lift-at ?f))
  (:action board
    :parameters (?f ?p)
    :precondition (and (floor ?f) (passenger ?p) (lift-at ?f) (origin ?p ?f) (not-boarded ?p))
    :effect (and (boarded ?p) (not (not-boarded ?p))))
  (:action depart
    :parameters (?f ?p)
    :precondition (and (floor ?f) (passenger ?p) (lift-at ?f) (destin ?p ?f) (boarded ?p))
    :effect (and (not (boarded ?p)) (served ?p)))
  (:action up
    :parameters (?f1 ?f2)
    :precondition (and (floor ?f1) (floor ?f2) (lift-at ?f1) (above ?f1 ?f2))
    :effect (and (lift-at ?f2) (not (lift-at ?f1))))
  (:action down
    :parameters (?f1 ?f2)
    :precondition (and (floor ?f1) (floor ?f2) (lift-at ?f1) (above ?f2 ?f1))
    :effect (and (lift-at ?f2) (not (lift-at ?f1)))))
