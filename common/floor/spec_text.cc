#include "spec_text.h"

#include <array>
#include <charconv>
#include <set>
#include <sstream>

namespace envdesign::floor {

namespace {

std::string quoted(const std::string &text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\')
            out += '\\';
        if (c == '\n')
            out += "\\n";
        else
            out += c;
    }
    return out + "\"";
}

std::string atom(const Edge &e) {
    return "(connected " + object_name(e.from) + " " + object_name(e.to) + ")";
}

const Place &place_of(const FloorProblem &p, int vertex) {
    return p.floor.places[p.graph.index.at(vertex)];
}

std::string label(const FloorProblem &p, int vertex) {
    const std::string &name = place_of(p, vertex).name;
    return object_name(vertex) + (name.empty() ? "" : " (" + name + ")");
}

// The edges of a model: the robot's, or with the sight lines as well.
std::vector<Edge> model_edges(const FloorProblem &p, bool human) {
    std::set<Edge> edges(p.graph.robot.begin(), p.graph.robot.end());
    if (human)
        edges.insert(p.graph.human_only.begin(), p.graph.human_only.end());
    return {edges.begin(), edges.end()};
}

void write_init(std::ostringstream &out, const FloorProblem &p, const FloorTask &t, bool human) {
    out << "  (:init (at " << object_name(t.from) << ") (= (total-cost) 0)\n";
    for (const Edge &e : model_edges(p, human))
        out << "    " << atom(e) << "\n";
    // Lengths of every edge of either model (a lane candidate adds a sight line to the
    // robot's model, and its length must be there).
    for (const Edge &e : model_edges(p, true))
        out << "    (= (length " << object_name(e.from) << " " << object_name(e.to) << ") "
            << edge_length_dm(p.floor, p.graph, e) << ")\n";
    out << "  )\n";
}

const char *edit_model(EditModel m) {
    return m == EditModel::HUMAN ? "HUMAN" : m == EditModel::ROBOT ? "ROBOT" : "BOTH";
}

void write_modification(std::ostringstream &out, const Candidate &c) {
    out << "modification {\n  name: " << quoted(c.name) << " cost: " << number_text(c.cost) << "\n";
    for (const InitEdit &e : c.edits)
        out << "  edit { model: " << edit_model(e.model)
            << (e.add ? " add_init: " : " remove_init: ") << quoted(atom(e.edge)) << " }\n";
    out << "}\n";
}

} // namespace

std::string number_text(double value) {
    std::array<char, 64> buffer{};
    auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return std::string(buffer.data(), end);
}

std::string domain_text() {
    return "; A floor (envdesign floor import, FLOORS.md): the robot moves between places;\n"
           "; which moves exist is in each problem's (connected p q), their lengths in\n"
           "; decimetres in (length p q). The robot's problems have its lanes, the human\n"
           "; problems also the sight lines people expect it to take.\n"
           "(define (domain floor)\n"
           "  (:requirements :strips :typing :action-costs)\n"
           "  (:types place)\n"
           "  (:predicates (at ?p - place) (connected ?from ?to - place))\n"
           "  (:functions (length ?from ?to - place) - number (total-cost) - number)\n"
           "  (:action move\n"
           "    :parameters (?from ?to - place)\n"
           "    :precondition (and (at ?from) (connected ?from ?to))\n"
           "    :effect (and (not (at ?from)) (at ?to)\n"
           "                 (increase (total-cost) (length ?from ?to)))))\n";
}

std::string robot_problem_path(const FloorTask &task) { return "tasks/" + task.name() + ".pddl"; }

std::string human_problem_path(const FloorTask &task) {
    return "tasks/" + task.name() + "-human.pddl";
}

std::string problem_text(const FloorProblem &p, std::size_t task, bool human) {
    const FloorTask &t = p.tasks[task];
    std::ostringstream out;
    out << "; Task " << t.name() << ": from " << label(p, t.from) << " to " << label(p, t.to)
        << "; " << (human ? "the human model (lanes and sight lines)" : "the robot's model (lanes)")
        << ".\n(define (problem " << t.name() << (human ? "-human" : "") << ")\n  (:domain floor)\n"
        << "  (:objects";
    for (const Place &pl : p.floor.places)
        out << " " << object_name(pl.vertex);
    out << " - place)\n";
    write_init(out, p, t, human);
    out << "  (:goal (at " << object_name(t.to) << "))\n  (:metric minimize (total-cost)))\n";
    return out.str();
}

std::string spec_text(const FloorProblem &p) {
    std::ostringstream out;
    out << "# A floor's design problem, written by `envdesign floor import` (docs/floors.md)\n"
        << "# from " << p.floor.source << ", level " << p.floor.level << ", graph " << p.floor.graph
        << ": " << p.floor.places.size() << " places, " << p.graph.robot.size() << " robot edges, "
        << p.graph.human_only.size() << " human-only edges (sight " << number_text(p.sight_m)
        << " m). Lengths in decimetres; geometry in floor.json.\n"
        << "robot_domain: \"domain.pddl\"\n";
    for (std::size_t i = 0; i < p.tasks.size(); ++i) {
        const FloorTask &t = p.tasks[i];
        out << "task { name: " << quoted(t.name()) << " problem: " << quoted(robot_problem_path(t))
            << " human_problem: " << quoted(human_problem_path(t));
        if (auto prob = task_probability(p, i))
            out << " probability: " << number_text(*prob);
        out << " }\n";
    }
    for (const Candidate &c : p.candidates)
        write_modification(out, c);
    const Weights &w = p.weights;
    out << "alpha: " << number_text(w.alpha) << " beta: " << number_text(w.beta)
        << " kappa: " << number_text(w.kappa) << " gamma: " << number_text(w.gamma)
        << " horizon: " << w.horizon << "\ndistance: COST_DIFF\n";
    return out.str();
}

std::optional<double> task_probability(const FloorProblem &p, std::size_t task) {
    double sum = 0;
    for (const auto &t : p.tasks)
        sum += t.weight.value_or(0);
    if (!p.tasks[task].weight || !(sum > 0))
        return std::nullopt;
    return *p.tasks[task].weight / sum;
}

} // namespace envdesign::floor
