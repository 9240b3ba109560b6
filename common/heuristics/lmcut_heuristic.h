#pragma once
// The LM-cut heuristic: a thin adapter that sums the costs of LmCutLandmarks' cuts.

#include "heuristics/heuristic.h"
#include "heuristics/lmcut_landmarks.h"

namespace envdesign::heuristics {

class LmCutHeuristic : public Heuristic {
public:
    explicit LmCutHeuristic(const ground::GroundTask &task) : landmarks_(task) {}
    // The sum of the cut costs, or DEAD_END.
    int compute(const StateView &state) override;

private:
    LmCutLandmarks landmarks_;
};

} // namespace envdesign::heuristics
