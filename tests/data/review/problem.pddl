(define (problem p) (:domain t)
 (:objects a b c - loc)
 (:init (at a) (conn a b) (conn b c) (conn a c))
 (:goal (at c)))
