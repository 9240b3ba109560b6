#include "heuristics/adaptive_queue.h"

#include <algorithm>

namespace envdesign::heuristics {
namespace {

// Orders by key only, so that ties resolve exactly as in a std::priority_queue (FD's heap).
struct KeyGreater {
    bool operator()(const std::pair<int, int> &a, const std::pair<int, int> &b) const {
        return a.first > b.first;
    }
};

} // namespace

void AdaptiveQueue::clear() {
    if (heap_mode_) {
        heap_.clear();
    } else {
        for (int key = current_bucket_; num_entries_ > 0; ++key) {
            num_entries_ -= static_cast<int>(buckets_[key].size());
            buckets_[key].clear();
        }
        current_bucket_ = 0;
        num_pushes_ = 0;
    }
    num_entries_ = 0;
}

void AdaptiveQueue::heap_push(int key, int value) {
    ++num_entries_;
    heap_.emplace_back(key, value);
    std::push_heap(heap_.begin(), heap_.end(), KeyGreater());
}

AdaptiveQueue::Entry AdaptiveQueue::heap_pop() {
    --num_entries_;
    std::pop_heap(heap_.begin(), heap_.end(), KeyGreater());
    Entry top = heap_.back();
    heap_.pop_back();
    return top;
}

// Entries move in ascending key order (insertion order within a key); a sorted array is
// already a valid min-heap, so no heapify is needed.
void AdaptiveQueue::switch_to_heap() {
    heap_.clear();
    heap_.reserve(num_entries_);
    for (int key = current_bucket_; static_cast<int>(heap_.size()) < num_entries_; ++key) {
        for (int value : buckets_[key])
            heap_.emplace_back(key, value);
    }
    buckets_.clear();
    buckets_.shrink_to_fit();
    current_bucket_ = 0;
    heap_mode_ = true;
}

} // namespace envdesign::heuristics
