#pragma once
// A design problem file (SPEC.md, "Design problem file") -> a checked DesignProblem.
//
// The PDDL files the spec names come from a FileSource (file_source.h): the disk, paths
// relative to the spec file, or the files a spec_t message carries (spec_message.h).
// Everything is checked here, once, so that the search never meets bad input: the PDDL
// files parse, every task's models compile, each modification applies on its own to every
// task (unknown actions, predicates, objects or parameters, wrong arities, and removes of
// what no task has are errors), probabilities are non-negative with a positive sum, weights
// are in range.
//
// Errors are pddl::ParseError "SPEC:LINE:COL: error: ..." naming the field at fault; an
// error inside a PDDL file names that file, with a note naming the spec line that refers
// to it.

#include "design/design_problem.h"
#include "spec/file_source.h"
#include "spec/spec_reader.h"

#include <optional>
#include <string>

namespace envdesign::spec {

// How much of a spec is checked.
enum class Checks {
    // Everything above: a local run, and the coordinator, the one that accepts a request.
    FULL,
    // Parse only (spec text, PDDL, edit texts, values): no modification is applied STRICT
    // and no task compiled or grounded. For a planner: the spec came with a content hash that
    // its assembled bytes matched, and the coordinator loaded exactly those bytes with FULL
    // before publishing them (bus authentication, when on, says who sent them). Redoing the
    // full check on every planner cost as much as the coordinator's. What a job does with a
    // spec (applying edits, grounding) still throws on anything bad, and the planner catches
    // it per job.
    TRUSTED_BY_HASH,
};

design::DesignProblem load_design_problem(const std::string &spec_path);

// "SPEC:LINE:COL: warning: the task probabilities sum to 1.1, not 1; they were normalised
// to a 0.545455, b 0.454545" when the probabilities written in `spec` do not sum to 1;
// nothing when they do, when no task writes one, or when they are bad input (negative, not
// finite, a zero sum: load_design_problem says so). load_design_problem keeps it in
// DesignProblem::warnings; a client of a coordinator asks here.
std::optional<std::string> probability_warning(const SpecFile &spec);

// From a spec already read; its PDDL files come from `files`. A file `files` cannot give is
// an error at the spec's field naming it.
design::DesignProblem load_design_problem(const SpecFile &spec, const FileSource &files,
                                          Checks checks = Checks::FULL);

// The same with the files on disk, relative to the directory of spec.path.
design::DesignProblem load_design_problem(const SpecFile &spec);

} // namespace envdesign::spec
