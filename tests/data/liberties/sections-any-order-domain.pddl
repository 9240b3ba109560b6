; Declarations in any order: here the predicates come first and the requirements last, as
; Fast Downward reads them (with a warning). No domain of the IPC collection needs it;
; hand-written domains do.
(define (domain sections-any-order)
  (:predicates (at ?r - robot ?p - place) (link ?a ?b - place))
  (:types robot place)
  (:requirements :strips :typing)
  (:action go
    :parameters (?r - robot ?a ?b - place)
    :precondition (and (at ?r ?a) (link ?a ?b))
    :effect (and (not (at ?r ?a)) (at ?r ?b))))
