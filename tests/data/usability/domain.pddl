; Two ways to reach (g): x needs (a), y needs (b). Which facts hold decides which plans exist.
(define (domain two-ways)
  (:requirements :strips)
  (:predicates (a) (b) (g))
  (:action x :parameters () :precondition (a) :effect (g))
  (:action y :parameters () :precondition (b) :effect (g)))
