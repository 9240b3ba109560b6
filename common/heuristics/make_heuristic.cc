#include "heuristics/make_heuristic.h"

#include "heuristics/blind_heuristic.h"
#include "heuristics/hmax_heuristic.h"
#include "heuristics/lmcut_heuristic.h"

#include <stdexcept>

namespace envdesign::heuristics {

// Every operator needs at most one fact and the goal is one fact: the delete relaxation is
// a shortest-path problem (a robot on a route graph), where h^max is h+ and LM-cut, lying
// between them, equals both at every state. h^max costs a fraction per state.
bool lmcut_is_hmax(const ground::GroundTask &task) {
    if (task.goal.size() != 1)
        return false;
    for (const auto &op : task.operators)
        if (op.pre.size() > 1)
            return false;
    return true;
}

std::unique_ptr<Heuristic> make_heuristic(HeuristicKind kind, const ground::GroundTask &task) {
    switch (kind) {
    case HeuristicKind::BLIND:
        return std::make_unique<BlindHeuristic>(task);
    case HeuristicKind::HMAX:
        return std::make_unique<HMaxHeuristic>(task);
    case HeuristicKind::LMCUT:
        if (lmcut_is_hmax(task)) // the same estimates, so the same search and plan
            return std::make_unique<HMaxHeuristic>(task);
        return std::make_unique<LmCutHeuristic>(task);
    }
    throw std::invalid_argument("unknown heuristic kind");
}

} // namespace envdesign::heuristics
