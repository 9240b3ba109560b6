#include "heuristics/heuristic.h"

#include "heuristics/blind_heuristic.h"
#include "heuristics/hmax_heuristic.h"
#include "heuristics/lmcut_heuristic.h"

#include <stdexcept>
#include <string>

namespace envdesign::heuristics {

Heuristic::~Heuristic() = default;

std::unique_ptr<Heuristic> make_heuristic(HeuristicKind kind, const ground::GroundTask &task) {
    switch (kind) {
    case HeuristicKind::BLIND:
        return std::make_unique<BlindHeuristic>(task);
    case HeuristicKind::HMAX:
        return std::make_unique<HMaxHeuristic>(task);
    case HeuristicKind::LMCUT:
        return std::make_unique<LmCutHeuristic>(task);
    }
    throw std::invalid_argument("unknown heuristic kind");
}

HeuristicKind parse_heuristic_kind(std::string_view name) {
    if (name == "lmcut")
        return HeuristicKind::LMCUT;
    if (name == "hmax")
        return HeuristicKind::HMAX;
    if (name == "blind")
        return HeuristicKind::BLIND;
    throw std::invalid_argument("unknown heuristic '" + std::string(name) +
                                "' (expected lmcut, hmax or blind)");
}

std::string_view heuristic_kind_name(HeuristicKind kind) {
    switch (kind) {
    case HeuristicKind::BLIND:
        return "blind";
    case HeuristicKind::HMAX:
        return "hmax";
    case HeuristicKind::LMCUT:
        return "lmcut";
    }
    return "unknown";
}

} // namespace envdesign::heuristics
