; The problem lists atoms as false and one value twice, as Fast Downward reads it: the
; closed world makes the false ones redundant, and the same value twice is harmless. No
; domain of the IPC collection needs it; generated problems do.
(define (domain init-listed-false)
  (:requirements :strips :negative-preconditions :action-costs)
  (:predicates (on ?l) (off ?l))
  (:functions (total-cost) - number (switch-cost ?l) - number)
  (:action switch-on
    :parameters (?l)
    :precondition (not (on ?l))
    :effect (and (on ?l) (increase (total-cost) (switch-cost ?l)))))
