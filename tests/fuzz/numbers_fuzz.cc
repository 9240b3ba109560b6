// Every number parser of issue 21's rule (design/model/numbers.h): the input is a number's text,
// its first byte picks where it enters (a spec field, or a flag). A spec that loads holds
// only numbers in their ranges; a flag that passes its check is finite and in range; nothing
// crashes (the solver aborted on beta 1e25).

#include "design/model/numbers.h"
#include "envdesign/spec_t.hpp"
#include "pddl/parse_error.h"
#include "service/number_flag.h"
#include "spec/design_spec.h"
#include "spec/file_source.h"
#include "spec/spec_reader.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace {

using namespace envdesign;

const char *DOMAIN = "(define (domain d) (:requirements :strips) (:predicates (at ?p) (link ?a ?b))"
                     " (:action go :parameters (?a ?b) :precondition (and (at ?a) (link ?a ?b))"
                     " :effect (and (at ?b) (not (at ?a)))))";
const char *PROBLEM = "(define (problem p) (:domain d) (:objects a b) (:init (at a) (link a b))"
                      " (:goal (at b)))";

const char *FIELDS[] = {"alpha",   "beta",         "kappa",           "gamma",
                        "horizon", "time_limit_s", "max_design_size", "explanation_cost",
                        "cost",    "probability"};

std::string spec_text(const std::string &field, const std::string &value) {
    std::string task_probability = field == "probability" ? " probability: " + value : "";
    std::string cost = field == "cost" ? value : "1";
    std::string text = "robot_domain: \"d.pddl\"\ntask { name: \"t\" problem: \"p.pddl\"" +
                       task_probability + " }\nmodification { name: \"m\" cost: " + cost +
                       " edit { model: HUMAN add_init: \"(link b a)\" } }\n";
    if (field != "probability" && field != "cost")
        text += field + ": " + value + "\n";
    return text;
}

void check_loaded(const design::DesignProblem &p) {
    const design::ObjectiveWeights &w = p.weights;
    bool ok = !design::number_problem(w.alpha, design::WEIGHT) &&
              !design::number_problem(w.beta, design::WEIGHT) &&
              !design::number_problem(w.kappa, design::WEIGHT) &&
              !design::number_problem(w.gamma, design::DISCOUNT) &&
              !design::number_problem(w.horizon, design::HORIZON) &&
              !design::number_problem(w.explanation_cost, design::WEIGHT) &&
              !design::number_problem(p.time_limit_s, design::TIME_LIMIT_S);
    for (const auto &m : p.modifications)
        ok = ok && !design::number_problem(m.cost, design::MODIFICATION_COST);
    for (const auto &t : p.tasks)
        ok = ok && std::isfinite(t.probability) && t.probability >= 0 && t.probability <= 1;
    if (!ok)
        std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    if (size < 1 || size > 200)
        return 0;
    std::string value(reinterpret_cast<const char *>(data) + 1, size - 1);
    std::size_t pick = data[0] % (std::size(FIELDS) + 1);
    if (pick == std::size(FIELDS)) { // a flag: service::number_in
        std::string text = value;
        if (service::number_in(design::TIME_LIMIT_S)(text).empty()) {
            double v = std::strtod(value.c_str(), nullptr);
            if (!std::isfinite(v) || v < 0 || v > design::TIME_LIMIT_S.high)
                std::abort();
        }
        return 0;
    }
    envdesign::spec_t message{};
    message.name = "fuzz.textproto";
    message.text = spec_text(FIELDS[pick], value);
    for (auto [path, content] : {std::pair{"d.pddl", DOMAIN}, std::pair{"p.pddl", PROBLEM}}) {
        envdesign::spec_file_t file{};
        file.path = path;
        file.content = content;
        message.files.push_back(file);
    }
    message.num_files = static_cast<std::int16_t>(message.files.size());
    try {
        spec::SpecFile spec = spec::read_spec_text(message.text, message.name);
        check_loaded(spec::load_design_problem(spec, spec::MessageFiles(message)));
    } catch (const pddl::ParseError &) {
    }
    return 0;
}
