#pragma once
// The N best designs (`envdesign design --ranking N`, DesignResult::ranking), best first in
// SPEC.md's order (ranks_before). Only designs of finite objective are ranked: an infinite
// objective never beats a finite one, and designs that leave a task without a plan are not
// worth listing.
//
// The searches prune against the ranking's last design once it holds N (threshold()): a
// bound clearly above its objective, or nearly equal to it with more modifications, cannot
// enter. docs/design-search.md ("Ranking") says why each pruning rule stays exact.
//
//   Ranking ranking(options.ranking);
//   ranking.offer({objective, cost, configuration});
//   if (!ranking.may_enter(bound, configuration.size())) ...   // skip the subtree

#include "design/objective.h"

#include <cstddef>
#include <vector>

namespace envdesign::design {

class Ranking {
public:
    // `size` designs at most; 0 counts as 1 (only the best).
    explicit Ranking(int size = 1);

    int size() const { return size_; }
    bool full() const { return static_cast<int>(designs_.size()) >= size_; }

    // Puts `design` in its place when it is among the best `size` offered so far; a
    // configuration offered twice is ranked once. True if it entered.
    bool offer(const RankedDesign &design);

    // The objective of the last design when full, else INF.
    double threshold() const;

    // Whether a design whose objective is at least `bound`, with at least `modifications`
    // modifications, could still enter.
    bool may_enter(double bound, std::size_t modifications) const;

    // Best first.
    const std::vector<RankedDesign> &designs() const { return designs_; }

private:
    int size_;
    std::vector<RankedDesign> designs_;
};

// Offers to `ranking` every design `design` + E, E a non-empty subset of `free` (ascending,
// none in `design`, each of non-negative weighted cost beta * cost), with at most `max_size`
// modifications in all (0: no limit), whose tasks have the values `tasks` of `design` (every
// task known). This is the witness search's cone: the objective of each member is known
// without planning. Members are visited cheapest first, and a member that cannot enter
// ends its branch, so the work grows with what enters, not with 2^|free|. Returns how many
// members were offered.
long long offer_cone(const DesignProblem &problem, const Configuration &design,
                     const std::vector<const TaskExplicability *> &tasks,
                     const std::vector<int> &free, int max_size, Ranking &ranking);

} // namespace envdesign::design
