// The witness-driven design search (issue 9) against exhaustive enumeration, on seeded
// random small design problems with real planning.
//
// Each seed generates a navigation design problem (nodes n0.., passages (conn a b), jumps
// over (far a b), blocked nodes the robot must avoid, and sometimes a key k0 that unlocks
// locked nodes), writes its PDDL and spec file into a directory of its own under the temp
// directory and loads it like any spec. The robot's and the human's models differ: passages
// people believe in that the robot lacks (often a direct one from a task's start to its goal)
// and the other way round, a precondition or an action only one model has, other action
// costs, other blocked or locked nodes. The modifications (3 to 7) target HUMAN, ROBOT or
// BOTH and mix
//   - those that only remove plans: barriers (remove_init of passages), added preconditions
//     (positive and negative), removed actions and ground actions, added goals (positive and
//     negative), a fresh predicate within one modification (add_predicate + add_effect +
//     add_precondition, as in SPEC.md; or a poster nobody reads);
//   - those that do not: new passages (add_init), removed preconditions, added and removed
//     effects, removed goals, removed or added atoms that preconditions use negatively, and
//     a fresh predicate declared by two modifications, a rule that needs it and another that
//     provides it (each alone only removes plans or changes nothing; together they do not);
//   - the same edits again under another name.
// Costs may be zero, all equal, or negative; tasks (1 to 4) have uneven probabilities, some
// 0, and some are unsolvable for the robot or for the human (infinite IE); both distances;
// sometimes a max_design_size.
//
// search_design with SearchMethod::WITNESS and with SearchMethod::EXHAUSTIVE must give the
// same design, objective (relative 1e-9; "inf" equals only "inf"), status and baseline. The
// counts of what the seeds covered are printed, and asserted on 40 seeds or more so that the
// agreement cannot come from trivial problems.
//
// CI runs seeds 0..39. ENVDESIGN_AGREEMENT_SEEDS=N runs seeds 0..N-1, e.g. the issue's check:
//   ENVDESIGN_AGREEMENT_SEEDS=300 build/bin/design_tests --gtest_filter='WitnessAgreement*'
// ENVDESIGN_AGREEMENT_SEED=K runs seed K alone. A failing seed's directory is kept and named
// in the failure (so is every directory with ENVDESIGN_AGREEMENT_KEEP=1); the others are
// removed.

#include "design/behaviour/explicability.h"
#include "design/evaluation/local_evaluator.h"
#include "design/search/design_search.h"
#include "design/search/measured_floors.h"
#include "design/search/witness.h"
#include "spec/design_spec.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace envdesign::design {

using spec::load_design_problem;
namespace {

namespace fs = std::filesystem;

// std::mt19937's output is fixed by the standard, so a seed names the same problem
// everywhere (the standard distributions are not, hence the modulo).
class Random {
public:
    explicit Random(unsigned seed) : engine_(seed * 7919u + 17u) {}
    int below(int n) { return static_cast<int>(engine_() % static_cast<unsigned>(n)); }
    int between(int lo, int hi) { return lo + below(hi - lo + 1); }
    bool percent(int p) { return below(100) < p; }
    template <class T> T pick(const std::vector<T> &items) {
        return items[below(static_cast<int>(items.size()))];
    }

private:
    std::mt19937 engine_;
};

using Edge = std::pair<int, int>;

std::string node(int n) { return "n" + std::to_string(n); }

// What one model (the robot's or the human's) says: its domain's actions, and the facts of
// its initial state that every task shares.
struct Side {
    bool blocked_precondition = false; // move needs (not (blocked ?b))
    bool locked_precondition = false;  // move needs (not (locked ?b)) (with keys)
    bool unlock_needs_key = true;      // unlock needs (have ?k) (with keys)
    bool jump = false;                 // the jump action exists
    int move_cost = 1;                 // with action costs
    int jump_cost = 3;
    std::set<Edge> conn, far;
    std::set<int> blocked, safe, locked;
};

struct GeneratedTask {
    int start = 0;
    int goal = 1;
    int visit = -1; // a second goal (visited nV); -1: none
    int probability = 1;
};

struct GeneratedModification {
    std::string name;
    std::string kind;
    bool restricting = true; // only removes plans, whatever it is combined with
    std::vector<std::string> edits;
};

const std::vector<std::string> RESTRICTING_KINDS = {
    "barrier",       "precondition", "negative-precondition", "remove-schema",
    "remove-ground", "add-goal",     "fresh-predicate"};
const std::vector<std::string> OTHER_KINDS = {"new-passage",   "remove-precondition", "add-effect",
                                              "remove-effect", "remove-goal",         "unblock",
                                              "add-obstacle",  "fresh-split"};

// Kinds that usually only add plans (witness.h: adding): a new lane, a rule relaxed.
const std::vector<std::string> ADDING_KINDS = {
    "new-passage", "remove-precondition", "unblock", "remove-goal", "add-effect", "remove-effect"};

std::vector<std::string> all_kinds() {
    std::vector<std::string> kinds = RESTRICTING_KINDS;
    kinds.insert(kinds.end(), OTHER_KINDS.begin(), OTHER_KINDS.end());
    return kinds;
}

struct Generated {
    int nodes = 4;
    bool keys = false; // a key k0 at key_node opens every locked node
    int key_node = 0;
    bool costs = false; // :action-costs
    Side robot, human;
    std::vector<GeneratedTask> tasks;
    std::vector<GeneratedModification> modifications;
    std::vector<double> costs_of_modifications;
    double alpha = 1, beta = 1, kappa = 0, gamma = 1;
    int horizon = 1;
    bool cost_diff = false;
    int max_design_size = 0;
    std::string behaviour; // robot_behaviour; empty: the default (EXPLICABLE)
};

// ---------------------------------------------------------------------------------------
// PDDL and spec text.

bool uses_negative_preconditions(const Generated &g, const Side &s) {
    return s.blocked_precondition || (g.keys && s.locked_precondition);
}

std::string cost_effect(const Generated &g, int cost) {
    return g.costs ? " (increase (total-cost) " + std::to_string(cost) + ")" : "";
}

std::string domain_text(const Generated &g, const Side &s) {
    std::ostringstream d;
    d << "(define (domain agree)\n  (:requirements :strips :typing";
    if (uses_negative_preconditions(g, s))
        d << " :negative-preconditions";
    if (g.costs)
        d << " :action-costs";
    d << ")\n  (:types node" << (g.keys ? " key" : "") << ")\n";
    d << "  (:predicates (at ?n - node) (conn ?a ?b - node) (far ?a ?b - node)\n"
         "               (visited ?n - node) (blocked ?n - node) (safe ?n - node)";
    if (g.keys)
        d << "\n               (locked ?n - node) (key-at ?k - key ?n - node) (have ?k - key)"
             "\n               (opens ?k - key ?n - node)";
    d << ")\n";
    if (g.costs)
        d << "  (:functions (total-cost) - number)\n";
    d << "  (:action move\n    :parameters (?a ?b - node)\n"
         "    :precondition (and (at ?a) (conn ?a ?b)"
      << (s.blocked_precondition ? " (not (blocked ?b))" : "")
      << (g.keys && s.locked_precondition ? " (not (locked ?b))" : "") << ")\n"
      << "    :effect (and (at ?b) (not (at ?a)) (visited ?b)" << cost_effect(g, s.move_cost)
      << "))\n";
    if (s.jump)
        d << "  (:action jump\n    :parameters (?a ?b - node)\n"
             "    :precondition (and (at ?a) (far ?a ?b))\n"
             "    :effect (and (at ?b) (not (at ?a)) (visited ?b)"
          << cost_effect(g, s.jump_cost) << "))\n";
    if (g.keys) {
        d << "  (:action pick\n    :parameters (?k - key ?n - node)\n"
             "    :precondition (and (at ?n) (key-at ?k ?n))\n"
             "    :effect (and (have ?k) (not (key-at ?k ?n))"
          << cost_effect(g, 1) << "))\n";
        d << "  (:action unlock\n    :parameters (?a ?b - node ?k - key)\n"
             "    :precondition (and (at ?a) (conn ?a ?b) (locked ?b)"
          << (s.unlock_needs_key ? " (have ?k)" : "") << " (opens ?k ?b))\n"
          << "    :effect (and (not (locked ?b))" << cost_effect(g, 1) << "))\n";
    }
    d << ")\n";
    return d.str();
}

std::string problem_text(const Generated &g, const Side &s, const GeneratedTask &t,
                         const std::string &name) {
    std::ostringstream p;
    p << "(define (problem " << name << ")\n  (:domain agree)\n  (:objects";
    for (int n = 0; n < g.nodes; ++n)
        p << ' ' << node(n);
    p << " - node" << (g.keys ? " k0 - key" : "") << ")\n  (:init (at " << node(t.start) << ")";
    for (auto [a, b] : s.conn)
        p << "\n         (conn " << node(a) << ' ' << node(b) << ")";
    for (auto [a, b] : s.far)
        p << "\n         (far " << node(a) << ' ' << node(b) << ")";
    for (int n : s.blocked)
        p << " (blocked " << node(n) << ")";
    for (int n : s.safe)
        p << " (safe " << node(n) << ")";
    if (g.keys) {
        p << "\n         (key-at k0 " << node(g.key_node) << ")";
        std::set<int> doors = g.robot.locked;
        doors.insert(g.human.locked.begin(), g.human.locked.end());
        for (int n : doors)
            p << " (opens k0 " << node(n) << ")";
        for (int n : s.locked)
            p << " (locked " << node(n) << ")";
    }
    if (g.costs)
        p << "\n         (= (total-cost) 0)";
    p << ")\n  (:goal (and (at " << node(t.goal) << ")";
    if (t.visit >= 0)
        p << " (visited " << node(t.visit) << ")";
    p << "))";
    if (g.costs)
        p << "\n  (:metric minimize (total-cost))";
    p << ")\n";
    return p.str();
}

std::string number(double x) {
    std::ostringstream out;
    out << std::setprecision(12) << x;
    return out.str();
}

void write_file(const fs::path &path, const std::string &text) {
    std::ofstream out(path);
    out << text;
    if (!out)
        throw std::runtime_error("cannot write " + path.string());
}

// Writes the problem into `dir`; returns the spec file's path.
fs::path write_spec(const Generated &g, const fs::path &dir, bool explicit_defaults) {
    fs::create_directories(dir);
    std::string robot_domain = domain_text(g, g.robot), human_domain = domain_text(g, g.human);
    write_file(dir / "domain-robot.pddl", robot_domain);
    std::ostringstream spec;
    spec << "# Generated by tests/design/witness_agreement_test.cc\n";
    spec << "robot_domain: \"domain-robot.pddl\"\n";
    if (robot_domain != human_domain || explicit_defaults) {
        write_file(dir / "domain-human.pddl", human_domain);
        spec << "human_domain: \"domain-human.pddl\"\n";
    }
    for (std::size_t t = 0; t < g.tasks.size(); ++t) {
        std::string name = "t" + std::to_string(t);
        std::string robot = problem_text(g, g.robot, g.tasks[t], name);
        std::string human = problem_text(g, g.human, g.tasks[t], name);
        write_file(dir / (name + "-robot.pddl"), robot);
        spec << "task { name: \"" << name << "\" problem: \"" << name << "-robot.pddl\"";
        if (robot != human || explicit_defaults) {
            write_file(dir / (name + "-human.pddl"), human);
            spec << " human_problem: \"" << name << "-human.pddl\"";
        }
        spec << " probability: " << g.tasks[t].probability << " }\n";
    }
    for (std::size_t m = 0; m < g.modifications.size(); ++m) {
        const auto &mod = g.modifications[m];
        spec << "modification {\n  name: \"" << mod.name
             << "\" cost: " << number(g.costs_of_modifications[m]) << "\n";
        for (const auto &e : mod.edits)
            spec << "  edit { " << e << " }\n";
        spec << "}\n";
    }
    spec << "alpha: " << number(g.alpha) << " beta: " << number(g.beta)
         << " kappa: " << number(g.kappa) << " gamma: " << number(g.gamma)
         << " horizon: " << g.horizon << "\n";
    if (g.cost_diff)
        spec << "distance: COST_DIFF\n";
    else if (explicit_defaults)
        spec << "distance: EXP_COST_DIFF\n";
    if (g.max_design_size > 0)
        spec << "max_design_size: " << g.max_design_size << "\n";
    if (!g.behaviour.empty())
        spec << "robot_behaviour: " << g.behaviour << "\n";
    fs::path path = dir / "spec.textproto";
    write_file(path, spec.str());
    return path;
}

// ---------------------------------------------------------------------------------------
// The generator.

enum class Target { HUMAN, ROBOT, BOTH };

class Generator {
public:
    // `restricting_only`: every modification restricting and of non-negative cost, and up
    // to 9 of them (the witness search's hitting-set phase applies). `adding_too`: the same
    // with modifications that add plans among them (the phase applies when each adds only).
    // `robot_ways`: with `adding_too`, the adding kinds edit the robot's model alone (lanes).
    explicit Generator(unsigned seed, bool restricting_only = false, bool adding_too = false,
                       bool robot_ways = false)
        : seed_(seed), restricting_only_(restricting_only || adding_too), adding_too_(adding_too),
          robot_ways_(robot_ways), r_(seed) {}

    Generated run() {
        world();
        tasks();
        weights();
        modifications();
        return g_;
    }

private:
    Edge random_pair() {
        int a = r_.below(g_.nodes), b = r_.below(g_.nodes - 1);
        return {a, b >= a ? b + 1 : b};
    }

    void world() {
        g_.nodes = r_.between(4, 7);
        g_.costs = r_.percent(40);
        g_.keys = r_.percent(30);
        Side &robot = g_.robot;
        // A ring through every node in a random order, both ways (one blocked node does not
        // cut it), and a few more passages, some one-way.
        std::vector<int> order(g_.nodes);
        for (int n = 0; n < g_.nodes; ++n)
            order[n] = n;
        for (int i = g_.nodes - 1; i > 0; --i)
            std::swap(order[i], order[r_.below(i + 1)]);
        for (int i = 0; i < g_.nodes; ++i) {
            int a = order[i], b = order[(i + 1) % g_.nodes];
            if (i + 1 == g_.nodes && r_.percent(25))
                continue; // a path, not a ring
            robot.conn.insert({a, b});
            robot.conn.insert({b, a});
        }
        for (int extra = r_.between(0, 2); extra > 0; --extra) {
            Edge e = random_pair();
            robot.conn.insert(e);
            if (r_.percent(60))
                robot.conn.insert({e.second, e.first});
        }
        Side human = robot;
        // People believe in passages the robot lacks, and do not know some it has.
        for (int phantom = r_.between(r_.percent(80) ? 1 : 0, 3); phantom > 0; --phantom) {
            Edge e = random_pair();
            human.conn.insert(e);
            if (r_.percent(70))
                human.conn.insert({e.second, e.first});
        }
        for (int hidden = r_.percent(35) ? 1 : 0; hidden > 0; --hidden) {
            std::vector<Edge> edges(human.conn.begin(), human.conn.end());
            human.conn.erase(r_.pick(edges));
        }
        // Sometimes a node the robot (or the human) believes cannot be entered at all.
        if (r_.percent(10)) {
            isolated_robot_ = r_.below(g_.nodes);
            std::erase_if(robot.conn, [&](const Edge &e) { return e.second == isolated_robot_; });
        }
        if (r_.percent(6)) {
            isolated_human_ = r_.below(g_.nodes);
            std::erase_if(human.conn, [&](const Edge &e) { return e.second == isolated_human_; });
        }
        // Jumps: costlier shortcuts over (far a b), in one model, both or neither.
        robot.jump = r_.percent(30);
        human.jump = r_.percent(40);
        for (int far = r_.between(1, 3); far > 0; --far)
            robot.far.insert(random_pair());
        human.far = robot.far;
        if (r_.percent(30))
            human.far.insert(random_pair());
        // Blocked nodes the robot avoids; people may not know it does.
        robot.blocked_precondition = r_.percent(45);
        human.blocked_precondition = robot.blocked_precondition ? r_.percent(55) : r_.percent(15);
        if (robot.blocked_precondition || human.blocked_precondition || r_.percent(20)) {
            for (int b = r_.percent(15) ? 2 : 1; b > 0; --b)
                robot.blocked.insert(r_.below(g_.nodes));
            human.blocked = robot.blocked;
            if (r_.percent(10))
                human.blocked.insert(r_.below(g_.nodes));
            if (r_.percent(30) && human.blocked.size() > 1)
                human.blocked.erase(human.blocked.begin());
        }
        for (int n = 0; n < g_.nodes; ++n)
            if (r_.percent(55))
                robot.safe.insert(n);
        human.safe = robot.safe;
        if (r_.percent(25))
            human.safe.insert(r_.below(g_.nodes));
        // Action costs (only with :action-costs).
        robot.move_cost = r_.between(1, 2);
        robot.jump_cost = r_.between(1, 4);
        human.move_cost = r_.percent(70) ? robot.move_cost : r_.between(1, 3);
        human.jump_cost = r_.percent(50) ? robot.jump_cost : r_.between(1, 4);
        // Keys: locked nodes need an unlock with k0; people may think they are open, or
        // that they need no key.
        if (g_.keys) {
            g_.key_node = r_.below(g_.nodes);
            for (int l = r_.between(1, 2); l > 0; --l) {
                int n = r_.below(g_.nodes);
                if (n != g_.key_node)
                    robot.locked.insert(n);
            }
            if (robot.locked.empty())
                robot.locked.insert((g_.key_node + 1) % g_.nodes);
            robot.locked_precondition = true;
            human.locked = r_.percent(85) ? robot.locked : std::set<int>{};
            human.locked_precondition = r_.percent(75);
            human.unlock_needs_key = r_.percent(60);
            // Doors and the key's node are not blocked as well (too many dead ends).
            for (Side *side : {&robot, &human}) {
                side->blocked.erase(g_.key_node);
                for (int n : robot.locked)
                    side->blocked.erase(n);
            }
        }
        g_.human = human;
    }

    void tasks() {
        int count = r_.between(1, 4);
        for (int t = 0; t < count; ++t) {
            GeneratedTask task;
            task.start = r_.below(g_.nodes);
            task.goal = (task.start + 1 + r_.below(g_.nodes - 1)) % g_.nodes;
            // Mostly a goal the robot may enter.
            for (int retry = 0; retry < 3 && g_.robot.blocked_precondition &&
                                g_.robot.blocked.count(task.goal) && r_.percent(80);
                 ++retry)
                task.goal = (task.start + 1 + r_.below(g_.nodes - 1)) % g_.nodes;
            // A goal nobody can reach in one of the models, now and then.
            int isolated = t == 0 && r_.percent(60)   ? isolated_robot_
                           : t == 1 && r_.percent(60) ? isolated_human_
                                                      : -1;
            if (isolated >= 0 && isolated != task.start)
                task.goal = isolated;
            if (r_.percent(20))
                task.visit = r_.below(g_.nodes);
            if (g_.robot.blocked.count(task.visit) && r_.percent(80))
                task.visit = -1;
            // People often believe in a direct passage the robot lacks (the paper's case:
            // they expect a shorter path than the robot's).
            if (r_.percent(60) && !g_.robot.conn.count({task.start, task.goal})) {
                g_.human.conn.insert({task.start, task.goal});
                shortcuts_.push_back({task.start, task.goal});
            }
            task.probability = r_.percent(8) ? 0 : r_.pick(std::vector<int>{1, 1, 2, 3, 5, 8});
            g_.tasks.push_back(task);
        }
        bool any = std::any_of(g_.tasks.begin(), g_.tasks.end(),
                               [](const GeneratedTask &t) { return t.probability > 0; });
        if (!any)
            g_.tasks[0].probability = 1;
    }

    void weights() {
        g_.alpha = r_.pick(std::vector<double>{1, 1, 2});
        g_.beta = r_.pick(std::vector<double>{0, 0.1, 0.5, 1, 1, 3});
        g_.kappa = r_.pick(std::vector<double>{0, 0.25, 1});
        g_.gamma = r_.pick(std::vector<double>{0.9, 1, 0.5});
        g_.horizon = r_.pick(std::vector<int>{1, 2, 10});
        g_.cost_diff = r_.percent(40);
        g_.max_design_size = r_.percent(25) ? r_.between(1, 2) : 0;
    }

    void modifications() {
        int count = restricting_only_ ? r_.between(3, 9) : r_.between(3, 7);
        std::vector<std::string> kinds = restricting_only_ ? RESTRICTING_KINDS : all_kinds();
        if (adding_too_)
            kinds.insert(kinds.end(), ADDING_KINDS.begin(), ADDING_KINDS.end());
        // The first kind cycles with the seed, so that every kind is met in a few seeds; the
        // others are drawn without repeats, except barriers (the paper's design).
        std::string first = kinds[seed_ % kinds.size()];
        kinds.push_back("barrier");
        // Mostly a barrier that tells people about a shortcut they believe in.
        for (const Edge &e : shortcuts_) {
            if (static_cast<int>(g_.modifications.size()) + 1 >= count || r_.percent(25))
                continue;
            GeneratedModification m{"sign-" + node(e.first) + "-" + node(e.second),
                                    "barrier",
                                    true,
                                    {atom_edit(Target::HUMAN, "remove_init", conn(e))}};
            m.name = "m" + std::to_string(g_.modifications.size()) + "-" + m.name;
            g_.modifications.push_back(m);
        }
        for (int attempt = 0; static_cast<int>(g_.modifications.size()) < count && attempt < 100;
             ++attempt) {
            if (!g_.modifications.empty() && r_.percent(8)) {
                // The same edits again under another name (and maybe another cost).
                GeneratedModification copy = r_.pick(g_.modifications);
                copy.name = "m" + std::to_string(g_.modifications.size()) + "-again-" +
                            copy.name.substr(copy.name.find('-') + 1);
                g_.modifications.push_back(copy);
                continue;
            }
            if (kinds.empty())
                break;
            std::string kind = attempt == 0 ? first : r_.pick(kinds);
            if (attempt > 0 && kind == first && kind != "barrier")
                continue;
            auto used = std::find(kinds.begin(), kinds.end(), kind);
            if (attempt > 0 && used != kinds.end())
                kinds.erase(used);
            if (kind == "fresh-split") {
                if (static_cast<int>(g_.modifications.size()) + 2 <= count)
                    fresh_split();
                continue;
            }
            if (auto m = make(kind)) {
                m->kind = kind;
                m->restricting = std::find(RESTRICTING_KINDS.begin(), RESTRICTING_KINDS.end(),
                                           kind) != RESTRICTING_KINDS.end();
                m->name = "m" + std::to_string(g_.modifications.size()) + "-" + m->name;
                g_.modifications.push_back(*m);
            }
        }
        int mode = r_.below(20);
        for (std::size_t m = 0; m < g_.modifications.size(); ++m) {
            double cost = mode == 0   ? 0 // every design costs nothing: ties everywhere
                          : mode <= 4 ? 1 // equal costs
                          : mode == 5 && !restricting_only_
                              ? r_.pick(std::vector<double>{-0.5, 0.5, 1, 2}) // a saving
                              : r_.pick(std::vector<double>{0, 0.5, 1, 1, 2, 3});
            g_.costs_of_modifications.push_back(cost);
        }
    }

    // Two modifications over one fresh predicate, each declaring it: a rule that needs it
    // (alone it forbids an action; it only removes plans) and what provides it (alone it
    // changes nothing; beside the rule it gives back part of what the rule took).
    void fresh_split() {
        Target t = r_.percent(70) ? Target::HUMAN : target();
        bool jump = all(t, [](const Side &s) { return s.jump; });
        std::string id = std::to_string(g_.modifications.size());
        std::vector<int> variants = {0, 0};
        if (jump)
            variants.push_back(1);
        if (g_.keys)
            variants.push_back(2);
        GeneratedModification rule{"", "fresh-split", true, {}};
        GeneratedModification provider{"", "fresh-split", false, {}};
        switch (r_.pick(variants)) {
        case 0: { // moves only along marked passages; marks on (most of) the robot's
            std::string p = "marked-" + id;
            std::string declaration = atom_edit(t, "add_predicate", "(" + p + " ?a ?b - node)");
            rule.name = "marked-only";
            rule.edits = {declaration,
                          schema_edit(t, "add_precondition", "move", "(" + p + " ?a ?b)")};
            provider.name = "marks";
            provider.edits = {declaration};
            std::set<Edge> edges = g_.robot.conn;
            edges.insert(g_.human.conn.begin(), g_.human.conn.end());
            for (const Edge &e : edges)
                if (r_.percent(g_.robot.conn.count(e) ? 85 : 15))
                    provider.edits.push_back(atom_edit(
                        t, "add_init", "(" + p + " " + node(e.first) + " " + node(e.second) + ")"));
            if (provider.edits.size() == 1)
                provider.edits.push_back(atom_edit(t, "add_init", "(" + p + " n0 n1)"));
            break;
        }
        case 1: { // jumps only from a node reached by walking; walking marks it
            std::string p = "walked-" + id;
            std::string declaration = atom_edit(t, "add_predicate", "(" + p + " ?n - node)");
            rule.name = "jump-rule";
            rule.edits = {declaration,
                          schema_edit(t, "add_precondition", "jump", "(" + p + " ?a)")};
            provider.name = "walk-marks";
            provider.edits = {declaration, schema_edit(t, "add_effect", "move", "(" + p + " ?b)")};
            break;
        }
        default: { // doors open only with an escort; picking the key up brings one
            std::string p = "escort-" + id;
            std::string declaration = atom_edit(t, "add_predicate", "(" + p + ")");
            rule.name = "escort-rule";
            rule.edits = {declaration, schema_edit(t, "add_precondition", "unlock", "(" + p + ")")};
            provider.name = "escort-at-key";
            provider.edits = {declaration, schema_edit(t, "add_effect", "pick", "(" + p + ")")};
            break;
        }
        }
        bool provider_first = r_.percent(30);
        for (GeneratedModification *m :
             provider_first ? std::vector{&provider, &rule} : std::vector{&rule, &provider}) {
            m->name = "m" + std::to_string(g_.modifications.size()) + "-" + m->name;
            g_.modifications.push_back(*m);
        }
    }

    // --- one modification of a kind; nullopt when this problem has nothing of that kind.

    Target target() {
        return r_.pick(
            std::vector<Target>{Target::HUMAN, Target::HUMAN, Target::ROBOT, Target::BOTH});
    }

    std::vector<const Side *> sides(Target t) const {
        if (t == Target::HUMAN)
            return {&g_.human};
        if (t == Target::ROBOT)
            return {&g_.robot};
        return {&g_.robot, &g_.human};
    }

    template <class F> bool all(Target t, F f) const {
        auto s = sides(t);
        return std::all_of(s.begin(), s.end(), [&](const Side *side) { return f(*side); });
    }
    template <class F> bool any(Target t, F f) const {
        auto s = sides(t);
        return std::any_of(s.begin(), s.end(), [&](const Side *side) { return f(*side); });
    }

    std::string model(Target t) {
        switch (t) {
        case Target::HUMAN:
            return "model: HUMAN ";
        case Target::ROBOT:
            return "model: ROBOT ";
        default:
            return r_.percent(50) ? "model: BOTH " : ""; // BOTH is the default
        }
    }

    std::string atom_edit(Target t, const std::string &field, const std::string &atom) {
        return model(t) + field + ": \"" + atom + "\"";
    }

    std::string schema_edit(Target t, const std::string &field, const std::string &action,
                            const std::string &literal) {
        return model(t) + field + " { action: \"" + action + "\" literal: \"" + literal + "\" }";
    }

    static std::string conn(Edge e) {
        return "(conn " + node(e.first) + " " + node(e.second) + ")";
    }

    struct SchemaLiteral {
        std::string action, literal;
    };

    // Edges in the initial state of every targeted model.
    std::vector<Edge> shared_edges(Target t) const {
        std::vector<Edge> out;
        std::set<Edge> candidates = g_.robot.conn;
        candidates.insert(g_.human.conn.begin(), g_.human.conn.end());
        for (const Edge &e : candidates)
            if (all(t, [&](const Side &s) { return s.conn.count(e) > 0; }))
                out.push_back(e);
        return out;
    }

    std::optional<GeneratedModification> make(const std::string &kind) {
        GeneratedModification m;
        Target t = target();
        if (robot_ways_ &&
            std::find(ADDING_KINDS.begin(), ADDING_KINDS.end(), kind) != ADDING_KINDS.end())
            t = Target::ROBOT;
        bool jump = all(t, [](const Side &s) { return s.jump; });
        auto schema = [&](const std::string &field, const std::vector<SchemaLiteral> &options,
                          const std::string &name) -> std::optional<GeneratedModification> {
            if (options.empty())
                return std::nullopt;
            SchemaLiteral o = r_.pick(options);
            m.name = name + "-" + o.action;
            m.edits.push_back(schema_edit(t, field, o.action, o.literal));
            return m;
        };
        if (kind == "barrier") {
            std::vector<Edge> edges = shared_edges(t);
            if (t == Target::HUMAN && r_.percent(60)) {
                std::vector<Edge> phantoms;
                for (const Edge &e : g_.human.conn)
                    if (!g_.robot.conn.count(e))
                        phantoms.push_back(e);
                if (!phantoms.empty())
                    edges = phantoms;
            }
            if (edges.empty())
                return std::nullopt;
            Edge e = r_.pick(edges);
            m.name = "barrier-" + node(e.first) + "-" + node(e.second);
            m.edits.push_back(atom_edit(t, "remove_init", conn(e)));
            Edge back{e.second, e.first};
            if (r_.percent(60) && all(t, [&](const Side &s) { return s.conn.count(back) > 0; }))
                m.edits.push_back(atom_edit(t, "remove_init", conn(back)));
            return m;
        }
        if (kind == "precondition") {
            std::vector<SchemaLiteral> options = {{"move", "(safe ?b)"}};
            if (jump)
                options.push_back({"jump", "(safe ?b)"}),
                    options.push_back({"jump", "(conn ?a ?b)"});
            if (g_.keys)
                options.push_back({"unlock", "(have ?k)"}),
                    options.push_back({"pick", "(safe ?n)"});
            return schema("add_precondition", options, "sign");
        }
        if (kind == "negative-precondition") {
            std::vector<SchemaLiteral> options = {{"move", "(not (visited ?b))"},
                                                  {"move", "(not (blocked ?b))"},
                                                  {"move", "(not (safe ?a))"}};
            if (jump)
                options.push_back({"jump", "(not (blocked ?b))"});
            if (g_.keys)
                options.push_back({"unlock", "(not (visited ?b))"});
            return schema("add_precondition", options, "rule");
        }
        if (kind == "remove-schema") {
            std::vector<std::string> options;
            if (jump)
                options.push_back("jump"), options.push_back("jump");
            if (g_.keys)
                options.push_back("pick"), options.push_back("unlock");
            if (options.empty() || r_.percent(10))
                options.push_back("move");
            std::string action = r_.pick(options);
            m.name = "no-" + action;
            m.edits.push_back(atom_edit(t, "remove_action", action));
            return m;
        }
        if (kind == "remove-ground") {
            std::string action = "move";
            Edge e = random_pair();
            std::vector<Edge> edges = shared_edges(t);
            if (jump && r_.percent(40)) {
                action = "jump";
                e = r_.pick(std::vector<Edge>(g_.robot.far.begin(), g_.robot.far.end()));
            } else if (!edges.empty()) {
                e = r_.pick(edges);
            }
            m.name = "no-" + action + "-" + node(e.first) + "-" + node(e.second);
            m.edits.push_back(
                atom_edit(t, "remove_action",
                          "(" + action + " " + node(e.first) + " " + node(e.second) + ")"));
            return m;
        }
        if (kind == "add-goal") {
            int n = r_.below(g_.nodes);
            bool negative = r_.percent(25);
            m.name = std::string(negative ? "avoid-" : "visit-") + node(n);
            std::string atom = "(visited " + node(n) + ")";
            m.edits.push_back(atom_edit(t, "add_goal", negative ? "(not " + atom + ")" : atom));
            if (g_.keys && r_.percent(30))
                m.edits.push_back(atom_edit(t, "add_goal", "(have k0)"));
            return m;
        }
        if (kind == "fresh-predicate") {
            std::string id = std::to_string(g_.modifications.size());
            std::vector<int> variants = {0, 1, 2};
            if (jump)
                variants.push_back(3), variants.push_back(3);
            if (g_.keys)
                variants.push_back(4), variants.push_back(4);
            switch (r_.pick(variants)) {
            case 0: // no return to a node once left (negative precondition on it)
            case 1: {
                std::string p = "left-" + id;
                m.name = "one-way-rule";
                m.edits.push_back(atom_edit(t, "add_predicate", "(" + p + " ?n - node)"));
                m.edits.push_back(schema_edit(t, "add_effect", "move", "(" + p + " ?a)"));
                m.edits.push_back(
                    schema_edit(t, "add_precondition", "move", "(not (" + p + " ?b))"));
                return m;
            }
            case 2: { // a poster nobody reads: a fresh atom in the init, used nowhere
                std::string p = "poster-" + id;
                m.name = "poster";
                m.edits.push_back(atom_edit(t, "add_predicate", "(" + p + ")"));
                m.edits.push_back(atom_edit(t, "add_init", "(" + p + ")"));
                return m;
            }
            case 3: { // jump only from a node reached by walking (the SPEC's example's shape)
                std::string p = "walked-" + id;
                m.name = "jump-after-walk";
                m.edits.push_back(atom_edit(t, "add_predicate", "(" + p + " ?n - node)"));
                m.edits.push_back(schema_edit(t, "add_effect", "move", "(" + p + " ?b)"));
                m.edits.push_back(schema_edit(t, "add_precondition", "jump", "(" + p + " ?a)"));
                return m;
            }
            default: { // a door is opened only by whoever picked the key up here
                std::string p = "escorted-" + id;
                m.name = "escort";
                m.edits.push_back(atom_edit(t, "add_predicate", "(" + p + ")"));
                m.edits.push_back(schema_edit(t, "add_effect", "pick", "(" + p + ")"));
                m.edits.push_back(schema_edit(t, "add_precondition", "unlock", "(" + p + ")"));
                return m;
            }
            }
        }
        if (kind == "new-passage") {
            std::vector<Edge> missing;
            for (int a = 0; a < g_.nodes; ++a)
                for (int b = 0; b < g_.nodes; ++b)
                    if (a != b && any(t, [&](const Side &s) { return !s.conn.count({a, b}); }))
                        missing.push_back({a, b});
            if (t == Target::HUMAN && r_.percent(60)) {
                // Mostly: tell people about a passage the robot has.
                std::vector<Edge> unknown;
                for (const Edge &e : g_.robot.conn)
                    if (!g_.human.conn.count(e))
                        unknown.push_back(e);
                if (!unknown.empty())
                    missing = unknown;
            }
            if (missing.empty())
                return std::nullopt;
            Edge e = r_.pick(missing);
            if (r_.percent(20)) { // a new shortcut instead
                m.name = "shortcut-" + node(e.first) + "-" + node(e.second);
                m.edits.push_back(
                    atom_edit(t, "add_init", "(far " + node(e.first) + " " + node(e.second) + ")"));
                return m;
            }
            m.name = "passage-" + node(e.first) + "-" + node(e.second);
            m.edits.push_back(atom_edit(t, "add_init", conn(e)));
            if (r_.percent(50))
                m.edits.push_back(atom_edit(t, "add_init", conn({e.second, e.first})));
            return m;
        }
        if (kind == "remove-precondition") {
            std::vector<SchemaLiteral> options;
            if (all(t, [](const Side &s) { return s.blocked_precondition; }))
                options.push_back({"move", "(not (blocked ?b))"}),
                    options.push_back({"move", "(not (blocked ?b))"});
            if (g_.keys && all(t, [](const Side &s) { return s.locked_precondition; }))
                options.push_back({"move", "(not (locked ?b))"});
            if (g_.keys && all(t, [](const Side &s) { return s.unlock_needs_key; }))
                options.push_back({"unlock", "(have ?k)"});
            if (jump)
                options.push_back({"jump", "(far ?a ?b)"});
            if (options.empty() || r_.percent(15))
                options.push_back({"move", "(conn ?a ?b)"});
            return schema("remove_precondition", options, "allow");
        }
        if (kind == "add-effect") {
            std::vector<SchemaLiteral> options = {{"move", "(not (visited ?a))"},
                                                  {"move", "(blocked ?a)"},
                                                  {"move", "(safe ?b)"},
                                                  {"move", "(not (safe ?a))"}};
            if (jump)
                options.push_back({"jump", "(visited ?a)"});
            if (g_.keys)
                options.push_back({"pick", "(not (locked ?n))"}),
                    options.push_back({"unlock", "(visited ?b)"});
            return schema("add_effect", options, "effect");
        }
        if (kind == "remove-effect") {
            std::vector<SchemaLiteral> options = {{"move", "(visited ?b)"},
                                                  {"move", "(not (at ?a))"}};
            if (jump)
                options.push_back({"jump", "(visited ?b)"});
            if (g_.keys)
                options.push_back({"unlock", "(not (locked ?b))"}),
                    options.push_back({"pick", "(not (key-at ?k ?n))"});
            return schema("remove_effect", options, "no-effect");
        }
        if (kind == "remove-goal") {
            std::vector<std::string> goals;
            for (const auto &task : g_.tasks) {
                if (task.visit < 0)
                    continue;
                goals.push_back("(visited " + node(task.visit) + ")");
                goals.push_back("(at " + node(task.goal) + ")");
            }
            if (goals.empty())
                return std::nullopt;
            std::string goal = r_.pick(goals);
            m.name = "drop-goal";
            m.edits.push_back(atom_edit(t, "remove_goal", goal));
            return m;
        }
        if (kind == "unblock" || kind == "add-obstacle") {
            // Atoms that a precondition of a targeted model uses negatively.
            bool remove = kind == "unblock";
            std::vector<std::string> atoms;
            if (any(t, [](const Side &s) { return s.blocked_precondition; }))
                for (int n = 0; n < g_.nodes; ++n)
                    if (remove == all(t, [&](const Side &s) { return s.blocked.count(n) > 0; }))
                        atoms.push_back("(blocked " + node(n) + ")");
            if (g_.keys && any(t, [](const Side &s) { return s.locked_precondition; }))
                for (int n = 0; n < g_.nodes; ++n)
                    if (remove == all(t, [&](const Side &s) { return s.locked.count(n) > 0; }))
                        atoms.push_back("(locked " + node(n) + ")");
            if (t == Target::HUMAN && r_.percent(60)) {
                // Mostly: make people's model of obstacles and doors the robot's.
                std::vector<std::string> robot_like;
                for (const auto &atom : atoms) {
                    int n = std::stoi(atom.substr(atom.find(" n") + 2));
                    bool locked = atom.find("locked") != std::string::npos;
                    bool robot_has = (locked ? g_.robot.locked : g_.robot.blocked).count(n) > 0;
                    if (robot_has != remove)
                        robot_like.push_back(atom);
                }
                if (!robot_like.empty())
                    atoms = robot_like;
            }
            if (atoms.empty())
                return std::nullopt;
            std::string atom = r_.pick(atoms);
            m.name = (remove ? "clear-" : "obstacle-") + atom.substr(1, atom.find(' ') - 1);
            m.edits.push_back(atom_edit(t, remove ? "remove_init" : "add_init", atom));
            return m;
        }
        return std::nullopt;
    }

    unsigned seed_;
    bool restricting_only_;
    bool adding_too_;
    bool robot_ways_;
    Random r_;
    Generated g_;
    int isolated_robot_ = -1, isolated_human_ = -1;
    std::vector<Edge> shortcuts_; // passages only people believe in, from a start to a goal
};

// ---------------------------------------------------------------------------------------
// The comparison.

bool same_value(double a, double b) {
    if (std::isinf(a) || std::isinf(b))
        return a == b;
    return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
}

std::string show(double x) { return std::isinf(x) ? "inf" : number(x); }

std::string show(const std::vector<std::string> &names) {
    std::string out = "{";
    for (std::size_t i = 0; i < names.size(); ++i)
        out += (i ? ", " : "") + names[i];
    return out + "}";
}

struct Answer {
    bool has_best = false;
    Configuration design;
    std::vector<std::string> names;
    double objective = INF;
    bool optimal = false;
    bool limit = false;
    bool has_baseline = false;
    double baseline = INF;
    std::vector<double> baseline_ie; // per task
    long long evaluated = 0;
    double seconds = 0;
    bool hitting_set_proof = false;    // the witness search's hitting-set phase proved it
    std::vector<RankedDesign> ranking; // with `ranking` > 0
};

Answer search(const DesignProblem &problem, SearchMethod method, bool hitting_sets = true,
              int ranking = 0, Padding padding = Padding::LISTED) {
    auto start = std::chrono::steady_clock::now();
    LocalEvaluator evaluator(problem, 1);
    DesignSearchOptions options;
    options.method = method;
    options.max_design_size = problem.max_design_size;
    options.hitting_sets = hitting_sets;
    options.ranking = ranking;
    options.ranking_all = padding == Padding::LISTED;
    DesignResult r = search_design(problem, evaluator, options);
    Answer a;
    a.ranking = r.ranking;
    a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    a.optimal = r.optimal;
    a.limit = r.limit_reached;
    a.evaluated = r.counters.configurations_evaluated;
    a.hitting_set_proof = std::any_of(r.notes.begin(), r.notes.end(), [](const std::string &n) {
        return n.find("proven optimal by the hitting-set phase") != std::string::npos;
    });
    if (r.best) {
        a.has_best = true;
        a.design = r.best->ranked.configuration;
        a.names = design_names(problem, a.design);
        a.objective = r.best->objective.value;
    }
    if (r.baseline) {
        a.has_baseline = true;
        a.baseline = r.baseline->objective.value;
        for (const auto &t : r.baseline->tasks)
            a.baseline_ie.push_back(t.ie);
    }
    return a;
}

std::string describe(const Answer &a) {
    std::ostringstream out;
    out << "design " << (a.has_best ? show(a.names) : "(none)") << ", objective "
        << show(a.objective) << ", " << (a.optimal ? "optimal" : "best_found")
        << (a.limit ? " (limit)" : "") << ", baseline "
        << (a.has_baseline ? show(a.baseline) : "(none)") << ", " << a.evaluated
        << " configurations evaluated";
    return out.str();
}

// The differences between two answers, empty when they agree.
std::string disagreement(const Answer &witness, const Answer &exhaustive) {
    std::ostringstream out;
    if (witness.has_best != exhaustive.has_best || witness.design != exhaustive.design)
        out << " design differs;";
    if (!same_value(witness.objective, exhaustive.objective))
        out << " objective differs;";
    if (witness.optimal != exhaustive.optimal)
        out << " status differs;";
    if (witness.has_baseline != exhaustive.has_baseline ||
        !same_value(witness.baseline, exhaustive.baseline))
        out << " baseline differs;";
    return out.str();
}

int seeds_from_environment() {
    if (const char *n = std::getenv("ENVDESIGN_AGREEMENT_SEEDS"))
        return std::max(1, std::atoi(n));
    return 40;
}

// What the seeds covered, so that agreement cannot come from trivial problems.
struct Coverage {
    int problems = 0;
    std::map<std::string, int> kinds;
    int with_non_restricting = 0, with_negative_preconditions = 0, with_keys = 0, with_costs = 0;
    int models_differ = 0, cost_diff = 0, size_limited = 0, zero_cost = 0, equal_costs = 0;
    int several_tasks = 0, zero_probability = 0, negative_cost = 0, fresh_splits = 0;
    int robot_unsolvable_tasks = 0, human_unsolvable_tasks = 0;
    int non_empty_designs = 0, infinite_baselines = 0, finite_objectives = 0;
    int infinite_objectives = 0, designs_with_non_restricting = 0, designs_of_two_or_more = 0;
    int improved = 0; // best objective below the baseline
};

void count_generated(const Generated &g, Coverage &c) {
    ++c.problems;
    bool non_restricting = false;
    for (const auto &m : g.modifications)
        ++c.kinds[m.kind], non_restricting |= !m.restricting;
    c.with_non_restricting += non_restricting;
    c.with_negative_preconditions +=
        uses_negative_preconditions(g, g.robot) || uses_negative_preconditions(g, g.human);
    c.with_keys += g.keys;
    c.with_costs += g.costs;
    c.models_differ += domain_text(g, g.robot) != domain_text(g, g.human) ||
                       g.robot.conn != g.human.conn || g.robot.blocked != g.human.blocked ||
                       g.robot.locked != g.human.locked;
    c.cost_diff += g.cost_diff;
    c.size_limited += g.max_design_size > 0;
    const auto &costs = g.costs_of_modifications;
    c.zero_cost += std::count(costs.begin(), costs.end(), 0.0) > 0;
    c.negative_cost += std::any_of(costs.begin(), costs.end(), [](double x) { return x < 0; });
    c.fresh_splits +=
        std::any_of(g.modifications.begin(), g.modifications.end(),
                    [](const GeneratedModification &m) { return m.kind == "fresh-split"; });
    c.equal_costs +=
        std::adjacent_find(costs.begin(), costs.end(), std::not_equal_to<>()) == costs.end();
    c.several_tasks += g.tasks.size() > 1;
    c.zero_probability += std::any_of(g.tasks.begin(), g.tasks.end(),
                                      [](const GeneratedTask &t) { return t.probability == 0; });
}

// Which tasks of the unmodified problem have no plan in the robot's or the human's model.
void count_unsolvable(const DesignProblem &problem, Coverage &c) {
    PlanCache planner(planning::PlannerOptions{});
    for (std::size_t t = 0; t < problem.tasks.size(); ++t) {
        ModelPair models = base_models(problem, static_cast<int>(t));
        c.robot_unsolvable_tasks +=
            solve_model(models.robot_domain, models.robot_problem, planner, Deadline{}).status ==
            PlanStatus::UNSOLVABLE;
        c.human_unsolvable_tasks +=
            solve_model(models.human_domain, models.human_problem, planner, Deadline{}).status ==
            PlanStatus::UNSOLVABLE;
    }
}

void count_answer(const Generated &g, const Answer &a, Coverage &c) {
    c.non_empty_designs += !a.design.empty();
    c.designs_of_two_or_more += a.design.size() >= 2;
    c.infinite_baselines += std::isinf(a.baseline);
    c.finite_objectives += !std::isinf(a.objective);
    c.infinite_objectives += std::isinf(a.objective);
    c.improved += a.objective < a.baseline && !same_value(a.objective, a.baseline);
    c.designs_with_non_restricting += std::any_of(
        a.design.begin(), a.design.end(), [&](int m) { return !g.modifications[m].restricting; });
}

fs::path directory_for(unsigned seed) {
    return fs::temp_directory_path() /
           ("envdesign-agreement-" + std::to_string(getpid()) + "-seed" + std::to_string(seed));
}

TEST(WitnessAgreement, WitnessSearchAgreesWithExhaustiveOnRandomProblems) {
    std::vector<unsigned> seeds;
    if (const char *one = std::getenv("ENVDESIGN_AGREEMENT_SEED"))
        seeds.push_back(static_cast<unsigned>(std::atoi(one)));
    else
        for (int s = 0; s < seeds_from_environment(); ++s)
            seeds.push_back(static_cast<unsigned>(s));
    const bool keep_all = std::getenv("ENVDESIGN_AGREEMENT_KEEP") != nullptr;

    Coverage coverage;
    int disagreements = 0;
    double witness_seconds = 0, exhaustive_seconds = 0;
    long long witness_evaluated = 0, exhaustive_evaluated = 0;
    for (unsigned seed : seeds) {
        Generated g = Generator(seed).run();
        fs::path dir = directory_for(seed);
        fs::remove_all(dir);
        fs::path spec = write_spec(g, dir, seed % 5 == 0);
        count_generated(g, coverage);
        EXPECT_TRUE(g.modifications.size() >= 3 && g.modifications.size() <= 7)
            << "seed " << seed << ": " << g.modifications.size() << " modifications";
        bool failed = false;
        try {
            DesignProblem problem = load_design_problem(spec.string());
            count_unsolvable(problem, coverage);
            Answer exhaustive = search(problem, SearchMethod::EXHAUSTIVE);
            Answer witness = search(problem, SearchMethod::WITNESS);
            witness_seconds += witness.seconds, exhaustive_seconds += exhaustive.seconds;
            witness_evaluated += witness.evaluated, exhaustive_evaluated += exhaustive.evaluated;
            count_answer(g, exhaustive, coverage);
            EXPECT_TRUE(exhaustive.optimal && !exhaustive.limit)
                << "seed " << seed << " (" << dir.string() << "): exhaustive is not optimal";
            std::string diff = disagreement(witness, exhaustive);
            if (!diff.empty()) {
                failed = true;
                ++disagreements;
                ADD_FAILURE() << "seed " << seed << ", spec " << spec.string() << ":" << diff
                              << "\n  witness:    " << describe(witness)
                              << "\n  exhaustive: " << describe(exhaustive);
            }
        } catch (const std::exception &e) {
            failed = true;
            ADD_FAILURE() << "seed " << seed << ", spec " << spec.string() << ": " << e.what();
        }
        if (!failed && !keep_all)
            fs::remove_all(dir);
    }

    std::cout << "[ agreement ] " << seeds.size() << " seeds, " << disagreements
              << " disagreements; witness " << number(witness_seconds) << " s, "
              << witness_evaluated << " configurations evaluated; exhaustive "
              << number(exhaustive_seconds) << " s, " << exhaustive_evaluated << "\n"
              << "[ coverage  ] non-restricting " << coverage.with_non_restricting
              << ", negative preconditions " << coverage.with_negative_preconditions << ", keys "
              << coverage.with_keys << ", action costs " << coverage.with_costs
              << ", models differ " << coverage.models_differ << ", COST_DIFF "
              << coverage.cost_diff << ", size limit " << coverage.size_limited << ", zero costs "
              << coverage.zero_cost << ", equal costs " << coverage.equal_costs
              << ", several tasks " << coverage.several_tasks << ", probability 0 "
              << coverage.zero_probability << ", negative costs " << coverage.negative_cost
              << ", fresh predicate shared by two modifications " << coverage.fresh_splits << "\n"
              << "[ coverage  ] robot-unsolvable tasks " << coverage.robot_unsolvable_tasks
              << ", human-unsolvable tasks " << coverage.human_unsolvable_tasks
              << ", non-empty designs " << coverage.non_empty_designs
              << " (2+: " << coverage.designs_of_two_or_more
              << ", with a non-restricting modification: " << coverage.designs_with_non_restricting
              << "), improved " << coverage.improved << ", infinite baselines "
              << coverage.infinite_baselines << ", infinite objectives "
              << coverage.infinite_objectives << "\n[ kinds     ]";
    for (const auto &[kind, n] : coverage.kinds)
        std::cout << ' ' << kind << ' ' << n;
    std::cout << std::endl;

    // The variety is asserted on the CI sample and larger runs, not on a single seed.
    if (seeds.size() < 40)
        return;
    for (const auto &kind : all_kinds())
        EXPECT_GE(coverage.kinds[kind], 1) << "no modification of kind " << kind;
    EXPECT_GE(coverage.with_non_restricting, static_cast<int>(seeds.size()) / 4);
    EXPECT_GE(coverage.with_negative_preconditions, 5);
    EXPECT_GE(coverage.with_keys, 3);
    EXPECT_GE(coverage.with_costs, 5);
    EXPECT_GE(coverage.models_differ, static_cast<int>(seeds.size()) / 2);
    EXPECT_GE(coverage.cost_diff, 5);
    EXPECT_GE(coverage.size_limited, 3);
    EXPECT_GE(coverage.zero_cost, 3);
    EXPECT_GE(coverage.negative_cost, 1);
    EXPECT_GE(coverage.fresh_splits, 3);
    EXPECT_GE(coverage.equal_costs, 3);
    EXPECT_GE(coverage.several_tasks, 10);
    EXPECT_GE(coverage.robot_unsolvable_tasks, 2);
    EXPECT_GE(coverage.human_unsolvable_tasks, 2);
    EXPECT_GE(coverage.non_empty_designs, 5);
    EXPECT_GE(coverage.designs_of_two_or_more, 1);
    EXPECT_GE(coverage.designs_with_non_restricting, 1);
    EXPECT_GE(coverage.improved, 5);
    EXPECT_GE(coverage.infinite_baselines, 2);
    EXPECT_GE(coverage.finite_objectives, static_cast<int>(seeds.size()) / 3);
}

// Several cost-optimal robot plans that people see differently: a jump over every two
// passages a -> x -> b costs the robot as much as the two moves (2), people count it 1 or 4.
void add_equal_cost_jumps(Generated &g, unsigned seed) {
    g.costs = true;
    g.robot.move_cost = 1, g.robot.jump_cost = 2, g.robot.jump = g.human.jump = true;
    g.human.jump_cost = seed % 2 == 0 ? 1 : 4;
    Random r(seed + 1);
    for (auto [a, x] : g.robot.conn)
        for (auto [y, b] : g.robot.conn)
            if (x == y && a != b && r.percent(50))
                g.robot.far.insert({a, b}), g.human.far.insert({a, b});
}

// Whether the witness search and its best-first search alone both agree with every subset;
// a failure names the seed, the spec and the differences.
bool agree_all_three(unsigned seed, const fs::path &spec, const Answer &witness,
                     const Answer &best_first, const Answer &exhaustive) {
    std::string diff = disagreement(witness, exhaustive);
    if (std::string alone = disagreement(best_first, exhaustive); !alone.empty())
        diff += " (best-first alone:" + alone + ")";
    if (diff.empty())
        return true;
    ADD_FAILURE() << "seed " << seed << ", spec " << spec.string() << ":" << diff
                  << "\n  witness:    " << describe(witness)
                  << "\n  exhaustive: " << describe(exhaustive);
    return false;
}

// COST_OPTIMAL and COST_OPTIMAL_BEST_CASE (issue 14): the witness argument there takes every
// action of every optimal robot plan as a witness and bounds the IE term by its least value;
// where every modification restricts (even seeds), the hitting-set phase proves the answer
// with the empty design's worst (best) optimal plan as a floor (docs/design-search.md). Both
// must agree with every subset, and so must the best-first search alone. The same generated
// problems (navigation with equal-cost detours, zero costs, unsolvable tasks), both modes.
TEST(WitnessAgreement, CostOptimalBehavioursAgreeWithExhaustive) {
    int seeds = seeds_from_environment();
    int disagreements = 0, non_empty = 0, differs_from_explicable = 0, finite = 0, proofs = 0,
        non_empty_proofs = 0;
    for (const std::string behaviour : {"COST_OPTIMAL", "COST_OPTIMAL_BEST_CASE"}) {
        for (int s = 0; s < seeds; ++s) {
            unsigned seed = 200000u + static_cast<unsigned>(s);
            Generated g = Generator(seed, s % 2 == 0).run();
            if (s % 3 != 0)
                add_equal_cost_jumps(g, seed);
            fs::path dir = directory_for(seed);
            fs::remove_all(dir);
            fs::path explicable_spec = write_spec(g, dir / "explicable", false);
            g.behaviour = behaviour;
            fs::path spec = write_spec(g, dir, false);
            DesignProblem problem = load_design_problem(spec.string());
            Answer exhaustive = search(problem, SearchMethod::EXHAUSTIVE);
            Answer witness = search(problem, SearchMethod::WITNESS);
            Answer best_first = search(problem, SearchMethod::WITNESS, false);
            Answer explicable =
                search(load_design_problem(explicable_spec.string()), SearchMethod::EXHAUSTIVE);
            non_empty += !exhaustive.design.empty();
            finite += !std::isinf(exhaustive.objective);
            differs_from_explicable += !disagreement(explicable, exhaustive).empty();
            proofs += witness.hitting_set_proof;
            non_empty_proofs += witness.hitting_set_proof && !witness.design.empty();
            EXPECT_TRUE(exhaustive.optimal) << behaviour << " seed " << seed;
            if (!agree_all_three(seed, spec, witness, best_first, exhaustive)) {
                ++disagreements;
                ADD_FAILURE() << behaviour;
                continue;
            }
            fs::remove_all(dir);
        }
    }
    std::cout << "[ agreement ] cost-optimal behaviours: " << 2 * seeds << " problems, "
              << disagreements << " disagreements; non-empty designs " << non_empty
              << ", finite objectives " << finite << ", answer differs from EXPLICABLE "
              << differs_from_explicable << ", hitting-set proofs " << proofs
              << " (non-empty design " << non_empty_proofs << ")" << std::endl;
    if (seeds < 40)
        return;
    EXPECT_GE(non_empty, seeds / 5);
    EXPECT_GE(finite, seeds / 2);
    EXPECT_GE(differs_from_explicable, seeds / 5);
    EXPECT_GE(proofs, seeds / 2);
    EXPECT_GE(non_empty_proofs, seeds / 10);
}

// COST_OPTIMAL and COST_OPTIMAL_BEST_CASE with lanes: restricting modifications beside ones
// that add plans to the robot's model alone. The hitting-set phase takes them, a lane that may
// bring optimal plans of its own dropping the floor (docs/design-search.md); the witness search
// and its best-first search alone must agree with every subset.
TEST(WitnessAgreement, CostOptimalWithLanesAgreesWithExhaustive) {
    int seeds = seeds_from_environment();
    int disagreements = 0, proofs_with_lanes = 0, lanes_chosen = 0;
    for (const std::string behaviour : {"COST_OPTIMAL", "COST_OPTIMAL_BEST_CASE"}) {
        for (int s = 0; s < seeds; ++s) {
            unsigned seed = 400000u + static_cast<unsigned>(s);
            Generated g = Generator(seed, false, true, true).run();
            if (s % 3 != 0)
                add_equal_cost_jumps(g, seed);
            g.behaviour = behaviour;
            fs::path dir = directory_for(seed);
            fs::remove_all(dir);
            fs::path spec = write_spec(g, dir, false);
            DesignProblem problem = load_design_problem(spec.string());
            TouchIndex index(problem);
            auto lane = [&](int m) { return !index.of(m).restricting && index.of(m).adding; };
            bool has_lane = false;
            for (int m = 0; m < index.size(); ++m)
                has_lane = has_lane || lane(m);
            Answer exhaustive = search(problem, SearchMethod::EXHAUSTIVE);
            Answer witness = search(problem, SearchMethod::WITNESS);
            Answer best_first = search(problem, SearchMethod::WITNESS, false);
            proofs_with_lanes += witness.hitting_set_proof && has_lane;
            lanes_chosen += std::any_of(exhaustive.design.begin(), exhaustive.design.end(), lane);
            if (!agree_all_three(seed, spec, witness, best_first, exhaustive)) {
                ++disagreements;
                ADD_FAILURE() << behaviour;
                continue;
            }
            fs::remove_all(dir);
        }
    }
    std::cout << "[ agreement ] cost-optimal behaviours with lanes: " << 2 * seeds << " problems, "
              << disagreements << " disagreements; hitting-set proofs with lanes "
              << proofs_with_lanes << ", best designs with a lane " << lanes_chosen << std::endl;
    if (seeds < 40)
        return;
    EXPECT_GE(proofs_with_lanes, seeds / 2);
    EXPECT_GE(lanes_chosen, seeds / 20);
}

// Problems whose modifications all restrict, up to 9 of them: the witness search proves
// its answer with the hitting-set phase (hitting_set.h), which must agree with every subset.
TEST(WitnessAgreement, HittingSetPhaseAgreesWithExhaustive) {
    int seeds = seeds_from_environment();
    int disagreements = 0, proofs = 0, non_empty_proofs = 0, improved = 0;
    double witness_seconds = 0, exhaustive_seconds = 0;
    for (int s = 0; s < seeds; ++s) {
        unsigned seed = 100000u + static_cast<unsigned>(s);
        Generated g = Generator(seed, true).run();
        fs::path dir = directory_for(seed);
        fs::remove_all(dir);
        fs::path spec = write_spec(g, dir, seed % 5 == 0);
        DesignProblem problem = load_design_problem(spec.string());
        Answer exhaustive = search(problem, SearchMethod::EXHAUSTIVE);
        Answer witness = search(problem, SearchMethod::WITNESS);
        Answer best_first = search(problem, SearchMethod::WITNESS, false);
        witness_seconds += witness.seconds, exhaustive_seconds += exhaustive.seconds;
        if (std::getenv("ENVDESIGN_AGREEMENT_VERBOSE"))
            std::cout << "seed " << seed << " witness " << witness.seconds << " s, exhaustive "
                      << exhaustive.seconds << " s\n";
        proofs += witness.hitting_set_proof;
        non_empty_proofs += witness.hitting_set_proof && !witness.design.empty();
        improved += exhaustive.objective < exhaustive.baseline &&
                    !same_value(exhaustive.objective, exhaustive.baseline);
        if (!agree_all_three(seed, spec, witness, best_first, exhaustive)) {
            ++disagreements;
            continue;
        }
        fs::remove_all(dir);
    }
    std::cout << "[ agreement ] restricting only: " << seeds << " seeds, " << disagreements
              << " disagreements; hitting-set proofs " << proofs << " (non-empty design "
              << non_empty_proofs << "), improved " << improved << "; witness "
              << number(witness_seconds) << " s, exhaustive " << number(exhaustive_seconds) << " s"
              << std::endl;
    if (seeds < 40)
        return;
    EXPECT_GE(proofs, seeds / 2);
    EXPECT_GE(non_empty_proofs, seeds / 10);
}

// Problems with restricting modifications and modifications that add plans (a new passage,
// a rule relaxed), up to 9: the hitting-set phase proves them with the floors of
// addition_floors.h, and must agree with every subset; so must the best-first search alone.
TEST(WitnessAgreement, MixedModificationsAgreeWithExhaustive) {
    int seeds = seeds_from_environment();
    int disagreements = 0, proofs = 0, proofs_with_adding = 0, adding_chosen = 0;
    double witness_seconds = 0, exhaustive_seconds = 0;
    int first = std::getenv("ENVDESIGN_AGREEMENT_FIRST")
                    ? std::atoi(std::getenv("ENVDESIGN_AGREEMENT_FIRST"))
                    : 0;
    for (int s = first; s < first + seeds; ++s) {
        unsigned seed = 200000u + static_cast<unsigned>(s);
        Generated g = Generator(seed, false, true).run();
        fs::path dir = directory_for(seed);
        fs::remove_all(dir);
        fs::path spec = write_spec(g, dir, seed % 5 == 0);
        DesignProblem problem = load_design_problem(spec.string());
        TouchIndex index(problem);
        bool has_adding = false;
        for (int m = 0; m < index.size(); ++m)
            has_adding = has_adding || (!index.of(m).restricting && index.of(m).adding);
        Answer exhaustive = search(problem, SearchMethod::EXHAUSTIVE);
        Answer witness = search(problem, SearchMethod::WITNESS);
        Answer best_first = search(problem, SearchMethod::WITNESS, false);
        witness_seconds += witness.seconds, exhaustive_seconds += exhaustive.seconds;
        proofs += witness.hitting_set_proof;
        if (std::getenv("ENVDESIGN_AGREEMENT_VERBOSE"))
            std::cout << "seed " << seed << " witness " << witness.seconds << " s ("
                      << witness.evaluated << " evaluated), exhaustive " << exhaustive.seconds
                      << " s\n";
        proofs_with_adding += witness.hitting_set_proof && has_adding;
        adding_chosen += witness.hitting_set_proof &&
                         std::any_of(witness.design.begin(), witness.design.end(), [&](int m) {
                             return !index.of(m).restricting && index.of(m).adding;
                         });
        if (!agree_all_three(seed, spec, witness, best_first, exhaustive)) {
            ++disagreements;
            continue;
        }
        if (!std::getenv("ENVDESIGN_AGREEMENT_KEEP"))
            fs::remove_all(dir);
    }
    std::cout << "[ agreement ] restricting and adding: " << seeds << " seeds, " << disagreements
              << " disagreements; hitting-set proofs " << proofs << " (with adding modifications "
              << proofs_with_adding << ", an adding one chosen " << adding_chosen << "); witness "
              << number(witness_seconds) << " s, exhaustive " << number(exhaustive_seconds) << " s"
              << std::endl;
    if (seeds < 40)
        return;
    EXPECT_GE(proofs_with_adding, seeds / 4);
    EXPECT_GE(adding_chosen, 1);
}

// The floors measured in a design with additions (measured_floors.h) hold in every design
// within it, checked against every design evaluated in full on the mixed problems: c_H(pi)
// and c_R* there are never below them. The designs within reach beyond D's own subsets (more
// restricting modifications; modifications that leave the robot's model alone) are counted, so
// the check covers what the phase relies on.
TEST(WitnessAgreement, MeasuredFloorsHoldInEveryDesignWithin) {
    using witness::measured_floor, witness::Within;
    int seeds = std::min(seeds_from_environment(), 20);
    long long human_checks = 0, robot_checks = 0, beyond_subsets = 0, failures = 0;
    for (int s = 0; s < seeds; ++s) {
        unsigned seed = 200000u + static_cast<unsigned>(s);
        Generated g = Generator(seed, false, true).run();
        fs::path dir = directory_for(seed);
        fs::remove_all(dir);
        DesignProblem problem = load_design_problem(write_spec(g, dir, false).string());
        TouchIndex index(problem);
        int n = index.size(), tasks = static_cast<int>(problem.tasks.size());
        std::vector<int> adding;
        std::vector<bool> edits_robot(n);
        for (int m = 0; m < n; ++m) {
            if (!index.of(m).restricting)
                adding.push_back(m);
            edits_robot[m] = index.of(m).edits_robot;
        }
        LocalEvaluator evaluator(problem, 1);
        std::vector<std::vector<TaskExplicability>> value(1u << n);
        std::vector<std::vector<std::optional<double>>> robot(1u << n);
        auto design_of = [&](unsigned mask) {
            Configuration c;
            for (int i = 0; i < n; ++i)
                if (mask & (1u << i))
                    c.push_back(i);
            return c;
        };
        for (unsigned mask = 0; mask < (1u << n); ++mask)
            for (int t = 0; t < tasks; ++t) {
                value[mask].push_back(evaluator.evaluate_task(design_of(mask), t, Deadline{}));
                robot[mask].push_back(evaluator.robot_cost_bound(design_of(mask), t, Deadline{}));
            }
        auto within = [&](const Within &w, const Configuration &c) {
            return std::includes(c.begin(), c.end(), w.restricting.begin(), w.restricting.end()) &&
                   std::none_of(w.outside.begin(), w.outside.end(),
                                [&](int e) { return std::binary_search(c.begin(), c.end(), e); });
        };
        for (unsigned d = 0; d < (1u << n); ++d) {
            std::vector<const TaskExplicability *> evaluations;
            for (const TaskExplicability &e : value[d])
                evaluations.push_back(&e);
            auto floor =
                measured_floor(design_of(d), adding, edits_robot, evaluations, robot[d], true);
            if (!floor)
                continue;
            for (unsigned s2 = 0; s2 < (1u << n); ++s2) {
                Configuration c = design_of(s2);
                bool subset = (s2 & ~d) == 0;
                for (int t = 0; t < tasks; ++t) {
                    if (floor->human[t] && within(floor->human_within, c)) {
                        ++human_checks, beyond_subsets += !subset;
                        failures += value[s2][t].human_plan_cost < *floor->human[t];
                    }
                    if (floor->robot[t] && within(floor->robot_within, c)) {
                        ++robot_checks, beyond_subsets += !subset;
                        failures += robot[s2][t].value_or(INF) < *floor->robot[t];
                    }
                }
            }
        }
        fs::remove_all(dir);
    }
    std::cout << "[ agreement ] measured floors: " << seeds << " seeds, " << human_checks
              << " human and " << robot_checks << " robot checks (" << beyond_subsets
              << " beyond the design's subsets), " << failures << " below a floor" << std::endl;
    EXPECT_EQ(failures, 0);
    EXPECT_GT(human_checks, 0);
    EXPECT_GT(beyond_subsets, 0);
}

// A directed case: a fresh predicate declared by two modifications. "rule" (people are told
// that only marked passages can be used) alone forbids every move of the human's model;
// "marks" (the robot's passages are marked) alone changes nothing. Together they tell people
// about the robot's passages, and the one they wrongly believe in, n0 -> n2, is unmarked:
// IE 1 at cost 0.5, better than the barrier (cost 2) and than nothing (IE e). Each
// modification alone only removes plans or changes nothing, but "marks" is not restricting
// beside "rule", so a search that never adds it to {rule} misses the optimum.
TEST(WitnessAgreement, FreshPredicateSharedByTwoModifications) {
    fs::path dir = fs::temp_directory_path() /
                   ("envdesign-agreement-" + std::to_string(getpid()) + "-fresh-shared");
    fs::remove_all(dir);
    fs::create_directories(dir);
    write_file(dir / "domain.pddl", R"pddl((define (domain agree)
  (:requirements :strips :typing)
  (:types node)
  (:predicates (at ?n - node) (conn ?a ?b - node))
  (:action move
    :parameters (?a ?b - node)
    :precondition (and (at ?a) (conn ?a ?b))
    :effect (and (at ?b) (not (at ?a)))))
)pddl");
    write_file(dir / "robot.pddl", R"pddl((define (problem t0) (:domain agree)
  (:objects n0 n1 n2 - node)
  (:init (at n0) (conn n0 n1) (conn n1 n2))
  (:goal (at n2)))
)pddl");
    write_file(dir / "human.pddl", R"pddl((define (problem t0) (:domain agree)
  (:objects n0 n1 n2 - node)
  (:init (at n0) (conn n0 n1) (conn n1 n2) (conn n0 n2))
  (:goal (at n2)))
)pddl");
    write_file(dir / "spec.textproto", R"spec(robot_domain: "domain.pddl"
task { name: "t0" problem: "robot.pddl" human_problem: "human.pddl" probability: 1 }
modification {
  name: "rule" cost: 0
  edit { model: HUMAN add_predicate: "(ok ?a ?b - node)" }
  edit { model: HUMAN add_precondition { action: "move" literal: "(ok ?a ?b)" } }
}
modification {
  name: "marks" cost: 0.5
  edit { model: HUMAN add_predicate: "(ok ?a ?b - node)" }
  edit { model: HUMAN add_init: "(ok n0 n1)" }
  edit { model: HUMAN add_init: "(ok n1 n2)" }
}
modification {
  name: "barrier" cost: 2
  edit { model: HUMAN remove_init: "(conn n0 n2)" }
}
alpha: 1 beta: 1 kappa: 0 gamma: 1 horizon: 1
)spec");
    DesignProblem problem = load_design_problem((dir / "spec.textproto").string());
    Answer exhaustive = search(problem, SearchMethod::EXHAUSTIVE);
    Answer witness = search(problem, SearchMethod::WITNESS);
    EXPECT_EQ(exhaustive.names, (std::vector<std::string>{"rule", "marks"}));
    EXPECT_NEAR(exhaustive.objective, 1.5, 1e-9);
    EXPECT_NEAR(exhaustive.baseline, std::exp(1.0), 1e-9);
    std::string diff = disagreement(witness, exhaustive);
    EXPECT_TRUE(diff.empty()) << "spec " << (dir / "spec.textproto").string() << ":" << diff
                              << "\n  witness:    " << describe(witness)
                              << "\n  exhaustive: " << describe(exhaustive);
    if (diff.empty())
        fs::remove_all(dir);
}

// ---------------------------------------------------------------------------------------
// Rankings (--ranking N, docs/design-search.md "Ranking").

// The reference: every design up to the size limit, evaluated in full with no bound and no
// inheritance, in SPEC.md's order; the first `n` of finite objective. With Padding::LEFT_OUT
// the first `n` of those with no design one modification smaller before them (ranking.h: a
// design ranks after such a subset exactly when its objective is not clearly lower).
std::vector<RankedDesign> every_design_ranked(const DesignProblem &problem, int n,
                                              Padding padding = Padding::LISTED) {
    int m = static_cast<int>(problem.modifications.size());
    int limit = problem.max_design_size > 0 ? problem.max_design_size : m;
    std::vector<ConfigurationEvaluation> batch;
    for (int mask = 0; mask < (1 << m); ++mask) {
        Configuration c;
        for (int i = 0; i < m; ++i)
            if (mask >> i & 1)
                c.push_back(i);
        if (static_cast<int>(c.size()) <= limit)
            batch.push_back(unevaluated(c));
    }
    LocalEvaluator evaluator(problem, 1);
    std::vector<RankedDesign> all;
    EvaluationCallbacks callbacks;
    callbacks.abandon = [](const ConfigurationEvaluation &) { return false; };
    callbacks.done = [&](ConfigurationEvaluation e) {
        if (e.status != EvaluationStatus::COMPLETE)
            throw std::runtime_error("reference evaluation incomplete");
        std::vector<TaskExplicability> tasks;
        for (auto &t : e.tasks)
            tasks.push_back(*t);
        double cost = design_cost(problem, e.configuration);
        double value = objective_of(problem, cost, tasks).value;
        if (!std::isinf(value))
            all.push_back({value, cost, e.configuration});
    };
    evaluator.evaluate(batch, Deadline{}, callbacks);
    std::sort(all.begin(), all.end(), ranks_before);
    std::vector<RankedDesign> listed;
    for (std::size_t i = 0; i < all.size() && static_cast<int>(listed.size()) < n; ++i) {
        bool padded = false;
        for (std::size_t j = 0; j < i && padding == Padding::LEFT_OUT; ++j) {
            const Configuration &a = all[j].configuration, &b = all[i].configuration;
            padded = padded || (a.size() + 1 == b.size() &&
                                std::includes(b.begin(), b.end(), a.begin(), a.end()));
        }
        if (!padded)
            listed.push_back(all[i]);
    }
    return listed;
}

std::string show(const DesignProblem &problem, const std::vector<RankedDesign> &ranking) {
    std::string out;
    for (const auto &d : ranking)
        out += " " + show(design_names(problem, d.configuration)) + " " + show(d.objective);
    return out.empty() ? " (empty)" : out;
}

// Empty when `ranking` is `reference`: the same designs in the same order, objectives equal.
std::string ranking_disagreement(const std::vector<RankedDesign> &ranking,
                                 const std::vector<RankedDesign> &reference) {
    if (ranking.size() != reference.size())
        return " " + std::to_string(ranking.size()) + " designs, not " +
               std::to_string(reference.size()) + ";";
    for (std::size_t i = 0; i < ranking.size(); ++i)
        if (ranking[i].configuration != reference[i].configuration ||
            !same_value(ranking[i].objective, reference[i].objective))
            return " rank " + std::to_string(i + 1) + " differs;";
    return "";
}

// Both searches' rankings against every design ranked, N in {2, 3, 5}, on the generator of
// the first test (even seeds) and on restricting-only problems (odd seeds, the hitting-set
// phase applies). The witness search also runs without the hitting-set phase, so that the
// best-first search's ranking is checked on its own. Ranked designs often lie in the cone
// of a better one (a superset whose tasks keep their values, objective above it by exactly
// beta times the added cost): those the witness search never evaluates, so the count of
// such designs is asserted, as are full rankings and ties.
// CI runs seeds 0..39; ENVDESIGN_AGREEMENT_SEEDS=300 runs the issue's check.
TEST(RankingAgreement, RankingsAgreeWithEveryDesignRanked) {
    const int sizes[] = {2, 3, 5};
    int seeds = seeds_from_environment();
    int disagreements = 0, full = 0, ties = 0, cone_members = 0, proofs = 0;
    for (int s = 0; s < seeds; ++s) {
        bool restricting = s % 2 == 1;
        unsigned seed = restricting ? 200000u + static_cast<unsigned>(s) : static_cast<unsigned>(s);
        int n = sizes[s % 3];
        Generated g = Generator(seed, restricting).run();
        fs::path dir = directory_for(seed);
        fs::remove_all(dir);
        fs::path spec = write_spec(g, dir, false);
        DesignProblem problem = load_design_problem(spec.string());
        std::vector<RankedDesign> reference = every_design_ranked(problem, n);
        Answer exhaustive = search(problem, SearchMethod::EXHAUSTIVE, true, n);
        Answer witness = search(problem, SearchMethod::WITNESS, true, n);
        Answer best_first = search(problem, SearchMethod::WITNESS, false, n);
        std::string diff;
        for (const auto &[name, answer] :
             {std::pair<std::string, const Answer &>{"exhaustive", exhaustive},
              {"witness", witness},
              {"best-first", best_first}}) {
            std::string d = ranking_disagreement(answer.ranking, reference);
            if (!answer.optimal)
                d += " not optimal;";
            if (!d.empty())
                diff += "\n  " + name + ":" + d + show(problem, answer.ranking);
        }
        if (!diff.empty()) {
            ++disagreements;
            ADD_FAILURE() << "seed " << seed << " (N = " << n << "), spec " << spec.string() << ":"
                          << diff << "\n  every design:" << show(problem, reference);
            continue;
        }
        fs::remove_all(dir);
        full += static_cast<int>(reference.size()) == n;
        proofs += witness.hitting_set_proof;
        for (std::size_t i = 1; i < reference.size(); ++i) {
            ties += nearly_equal(reference[i].objective, reference[i - 1].objective);
            for (std::size_t j = 0; j < i; ++j) {
                const auto &a = reference[j].configuration, &b = reference[i].configuration;
                double extra =
                    problem.weights.beta * (reference[i].design_cost - reference[j].design_cost);
                if (b.size() > a.size() && std::includes(b.begin(), b.end(), a.begin(), a.end()) &&
                    same_value(reference[i].objective, reference[j].objective + extra)) {
                    ++cone_members;
                    break;
                }
            }
        }
    }
    std::cout << "[ ranking   ] " << seeds << " seeds, " << disagreements
              << " disagreements; full rankings " << full << ", ties " << ties
              << ", supersets at exactly the added cost " << cone_members << ", hitting-set proofs "
              << proofs << std::endl;
    if (seeds < 40)
        return;
    EXPECT_GE(full, seeds / 2);
    EXPECT_GE(ties, 5);
    EXPECT_GE(cone_members, 5);
    EXPECT_GE(proofs, seeds / 5);
}

// The default ranking leaves padded designs out (ranking.h): both searches against every
// design ranked with the padded ones dropped, N in {2, 3, 5}, on both generators, in the
// three behaviours the witness search serves (the cones are kept as cones then, not
// offered). Counted: rankings where --ranking-all would have listed a padded design among
// the first N, so that the rule is exercised, and full rankings (rare). CI runs 30 seeds;
// ENVDESIGN_AGREEMENT_SEEDS=N runs N.
TEST(RankingAgreement, PaddedDesignsAreLeftOutAsEveryDesignRankedSays) {
    const int sizes[] = {2, 3, 5};
    const char *behaviours[] = {"", "COST_OPTIMAL", "COST_OPTIMAL_BEST_CASE"};
    int seeds = std::getenv("ENVDESIGN_AGREEMENT_SEEDS") ? seeds_from_environment() : 30;
    int disagreements = 0, full = 0, padded_left_out = 0;
    for (int s = 0; s < seeds; ++s) {
        unsigned seed = 400000u + static_cast<unsigned>(s);
        int n = sizes[s % 3];
        Generated g = Generator(seed, s % 2 == 1).run();
        g.behaviour = behaviours[(s / 3) % 3];
        fs::path dir = directory_for(seed);
        fs::remove_all(dir);
        fs::path spec = write_spec(g, dir, false);
        DesignProblem problem = load_design_problem(spec.string());
        std::vector<RankedDesign> reference = every_design_ranked(problem, n, Padding::LEFT_OUT);
        std::vector<RankedDesign> with_padded = every_design_ranked(problem, n, Padding::LISTED);
        std::string diff;
        for (SearchMethod method : {SearchMethod::EXHAUSTIVE, SearchMethod::WITNESS}) {
            Answer answer = search(problem, method, true, n, Padding::LEFT_OUT);
            std::string d = ranking_disagreement(answer.ranking, reference);
            if (!answer.optimal)
                d += " not optimal;";
            if (!d.empty())
                diff += std::string("\n  ") +
                        (method == SearchMethod::WITNESS ? "witness" : "exhaustive") + ":" + d +
                        show(problem, answer.ranking);
        }
        if (!diff.empty()) {
            ++disagreements;
            ADD_FAILURE() << g.behaviour << " seed " << seed << " (N = " << n << "), spec "
                          << spec.string() << ":" << diff
                          << "\n  without padded designs:" << show(problem, reference)
                          << "\n  every design:" << show(problem, with_padded);
            continue;
        }
        fs::remove_all(dir);
        full += static_cast<int>(reference.size()) == n;
        padded_left_out += !ranking_disagreement(reference, with_padded).empty();
    }
    std::cout << "[ ranking   ] padded designs left out: " << seeds << " seeds, " << disagreements
              << " disagreements; full rankings " << full << ", rankings with a padded design "
              << "left out " << padded_left_out << std::endl;
    if (seeds < 30)
        return;
    // Few designs pay on these small problems (30 seeds: 1 ranking of N), but about half
    // the rankings leave a padded design out: the rule is exercised.
    EXPECT_GE(padded_left_out, seeds / 3);
}

// The COST_OPTIMAL modes have their own witnesses (the worst or best optimal plan, and for a
// finite worst case every action of every optimal plan), so the cones offered to a ranking
// rest on them: both searches' rankings against every design ranked, both modes, N in
// {2, 3, 5}, on the generator of CostOptimalBehavioursAgreeWithExhaustive (on even seeds
// every modification restricts, and the hitting-set phase runs with the ranking's cutoff).
// CI runs 60 seeds per mode; ENVDESIGN_AGREEMENT_SEEDS=200 runs the issue's check.
TEST(RankingAgreement, CostOptimalRankingsAgreeWithEveryDesignRanked) {
    const int sizes[] = {2, 3, 5};
    int seeds = std::getenv("ENVDESIGN_AGREEMENT_SEEDS") ? seeds_from_environment() : 60;
    int disagreements = 0, full = 0, ties = 0, cone_members = 0, differs_from_explicable = 0;
    for (const std::string behaviour : {"COST_OPTIMAL", "COST_OPTIMAL_BEST_CASE"}) {
        for (int s = 0; s < seeds; ++s) {
            unsigned seed = 300000u + static_cast<unsigned>(s);
            int n = sizes[s % 3];
            Generated g = Generator(seed, s % 2 == 0).run();
            if (s % 3 != 0)
                add_equal_cost_jumps(g, seed);
            fs::path dir = directory_for(seed);
            fs::remove_all(dir);
            fs::path explicable_spec = write_spec(g, dir / "explicable", false);
            g.behaviour = behaviour;
            fs::path spec = write_spec(g, dir, false);
            DesignProblem problem = load_design_problem(spec.string());
            std::vector<RankedDesign> reference = every_design_ranked(problem, n);
            Answer explicable = search(load_design_problem(explicable_spec.string()),
                                       SearchMethod::WITNESS, true, n); // only counted below
            Answer exhaustive = search(problem, SearchMethod::EXHAUSTIVE, true, n);
            Answer witness = search(problem, SearchMethod::WITNESS, true, n);
            std::string diff;
            for (const auto &[name, answer] :
                 {std::pair<std::string, const Answer &>{"exhaustive", exhaustive},
                  {"witness", witness}}) {
                std::string d = ranking_disagreement(answer.ranking, reference);
                if (!answer.optimal)
                    d += " not optimal;";
                if (!d.empty())
                    diff += "\n  " + name + ":" + d + show(problem, answer.ranking);
            }
            if (!diff.empty()) {
                ++disagreements;
                ADD_FAILURE() << behaviour << " seed " << seed << " (N = " << n << "), spec "
                              << spec.string() << ":" << diff
                              << "\n  every design:" << show(problem, reference);
                continue;
            }
            fs::remove_all(dir);
            full += static_cast<int>(reference.size()) == n;
            differs_from_explicable += !ranking_disagreement(explicable.ranking, reference).empty();
            for (std::size_t i = 1; i < reference.size(); ++i) {
                ties += nearly_equal(reference[i].objective, reference[i - 1].objective);
                for (std::size_t j = 0; j < i; ++j) {
                    const auto &a = reference[j].configuration, &b = reference[i].configuration;
                    double extra = problem.weights.beta *
                                   (reference[i].design_cost - reference[j].design_cost);
                    if (b.size() > a.size() &&
                        std::includes(b.begin(), b.end(), a.begin(), a.end()) &&
                        same_value(reference[i].objective, reference[j].objective + extra)) {
                        ++cone_members;
                        break;
                    }
                }
            }
        }
    }
    std::cout << "[ ranking   ] cost-optimal behaviours: " << 2 * seeds << " problems, "
              << disagreements << " disagreements; full rankings " << full << ", ties " << ties
              << ", supersets at exactly the added cost " << cone_members
              << ", ranking differs from EXPLICABLE's " << differs_from_explicable << std::endl;
    if (seeds < 40)
        return;
    EXPECT_GE(full, seeds / 2);
    EXPECT_GE(ties, 5);
    EXPECT_GE(cone_members, 5);
    EXPECT_GE(differs_from_explicable, seeds / 5);
}

} // namespace
} // namespace envdesign::design
