; Ferry, untyped STRIPS: types are static unary predicates (written for relevance-plan).
(define (domain ferry)
  (:requirements :strips)
  (:predicates (car ?c) (location ?l) (not-eq ?x ?y) (at-ferry ?l) (at ?c ?l) (empty-ferry) (on ?c))
  (:action sail
    :parameters (?from ?to)
    :precondition (and (location ?from) (location ?to) (not-eq ?from ?to) (at-ferry ?from))
    :effect (and (at-ferry ?to) (not (at-ferry ?from))))
  (:action board
    :parameters (?c ?l)
    :precondition (and (car ?c) (location ?l) (at ?c ?l) (at-ferry ?l) (empty-ferry))
    :effect (and (on ?c) (not (at ?c ?l)) (not (empty-ferry))))
  (:action debark
    :parameters (?c ?l)
    :precondition (and (car ?c) (location ?l) (on ?c) (at-ferry ?l))
    :effect (and (at ?c ?l) (empty-ferry) (not (on ?c)))))
