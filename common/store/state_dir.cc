#include "store/state_dir.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace envdesign::store {

std::shared_ptr<RecordDb> open_state_file(const std::string &dir, const RecordDbOptions &options,
                                          spdlog::logger &log) {
    if (dir.empty())
        return nullptr;
    auto db = std::make_shared<RecordDb>((std::filesystem::path(dir) / "evaluations.db").string(),
                                         options);
    const OpenReport &report = db->report();
    if (!report.set_aside.empty())
        log.error("request - | {} could not be trusted ({}): set aside as {}; starting empty",
                  db->path(), report.reason, report.set_aside);
    log.info("request - | stored evaluations in {}: {} record(s){} (checked in {:.3f} s)",
             db->path(), report.records, report.created ? ", a new file" : "",
             report.check_seconds);
    return db;
}

std::optional<std::string> state_dir_problem(const std::string &dir) {
    namespace fs = std::filesystem;
    if (dir.empty())
        return std::nullopt;
    std::error_code error;
    if (!fs::is_directory(dir, error))
        return dir + " is not a directory";
    if (access(dir.c_str(), W_OK | X_OK) != 0)
        return "cannot write in " + dir + ": " + std::strerror(errno);
    fs::path file = fs::path(dir) / "evaluations.db";
    fs::file_status status = fs::status(file, error);
    if (!fs::exists(status))
        return std::nullopt; // created at start
    if (!fs::is_regular_file(status))
        return file.string() + " is not a regular file";
    if (access(file.c_str(), R_OK | W_OK) != 0)
        return "cannot read and write " + file.string() + ": " + std::strerror(errno);
    return std::nullopt;
}

} // namespace envdesign::store
