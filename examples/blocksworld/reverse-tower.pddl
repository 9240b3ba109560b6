; Turn the tower a-b-c-d upside down.
(define (problem reverse-tower)
  (:domain blocksworld)
  (:objects a b c d)
  (:init (handempty) (ontable d) (on c d) (on b c) (on a b) (clear a))
  (:goal (and (on d c) (on c b) (on b a))))
