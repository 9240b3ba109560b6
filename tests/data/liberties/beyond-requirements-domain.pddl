; Requirements declared beyond the fragment but not used, as IPC 2018's
; data-network-opt18-strips (and IPC 2023's labyrinth, ricochet-robots, slitherlink) declare
; :adl: the declaration is accepted, a construct outside the fragment would be refused.
(define (domain beyond-requirements)
  (:requirements :adl :conditional-effects :action-costs)
  (:predicates (at ?p) (link ?a ?b))
  (:functions (total-cost) - number)
  (:action go
    :parameters (?a ?b)
    :precondition (and (at ?a) (link ?a ?b))
    :effect (and (not (at ?a)) (at ?b) (increase (total-cost) 2))))
