#include "cluster/planner_specs.h"

#include "bus/codec.h"
#include "envdesign/spec_t.hpp"
#include "pddl/parse_error.h"
#include "spec/spec_message.h"

#include <algorithm>

namespace envdesign::cluster {

PlannerSpecs::Added PlannerSpecs::add_chunk(const envdesign::spec_chunk_t &chunk,
                                            std::string &why) {
    if (auto problem = chunk_problem(chunk, limits_.max_spec_bytes)) {
        why = *problem;
        return Added::BAD;
    }
    std::lock_guard lock(mutex_);
    auto now = Clock::now();
    expire_locked(now);
    auto it = specs_.find(chunk.spec_hash);
    if (it != specs_.end() && !it->second.bytes.empty()) {
        it->second.used = now;
        return Added::KNOWN;
    }
    bool is_new = it == specs_.end() || !it->second.assembling;
    if (!make_room(chunk.spec_hash, static_cast<std::size_t>(chunk.num_bytes), is_new ? 1 : 0)) {
        why = "specs being assembled would hold more than " +
              std::to_string(limits_.max_incomplete_bytes) + " bytes";
        return Added::BAD;
    }
    Entry &entry = specs_[chunk.spec_hash];
    entry.used = now;
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

int PlannerSpecs::incomplete() const {
    std::lock_guard lock(mutex_);
    return static_cast<int>(std::count_if(specs_.begin(), specs_.end(), [](const auto &e) {
        return e.second.assembling.has_value();
    }));
}

std::size_t PlannerSpecs::incomplete_bytes() const {
    std::lock_guard lock(mutex_);
    return incomplete_bytes_locked();
}

void PlannerSpecs::expire() {
    std::lock_guard lock(mutex_);
    expire_locked(Clock::now());
}

void PlannerSpecs::expire_locked(Clock::time_point now) {
    auto limit = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(limits_.expire_s));
    std::erase_if(
        specs_, [&](const auto &e) { return e.second.assembling && now - e.second.used > limit; });
}

std::size_t PlannerSpecs::incomplete_bytes_locked() const {
    std::size_t total = 0;
    for (const auto &[hash, entry] : specs_)
        if (entry.assembling)
            total += entry.assembling->received_bytes();
    return total;
}

std::map<std::string, PlannerSpecs::Entry>::iterator
PlannerSpecs::oldest_incomplete(const std::string &keep) {
    auto oldest = specs_.end();
    for (auto it = specs_.begin(); it != specs_.end(); ++it)
        if (it->second.assembling && it->first != keep &&
            (oldest == specs_.end() || it->second.used < oldest->second.used))
            oldest = it;
    return oldest;
}

// Drops the oldest specs being assembled (never `keep`) until `entries` more of them and
// `bytes` more bytes fit the limits; false if they cannot.
bool PlannerSpecs::make_room(const std::string &keep, std::size_t bytes, int entries) {
    auto fits = [&] {
        int count = 0;
        for (const auto &[hash, entry] : specs_)
            count += entry.assembling ? 1 : 0;
        return count + entries <= std::max(1, limits_.max_incomplete) &&
               incomplete_bytes_locked() + bytes <= limits_.max_incomplete_bytes;
    };
    while (!fits()) {
        auto oldest = oldest_incomplete(keep);
        if (oldest == specs_.end())
            return false;
        specs_.erase(oldest);
    }
    return true;
}

std::shared_ptr<const LoadedSpec> PlannerSpecs::load_now(const std::string &hash,
                                                         const std::string &bytes) {
    auto spec = std::make_shared<LoadedSpec>();
    spec->hash = hash;
    envdesign::spec_t message;
    try {
        if (!bus::decode_message(bytes, message))
            spec->error = "the spec does not decode as spec_t";
        else // the hash matched: the coordinator checked these bytes in full
            spec->problem =
                envdesign::spec::load_spec(message, envdesign::spec::Checks::TRUSTED_BY_HASH);
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
