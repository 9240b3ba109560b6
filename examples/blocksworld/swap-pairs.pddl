; Two towers of two: swap the top blocks.
(define (problem swap-pairs)
  (:domain blocksworld)
  (:objects a b c d)
  (:init (handempty) (ontable b) (on a b) (clear a) (ontable d) (on c d) (clear c))
  (:goal (and (on c b) (on a d))))
