; Coffee world with a battery (numeric fluents, written for relevance-plan):
; the coffee world's objects and goal; a move needs and uses (distance ?from
; ?to) units of (battery), and recharge at a dock fills it to
; (battery-capacity).
(define (domain coffee-numeric)
  (:requirements :strips :typing :negative-preconditions :numeric-fluents)
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
    (dock ?p - place)
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
    (battery) - number
    (battery-capacity) - number
    (distance ?from - place ?to - place) - number)

  (:action move
    :parameters (?from - place ?to - place)
    :precondition (and (robot-at ?from) (not (robot-at ?to)) (>= (battery) (distance ?from ?to)))
    :effect (and (robot-at ?to) (not (robot-at ?from)) (decrease (battery) (distance ?from ?to))))

  (:action recharge
    :parameters (?p - place)
    :precondition (and (robot-at ?p) (dock ?p) (< (battery) (battery-capacity)))
    :effect (assign (battery) (battery-capacity)))

  (:action open
    :parameters (?c - container)
    :precondition (and (robot-at ?c) (hand-empty) (not (accessible ?c)))
    :effect (accessible ?c))

  (:action close
    :parameters (?c - container)
    :precondition (and (robot-at ?c) (hand-empty) (accessible ?c))
    :effect (not (accessible ?c)))

  (:action pick
    :parameters (?i - item ?p - place)
    :precondition (and (robot-at ?p) (accessible ?p) (at ?i ?p) (on-base ?i) (clear ?i) (hand-empty))
    :effect (and (holding ?i) (not (at ?i ?p)) (not (on-base ?i)) (not (clear ?i)) (not (hand-empty))))

  (:action put-down
    :parameters (?i - item ?p - place)
    :precondition (and (robot-at ?p) (accessible ?p) (holding ?i))
    :effect (and (at ?i ?p) (on-base ?i) (clear ?i) (hand-empty) (not (holding ?i))))

  (:action unstack
    :parameters (?x - item ?y - item ?p - place)
    :precondition (and (robot-at ?p) (accessible ?p) (at ?x ?p) (on ?x ?y) (clear ?x) (hand-empty))
    :effect (and (holding ?x) (clear ?y) (not (on ?x ?y)) (not (at ?x ?p)) (not (clear ?x)) (not (hand-empty))))

  (:action stack
    :parameters (?x - item ?y - item ?p - place)
    :precondition (and (robot-at ?p) (accessible ?p) (holding ?x) (at ?y ?p) (clear ?y))
    :effect (and (on ?x ?y) (at ?x ?p) (clear ?x) (hand-empty) (not (holding ?x)) (not (clear ?y))))

  (:action pour-coffee
    :parameters (?s - coffee-source ?c - cup ?p - place)
    :precondition (and (robot-at ?p) (accessible ?p) (holding ?s) (at ?c ?p) (clear ?c) (empty ?c))
    :effect (and (has-coffee ?c) (not (empty ?c))))

  (:action add-whitener
    :parameters (?w - whitener ?c - cup ?p - place)
    :precondition (and (robot-at ?p) (accessible ?p) (holding ?w) (at ?c ?p) (clear ?c) (has-coffee ?c))
    :effect (has-whitener ?c))

  (:action stir
    :parameters (?s - stirrer ?c - cup ?p - place)
    :precondition (and (robot-at ?p) (accessible ?p) (holding ?s) (at ?c ?p) (clear ?c) (has-whitener ?c))
    :effect (stirred ?c))

  (:action serve-coffee
    :parameters (?c - cup ?h - human ?p - place)
    :precondition (and (robot-at ?p) (human-at ?h ?p) (holding ?c) (stirred ?c))
    :effect (and (coffee-served ?h) (hand-empty) (not (holding ?c))))
)
