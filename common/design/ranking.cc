#include "design/ranking.h"

#include <algorithm>
#include <queue>
#include <tuple>

namespace envdesign::design {

Ranking::Ranking(int size) : size_(std::max(1, size)) {}

bool Ranking::offer(const RankedDesign &design) {
    if (!(design.objective < INF))
        return false;
    for (const RankedDesign &d : designs_)
        if (d.configuration == design.configuration)
            return false;
    auto place = std::find_if(designs_.begin(), designs_.end(),
                              [&](const RankedDesign &d) { return ranks_before(design, d); });
    if (place - designs_.begin() >= size_)
        return false;
    designs_.insert(place, design);
    if (static_cast<int>(designs_.size()) > size_)
        designs_.pop_back();
    return true;
}

double Ranking::threshold() const { return full() ? designs_.back().objective : INF; }

bool Ranking::may_enter(double bound, std::size_t modifications) const {
    if (!(bound < INF))
        return false;
    if (!full())
        return true;
    const RankedDesign &last = designs_.back();
    if (nearly_equal(bound, last.objective))
        return modifications <= last.configuration.size();
    return bound < last.objective;
}

namespace {

// A non-empty subset of the free modifications: positions in the cheapest-first order.
struct Member {
    double weighted = 0; // beta * its cost
    std::vector<int> picks;
};

// Cheapest first, then fewer modifications: each successor below is no earlier.
struct LaterMember {
    bool operator()(const Member &a, const Member &b) const {
        return std::make_tuple(a.weighted, a.picks.size()) >
               std::make_tuple(b.weighted, b.picks.size());
    }
};

} // namespace

long long offer_cone(const DesignProblem &problem, const Configuration &design,
                     const std::vector<const TaskExplicability *> &tasks,
                     const std::vector<int> &free, int max_size, Ranking &ranking) {
    const double beta = problem.weights.beta;
    std::vector<int> order;
    for (int m : free)
        if (beta * problem.modifications[m].cost >= 0) // always true for a cone (precondition)
            order.push_back(m);
    auto weight = [&](int m) { return beta * problem.modifications[m].cost; };
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return weight(a) != weight(b) ? weight(a) < weight(b) : a < b; });
    int room =
        max_size > 0 ? max_size - static_cast<int>(design.size()) : static_cast<int>(order.size());
    if (order.empty() || room <= 0)
        return 0;
    // Every non-empty subset once: a member's successors add the next position, or move
    // its last one on. Neither is cheaper nor smaller, so a member that cannot enter has
    // no successor that can (the objective grows with beta * cost).
    std::priority_queue<Member, std::vector<Member>, LaterMember> open;
    open.push({weight(order[0]), {0}});
    long long offered = 0;
    const int k = static_cast<int>(order.size());
    while (!open.empty()) {
        Member member = open.top();
        open.pop();
        Configuration c = design;
        for (int p : member.picks)
            c.push_back(order[p]);
        std::sort(c.begin(), c.end());
        double cost = design_cost(problem, c);
        double value = objective_lower_bound(problem, cost, tasks); // every task known: exact
        if (!ranking.may_enter(value, c.size())) {
            if (ranking.full() && clearly_greater(value, ranking.threshold()))
                break; // every member left costs at least as much
            continue;
        }
        ranking.offer({value, cost, c});
        ++offered;
        int last = member.picks.back();
        if (last + 1 >= k)
            continue;
        if (static_cast<int>(member.picks.size()) < room) {
            Member grown = member;
            grown.picks.push_back(last + 1);
            grown.weighted += weight(order[last + 1]);
            open.push(std::move(grown));
        }
        member.picks.back() = last + 1;
        member.weighted = 0;
        for (int p : member.picks)
            member.weighted += weight(order[p]);
        open.push(std::move(member));
    }
    return offered;
}

} // namespace envdesign::design
