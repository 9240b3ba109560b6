(define (domain d)
  (:requirements :strips)
  (:predicates (p ?x)
               (p ?y))
  (:action a
    :parameters (?x)
    :precondition (p ?x)
    :effect (not (p ?x))))
