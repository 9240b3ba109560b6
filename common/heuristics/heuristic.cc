#include "heuristics/heuristic.h"

#include <stdexcept>
#include <string>

namespace envdesign::heuristics {

Heuristic::~Heuristic() = default;

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
