; Serve the dish at booth G1 (c12); the robot's model: no passage into a table cell.
(define (problem serve-g1)
  (:domain restaurant)
  (:objects c00 c01 c02 c10 c11 c12 c20 c21 c22 - cell dish - item)
  (:init (robot-at c00) (hand-empty) (item-at dish c00)
         (connected c00 c10) (connected c02 c12) (connected c10 c20) (connected c10 c00)
         (connected c12 c22) (connected c12 c02) (connected c20 c10) (connected c20 c21)
         (connected c21 c22) (connected c21 c20) (connected c22 c12) (connected c22 c21))
  (:goal (item-at dish c12)))
