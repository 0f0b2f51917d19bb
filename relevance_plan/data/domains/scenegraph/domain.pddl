; 3D scene graph world (written for relevance-plan): an agent moves between
; connected places (navigation nodes) inside a room and between rooms
; through doors, opens doors and receptacles (fridges, cabinets, drawers),
; and picks and places items in or on receptacles, one at a time.
(define (domain scenegraph)
  (:requirements :strips :typing)
  (:types agent room place door receptacle item - object)
  (:predicates
    (agent-at ?a - agent ?p - place)
    (in-room ?p - place ?r - room)
    (connected ?from - place ?to - place)
    (door-between ?d - door ?from - place ?to - place)
    (door-open ?d - door)
    (door-closed ?d - door)
    (receptacle-at ?r - receptacle ?p - place)
    (openable ?r - receptacle)
    (opened ?r - receptacle)
    (closed ?r - receptacle)
    (in ?i - item ?r - receptacle)
    (holding ?a - agent ?i - item)
    (hand-free ?a - agent))

  (:action move
    :parameters (?a - agent ?from - place ?to - place ?r - room)
    :precondition (and (agent-at ?a ?from) (connected ?from ?to) (in-room ?from ?r) (in-room ?to ?r))
    :effect (and (agent-at ?a ?to) (not (agent-at ?a ?from))))

  (:action go-through
    :parameters (?a - agent ?d - door ?from - place ?to - place)
    :precondition (and (agent-at ?a ?from) (door-between ?d ?from ?to) (door-open ?d))
    :effect (and (agent-at ?a ?to) (not (agent-at ?a ?from))))

  (:action open-door
    :parameters (?a - agent ?d - door ?from - place ?to - place)
    :precondition (and (agent-at ?a ?from) (door-between ?d ?from ?to) (door-closed ?d) (hand-free ?a))
    :effect (and (door-open ?d) (not (door-closed ?d))))

  (:action open
    :parameters (?a - agent ?r - receptacle ?p - place)
    :precondition (and (agent-at ?a ?p) (receptacle-at ?r ?p) (openable ?r) (closed ?r) (hand-free ?a))
    :effect (and (opened ?r) (not (closed ?r))))

  (:action close
    :parameters (?a - agent ?r - receptacle ?p - place)
    :precondition (and (agent-at ?a ?p) (receptacle-at ?r ?p) (openable ?r) (opened ?r) (hand-free ?a))
    :effect (and (closed ?r) (not (opened ?r))))

  (:action pick
    :parameters (?a - agent ?i - item ?r - receptacle ?p - place)
    :precondition (and (agent-at ?a ?p) (receptacle-at ?r ?p) (opened ?r) (in ?i ?r) (hand-free ?a))
    :effect (and (holding ?a ?i) (not (in ?i ?r)) (not (hand-free ?a))))

  (:action place
    :parameters (?a - agent ?i - item ?r - receptacle ?p - place)
    :precondition (and (agent-at ?a ?p) (receptacle-at ?r ?p) (opened ?r) (holding ?a ?i))
    :effect (and (in ?i ?r) (hand-free ?a) (not (holding ?a ?i))))
)
