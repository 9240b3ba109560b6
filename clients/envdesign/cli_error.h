#pragma once
// How the CLI reports a failure, the same for every subcommand: one line on stderr
// ("FILE:LINE:COL: error: ..." when a file is at fault) and, when the command line asked for
// --json, one JSON object on stdout so that scripts never parse stderr:
//   {"status": "error", "exit_code": 2, "error": "undefined predicate 'q'",
//    "file": "domain.pddl", "line": 6, "column": 20}
// "file", "line" and "column" are present only when known. Exit codes are SPEC.md's.

#include "pddl/parse_error.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace envdesign::cli {

// A failure a subcommand found that is not an input file's fault (no coordinator, a bad
// URL, an unwritable output): main() reports it with its exit code.
class CommandError : public std::runtime_error {
public:
    CommandError(int exit_code, const std::string &message)
        : std::runtime_error(message), exit_code_(exit_code) {}
    int exit_code() const { return exit_code_; }

private:
    int exit_code_;
};

// True if `--json` is among the arguments (before a "--"): whether failures, even of the
// command line itself, are also reported as JSON.
bool json_requested(int argc, const char *const *argv);

nlohmann::json error_json(int exit_code, const std::string &message,
                          const std::optional<pddl::Location> &where = std::nullopt);

// "FILE:LINE:COL: error: MESSAGE" (as the coordinator sends bad input back) -> the place and
// MESSAGE; "FILE: error: MESSAGE" (a file that cannot be read) -> FILE at line 0 and MESSAGE;
// nullopt for text of another form.
std::optional<std::pair<pddl::Location, std::string>> split_file_error(const std::string &text);

// Prints error_json(...) on stdout, one line.
void print_error_json(int exit_code, const std::string &message,
                      const std::optional<pddl::Location> &where = std::nullopt);

// Prints the failure on stderr ("WHERE: error: MESSAGE" when `where` is given, or when
// `message` has that form) and, with `json`, error_json(...) on stdout. Returns `exit_code`.
int report_failure(bool json, int exit_code, const std::string &message,
                   const std::optional<pddl::Location> &where = std::nullopt);

} // namespace envdesign::cli
