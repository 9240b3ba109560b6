#pragma once
// What a search for a minimal explanation answers (minimal_explanation.h: the enumeration;
// explanation_hitting.h: implicit hitting sets).

#include "design/reconciliation/model_differences.h"

#include <vector>

namespace envdesign::design {

enum class ExplanationStatus {
    FOUND, // `chosen` is a minimal explanation
    NONE,  // no subset of the differences makes pi_R optimal (or pi_R is not a plan of P_R)
    LIMIT, // the deadline passed first
};

struct ExplanationSearch {
    ExplanationStatus status = ExplanationStatus::LIMIT;
    std::vector<ModelDifference> differences; // all candidates
    std::vector<int> chosen;                  // indices into `differences`, ascending
    long long subsets_tried = 0;  // told the human (with hitting sets: the rounds' sets too)
    long long planner_checks = 0; // subsets on which pi_R was valid, so the planner ran
    bool hitting_sets = false;    // found by explanation_hitting.h (all differences restricting)
};

} // namespace envdesign::design
