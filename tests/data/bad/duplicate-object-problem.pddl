(define (problem pr)
  (:domain d)
  (:objects o1 o2
            o1)
  (:init (p o1))
  (:goal (not (p o1))))
