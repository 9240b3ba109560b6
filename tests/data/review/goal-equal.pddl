; (= a a) holds, so the goal is (at b) alone: one move.
(define (problem p) (:domain t)
 (:objects a b - loc)
 (:init (at a) (conn a b))
 (:goal (and (at b) (= a a))))
