; A variable written against its predicate's name, as in IPC 2002's Zenotravel
; "(aircraft?a)": the '?' starts a new token.
(define (domain variable-glued)
  (:requirements :strips)
  (:predicates (aircraft ?a) (city ?c) (at ?a ?c))
  (:action fly
    :parameters (?a ?from ?to)
    :precondition (and (aircraft?a) (city?from) (city ?to) (at ?a?from))
    :effect (and (at ?a ?to) (not (at ?a ?from)))))
