; Roads with costs: a robot drives from s to g. Which roads exist and what they cost differ
; between the robot's model and the observers' (see robot.pddl, human.pddl).
(define (domain roads)
  (:requirements :strips :typing :action-costs)
  (:types place)
  (:predicates (at ?p - place) (road ?from ?to - place) (visited ?p - place))
  (:functions (total-cost) - number (road-cost ?from ?to - place) - number)
  (:action drive
    :parameters (?from ?to - place)
    :precondition (and (at ?from) (road ?from ?to))
    :effect (and (at ?to) (not (at ?from)) (visited ?to)
                 (increase (total-cost) (road-cost ?from ?to)))))
