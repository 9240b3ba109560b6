; Crate c1 sits on c2 in area a1; the goal puts c2 on area a2: move c1 away, then c2 (2 steps).
(define (problem type-listed-twice-1)
  (:domain type-listed-twice)
  (:objects h - hoist a1 a2 a3 - area c1 c2 - crate)
  (:init (free h) (on c2 a1) (on c1 c2) (clear c1) (clear a2) (clear a3))
  (:goal (on c2 a2)))
