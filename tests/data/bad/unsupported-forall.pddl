(define (domain d)
  (:requirements :strips)
  (:predicates (p ?x))
  (:action a
    :parameters (?x)
    :precondition (forall (?y) (p ?y))
    :effect (not (p ?x))))
