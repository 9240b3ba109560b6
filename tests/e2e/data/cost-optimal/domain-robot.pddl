; Two ways from n0 to n2: two moves, or one hop over n1. The robot pays as much for both
; (2); people think a hop costs 2.
(define (domain two-ways)
  (:requirements :strips :typing :action-costs)
  (:types node)
  (:predicates (at ?n - node) (conn ?a ?b - node) (far ?a ?b - node))
  (:functions (total-cost) - number)
  (:action move :parameters (?a ?b - node)
    :precondition (and (at ?a) (conn ?a ?b))
    :effect (and (not (at ?a)) (at ?b) (increase (total-cost) 1)))
  (:action hop :parameters (?a ?b - node)
    :precondition (and (at ?a) (far ?a ?b))
    :effect (and (not (at ?a)) (at ?b) (increase (total-cost) 2))))
