#include "search/open_list.h"

#include <algorithm>
#include <tuple>

namespace envdesign::search {

OpenList::~OpenList() = default;

void BucketOpenList::push(StateID id, const OpenKey &key) {
    if (key.f >= static_cast<int>(by_f_.size()))
        by_f_.resize(key.f + 1);
    FBucket &bucket = by_f_[key.f];
    if (key.h >= static_cast<int>(bucket.by_h.size()))
        bucket.by_h.resize(key.h + 1);
    bucket.by_h[key.h].items.push_back(id);
    if (bucket.size++ == 0 || key.h < bucket.min_h)
        bucket.min_h = key.h;
    // An inconsistent heuristic (LM-cut) can give a successor a smaller f than its parent.
    if (size_++ == 0 || key.f < min_f_)
        min_f_ = key.f;
}

StateID BucketOpenList::pop() {
    while (by_f_[min_f_].size == 0)
        ++min_f_;
    FBucket &bucket = by_f_[min_f_];
    while (bucket.by_h[bucket.min_h].head == bucket.by_h[bucket.min_h].items.size())
        ++bucket.min_h;
    Fifo &fifo = bucket.by_h[bucket.min_h];
    StateID id = fifo.items[fifo.head++];
    if (fifo.head == fifo.items.size()) {
        // Drained: reuse the capacity instead of letting the consumed prefix grow.
        fifo.items.clear();
        fifo.head = 0;
    }
    --bucket.size;
    --size_;
    return id;
}

std::size_t BucketOpenList::memory_bytes() const {
    std::size_t bytes = by_f_.capacity() * sizeof(FBucket);
    for (const FBucket &bucket : by_f_) {
        bytes += bucket.by_h.capacity() * sizeof(Fifo);
        for (const Fifo &fifo : bucket.by_h)
            bytes += fifo.items.capacity() * sizeof(StateID);
    }
    return bytes;
}

bool HeapOpenList::Later::operator()(const Entry &a, const Entry &b) const {
    return std::tie(a.key.f, a.key.secondary_g, a.key.h, a.order) >
           std::tie(b.key.f, b.key.secondary_g, b.key.h, b.order);
}

void HeapOpenList::push(StateID id, const OpenKey &key) {
    heap_.push_back({key, next_order_++, id});
    std::push_heap(heap_.begin(), heap_.end(), Later());
}

StateID HeapOpenList::pop() {
    std::pop_heap(heap_.begin(), heap_.end(), Later());
    StateID id = heap_.back().id;
    heap_.pop_back();
    return id;
}

std::unique_ptr<OpenList> make_open_list(bool use_secondary, int max_operator_cost) {
    // Dense buckets index by f and h; with huge operator costs they would be mostly empty.
    constexpr int MAX_BUCKETED_OPERATOR_COST = 100;
    if (!use_secondary && max_operator_cost <= MAX_BUCKETED_OPERATOR_COST)
        return std::make_unique<BucketOpenList>();
    return std::make_unique<HeapOpenList>();
}

} // namespace envdesign::search
