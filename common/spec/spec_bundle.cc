#include "spec/spec_bundle.h"

#include "pddl/input_file.h"
#include "spec/file_source.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <set>

namespace envdesign::spec {
namespace {

// Protobuf text format, only as far as finding string fields and nesting needs.
class TextScanner {
public:
    explicit TextScanner(const std::string &text) : s_(text) {}

    std::vector<NamedPath> scan() {
        std::vector<std::string> open; // names of the enclosing messages
        std::vector<NamedPath> found;
        int tasks = 0;
        while (skip_space(), i_ < s_.size()) {
            char c = s_[i_];
            if (c == '}' || c == '>') {
                ++i_;
                if (!open.empty())
                    open.pop_back();
                continue;
            }
            if (!(std::isalpha(static_cast<unsigned char>(c)) || c == '_')) {
                skip_token();
                continue;
            }
            int line = line_, column = column_at(i_);
            std::string name = identifier();
            skip_space();
            if (i_ < s_.size() && s_[i_] == ':')
                ++i_, skip_space();
            if (i_ < s_.size() && (s_[i_] == '{' || s_[i_] == '<')) {
                ++i_;
                if (open.empty() && name == "task")
                    ++tasks;
                open.push_back(name);
                continue;
            }
            if (i_ >= s_.size() || (s_[i_] != '"' && s_[i_] != '\''))
                continue;
            std::string value = strings();
            if (open.empty() && (name == "robot_domain" || name == "human_domain"))
                found.push_back({name, value, line, column});
            else if (open.size() == 1 && open[0] == "task" &&
                     (name == "problem" || name == "human_problem"))
                found.push_back(
                    {"task[" + std::to_string(tasks - 1) + "]." + name, value, line, column});
        }
        return found;
    }

private:
    void skip_space() {
        while (i_ < s_.size()) {
            if (s_[i_] == '#') {
                while (i_ < s_.size() && s_[i_] != '\n')
                    ++i_;
            } else if (std::isspace(static_cast<unsigned char>(s_[i_]))) {
                if (s_[i_] == '\n')
                    ++line_, line_start_ = i_ + 1;
                ++i_;
            } else {
                return;
            }
        }
    }
    void skip_token() {
        if (s_[i_] == '"' || s_[i_] == '\'') {
            strings();
            return;
        }
        ++i_;
    }
    std::string identifier() {
        std::size_t start = i_;
        while (i_ < s_.size() &&
               (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_' || s_[i_] == '.'))
            ++i_;
        return s_.substr(start, i_ - start);
    }
    // One or more adjacent quoted strings, concatenated, with C escapes.
    std::string strings() {
        std::string value;
        while (i_ < s_.size() && (s_[i_] == '"' || s_[i_] == '\'')) {
            char quote = s_[i_++];
            while (i_ < s_.size() && s_[i_] != quote && s_[i_] != '\n') {
                char c = s_[i_++];
                if (c == '\\' && i_ < s_.size())
                    c = unescape(s_[i_++]);
                value += c;
            }
            ++i_;
            skip_space();
        }
        return value;
    }
    static char unescape(char c) {
        switch (c) {
        case 'n':
            return '\n';
        case 't':
            return '\t';
        default:
            return c; // \" \' \\ and, in paths, nothing else of use
        }
    }
    int column_at(std::size_t i) const { return static_cast<int>(i - line_start_) + 1; }

    const std::string &s_;
    std::size_t i_ = 0;
    int line_ = 1;
    std::size_t line_start_ = 0;
};

std::string json_string(const nlohmann::json &object, const char *snake, const char *camel) {
    for (const char *key : {snake, camel})
        if (auto it = object.find(key); it != object.end() && it->is_string())
            return it->get<std::string>();
    return "";
}

std::vector<NamedPath> json_paths(const std::string &text) {
    std::vector<NamedPath> found;
    nlohmann::json spec = nlohmann::json::parse(text, nullptr, false);
    if (!spec.is_object())
        return found; // the coordinator says what is wrong with it
    for (auto [snake, camel] :
         {std::pair{"robot_domain", "robotDomain"}, std::pair{"human_domain", "humanDomain"}})
        if (auto path = json_string(spec, snake, camel); !path.empty())
            found.push_back({snake, path});
    auto tasks = spec.find("task");
    if (tasks == spec.end() || !tasks->is_array())
        return found;
    for (std::size_t i = 0; i < tasks->size(); ++i) {
        if (!(*tasks)[i].is_object())
            continue;
        std::string at = "task[" + std::to_string(i) + "].";
        if (auto p = json_string((*tasks)[i], "problem", "problem"); !p.empty())
            found.push_back({at + "problem", p});
        if (auto p = json_string((*tasks)[i], "human_problem", "humanProblem"); !p.empty())
            found.push_back({at + "human_problem", p});
    }
    return found;
}

bool ends_with(const std::string &s, const std::string &suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

} // namespace

std::vector<NamedPath> named_paths(const std::string &text, bool json) {
    return json ? json_paths(text) : TextScanner(text).scan();
}

envdesign::spec_t bundle_spec(const std::string &spec_path) {
    envdesign::spec_t spec;
    spec.name = spec_path;
    spec.text = pddl::read_input_file(spec_path);
    DiskFiles disk(spec_path);
    std::set<std::string> seen;
    for (const NamedPath &named : named_paths(spec.text, ends_with(spec_path, ".json"))) {
        if (!seen.insert(named.path).second)
            continue;
        envdesign::spec_file_t file;
        file.path = named.path;
        try {
            file.content = disk.read(named.path, named.field).content;
        } catch (const MissingFile &e) {
            throw pddl::ParseError({spec_path, named.line, named.column}, e.what());
        }
        spec.files.push_back(std::move(file));
    }
    spec.num_files = static_cast<std::int16_t>(spec.files.size());
    return spec;
}

} // namespace envdesign::spec
