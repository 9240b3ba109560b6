; A task whose grounding never ends in reasonable time: 4-ary links over every node
; (80^4 = 40 960 000 reachable actions with the problem beside this file). For the tests
; that a time limit holds while grounding.
(define (domain huge-grounding)
  (:requirements :strips :typing)
  (:types node)
  (:predicates (node ?n - node) (linked ?a ?b ?c ?d - node))
  (:action link
    :parameters (?a ?b ?c ?d - node)
    :precondition (and (node ?a) (node ?b) (node ?c) (node ?d))
    :effect (linked ?a ?b ?c ?d)))
