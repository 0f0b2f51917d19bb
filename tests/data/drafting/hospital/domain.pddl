; A hospital supply robot brings supplies to nurses.  Supplies are kept in
; locked medicine cabinets (a keycard opens each) or in taped boxes stacked on
; shelves: a box is taken from the top of its stack, put on the floor and cut
; open with a cutter before anything comes out of it.
(define (domain hospital)
  (:requirements :strips :typing :negative-preconditions)
  (:types
    room shelf cabinet keycard box supply nurse - object
    cutter medicine dressing - supply)
  (:predicates
    (robot-at ?r - room)
    (adjacent ?r - room ?s - room)
    (shelf-in ?s - shelf ?r - room)
    (cabinet-in ?c - cabinet ?r - room)
    (cabinet-locked ?c - cabinet)
    (opens ?k - keycard ?c - cabinet)
    (keycard-at ?k - keycard ?r - room)
    (carrying ?k - keycard)
    (on-shelf ?b - box ?s - shelf)
    (box-on ?b - box ?c - box)
    (box-clear ?b - box)
    (box-at ?b - box ?r - room)
    (taped ?b - box)
    (in-box ?i - supply ?b - box)
    (in-cabinet ?i - supply ?c - cabinet)
    (supply-at ?i - supply ?r - room)
    (holding-box ?b - box)
    (holding ?i - supply)
    (hands-free)
    (nurse-at ?n - nurse ?r - room)
    (handed ?i - supply ?n - nurse))

  (:action move
    :parameters (?from - room ?to - room)
    :precondition (and (robot-at ?from) (adjacent ?from ?to))
    :effect (and (robot-at ?to) (not (robot-at ?from))))

  (:action pick-up-keycard
    :parameters (?k - keycard ?r - room)
    :precondition (and (robot-at ?r) (keycard-at ?k ?r))
    :effect (and (carrying ?k) (not (keycard-at ?k ?r))))

  (:action unlock-cabinet
    :parameters (?c - cabinet ?k - keycard ?r - room)
    :precondition (and (robot-at ?r) (cabinet-in ?c ?r) (carrying ?k) (opens ?k ?c) (cabinet-locked ?c))
    :effect (not (cabinet-locked ?c)))

  (:action take-from-cabinet
    :parameters (?i - supply ?c - cabinet ?r - room)
    :precondition (and (robot-at ?r) (cabinet-in ?c ?r) (not (cabinet-locked ?c)) (in-cabinet ?i ?c) (hands-free))
    :effect (and (holding ?i) (not (in-cabinet ?i ?c)) (not (hands-free))))

  (:action take-box
    :parameters (?b - box ?s - shelf ?r - room)
    :precondition (and (robot-at ?r) (shelf-in ?s ?r) (on-shelf ?b ?s) (box-clear ?b) (hands-free))
    :effect (and (holding-box ?b) (not (on-shelf ?b ?s)) (not (hands-free))))

  (:action unstack-box
    :parameters (?b - box ?c - box ?s - shelf ?r - room)
    :precondition (and (robot-at ?r) (shelf-in ?s ?r) (box-on ?b ?c) (on-shelf ?c ?s) (box-clear ?b) (hands-free))
    :effect (and (holding-box ?b) (box-clear ?c) (not (box-on ?b ?c)) (not (hands-free))))

  (:action set-box-down
    :parameters (?b - box ?r - room)
    :precondition (and (robot-at ?r) (holding-box ?b))
    :effect (and (box-at ?b ?r) (hands-free) (not (holding-box ?b))))

  (:action cut-tape
    :parameters (?b - box ?t - cutter ?r - room)
    :precondition (and (robot-at ?r) (box-at ?b ?r) (holding ?t) (taped ?b))
    :effect (not (taped ?b)))

  (:action take-from-box
    :parameters (?i - supply ?b - box ?r - room)
    :precondition (and (robot-at ?r) (box-at ?b ?r) (not (taped ?b)) (in-box ?i ?b) (hands-free))
    :effect (and (holding ?i) (not (in-box ?i ?b)) (not (hands-free))))

  (:action pick-up
    :parameters (?i - supply ?r - room)
    :precondition (and (robot-at ?r) (supply-at ?i ?r) (hands-free))
    :effect (and (holding ?i) (not (supply-at ?i ?r)) (not (hands-free))))

  (:action put-down
    :parameters (?i - supply ?r - room)
    :precondition (and (robot-at ?r) (holding ?i))
    :effect (and (supply-at ?i ?r) (hands-free) (not (holding ?i))))

  (:action hand-over
    :parameters (?i - supply ?n - nurse ?r - room)
    :precondition (and (robot-at ?r) (nurse-at ?n ?r) (holding ?i))
    :effect (and (handed ?i ?n) (hands-free) (not (holding ?i))))
)
