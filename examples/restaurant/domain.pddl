; A robot waiter on a grid: it carries a dish from the kitchen to a booth.
; Cells are cXY (column X, row Y). Which cells are connected is in the problems: the robot's
; problems have no passage into the table cells, the observers' problems do.
(define (domain restaurant)
  (:requirements :strips :typing)
  (:types cell item)
  (:predicates (robot-at ?c - cell)
               (connected ?from ?to - cell)
               (item-at ?i - item ?c - cell)
               (holding ?i - item)
               (hand-empty))
  (:action move
    :parameters (?from ?to - cell)
    :precondition (and (robot-at ?from) (connected ?from ?to))
    :effect (and (robot-at ?to) (not (robot-at ?from))))
  (:action pick-up
    :parameters (?i - item ?c - cell)
    :precondition (and (robot-at ?c) (item-at ?i ?c) (hand-empty))
    :effect (and (holding ?i) (not (item-at ?i ?c)) (not (hand-empty))))
  (:action put-down
    :parameters (?i - item ?c - cell)
    :precondition (and (robot-at ?c) (holding ?i))
    :effect (and (item-at ?i ?c) (hand-empty) (not (holding ?i)))))
