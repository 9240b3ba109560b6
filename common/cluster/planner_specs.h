#pragma once
// The specs a planner knows, by content hash: chunks heard on ENVDESIGN_SPEC are assembled
// (every planner keeps every spec it hears, so one that joins later rarely has to ask), the
// assembled encoding is checked against its hash, and a spec is loaded
// (spec/spec_message.h, Checks::TRUSTED_BY_HASH: parsed, not re-checked) the first time a
// job needs it. At most `max_specs` specs are kept, the least recently used
// going first. Specs being assembled are bounded too (SpecLimits): anyone on the bus can send
// chunks. Thread-safe: chunks come from the bus thread, loads from worker threads.

#include "cluster/spec_chunks.h"
#include "design/design_problem.h"

#include <chrono>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

namespace envdesign::cluster {

struct LoadedSpec {
    std::string hash;
    std::optional<design::DesignProblem> problem; // unset: it did not load
    std::string error;                            // why not
};

struct SpecLimits {
    std::size_t max_spec_bytes = DEFAULT_MAX_SPEC_BYTES; // one spec's encoding
    // Specs being assembled: at most this many (a new one pushes out the oldest) holding at
    // most this many bytes together, each dropped when no chunk came for expire_s.
    int max_incomplete = 8;
    std::size_t max_incomplete_bytes = 4 * DEFAULT_MAX_SPEC_BYTES;
    double expire_s = 60;
};

class PlannerSpecs {
public:
    enum class Added { INCOMPLETE, COMPLETED, KNOWN, BAD };

    explicit PlannerSpecs(int max_specs, SpecLimits limits = {})
        : max_specs_(std::max(1, max_specs)), limits_(limits) {}

    // `why` says what is wrong when BAD.
    Added add_chunk(const envdesign::spec_chunk_t &chunk, std::string &why);
    bool complete(const std::string &hash) const;
    // Chunk indices still missing of a spec being assembled; empty: unknown (ask for all).
    std::vector<int> missing(const std::string &hash) const;
    // The spec `hash` loaded; the first caller loads it, others wait for that. Null if the
    // spec is not complete here.
    std::shared_ptr<const LoadedSpec> load(const std::string &hash);
    int size() const;
    // Specs being assembled, and the bytes they hold.
    int incomplete() const;
    std::size_t incomplete_bytes() const;
    // Drops specs being assembled that heard no chunk for limits.expire_s (also done on every
    // chunk); the bus thread calls it now and then.
    void expire();

private:
    using Clock = std::chrono::steady_clock;
    struct Entry {
        std::optional<SpecAssembler> assembling;
        std::string bytes; // complete and checked
        std::shared_future<std::shared_ptr<const LoadedSpec>> loaded;
        Clock::time_point used;
    };

    std::shared_ptr<const LoadedSpec> load_now(const std::string &hash, const std::string &bytes);
    void evict(const std::string &keep);
    // Under the lock.
    void expire_locked(Clock::time_point now);
    bool make_room(const std::string &keep, std::size_t bytes, int entries);
    std::map<std::string, Entry>::iterator oldest_incomplete(const std::string &keep);
    std::size_t incomplete_bytes_locked() const;

    int max_specs_;
    SpecLimits limits_;
    mutable std::mutex mutex_;
    std::map<std::string, Entry> specs_;
};

} // namespace envdesign::cluster
