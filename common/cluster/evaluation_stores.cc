#include "cluster/evaluation_stores.h"

#include "wire/job_messages.h"

#include <algorithm>

namespace envdesign::cluster {

std::shared_ptr<design::EvaluationStore>
EvaluationStores::store_for(const design::DesignProblem &problem, int heuristic) {
    Key key = design::store_key(problem, wire::heuristic_kind(static_cast<std::int8_t>(heuristic)));
    std::lock_guard lock(mutex_);
    auto it = stores_.find(key);
    if (it != stores_.end()) {
        recent_.splice(recent_.begin(), recent_, it->second.second);
        return it->second.first;
    }
    recent_.push_front(key);
    auto store = db_ ? std::make_shared<design::EvaluationStore>(db_, key)
                     : std::make_shared<design::EvaluationStore>();
    stores_.emplace(key, std::make_pair(store, recent_.begin()));
    return store;
}

void EvaluationStores::trim() {
    std::lock_guard lock(mutex_);
    std::size_t total = 0;
    for (const auto &[key, entry] : stores_)
        total += entry.first->records();
    for (auto key = recent_.end(); total > max_records_ && key != recent_.begin();) {
        --key;
        auto it = stores_.find(*key);
        if (it->second.first.use_count() > 1)
            continue; // a search is filling it
        total -= std::min(total, it->second.first->records());
        stores_.erase(it);
        key = recent_.erase(key);
    }
}

std::size_t EvaluationStores::stores() const {
    std::lock_guard lock(mutex_);
    return stores_.size();
}

std::size_t EvaluationStores::records() const {
    if (db_)
        return db_->records();
    std::lock_guard lock(mutex_);
    std::size_t total = 0;
    for (const auto &[key, entry] : stores_)
        total += entry.first->records();
    return total;
}

} // namespace envdesign::cluster
