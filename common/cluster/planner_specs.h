#pragma once
// The specs a planner knows, by content hash: chunks heard on ENVDESIGN_SPEC are assembled
// (every planner keeps every spec it hears, so one that joins later rarely has to ask), the
// assembled encoding is checked against its hash, and a spec is loaded (spec_loader.h) the
// first time a job needs it. At most `max_specs` specs are kept, the least recently used
// going first. Thread-safe: chunks come from the bus thread, loads from worker threads.

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

class PlannerSpecs {
public:
    enum class Added { INCOMPLETE, COMPLETED, KNOWN, BAD };

    PlannerSpecs(std::string work_dir, int max_specs)
        : work_dir_(std::move(work_dir)), max_specs_(std::max(1, max_specs)) {}

    // `why` says what is wrong when BAD.
    Added add_chunk(const envdesign::spec_chunk_t &chunk, std::string &why);
    bool complete(const std::string &hash) const;
    // Chunk indices still missing of a spec being assembled; empty: unknown (ask for all).
    std::vector<int> missing(const std::string &hash) const;
    // The spec `hash` loaded; the first caller loads it, others wait for that. Null if the
    // spec is not complete here.
    std::shared_ptr<const LoadedSpec> load(const std::string &hash);
    int size() const;

private:
    struct Entry {
        std::optional<SpecAssembler> assembling;
        std::string bytes; // complete and checked
        std::shared_future<std::shared_ptr<const LoadedSpec>> loaded;
        std::chrono::steady_clock::time_point used;
    };

    std::shared_ptr<const LoadedSpec> load_now(const std::string &hash, const std::string &bytes);
    void evict(const std::string &keep);

    std::string work_dir_;
    int max_specs_;
    mutable std::mutex mutex_;
    std::map<std::string, Entry> specs_;
};

} // namespace envdesign::cluster
