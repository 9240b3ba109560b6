; A type listed twice, as in IPC 2006's Storage ("area - object", then "area crate -
; surface"): its parent is the more specific one, surface.
(define (domain type-listed-twice)
  (:requirements :typing)
  (:types hoist surface area - object
          area crate - surface)
  (:predicates (clear ?s - surface) (on ?c - crate ?s - surface) (free ?h - hoist))
  (:action stack
    :parameters (?h - hoist ?c - crate ?from - surface ?to - surface)
    :precondition (and (free ?h) (on ?c ?from) (clear ?c) (clear ?to))
    :effect (and (on ?c ?to) (not (on ?c ?from)) (clear ?from) (not (clear ?to)))))
