(define (problem has-b) (:domain two-ways) (:init (b)) (:goal (g)))
