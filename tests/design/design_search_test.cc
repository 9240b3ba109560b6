// The exhaustive search over configurations against a written-out enumeration, on scripted
// evaluators (no planning): bounds must never change the answer, ties follow SPEC.md, time
// limits give "best found". Scripted answers have nothing to do with the modifications'
// edits, so only the exhaustive search applies (the witness search reads the edits:
// witness_search_test.cc).

#include "design/search/design_search.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <functional>
#include <map>

namespace envdesign::design {
namespace {

using Script = std::function<std::vector<TaskExplicability>(const Configuration &)>;

TaskExplicability solved(double ie, double robot_cost) {
    TaskExplicability t;
    t.status = ExplicabilityStatus::SOLVED;
    t.ie = ie;
    t.robot_cost = robot_cost;
    return t;
}

// Answers from a script, task by task, honouring `abandon`; after `budget` task
// evaluations every answer is LIMIT (a deadline that passed).
class ScriptedEvaluator : public Evaluator {
public:
    ScriptedEvaluator(Script script, long long budget = -1)
        : script_(std::move(script)), budget_(budget) {}

    void evaluate(const std::vector<ConfigurationEvaluation> &batch, const Deadline &,
                  const EvaluationCallbacks &callbacks) override {
        for (const auto &request : batch) {
            const Configuration &configuration = request.configuration;
            auto answers = script_(configuration);
            ConfigurationEvaluation e{configuration,
                                      EvaluationStatus::COMPLETE,
                                      std::vector<std::optional<TaskExplicability>>(answers.size()),
                                      {},
                                      {}};
            for (std::size_t t = 0; t < answers.size() && e.status == EvaluationStatus::COMPLETE;
                 ++t) {
                if (callbacks.abandon(e))
                    e.status = EvaluationStatus::CUT_OFF;
                else if (budget_ >= 0 && counters_.task_evaluations >= budget_)
                    e.status = EvaluationStatus::LIMIT;
                else
                    ++counters_.task_evaluations, e.tasks[t] = answers[t];
            }
            evaluated_.push_back(configuration);
            callbacks.done(e);
        }
    }
    EvaluatorCounters counters() const override { return counters_; }
    const std::vector<Configuration> &evaluated() const { return evaluated_; }

private:
    Script script_;
    long long budget_;
    EvaluatorCounters counters_;
    std::vector<Configuration> evaluated_;
};

DesignSearchOptions exhaustive_search() {
    DesignSearchOptions options;
    options.method = SearchMethod::EXHAUSTIVE;
    return options;
}

DesignProblem synthetic(std::vector<double> costs, std::vector<double> probabilities,
                        ObjectiveWeights w) {
    DesignProblem problem;
    for (std::size_t i = 0; i < costs.size(); ++i)
        problem.modifications.push_back({"m" + std::to_string(i), costs[i], {}});
    for (double p : probabilities)
        problem.tasks.push_back({"t", p, {}, {}});
    problem.weights = w;
    return problem;
}

// Task t's IE is 1 + |target_t - (sum of chosen indices + 1)|, robot cost 5 + #chosen + t:
// some designs help one task and hurt the other.
std::vector<TaskExplicability> landscape(const Configuration &c) {
    double s = 1;
    for (int m : c)
        s += m + 1;
    return {solved(std::exp(std::abs(6.0 - s)), 5.0 + c.size()),
            solved(std::exp(std::abs(4.0 - s) / 2), 6.0 + c.size())};
}

// The objective written out again, and the best of all subsets by SPEC.md's rules.
struct Exhaustive {
    Configuration best;
    double objective = INFINITY;
};

Exhaustive exhaustive(const DesignProblem &p, const Script &script, int max_size) {
    int n = static_cast<int>(p.modifications.size());
    double f = (1 - std::pow(p.weights.gamma, p.weights.horizon)) / (1 - p.weights.gamma);
    Exhaustive out;
    double best_cost = 0;
    for (int mask = 0; mask < (1 << n); ++mask) {
        Configuration c;
        double cost = 0;
        for (int m = 0; m < n; ++m)
            if (mask >> m & 1)
                c.push_back(m), cost += p.modifications[m].cost;
        if (max_size > 0 && static_cast<int>(c.size()) > max_size)
            continue;
        auto tasks = script(c);
        double ie = 0, rc = 0;
        for (std::size_t t = 0; t < tasks.size(); ++t)
            ie += p.tasks[t].probability * tasks[t].ie,
                rc += p.tasks[t].probability * tasks[t].robot_cost;
        double value = p.weights.alpha * f * ie + p.weights.beta * cost +
                       p.weights.kappa * p.weights.horizon * rc;
        bool tie = std::abs(value - out.objective) <= 1e-9 * std::max(1.0, std::abs(value));
        bool better = !tie                          ? value < out.objective
                      : c.size() != out.best.size() ? c.size() < out.best.size()
                      : cost != best_cost           ? cost < best_cost
                                                    : c < out.best;
        if (better)
            out = {c, value}, best_cost = cost;
    }
    return out;
}

struct Setting {
    double beta;
    int horizon;
    int max_size;
};

void PrintTo(const Setting &s, std::ostream *out) {
    *out << "beta " << s.beta << ", T " << s.horizon << ", max size " << s.max_size;
}

class AgainstExhaustive : public ::testing::TestWithParam<Setting> {};

TEST_P(AgainstExhaustive, BoundsNeverChangeTheAnswer) {
    const Setting s = GetParam();
    DesignProblem p = synthetic({1, 2, 0.5, 3, 1}, {0.3, 0.7}, {1, s.beta, 0.25, 0.9, s.horizon});
    ScriptedEvaluator evaluator(landscape);
    DesignSearchOptions options = exhaustive_search();
    options.max_design_size = s.max_size;
    DesignResult r = search_design(p, evaluator, options);
    Exhaustive expected = exhaustive(p, landscape, s.max_size);
    ASSERT_TRUE(r.best);
    EXPECT_EQ(r.best->ranked.configuration, expected.best);
    EXPECT_NEAR(r.best->objective.value, expected.objective, 1e-9);
    EXPECT_TRUE(r.optimal);
    for (const auto &c : evaluator.evaluated())
        EXPECT_TRUE(s.max_size == 0 || static_cast<int>(c.size()) <= s.max_size);
    const auto &k = r.counters;
    EXPECT_EQ(k.configurations_evaluated + k.configurations_abandoned + k.configurations_skipped,
              k.configurations_total);
}

// Every subset's objective written out again, sorted by SPEC.md's rules: the reference
// ranking (ties within 1e-9: fewer modifications, then lower cost, then spec order).
std::vector<RankedDesign> every_subset_ranked(const DesignProblem &p, const Script &script,
                                              int max_size) {
    int n = static_cast<int>(p.modifications.size());
    double f = (1 - std::pow(p.weights.gamma, p.weights.horizon)) / (1 - p.weights.gamma);
    std::vector<RankedDesign> all;
    for (int mask = 0; mask < (1 << n); ++mask) {
        Configuration c;
        double cost = 0;
        for (int m = 0; m < n; ++m)
            if (mask >> m & 1)
                c.push_back(m), cost += p.modifications[m].cost;
        if (max_size > 0 && static_cast<int>(c.size()) > max_size)
            continue;
        auto tasks = script(c);
        double ie = 0, rc = 0;
        for (std::size_t t = 0; t < tasks.size(); ++t)
            ie += p.tasks[t].probability * tasks[t].ie,
                rc += p.tasks[t].probability * tasks[t].robot_cost;
        all.push_back({p.weights.alpha * f * ie + p.weights.beta * cost +
                           p.weights.kappa * p.weights.horizon * rc,
                       cost, c});
    }
    std::sort(all.begin(), all.end(), [](const RankedDesign &a, const RankedDesign &b) {
        if (std::abs(a.objective - b.objective) > 1e-9 * std::max(1.0, std::abs(a.objective)))
            return a.objective < b.objective;
        if (a.configuration.size() != b.configuration.size())
            return a.configuration.size() < b.configuration.size();
        if (a.design_cost != b.design_cost)
            return a.design_cost < b.design_cost;
        return a.configuration < b.configuration;
    });
    return all;
}

// --ranking N: the bounds compare with the N-th best, and never change the N best.
TEST_P(AgainstExhaustive, BoundsNeverChangeTheRanking) {
    const Setting s = GetParam();
    DesignProblem p = synthetic({1, 2, 0.5, 3, 1}, {0.3, 0.7}, {1, s.beta, 0.25, 0.9, s.horizon});
    std::vector<RankedDesign> all = every_subset_ranked(p, landscape, s.max_size);
    for (int n : {2, 3, 7, 40}) {
        ScriptedEvaluator evaluator(landscape);
        DesignSearchOptions options = exhaustive_search();
        options.max_design_size = s.max_size;
        options.ranking = n;
        options.ranking_all = true; // every subset, padded ones too (ranking_test.cc: without)
        DesignResult r = search_design(p, evaluator, options);
        EXPECT_TRUE(r.optimal);
        ASSERT_EQ(r.ranking.size(), std::min<std::size_t>(n, all.size())) << "N = " << n;
        for (std::size_t i = 0; i < r.ranking.size(); ++i) {
            EXPECT_EQ(r.ranking[i].configuration, all[i].configuration)
                << "N = " << n << ", rank " << i + 1;
            EXPECT_NEAR(r.ranking[i].objective, all[i].objective, 1e-9);
        }
        if (n == 40) { // more than every subset: nothing may be skipped
            EXPECT_EQ(r.counters.configurations_skipped + r.counters.configurations_abandoned, 0);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Settings, AgainstExhaustive,
                         ::testing::Values(Setting{30, 1, 0}, Setting{30, 10, 0}, Setting{1, 10, 0},
                                           Setting{0.25, 10, 0}, Setting{0.25, 10, 2},
                                           Setting{5, 3, 1}, Setting{0, 1, 0}));

TEST(DesignSearch, AnExpensiveDesignSpaceIsSkippedByTheBound) {
    // Baseline objective: IE 1 everywhere except... every IE is 1: nothing can beat {}.
    DesignProblem p = synthetic({10, 10, 10, 10}, {1}, {1, 1, 1, 1, 1});
    ScriptedEvaluator evaluator([](const Configuration &) { return std::vector{solved(1, 3)}; });
    DesignResult r = search_design(p, evaluator, exhaustive_search());
    EXPECT_TRUE(r.optimal);
    EXPECT_TRUE(r.best->ranked.configuration.empty());
    EXPECT_EQ(evaluator.evaluated().size(), 1u); // objective 4 < 1 + 10: sizes >= 1 skipped
    EXPECT_EQ(r.counters.configurations_skipped, 15);
}

TEST(DesignSearch, EqualDesignsGoToTheEarlierModification) {
    DesignProblem p = synthetic({1, 1, 1}, {1}, {1, 1, 0, 1, 1});
    // m1 and m2 both fix the task; m0 does nothing.
    ScriptedEvaluator evaluator([](const Configuration &c) {
        bool fixed = std::find(c.begin(), c.end(), 1) != c.end() ||
                     std::find(c.begin(), c.end(), 2) != c.end();
        return std::vector{solved(fixed ? 1 : 100, 1)};
    });
    DesignResult r = search_design(p, evaluator, exhaustive_search());
    EXPECT_EQ(r.best->ranked.configuration, Configuration{1});
}

TEST(DesignSearch, EqualObjectivesGoToTheCheaperDesign) {
    DesignProblem p = synthetic({3, 2}, {1}, {1, 0, 0, 1, 1}); // beta 0: C does not count
    ScriptedEvaluator evaluator(
        [](const Configuration &c) { return std::vector{solved(c.empty() ? 9 : 1, 1)}; });
    DesignResult r = search_design(p, evaluator, exhaustive_search());
    EXPECT_EQ(r.best->ranked.configuration, Configuration{1});
}

TEST(DesignSearch, AnInfiniteBaselineIsBeatenByAnyFiniteDesign) {
    DesignProblem p = synthetic({100, 100}, {1}, {1, 1, 1, 1, 1});
    ScriptedEvaluator evaluator([](const Configuration &c) {
        if (c == Configuration{1})
            return std::vector{solved(1, 1)};
        TaskExplicability t;
        t.status = ExplicabilityStatus::INEXPLICABLE;
        return std::vector{t};
    });
    DesignResult r = search_design(p, evaluator, exhaustive_search());
    EXPECT_EQ(r.best->ranked.configuration, Configuration{1});
    EXPECT_TRUE(std::isinf(r.baseline->objective.value));
}

TEST(DesignSearch, ATimeLimitGivesTheBestFoundSoFar) {
    DesignProblem p = synthetic({1, 2, 0.5, 3, 1}, {0.3, 0.7}, {1, 0.25, 0.25, 0.9, 10});
    ScriptedEvaluator evaluator(landscape, 9); // the budget runs out during size 1
    DesignResult r = search_design(p, evaluator, exhaustive_search());
    EXPECT_FALSE(r.optimal);
    EXPECT_TRUE(r.limit_reached);
    ASSERT_TRUE(r.best);
    EXPECT_LE(r.best->ranked.configuration.size(), 1u);
    EXPECT_TRUE(r.baseline);
}

// Designs of infinite objective are not ranked: only {m1} has a plan for every task.
TEST(DesignSearch, InfiniteObjectivesAreNotRanked) {
    DesignProblem p = synthetic({100, 100}, {1}, {1, 1, 1, 1, 1});
    ScriptedEvaluator evaluator([](const Configuration &c) {
        if (c == Configuration{1})
            return std::vector{solved(1, 1)};
        TaskExplicability t;
        t.status = ExplicabilityStatus::INEXPLICABLE;
        return std::vector{t};
    });
    DesignSearchOptions options = exhaustive_search();
    options.ranking = 3;
    DesignResult r = search_design(p, evaluator, options);
    ASSERT_EQ(r.ranking.size(), 1u);
    EXPECT_EQ(r.ranking[0].configuration, Configuration{1});
    EXPECT_NEAR(r.ranking[0].objective, 1 + 100 + 1, 1e-9); // IE 1, C 100, robot cost 1
}

// A limit leaves the best ones found: real designs, in order, not proven.
TEST(DesignSearch, ATimeLimitGivesTheBestRankingFoundSoFar) {
    DesignProblem p = synthetic({1, 2, 0.5, 3, 1}, {0.3, 0.7}, {1, 0.25, 0.25, 0.9, 10});
    ScriptedEvaluator evaluator(landscape, 9); // the budget runs out during size 1
    DesignSearchOptions options = exhaustive_search();
    options.ranking = 3;
    options.ranking_all = true;
    DesignResult r = search_design(p, evaluator, options);
    EXPECT_FALSE(r.optimal);
    ASSERT_EQ(r.ranking.size(), 3u); // {} and 3 designs of size 1 were evaluated in full
    EXPECT_EQ(r.ranking[0].configuration, r.best->ranked.configuration);
    std::vector<RankedDesign> all = every_subset_ranked(p, landscape, 0);
    for (std::size_t i = 0; i < r.ranking.size(); ++i) {
        auto same = std::find_if(all.begin(), all.end(), [&](const RankedDesign &d) {
            return d.configuration == r.ranking[i].configuration;
        });
        ASSERT_NE(same, all.end());
        EXPECT_NEAR(r.ranking[i].objective, same->objective, 1e-9);
        EXPECT_LE(r.ranking[i].configuration.size(), 1u);
        if (i > 0) {
            EXPECT_TRUE(ranks_before(r.ranking[i - 1], r.ranking[i]));
        }
    }
}

// Relevance says: from {} only m0 and m2; from {m0} only m1; from anything else nothing.
TEST(DesignSearch, PruningGrowsOnlyRelevantConfigurations) {
    DesignProblem p = synthetic({1, 2, 0.5}, {0.3, 0.7}, {1, 0.25, 0.25, 0.9, 10});
    ScriptedEvaluator evaluator(landscape);
    DesignSearchOptions options;
    std::vector<Configuration> asked;
    options.relevant = [&](const Configuration &c) {
        asked.push_back(c);
        if (c.empty())
            return std::vector<int>{0, 2};
        return c == Configuration{0} ? std::vector<int>{0, 1} : std::vector<int>{};
    };
    DesignResult r = search_design(p, evaluator, options);
    EXPECT_FALSE(r.optimal);
    EXPECT_FALSE(r.limit_reached);
    EXPECT_EQ(evaluator.evaluated(), (std::vector<Configuration>{{}, {0}, {2}, {0, 1}}));
    EXPECT_EQ(r.counters.configurations_total, 8);
    EXPECT_EQ(r.counters.configurations_pruned, 4);
}

TEST(DesignSearch, PruningThatLeavesNothingOutIsExact) {
    DesignProblem p = synthetic({1, 2, 0.5}, {0.3, 0.7}, {1, 0.25, 0.25, 0.9, 10});
    ScriptedEvaluator evaluator(landscape);
    DesignSearchOptions options;
    options.relevant = [](const Configuration &) { return std::vector<int>{0, 1, 2}; };
    DesignResult r = search_design(p, evaluator, options);
    EXPECT_TRUE(r.optimal);
    EXPECT_EQ(r.best->ranked.configuration, exhaustive(p, landscape, 0).best);
}

TEST(DesignSearch, Binomial) {
    EXPECT_EQ(binomial(6, 0), 1);
    EXPECT_EQ(binomial(6, 2), 15);
    EXPECT_EQ(binomial(6, 6), 1);
    EXPECT_EQ(binomial(6, 7), 0);
    EXPECT_EQ(binomial(1000, 500), LLONG_MAX);
}

} // namespace
} // namespace envdesign::design
