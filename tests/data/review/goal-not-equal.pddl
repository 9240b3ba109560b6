; (not (= a a)) never holds: unsolvable.
(define (problem p) (:domain t)
 (:objects a b - loc)
 (:init (at a) (conn a b))
 (:goal (and (at b) (not (= a a)))))
