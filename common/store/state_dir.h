#pragma once
// The durable evaluation file of a service's state directory (--state-dir): opened, checked
// (record_db.h), and what the check found logged, one line each. The coordinator and the
// bridge open theirs with this.

#include "store/record_db.h"

#include <spdlog/logger.h>

#include <memory>
#include <optional>
#include <string>

namespace envdesign::store {

// DIR/evaluations.db; null when `dir` is empty. A file that could not be trusted is logged
// as an error (it was set aside). Throws StoreError (e.g. DIR does not exist).
std::shared_ptr<RecordDb> open_state_file(const std::string &dir, const RecordDbOptions &options,
                                          spdlog::logger &log);

// Why open_state_file(dir) could not open DIR/evaluations.db (DIR not a directory this
// process may write in, the file not a regular file it may read and write), found without
// opening, creating or setting aside anything (--check-config); nullopt when it could, or
// when `dir` is empty.
std::optional<std::string> state_dir_problem(const std::string &dir);

} // namespace envdesign::store
