// Gated modifications (gated_twins.h) in every behaviour: seeded Blocksworld problems with the
// paper's from-table-x gates on some blocks, sometimes a sign that tells people about the one
// hand, sometimes a gate whose fluent edits differ from the family's (the rule must then say
// no). The witness and the exhaustive search, which both start configurations from inherited
// robot bounds, must give the design and objective of every configuration evaluated in full.
// CI runs 40 seeds; ENVDESIGN_AGREEMENT_SEEDS=300 runs the check.

#include "design/search/design_search.h"
#include "design/search/gated_twins.h"
#include "every_configuration.h"
#include "explaining_generator.h"
#include "spec/design_spec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace envdesign::design {
namespace {

using testing::Dice;

const std::string GATED_BLOCKS = "abcd";

// A random state of the four blocks as towers: each block goes on the table or on a clear
// tower top. Its atoms, with (handempty) when `with_hand`.
std::vector<std::string> random_towers(Dice &d, bool with_hand) {
    std::vector<std::string> atoms, tops;
    std::string order = GATED_BLOCKS;
    for (int i = 3; i > 0; --i)
        std::swap(order[i], order[d.below(i + 1)]);
    for (char b : order) {
        std::string x(1, b);
        int where = d.below(static_cast<int>(tops.size()) + 1);
        if (where == static_cast<int>(tops.size())) {
            atoms.push_back("(ontable " + x + ")");
            tops.push_back(x);
        } else {
            atoms.push_back("(on " + x + " " + tops[where] + ")");
            tops[where] = x;
        }
    }
    if (with_hand) {
        for (const auto &t : tops)
            atoms.push_back("(clear " + t + ")");
        atoms.push_back("(handempty)");
    }
    return atoms;
}

std::string write_text(const std::string &path, const std::string &text) {
    std::ofstream(path) << text;
    return path;
}

std::string gate_modification(char block, double cost, bool odd_family) {
    std::string x(1, block);
    std::ostringstream m;
    m << "modification { name: \"from-table-" << x << "\" cost: " << cost << "\n"
      << "  edit { add_init: \"(restricted " << x << ")\" }\n"
      << "  edit { add_effect { action: \"pick-up\" literal: \"(from-table ?x)\" } }\n";
    if (!odd_family) // without it, from-table is never cleared: not the family's edits
        m << "  edit { add_effect { action: \"unstack\" literal: \"(not (from-table ?x))\" } }\n";
    m << "}\n";
    return m.str();
}

DesignProblem gated_problem(unsigned seed, const std::string &dir) {
    Dice d(seed);
    const std::string data = std::string(ENVDESIGN_TEST_DATA) + "/paper/blocksworld/";
    std::ostringstream spec;
    spec << "robot_domain: \"" << data << "domain-robot.pddl\"\n"
         << "human_domain: \"" << data << "domain-human.pddl\"\n";
    int tasks = d.between(1, 3);
    for (int t = 0; t < tasks; ++t) {
        std::ostringstream p;
        p << "(define (problem t" << t << ") (:domain blocksworld) (:objects a b c d)\n(:init";
        for (const auto &a : random_towers(d, true))
            p << " " << a;
        p << ")\n(:goal (and";
        for (const auto &a : random_towers(d, false)) // a whole state: always reachable
            p << " " << a;
        p << "))) ";
        std::string file = write_text(dir + "/t" + std::to_string(t) + ".pddl", p.str());
        spec << "task { name: \"t" << t << "\" problem: \"" << file
             << "\" probability: " << d.between(1, 3) << " }\n";
    }
    std::string gated = GATED_BLOCKS;
    for (int i = 3; i > 0; --i)
        std::swap(gated[i], gated[d.below(i + 1)]);
    gated.resize(d.between(2, 4));
    bool odd = d.percent(15);
    for (std::size_t i = 0; i < gated.size(); ++i)
        spec << gate_modification(gated[i], 0.1 * d.between(1, 5), odd && i == 0);
    if (d.percent(40))
        spec << "modification { name: \"one-hand-sign\" cost: " << 0.5 * d.between(1, 4) << "\n"
             << "  edit { model: HUMAN add_precondition { action: \"pick-up\" literal: "
                "\"(handempty)\" } }\n"
             << "  edit { model: HUMAN add_effect { action: \"pick-up\" literal: "
                "\"(not (handempty))\" } }\n}\n";
    const char *behaviours[] = {"EXPLICABLE", "COST_OPTIMAL", "COST_OPTIMAL_BEST_CASE",
                                "EXPLAINING"};
    spec << "alpha: " << std::vector<double>{0.5, 1, 3}[d.below(3)]
         << " beta: " << std::vector<double>{0.1, 0.25, 1}[d.below(3)]
         << " kappa: " << (d.percent(30) ? 0 : 0.25) << " gamma: 0.9"
         << " horizon: " << std::vector<int>{1, 10}[d.below(2)]
         << "\nrobot_behaviour: " << behaviours[seed % 4] << "\n";
    if (seed % 4 == 3)
        spec << "explanation_cost: " << std::vector<double>{0.2, 1, 3}[d.below(3)] << "\n";
    return spec::load_design_problem(write_text(dir + "/design.textproto", spec.str()));
}

int gated_seeds() {
    const char *n = std::getenv("ENVDESIGN_AGREEMENT_SEEDS");
    return n ? std::max(1, std::atoi(n)) : 40;
}

TEST(GatedAgreement, BothSearchesAgreeWithEveryConfiguration) {
    int gated = 0, ungated = 0, nonempty = 0;
    for (int seed = 0; seed < gated_seeds(); ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::string dir = ::testing::TempDir() + "/gated-" + std::to_string(seed);
        std::filesystem::create_directories(dir);
        DesignProblem p = gated_problem(static_cast<unsigned>(seed), dir);
        int explained = 0;
        RankedDesign expected = testing::every_configuration(p, explained);
        for (int m = 0; m < static_cast<int>(p.modifications.size()); ++m)
            (gated_twin_restricting(p, m, true) ? gated : ungated) += 1;
        nonempty += !expected.configuration.empty();
        for (SearchMethod method : {SearchMethod::WITNESS, SearchMethod::EXHAUSTIVE}) {
            LocalEvaluator evaluator(p, 1);
            DesignSearchOptions options;
            options.method = method;
            DesignResult r = search_design(p, evaluator, options);
            ASSERT_TRUE(r.best);
            EXPECT_TRUE(r.optimal);
            if (std::isfinite(expected.objective))
                EXPECT_NEAR(r.best->objective.value, expected.objective,
                            1e-9 * std::max(1.0, std::abs(expected.objective)));
            else
                EXPECT_FALSE(std::isfinite(r.best->objective.value));
            EXPECT_EQ(r.best->ranked.configuration, expected.configuration);
        }
    }
    std::cout << "gated " << gated << ", not " << ungated << ", non-empty designs " << nonempty
              << std::endl;
    EXPECT_GT(gated, ungated); // mostly the rule's case, and some of the fallback
    EXPECT_GT(ungated, 0);
    EXPECT_GE(nonempty, gated_seeds() / 4);
}

} // namespace
} // namespace envdesign::design
