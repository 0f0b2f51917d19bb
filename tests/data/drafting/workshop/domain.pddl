; A workshop robot with one gripper fetches tools and uses them.  Things lie on
; benches and shelves, hang on hooks on the walls, or are kept in storage
; (toolboxes, drawers, cabinets) that has to be unlocked with the key that fits
; it and opened before anything can be taken out.  Storage does not move.
(define (domain workshop)
  (:requirements :strips :typing :negative-preconditions)
  (:types
    area hook storage item - object
    toolbox drawer cabinet - storage
    tool key part - item
    wrench screwdriver meter - tool
    bolt - part)
  (:predicates
    (robot-at ?a - area)
    (at ?i - item ?a - area)
    (in ?i - item ?s - storage)
    (on-hook ?i - item ?h - hook)
    (hook-at ?h - hook ?a - area)
    (storage-at ?s - storage ?a - area)
    (locked ?s - storage)
    (open ?s - storage)
    (fits ?k - key ?s - storage)
    (holding ?i - item)
    (hand-empty)
    (mounted ?b - bolt ?a - area)
    (tightened ?b - bolt)
    (tested ?a - area))

  (:action move
    :parameters (?from - area ?to - area)
    :precondition (and (robot-at ?from) (not (robot-at ?to)))
    :effect (and (robot-at ?to) (not (robot-at ?from))))

  (:action pick
    :parameters (?i - item ?a - area)
    :precondition (and (robot-at ?a) (at ?i ?a) (hand-empty))
    :effect (and (holding ?i) (not (at ?i ?a)) (not (hand-empty))))

  (:action put
    :parameters (?i - item ?a - area)
    :precondition (and (robot-at ?a) (holding ?i))
    :effect (and (at ?i ?a) (hand-empty) (not (holding ?i))))

  (:action take-from-hook
    :parameters (?i - item ?h - hook ?a - area)
    :precondition (and (robot-at ?a) (hook-at ?h ?a) (on-hook ?i ?h) (hand-empty))
    :effect (and (holding ?i) (not (on-hook ?i ?h)) (not (hand-empty))))

  (:action hang
    :parameters (?i - item ?h - hook ?a - area)
    :precondition (and (robot-at ?a) (hook-at ?h ?a) (holding ?i))
    :effect (and (on-hook ?i ?h) (hand-empty) (not (holding ?i))))

  (:action unlock
    :parameters (?s - storage ?k - key ?a - area)
    :precondition (and (robot-at ?a) (storage-at ?s ?a) (holding ?k) (fits ?k ?s) (locked ?s))
    :effect (not (locked ?s)))

  (:action lock
    :parameters (?s - storage ?k - key ?a - area)
    :precondition (and (robot-at ?a) (storage-at ?s ?a) (holding ?k) (fits ?k ?s) (not (open ?s)) (not (locked ?s)))
    :effect (locked ?s))

  (:action open
    :parameters (?s - storage ?a - area)
    :precondition (and (robot-at ?a) (storage-at ?s ?a) (not (locked ?s)) (not (open ?s)))
    :effect (open ?s))

  (:action close
    :parameters (?s - storage ?a - area)
    :precondition (and (robot-at ?a) (storage-at ?s ?a) (open ?s))
    :effect (not (open ?s)))

  (:action take-out
    :parameters (?i - item ?s - storage ?a - area)
    :precondition (and (robot-at ?a) (storage-at ?s ?a) (open ?s) (in ?i ?s) (hand-empty))
    :effect (and (holding ?i) (not (in ?i ?s)) (not (hand-empty))))

  (:action put-in
    :parameters (?i - item ?s - storage ?a - area)
    :precondition (and (robot-at ?a) (storage-at ?s ?a) (open ?s) (holding ?i))
    :effect (and (in ?i ?s) (hand-empty) (not (holding ?i))))

  (:action tighten
    :parameters (?b - bolt ?w - wrench ?a - area)
    :precondition (and (robot-at ?a) (mounted ?b ?a) (holding ?w) (not (tightened ?b)))
    :effect (tightened ?b))

  (:action test-circuit
    :parameters (?m - meter ?a - area)
    :precondition (and (robot-at ?a) (holding ?m))
    :effect (tested ?a))
)
