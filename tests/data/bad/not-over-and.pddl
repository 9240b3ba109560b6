(define (domain d)
  (:requirements :strips :negative-preconditions)
  (:predicates (p ?x))
  (:action a
    :parameters (?x)
    :precondition (not (and (p ?x) (p ?x)))
    :effect (p ?x)))
