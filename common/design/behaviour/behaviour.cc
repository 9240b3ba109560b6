#include "design/behaviour/behaviour.h"

namespace envdesign::design {
namespace {

// One row per RobotBehaviour, in the enum's order.
const Behaviour BEHAVIOURS[] = {
    // id, name, most explicable, an optimal plan, best case, explains, witnesses, every action
    {RobotBehaviour::EXPLICABLE, "EXPLICABLE", true, false, false, false, true, false},
    {RobotBehaviour::COST_OPTIMAL, "COST_OPTIMAL", false, true, false, false, true, true},
    {RobotBehaviour::COST_OPTIMAL_BEST_CASE, "COST_OPTIMAL_BEST_CASE", false, true, true, false,
     true, false},
    {RobotBehaviour::EXPLAINING, "EXPLAINING", false, false, false, true, false, false},
};

} // namespace

const Behaviour &behaviour_of(RobotBehaviour id) {
    for (const Behaviour &b : BEHAVIOURS)
        if (b.id == id)
            return b;
    return BEHAVIOURS[0]; // unreachable: every enum value has its row
}

} // namespace envdesign::design
