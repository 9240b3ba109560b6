; Two towers of three, a-b-c and d-e-f: build one tower alternating their blocks.
(define (problem interleave)
  (:domain blocksworld)
  (:objects a b c d e f)
  (:init (handempty) (ontable c) (on b c) (on a b) (clear a)
         (ontable f) (on e f) (on d e) (clear d))
  (:goal (and (on a d) (on d b) (on b e) (on e c) (on c f))))
