(define (problem has-a) (:domain two-ways) (:init (a)) (:goal (g)))
