#include "design/reconciliation/explanation_hitting.h"

#include <algorithm>

namespace envdesign::design {
namespace {

// The search tree of least_hitting_set: a node is the elements chosen so far; its children
// choose each element, in order, of the smallest set not hit yet (the first of equally small
// ones); a leaf hits every set. The answer is the first leaf of least depth, sorted. Searched
// depth-first with a limit k = a lower bound, k+1, ...: the first leaf found within k = the
// least depth is that leaf. A node is given up when more sets not hit yet are pairwise
// disjoint than elements are left to choose (each needs one of its own), which removes no
// leaf within the limit, so the order of the leaves, and the answer, stay those of the tree.
class FirstLeastHitting {
public:
    FirstLeastHitting(const std::vector<std::vector<int>> &sets, int size)
        : sets_(sets), hits_(sets.size(), 0), of_(size), taken_(size, false) {
        for (std::size_t s = 0; s < sets.size(); ++s)
            for (int e : sets[s])
                of_[e].push_back(static_cast<int>(s));
        for (std::size_t s = 0; s < sets.size(); ++s)
            by_size_.push_back({sets[s].size(), static_cast<int>(s)});
        std::sort(by_size_.begin(), by_size_.end());
    }

    std::vector<int> solve(int at_least) {
        for (int k = std::max(at_least, disjoint_open());; ++k)
            if (search(k)) {
                std::sort(chosen_.begin(), chosen_.end());
                return chosen_;
            }
    }

private:
    bool search(int budget) {
        const std::vector<int> *open = nullptr;
        for (const auto &[size, s] : by_size_) // by size, then order: the first is the smallest
            if (!hits_[s]) {
                open = &sets_[s];
                break;
            }
        if (!open)
            return true;
        if (budget == 0 || disjoint_open() > budget)
            return false;
        for (int e : *open) {
            choose(e, 1);
            if (search(budget - 1))
                return true;
            choose(e, -1);
        }
        return false;
    }

    void choose(int e, int step) {
        for (int s : of_[e])
            hits_[s] += step;
        if (step > 0)
            chosen_.push_back(e);
        else
            chosen_.pop_back();
    }

    // How many sets not hit yet a greedy pass (smallest first) finds pairwise disjoint: a
    // lower bound on the elements still needed.
    int disjoint_open() {
        int count = 0;
        std::vector<int> marked;
        for (const auto &[size, s] : by_size_) {
            if (hits_[s] ||
                std::any_of(sets_[s].begin(), sets_[s].end(), [&](int e) { return taken_[e]; }))
                continue;
            ++count;
            for (int e : sets_[s])
                if (!taken_[e])
                    taken_[e] = true, marked.push_back(e);
        }
        for (int e : marked)
            taken_[e] = false;
        return count;
    }

    const std::vector<std::vector<int>> &sets_;
    std::vector<int> hits_;                            // per set: chosen elements in it
    std::vector<std::vector<int>> of_;                 // per element: the sets holding it
    std::vector<std::pair<std::size_t, int>> by_size_; // (size, set), ascending
    std::vector<bool> taken_;                          // scratch of disjoint_open
    std::vector<int> chosen_;                          // in the order chosen
};

} // namespace

std::vector<int> least_hitting_set(const std::vector<std::vector<int>> &sets, int size,
                                   int at_least) {
    for (const auto &s : sets)
        if (s.empty())
            return {}; // nothing hits it (the callers stop before: no explanation exists)
    if (sets.empty())
        return {};
    return FirstLeastHitting(sets, size).solve(at_least);
}

} // namespace envdesign::design
