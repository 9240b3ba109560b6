; A predicate declared twice alike, as Fast Downward reads it (declared twice otherwise is
; refused: which one is meant would be a guess). No domain of the IPC collection needs it;
; domains put together from pieces do.
(define (domain predicate-declared-twice)
  (:requirements :strips)
  (:predicates (at ?p) (link ?a ?b) (at ?q))
  (:action go
    :parameters (?a ?b)
    :precondition (and (at ?a) (link ?a ?b))
    :effect (and (not (at ?a)) (at ?b))))
