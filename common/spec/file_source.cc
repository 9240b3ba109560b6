#include "spec/file_source.h"

#include "pddl/input_file.h"

#include <filesystem>

namespace envdesign::spec {

namespace fs = std::filesystem;

FileSource::~FileSource() = default;

std::string path_beside(const std::string &spec_path, const std::string &path) {
    fs::path p(path);
    return (p.is_absolute() ? p : fs::path(spec_path).parent_path() / p).string();
}

SourceFile DiskFiles::read(const std::string &path, const std::string &field) const {
    std::string full = path_beside(spec_path_, path);
    std::string where = "cannot open '" + path + "' (" + field + ", looked for " + full + ")";
    std::error_code error;
    if (!fs::is_regular_file(full, error))
        throw MissingFile(where);
    try {
        return {full, pddl::read_input_file(full)};
    } catch (const pddl::ParseError &e) { // vanished, unreadable or too large
        throw MissingFile(where + ": " + e.message());
    }
}

MessageFiles::MessageFiles(const envdesign::spec_t &spec) : spec_name_(spec.name) {
    for (const auto &file : spec.files)
        files_.emplace(file.path, &file.content); // a repeated path: the first counts
}

SourceFile MessageFiles::read(const std::string &path, const std::string &field) const {
    auto it = files_.find(path);
    if (it == files_.end())
        throw MissingFile("the request does not carry '" + path + "' (" + field + ")");
    return {path_beside(spec_name_, path), *it->second};
}

} // namespace envdesign::spec
