#pragma once
// The witness search's queue of configurations to evaluate (witness_search.h), least bound
// first.

#include "design/search/witness_bound.h"

#include <algorithm>
#include <vector>

namespace envdesign::design::witness {

// Least bound first; then the order in which SPEC.md breaks ties.
struct LaterInQueue {
    bool operator()(const Node &a, const Node &b) const {
        if (a.bound != b.bound)
            return a.bound > b.bound;
        if (a.configuration.size() != b.configuration.size())
            return a.configuration.size() > b.configuration.size();
        if (a.cost != b.cost)
            return a.cost > b.cost;
        return a.configuration > b.configuration;
    }
};

// The queue of configurations to evaluate, least bound first; pop() moves the node out.
class OpenList {
public:
    bool empty() const { return heap_.empty(); }
    std::size_t size() const { return heap_.size(); }
    const Node &top() const { return heap_.front(); }
    void push(Node node) {
        heap_.push_back(std::move(node));
        std::push_heap(heap_.begin(), heap_.end(), LaterInQueue{});
    }
    Node pop() {
        std::pop_heap(heap_.begin(), heap_.end(), LaterInQueue{});
        Node node = std::move(heap_.back());
        heap_.pop_back();
        return node;
    }
    void clear() { heap_.clear(); }

private:
    std::vector<Node> heap_;
};

} // namespace envdesign::design::witness
