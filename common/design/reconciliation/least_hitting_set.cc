#include "design/reconciliation/explanation_hitting.h"

#include <algorithm>

namespace envdesign::design {
namespace {

// least_hitting_set: the lexicographically least of the least hitting sets, so that an
// explanation does not depend on which plans earlier searches met (explanation_hitting.h);
// some_least_hitting_set stops after the first step. First the least size k: a depth-first search
// with a limit k = a lower bound, k+1, ... that branches on the smallest set not hit yet. Then the
// answer element by element: the least element e such that some hitting set of size k holds the
// elements fixed so far, e, and otherwise only elements above e; each such question is the same
// search, with the elements at or below e barred. A node is given up when more sets not hit yet are
// pairwise disjoint in their allowed elements than elements are left to choose (each needs one of
// its own), or when a set not hit yet has no allowed element.
class LexLeastHitting {
public:
    LexLeastHitting(const std::vector<std::vector<int>> &sets, int size)
        : sets_(sets), hits_(sets.size(), 0), of_(size), taken_(size, false) {
        for (std::size_t s = 0; s < sets.size(); ++s)
            for (int e : sets[s])
                of_[e].push_back(static_cast<int>(s));
        for (std::size_t s = 0; s < sets.size(); ++s)
            by_size_.push_back({sets[s].size(), static_cast<int>(s)});
        std::sort(by_size_.begin(), by_size_.end());
    }

    // A least hitting set, ascending: the first the search meets.
    std::vector<int> any_least(int at_least) {
        int k = std::max(at_least, disjoint_open(static_cast<int>(of_.size())));
        while (!search(k))
            ++k;
        std::vector<int> out = found_;
        std::sort(out.begin(), out.end());
        return out;
    }

    std::vector<int> solve(int at_least) {
        any_least(at_least);
        // `best`: a least hitting set whose first elements are `answer` (the last one found);
        // its next element needs no search, only the lesser ones do.
        std::vector<int> best = found_, answer;
        std::sort(best.begin(), best.end());
        for (std::size_t i = 0; i < best.size(); ++i) {
            for (int e = answer.empty() ? 0 : answer.back() + 1; e <= best[i]; ++e) {
                if (e < best[i] && !hits_open(e))
                    continue; // a least hitting set has no element that hits nothing new
                choose(e, 1);
                allowed_from_ = e + 1;
                if (e == best[i] || search(static_cast<int>(best.size() - i) - 1)) {
                    answer.push_back(e);
                    if (e < best[i]) {
                        best = answer;
                        std::sort(found_.begin(), found_.end());
                        best.insert(best.end(), found_.begin(), found_.end());
                    }
                    break;
                }
                choose(e, -1);
            }
        }
        return answer;
    }

private:
    // Whether `budget` more elements, all from allowed_from_ on, hit every set not hit yet
    // (then found_ holds them); leaves the hits as it found them.
    bool search(int budget) {
        const std::vector<int> *open = nullptr;
        for (const auto &[size, s] : by_size_) // by size, then order: the first is the smallest
            if (!hits_[s]) {
                open = &sets_[s];
                break;
            }
        if (!open) {
            found_ = path_;
            return true;
        }
        if (budget == 0 || disjoint_open(budget) > budget)
            return false;
        for (int e : *open) {
            if (e < allowed_from_)
                continue;
            choose(e, 1);
            path_.push_back(e);
            bool found = search(budget - 1);
            path_.pop_back();
            choose(e, -1);
            if (found)
                return true;
        }
        return false;
    }

    bool hits_open(int e) const {
        return std::any_of(of_[e].begin(), of_[e].end(), [&](int s) { return hits_[s] == 0; });
    }

    void choose(int e, int step) {
        for (int s : of_[e])
            hits_[s] += step;
    }

    // How many sets not hit yet a greedy pass (smallest first) finds pairwise disjoint in
    // their allowed elements: a lower bound on the elements still needed (a set with none
    // allowed counts as more than any budget). It stops once the count passes `limit`.
    int disjoint_open(int limit) {
        int count = 0;
        marked_.clear();
        for (const auto &[size, s] : by_size_) {
            if (hits_[s])
                continue;
            bool any = false, shared = false;
            for (int e : sets_[s])
                if (e >= allowed_from_) {
                    any = true;
                    shared = shared || taken_[e];
                }
            if (!any) {
                count = static_cast<int>(of_.size()) + 1;
                break;
            }
            if (shared)
                continue;
            for (int e : sets_[s])
                if (e >= allowed_from_)
                    taken_[e] = true, marked_.push_back(e);
            if (++count > limit)
                break;
        }
        for (int e : marked_)
            taken_[e] = false;
        return count;
    }

    const std::vector<std::vector<int>> &sets_;
    std::vector<int> hits_;                            // per set: chosen elements in it
    std::vector<std::vector<int>> of_;                 // per element: the sets holding it
    std::vector<std::pair<std::size_t, int>> by_size_; // (size, set), ascending
    std::vector<bool> taken_;                          // scratch of disjoint_open
    std::vector<int> marked_;                          // scratch of disjoint_open
    int allowed_from_ = 0;                             // elements below it are barred
    std::vector<int> path_;                            // search()'s elements, as chosen
    std::vector<int> found_;                           // the last hitting elements search() found
};

} // namespace

std::vector<int> some_least_hitting_set(const std::vector<std::vector<int>> &sets, int size,
                                        int at_least) {
    for (const auto &s : sets)
        if (s.empty())
            return {};
    if (sets.empty())
        return {};
    return LexLeastHitting(sets, size).any_least(at_least);
}

std::vector<int> least_hitting_set(const std::vector<std::vector<int>> &sets, int size,
                                   int at_least) {
    for (const auto &s : sets)
        if (s.empty())
            return {}; // nothing hits it (the callers stop before: no explanation exists)
    if (sets.empty())
        return {};
    return LexLeastHitting(sets, size).solve(at_least);
}

} // namespace envdesign::design
