#pragma once
// Replay files for `envdesign-arrivals --replay FILE.csv`: one arrival a line.
//
//   # comments and blank lines are skipped
//   task,site,problem_id,utime,sequence,problem_file,human_problem_file
//   serve-g1
//   serve-g2,dock-2
//   clean-g3,,,,,clean-g3.pddl
//
// The first other line is the header: it names the columns, in any order; only `task` is
// required (or `from` and `to` instead: a trip on an imported floor, its places by vI or by
// label, named as the floor's task vI-vJ; `envdesign-arrivals --floor DIR`).
// An empty cell takes the default: site and problem_id from the command line,
// utime the time of publishing, sequence the next number of that (problem_id, site), no
// problem. utime and sequence cells are taken as written, absurd values included (that is
// how tests send bad samples). problem_file and human_problem_file are paths relative to
// the replay file; their text is read when the file is loaded (a new task's PDDL problem).
// Cells are not quoted; a value cannot contain a comma. The replay file and the problem
// files are read as every input file is (pddl/input_file.h): regular files of bounded size
// only, so a FIFO, a device or a directory is bad input instead of a read that never ends.

#include "arrivals/arrival.h"
#include "pddl/parse_error.h"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace envdesign::arrivals_client {

struct ReplayRow {
    int line = 0;
    std::string task;
    // A trip's places (columns from, to), and where they are written; the task is then named
    // by name_trips().
    std::optional<std::string> from, to;
    pddl::Location from_at, to_at;
    std::optional<std::string> site, problem_id;
    std::optional<int64_t> utime, sequence;
    std::string problem, human_problem; // texts, read from the files named
};

// Throws pddl::ParseError "FILE:LINE:COL: error: ..." for a file that cannot be read or is
// not a regular file ("FILE: error: ..."), a header without `task`, an unknown column, a row with
// too many cells, a number that is not one, or a problem file that cannot be read.
std::vector<ReplayRow> read_replay_file(const std::string &path);

// Names the task of every row with `from` and `to` by `name_of(from, to, why)` (nullopt:
// bad input, `why` says why). Throws pddl::ParseError at the row's `from` cell for a trip
// that cannot be named, or when `name_of` is empty (no floor given).
using TripNamer = std::function<std::optional<std::string>(const std::string &, const std::string &,
                                                           std::string &)>;
void name_trips(std::vector<ReplayRow> &rows, const TripNamer &name_of);

// Fills the defaults of `row`; `sequences` numbers each (problem_id, site) from 1.
class ReplayNumbering {
public:
    arrivals::Arrival arrival(const ReplayRow &row, const std::string &problem_id,
                              const std::string &site, int64_t now_utime);

private:
    std::map<std::pair<std::string, std::string>, int64_t> last_; // (problem_id, site)
};

} // namespace envdesign::arrivals_client
