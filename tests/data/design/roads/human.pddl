; The observers believe in a direct road s-g of cost 1, and cost the others differently.
(define (problem roads-human)
  (:domain roads)
  (:objects s x y g - place)
  (:init (at s) (road s x) (road x g) (road s y) (road y g) (road s g)
         (= (road-cost s x) 2) (= (road-cost x g) 2) (= (road-cost s y) 1) (= (road-cost y g) 3)
         (= (road-cost s g) 1))
  (:goal (at g))
  (:metric minimize (total-cost)))
