; Move the tower a-b-c from e onto d, keeping its order.
(define (problem move-tower)
  (:domain blocksworld)
  (:objects a b c d e)
  (:init (handempty) (ontable e) (on c e) (on b c) (on a b) (clear a) (ontable d) (clear d))
  (:goal (and (on a b) (on b c) (on c d))))
