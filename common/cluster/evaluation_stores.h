#pragma once
// The coordinator's task evaluations, kept across requests (design/evaluation/evaluation_store.h):
// one EvaluationStore per store key, so that a request that differs from an earlier one only
// in its task distribution, its weights or added tasks (what envdesign-bridge sends when the
// distribution drifts) is a re-weighting of what the planners answered before, not a
// re-planning. A long-running coordinator must not grow without bound: past max_records
// evaluations and bounds in all, the stores used least recently are dropped whole, except
// those a running search holds (it would keep filling a store nobody finds again).
// With a RecordDb (store/record_db.h: the coordinator's --state-dir) every store is durable:
// what it keeps is in the file before the search uses it, and a store made after a restart
// finds what the file holds; dropping a store here frees memory only.
// Thread-safe.

#include "design/evaluation/evaluation_store.h"

#include <cstddef>
#include <list>
#include <map>
#include <memory>
#include <mutex>

namespace envdesign::cluster {

class EvaluationStores {
public:
    // `db`: where the stores keep their entries; null: in memory only.
    explicit EvaluationStores(std::size_t max_records,
                              std::shared_ptr<store::RecordDb> db = nullptr)
        : max_records_(max_records), db_(std::move(db)) {}

    // The store of `problem`'s store key searched with `heuristic` (it picks among plans of
    // equal cost, so its plans are its own), made if new; it stays valid for the caller
    // while held even if dropped here.
    std::shared_ptr<design::EvaluationStore> store_for(const design::DesignProblem &problem,
                                                       int heuristic);
    // Drops stores nobody holds (least recently used first) until the rest hold at most
    // max_records.
    void trim();
    std::size_t stores() const;
    // Evaluations and bounds kept: the file's records with a RecordDb, else those in memory.
    std::size_t records() const;
    const std::shared_ptr<store::RecordDb> &db() const { return db_; }

private:
    using Key = design::TaskKey;
    std::size_t max_records_;
    std::shared_ptr<store::RecordDb> db_;
    mutable std::mutex mutex_;
    std::list<Key> recent_; // most recently used first
    std::map<Key, std::pair<std::shared_ptr<design::EvaluationStore>, std::list<Key>::iterator>>
        stores_;
};

} // namespace envdesign::cluster
