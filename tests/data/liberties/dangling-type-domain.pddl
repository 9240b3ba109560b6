; A '- type' with nothing before it types nothing ("a b - place - spot" in the problem), as
; Fast Downward reads it (with a warning). No domain of the IPC collection needs it.
(define (domain dangling-type)
  (:requirements :strips :typing)
  (:types place spot)
  (:predicates (at ?p - place) (link ?a ?b - place))
  (:action go
    :parameters (?a ?b - place)
    :precondition (and (at ?a) (link ?a ?b))
    :effect (and (not (at ?a)) (at ?b))))
