; A robot moving between rooms, with a door that must not be locked (negative precondition),
; typed objects with either, a constant, equality and action costs.
(define (domain tiny)
  (:requirements :strips :typing :negative-preconditions :equality :action-costs)
  (:types room corridor - place
          robot)
  (:constants hub - corridor)
  (:predicates (at ?r - robot ?p - place)
               (connected ?a ?b - place)
               (locked ?p - place)
               (visited ?p - place))
  (:functions (total-cost) - number
              (distance ?a ?b - place) - number)
  (:action move
    :parameters (?r - robot ?from ?to - (either room corridor))
    :precondition (and (at ?r ?from) (connected ?from ?to) (not (locked ?to))
                       (not (= ?from ?to)))
    :effect (and (not (at ?r ?from)) (at ?r ?to) (visited ?to)
                 (increase (total-cost) (distance ?from ?to))))
  (:action unlock
    :parameters (?r - robot ?p - place)
    :precondition (and (at ?r hub) (locked ?p))
    :effect (and (not (locked ?p)) (increase (total-cost) 5))))
