#include "cli_error.h"

#include <cstring>
#include <iostream>
#include <regex>

namespace envdesign::cli {

bool json_requested(int argc, const char *const *argv) {
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--") == 0)
            return false;
        if (std::strcmp(argv[i], "--json") == 0)
            return true;
    }
    return false;
}

nlohmann::json error_json(int exit_code, const std::string &message,
                          const std::optional<pddl::Location> &where) {
    nlohmann::json out = {{"status", "error"}, {"exit_code", exit_code}, {"error", message}};
    if (where && !where->file.empty())
        out["file"] = where->file;
    // Line 0 means the place in the file is not known (e.g. the file cannot be opened).
    if (where && where->line > 0) {
        out["line"] = where->line;
        out["column"] = where->column;
    }
    return out;
}

void print_error_json(int exit_code, const std::string &message,
                      const std::optional<pddl::Location> &where) {
    // A JSON document, not a fragment of one: text that is not UTF-8 is replaced.
    std::cout << error_json(exit_code, message, where)
                     .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)
              << std::endl;
}

std::optional<std::pair<pddl::Location, std::string>> split_file_error(const std::string &text) {
    static const std::regex placed(R"(^([^\n]+):([0-9]+):([0-9]+): error: )");
    // A file as a whole ("spec.textproto: error: cannot open file: ..."): no spaces in the
    // name, so that a sentence with ": error: " in it is not taken for a file.
    static const std::regex whole(R"(^([^\s:][^\s]*): error: )");
    std::smatch m;
    if (std::regex_search(text, m, placed)) {
        pddl::Location where{m[1].str(), std::stoi(m[2].str()), std::stoi(m[3].str())};
        return std::make_pair(where, text.substr(m.length(0)));
    }
    if (std::regex_search(text, m, whole))
        return std::make_pair(pddl::Location{m[1].str(), 0, 0}, text.substr(m.length(0)));
    return std::nullopt;
}

int report_failure(bool json, int exit_code, const std::string &message,
                   const std::optional<pddl::Location> &where) {
    // A message that arrived as text (from the coordinator) still names its place.
    if (!where)
        if (auto split = split_file_error(message))
            return report_failure(json, exit_code, split->second, split->first);
    if (where)
        std::cerr << pddl::ParseError(*where, message).what() << std::endl;
    else
        std::cerr << message << std::endl;
    if (json)
        print_error_json(exit_code, message, where);
    return exit_code;
}

} // namespace envdesign::cli
