#include "search/astar_search.h"
#include "heuristics/make_heuristic.h"
#include "search/inherited_lmcut.h"

#include <algorithm>
#include <utility>

namespace envdesign::search {
namespace {

// Whether every operator's secondary cost equals its primary cost. Then every plan's two
// costs are equal, the plans of least primary cost are those of least secondary cost, and
// the search orders by (f, h) alone: within the last f layer it goes deep instead of
// expanding the layer by secondary g first.
bool secondary_is_primary(const ground::GroundTask &task) {
    return std::all_of(
        task.operators.begin(), task.operators.end(),
        [](const ground::GroundOperator &op) { return op.secondary_cost == op.cost; });
}

bool has_secondary_costs(const ground::GroundTask &task) {
    return std::any_of(task.operators.begin(), task.operators.end(),
                       [](const ground::GroundOperator &op) { return op.secondary_cost != 0; });
}

int max_operator_cost(const ground::GroundTask &task) {
    int result = 0;
    for (const ground::GroundOperator &op : task.operators)
        result = std::max(result, static_cast<int>(op.cost));
    return result;
}

} // namespace

AStarSearch::AStarSearch(const ground::GroundTask &task, heuristics::Heuristic &heuristic,
                         SearchLimits limits)
    : AStarSearch(task, std::make_unique<HeuristicEstimates>(heuristic), limits) {}

AStarSearch::AStarSearch(const ground::GroundTask &task, std::unique_ptr<StateEstimates> own,
                         SearchLimits limits)
    : AStarSearch(task, *own, limits) {
    own_estimates_ = std::move(own);
}

AStarSearch::AStarSearch(const ground::GroundTask &task, StateEstimates &estimates,
                         SearchLimits limits)
    : task_(task), estimates_(estimates), limits_(limits), start_(std::chrono::steady_clock::now()),
      secondary_is_primary_(secondary_is_primary(task)),
      use_secondary_(!secondary_is_primary_ && has_secondary_costs(task)), registry_(task),
      successors_(task), open_list_(make_open_list(use_secondary_, max_operator_cost(task))),
      current_(registry_.codec()), successor_(registry_.codec()) {
    result_.stats.bytes_per_state = registry_.bytes_per_state();
}

SearchStatus AStarSearch::step() {
    if (result_.status != SearchStatus::IN_PROGRESS)
        return result_.status;
    if (!initialized_)
        return initialize();
    if (limit_reached())
        return finish(SearchStatus::LIMIT);
    while (!open_list_->empty()) {
        StateID id = open_list_->pop();
        // Entries of states closed since they were pushed are stale: FD skips them too.
        if (statuses_[id] == NodeStatus::CLOSED)
            continue;
        statuses_[id] = NodeStatus::CLOSED;
        const Node &node = nodes_[id];
        if (node.g + node.h > last_jump_f_) {
            last_jump_f_ = node.g + node.h;
            result_.stats.expanded_until_last_jump = result_.stats.expanded;
            result_.stats.f_bound = std::max<long long>(result_.stats.f_bound, last_jump_f_);
        }
        ++result_.stats.expanded;
        registry_.unpack(id, current_);
        if (is_goal(current_)) {
            extract_plan(id);
            return finish(SearchStatus::SOLVED);
        }
        expand(id);
        return SearchStatus::IN_PROGRESS;
    }
    return finish(SearchStatus::FAILED);
}

SearchStatus AStarSearch::initialize() {
    initialized_ = true;
    StateID id = registry_.insert_facts(task_.initial_state).id;
    registry_.unpack(id, current_);
    int h = estimates_.initial(id, current_);
    ++result_.stats.evaluated;
    result_.stats.initial_h = h;
    if (h != heuristics::DEAD_END)
        result_.stats.f_bound = h;
    if (h == heuristics::DEAD_END) {
        ++result_.stats.dead_ends;
        statuses_[id] = NodeStatus::DEAD_END;
        return finish(SearchStatus::FAILED);
    }
    Node node;
    node.h = h;
    open(id, node, 0);
    return SearchStatus::IN_PROGRESS;
}

SearchStatus AStarSearch::finish(SearchStatus status) {
    result_.status = status;
    result_.stats.registered_states = static_cast<long long>(registry_.size());
    result_.stats.search_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    return status;
}

bool AStarSearch::limit_reached() const {
    if (limits_.stop && limits_.stop->load(std::memory_order_relaxed))
        return true;
    if (limits_.time_limit_s > 0) {
        double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        if (elapsed >= limits_.time_limit_s)
            return true;
    }
    return limits_.memory_limit_bytes > 0 && result_.stats.expanded % MEMORY_CHECK_INTERVAL == 0 &&
           memory_bytes() >= limits_.memory_limit_bytes;
}

bool AStarSearch::is_goal(const UnpackedState &state) const {
    return std::all_of(task_.goal.begin(), task_.goal.end(),
                       [&](ground::FactId fact) { return state.holds(fact); });
}

void AStarSearch::expand(StateID id) {
    successors_.applicable_operators(current_, applicable_);
    for (ground::OperatorId op : applicable_)
        generate(id, op);
    estimates_.expanded(id);
}

void AStarSearch::generate(StateID parent_id, ground::OperatorId op) {
    InsertResult succ = registry_.insert_successor(parent_id, op);
    ++result_.stats.generated;
    NodeStatus &status = statuses_[succ.id];
    if (status == NodeStatus::DEAD_END)
        return;
    const ground::GroundOperator &o = task_.operators[op];
    // Copy the parent: nodes_[succ.id] may grow the storage and move it.
    const Node parent = nodes_[parent_id];
    Node candidate{parent.g + o.cost, 0, parent_id, op};
    // 0 where the secondary is not searched (costs equal to the primary's are not keys).
    long long candidate_secondary = use_secondary_ ? secondary_g(parent_id) + o.secondary_cost : 0;
    if (status == NodeStatus::NEW) {
        registry_.unpack(succ.id, successor_);
        int h = estimates_.successor(succ.id, successor_, parent_id, op);
        ++result_.stats.evaluated;
        if (h == heuristics::DEAD_END) {
            status = NodeStatus::DEAD_END;
            ++result_.stats.dead_ends;
            return;
        }
        candidate.h = h;
        open(succ.id, candidate, candidate_secondary);
        return;
    }
    const Node &node = nodes_[succ.id];
    if (std::pair(candidate.g, candidate_secondary) < std::pair(node.g, secondary_g(succ.id))) {
        if (status == NodeStatus::CLOSED)
            ++result_.stats.reopened;
        candidate.h = node.h; // a state's estimate is computed once, whatever the path
        open(succ.id, candidate, candidate_secondary);
    }
}

void AStarSearch::open(StateID id, const Node &node, long long secondary_g) {
    nodes_[id] = node;
    statuses_[id] = NodeStatus::OPEN;
    if (use_secondary_)
        secondary_g_[id] = secondary_g;
    open_list_->push(id, {node.g + node.h, secondary_g, node.h});
}

void AStarSearch::extract_plan(StateID goal) {
    const Node &goal_node = nodes_[goal];
    result_.cost = goal_node.g;
    result_.secondary_cost = secondary_is_primary_ ? goal_node.g : secondary_g(goal);
    result_.plan.clear();
    for (StateID id = goal; nodes_[id].parent != NO_STATE; id = nodes_[id].parent)
        result_.plan.push_back(nodes_[id].op);
    std::reverse(result_.plan.begin(), result_.plan.end());
}

std::size_t AStarSearch::memory_bytes() const {
    return registry_.memory_bytes() + nodes_.memory_bytes() + statuses_.memory_bytes() +
           secondary_g_.memory_bytes() + open_list_->memory_bytes() + estimates_.memory_bytes();
}

SearchResult AStarSearch::result() const {
    SearchResult copy = result_;
    copy.stats.registered_states = static_cast<long long>(registry_.size());
    if (copy.status == SearchStatus::IN_PROGRESS)
        copy.stats.search_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    return copy;
}

SearchResult astar(const ground::GroundTask &task, heuristics::HeuristicKind kind,
                   const SearchLimits &limits, bool inherit_cuts) {
    std::unique_ptr<heuristics::Heuristic> heuristic;
    std::unique_ptr<StateEstimates> estimates;
    if (inherit_cuts && kind == heuristics::HeuristicKind::LMCUT &&
        !heuristics::lmcut_is_hmax(task)) {
        estimates = std::make_unique<InheritedLmCut>(task);
    } else {
        heuristic = heuristics::make_heuristic(kind, task);
        estimates = std::make_unique<HeuristicEstimates>(*heuristic);
    }
    AStarSearch search(task, *estimates, limits);
    while (search.step() == SearchStatus::IN_PROGRESS) {
    }
    return search.result();
}

} // namespace envdesign::search
