#pragma once
// A* open lists: StateIDs ordered by (f, secondary g, h) ascending, first in first out
// among equal keys, as Fast Downward's tie-breaking open list [sum(g, h), h] with the
// secondary cost inserted between (it is 0 in tasks without secondary costs).
//
// BucketOpenList is the fast one for tasks without secondary costs: a FIFO per (f, h),
// found by direct indexing. HeapOpenList handles any key, including secondary costs and
// very large f values, with a binary heap and an insertion counter for FIFO order.
// Entries are never removed early: the search skips entries of already closed states.

#include "search/state_registry.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace envdesign::search {

struct OpenKey {
    int f = 0;
    long long secondary_g = 0;
    int h = 0;
};

class OpenList {
public:
    virtual ~OpenList();
    virtual void push(StateID id, const OpenKey &key) = 0;
    // Removes and returns an entry of minimum key. Precondition: !empty().
    virtual StateID pop() = 0;
    virtual bool empty() const = 0;
    virtual std::size_t memory_bytes() const = 0;
};

class BucketOpenList : public OpenList {
public:
    // Ignores key.secondary_g (callers use it only when every secondary cost is 0).
    void push(StateID id, const OpenKey &key) override;
    StateID pop() override;
    bool empty() const override { return size_ == 0; }
    std::size_t memory_bytes() const override;

private:
    struct Fifo {
        std::vector<StateID> items;
        std::size_t head = 0;
    };
    struct FBucket {
        std::vector<Fifo> by_h;
        std::size_t size = 0;
        int min_h = 0; // no entry has a smaller h (a lower bound, tightened on pop)
    };

    std::vector<FBucket> by_f_;
    std::size_t size_ = 0;
    int min_f_ = 0; // no entry has a smaller f
};

class HeapOpenList : public OpenList {
public:
    void push(StateID id, const OpenKey &key) override;
    StateID pop() override;
    bool empty() const override { return heap_.empty(); }
    std::size_t memory_bytes() const override { return heap_.capacity() * sizeof(Entry); }

private:
    struct Entry {
        OpenKey key;
        std::uint64_t order; // insertion counter: FIFO among equal keys
        StateID id;
    };
    struct Later {
        bool operator()(const Entry &a, const Entry &b) const;
    };

    std::vector<Entry> heap_;
    std::uint64_t next_order_ = 0;
};

// The bucket list when `use_secondary` is false and f stays moderate, else the heap.
std::unique_ptr<OpenList> make_open_list(bool use_secondary, int max_operator_cost);

} // namespace envdesign::search
