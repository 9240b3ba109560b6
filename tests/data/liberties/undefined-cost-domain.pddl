; An action instance whose cost refers to a value the problem does not give is not
; applicable (PDDL 2.1's semantics of an undefined value; Fast Downward leaves such instances
; out): the direct road a-c below has no length, so the plan takes the long way.
(define (domain undefined-cost)
  (:requirements :strips :typing :action-costs)
  (:types place)
  (:predicates (at ?p - place) (road ?a ?b - place))
  (:functions (total-cost) - number (length ?a ?b - place) - number)
  (:action drive
    :parameters (?a ?b - place)
    :precondition (and (at ?a) (road ?a ?b))
    :effect (and (not (at ?a)) (at ?b) (increase (total-cost) (length ?a ?b)))))
