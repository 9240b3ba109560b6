; The robot can go s-x-g (human cost 2+2, robot cost 5+5) or s-y-g (human 1+3, robot 1+1).
(define (problem roads-robot)
  (:domain roads)
  (:objects s x y g - place)
  (:init (at s) (road s x) (road x g) (road s y) (road y g)
         (= (road-cost s x) 5) (= (road-cost x g) 5) (= (road-cost s y) 1) (= (road-cost y g) 1))
  (:goal (at g))
  (:metric minimize (total-cost)))
