; Carry the box from c00 to c03; every passage of the 5x5 grid is open.
(define (problem to-c03)
  (:domain warehouse)
  (:objects c00 c01 c02 c03 c10 c11 c12 c13 c20 c21 c22 c23 c30 c31 c32 c33 - cell box - item)
  (:init (robot-at c00) (hand-empty) (item-at box c00)
         (connected c00 c10) (connected c10 c00) (connected c00 c01) (connected c01 c00) (connected c01 c11) (connected c11 c01) (connected c01 c02) (connected c02 c01) (connected c02 c12) (connected c12 c02) (connected c02 c03) (connected c03 c02) (connected c03 c13) (connected c13 c03) (connected c10 c20) (connected c20 c10) (connected c10 c11) (connected c11 c10) (connected c11 c21) (connected c21 c11) (connected c11 c12) (connected c12 c11) (connected c12 c22) (connected c22 c12) (connected c12 c13) (connected c13 c12) (connected c13 c23) (connected c23 c13) (connected c20 c30) (connected c30 c20) (connected c20 c21) (connected c21 c20) (connected c21 c31) (connected c31 c21) (connected c21 c22) (connected c22 c21) (connected c22 c32) (connected c32 c22) (connected c22 c23) (connected c23 c22) (connected c23 c33) (connected c33 c23) (connected c30 c31) (connected c31 c30) (connected c31 c32) (connected c32 c31) (connected c32 c33) (connected c33 c32))
  (:goal (item-at box c03)))
