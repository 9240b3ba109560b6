; The robot reaches g only by a road the observers do not believe in: no plan fits both.
(define (problem roads-robot-only)
  (:domain roads)
  (:objects s x y g - place)
  (:init (at s) (road s g) (= (road-cost s g) 1))
  (:goal (at g))
  (:metric minimize (total-cost)))
