#pragma once
// The N best designs (`envdesign design --ranking N`, DesignResult::ranking), best first in
// SPEC.md's order (ranks_before). Only designs of finite objective are ranked: an infinite
// objective never beats a finite one, and designs that leave a task without a plan are not
// worth listing.
//
// Padded designs are left out unless asked for (Padding::LISTED, --ranking-all): a design is
// padded when removing one of its modifications gives an objective that is not clearly
// greater (objective.h's nearly_equal counts as equal), i.e. that modification does not pay
// for itself. Such a subset always ranks before the design (a lower objective, or an equal
// one with fewer modifications), so a design is padded exactly when a design one
// modification smaller, offered here, ranks before it; the witness search's cones
// (offer_cone) are all padded and are kept as cones, not listed.
//
// The searches prune against the ranking's last listed design once N are listed
// (threshold()): a bound clearly above its objective, or nearly equal to it with more
// modifications, cannot enter. docs/design-search.md ("Ranking") says why each pruning rule
// stays exact, padded designs left out included.
//
//   Ranking ranking(options.ranking);
//   ranking.offer({objective, cost, configuration});
//   if (!ranking.may_enter(bound, configuration.size())) ...   // skip the subtree

#include "design/objective/objective.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace envdesign::design {

// What a ranking without padded designs says of itself (a note of the result).
inline constexpr const char *RANKING_NOTE =
    "the ranking lists only designs in which every modification pays for itself (removing any "
    "one makes the objective clearly worse); designs padded with a modification that does not "
    "were left out (--ranking-all lists them)";

// Whether the ranking lists padded designs (above).
enum class Padding {
    LEFT_OUT, // the default: only designs in which every modification pays for itself
    LISTED,   // every design (--ranking-all)
};

class Ranking {
public:
    // `size` designs listed at most; 0 counts as 1 (only the best, which is never padded).
    explicit Ranking(int size = 1, Padding padding = Padding::LEFT_OUT);

    int size() const { return size_; }
    Padding padding() const { return padding_; }
    // Whether `size` designs are proven to rank before threshold(): listed, and with
    // Padding::LEFT_OUT confirmed (below).
    bool full() const { return last_ < entries_.size(); }

    // Puts `design` in its place when it ranks before the last design full() counts (or the
    // ranking is not full); a configuration offered twice is ranked once. True if it entered
    // (with Padding::LEFT_OUT it may have entered padded: kept, not listed).
    bool offer(const RankedDesign &design);

    // Every member of the cone `base` + E (offer_cone): with Padding::LEFT_OUT all of them are
    // padded, and they are kept as one record, whose members' objectives are known (a design
    // one modification larger may be padded by one). `weights[i]` is beta * the cost of
    // `free[i]`.
    void add_cone(const RankedDesign &base, const std::vector<int> &free,
                  const std::vector<double> &weights, int max_size);

    // The objective of the last design full() counts when full, else INF.
    double threshold() const;

    // Whether a design whose objective is at least `bound`, with at least `modifications`
    // modifications, could still enter.
    bool may_enter(double bound, std::size_t modifications) const;

    // The listed designs, best first.
    const std::vector<RankedDesign> &designs() const { return listed_; }

private:
    // With Padding::LEFT_OUT a design is *confirmed* when the objective of every design one
    // modification smaller is known (offered, or a cone's member): no later offer can pad it.
    // Only confirmed designs count for pruning: a design listed now may be padded by a
    // subset offered later, and the list would then be short of what was pruned.
    struct Entry {
        RankedDesign design;
        bool padded = false;
        bool confirmed = false;
    };
    struct Cone {
        RankedDesign base;
        std::vector<int> free; // ascending
        std::vector<double> weights;
        int max_size = 0; // 0: no limit
    };

    std::optional<double> known_objective(const Configuration &c) const;
    void classify(Entry &entry) const;
    void reclassify();
    void list();

    int size_;
    Padding padding_;
    std::vector<Entry> entries_;            // in rank order, down to the last one full() counts
    std::size_t last_ = SIZE_MAX;           // that one, when full
    std::map<Configuration, double> known_; // every design offered (Padding::LEFT_OUT)
    std::vector<Cone> cones_;
    std::vector<RankedDesign> listed_;
};

// Offers to `ranking` every design `design` + E, E a non-empty subset of `free` (ascending,
// none in `design`, each of non-negative weighted cost beta * cost), with at most `max_size`
// modifications in all (0: no limit), whose tasks have the values `tasks` of `design` (every
// task known). This is the witness search's cone: the objective of each member is known
// without planning. Members are visited cheapest first, and a member that cannot enter
// ends its branch, so the work grows with what enters, not with 2^|free|. Returns how many
// members were offered. With Padding::LEFT_OUT every member is padded (removing a member's
// free modification lowers the objective by beta * its cost >= 0): the cone is recorded
// (Ranking::add_cone) and none is offered.
long long offer_cone(const DesignProblem &problem, const Configuration &design,
                     const std::vector<const TaskExplicability *> &tasks,
                     const std::vector<int> &free, int max_size, Ranking &ranking);

} // namespace envdesign::design
