#include "tasks.h"

#include "floor_error.h"

#include "pddl/input_file.h"
#include "pddl/parse_error.h"

#include <charconv>
#include <cmath>
#include <set>
#include <utility>

namespace envdesign::floor {

namespace {

struct Field {
    std::string text;
    int column = 1; // 1-based, of the text's first character
};

// The comma-separated fields of `line`, each without surrounding blanks.
std::vector<Field> split_fields(const std::string &line) {
    std::vector<Field> fields;
    std::size_t start = 0;
    while (true) {
        std::size_t end = line.find(',', start);
        std::string raw = line.substr(start, end == std::string::npos ? end : end - start);
        std::size_t first = raw.find_first_not_of(" \t");
        std::size_t last = raw.find_last_not_of(" \t");
        Field f;
        f.column = static_cast<int>(start + (first == std::string::npos ? 0 : first)) + 1;
        f.text = first == std::string::npos ? "" : raw.substr(first, last - first + 1);
        fields.push_back(f);
        if (end == std::string::npos)
            return fields;
        start = end + 1;
    }
}

std::string place_label(const Floor &floor, int vertex) {
    for (const auto &p : floor.places)
        if (p.vertex == vertex && !p.name.empty())
            return object_name(vertex) + " (" + p.name + ")";
    return object_name(vertex);
}

class CsvReader {
public:
    CsvReader(std::string path, const Floor &floor) : path_(std::move(path)), floor_(floor) {}

    [[noreturn]] void fail(int line, int column, const std::string &message) const {
        throw pddl::ParseError({path_, line, column}, message);
    }

    int place(int line, const Field &f) const {
        std::string why;
        std::optional<int> vertex = find_place(floor_, f.text, why);
        if (!vertex)
            fail(line, f.column, why);
        return *vertex;
    }

    double weight(int line, const Field &f) const {
        double w = 0;
        const char *end = f.text.data() + f.text.size();
        auto [ptr, ec] = std::from_chars(f.text.data(), end, w);
        if (ec != std::errc() || ptr != end || f.text.empty())
            fail(line, f.column, "weight '" + f.text + "' is not a number");
        if (!(w > 0) || !(w <= MAX_TASK_WEIGHT)) // their sum must be finite
            fail(line, f.column,
                 "weight " + f.text + " is not a finite number > 0 and at most 1e12");
        return w;
    }

    FloorTask row(int line, const std::string &text) const {
        std::vector<Field> fields = split_fields(text);
        if (fields.size() != 3)
            fail(line, 1,
                 "a task is 'from,to,weight'; this row has " + std::to_string(fields.size()) +
                     " fields");
        FloorTask task{place(line, fields[0]), place(line, fields[1]), weight(line, fields[2])};
        if (task.from == task.to)
            fail(line, fields[1].column,
                 "the task goes from " + place_label(floor_, task.from) + " to itself");
        return task;
    }

private:
    std::string path_;
    const Floor &floor_;
};

} // namespace

std::optional<int> find_place(const Floor &floor, const std::string &text, std::string &why) {
    for (const auto &p : floor.places)
        if (object_name(p.vertex) == text)
            return p.vertex;
    std::vector<int> named;
    for (const auto &p : floor.places)
        if (!p.name.empty() && p.name == text)
            named.push_back(p.vertex);
    if (named.size() == 1)
        return named.front();
    if (named.empty())
        why = "no place '" + text +
              "' (a place is vI or the name of a vertex on a lane of the graph)";
    else
        why = "'" + text + "' names " + std::to_string(named.size()) + " places (" +
              object_name(named[0]) + ", " + object_name(named[1]) + "): use vI";
    return std::nullopt;
}

std::vector<FloorTask> read_tasks_csv(const std::string &path, const Floor &floor) {
    return parse_tasks_csv(pddl::read_input_file(path), path, floor);
}

std::vector<FloorTask> parse_tasks_csv(const std::string &text, const std::string &path,
                                       const Floor &floor) {
    CsvReader reader(path, floor);
    std::vector<FloorTask> tasks;
    std::set<std::pair<int, int>> seen;
    bool header = false;
    std::size_t start = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0; // a spreadsheet's BOM
    for (int line = 1; start <= text.size(); ++line) {
        std::size_t end = text.find('\n', start);
        std::string row = text.substr(start, end == std::string::npos ? end : end - start);
        start = end == std::string::npos ? text.size() + 1 : end + 1;
        if (!row.empty() && row.back() == '\r')
            row.pop_back();
        if (row.find_first_not_of(" \t") == std::string::npos)
            continue;
        if (!header) {
            std::vector<Field> names = split_fields(row);
            if (names.size() != 3 || names[0].text != "from" || names[1].text != "to" ||
                names[2].text != "weight")
                reader.fail(line, 1, "the first row must be the header 'from,to,weight'");
            header = true;
            continue;
        }
        FloorTask task = reader.row(line, row);
        if (!seen.insert({task.from, task.to}).second)
            reader.fail(line, 1, "task " + task.name() + " is given twice");
        if (tasks.size() == MAX_TASKS)
            reader.fail(line, 1, "more than " + std::to_string(MAX_TASKS) + " tasks");
        tasks.push_back(task);
    }
    if (tasks.empty())
        reader.fail(1, 1, "no task: the file has no row after the header 'from,to,weight'");
    return tasks;
}

std::vector<FloorTask> default_tasks(const Floor &floor) {
    std::vector<int> named;
    for (const auto &p : floor.places)
        if (!p.name.empty())
            named.push_back(p.vertex);
    if (named.size() < 2)
        throw FloorError(std::to_string(named.size()) +
                         " named places on the graph, so no default task: name places in "
                         "traffic-editor, or give the tasks (--tasks FILE)");
    std::size_t pairs = named.size() * (named.size() - 1);
    if (pairs > MAX_TASKS)
        throw FloorError(std::to_string(named.size()) + " named places make " +
                         std::to_string(pairs) + " tasks, more than " + std::to_string(MAX_TASKS) +
                         ": give the tasks (--tasks FILE)");
    std::vector<FloorTask> tasks;
    for (int a : named)
        for (int b : named)
            if (a != b)
                tasks.push_back({a, b, std::nullopt});
    return tasks;
}

std::vector<FloorTask> drop_unreachable(const std::vector<FloorTask> &tasks, const Floor &floor,
                                        const FloorGraph &graph,
                                        std::vector<std::string> &warnings) {
    std::map<int, std::map<int, bool>> reach; // from -> (to -> reachable), computed once a from
    std::vector<FloorTask> kept;
    for (const auto &t : tasks) {
        auto it = reach.find(t.from);
        if (it == reach.end())
            it = reach.emplace(t.from, robot_reachable(graph, t.from)).first;
        if (it->second[t.to]) {
            kept.push_back(t);
            continue;
        }
        warnings.push_back("task " + t.name() + " dropped: the robot's lanes do not lead from " +
                           place_label(floor, t.from) + " to " + place_label(floor, t.to));
    }
    return kept;
}

} // namespace envdesign::floor
