#include "bridge/spec_request.h"

#include "design/spec_reader.h"
#include "pddl/input_file.h"
#include "pddl/parse_error.h"

#include <google/protobuf/text_format.h>
#include <google/protobuf/util/json_util.h>

#include <filesystem>
#include <set>
#include <sstream>

namespace envdesign::bridge {
namespace {

namespace fs = std::filesystem;

envdesign::spec_file_t file_message(const std::string &path, const std::string &content) {
    envdesign::spec_file_t f;
    f.path = path;
    f.content = content;
    return f;
}

bool is_json(const std::string &name) { return name.size() >= 5 && name.ends_with(".json"); }

std::string read_file(const fs::path &path, const pddl::Location &where) {
    try {
        return pddl::read_input_file(path.string());
    } catch (const pddl::ParseError &e) {
        throw pddl::ParseError(where, "cannot read '" + path.string() + "': " + e.message());
    }
}

std::string print(const proto::DesignProblem &message, const std::string &name) {
    std::string text;
    if (is_json(name)) {
        google::protobuf::util::JsonPrintOptions options;
        options.preserve_proto_field_names = true;
        if (!google::protobuf::util::MessageToJsonString(message, &text, options).ok())
            throw std::runtime_error("cannot print the spec " + name + " as JSON");
    } else if (!google::protobuf::TextFormat::PrintToString(message, &text)) {
        throw std::runtime_error("cannot print the spec " + name);
    }
    return text;
}

} // namespace

envdesign::spec_t read_spec_message(const std::string &spec_path) {
    design::SpecFile spec = design::read_spec_file(spec_path);
    envdesign::spec_t m{};
    m.name = spec_path;
    m.text = read_file(spec_path, {spec_path, 1, 1});
    std::set<std::string> seen;
    auto add = [&](const std::string &path, const std::string &field) {
        if (path.empty() || !seen.insert(path).second)
            return;
        fs::path full = fs::path(path).is_absolute() ? fs::path(path)
                                                     : fs::path(spec_path).parent_path() / path;
        m.files.push_back(file_message(path, read_file(full, spec.at(field))));
    };
    const auto &p = spec.message;
    add(p.robot_domain(), "robot_domain");
    add(p.human_domain(), "human_domain");
    for (int i = 0; i < p.task_size(); ++i) {
        std::string at = "task[" + std::to_string(i) + "]";
        add(p.task(i).problem(), at + ".problem");
        add(p.task(i).human_problem(), at + ".human_problem");
    }
    m.num_files = static_cast<std::int16_t>(m.files.size());
    return m;
}

envdesign::spec_t with_distribution(const envdesign::spec_t &spec, const arrivals::Distribution &d,
                                    const std::vector<arrivals::NewTask> &new_tasks) {
    design::SpecFile parsed = design::read_spec_text(spec.text, spec.name);
    proto::DesignProblem &message = parsed.message;
    envdesign::spec_t out = spec;
    for (const auto &task : new_tasks) {
        // Files are named by the task's index: a name from the wire ("../x") is no path.
        std::string file = "new-tasks/task-" + std::to_string(message.task_size());
        auto *t = message.add_task();
        t->set_name(task.name);
        t->set_problem(file + ".pddl");
        out.files.push_back(file_message(t->problem(), task.problem));
        if (!task.human_problem.empty()) {
            t->set_human_problem(file + "-human.pddl");
            out.files.push_back(file_message(t->human_problem(), task.human_problem));
        }
    }
    for (auto &t : *message.mutable_task()) {
        auto it = d.find(t.name());
        t.set_probability(it == d.end() ? 0.0 : it->second);
    }
    out.text = print(message, spec.name);
    out.num_files = static_cast<std::int16_t>(out.files.size());
    return out;
}

} // namespace envdesign::bridge
