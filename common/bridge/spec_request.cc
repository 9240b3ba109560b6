#include "bridge/spec_request.h"

#include "pddl/parse_error.h"
#include "spec/spec_reader.h"

#include <google/protobuf/text_format.h>
#include <google/protobuf/util/json_util.h>

namespace envdesign::bridge {
namespace {

envdesign::spec_file_t file_message(const std::string &path, const std::string &content) {
    envdesign::spec_file_t f;
    f.path = path;
    f.content = content;
    return f;
}

bool is_json(const std::string &name) { return name.size() >= 5 && name.ends_with(".json"); }

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

envdesign::spec_t with_distribution(const envdesign::spec_t &spec, const arrivals::Distribution &d,
                                    const std::vector<arrivals::NewTask> &new_tasks) {
    envdesign::spec::SpecFile parsed = envdesign::spec::read_spec_text(spec.text, spec.name);
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
