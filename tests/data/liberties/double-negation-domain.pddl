; (not (not L)) is L in a condition, as Fast Downward's translator reads conditions
; (negation normal form). No domain of the IPC collection needs it; hand-written domains do.
(define (domain double-negation)
  (:requirements :strips :negative-preconditions)
  (:predicates (done ?x) (ready ?x))
  (:action finish
    :parameters (?x)
    :precondition (and (not (not (and (ready ?x)))) (not (not (not (done ?x)))))
    :effect (and (done ?x) (not (ready ?x)))))
