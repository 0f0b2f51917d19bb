; A laboratory robot moves samples between rooms.  Doors between rooms open
; only to a badge that grants them; sample fridges are sealed, and a badge
; that grants the fridge breaks the seal before the door can be opened.
; Tubes stand in racks, stacked on top of one another: a tube under another
; can be taken only once the one on top is off.
(define (domain laboratory)
  (:requirements :strips :typing :negative-preconditions)
  (:types
    room door badge fridge tube instrument rack - object
    centrifuge analyser - instrument)
  (:predicates
    (robot-at ?r - room)
    (connects ?d - door ?from - room ?to - room)
    (door-locked ?d - door)
    (grants ?b - badge ?d - door)
    (authorises ?b - badge ?f - fridge)
    (fridge-in ?f - fridge ?r - room)
    (sealed ?f - fridge)
    (fridge-open ?f - fridge)
    (badge-at ?b - badge ?r - room)
    (carrying ?b - badge)
    (in-fridge ?t - tube ?f - fridge)
    (rack-in ?k - rack ?r - room)
    (in-rack ?t - tube ?k - rack)
    (stacked-on ?t - tube ?u - tube)
    (top-free ?t - tube)
    (rack-base ?t - tube)
    (holding ?t - tube)
    (gripper-free)
    (instrument-in ?i - instrument ?r - room)
    (loaded ?t - tube ?i - instrument)
    (spun ?t - tube)
    (analysed ?t - tube))

  (:action move
    :parameters (?from - room ?to - room ?d - door)
    :precondition (and (robot-at ?from) (connects ?d ?from ?to) (not (door-locked ?d)))
    :effect (and (robot-at ?to) (not (robot-at ?from))))

  (:action pick-up-badge
    :parameters (?b - badge ?r - room)
    :precondition (and (robot-at ?r) (badge-at ?b ?r))
    :effect (and (carrying ?b) (not (badge-at ?b ?r))))

  (:action swipe-door
    :parameters (?b - badge ?d - door ?from - room ?to - room)
    :precondition (and (robot-at ?from) (connects ?d ?from ?to) (carrying ?b) (grants ?b ?d) (door-locked ?d))
    :effect (not (door-locked ?d)))

  (:action break-seal
    :parameters (?b - badge ?f - fridge ?r - room)
    :precondition (and (robot-at ?r) (fridge-in ?f ?r) (carrying ?b) (authorises ?b ?f) (sealed ?f))
    :effect (not (sealed ?f)))

  (:action open-fridge
    :parameters (?f - fridge ?r - room)
    :precondition (and (robot-at ?r) (fridge-in ?f ?r) (not (sealed ?f)) (not (fridge-open ?f)))
    :effect (fridge-open ?f))

  (:action take-from-fridge
    :parameters (?t - tube ?f - fridge ?r - room)
    :precondition (and (robot-at ?r) (fridge-in ?f ?r) (fridge-open ?f) (in-fridge ?t ?f) (gripper-free))
    :effect (and (holding ?t) (not (in-fridge ?t ?f)) (not (gripper-free))))

  (:action take-from-rack
    :parameters (?t - tube ?k - rack ?r - room)
    :precondition (and (robot-at ?r) (rack-in ?k ?r) (in-rack ?t ?k) (rack-base ?t) (top-free ?t) (gripper-free))
    :effect (and (holding ?t) (not (in-rack ?t ?k)) (not (rack-base ?t)) (not (gripper-free))))

  (:action unstack
    :parameters (?t - tube ?u - tube ?k - rack ?r - room)
    :precondition (and (robot-at ?r) (rack-in ?k ?r) (in-rack ?t ?k) (stacked-on ?t ?u) (top-free ?t) (gripper-free))
    :effect (and (holding ?t) (top-free ?u) (not (stacked-on ?t ?u)) (not (in-rack ?t ?k)) (not (gripper-free))))

  (:action place-in-rack
    :parameters (?t - tube ?k - rack ?r - room)
    :precondition (and (robot-at ?r) (rack-in ?k ?r) (holding ?t))
    :effect (and (in-rack ?t ?k) (rack-base ?t) (top-free ?t) (gripper-free) (not (holding ?t))))

  (:action stack
    :parameters (?t - tube ?u - tube ?k - rack ?r - room)
    :precondition (and (robot-at ?r) (rack-in ?k ?r) (in-rack ?u ?k) (top-free ?u) (holding ?t))
    :effect (and (stacked-on ?t ?u) (in-rack ?t ?k) (top-free ?t) (gripper-free) (not (top-free ?u)) (not (holding ?t))))

  (:action load
    :parameters (?t - tube ?i - instrument ?r - room)
    :precondition (and (robot-at ?r) (instrument-in ?i ?r) (holding ?t))
    :effect (and (loaded ?t ?i) (gripper-free) (not (holding ?t))))

  (:action spin
    :parameters (?t - tube ?c - centrifuge)
    :precondition (and (loaded ?t ?c))
    :effect (spun ?t))

  (:action analyse
    :parameters (?t - tube ?a - analyser)
    :precondition (and (loaded ?t ?a) (spun ?t))
    :effect (analysed ?t))

  (:action unload
    :parameters (?t - tube ?i - instrument ?r - room)
    :precondition (and (robot-at ?r) (instrument-in ?i ?r) (loaded ?t ?i) (gripper-free))
    :effect (and (holding ?t) (not (loaded ?t ?i)) (not (gripper-free))))
)
