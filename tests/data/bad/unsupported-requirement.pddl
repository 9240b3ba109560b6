(define (domain d)
  (:requirements :strips :durative-actions)
  (:predicates (p ?x))
  (:action a
    :parameters (?x)
    :precondition (p ?x)
    :effect (not (p ?x))))
