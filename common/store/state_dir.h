#pragma once
// The durable evaluation file of a service's state directory (--state-dir): opened, checked
// (record_db.h), and what the check found logged, one line each. The coordinator and the
// bridge open theirs with this.

#include "store/record_db.h"

#include <spdlog/logger.h>

#include <memory>
#include <string>

namespace envdesign::store {

// DIR/evaluations.db; null when `dir` is empty. A file that could not be trusted is logged
// as an error (it was set aside). Throws StoreError (e.g. DIR does not exist).
std::shared_ptr<RecordDb> open_state_file(const std::string &dir, const RecordDbOptions &options,
                                          spdlog::logger &log);

} // namespace envdesign::store
