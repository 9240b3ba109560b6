#!/usr/bin/env python3
"""Generates the design problems of the paper's IPC evaluation (Section VI, Table 1).

  python3 tests/benchmarks/paper/generate_design_problems.py [--ipc ../shared/benchmarks/ipc]
                                                            [--out tests/data/paper]

Deterministic: no randomness, the output depends only on the IPC files. It writes, per
domain, the robot's and the human's domain (`<domain>/domain-robot.pddl`,
`<domain>/domain-human.pddl`) and 20 design problems `<domain>/<nn>/`, each with its task
PDDL and two specs that differ only in the horizon: `design-t1.textproto` (T = 1) and
`design-t10.textproto` (T = 10). Every spec has 3 tasks of probability 1/3 (uniform), unit
action costs, modifications of cost 1, and the paper's weights alpha = 1, beta = 0.25,
kappa = 0.25, gamma = 0.9, with its 1800 s limit. Run one with

  build/bin/envdesign design tests/data/paper/blocksworld/01/design-t10.textproto

Blocksworld (IPC 2000, `blocks/`, the untyped 4-operator domain):
  - robot: IPC's domain. Human: the robot can hold several blocks at once (pick-up and
    unstack neither need nor take the empty hand), so observers expect towers to be moved
    without putting blocks down.
  - modifications, one per block x, `from-table-x`: x is stacked only after it was picked
    up from the table. Both models (the robot really follows the rule, the observers are
    told). The schema edits can only change every instance of an action, so the domains
    carry a hook: `stack` needs (not (restricted ?x)), and its twin `stack-from-table`
    needs (restricted ?x) and (from-table ?x). The modification adds (restricted x) to the
    initial state and the bookkeeping effects (pick-up marks the block, unstack unmarks
    it). With no modification no block is restricted: `stack-from-table` has no instance
    and the models are IPC's.
  - problems: block sets of 4, 5, 6 and 7 blocks (probBLOCKS-n-0/1/2 share their blocks).
    Task (i, j) starts in the initial state of probBLOCKS-n-i and has the goal of
    probBLOCKS-n-j. Per n five problems: the IPC instances {(0,0), (1,1), (2,2)}, the
    rotations {(0,1), (1,2), (2,0)} and {(0,2), (1,0), (2,1)}, and one initial state with
    the three goals {(0,0), (0,1), (0,2)} and {(1,0), (1,1), (1,2)}. Problems 01-05 have 4
    blocks, 06-10 5, 11-15 6, 16-20 7.
IPC-Grid (IPC 1998 round 2, `grid/`): the full instances are too hard for an optimal
  planner beyond prob01 (FD's A*/LM-cut fails on prob02 in 30 s), so each problem is a 4x4
  window of one of them.
  - window: prob0k (k = 1..5) cut at its four corners, in the order SW (x 0-3, y 0-3), SE,
    NW, NE; problem nn = 4 (k - 1) + corner + 1. The window keeps IPC's places, their conn
    atoms inside the window, locks and lock shapes, and the keys lying in it; keys outside
    the window are dropped.
  - robot: IPC's domain. Human: the same domain, but the human problem also connects
    diagonal neighbours (both directions), so observers expect diagonal moves.
  - tasks: "sw-ne": start at the place nearest the SW corner, goal: the robot at the place
    nearest the NE corner; "se-nw" likewise; "key": start near NE, goal: the
    lowest-numbered key lying in that region, at the place nearest SW (when there is no
    such key, the robot itself goes there). Places are chosen from the window's largest
    region of open places connected without locks (the first by (x, y) on a tie);
    "nearest": least Manhattan distance, ties by (x, y). So every task is solvable
    without unlocking (unlocking may still be a shortcut).
  - modifications, one per place of the window's 2x2 centre and one per corner place,
    `no-diagonal-x-y`: the observers are told the robot cannot move diagonally from or
    to node x-y (HUMAN: removes that place's diagonal conn atoms from the human problem).
Driverlog (IPC 2002, `driverlog/`, p01-p05):
  - robot: IPC's domain (loading and unloading need the truck and the package at the
    place, not the driver). Human: packages can be loaded and unloaded wherever the driver
    and the truck are; observers do not tie loading to the truck's place (load and unload
    do not need (at ?truck ?loc)), so they expect packages to get on and off a truck that
    never drives to them.
  - modifications, one per depot s (s0, s1, s2), `disembark-rule-s`: at s, packages are
    loaded and unloaded only after the driver got off the truck there (and before anyone
    boards it again). Both models. Hook as in Blocksworld: load-truck/unload-truck need
    (not (rule ?loc)), their twins load-truck-parked/unload-truck-parked need (rule ?loc)
    and (parked ?truck ?loc); the modification adds (rule s), disembark-truck's effect
    (parked ?truck ?loc) and board-truck's effect (not (parked ?truck ?loc)).
  - tasks: the IPC instance's initial state; the goal is the IPC goal for the drivers and
    trucks plus one package at another depot (a pair (package, depot), the depot not the
    package's start; the IPC goals for packages are dropped). With P packages
    there are 2P pairs, ordered by package then depot; problem v (0..3) of pK takes the
    combination of 3 pairs at index floor(v * C(2P, 3) / 4) of itertools.combinations
    (lexicographic). Problem nn = 4 (K - 1) + v + 1.
"""
import argparse
import itertools
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
HEADER = "; Generated by tests/benchmarks/paper/generate_design_problems.py: do not edit.\n"
WEIGHTS = "alpha: 1 beta: 0.25 kappa: 0.25 gamma: 0.9"
HORIZONS = (1, 10)
TIME_LIMIT_S = 1800


# --- PDDL in and out ---------------------------------------------------------------------

def parse_sexpr(text):
    """The first S-expression of `text` as nested lists of lower-case symbols."""
    tokens = re.findall(r"[()]|[^\s()]+", re.sub(r";[^\n]*", "", text).lower())
    stack = [[]]
    for token in tokens:
        if token == "(":
            stack.append([])
        elif token == ")":
            done = stack.pop()
            stack[-1].append(done)
        else:
            stack[-1].append(token)
    return stack[0][0]


def read_problem(path):
    """(objects, init atoms, goal atoms) of a STRIPS problem; atoms are tuples."""
    with open(path) as f:
        tree = parse_sexpr(f.read())
    sections = {item[0]: item[1:] for item in tree[2:] if isinstance(item, list)}
    goal = sections[":goal"][0]
    goal = goal[1:] if goal[0] == "and" else [goal]
    return (list(sections[":objects"]), [tuple(a) for a in sections[":init"]],
            [tuple(a) for a in goal])


def atom(a):
    return "(" + " ".join(a) + ")"


def problem_text(name, domain, objects, init, goal, comment):
    lines = [HEADER.rstrip(), "; " + comment, f"(define (problem {name})", f"  (:domain {domain})",
             "  (:objects " + " ".join(objects) + ")", "  (:init"]
    lines += ["    " + atom(a) for a in init]
    lines += ["  )", "  (:goal (and"]
    lines += ["    " + atom(a) for a in goal]
    lines += ["  )))"]
    return "\n".join(lines) + "\n"


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


# --- specs ---------------------------------------------------------------------------------

def edit_text(edit):
    """One edit: (kind, value, model) with value a string or (action, literal)."""
    kind, value, model = edit
    prefix = f"model: {model} " if model != "BOTH" else ""
    if isinstance(value, tuple):
        return f'edit {{ {prefix}{kind} {{ action: "{value[0]}" literal: "{value[1]}" }} }}'
    return f'edit {{ {prefix}{kind}: "{value}" }}'


def spec_text(comment, tasks, modifications, horizon):
    """tasks: [(name, problem, human_problem or None)]; modifications: [(name, comment, edits)]."""
    lines = ["# " + line for line in comment] + [
        'robot_domain: "../domain-robot.pddl"', 'human_domain: "../domain-human.pddl"']
    for name, problem, human in tasks:
        human_field = f' human_problem: "{human}"' if human else ""
        lines.append(f'task {{ name: "{name}" problem: "{problem}"{human_field} probability: 1 }}')
    for name, note, edits in modifications:
        lines += [f"# {note}", "modification {", f'  name: "{name}" cost: 1']
        lines += ["  " + edit_text(e) for e in edits]
        lines.append("}")
    lines.append(f"{WEIGHTS} horizon: {horizon}")
    lines.append(f"time_limit_s: {TIME_LIMIT_S}")
    return "# Generated by tests/benchmarks/paper/generate_design_problems.py: do not edit.\n" + \
        "\n".join(lines) + "\n"


def write_specs(folder, comment, tasks, modifications):
    for horizon in HORIZONS:
        text = spec_text(comment + [f"Horizon T = {horizon}."], tasks, modifications, horizon)
        write(os.path.join(folder, f"design-t{horizon}.textproto"), text)


# --- Blocksworld ---------------------------------------------------------------------------

BLOCKS_ACTIONS = """\
  (:action pick-up
    :parameters (?x)
    :precondition (and (clear ?x) (ontable ?x){hand})
    :effect (and (not (ontable ?x)) (not (clear ?x)){take} (holding ?x)))
  (:action put-down
    :parameters (?x)
    :precondition (holding ?x)
    :effect (and (not (holding ?x)) (clear ?x) (handempty) (ontable ?x)))
  (:action stack
    :parameters (?x ?y)
    :precondition (and (holding ?x) (clear ?y) (not (restricted ?x)))
    :effect (and (not (holding ?x)) (not (clear ?y)) (clear ?x) (handempty) (on ?x ?y)))
  (:action stack-from-table
    :parameters (?x ?y)
    :precondition (and (holding ?x) (clear ?y) (restricted ?x) (from-table ?x))
    :effect (and (not (holding ?x)) (not (clear ?y)) (clear ?x) (handempty) (on ?x ?y)))
  (:action unstack
    :parameters (?x ?y)
    :precondition (and (on ?x ?y) (clear ?x){hand})
    :effect (and (holding ?x) (clear ?y) (not (clear ?x)){take} (not (on ?x ?y)))))
"""

BLOCKS_DOMAIN = """\
{header}; {what}
; The hook of the from-table-x modifications: a block marked (restricted x) is stacked only by
; stack-from-table, which needs (from-table x); the modification makes pick-up set it and
; unstack clear it. No block is restricted in the unmodified model, where stack-from-table
; has no instance.
(define (domain blocksworld)
  (:requirements :strips :negative-preconditions)
  (:predicates (on ?x ?y) (ontable ?x) (clear ?x) (handempty) (holding ?x)
               (restricted ?x) (from-table ?x))
{actions}"""


def blocks_domains():
    robot = BLOCKS_DOMAIN.format(
        header=HEADER, what="The robot's Blocksworld: IPC 2000's 4-operator domain, one block "
        "in the hand.", actions=BLOCKS_ACTIONS.format(hand=" (handempty)",
                                                      take=" (not (handempty))"))
    human = BLOCKS_DOMAIN.format(
        header=HEADER, what="Blocksworld as observers imagine it: the robot holds several "
        "blocks at once\n; (pick-up and unstack neither need nor take the empty hand).",
        actions=BLOCKS_ACTIONS.format(hand="", take=""))
    return robot, human


BLOCKS_TASK_SETS = [  # (initial state of probBLOCKS-n-i, goal of probBLOCKS-n-j)
    ("the IPC instances", [(0, 0), (1, 1), (2, 2)]),
    ("goals rotated by one", [(0, 1), (1, 2), (2, 0)]),
    ("goals rotated by two", [(0, 2), (1, 0), (2, 1)]),
    ("the initial state of instance 0 with the three goals", [(0, 0), (0, 1), (0, 2)]),
    ("the initial state of instance 1 with the three goals", [(1, 0), (1, 1), (1, 2)]),
]


def generate_blocksworld(ipc, out):
    robot, human = blocks_domains()
    write(os.path.join(out, "domain-robot.pddl"), robot)
    write(os.path.join(out, "domain-human.pddl"), human)
    number = 0
    for n in (4, 5, 6, 7):
        instances = [read_problem(os.path.join(ipc, "blocks", f"probBLOCKS-{n}-{i}.pddl"))
                     for i in range(3)]
        blocks = sorted(instances[0][0])
        for description, pairs in BLOCKS_TASK_SETS:
            number += 1
            folder = os.path.join(out, f"{number:02d}")
            tasks = []
            for i, j in pairs:
                name = f"init-{n}-{i}-goal-{n}-{j}"
                write(os.path.join(folder, name + ".pddl"), problem_text(
                    name, "blocksworld", blocks, instances[i][1], instances[j][2],
                    f"Initial state of probBLOCKS-{n}-{i}, goal of probBLOCKS-{n}-{j}."))
                tasks.append((name, name + ".pddl", None))
            modifications = [(f"from-table-{b}", f"Block {b} is stacked only after it was "
                              "picked up from the table.", [
                                  ("add_init", f"(restricted {b})", "BOTH"),
                                  ("add_effect", ("pick-up", "(from-table ?x)"), "BOTH"),
                                  ("add_effect", ("unstack", "(not (from-table ?x))"), "BOTH")])
                             for b in blocks]
            comment = [f"Blocksworld design problem {number:02d}: {n} blocks, {description} "
                       f"(IPC probBLOCKS-{n}-*).",
                       "Observers believe the robot holds several blocks at once; one "
                       "modification per block."]
            write_specs(folder, comment, tasks, modifications)


# --- IPC-Grid --------------------------------------------------------------------------------

WINDOW = 4
CORNERS = ("sw", "se", "nw", "ne")


def node_xy(name):
    x, y = name[len("node"):].split("-")
    return int(x), int(y)


def corner_xy(corner, ox, oy):
    return (ox + (WINDOW - 1 if corner[1] == "e" else 0),
            oy + (WINDOW - 1 if corner[0] == "n" else 0))


def open_region(start, places, conn, locked):
    """The open places reachable from open `start` through open places (4-neighbour conn)."""
    seen, todo = {start}, [start]
    while todo:
        p = todo.pop()
        for q in conn.get(p, ()):
            if q not in seen and q not in locked:
                seen.add(q)
                todo.append(q)
    return seen


def nearest(xy, candidates):
    return min(candidates, key=lambda n: (abs(node_xy(n)[0] - xy[0]) + abs(node_xy(n)[1] - xy[1]),
                                          node_xy(n)))


def grid_window(ipc, k, corner):
    """The environment of one 4x4 window of prob0k: objects, init, and its geometry."""
    objects, init, _ = read_problem(os.path.join(ipc, "grid", f"prob0{k}.pddl"))
    size = max(node_xy(o)[0] for o in objects if o.startswith("node")) + 1
    ox, oy = corner_xy(corner, 0, 0)
    ox, oy = (size - WINDOW if ox else 0), (size - WINDOW if oy else 0)
    inside = lambda n: n.startswith("node") and ox <= node_xy(n)[0] < ox + WINDOW and \
        oy <= node_xy(n)[1] < oy + WINDOW
    places = sorted((o for o in objects if inside(o)), key=node_xy)
    keys = sorted({a[1] for a in init if a[0] == "at" and inside(a[2])},
                  key=lambda key: int(key[3:]))
    kept = set(places) | set(keys) | {o for o in objects if o in
                                      {a[1] for a in init if a[0] == "shape"}}
    env = [a for a in init if a[0] != "at-robot" and all(
        arg in kept for arg in a[1:]) and (a[0] != "key-shape" or a[1] in keys)]
    conn = {}
    for a in env:
        if a[0] == "conn":
            conn.setdefault(a[1], []).append(a[2])
    locked = {a[1] for a in env if a[0] == "locked"}
    regions = [open_region(p, places, conn, locked) for p in places if p not in locked]
    region = sorted(max(regions, key=len), key=node_xy)  # the first largest one
    return {"objects": [o for o in objects if o in kept], "init": env, "places": places,
            "region": region,
            "keys": keys, "conn": conn, "locked": locked, "origin": (ox, oy), "size": size,
            "key_at": {a[1]: a[2] for a in env if a[0] == "at"}}


def grid_task(window, start_corner, goal_corner, with_key):
    """(init, goal, description) of a task of `window`."""
    ox, oy = window["origin"]
    region = window["region"]
    start = nearest(corner_xy(start_corner, ox, oy), region)
    target = nearest(corner_xy(goal_corner, ox, oy), [p for p in region if p != start])
    key = next((k for k in window["keys"] if window["key_at"][k] in region
                and window["key_at"][k] != target), None) if with_key else None
    init = window["init"] + [("at-robot", start)]
    if key:
        return init, [("at", key, target)], f"robot at {start}, {key} to {target}"
    return init, [("at-robot", target)], f"robot from {start} to {target}"


def diagonals(place, places):
    x, y = node_xy(place)
    return [q for q in places if abs(node_xy(q)[0] - x) == 1 and abs(node_xy(q)[1] - y) == 1]


def grid_modification_places(window):
    """The window's 2x2 centre and its four corners."""
    ox, oy = window["origin"]
    centre = [(ox + 1, oy + 1), (ox + 2, oy + 1), (ox + 1, oy + 2), (ox + 2, oy + 2)]
    corners = [corner_xy(c, ox, oy) for c in CORNERS]
    return sorted((f"node{x}-{y}" for x, y in centre + corners), key=node_xy)


def generate_grid(ipc, out):
    with open(os.path.join(ipc, "grid", "domain.pddl")) as f:
        ipc_domain = f.read()
    write(os.path.join(out, "domain-robot.pddl"),
          HEADER + "; The robot's Grid: IPC 1998's domain, unchanged.\n" + ipc_domain)
    write(os.path.join(out, "domain-human.pddl"),
          HEADER + "; The observers' Grid: IPC 1998's domain, unchanged; their problems also\n"
          "; connect diagonal neighbours, so they believe the robot moves diagonally.\n" +
          ipc_domain)
    number = 0
    for k in range(1, 6):
        for corner in CORNERS:
            number += 1
            folder = os.path.join(out, f"{number:02d}")
            window = grid_window(ipc, k, corner)
            ox, oy = window["origin"]
            diagonal_conn = [("conn", p, q) for p in window["places"]
                             for q in diagonals(p, window["places"])]
            tasks = []
            for name, start, goal, with_key in (("sw-ne", "sw", "ne", False),
                                                ("se-nw", "se", "nw", False),
                                                ("key", "ne", "sw", True)):
                init, goal_atoms, what = grid_task(window, start, goal, with_key)
                comment = (f"Window x {ox}-{ox + WINDOW - 1}, y {oy}-{oy + WINDOW - 1} of IPC "
                           f"grid prob0{k}: {what}.")
                write(os.path.join(folder, name + ".pddl"), problem_text(
                    name, "grid", window["objects"], init, goal_atoms, comment))
                write(os.path.join(folder, name + "-human.pddl"), problem_text(
                    name, "grid", window["objects"], init + diagonal_conn, goal_atoms,
                    comment + " Observers' view: diagonal neighbours connected too."))
                tasks.append((name, name + ".pddl", name + "-human.pddl"))
            modifications = []
            for place in grid_modification_places(window):
                edits = []
                for q in diagonals(place, window["places"]):
                    edits += [("remove_init", f"(conn {place} {q})", "HUMAN"),
                              ("remove_init", f"(conn {q} {place})", "HUMAN")]
                x, y = node_xy(place)
                modifications.append((f"no-diagonal-{x}-{y}", f"Observers are told: no diagonal "
                                      f"moves from or to node{x}-{y}.", edits))
            comment = [f"IPC-Grid design problem {number:02d}: the {corner.upper()} 4x4 window "
                       f"(x {ox}-{ox + WINDOW - 1}, y {oy}-{oy + WINDOW - 1}) of IPC grid "
                       f"prob0{k}.",
                       "Observers believe the robot moves diagonally; one modification per "
                       "centre or corner place."]
            write_specs(folder, comment, tasks, modifications)


# --- Driverlog -------------------------------------------------------------------------------

DRIVERLOG_DOMAIN = """\
{header}; {what}
; The hook of the disembark-rule-s modifications: at a depot marked (rule s), packages are
; loaded and unloaded only by the -parked twins, which need (parked ?truck s); the
; modification makes disembark-truck set it and board-truck clear it. No depot has the rule
; in the unmodified model, where the twins have no instance.
(define (domain driverlog)
  (:requirements :strips :negative-preconditions)
  (:predicates (obj ?obj) (truck ?truck) (location ?loc) (driver ?d) (at ?obj ?loc)
               (in ?obj1 ?obj) (driving ?d ?v) (link ?x ?y) (path ?x ?y) (empty ?v)
               (rule ?loc) (parked ?truck ?loc))
  (:action load-truck
    :parameters (?obj ?truck ?loc)
    :precondition (and (obj ?obj) (truck ?truck) (location ?loc){truck_at} (at ?obj ?loc)
                       (not (rule ?loc)))
    :effect (and (not (at ?obj ?loc)) (in ?obj ?truck)))
  (:action load-truck-parked
    :parameters (?obj ?truck ?loc)
    :precondition (and (obj ?obj) (truck ?truck) (location ?loc){truck_at} (at ?obj ?loc)
                       (rule ?loc) (parked ?truck ?loc))
    :effect (and (not (at ?obj ?loc)) (in ?obj ?truck)))
  (:action unload-truck
    :parameters (?obj ?truck ?loc)
    :precondition (and (obj ?obj) (truck ?truck) (location ?loc){truck_at} (in ?obj ?truck)
                       (not (rule ?loc)))
    :effect (and (not (in ?obj ?truck)) (at ?obj ?loc)))
  (:action unload-truck-parked
    :parameters (?obj ?truck ?loc)
    :precondition (and (obj ?obj) (truck ?truck) (location ?loc){truck_at} (in ?obj ?truck)
                       (rule ?loc) (parked ?truck ?loc))
    :effect (and (not (in ?obj ?truck)) (at ?obj ?loc)))
  (:action board-truck
    :parameters (?driver ?truck ?loc)
    :precondition (and (driver ?driver) (truck ?truck) (location ?loc) (at ?truck ?loc)
                       (at ?driver ?loc) (empty ?truck))
    :effect (and (not (at ?driver ?loc)) (driving ?driver ?truck) (not (empty ?truck))))
  (:action disembark-truck
    :parameters (?driver ?truck ?loc)
    :precondition (and (driver ?driver) (truck ?truck) (location ?loc) (at ?truck ?loc)
                       (driving ?driver ?truck))
    :effect (and (not (driving ?driver ?truck)) (at ?driver ?loc) (empty ?truck)))
  (:action drive-truck
    :parameters (?truck ?loc-from ?loc-to ?driver)
    :precondition (and (truck ?truck) (location ?loc-from) (location ?loc-to) (driver ?driver)
                       (at ?truck ?loc-from) (driving ?driver ?truck) (link ?loc-from ?loc-to))
    :effect (and (not (at ?truck ?loc-from)) (at ?truck ?loc-to)))
  (:action walk
    :parameters (?driver ?loc-from ?loc-to)
    :precondition (and (driver ?driver) (location ?loc-from) (location ?loc-to)
                       (at ?driver ?loc-from) (path ?loc-from ?loc-to))
    :effect (and (not (at ?driver ?loc-from)) (at ?driver ?loc-to))))
"""


def driverlog_tasks(objects, init):
    """Every (package, depot) pair with the depot not the package's start, in order."""
    depots = sorted(o for o in objects if re.fullmatch(r"s\d+", o))
    packages = sorted((a[1] for a in init if a[0] == "obj"), key=lambda p: int(p[7:]))
    start = {a[1]: a[2] for a in init if a[0] == "at"}
    return [(p, s) for p in packages for s in depots if s != start[p]], depots


def generate_driverlog(ipc, out):
    write(os.path.join(out, "domain-robot.pddl"), DRIVERLOG_DOMAIN.format(
        header=HEADER, what="The robot's Driverlog: IPC 2002's STRIPS domain (types as unary "
        "predicates).", truck_at=" (at ?truck ?loc)"))
    write(os.path.join(out, "domain-human.pddl"), DRIVERLOG_DOMAIN.format(
        header=HEADER, what="Driverlog as observers imagine it: packages get on and off a "
        "truck wherever\n; it is (load and unload do not need the truck at the place).",
        truck_at=""))
    for k in range(1, 6):
        objects, init, goal = read_problem(os.path.join(ipc, "driverlog", f"p0{k}.pddl"))
        vehicles = [a for a in goal if a[1].startswith(("driver", "truck"))]
        pairs, depots = driverlog_tasks(objects, init)
        combinations = list(itertools.combinations(range(len(pairs)), 3))
        for v in range(4):
            number = 4 * (k - 1) + v + 1
            folder = os.path.join(out, f"{number:02d}")
            tasks = []
            for index in combinations[v * len(combinations) // 4]:
                package, depot = pairs[index]
                name = f"{package}-to-{depot}"
                write(os.path.join(folder, name + ".pddl"), problem_text(
                    name, "driverlog", objects, init, vehicles + [("at", package, depot)],
                    f"Initial state of IPC driverlog p0{k}; goal: its drivers and trucks "
                    f"as in p0{k}, {package} at {depot}."))
                tasks.append((name, name + ".pddl", None))
            modifications = [(f"disembark-rule-{s}", f"At {s}, packages are loaded and unloaded "
                              "only after the driver got off the truck.", [
                                  ("add_init", f"(rule {s})", "BOTH"),
                                  ("add_effect", ("disembark-truck", "(parked ?truck ?loc)"),
                                   "BOTH"),
                                  ("add_effect", ("board-truck", "(not (parked ?truck ?loc))"),
                                   "BOTH")])
                             for s in depots]
            comment = [f"Driverlog design problem {number:02d}: IPC driverlog p0{k}, three "
                       "one-package deliveries.",
                       "Observers believe packages get on and off a truck wherever it is; one "
                       "modification per depot."]
            write_specs(folder, comment, tasks, modifications)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ipc", default=os.path.join(os.path.dirname(ROOT), "shared",
                                                      "benchmarks", "ipc"))
    parser.add_argument("--out", default=os.path.join(ROOT, "tests", "data", "paper"))
    parser.add_argument("--domain", action="append", choices=sorted(GENERATORS),
                        help="only these domains (default: all)")
    args = parser.parse_args()
    for domain in args.domain or sorted(GENERATORS):
        GENERATORS[domain](args.ipc, os.path.join(args.out, domain))
        print(f"wrote {os.path.join(args.out, domain)}", file=sys.stderr)


GENERATORS = {"blocksworld": generate_blocksworld, "grid": generate_grid,
              "driverlog": generate_driverlog}

if __name__ == "__main__":
    main()
