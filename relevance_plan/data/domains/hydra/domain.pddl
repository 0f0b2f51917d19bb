; A robot in a 3D scene graph (written for relevance-plan's scene-graph import): the graph's places
; are where it can stand, its place edges the ways between them, its rooms hold the places, and its
; objects stand at places.  A class says what an object affords: picked up, something put on it,
; something put in it (after opening it, when it opens).  Goals name objects, or classes: any object
; of a class on any object of another class, or in any room of a class (Taskography's class goals).
(define (domain hydra-scene-graph)
  (:requirements :strips :typing)
  (:types agent place room thing class - object)
  (:predicates
    (agent-at ?a - agent ?p - place)
    (hand-free ?a - agent)
    (holding ?a - agent ?t - thing)
    (connected ?from - place ?to - place)
    (in-room ?p - place ?r - room)
    (room-is ?r - room ?k - class)
    (is-a ?t - thing ?k - class)
    (at ?t - thing ?p - place)
    (loose ?t - thing)
    (pickable ?t - thing)
    (supports ?t - thing)
    (holds-inside ?t - thing)
    (openable ?t - thing)
    (opened ?t - thing)
    (closed ?t - thing)
    (on ?t - thing ?s - thing)
    (inside ?t - thing ?s - thing)
    (class-on ?k - class ?l - class)
    (class-inside ?k - class ?l - class)
    (class-in-room ?k - class ?l - class))

  (:action move
    :parameters (?a - agent ?from - place ?to - place)
    :precondition (and (agent-at ?a ?from) (connected ?from ?to))
    :effect (and (agent-at ?a ?to) (not (agent-at ?a ?from))))

  (:action open
    :parameters (?a - agent ?s - thing ?p - place)
    :precondition (and (agent-at ?a ?p) (at ?s ?p) (openable ?s) (closed ?s) (hand-free ?a))
    :effect (and (opened ?s) (not (closed ?s))))

  (:action close
    :parameters (?a - agent ?s - thing ?p - place)
    :precondition (and (agent-at ?a ?p) (at ?s ?p) (openable ?s) (opened ?s) (hand-free ?a))
    :effect (and (closed ?s) (not (opened ?s))))

  ; Picking a thing up undoes the class goals it met where it was (as Taskography's domains do).
  (:action pick-up
    :parameters (?a - agent ?t - thing ?p - place ?r - room ?k - class ?l - class)
    :precondition (and (agent-at ?a ?p) (at ?t ?p) (loose ?t) (pickable ?t) (hand-free ?a)
                       (in-room ?p ?r) (room-is ?r ?l) (is-a ?t ?k))
    :effect (and (holding ?a ?t) (not (at ?t ?p)) (not (loose ?t)) (not (hand-free ?a))
                 (not (class-in-room ?k ?l))))

  (:action pick-from
    :parameters (?a - agent ?t - thing ?s - thing ?p - place ?r - room ?k - class ?l - class ?m - class)
    :precondition (and (agent-at ?a ?p) (at ?t ?p) (on ?t ?s) (pickable ?t) (hand-free ?a)
                       (is-a ?t ?k) (is-a ?s ?l) (in-room ?p ?r) (room-is ?r ?m))
    :effect (and (holding ?a ?t) (not (at ?t ?p)) (not (on ?t ?s)) (not (hand-free ?a))
                 (not (class-on ?k ?l)) (not (class-in-room ?k ?m))))

  (:action take-out
    :parameters (?a - agent ?t - thing ?s - thing ?p - place ?r - room ?k - class ?l - class ?m - class)
    :precondition (and (agent-at ?a ?p) (at ?t ?p) (inside ?t ?s) (opened ?s) (pickable ?t) (hand-free ?a)
                       (is-a ?t ?k) (is-a ?s ?l) (in-room ?p ?r) (room-is ?r ?m))
    :effect (and (holding ?a ?t) (not (at ?t ?p)) (not (inside ?t ?s)) (not (hand-free ?a))
                 (not (class-inside ?k ?l)) (not (class-in-room ?k ?m))))

  (:action put-down
    :parameters (?a - agent ?t - thing ?p - place ?r - room ?k - class ?l - class)
    :precondition (and (agent-at ?a ?p) (holding ?a ?t) (in-room ?p ?r) (room-is ?r ?l) (is-a ?t ?k))
    :effect (and (at ?t ?p) (loose ?t) (hand-free ?a) (not (holding ?a ?t)) (class-in-room ?k ?l)))

  ; Put on or in something, a thing is in that thing's room too.
  (:action put-on
    :parameters (?a - agent ?t - thing ?s - thing ?p - place ?r - room ?k - class ?l - class ?m - class)
    :precondition (and (agent-at ?a ?p) (holding ?a ?t) (at ?s ?p) (supports ?s)
                       (is-a ?t ?k) (is-a ?s ?l) (in-room ?p ?r) (room-is ?r ?m))
    :effect (and (at ?t ?p) (on ?t ?s) (hand-free ?a) (not (holding ?a ?t))
                 (class-on ?k ?l) (class-in-room ?k ?m)))

  (:action put-in
    :parameters (?a - agent ?t - thing ?s - thing ?p - place ?r - room ?k - class ?l - class ?m - class)
    :precondition (and (agent-at ?a ?p) (holding ?a ?t) (at ?s ?p) (holds-inside ?s) (opened ?s)
                       (is-a ?t ?k) (is-a ?s ?l) (in-room ?p ?r) (room-is ?r ?m))
    :effect (and (at ?t ?p) (inside ?t ?s) (hand-free ?a) (not (holding ?a ?t))
                 (class-inside ?k ?l) (class-in-room ?k ?m)))
)
