#include "spec/spec_suggestions.h"

#include "spec/proto/design_problem.pb.h"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace envdesign::spec {
namespace {

namespace gp = google::protobuf;

std::string lower(std::string s) {
    for (char &c : s)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// Optimal string alignment distance: Levenshtein plus a swap of two neighbours, the typos
// people make most ("probabilty", "modle").
std::size_t edit_distance(const std::string &a, const std::string &b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i)
        d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j)
        d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t change = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + change});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

// "Task" -> "task", "DesignProblem" -> "the design problem", "ActionLiteral" -> "action
// literal": the type as the spec reference names it.
std::string type_words(const gp::Descriptor &type) {
    if (&type == proto::DesignProblem::descriptor())
        return "the design problem";
    std::string words;
    for (char c : type.name()) {
        if (std::isupper(static_cast<unsigned char>(c)) && !words.empty())
            words += ' ';
        words += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return words;
}

// "a, b or c"
std::string listed(const std::vector<std::string> &names, const char *last_separator) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i)
        out += (i == 0 ? "" : i + 1 == names.size() ? last_separator : ", ") + names[i];
    return out;
}

void collect_enums(const gp::Descriptor &type, const std::string &field,
                   std::vector<const gp::EnumDescriptor *> &found) {
    for (int i = 0; i < type.field_count(); ++i) {
        const gp::FieldDescriptor *f = type.field(i);
        if (f->name() == field && f->enum_type() &&
            std::find(found.begin(), found.end(), f->enum_type()) == found.end())
            found.push_back(f->enum_type());
    }
    for (int i = 0; i < type.nested_type_count(); ++i)
        collect_enums(*type.nested_type(i), field, found);
}

} // namespace

std::string nearest_name(const std::string &written, const std::vector<std::string> &names) {
    const std::size_t most = std::max<std::size_t>(1, written.size() / 3);
    std::string best;
    std::size_t best_distance = most + 1;
    for (const std::string &name : names) {
        std::size_t d = edit_distance(lower(written), lower(name));
        if (d < best_distance) {
            best = name;
            best_distance = d;
        }
    }
    return best;
}

std::string unknown_field_message(const gp::Descriptor &type, const std::string &written,
                                  const std::string &shown) {
    std::vector<std::string> names;
    for (int i = 0; i < type.field_count(); ++i)
        names.push_back(std::string(type.field(i)->name()));
    std::string text = "unknown field '" + shown + "' in " + type_words(type);
    std::string near = nearest_name(written, names);
    if (!near.empty())
        return text + " (did you mean '" + near + "'?)";
    return text + "; its fields are " + listed(names, ", ");
}

std::string bad_enum_message(const gp::EnumDescriptor &type, const std::string &field,
                             const std::string &written) {
    std::vector<std::string> names;
    for (int i = 0; i < type.value_count(); ++i)
        names.push_back(std::string(type.value(i)->name()));
    std::string text =
        "'" + written + "' is not a value of " + field + ": " + listed(names, " or ");
    std::string near = nearest_name(written, names);
    return near.empty() ? text : text + " (did you mean " + near + "?)";
}

const gp::Descriptor *message_type_at(const std::string &path) {
    const gp::Descriptor *type = proto::DesignProblem::descriptor();
    std::stringstream in(path);
    std::string step;
    while (type && std::getline(in, step, '.')) {
        const gp::FieldDescriptor *field = type->FindFieldByName(step.substr(0, step.find('[')));
        type = field ? field->message_type() : nullptr;
    }
    return type;
}

const gp::EnumDescriptor *enum_of_field(const std::string &field) {
    std::vector<const gp::EnumDescriptor *> found;
    const gp::FileDescriptor *file = proto::DesignProblem::descriptor()->file();
    for (int i = 0; i < file->message_type_count(); ++i)
        collect_enums(*file->message_type(i), field, found);
    return found.size() == 1 ? found[0] : nullptr;
}

} // namespace envdesign::spec
