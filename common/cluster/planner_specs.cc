#include "cluster/planner_specs.h"

#include "bus/codec.h"
#include "cluster/spec_loader.h"
#include "envdesign/spec_t.hpp"
#include "pddl/parse_error.h"

namespace envdesign::cluster {

PlannerSpecs::Added PlannerSpecs::add_chunk(const envdesign::spec_chunk_t &chunk,
                                            std::string &why) {
    if (auto problem = chunk_problem(chunk)) {
        why = *problem;
        return Added::BAD;
    }
    std::lock_guard lock(mutex_);
    Entry &entry = specs_[chunk.spec_hash];
    entry.used = std::chrono::steady_clock::now();
    if (!entry.bytes.empty())
        return Added::KNOWN;
    if (!entry.assembling)
        entry.assembling.emplace(chunk);
    if (!entry.assembling->add(chunk)) {
        why = "the chunk's sizes differ from earlier chunks of the spec";
        return Added::BAD;
    }
    if (!entry.assembling->complete())
        return Added::INCOMPLETE;
    std::string bytes = entry.assembling->bytes();
    entry.assembling.reset();
    if (content_hash(bytes) != chunk.spec_hash) {
        why = "the assembled spec does not match its hash " + chunk.spec_hash.substr(0, 12);
        specs_.erase(chunk.spec_hash);
        return Added::BAD;
    }
    entry.bytes = std::move(bytes);
    evict(chunk.spec_hash);
    return Added::COMPLETED;
}

bool PlannerSpecs::complete(const std::string &hash) const {
    std::lock_guard lock(mutex_);
    auto it = specs_.find(hash);
    return it != specs_.end() && !it->second.bytes.empty();
}

std::vector<int> PlannerSpecs::missing(const std::string &hash) const {
    std::lock_guard lock(mutex_);
    auto it = specs_.find(hash);
    if (it == specs_.end() || !it->second.assembling)
        return {};
    return it->second.assembling->missing();
}

std::shared_ptr<const LoadedSpec> PlannerSpecs::load(const std::string &hash) {
    std::promise<std::shared_ptr<const LoadedSpec>> promise;
    std::shared_future<std::shared_ptr<const LoadedSpec>> loaded;
    std::string bytes; // set when this call is the one to load
    {
        std::lock_guard lock(mutex_);
        auto it = specs_.find(hash);
        if (it == specs_.end() || it->second.bytes.empty())
            return nullptr;
        Entry &entry = it->second;
        entry.used = std::chrono::steady_clock::now();
        if (!entry.loaded.valid()) {
            entry.loaded = promise.get_future().share();
            bytes = entry.bytes;
        }
        loaded = entry.loaded;
    }
    if (!bytes.empty()) // loading takes a while: not under the lock
        promise.set_value(load_now(hash, bytes));
    return loaded.get();
}

int PlannerSpecs::size() const {
    std::lock_guard lock(mutex_);
    return static_cast<int>(specs_.size());
}

std::shared_ptr<const LoadedSpec> PlannerSpecs::load_now(const std::string &hash,
                                                         const std::string &bytes) {
    auto spec = std::make_shared<LoadedSpec>();
    spec->hash = hash;
    envdesign::spec_t message;
    try {
        if (!bus::decode_message(bytes, message))
            spec->error = "the spec does not decode as spec_t";
        else
            spec->problem = load_spec(message, work_dir_);
    } catch (const pddl::ParseError &e) {
        spec->error = e.what();
    } catch (const std::exception &e) {
        spec->error = std::string("cannot load the spec: ") + e.what();
    }
    return spec;
}

// Drops the least recently used specs beyond max_specs (never `keep`). Workers that hold
// a loaded spec keep it alive through their shared_ptr.
void PlannerSpecs::evict(const std::string &keep) {
    while (static_cast<int>(specs_.size()) > max_specs_) {
        auto oldest = specs_.end();
        for (auto it = specs_.begin(); it != specs_.end(); ++it)
            if (it->first != keep &&
                (oldest == specs_.end() || it->second.used < oldest->second.used))
                oldest = it;
        if (oldest == specs_.end())
            return;
        specs_.erase(oldest);
    }
}

} // namespace envdesign::cluster
