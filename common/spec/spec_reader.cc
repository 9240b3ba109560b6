#include "spec/spec_reader.h"

#include "pddl/input_file.h"
#include "pddl/text_location.h"
#include "spec/json_positions.h"
#include "spec/spec_suggestions.h"

#include <google/protobuf/io/tokenizer.h>
#include <google/protobuf/text_format.h>
#include <google/protobuf/util/json_util.h>
#include <nlohmann/json.hpp>

#include <regex>
#include <sstream>
#include <vector>

namespace envdesign::spec {
namespace {

namespace gp = google::protobuf;

struct PathStep {
    std::string field;
    int index = -1; // -1: a singular field
};

std::vector<PathStep> split_path(const std::string &path) {
    std::vector<PathStep> steps;
    std::stringstream in(path);
    std::string part;
    while (std::getline(in, part, '.')) {
        PathStep step{part, -1};
        if (auto open = part.find('['); open != std::string::npos) {
            step.field = part.substr(0, open);
            step.index = std::stoi(part.substr(open + 1));
        }
        steps.push_back(step);
    }
    return steps;
}

// Text format: protobuf's ParseInfoTree, walked along the message's descriptors.
class TextLocations : public SpecLocations {
public:
    explicit TextLocations(std::string file) : file_(std::move(file)) {}
    gp::TextFormat::ParseInfoTree &tree() { return tree_; }

    pddl::Location locate(const std::string &path) const override {
        pddl::Location best{file_, 1, 1};
        const gp::Descriptor *type = proto::DesignProblem::descriptor();
        const gp::TextFormat::ParseInfoTree *tree = &tree_;
        for (const PathStep &step : split_path(path)) {
            const gp::FieldDescriptor *field = type ? type->FindFieldByName(step.field) : nullptr;
            if (!field || !tree)
                break;
            auto where = tree->GetLocation(field, field->is_repeated() ? step.index : -1);
            if (where.line < 0)
                break;
            best = {file_, where.line + 1, where.column + 1};
            type = field->message_type();
            tree = type ? tree->GetTreeForNested(field, field->is_repeated() ? step.index : -1)
                        : nullptr;
        }
        return best;
    }

private:
    std::string file_;
    gp::TextFormat::ParseInfoTree tree_;
};

// JSON: the positions of keys found by index_json_positions.
class JsonLocations : public SpecLocations {
public:
    JsonLocations(std::string file, std::map<std::string, pddl::Location> positions)
        : file_(std::move(file)), positions_(std::move(positions)) {}

    pddl::Location locate(const std::string &path) const override {
        for (std::string p = path; !p.empty();) {
            if (auto it = positions_.find(p); it != positions_.end())
                return it->second;
            auto cut = p.find_last_of(".[");
            p = cut == std::string::npos ? "" : p.substr(0, cut);
        }
        return {file_, 1, 1};
    }

    // The first key named `name` anywhere in the file, for protobuf's "NAME: Cannot find
    // field." messages that carry no path.
    pddl::Location locate_key(const std::string &name) const {
        for (const auto &[path, where] : positions_) {
            auto dot = path.find_last_of('.');
            if (path.substr(dot == std::string::npos ? 0 : dot + 1) == snake_case(name))
                return where;
        }
        return {file_, 1, 1};
    }

private:
    std::string file_;
    std::map<std::string, pddl::Location> positions_;
};

// protobuf's text-format wording for an unknown field or enum value -> the names there are,
// with the nearest one (spec_suggestions.h); `word` is set to what the file wrote. Any other
// message as it is.
std::string text_format_message(const std::string &message, std::string &word) {
    static const std::regex no_field(R"re(Message type "([\w.]+)" has no field named "(\w+)")re");
    static const std::regex no_value(
        R"re(Unknown enumeration value of "([^"]*)" for field "(\w+)")re");
    std::smatch m;
    if (std::regex_search(message, m, no_field))
        if (auto *type = gp::DescriptorPool::generated_pool()->FindMessageTypeByName(m[1].str())) {
            word = m[2].str();
            return unknown_field_message(*type, word, word);
        }
    if (std::regex_search(message, m, no_value))
        if (auto *type = enum_of_field(m[2].str())) {
            word = m[1].str();
            return bad_enum_message(*type, m[2].str(), word);
        }
    return message;
}

// protobuf places those errors at the token after the word at fault; the column of the word
// itself when it is written before `column` on `line` (both 0-based), else `column`.
int column_of_word(const std::string &text, int line, int column, const std::string &word) {
    std::size_t start = 0;
    for (int l = 0; l < line && start != std::string::npos; ++l) {
        start = text.find('\n', start);
        if (start != std::string::npos)
            ++start;
    }
    if (word.empty() || start == std::string::npos || column <= 0)
        return column;
    std::size_t at = text.rfind(word, start + static_cast<std::size_t>(column) - 1);
    return at != std::string::npos && at >= start ? static_cast<int>(at - start) : column;
}

class FirstError : public gp::io::ErrorCollector {
public:
    FirstError(const std::string &text, std::string file) : text_(text), file_(std::move(file)) {}

    void AddError(int line, gp::io::ColumnNumber column, const std::string &message) override {
        if (error_)
            return;
        std::string word;
        std::string words = text_format_message(message, word);
        int at = column_of_word(text_, line, column, word);
        error_ = pddl::ParseError({file_, line + 1, at + 1}, words);
    }
    const std::optional<pddl::ParseError> &error() const { return error_; }

private:
    const std::string &text_;
    std::string file_;
    std::optional<pddl::ParseError> error_;
};

bool ends_with(const std::string &s, const std::string &suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// protobuf's JSON parser names the place as "(task[1].probability): invalid value ...",
// "(modification[0]) colour: Cannot find field." or, at the top, ": invalid value ..."; some
// messages and older versions as "colour: ..." alone. The error points at that key (for the
// last form, the first key so named).
pddl::ParseError json_message_error(const std::string &message, const JsonLocations &locations) {
    const std::string unknown = ": Cannot find field.";
    std::string path, rest;
    if (!message.empty() && message[0] == '(' && message.find(')') != std::string::npos) {
        auto close = message.find(')');
        path = snake_case(message.substr(1, close - 1));
        rest = message.substr(close + 1);
    } else if (!message.empty() && message[0] == ':') {
        rest = message;
    } else if (ends_with(message, unknown)) { // "taks: Cannot find field." at the top
        std::string key = snake_case(message.substr(0, message.size() - unknown.size()));
        return pddl::ParseError(
            locations.locate_key(key),
            unknown_field_message(*proto::DesignProblem::descriptor(), key, key));
    } else {
        auto colon = message.find(':');
        std::string key = colon == std::string::npos ? "" : message.substr(0, colon);
        return pddl::ParseError(locations.locate_key(key), message);
    }
    rest.erase(0, rest.find_first_not_of(" :"));
    if (rest.size() > unknown.size() && ends_with(rest, unknown)) {
        std::string key = snake_case(rest.substr(0, rest.size() - unknown.size()));
        std::string field = path.empty() ? key : path + "." + key;
        const gp::Descriptor *type = message_type_at(path);
        return pddl::ParseError(locations.locate(field),
                                type ? unknown_field_message(*type, key, field)
                                     : "unknown field '" + field + "'");
    }
    // An enum value: 'invalid value "HUMANS" for type type.googleapis.com/envdesign.proto.X'.
    static const std::regex bad_value(
        R"re(invalid value "([^"]*)" for type (?:[\w.]+/)?([\w.]+))re");
    std::smatch v;
    if (std::regex_search(rest, v, bad_value))
        if (auto *type = gp::DescriptorPool::generated_pool()->FindEnumTypeByName(v[2].str())) {
            auto dot = path.find_last_of('.');
            std::string field = path.substr(dot == std::string::npos ? 0 : dot + 1);
            return pddl::ParseError(locations.locate(path),
                                    bad_enum_message(*type, field, v[1].str()));
        }
    // A duplicate key, or two members of a oneof (two kinds in one edit): at the second key.
    static const std::regex twice(R"(oneof field '_?(\w+)' is already set\. Cannot set '(\w+)')");
    std::smatch m;
    if (std::regex_search(rest, m, twice)) {
        std::string key = snake_case(m[2].str());
        std::string field = path.empty() ? key : path + "." + key;
        std::string why = m[1].str() == m[2].str()
                              ? "'" + field + "' is given twice"
                              : "only one field of '" + m[1].str() + "' may be given: '" + field +
                                    "' is a second one";
        return pddl::ParseError(locations.locate(field), why);
    }
    return pddl::ParseError(locations.locate(path), (path.empty() ? "" : path + ": ") + rest);
}

SpecFile read_json(const std::string &text, const std::string &path) {
    check_json_limits(text, path); // first: the readers below recurse or throw without a line
    try {
        auto parsed = nlohmann::json::parse(text); // only for the position of a syntax error
        (void)parsed;
    } catch (const nlohmann::json::parse_error &e) {
        std::string message = e.what();
        auto reason = message.find("syntax error");
        throw pddl::ParseError(
            pddl::location_of_byte(text, e.byte ? e.byte - 1 : 0, path),
            "malformed JSON: " + (reason == std::string::npos ? message : message.substr(reason)));
    } catch (const nlohmann::json::exception &e) { // anything check_json_limits missed
        throw pddl::ParseError({path, 1, 1}, std::string("malformed JSON: ") + e.what());
    }
    auto locations = std::make_unique<JsonLocations>(path, index_json_positions(text, path));
    SpecFile spec{path, {}, nullptr};
    auto status = gp::util::JsonStringToMessage(text, &spec.message);
    if (!status.ok())
        throw json_message_error(std::string(status.message()), *locations);
    spec.locations = std::move(locations);
    return spec;
}

SpecFile read_text(const std::string &text, const std::string &path) {
    auto locations = std::make_unique<TextLocations>(path);
    FirstError errors(text, path);
    gp::TextFormat::Parser parser;
    parser.RecordErrorsTo(&errors);
    parser.WriteLocationsTo(&locations->tree());
    SpecFile spec{path, {}, nullptr};
    if (!parser.ParseFromString(text, &spec.message)) {
        if (errors.error())
            throw *errors.error();
        throw pddl::ParseError({path, 1, 1}, "malformed design problem file");
    }
    spec.locations = std::move(locations);
    return spec;
}

} // namespace

SpecLocations::~SpecLocations() = default;

SpecFile read_spec_text(const std::string &text, const std::string &path) {
    return ends_with(path, ".json") ? read_json(text, path) : read_text(text, path);
}

SpecFile read_spec_file(const std::string &path) {
    return read_spec_text(pddl::read_input_file(path), path);
}

} // namespace envdesign::spec
