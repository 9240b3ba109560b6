// The explanation of a design (design/explanation.h, break_even.h, evaluate_design.h) on the
// paper's restaurant, setting (c), with the values worked out by hand, and break-even
// checked against re-running the exact search at other horizons and alphas.

#include "design/design_explanation.h"
#include "design/evaluation/evaluate_design.h"
#include "design/evaluation/local_evaluator.h"
#include "design/objective/break_even.h"
#include "spec/design_spec.h"

#include <gtest/gtest.h>

#include <cmath>

namespace envdesign::design {

using spec::load_design_problem;
namespace {

const std::string SPEC = std::string(ENVDESIGN_EXAMPLES) + "/restaurant/c-two-tasks-t10.textproto";

// Modification indices in the spec.
constexpr int B00_01 = 0, B01_11 = 2, B10_11 = 3;

// f_T = (1 - 0.9^T) / 0.1; f_10 = 6.5132156.
double f(int horizon) { return (1 - std::pow(0.9, horizon)) / 0.1; }

Configuration best_at(DesignProblem problem, double alpha, int horizon) {
    problem.weights.alpha = alpha;
    problem.weights.horizon = horizon;
    LocalEvaluator evaluator(problem, 1);
    return search_design(problem, evaluator, {}).best->ranked.configuration;
}

// Setting (c): alpha 1, beta 30, kappa 0.25, gamma 0.9, T 10. The robot's plans cost 7 (G1)
// and 8 (G2) whatever the barriers (they only change what observers believe).
//   chosen {00-01, 10-11}: IE 1 and 1, C = 2:
//       1 * f_10 + 30 * 2 + 0.25 * 10 * 7.5 = 6.5132 + 60 + 18.75 = 85.2632
//   without 10-11, {00-01}: observers now expect 5 + 2 (G1) and 6 (G2): IE e^2 and e^2:
//       e^2 * f_10 + 30 + 18.75 = 48.1265 + 48.75 = 96.8765   (value of 10-11: 11.6133)
//   without 00-01, {10-11}: no change for the observers, IE e^2 (G1) and e^4 (G2):
//       (e^2 + e^4) / 2 * f_10 + 30 + 18.75 = 201.8680 + 48.75 = 250.6180 (value: 165.3548)
TEST(DesignExplanation, MarginalValuesOfTheRestaurantBarriers) {
    DesignProblem problem = load_design_problem(SPEC);
    LocalEvaluator local(problem, 1);
    EvaluationLog log(problem, local);
    DesignResult result = search_design(problem, log, {});
    ASSERT_EQ(result.best->ranked.configuration, (Configuration{B00_01, B10_11}));
    DesignExplanation why = explain_design(problem, result, log, &local.planner(), {});

    double f10 = f(10), e2 = std::exp(2.0), e4 = std::exp(4.0);
    EXPECT_NEAR(why.chosen.expected_ie, 1, 1e-12);
    EXPECT_NEAR(objective_at(problem.weights, why.chosen).value, f10 + 60 + 18.75, 1e-9);
    EXPECT_NEAR(why.least_inexplicability, f10, 1e-12); // every IE 1: the chosen design
    ASSERT_EQ(why.marginal.size(), 2u);
    EXPECT_EQ(why.marginal[0].modification, B00_01);
    ASSERT_TRUE(why.marginal[0].without);
    EXPECT_EQ(why.marginal[0].without->configuration, (Configuration{B10_11}));
    EXPECT_NEAR(objective_at(problem.weights, *why.marginal[0].without).value,
                (e2 + e4) / 2 * f10 + 30 + 18.75, 1e-9);
    EXPECT_EQ(why.marginal[1].modification, B10_11);
    ASSERT_TRUE(why.marginal[1].without);
    EXPECT_NEAR(objective_at(problem.weights, *why.marginal[1].without).value,
                e2 * f10 + 30 + 18.75, 1e-9);

    // Per task: the empty design beside the chosen one, and the three plans.
    ASSERT_EQ(why.tasks.size(), 2u);
    EXPECT_NEAR(why.tasks[0].baseline.ie, e2, 1e-9);
    EXPECT_NEAR(why.tasks[1].baseline.ie, e4, 1e-9);
    EXPECT_EQ(*why.tasks[1].baseline.human_optimal_cost, 4);
    EXPECT_EQ(*why.tasks[1].chosen.human_optimal_cost, 8);
    ASSERT_TRUE(why.tasks[1].robot_plan && why.tasks[1].expected_plan);
    EXPECT_EQ(*why.tasks[1].robot_optimal_cost, 8);
    EXPECT_EQ(why.tasks[1].robot_plan->size(), 8u);
    EXPECT_EQ(why.tasks[1].expected_plan->size(), 8u); // observers: 8 once barred
}

// Break-even in T: the runner-up {00-01} has E[IE] = e^2, C = 1; both have E[c_R] = 7.5, so
// {00-01} ranks first iff (e^2 - 1) f_T < 30, i.e. f_T < 4.6955:
// f_6 = 4.6856 (it does), f_7 = 5.2170 (it does not). Nothing overtakes the chosen design
// for larger T (f_T < 10 and the chosen IE is already least).
// Break-even in alpha: alpha (e^2 - 1) f_10 = 30 at alpha = 30 / 41.6135 = 0.72092.
TEST(DesignExplanation, BreakEvenOfTheRestaurant) {
    DesignProblem problem = load_design_problem(SPEC);
    LocalEvaluator local(problem, 1);
    EvaluationLog log(problem, local);
    DesignResult result = search_design(problem, log, {});
    DesignExplanation why = explain_design(problem, result, log, nullptr, {});
    const BreakEven &b = why.break_even;
    ASSERT_TRUE(b.horizon_down);
    EXPECT_EQ(b.horizon_down->at, 6);
    EXPECT_EQ(b.horizon_down->rival.configuration, (Configuration{B00_01}));
    EXPECT_FALSE(b.horizon_up);
    EXPECT_EQ(b.horizon_limit, 1000);
    ASSERT_TRUE(b.alpha_down);
    double e2 = std::exp(2.0);
    EXPECT_NEAR(b.alpha_down->at, 30 / ((e2 - 1) * f(10)), 1e-9);
    EXPECT_NEAR(b.alpha_down->at, 0.72092, 1e-5);
    EXPECT_FALSE(b.alpha_up);

    // The exact search at other weights agrees: the chosen design is the best for T = 7..30
    // and alpha just above the crossing, and not at T = 6 or just below it.
    Configuration chosen = result.best->ranked.configuration;
    EXPECT_NE(best_at(problem, 1, 6), chosen);
    for (int t : {7, 8, 9, 10, 15, 30})
        EXPECT_EQ(best_at(problem, 1, t), chosen) << "T = " << t;
    EXPECT_NE(best_at(problem, b.alpha_down->at - 1e-6, 10), chosen);
    EXPECT_EQ(best_at(problem, b.alpha_down->at + 1e-6, 10), chosen);
}

// Every one of the 64 designs evaluated: the break-even found among them is the exact one
// (re-running the search at each T from 1 to 40 changes its answer exactly there), and the
// search's own evaluated set can only report a crossing as late as or later than it.
TEST(DesignExplanation, BreakEvenAmongAllDesignsIsExact) {
    DesignProblem problem = load_design_problem(SPEC);
    LocalEvaluator local(problem, 2);
    EvaluationLog all(problem, local);
    std::vector<ConfigurationEvaluation> batch;
    for (int mask = 0; mask < 64; ++mask) {
        Configuration c;
        for (int m = 0; m < 6; ++m)
            if (mask & (1 << m))
                c.push_back(m);
        batch.push_back(unevaluated(c));
    }
    all.evaluate(batch, {}, {[](const auto &) { return false; }, [](auto) {}});
    ASSERT_EQ(all.points().size(), 64u);
    Configuration chosen{B00_01, B10_11};
    BreakEven exact = break_even(problem.weights, *all.find(chosen), all.points());
    int low = exact.horizon_down ? static_cast<int>(exact.horizon_down->at) : 0;
    int high = exact.horizon_up ? static_cast<int>(exact.horizon_up->at) : 1 << 30;
    for (int t = 1; t <= 40; ++t)
        EXPECT_EQ(best_at(problem, 1, t) == chosen, low < t && t < high) << "T = " << t;

    EvaluationLog searched(problem, local);
    DesignResult result = search_design(problem, searched, {});
    DesignExplanation why = explain_design(problem, result, searched, nullptr, {});
    ASSERT_TRUE(why.break_even.horizon_down && exact.horizon_down);
    EXPECT_LE(why.break_even.horizon_down->at, exact.horizon_down->at);
    EXPECT_LT(why.break_even.designs_compared, 64);
}

DesignPoint point(const Configuration &configuration, double cost, double ie, double robot_cost) {
    DesignPoint p;
    p.configuration = configuration;
    p.design_cost = cost;
    p.expected_ie = ie;
    p.expected_robot_cost = robot_cost;
    return p;
}

// Hand-made points, gamma = 1 (f_T = T), kappa = 0: objectives T * E[IE] + C.
//   chosen A = {0, 1}: IE 1, C 2 -> T + 2
//   B = {}:           IE 1.5, C 0 -> 1.5 T   (ties A at T = 4, and wins the tie: fewer
//                                             modifications; below alpha 0.8 at T = 5)
//   D = {0, 1, 2}:    IE 0.5, C 5 -> 0.5 T + 5 (ties A at T = 6, loses the tie; wins from
//                                             T = 7; at T = 5 wins above alpha 1.2)
TEST(BreakEven, HandMadePointsWithTies) {
    ObjectiveWeights w;
    w.alpha = 1, w.beta = 1, w.kappa = 0, w.gamma = 1, w.horizon = 5;
    DesignPoint a = point({0, 1}, 2, 1, 0), b = point({}, 0, 1.5, 0),
                d = point({0, 1, 2}, 5, 0.5, 0);
    BreakEven be = break_even(w, a, {a, b, d});
    EXPECT_EQ(be.designs_compared, 3);
    ASSERT_TRUE(be.horizon_down && be.horizon_up && be.alpha_down && be.alpha_up);
    EXPECT_EQ(be.horizon_down->at, 4);
    EXPECT_EQ(be.horizon_down->rival.configuration, Configuration{});
    EXPECT_EQ(be.horizon_up->at, 7);
    EXPECT_EQ(be.horizon_up->rival.configuration, (Configuration{0, 1, 2}));
    EXPECT_NEAR(be.alpha_down->at, 0.8, 1e-12); // 5a + 2 = 7.5a
    EXPECT_NEAR(be.alpha_up->at, 1.2, 1e-12);   // 5a + 2 = 2.5a + 5
    // An infinite chosen objective has no break-even.
    DesignPoint stuck = point({0}, 1, INF, INF);
    BreakEven none = break_even(w, stuck, {a, b, stuck});
    EXPECT_FALSE(none.horizon_down || none.horizon_up || none.alpha_down || none.alpha_up);
}

// `envdesign evaluate`'s library: {00-01} evaluated as the search would, beside {}.
TEST(EvaluateDesign, KnownDesignAndUnknownNames) {
    DesignProblem problem = load_design_problem(SPEC);
    LocalEvaluator local(problem, 1);
    Configuration c = configuration_of(problem, {"barrier-00-01"});
    EXPECT_EQ(c, Configuration{B00_01});
    DesignResult r = evaluate_design(problem, local, c, {});
    ASSERT_TRUE(r.best && r.baseline);
    EXPECT_FALSE(r.optimal);
    double f10 = f(10), e2 = std::exp(2.0), e4 = std::exp(4.0);
    EXPECT_NEAR(r.best->objective.value, e2 * f10 + 30 + 18.75, 1e-9);           // 96.8765
    EXPECT_NEAR(r.baseline->objective.value, (e2 + e4) / 2 * f10 + 18.75, 1e-9); // 220.6180
    EXPECT_EQ(r.counters.configurations_evaluated, 2);
    EXPECT_EQ(configuration_of(problem, {}), Configuration{});
    EXPECT_EQ(configuration_of(problem, {"barrier-10-11", "barrier-01-11"}),
              (Configuration{B01_11, B10_11}));
    try {
        configuration_of(problem, {"barrier-00-01", "barrier-99"});
        FAIL() << "an unknown name was taken";
    } catch (const UnknownModification &e) {
        EXPECT_NE(std::string(e.what()).find("'barrier-99'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(configuration_of(problem, {"barrier-00-01", "barrier-00-01"}),
                 UnknownModification);
}

// robot_behaviour EXPLAINING (design/behaviour/explaining.h): each task's choice between explaining
// and acting explicably depends on the weights, so a design point re-chooses in objective_at. At
// explanation_cost 20 the paper's barriers win (85.2632, both tasks act explicably); without
// barrier-10-11, G1's observers expect 5 and see 7: act explicably costs e^2 * f_10 + 0.25 *
// 10 * 7 per task, explaining (2 differences told) 1 * f_10 + 20 * 2 * f_10 + same robot
// cost, so G1 acts explicably (e^2 = 7.39 < 41). Each marginal point must give exactly the
// objective that evaluating its design does, under the spec's weights and under others.
TEST(DesignExplanation, ExplainingDesignPointsChooseAgainUnderOtherWeights) {
    DesignProblem problem = load_design_problem(SPEC);
    problem.weights.behaviour = RobotBehaviour::EXPLAINING;
    problem.weights.explanation_cost = 20;
    LocalEvaluator local(problem, 1);
    EvaluationLog log(problem, local);
    DesignResult result = search_design(problem, log, {});
    ASSERT_EQ(result.best->ranked.configuration, (Configuration{B00_01, B10_11}));
    EXPECT_NEAR(result.best->objective.value, f(10) + 60 + 18.75, 1e-9);
    DesignExplanation why = explain_design(problem, result, log, &local.planner(), {});
    EXPECT_EQ(why.break_even.designs_compared, 0); // not computed: choices move with T, alpha
    ASSERT_EQ(why.marginal.size(), 2u);
    for (const auto &m : why.marginal) {
        ASSERT_TRUE(m.without);
        for (double x : {20.0, 1.0}) { // 1: explaining wins where acting explicably did
            DesignProblem other = problem;
            other.weights.explanation_cost = x;
            LocalEvaluator evaluator(other, 1);
            DesignResult direct = evaluate_design(other, evaluator, m.without->configuration, {});
            EXPECT_NEAR(objective_at(other.weights, *m.without).value, direct.best->objective.value,
                        1e-9)
                << "x = " << x;
        }
    }
}

} // namespace
} // namespace envdesign::design
