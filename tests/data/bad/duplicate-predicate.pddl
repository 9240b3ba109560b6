(define (domain d)
  (:requirements :strips)
  (:predicates (p ?x)
               (p ?x ?y))
  (:action a
    :parameters (?x)
    :precondition (p ?x)
    :effect (not (p ?x))))
