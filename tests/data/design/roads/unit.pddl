; The human's model without a metric: every action costs 1.
(define (problem roads-unit)
  (:domain roads)
  (:objects s x y g - place)
  (:init (at s) (road s x) (road x g) (road s y) (road y g) (road s g))
  (:goal (at g)))
