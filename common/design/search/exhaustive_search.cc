#include "design/search/exhaustive_search.h"

#include "design/search/ranking.h"

#include <algorithm>
#include <chrono>
#include <climits>
#include <numeric>
#include <set>

namespace envdesign::design {
namespace {

long long saturating_add(long long a, long long b) { return a > LLONG_MAX - b ? LLONG_MAX : a + b; }

class Search {
public:
    Search(const DesignProblem &problem, Evaluator &evaluator, const DesignSearchOptions &options,
           const std::function<void(const SearchProgress &)> &progress)
        : problem_(problem), evaluator_(evaluator), options_(options), progress_(progress),
          ranking_(options.ranking, options.ranking_all ? Padding::LISTED : Padding::LEFT_OUT) {
        int n = static_cast<int>(problem.modifications.size());
        max_size_ = options.max_design_size > 0 ? std::min(options.max_design_size, n) : n;
        std::vector<double> costs;
        for (const auto &m : problem.modifications)
            costs.push_back(m.cost);
        std::sort(costs.begin(), costs.end());
        cheapest_.push_back(0); // cheapest_[k]: the least C over k-subsets
        for (double c : costs)
            cheapest_.push_back(cheapest_.back() + c);
        costs_non_negative_ = costs.empty() || costs.front() >= 0;
    }

    DesignResult run() {
        auto start = std::chrono::steady_clock::now();
        auto &counters = result_.counters;
        for (int k = 0; k <= max_size_; ++k)
            counters.configurations_total = saturating_add(
                counters.configurations_total, binomial(problem_.modifications.size(), k));
        bool interrupted = options_.relevant ? !search_layers() : !search_all_subsets();
        if (options_.relevant)
            counters.configurations_pruned = counters.configurations_total - generated_;
        result_.limit_reached = interrupted || limit_seen_;
        result_.optimal = !result_.limit_reached && counters.configurations_pruned == 0;
        if (options_.ranking > 0)
            result_.ranking = ranking_.designs();
        close_counters(counters, evaluator_, start);
        report();
        return std::move(result_);
    }

private:
    // Every subset, by size and in spec order; false if the deadline stopped it.
    bool search_all_subsets() {
        progress_total_ = result_.counters.configurations_total;
        int n = static_cast<int>(problem_.modifications.size());
        for (int k = 0; k <= max_size_; ++k) {
            if (sizes_excluded_from(k)) {
                for (int j = k; j <= max_size_; ++j)
                    skip(binomial(n, j));
                return true;
            }
            std::vector<int> combination(k);
            std::iota(combination.begin(), combination.end(), 0);
            std::vector<Configuration> batch;
            do {
                if (options_.deadline.expired())
                    return false;
                consider(Configuration(combination), batch);
            } while (next_subset(combination, n));
            flush(batch);
        }
        return true;
    }

    // --prune relevant: layer k + 1 adds one relevant modification to a configuration of
    // layer k that the bound did not exclude.
    bool search_layers() {
        std::vector<Configuration> layer{Configuration{}};
        for (int k = 0; k <= max_size_ && !layer.empty(); ++k) {
            if (sizes_excluded_from(k)) {
                skip(static_cast<long long>(layer.size()));
                return true;
            }
            if (options_.deadline.expired())
                return false;
            generated_ += static_cast<long long>(layer.size());
            progress_total_ = generated_;
            std::vector<Configuration> batch;
            std::set<Configuration> expand;
            for (const auto &c : layer)
                if (consider(c, batch) || !costs_non_negative_)
                    expand.insert(c);
            flush(batch);
            if (k == max_size_)
                break;
            layer = next_layer(expand);
        }
        return !options_.deadline.expired();
    }

    std::vector<Configuration> next_layer(const std::set<Configuration> &parents) {
        std::set<Configuration> children;
        for (const auto &parent : parents) {
            if (options_.deadline.expired())
                break;
            for (int m : options_.relevant(parent)) {
                if (std::binary_search(parent.begin(), parent.end(), m))
                    continue;
                Configuration child = parent;
                child.insert(std::upper_bound(child.begin(), child.end(), m), m);
                children.insert(std::move(child));
            }
        }
        return {children.begin(), children.end()};
    }

    // Queues `c` for evaluation unless the bound excludes it; false if it was excluded.
    bool consider(Configuration c, std::vector<Configuration> &batch) {
        if (cannot_win(unevaluated(c))) {
            skip(1);
            return false;
        }
        batch.push_back(std::move(c));
        if (static_cast<int>(batch.size()) >= std::max(1, options_.batch_size))
            flush(batch);
        return true;
    }

    // True when no subset of size k or more can beat the best design found (or, with a
    // ranking, enter it).
    bool sizes_excluded_from(int k) const {
        if (!result_.best)
            return false;
        double least = *std::min_element(cheapest_.begin() + k, cheapest_.begin() + max_size_ + 1);
        return clearly_greater(objective_lower_bound(problem_, least, {}),
                               ranking_limit(result_, ranking_));
    }

    bool cannot_win(const ConfigurationEvaluation &partial) const {
        if (!result_.best)
            return false;
        double bound =
            own_lower_bound(problem_, design_cost(problem_, partial.configuration), partial);
        return clearly_greater(bound, ranking_limit(result_, ranking_));
    }

    void flush(std::vector<Configuration> &batch) {
        if (batch.empty())
            return;
        std::vector<ConfigurationEvaluation> requests;
        for (auto &c : batch)
            requests.push_back(unevaluated(std::move(c)));
        EvaluationCallbacks callbacks;
        callbacks.abandon = [&](const ConfigurationEvaluation &partial) {
            return cannot_win(partial);
        };
        callbacks.done = [&](ConfigurationEvaluation e) { collect(std::move(e)); };
        evaluator_.evaluate(requests, options_.deadline, callbacks);
        batch.clear();
    }

    void collect(ConfigurationEvaluation e) {
        auto &counters = result_.counters;
        if (e.status == EvaluationStatus::LIMIT) {
            limit_seen_ = true;
            return;
        }
        ++done_;
        if (e.status == EvaluationStatus::CUT_OFF) {
            ++counters.configurations_abandoned;
            report();
            return;
        }
        ++counters.configurations_evaluated;
        std::vector<TaskExplicability> tasks;
        for (auto &t : e.tasks)
            tasks.push_back(std::move(*t));
        consider_design(problem_, e.configuration, std::move(tasks), result_, ranking_);
        report();
    }

    void skip(long long count) {
        result_.counters.configurations_skipped =
            saturating_add(result_.counters.configurations_skipped, count);
        done_ = saturating_add(done_, count);
        report();
    }

    void report() const {
        if (!progress_)
            return;
        EvaluatorCounters e = evaluator_.counters();
        progress_({done_, progress_total_, result_.best ? result_.best->objective.value : INF,
                   e.planner_runs, e.cache_hits});
    }

    const DesignProblem &problem_;
    Evaluator &evaluator_;
    const DesignSearchOptions &options_;
    const std::function<void(const SearchProgress &)> &progress_;
    int max_size_ = 0;
    std::vector<double> cheapest_;
    bool costs_non_negative_ = true;
    DesignResult result_;
    Ranking ranking_; // the N best (options.ranking), pruned against as the best alone is
    long long done_ = 0;
    long long progress_total_ = 0;
    long long generated_ = 0;
    bool limit_seen_ = false;
};

} // namespace

DesignResult search_exhaustive(const DesignProblem &problem, Evaluator &evaluator,
                               const DesignSearchOptions &options,
                               const std::function<void(const SearchProgress &)> &progress) {
    return Search(problem, evaluator, options, progress).run();
}

} // namespace envdesign::design
