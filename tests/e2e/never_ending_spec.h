#pragma once
// A design problem whose blind search never ends (tests of work bounded per request).

#include <filesystem>
#include <fstream>
#include <string>

namespace envdesign::e2e {

// 30 switches to turn on: LM-cut sees the 30 steps at once, blind search visits every state
// below 30 (about 10^9): it ends only at a limit.
inline std::string write_switches_spec(const std::filesystem::path &dir) {
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "domain.pddl") << R"((define (domain switches)
  (:requirements :strips)
  (:predicates (off ?s) (on ?s))
  (:action flip :parameters (?s) :precondition (off ?s) :effect (and (on ?s) (not (off ?s)))))
)";
    std::ofstream problem(dir / "all-on.pddl");
    problem << "(define (problem all-on) (:domain switches) (:objects";
    for (int i = 0; i < 30; ++i)
        problem << " s" << i;
    problem << ") (:init";
    for (int i = 0; i < 30; ++i)
        problem << " (off s" << i << ")";
    problem << ") (:goal (and";
    for (int i = 0; i < 30; ++i)
        problem << " (on s" << i << ")";
    problem << ")))\n";
    std::ofstream(dir / "design.textproto")
        << "robot_domain: \"domain.pddl\"\n"
           "task { name: \"all-on\" problem: \"all-on.pddl\" }\n"
           "modification { name: \"first-on\" cost: 1 edit { model: HUMAN add_init: \"(on s0)\" "
           "} }\n";
    return (dir / "design.textproto").string();
}

} // namespace envdesign::e2e
