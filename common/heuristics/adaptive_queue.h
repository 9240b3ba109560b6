#pragma once
// A min-priority queue of (integer key, int value) pairs for Dijkstra-style explorations.
//
// It starts as a bucket queue (one vector per key, LIFO within a key) and turns into a
// binary heap for good when a key is both >= 100 and larger than the number of pushes so
// far, i.e. when buckets would be sparse. This is the policy of Fast Downward's
// AdaptiveQueue; keeping it keeps LM-cut's supporter tie-breaking, hence expansions, close
// to FD's. Keys must be >= 0. Memory is kept between clear() calls (no per-call allocation
// once warmed up).

#include <utility>
#include <vector>

namespace envdesign::heuristics {

class AdaptiveQueue {
public:
    void push(int key, int value) {
        if (!heap_mode_ && key >= MIN_BUCKETS_BEFORE_SWITCH && key > num_pushes_)
            switch_to_heap();
        if (heap_mode_)
            heap_push(key, value);
        else
            bucket_push(key, value);
    }

    // Removes and returns a (key, value) pair of minimum key. Precondition: !empty().
    std::pair<int, int> pop() { return heap_mode_ ? heap_pop() : bucket_pop(); }

    bool empty() const { return num_entries_ == 0; }
    void clear();

    // Pretends `count` more pushes happened, delaying the switch to the heap (FD does this
    // before LM-cut's incremental explorations).
    void add_virtual_pushes(int count) {
        if (!heap_mode_)
            num_pushes_ += count;
    }

private:
    static constexpr int MIN_BUCKETS_BEFORE_SWITCH = 100;
    using Entry = std::pair<int, int>;

    void bucket_push(int key, int value) {
        ++num_entries_;
        ++num_pushes_;
        if (key >= static_cast<int>(buckets_.size()))
            buckets_.resize(key + 1);
        else if (key < current_bucket_)
            current_bucket_ = key;
        buckets_[key].push_back(value);
    }
    Entry bucket_pop() {
        --num_entries_;
        while (buckets_[current_bucket_].empty())
            ++current_bucket_;
        std::vector<int> &bucket = buckets_[current_bucket_];
        int value = bucket.back();
        bucket.pop_back();
        return {current_bucket_, value};
    }
    void heap_push(int key, int value);
    Entry heap_pop();
    void switch_to_heap();

    bool heap_mode_ = false;
    int num_entries_ = 0;
    int num_pushes_ = 0;
    int current_bucket_ = 0;
    std::vector<std::vector<int>> buckets_;
    std::vector<Entry> heap_; // a binary min-heap on the key only
};

} // namespace envdesign::heuristics
