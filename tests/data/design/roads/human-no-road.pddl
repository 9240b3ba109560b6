; The observers believe in no road at all.
(define (problem roads-human-none)
  (:domain roads)
  (:objects s x y g - place)
  (:init (at s))
  (:goal (at g))
  (:metric minimize (total-cost)))
