; Cereal world: the robot opens the cabinet, takes a cereal box, opens it,
; pours cereal into a bowl, adds milk, puts a spoon in, serves the bowl to the
; human and returns the cereal and the milk to where they were.  Every item can
; be picked, placed and stacked on any other item.
(define (domain cereal)
  (:requirements :strips :typing :negative-preconditions)
  (:types
    place item human - object
    surface container - place
    ; task roles
    bowl cereal milk spoon - item
    ; optional extras a helpful assistant might bring
    napkin sweetener fruit cup - item
    ; general kitchenware
    plate cookware utensil cutlery glassware board tray jar linen appliance food cleaning - item)
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
    (sealed ?b - cereal)
    (empty ?b - bowl)
    (has-cereal ?b - bowl)
    (has-milk ?b - bowl)
    (has-spoon ?b - bowl)
    (cereal-served ?h - human))

  (:action move
    :parameters (?from - place ?to - place)
    :precondition (and (robot-at ?from) (not (robot-at ?to)))
    :effect (and (robot-at ?to) (not (robot-at ?from))))

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

  (:action open-box
    :parameters (?b - cereal ?p - place)
    :precondition (and (robot-at ?p) (accessible ?p) (at ?b ?p) (clear ?b) (hand-empty) (sealed ?b))
    :effect (not (sealed ?b)))

  (:action pour-cereal
    :parameters (?b - cereal ?w - bowl ?p - place)
    :precondition (and (robot-at ?p) (accessible ?p) (holding ?b) (not (sealed ?b)) (at ?w ?p) (clear ?w) (empty ?w))
    :effect (and (has-cereal ?w) (not (empty ?w))))

  (:action add-milk
    :parameters (?m - milk ?w - bowl ?p - place)
    :precondition (and (robot-at ?p) (accessible ?p) (holding ?m) (at ?w ?p) (clear ?w) (has-cereal ?w))
    :effect (has-milk ?w))

  (:action add-spoon
    :parameters (?s - spoon ?w - bowl ?p - place)
    :precondition (and (robot-at ?p) (accessible ?p) (holding ?s) (at ?w ?p) (clear ?w) (has-milk ?w))
    :effect (and (has-spoon ?w) (hand-empty) (not (holding ?s))))

  (:action serve-cereal
    :parameters (?w - bowl ?h - human ?p - place)
    :precondition (and (robot-at ?p) (human-at ?h ?p) (holding ?w) (has-spoon ?w))
    :effect (and (cereal-served ?h) (hand-empty) (not (holding ?w))))
)
