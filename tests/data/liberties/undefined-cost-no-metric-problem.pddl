; Without the metric every action costs 1 and its cost terms are not read: the road a-c is
; taken although it has no length (Fast Downward would still leave it out).
(define (problem undefined-cost-no-metric-1)
  (:domain undefined-cost)
  (:objects a b c - place)
  (:init (at a) (road a b) (road b c) (road a c)
         (= (length a b) 3) (= (length b c) 4))
  (:goal (at c)))
