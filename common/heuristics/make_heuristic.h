#pragma once
// A heuristic of a kind, for a task: the factory over the heuristics of this folder.
//
// Example:
//   auto h = make_heuristic(parse_heuristic_kind("lmcut"), task);

#include "heuristics/heuristic.h"

#include <memory>

namespace envdesign::heuristics {

// The heuristic keeps a reference to `task`, which must outlive it. LMCUT on a task whose
// operators each need at most one fact and whose goal is one fact (a robot on a route graph)
// is computed as h^max: there the two give the same estimate at every state, h^max cheaper.
std::unique_ptr<Heuristic> make_heuristic(HeuristicKind kind, const ground::GroundTask &task);

// Whether LMCUT is computed as h^max on `task` (above).
bool lmcut_is_hmax(const ground::GroundTask &task);

} // namespace envdesign::heuristics
