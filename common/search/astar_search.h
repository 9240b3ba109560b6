#pragma once
// Optimal A* search with reopening over a GroundTask, step by step.
//
// Plans minimise the primary cost; among plans of minimum primary cost, the secondary cost
// (lexicographic costs; the heuristic estimates the primary cost only, so h = (h, 0) stays
// admissible). The open list orders by (f = g + h, secondary g, h) ascending, FIFO among
// equal keys, which is Fast Downward's astar tie-breaking [sum(g, h), h] when secondary
// costs are all 0. Where every operator's secondary cost equals its primary cost, each plan's
// two costs are equal and the secondary is not searched: the order is (f, h). States are
// evaluated when first generated, by a heuristic or by estimates that know the edge that
// reached them (state_estimates.h: LM-cut inherited from the parent); dead ends
// (h = DEAD_END) are pruned, and closed states are reopened when reached more cheaply
// (LM-cut is admissible but not consistent; the reopened state keeps its estimate). A state
// counts as expanded when it is taken from the open list and not already closed, the goal
// state included (as in FD, whose counts we match).
//
// Example:
//   auto h = heuristics::make_heuristic(heuristics::HeuristicKind::LMCUT, task);
//   AStarSearch search(task, *h, {.time_limit_s = 10});
//   SearchStatus status;
//   while ((status = search.step()) == SearchStatus::IN_PROGRESS) {
//       if (cancelled) break;   // callers may stop between steps
//   }
//   SearchResult result = search.result();

#include "ground/ground_task.h"
#include "heuristics/heuristic.h"
#include "search/open_list.h"
#include "search/per_state_information.h"
#include "search/state_estimates.h"
#include "search/state_registry.h"
#include "search/successor_generator.h"

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace envdesign::search {

enum class SearchStatus { IN_PROGRESS, SOLVED, FAILED, LIMIT };

struct SearchLimits {
    double time_limit_s = 0; // wall clock from construction; <= 0: none
    // Bytes of search data this search owns (state registry, per-state data, open list),
    // not the process size; 0: none. Time is checked before every step (a clock read costs
    // tens of nanoseconds, an expansion with LM-cut microseconds to milliseconds), memory
    // every MEMORY_CHECK_INTERVAL steps.
    std::size_t memory_limit_bytes = 0;
    // Set by another thread to stop the search as at a limit (a service shutting down);
    // null: none. Checked before every step, like the time. Outlives the search.
    const std::atomic<bool> *stop = nullptr;
};

struct SearchStatistics {
    long long expanded = 0;
    // Expansions before the first state of the final f layer was expanded (FD's "expanded
    // until last jump"): the part of the effort that tie-breaking cannot change.
    long long expanded_until_last_jump = 0;
    long long generated = 0; // successors produced, duplicates included
    long long evaluated = 0; // heuristic evaluations, the initial state included
    long long reopened = 0;
    long long dead_ends = 0;
    long long registered_states = 0;
    std::size_t bytes_per_state = 0; // packed state size in the registry
    int initial_h = 0;
    // The largest f = g + h expanded (at least the initial h): with an admissible heuristic
    // no plan costs less, so a search a limit stopped still proves this much.
    long long f_bound = 0;
    double search_seconds = 0;
};

struct SearchResult {
    SearchStatus status = SearchStatus::IN_PROGRESS;
    std::vector<ground::OperatorId> plan; // only when SOLVED
    long long cost = 0;                   // primary cost of the plan
    long long secondary_cost = 0;
    SearchStatistics stats;
};

class AStarSearch {
public:
    static constexpr int MEMORY_CHECK_INTERVAL = 64;

    // Keeps references to `task` and `heuristic` (`estimates`), which must outlive the search.
    AStarSearch(const ground::GroundTask &task, heuristics::Heuristic &heuristic,
                SearchLimits limits = {});
    AStarSearch(const ground::GroundTask &task, StateEstimates &estimates,
                SearchLimits limits = {});

    // Expands one state (the first call evaluates the initial state, then expands it).
    // Once the result is not IN_PROGRESS, further calls return it unchanged.
    SearchStatus step();
    // The result so far (plan and cost once SOLVED).
    SearchResult result() const;

    // Bytes of the search data counted by the memory limit.
    std::size_t memory_bytes() const;

private:
    AStarSearch(const ground::GroundTask &task, std::unique_ptr<StateEstimates> own,
                SearchLimits limits);

    enum class NodeStatus : std::uint8_t { NEW, OPEN, CLOSED, DEAD_END };
    // 16 bytes per state; the status and the secondary g live in their own arrays so that
    // tasks without secondary costs do not pay for them.
    struct Node {
        int g = 0;
        int h = 0;
        StateID parent = NO_STATE;
        ground::OperatorId op = -1;
    };

    SearchStatus initialize();
    SearchStatus finish(SearchStatus status);
    bool limit_reached() const;
    bool is_goal(const UnpackedState &state) const;
    void expand(StateID id);
    void generate(StateID parent, ground::OperatorId op);
    void open(StateID id, const Node &node, long long secondary_g);
    long long secondary_g(StateID id) const { return use_secondary_ ? secondary_g_.get(id) : 0; }
    void extract_plan(StateID goal);

    const ground::GroundTask &task_;
    std::unique_ptr<StateEstimates> own_estimates_; // of a plain heuristic
    StateEstimates &estimates_;
    SearchLimits limits_;
    std::chrono::steady_clock::time_point start_;
    bool secondary_is_primary_ = false; // every operator's two costs are equal
    bool use_secondary_ = false;
    bool initialized_ = false;
    StateRegistry registry_;
    SuccessorGenerator successors_;
    PerStateInformation<Node> nodes_;
    PerStateInformation<NodeStatus> statuses_{NodeStatus::NEW};
    PerStateInformation<long long> secondary_g_;
    std::unique_ptr<OpenList> open_list_;
    UnpackedState current_;   // the state being expanded
    UnpackedState successor_; // scratch for evaluating a new successor
    std::vector<ground::OperatorId> applicable_;
    SearchResult result_;
    int last_jump_f_ = -1;
};

// Runs A* with a fresh heuristic of `kind` to the end. `inherit_cuts`: LM-cut's estimates
// inherited from the parent (inherited_lmcut.h) where `kind` is LMCUT: cheaper per state,
// as admissible, but not LM-cut's values, so the search and its plan may differ.
SearchResult astar(const ground::GroundTask &task, heuristics::HeuristicKind kind,
                   const SearchLimits &limits = {}, bool inherit_cuts = false);

} // namespace envdesign::search
