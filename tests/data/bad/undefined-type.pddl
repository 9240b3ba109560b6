(define (domain d)
  (:requirements :strips :typing)
  (:types block)
  (:predicates (p ?x - blok))
  (:action a
    :parameters (?x - block)
    :precondition (p ?x)
    :effect (not (p ?x))))
