; (p o1) can only be deleted, never added: the goal is unreachable.
(define (problem unsolvable)
  (:domain d)
  (:objects o1 o2)
  (:init (p o2))
  (:goal (p o1)))
