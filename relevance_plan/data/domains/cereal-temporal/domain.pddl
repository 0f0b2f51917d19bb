; Cereal world with time (PDDL 2.1, written for relevance-plan): the cereal
; world's objects and goal, with durative actions.  Moving takes the static
; (distance ?from ?to) between two places; manipulation takes fixed times.
; The robot must stay at the place (over all) while it works there, and keep
; holding the box or the milk while pouring from it.
(define (domain cereal-temporal)
  (:requirements :strips :typing :negative-preconditions :durative-actions :numeric-fluents)
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

  (:durative-action open-box
    :parameters (?b - cereal ?p - place)
    :duration (= ?duration 2)
    :condition (and (over all (robot-at ?p)) (over all (accessible ?p)) (at start (at ?b ?p)) (over all (at ?b ?p))
                    (at start (clear ?b)) (at start (hand-empty)) (over all (hand-empty)) (at start (sealed ?b)))
    :effect (at end (not (sealed ?b))))

  (:durative-action pour-cereal
    :parameters (?b - cereal ?w - bowl ?p - place)
    :duration (= ?duration 3)
    :condition (and (over all (robot-at ?p)) (over all (accessible ?p)) (at start (holding ?b)) (over all (holding ?b))
                    (at start (not (sealed ?b))) (at start (at ?w ?p)) (over all (at ?w ?p)) (at start (clear ?w))
                    (at start (empty ?w)))
    :effect (and (at start (not (empty ?w))) (at end (has-cereal ?w))))

  (:durative-action add-milk
    :parameters (?m - milk ?w - bowl ?p - place)
    :duration (= ?duration 2)
    :condition (and (over all (robot-at ?p)) (over all (accessible ?p)) (at start (holding ?m)) (over all (holding ?m))
                    (at start (at ?w ?p)) (over all (at ?w ?p)) (at start (clear ?w)) (at start (has-cereal ?w)))
    :effect (at end (has-milk ?w)))

  (:durative-action add-spoon
    :parameters (?s - spoon ?w - bowl ?p - place)
    :duration (= ?duration 1)
    :condition (and (over all (robot-at ?p)) (over all (accessible ?p)) (at start (holding ?s))
                    (at start (at ?w ?p)) (over all (at ?w ?p)) (at start (clear ?w)) (at start (has-milk ?w)))
    :effect (and (at start (not (holding ?s))) (at end (has-spoon ?w)) (at end (hand-empty))))

  (:durative-action serve-cereal
    :parameters (?w - bowl ?h - human ?p - place)
    :duration (= ?duration 2)
    :condition (and (over all (robot-at ?p)) (over all (human-at ?h ?p)) (at start (holding ?w)) (at start (has-spoon ?w)))
    :effect (and (at start (not (holding ?w)))
                 (at end (cereal-served ?h)) (at end (hand-empty))))
)
