(define (problem has-none) (:domain two-ways) (:init) (:goal (g)))
