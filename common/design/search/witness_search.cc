#include "design/search/witness_search.h"

#include "design/behaviour/behaviour.h"
#include "design/search/rising_bounds.h"
#include "design/search/witness_bound.h"
#include "design/search/witness_learning.h"
#include "design/search/witness_queue.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <unordered_set>

namespace envdesign::design {
namespace {

using witness::contains;
using witness::Node;
using witness::offer_cone_of;
using witness::OpenList;
using witness::PooledPlan;
using witness::raise_floor;
using witness::Record;
using witness::TaskRecord;
using witness::values_only;

// What the search visits: designs grown by their witnesses (the default); for the explaining
// robot, the root, the probes and the hitting-set phase alone, or every design best first.
enum class Visit { WITNESSES, PHASE_ONLY, EVERY_DESIGN };

class WitnessSearch {
public:
    WitnessSearch(const DesignProblem &problem, Evaluator &evaluator,
                  const DesignSearchOptions &options,
                  const std::function<void(const SearchProgress &)> &progress, Visit visit)
        : problem_(problem), evaluator_(evaluator), options_(options), progress_(progress),
          index_(problem), bound_(problem, index_, visit == Visit::EVERY_DESIGN),
          robot_bound_memory_(index_.robot_restricting()),
          ranking_(options.ranking, options.ranking_all ? Padding::LISTED : Padding::LEFT_OUT),
          learner_(problem, evaluator, options, index_, bound_, result_, ranking_,
                   [this] { report(); }),
          tasks_(static_cast<int>(problem.tasks.size())), phase_only_(visit == Visit::PHASE_ONLY),
          every_design_(visit == Visit::EVERY_DESIGN) {
        if (!every_design_)
            for (std::string &note : bound_.weighed_everywhere_notes())
                result_.notes.push_back(std::move(note));
        if (behaviour_of(problem.weights.behaviour).runs_an_optimal_plan)
            result_.notes.push_back(
                "robot_behaviour " + std::string(behaviour_of(problem.weights.behaviour).name) +
                ": the witnesses are the worst (best) optimal plan and, for a finite worst case, "
                "every action of every optimal plan; the queue bounds the IE term by its least "
                "value, and the hitting-set phase, where every modification restricts or is a "
                "lane for the robot alone, by the "
                "empty design's worst (best) optimal plan while it stays a robot plan "
                "(docs/design-search.md)");
        max_size_ = options.max_design_size > 0 ? options.max_design_size : index_.size();
    }

    DesignResult run() {
        auto start = std::chrono::steady_clock::now();
        Node root{{},
                  std::vector<Record>(tasks_),
                  std::vector<std::optional<double>>(tasks_),
                  std::vector<double>(tasks_, 0.0),
                  0,
                  0,
                  {},
                  {}};
        root.bound = bound_(root);
        visited_.insert(root.configuration);
        ++generated_;
        open_.push(std::move(root));
        bool interrupted = false;
        bool probed = false;
        while (!open_.empty()) {
            if (options_.deadline.expired()) {
                interrupted = true;
                break;
            }
            evaluate(next_batch());
            if (!probed && result_.baseline && !every_design_) {
                probed = true;
                if (phase_only_)
                    open_.clear(); // no growth by witnesses (EXPLAINING)
                learner_.probe_shortcuts();
                if (learner_.prove_by_hitting_sets()) {
                    proven_ = true;
                    skip(static_cast<long long>(open_.size()));
                    open_.clear();
                    result_.notes.push_back("proven optimal by the hitting-set phase after " +
                                            std::to_string(learner_.designs()) +
                                            " designs (docs/design-search.md)");
                }
            }
        }
        // EXPLAINING: the phase alone proves the answer; stopped short of its proof (the
        // deadline), the best design so far is not known to be optimal.
        bool unproven = phase_only_ && !proven_;
        result_.limit_reached = interrupted || limit_seen_ || learner_.limit_seen() || unproven;
        result_.optimal = !result_.limit_reached;
        if (result_.limit_reached) {
            double least = std::min(open_.empty() ? INF : open_.top().bound, least_unfinished_);
            least = std::max(least, learner_.lower_bound()); // both hold for every design
            if (phase_only_)                                 // the queue held the root alone
                least = learner_.lower_bound();
            result_.gap = result_.best ? std::max(0.0, result_.best->objective.value - least) : INF;
        }
        if (options_.ranking > 0)
            result_.ranking = ranking_.designs();
        auto &counters = result_.counters;
        counters.configurations_total = generated_ + learner_.designs();
        close_counters(counters, evaluator_, start);
        report();
        return std::move(result_);
    }

    // The hitting-set phase proved the best design optimal.
    bool proven() const { return proven_; }

private:
    // The next configurations worth evaluating, least bound first.
    std::vector<Node> next_batch() {
        std::vector<Node> batch;
        while (!open_.empty() &&
               static_cast<int>(batch.size()) < std::max(1, options_.batch_size)) {
            if (clearly_greater(open_.top().bound, ranking_limit(result_, ranking_))) {
                skip(static_cast<long long>(open_.size())); // every other bound is larger
                open_.clear();
                break;
            }
            Node node = open_.pop();
            double now = bound_(node); // plans learnt since it was queued may raise it
            if (clearly_greater(now, node.bound)) {
                node.bound = now;
                open_.push(std::move(node));
                continue;
            }
            if (can_win(node.bound, node.configuration.size()))
                batch.push_back(std::move(node));
            else
                skip(1);
        }
        return batch;
    }

    void evaluate(std::vector<Node> batch) {
        if (batch.empty())
            return;
        std::vector<ConfigurationEvaluation> requests;
        std::map<Configuration, std::size_t> position;
        for (std::size_t i = 0; i < batch.size(); ++i) {
            if (blind(batch[i]))
                grow(batch[i]);
            if (std::all_of(batch[i].tasks.begin(), batch[i].tasks.end(),
                            [](const Record &r) { return r != nullptr; })) {
                // Known in full from smaller configurations: nothing to ask anyone.
                ConfigurationEvaluation known = unevaluated(batch[i].configuration);
                known.status = EvaluationStatus::COMPLETE;
                finish(batch[i], std::move(known));
                continue;
            }
            robot_bound_memory_.inherit(batch[i].configuration, batch[i].robot_bounds);
            position[batch[i].configuration] = i;
            requests.push_back(request_of(batch[i]));
        }
        EvaluationCallbacks callbacks;
        callbacks.abandon = [&](const ConfigurationEvaluation &partial) {
            return abandon(batch[position.at(partial.configuration)], partial);
        };
        callbacks.done = [&](ConfigurationEvaluation e) {
            Node &node = batch[position.at(e.configuration)];
            finish(node, std::move(e));
        };
        evaluator_.evaluate(requests, options_.deadline, callbacks);
    }

    // What the evaluator is told of `node`: what is known of it already.
    ConfigurationEvaluation request_of(const Node &node) const {
        ConfigurationEvaluation r = unevaluated(node.configuration);
        r.robot_cost_bounds = node.robot_bounds;
        r.ie_floors = node.ie_floors;
        r.explanation_floors = node.explanation_floors;
        r.tasks.resize(node.tasks.size());
        for (std::size_t t = 0; t < r.tasks.size(); ++t)
            if (const Record &record = node.tasks[t])
                r.tasks[t] = values_only(record->evaluation);
        return r;
    }

    // Whether to stop evaluating `node`, given what its evaluation knows so far.
    bool abandon(const Node &node, const ConfigurationEvaluation &partial) {
        if (blind(node)) { // grown already: only its own objective matters
            double own = own_bound(node.cost, partial);
            if (!can_win(own, node.configuration.size()))
                return true;
            if (should_defer(node, partial, own))
                deferred_.insert(node.configuration);
            return deferred_.count(node.configuration) > 0;
        }
        Node known = node; // what the answers so far add; their witnesses are not read yet
        for (int t = 0; t < tasks_; ++t) {
            if (!known.robot_bounds[t] && t < static_cast<int>(partial.robot_cost_bounds.size()))
                known.robot_bounds[t] = partial.robot_cost_bounds[t];
            if (t < static_cast<int>(partial.tasks.size()) && partial.tasks[t])
                raise_floor(known, t, *partial.tasks[t]);
        }
        if (!can_win(bound_(known), node.configuration.size()))
            return true;
        // With modifications outside that are added everywhere, the bound of the subtree
        // is weak and its witnesses narrow little: when the configuration itself cannot
        // win, stop evaluating it and grow it by every modification instead.
        if (bound_.always_outside(node) &&
            !can_win(own_bound(node.cost, partial), node.configuration.size())) {
            grow_without_witnesses_.insert(node.configuration);
            return true;
        }
        return false;
    }

    void finish(Node &node, ConfigurationEvaluation e) {
        auto &counters = result_.counters;
        if (e.status == EvaluationStatus::LIMIT) {
            limit_seen_ = true;
            least_unfinished_ = std::min(least_unfinished_, node.bound);
            return;
        }
        ++done_;
        robot_bound_memory_.remember(node.configuration, e.robot_cost_bounds);
        if (e.status == EvaluationStatus::CUT_OFF && deferred_.erase(node.configuration) > 0) {
            requeue(std::move(node), e);
            --done_;
            return;
        }
        if (e.status == EvaluationStatus::CUT_OFF) {
            ++counters.configurations_abandoned;
            if (grow_without_witnesses_.erase(node.configuration) > 0) {
                std::fill(node.tasks.begin(), node.tasks.end(), nullptr);
                grow(node); // every modification is a candidate, nothing is inherited
            }
            report();
            return;
        }
        ++counters.configurations_evaluated;
        std::vector<const TaskExplicability *> evaluations;
        for (int t = 0; t < tasks_; ++t) {
            if (node.tasks[t]) {
                ++counters.tasks_inherited;
            } else {
                auto record = std::make_shared<TaskRecord>();
                record->evaluation = std::move(*e.tasks[t]);
                record->touch = index_.touching(node.configuration, t, record->evaluation);
                bound_.learn(node.configuration, t, record->evaluation);
                node.tasks[t] = std::move(record);
            }
            if (!node.robot_bounds[t] && t < static_cast<int>(e.robot_cost_bounds.size()))
                node.robot_bounds[t] = e.robot_cost_bounds[t];
            raise_floor(node, t, node.tasks[t]->evaluation);
            evaluations.push_back(&node.tasks[t]->evaluation);
        }
        if (node.configuration.empty())
            learner_.evaluated(node);
        // Copies of the evaluations only for a design that ranks first.
        double value = objective_lower_bound(problem_, node.cost, evaluations); // all known
        if (can_win(value, node.configuration.size()) || node.configuration.empty()) {
            std::vector<TaskExplicability> copies;
            for (const auto *e : evaluations)
                copies.push_back(*e);
            consider_design(problem_, node.configuration, std::move(copies), result_, ranking_);
            if (ranking_.size() > 1) // its cone may hold the next ones (docs: "Ranking")
                offer_cone_of(problem_, bound_, node.configuration, node.tasks, max_size_,
                              ranking_);
        }
        if (!blind(node)) {
            node.bound = bound_(node);
            grow(node);
        }
        report();
    }

    // Queues the configurations one modification larger that can matter (witness_search.h).
    void grow(const Node &node) {
        const Configuration &c = node.configuration;
        if (static_cast<int>(c.size()) >= max_size_ || !can_win(node.bound, c.size() + 1))
            return;
        for (int m : candidates(node)) {
            Configuration child_configuration = c;
            child_configuration.insert(
                std::upper_bound(child_configuration.begin(), child_configuration.end(), m), m);
            if (!visited_.insert(child_configuration).second)
                continue;
            ++generated_;
            const ModificationClass &k = index_.of(m);
            Node child{std::move(child_configuration),
                       node.tasks,
                       node.robot_bounds,
                       node.explicable_floor,
                       node.cost + problem_.modifications[m].cost,
                       0,
                       {},
                       {}};
            for (int t = 0; t < tasks_; ++t) {
                const Record &r = node.tasks[t];
                if (!r || !k.restricting || !r->touch.known || contains(r->touch.all, m))
                    child.tasks[t] = r && k.restricting
                                         ? bound_.equally_cheap(t, *r, m, child.configuration)
                                         : nullptr;
                if (!k.robot_restricting) // else c_R* only rises: the parent's bound holds
                    child.robot_bounds[t].reset();
                if (!k.restricting)
                    child.explicable_floor[t] = 0;
            }
            // The parent's bound holds for the child's supersets too; its own is computed
            // when it is taken from the queue, if it ever is.
            child.bound = node.bound;
            if (can_win(child.bound, child.configuration.size()))
                open_.push(std::move(child));
            else
                skip(1);
        }
    }

    // Back to the queue under its own bound (should_defer), with the bounds and floors known.
    void requeue(Node node, const ConfigurationEvaluation &e) {
        node.bound = own_bound(node.cost, e);
        node.robot_bounds = e.robot_cost_bounds;
        node.ie_floors = e.ie_floors;
        node.explanation_floors = e.explanation_floors;
        open_.push(std::move(node));
    }

    // Every design weighed: before any task is evaluated, a design whose own bound, with the
    // bounds and floors answered since it left the queue, is above the least in the queue goes
    // back under that bound (not the empty design: the result's baseline). Designs are then
    // evaluated in the order of their own bounds (a good design early, the others abandoned on its
    // objective), and a design's remaining floors are asked only when it is the least again. Each
    // return follows a new answer, so it ends.
    bool should_defer(const Node &node, const ConfigurationEvaluation &partial, double own) const {
        if (!every_design_ || node.configuration.empty() || open_.empty() ||
            !clearly_greater(own, open_.top().bound) ||
            bounds_known(partial.robot_cost_bounds, partial.ie_floors) <=
                bounds_known(node.robot_bounds, node.ie_floors))
            return false;
        return std::none_of(partial.tasks.begin(), partial.tasks.end(),
                            [](const auto &t) { return t.has_value(); });
    }

    static int bounds_known(const std::vector<std::optional<double>> &robot_bounds,
                            const std::vector<std::optional<double>> &ie_floors) {
        auto set = [](const auto &v) { return v.has_value(); };
        return static_cast<int>(std::count_if(robot_bounds.begin(), robot_bounds.end(), set) +
                                std::count_if(ie_floors.begin(), ie_floors.end(), set));
    }

    // A lower bound on the objective of the configuration alone, from what is known of it.
    double own_bound(double cost, const ConfigurationEvaluation &partial) const {
        return own_lower_bound(problem_, cost, partial);
    }

    // When every modification outside `node` is added everywhere anyway, its witnesses do not
    // say what to add: it is grown before it is evaluated, and its evaluation may be
    // abandoned as soon as the configuration itself cannot win (as in the exhaustive search).
    bool blind(const Node &node) const {
        std::size_t outside = 0;
        for (int m : bound_.always())
            outside += contains(node.configuration, m) ? 0 : 1;
        return outside + node.configuration.size() == static_cast<std::size_t>(index_.size());
    }

    // The modifications that can change a task of `node` (or are added everywhere).
    std::vector<int> candidates(const Node &node) const {
        std::set<int> out(bound_.always().begin(), bound_.always().end());
        for (int t = 0; t < tasks_; ++t) {
            if (problem_.tasks[t].probability <= 0)
                continue;
            const Record &r = node.tasks[t];
            if (!r || !r->touch.known) {
                for (int m = 0; m < index_.size(); ++m)
                    out.insert(m);
                break;
            }
            out.insert(r->touch.all.begin(), r->touch.all.end());
        }
        std::vector<int> result;
        for (int m : out)
            if (!contains(node.configuration, m))
                result.push_back(m);
        return result;
    }

    // Whether a design of objective >= `bound` with at least `size` modifications could still
    // rank before the best one, or enter the ranking.
    bool can_win(double bound, std::size_t size) const {
        if (!result_.best)
            return true;
        double best = result_.best->objective.value;
        if (nearly_equal(bound, best))
            return size <= result_.best->ranked.configuration.size() ||
                   ranking_.may_enter(bound, size);
        return bound < best || ranking_.may_enter(bound, size);
    }

    void skip(long long count) {
        result_.counters.configurations_skipped += count;
        done_ += count;
    }

    void report() const {
        if (!progress_)
            return;
        EvaluatorCounters e = evaluator_.counters();
        SearchProgress p{done_ + learner_.designs(), // the hitting-set phase's designs too
                         generated_ + learner_.designs(),
                         result_.best ? result_.best->objective.value : INF,
                         e.planner_runs,
                         e.cache_hits,
                         static_cast<long long>(open_.size()),
                         open_.empty() ? INF : open_.top().bound};
        progress_(p);
    }

    const DesignProblem &problem_;
    Evaluator &evaluator_;
    const DesignSearchOptions &options_;
    const std::function<void(const SearchProgress &)> &progress_;
    TouchIndex index_;
    witness::SupersetBound bound_;
    RisingBounds robot_bound_memory_; // for children queued before their parent is known
    DesignResult result_;
    Ranking ranking_; // the N best (options.ranking)
    witness::DesignLearner learner_;
    int tasks_;
    bool phase_only_;   // EXPLAINING: the root, the probes and the hitting-set phase alone
    bool every_design_; // EXPLAINING: every design weighed, best first, no phase
    bool proven_ = false;
    int max_size_ = 0;
    OpenList open_;
    struct ConfigurationHash {
        std::size_t operator()(const Configuration &c) const {
            std::size_t h = c.size();
            for (int m : c)
                h = h * 1000003u ^ static_cast<std::size_t>(m);
            return h;
        }
    };
    std::unordered_set<Configuration, ConfigurationHash> visited_;
    std::set<Configuration> grow_without_witnesses_; // abandoned on their own bound
    std::set<Configuration> deferred_;               // back to the queue (should_defer)
    long long generated_ = 0;
    long long done_ = 0;
    bool limit_seen_ = false;
    double least_unfinished_ = INF;
};

} // namespace

DesignResult search_witness(const DesignProblem &problem, Evaluator &evaluator,
                            const DesignSearchOptions &options,
                            const std::function<void(const SearchProgress &)> &progress) {
    Visit visit = behaviour_of(problem.weights.behaviour).value_follows_witnesses
                      ? Visit::WITNESSES
                      : Visit::PHASE_ONLY;
    return WitnessSearch(problem, evaluator, options, progress, visit).run();
}

DesignResult search_every_design(const DesignProblem &problem, Evaluator &evaluator,
                                 const DesignSearchOptions &options,
                                 const std::function<void(const SearchProgress &)> &progress) {
    return WitnessSearch(problem, evaluator, options, progress, Visit::EVERY_DESIGN).run();
}

std::optional<DesignResult>
search_explaining_by_hitting_sets(const DesignProblem &problem, Evaluator &evaluator,
                                  const DesignSearchOptions &options,
                                  const std::function<void(const SearchProgress &)> &progress) {
    WitnessSearch search(problem, evaluator, options, progress, Visit::PHASE_ONLY);
    DesignResult result = search.run();
    if (search.proven() || options.deadline.expired())
        return result;
    return std::nullopt;
}

} // namespace envdesign::design
