#include "replay.h"

#include "pddl/input_file.h"
#include "pddl/parse_error.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace envdesign::arrivals_client {
namespace {

using pddl::Location;
using pddl::ParseError;

const std::vector<std::string> COLUMNS = {"task",     "site",         "problem_id",         "utime",
                                          "sequence", "problem_file", "human_problem_file", "from",
                                          "to"};

struct Cell {
    std::string text;
    int column = 1; // 1-based, for messages
};

std::vector<Cell> split(const std::string &line) {
    std::vector<Cell> cells;
    std::size_t start = 0;
    while (true) {
        std::size_t comma = line.find(',', start);
        std::string text = line.substr(start, comma == std::string::npos ? comma : comma - start);
        // Trim blanks (and a '\r' from files written on Windows).
        auto first = text.find_first_not_of(" \t\r");
        auto last = text.find_last_not_of(" \t\r");
        text = first == std::string::npos ? "" : text.substr(first, last - first + 1);
        cells.push_back({text, static_cast<int>(start) + 1});
        if (comma == std::string::npos)
            return cells;
        start = comma + 1;
    }
}

int64_t parse_integer(const Cell &cell, const Location &where) {
    std::size_t used = 0;
    long long value = 0;
    try {
        value = std::stoll(cell.text, &used);
    } catch (const std::exception &) {
        used = 0;
    }
    if (used != cell.text.size())
        throw ParseError(where, "'" + cell.text + "' is not a whole number");
    return value;
}

// A problem file named in a cell: a regular file within the size bound (input_file.h), the
// error at the cell.
std::string read_text(const std::filesystem::path &path, const Location &where) {
    try {
        return pddl::read_input_file(path.string());
    } catch (const ParseError &e) {
        throw ParseError(where, "cannot read '" + path.string() + "': " + e.message());
    }
}

class Reader {
public:
    explicit Reader(const std::string &path) : path_(path) {}

    std::vector<ReplayRow> read() {
        // Never a FIFO, a device or a directory, and bounded (input_file.h).
        std::istringstream in(pddl::read_input_file(path_));
        std::string line;
        std::vector<ReplayRow> rows;
        for (int number = 1; std::getline(in, line); ++number) {
            auto first = line.find_first_not_of(" \t\r");
            if (first == std::string::npos || line[first] == '#')
                continue;
            if (header_.empty())
                read_header(split(line), number);
            else
                rows.push_back(read_row(split(line), number));
        }
        if (header_.empty())
            throw ParseError({path_, 1, 1}, "the replay file has no header line");
        return rows;
    }

private:
    void read_header(const std::vector<Cell> &cells, int line) {
        for (const auto &cell : cells) {
            if (std::find(COLUMNS.begin(), COLUMNS.end(), cell.text) == COLUMNS.end())
                throw ParseError({path_, line, cell.column},
                                 "unknown column '" + cell.text +
                                     "' (expected task, site, "
                                     "problem_id, utime, sequence, "
                                     "problem_file, human_problem_file, from, to)");
            header_.push_back(cell.text);
        }
        auto has = [&](const char *c) {
            return std::find(header_.begin(), header_.end(), c) != header_.end();
        };
        if (has("from") != has("to"))
            throw ParseError({path_, line, 1}, "the header has one of 'from' and 'to'");
        if (!has("task") && !has("from"))
            throw ParseError({path_, line, 1}, "the header has no 'task' column (nor 'from' "
                                               "and 'to')");
    }

    ReplayRow read_row(const std::vector<Cell> &cells, int line) {
        if (cells.size() > header_.size())
            throw ParseError({path_, line, cells[header_.size()].column},
                             "more cells than the header has columns");
        ReplayRow row;
        row.line = line;
        for (std::size_t i = 0; i < cells.size(); ++i)
            set(row, header_[i], cells[i], {path_, line, cells[i].column});
        return row;
    }

    void set(ReplayRow &row, const std::string &column, const Cell &cell, const Location &at) {
        if (column == "task") {
            row.task = cell.text; // empty is allowed: a bad sample, for tests
            return;
        }
        if (column == "from" || column == "to") { // empty: a row of the task column
            if (!cell.text.empty())
                (column == "from" ? row.from : row.to) = cell.text;
            (column == "from" ? row.from_at : row.to_at) = at;
            return;
        }
        if (cell.text.empty())
            return;
        auto dir = std::filesystem::path(path_).parent_path();
        if (column == "site")
            row.site = cell.text;
        else if (column == "problem_id")
            row.problem_id = cell.text;
        else if (column == "utime")
            row.utime = parse_integer(cell, at);
        else if (column == "sequence")
            row.sequence = parse_integer(cell, at);
        else if (column == "problem_file")
            row.problem = read_text(dir / cell.text, at);
        else
            row.human_problem = read_text(dir / cell.text, at);
    }

    std::string path_;
    std::vector<std::string> header_;
};

} // namespace

std::vector<ReplayRow> read_replay_file(const std::string &path) { return Reader(path).read(); }

void name_trips(std::vector<ReplayRow> &rows, const TripNamer &name_of) {
    for (auto &row : rows) {
        if (!row.from && !row.to)
            continue;
        if (!row.from || !row.to)
            throw ParseError(row.from ? row.to_at : row.from_at, "a trip needs both from and to");
        if (!row.task.empty())
            throw ParseError(row.from_at, "a row has a task and a trip: give one");
        if (!name_of)
            throw ParseError(row.from_at, "a trip (from, to) needs the floor: --floor DIR");
        std::string why;
        std::optional<std::string> task = name_of(*row.from, *row.to, why);
        if (!task)
            throw ParseError(row.from_at, why);
        row.task = *task;
    }
}

arrivals::Arrival ReplayNumbering::arrival(const ReplayRow &row, const std::string &problem_id,
                                           const std::string &site, int64_t now_utime) {
    arrivals::Arrival a{row.problem_id.value_or(problem_id),
                        row.site.value_or(site),
                        row.task,
                        0,
                        row.utime.value_or(now_utime),
                        row.problem,
                        row.human_problem};
    int64_t &last = last_[{a.problem_id, a.site}];
    // An explicit sequence number also moves the count on, so that rows after it continue.
    a.sequence = row.sequence.value_or(last + 1);
    last = a.sequence;
    return a;
}

} // namespace envdesign::arrivals_client
