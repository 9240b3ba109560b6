#pragma once
// Seeded small navigation tasks whose robot and human models differ in every way a model
// difference can (model_differences.h), for the EXPLAINING tests:
//   - init: passages people believe in that the robot lacks (often a direct one from start
//     to goal), passages the robot has that people do not know, blocked nodes, jumps (far);
//   - a precondition only one model has (move needs (not (blocked ?b)));
//   - an add effect only one model has ((visited ?b), read by a goal in some seeds);
//   - a goal literal only one model has ((visited nV));
//   - an action schema only one model has (jump);
//   - facts about a predicate nothing reads ((lit ?n): the relevance pruning's case);
//   - action costs that differ (with :action-costs);
//   - a precondition and a delete on the same predicate that people do not know (move needs
//     and uses up (ready), rest restores it): Blocksworld's empty hand, where one difference
//     alone changes nothing and the pair does.
// The same text also makes design problems (spec_text) with modifications of several kinds.

#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace envdesign::design::testing {

class Dice {
public:
    explicit Dice(unsigned seed) : engine_(seed * 104729u + 11u) {}
    int below(int n) { return static_cast<int>(engine_() % static_cast<unsigned>(n)); }
    int between(int lo, int hi) { return lo + below(hi - lo + 1); }
    bool percent(int p) { return below(100) < p; }

private:
    std::mt19937 engine_;
};

using Pass = std::pair<int, int>;

struct Side {
    bool blocked_pre = false, visit_effect = true, visit_goal = false, jump = false;
    bool ready_pre = false, ready_del = false; // move needs / deletes (ready)
    int move_cost = 1, jump_cost = 2;
    std::set<Pass> conn, far;
    std::set<int> blocked, lit;
};

struct GeneratedPair {
    int nodes = 4, start = 0, goal = 1, visit = 2;
    bool costs = false, rest = false; // rest: the action that restores (ready)
    Side robot, human;
};

inline std::string gnode(int n) { return "n" + std::to_string(n); }

inline GeneratedPair generate_pair(unsigned seed) {
    Dice d(seed);
    GeneratedPair g;
    g.nodes = d.between(3, 5);
    g.costs = d.percent(30);
    Side &r = g.robot;
    for (int n = 0; n + 1 < g.nodes; ++n) { // a path through all nodes, both ways
        r.conn.insert({n, n + 1});
        r.conn.insert({n + 1, n});
    }
    if (d.percent(40))
        r.conn.insert({g.nodes - 1, 0});
    g.start = d.below(g.nodes);
    g.goal = (g.start + 1 + d.below(g.nodes - 1)) % g.nodes;
    g.visit = d.below(g.nodes);
    r.blocked_pre = d.percent(40);
    if (r.blocked_pre || d.percent(30)) {
        int b = d.below(g.nodes);
        if (b != g.start && b != g.goal)
            r.blocked.insert(b);
    }
    r.jump = d.percent(30);
    r.far.insert({d.below(g.nodes), d.below(g.nodes)});
    r.visit_goal = d.percent(25);
    g.rest = d.percent(30);
    r.ready_pre = r.ready_del = g.rest;
    r.move_cost = d.between(1, 2);
    r.jump_cost = d.between(1, 3);
    Side h = r;
    // At most a few differences of each kind, so that every subset can be tried.
    if (d.percent(65) && !r.conn.count({g.start, g.goal}))
        h.conn.insert({g.start, g.goal});
    for (int phantom = d.between(0, 2); phantom > 0; --phantom)
        h.conn.insert({d.below(g.nodes), d.below(g.nodes)});
    if (d.percent(25) && !h.conn.empty())
        h.conn.erase(h.conn.begin());
    if (d.percent(25))
        h.blocked_pre = !h.blocked_pre;
    if (d.percent(20))
        h.blocked.insert(d.below(g.nodes));
    if (d.percent(20))
        h.visit_effect = false;
    if (d.percent(15))
        h.visit_goal = !h.visit_goal;
    if (d.percent(25))
        h.jump = !h.jump;
    if (d.percent(20))
        h.far.insert({d.below(g.nodes), d.below(g.nodes)});
    if (d.percent(25))
        h.jump_cost = d.between(1, 3);
    if (g.rest) { // people do not know the robot must rest: one or both of the pair
        h.ready_pre = d.percent(30);
        h.ready_del = !h.ready_pre && d.percent(50);
    }
    for (int lit = d.between(0, 2); lit > 0; --lit)
        (d.percent(50) ? r : h).lit.insert(d.below(g.nodes));
    g.human = h;
    return g;
}

inline std::string cost_text(const GeneratedPair &g, int cost) {
    return g.costs ? " (increase (total-cost) " + std::to_string(cost) + ")" : "";
}

inline std::string pair_domain(const GeneratedPair &g, const Side &s) {
    std::ostringstream o;
    o << "(define (domain nav) (:requirements :strips :typing :negative-preconditions"
      << (g.costs ? " :action-costs" : "") << ")\n (:types node)\n"
      << " (:predicates (at ?n - node) (conn ?a ?b - node) (far ?a ?b - node)"
         " (visited ?n - node) (blocked ?n - node) (lit ?n - node) (ready))\n";
    if (g.costs)
        o << " (:functions (total-cost) - number)\n";
    o << " (:action move :parameters (?a ?b - node)\n  :precondition (and (at ?a) (conn ?a ?b)"
      << (s.blocked_pre ? " (not (blocked ?b))" : "") << (s.ready_pre ? " (ready)" : "")
      << ")\n  :effect (and (at ?b) (not (at ?a))" << (s.visit_effect ? " (visited ?b)" : "")
      << (s.ready_del ? " (not (ready))" : "") << cost_text(g, s.move_cost) << "))\n";
    if (g.rest)
        o << " (:action rest :parameters () :precondition (and) :effect (and (ready)"
          << cost_text(g, 1) << "))\n";
    if (s.jump)
        o << " (:action jump :parameters (?x ?y - node)\n  :precondition (and (at ?x) (far ?x "
             "?y))\n  :effect (and (at ?y) (not (at ?x)) (visited ?y) (lit ?y)"
          << cost_text(g, s.jump_cost) << "))\n";
    o << ")\n";
    return o.str();
}

inline std::string pair_problem(const GeneratedPair &g, const Side &s, const std::string &name) {
    std::ostringstream o;
    o << "(define (problem " << name << ") (:domain nav)\n (:objects";
    for (int n = 0; n < g.nodes; ++n)
        o << ' ' << gnode(n);
    o << " - node)\n (:init (at " << gnode(g.start) << ")" << (g.rest ? " (ready)" : "");
    for (auto [a, b] : s.conn)
        o << " (conn " << gnode(a) << ' ' << gnode(b) << ")";
    for (auto [a, b] : s.far)
        o << " (far " << gnode(a) << ' ' << gnode(b) << ")";
    for (int n : s.blocked)
        o << " (blocked " << gnode(n) << ")";
    for (int n : s.lit)
        o << " (lit " << gnode(n) << ")";
    if (g.costs)
        o << " (= (total-cost) 0)";
    o << ")\n (:goal (and (at " << gnode(g.goal) << ")"
      << (s.visit_goal ? " (visited " + gnode(g.visit) + ")" : "") << "))"
      << (g.costs ? " (:metric minimize (total-cost))" : "") << ")\n";
    return o.str();
}

} // namespace envdesign::design::testing
