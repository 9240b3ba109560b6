#pragma once
// The coordinator's specs by content hash, for planners that ask (spec_need_t). A spec stays
// while a request uses it. Several planners that join at once ask for the same spec
// together; a chunk sent less than `min_interval_s` ago is not sent again.
// Thread-safe.

#include "envdesign/spec_chunk_t.hpp"

#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace envdesign::cluster {

class SpecLibrary {
public:
    using Clock = std::chrono::steady_clock;

    SpecLibrary(std::string sender, double min_interval_s = 0.05)
        : sender_(std::move(sender)), min_interval_s_(min_interval_s) {}

    // Adds a user of the spec `bytes` (hash `hash`); returns every chunk, to publish now.
    std::vector<envdesign::spec_chunk_t> add(const std::string &hash, const std::string &bytes,
                                             std::int64_t request_id);
    void release(const std::string &hash);
    bool has(const std::string &hash) const;

    // The chunks `missing` (empty: all) of `hash` not sent within min_interval_s; nothing if
    // the spec is unknown.
    std::vector<envdesign::spec_chunk_t> need(const std::string &hash,
                                              const std::vector<int> &missing,
                                              std::int64_t request_id, Clock::time_point now);

private:
    struct Entry {
        std::string bytes;
        int users = 0;
        std::vector<Clock::time_point> sent; // per chunk
    };

    std::string sender_;
    double min_interval_s_;
    mutable std::mutex mutex_;
    std::map<std::string, Entry> specs_;
};

} // namespace envdesign::cluster
