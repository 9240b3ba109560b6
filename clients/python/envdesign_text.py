"""The answer as `envdesign design` prints it, from the design_result_t a coordinator sends.

    import envdesign_text
    print(envdesign_text.result_text(result), end="")   # result: envdesign.design_result_t

The message carries everything the answer says (terms, each task before and after, the plans,
the value of each chosen modification, break-even, the ranking). The C++ formatter is
clients/cpp/src/result_text.cc; this is the same text line for line, with the same rounding
(`shown`). tests/e2e/python_client_test.py (PythonText) holds the two to the same bytes on
the examples, so a change to one that the other lacks fails there.
"""
import math

# What a task's plan pi is under the result's robot_behaviour (result_json.cc's plan_name).
PLAN_NAMES = {
    "COST_OPTIMAL": "the worst of the robot's optimal plans",
    "COST_OPTIMAL_BEST_CASE": "the best of the robot's optimal plans",
    "EXPLAINING": "the plan the robot follows",
}


def shown(value):
    """A number for people: integers as such, else 4 significant digits (1 decimal from 1000
    on), "inf" for infinity, "?" for NaN (number_format.cc's shown)."""
    if math.isnan(value):
        return "?"
    if math.isinf(value):
        return "inf" if value > 0 else "-inf"
    if value == math.floor(value) and abs(value) < 1e15:
        return "%d" % int(value)
    if 1000 <= abs(value) < 1e9:
        return "%.1f" % value
    return "%.4g" % value


def design_set(design):
    """ "{a, b}" or "{} (the empty design)"."""
    return "{" + ", ".join(design) + "}" if design else "{} (the empty design)"


def plan_diff(first, second):
    """[(side, action)]: a longest common subsequence of the two plans' actions, side "=",
    the rest "+" (only in `first`) or "-" (only in `second`); at each place the removals from
    `first` come before the additions from `second` (plan_diff.cc)."""
    n, m = len(first), len(second)
    lcs = [[0] * (m + 1) for _ in range(n + 1)]
    for i in range(n - 1, -1, -1):
        for j in range(m - 1, -1, -1):
            lcs[i][j] = (lcs[i + 1][j + 1] + 1 if first[i] == second[j]
                         else max(lcs[i + 1][j], lcs[i][j + 1]))
    out, i, j = [], 0, 0
    while i < n or j < m:
        if i < n and j < m and first[i] == second[j]:
            out.append(("=", first[i]))
            i, j = i + 1, j + 1
        elif i < n and (j == m or lcs[i + 1][j] >= lcs[i][j + 1]):
            out.append(("+", first[i]))
            i += 1
        else:
            out.append(("-", second[j]))
            j += 1
    return out


def _terms_line(label, t):
    line = (f"{label}{shown(t.objective)} (inexplicability {shown(t.inexplicability)}, "
            f"design cost {shown(t.design_cost)}, robot cost {shown(t.robot_cost)}")
    if t.explanation != 0:  # EXPLAINING: the explanations told over the horizon
        line += f", explanation {shown(t.explanation)}"
    return [line + ")"]


def _weighted_line(label, t, w):
    """ "52.23 = 12.83 inexplicability (1 x 12.83) + 45 design cost (30 x 1.5) + ..." """
    line = (f"{label}{shown(t.objective)} = {shown(w.alpha * t.inexplicability)} "
            f"inexplicability ({shown(w.alpha)} x {shown(t.inexplicability)}) + "
            f"{shown(w.beta * t.design_cost)} design cost ({shown(w.beta)} x "
            f"{shown(t.design_cost)}) + {shown(w.kappa * t.robot_cost)} robot cost "
            f"({shown(w.kappa)} x {shown(t.robot_cost)})")
    if t.explanation != 0:  # EXPLAINING: its weight is 1
        line += f" + {shown(t.explanation)} explanation"
    return [line]


def _explanation_line(t):
    """EXPLAINING: "  explains: +init (a), ..." or "  acts explicably (explanation: ...)"."""
    if not t.has_explanation:
        return []
    line = "  explains" if t.explained else "  acts explicably (explanation"
    if not t.explanation.found:
        return [line + ": none)"]
    line += ":" + "".join(("," if i else "") + " " + d
                          for i, d in enumerate(t.explanation.differences))
    if not t.explanation.differences:
        line += " nothing to tell"
    return [line if t.explained else line + ")"]


def _least_line(r):
    w = r.explanation
    least = w.least_inexplicability
    line = (f"  least inexplicability term possible: {shown(least)} (every IE "
            f"{shown(w.least_ie)} over the horizon: f_T({shown(w.least_ie)}) with T = "
            f"{w.horizon}, gamma = {shown(w.gamma)})")
    if abs(r.best.inexplicability - least) <= 1e-9 * max(1.0, least):
        line += ": the chosen design is as explicable as it gets"
    return [line]


def _plan_line(label, plan):
    steps = "".join(" " + step for step in plan) if plan else " (empty plan)"
    return ["    " + label.ljust(22) + steps]


def _diff_line(label, pi, other):
    diff = [(side, action) for side, action in plan_diff(pi, other) if side != "="]
    if not diff:
        return ["    " + label.ljust(22) + " the same plan"]
    return ["    " + label.ljust(22) + "".join(f" {side}{action}" for side, action in diff)]


def _row(label, before, after, known):
    return ["    " + label.ljust(28) + (shown(before) if known else "?").rjust(12) +
            shown(after).rjust(12)]


def _task_block(behaviour, t, e):
    b, known = e.baseline, e.has_baseline
    lines = [f"task {t.name} (probability {shown(t.probability)}):"]
    lines += _explanation_line(t)
    lines.append("    " + "".ljust(28) + "empty design".rjust(12) + "chosen".rjust(12))
    lines += _row("IE", b.ie, t.ie, known)
    lines += _row("robot cost c_R(pi)", b.robot_cost, t.robot_cost, known)
    lines += _row("human optimal cost c_H*",
                  b.human_optimal_cost if b.has_human_optimal_cost else math.nan,
                  t.human_optimal_cost if t.has_human_optimal_cost else math.nan, known)
    lines += _row("human cost of pi c_H(pi)", b.human_plan_cost, t.human_plan_cost, known)
    lines.append("  plans under the chosen design:")
    if e.has_robot_plan:
        lines += _plan_line("robot's optimal:", e.robot_plan)
    lines += _plan_line("pi:", t.plan)
    lines.append(f"      (pi is {PLAN_NAMES.get(behaviour, 'the most explicable plan')})")
    if e.has_expected_plan:
        lines += _plan_line("observers expect:", e.expected_plan)
    if e.has_robot_plan:
        lines += _diff_line("pi vs robot's:", t.plan, e.robot_plan)
    if e.has_expected_plan:
        lines += _diff_line("pi vs expected:", t.plan, e.expected_plan)
    if e.has_expected_plan and t.has_human_optimal_cost and \
            t.human_plan_cost == t.human_optimal_cost:
        lines.append("    (pi costs observers what their expected plan costs: they find it "
                     "just as good)")
    return lines


def _marginal_block(r):
    if not r.explanation.marginal:
        return []
    lines = ["value of each chosen modification (the objective without it):"]
    for m in r.explanation.marginal:
        if not m.evaluated:
            lines.append(f"  {m.modification}: not evaluated (time limit)")
            continue
        value = m.without.terms.objective - r.best.objective
        lines.append(f"  {m.modification}: {shown(m.without.terms.objective)} without it "
                     f"({'+' if value >= 0 else ''}{shown(value)})")
    return lines


def _crossing_line(what, c):
    return [f"    {what} {shown(c.at)}: {design_set(c.rival.design)}"]


def _break_even_block(r):
    b, w = r.explanation.break_even, r.explanation
    if b.designs_compared == 0:
        return ["break-even: not computed (with robot_behaviour EXPLAINING each task's choice "
                "between explaining and acting explicably moves with T and alpha)"]
    low = int(b.horizon_down.at) + 1 if b.horizon_down.found else 1
    high = str(int(b.horizon_up.at) - 1) if b.horizon_up.found else f"{b.horizon_limit}+"
    lines = [f"break-even (among the {b.designs_compared} designs evaluated in full):",
             f"  horizon: the chosen design ranks first for T in [{low}, {high}] "
             f"(spec: T = {w.horizon})"]
    for crossing in (b.horizon_down, b.horizon_up):
        if crossing.found:
            lines += _crossing_line("first before it at T =", crossing)
    low = shown(b.alpha_down.at) if b.alpha_down.found else "0"
    high = shown(b.alpha_up.at) if b.alpha_up.found else "inf"
    lines.append(f"  alpha: the chosen design ranks first for alpha in [{low}, {high}] "
                 f"(spec: alpha = {shown(w.alpha)})")
    if b.alpha_down.found:
        lines += _crossing_line("below alpha =", b.alpha_down)
    if b.alpha_up.found:
        lines += _crossing_line("above alpha =", b.alpha_up)
    return lines


def _explanation_block(r):
    lines = []
    for t, e in zip(r.tasks, r.explanation.tasks):
        lines += _task_block(r.explanation.robot_behaviour, t, e)
    return lines + _marginal_block(r) + _break_even_block(r)


def _plain_tasks(r):
    lines = []
    for t in r.tasks:
        plan = "".join(" " + step for step in t.plan)
        lines.append(f"task {t.name}: ie {shown(t.ie)}, robot cost {shown(t.robot_cost)}, "
                     f"plan{plan}")
        lines += _explanation_line(t)
    return lines


def _ranking_block(r):
    if r.ranking_size == 0:
        return []
    return ["ranking:"] + [f"  {i}. {shown(p.terms.objective)}  {design_set(p.design)}"
                           for i, p in enumerate(r.ranking, 1)]


def result_text(r):
    """What `envdesign design SPEC` prints for design_result_t `r`, newline-terminated."""
    lines = [f"status: {r.status}"]
    if r.status == "unsolvable" and r.error:  # why no design has a finite objective
        lines[0] += f" ({r.error})"
    if not r.has_design:
        return "\n".join(lines + ["no configuration was evaluated in time"]) + "\n"
    lines.append(f"design: {design_set(r.design)}")
    if r.has_explanation:
        lines += _weighted_line("objective: ", r.best, r.explanation)
        lines += _least_line(r)
        if r.has_baseline:
            lines += _weighted_line("baseline (empty design): ", r.baseline, r.explanation)
        lines += _explanation_block(r)
    else:
        lines += _terms_line("objective: ", r.best)
        if r.has_baseline:
            lines += _terms_line("baseline: ", r.baseline)
        lines += _plain_tasks(r)
    lines += _ranking_block(r)
    if r.has_gap:
        lines.append(f"proven gap: {shown(r.gap)}")
    lines += [f"note: {note}" for note in r.notes]
    return "\n".join(lines) + "\n"
