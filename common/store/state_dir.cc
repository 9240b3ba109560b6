#include "store/state_dir.h"

#include <filesystem>

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

} // namespace envdesign::store
