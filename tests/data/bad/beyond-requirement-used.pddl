(define (domain d)
  (:requirements :adl)
  (:predicates (p ?x))
  (:action a
    :parameters (?x)
    :precondition (p ?x)
    :effect (when (p ?x) (not (p ?x)))))
