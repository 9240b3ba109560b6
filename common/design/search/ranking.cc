#include "design/search/ranking.h"

#include <algorithm>
#include <queue>
#include <tuple>

namespace envdesign::design {

// The best design alone is never padded (without the modification that would pad it, a
// design of no worse objective and fewer modifications ranks before it): with one design,
// nothing is left out, and the best found is the limit at once.
Ranking::Ranking(int size, Padding padding)
    : size_(std::max(1, size)), padding_(size <= 1 ? Padding::LISTED : padding) {}

bool Ranking::offer(const RankedDesign &design) {
    if (padding_ == Padding::LEFT_OUT &&
        known_.emplace(design.configuration, design.objective).second)
        reclassify(); // it may pad or confirm designs one modification larger
    if (!(design.objective < INF))
        return false;
    for (const Entry &e : entries_)
        if (e.design.configuration == design.configuration)
            return false;
    if (full() && !ranks_before(design, entries_[last_].design))
        return false;
    auto place = std::find_if(entries_.begin(), entries_.end(),
                              [&](const Entry &e) { return ranks_before(design, e.design); });
    Entry entry{design};
    classify(entry);
    entries_.insert(place, entry);
    list();
    return true;
}

void Ranking::add_cone(const RankedDesign &base, const std::vector<int> &free,
                       const std::vector<double> &weights, int max_size) {
    if (padding_ != Padding::LEFT_OUT || !(base.objective < INF) || free.empty())
        return;
    cones_.push_back({base, free, weights, max_size});
    reclassify();
}

double Ranking::threshold() const { return full() ? entries_[last_].design.objective : INF; }

bool Ranking::may_enter(double bound, std::size_t modifications) const {
    if (!(bound < INF))
        return false;
    if (!full())
        return true;
    const RankedDesign &last = entries_[last_].design;
    if (nearly_equal(bound, last.objective))
        return modifications <= last.configuration.size();
    return bound < last.objective;
}

// The objective of `c` if it was offered, or is a member of a cone: base + E, E a non-empty
// subset of the cone's free modifications, the base's objective plus E's weights.
std::optional<double> Ranking::known_objective(const Configuration &c) const {
    if (auto it = known_.find(c); it != known_.end())
        return it->second;
    for (const Cone &cone : cones_) {
        const Configuration &b = cone.base.configuration;
        if (c.size() <= b.size() ||
            (cone.max_size > 0 && c.size() > static_cast<std::size_t>(cone.max_size)) ||
            !std::includes(c.begin(), c.end(), b.begin(), b.end()))
            continue;
        double value = cone.base.objective;
        bool member = true;
        for (int m : c) {
            if (std::binary_search(b.begin(), b.end(), m))
                continue;
            auto f = std::lower_bound(cone.free.begin(), cone.free.end(), m);
            member = member && f != cone.free.end() && *f == m;
            if (!member)
                break;
            value += cone.weights[static_cast<std::size_t>(f - cone.free.begin())];
        }
        if (member)
            return value;
    }
    return std::nullopt;
}

// Padded: some design one modification smaller has an objective not clearly greater.
// Confirmed: every such design's objective is known.
void Ranking::classify(Entry &entry) const {
    if (padding_ != Padding::LEFT_OUT) {
        entry.confirmed = true;
        return;
    }
    const Configuration &d = entry.design.configuration;
    bool all_known = true;
    for (std::size_t i = 0; i < d.size(); ++i) {
        Configuration smaller = d;
        smaller.erase(smaller.begin() + static_cast<std::ptrdiff_t>(i));
        std::optional<double> value = known_objective(smaller);
        if (!value) {
            all_known = false;
            continue;
        }
        if (!clearly_greater(*value, entry.design.objective)) {
            entry.padded = entry.confirmed = true;
            return;
        }
    }
    entry.confirmed = all_known;
}

// Padded and confirmed are final; the other entries may change with what became known.
void Ranking::reclassify() {
    bool changed = false;
    for (Entry &e : entries_)
        if (!e.confirmed) {
            classify(e);
            changed = changed || e.confirmed;
        }
    if (changed)
        list();
}

// The listed designs: the first `size` entries not padded. The ranking is full at the
// `size`-th entry confirmed not padded; entries after it can never be listed (whatever
// enters later ranks before them), so they are dropped.
void Ranking::list() {
    listed_.clear();
    last_ = SIZE_MAX;
    int counted = 0;
    for (std::size_t i = 0; i < entries_.size(); ++i) {
        if (entries_[i].padded)
            continue;
        if (static_cast<int>(listed_.size()) < size_)
            listed_.push_back(entries_[i].design);
        if (entries_[i].confirmed && ++counted == size_) {
            last_ = i;
            entries_.resize(i + 1);
            return;
        }
    }
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

using MemberQueue = std::priority_queue<Member, std::vector<Member>, LaterMember>;

// What adding `m` adds to a design's objective: beta * its cost.
double cone_weight(const DesignProblem &problem, int m) {
    return problem.weights.beta * problem.modifications[m].cost;
}

// The free modifications of non-negative weighted cost, cheapest first, then by index.
std::vector<int> cheapest_first(const DesignProblem &problem, const std::vector<int> &free) {
    std::vector<int> order;
    for (int m : free)
        if (cone_weight(problem, m) >= 0) // always true for a cone (precondition)
            order.push_back(m);
    auto weight = [&](int m) { return cone_weight(problem, m); };
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return weight(a) != weight(b) ? weight(a) < weight(b) : a < b; });
    return order;
}

// With Padding::LEFT_OUT every member is padded: the cone is recorded whole, by its free
// modifications ascending (`order`, cheapest first, is not).
void record_cone(const DesignProblem &problem, const Configuration &design,
                 const std::vector<const TaskExplicability *> &tasks, const std::vector<int> &order,
                 int max_size, Ranking &ranking) {
    std::vector<int> ascending = order;
    std::sort(ascending.begin(), ascending.end());
    std::vector<double> weights;
    for (int m : ascending)
        weights.push_back(cone_weight(problem, m));
    double cost = design_cost(problem, design);
    ranking.add_cone({objective_lower_bound(problem, cost, tasks), cost, design}, ascending,
                     weights, max_size);
}

// A member's successors: it with the next position added (while it has fewer than `room`
// picks), and it with its last position moved on.
void push_successors(Member member, const DesignProblem &problem, const std::vector<int> &order,
                     int room, MemberQueue &open) {
    int last = member.picks.back();
    if (last + 1 >= static_cast<int>(order.size()))
        return;
    if (static_cast<int>(member.picks.size()) < room) {
        Member grown = member;
        grown.picks.push_back(last + 1);
        grown.weighted += cone_weight(problem, order[last + 1]);
        open.push(std::move(grown));
    }
    member.picks.back() = last + 1;
    member.weighted = 0;
    for (int p : member.picks)
        member.weighted += cone_weight(problem, order[p]);
    open.push(std::move(member));
}

// Offers the members of `design` + E, E picked from `order` (cheapest first) with at most
// `room` modifications. Returns how many were offered.
long long offer_members(const DesignProblem &problem, const Configuration &design,
                        const std::vector<const TaskExplicability *> &tasks,
                        const std::vector<int> &order, int room, Ranking &ranking) {
    // Every non-empty subset once: a member's successors add the next position, or move
    // its last one on. Neither is cheaper nor smaller, so a member that cannot enter has
    // no successor that can (the objective grows with beta * cost).
    MemberQueue open;
    open.push({cone_weight(problem, order[0]), {0}});
    long long offered = 0;
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
        push_successors(std::move(member), problem, order, room, open);
    }
    return offered;
}

} // namespace

long long offer_cone(const DesignProblem &problem, const Configuration &design,
                     const std::vector<const TaskExplicability *> &tasks,
                     const std::vector<int> &free, int max_size, Ranking &ranking) {
    std::vector<int> order = cheapest_first(problem, free);
    int room =
        max_size > 0 ? max_size - static_cast<int>(design.size()) : static_cast<int>(order.size());
    if (order.empty() || room <= 0)
        return 0;
    if (ranking.padding() == Padding::LEFT_OUT) {
        record_cone(problem, design, tasks, order, max_size, ranking);
        return 0;
    }
    return offer_members(problem, design, tasks, order, room, ranking);
}

} // namespace envdesign::design
