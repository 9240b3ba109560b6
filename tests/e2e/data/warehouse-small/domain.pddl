; A robot carries items between cells of a grid (the restaurant domain of examples/).
(define (domain warehouse)
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
