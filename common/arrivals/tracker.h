#pragma once
// The bridge's state, transport-free: the design problems it tracks, an estimator and a
// drift detector per problem, the intake checks, and the re-evaluation requests that come
// out of them (arrival.h has the overview).
//
// Per problem, an accepted arrival is
//   - ESTIMATED when its task is one of the problem's (it enters the estimate);
//   - NEW_TASK when its task is not, but it carries the task's problem text: the task is
//     taken in provisionally (it enters the estimate) and a re-evaluation that adds it is
//     requested at once; if the answer comes back without the task, the coordinator refused
//     it and the task counts as unknown from then on;
//   - UNKNOWN_TASK otherwise: counted (per task name), not estimated. New tasks are taken in
//     at most new_task_burst at once then one per new_task_interval_s (a token bucket), and
//     max_new_tasks in all, per problem (each costs
//     planning; DDS without Security lets anyone publish them): beyond, an arrival of a new
//     task counts as unknown (new_tasks_held_back) and may come again later.
//
// Re-weighting: besides the requests above, which may need planners and so wait for the
// drift threshold, reweighs_due() names the problems whose estimate changed since their last
// re-weighting (at most one per reweigh_interval_s each): the design search is re-run for
// the estimate over stored evaluations alone (Redesigner::reweigh), so the design in force
// follows every D the store covers and never lags by up to `threshold`. A re-weighting that
// needs an evaluation the store lacks changes nothing; the drift detector, still measuring
// from the D the design was last proven for, asks for the planners once TV passes the
// threshold.
//
// Not thread-safe: the bridge serialises calls.
//
// Example:
//   ArrivalTracker tracker(config);
//   tracker.add_problem("restaurant", {{"serve-g1", 0.9}, {"serve-g2", 0.1}});
//   Outcome o = tracker.receive(arrival, now, now_utime);
//   if (o.request) publish(*o.request);
//   ... on the coordinator's answer: tracker.answered("restaurant", new_d, now);

#include "arrivals/drift_detector.h"
#include "arrivals/estimator.h"
#include "arrivals/intake.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace envdesign::arrivals {

struct TrackerConfig {
    EstimatorConfig estimator;
    DriftConfig drift;
    IntakeConfig intake;
    double reweigh_interval_s = 0.1;  // per problem, at most this often; <= 0: never
    std::size_t max_new_tasks = 64;   // new tasks taken in per problem, in all
    double new_task_interval_s = 1.0; // per problem, one new task more this often
    double new_task_burst = 8;        // new tasks taken in at once
};

struct NewTask {
    std::string name;
    std::string problem;       // PDDL problem text (robot's model)
    std::string human_problem; // empty: `problem`
};

enum class Reason {
    INITIAL,     // the design for the spec's D, asked for when tracking starts
    DRIFT,       // TV(reference, estimate) passed the threshold
    NEW_TASK,    // a new task came with its problem
    REWEIGH,     // the estimate changed: re-weigh stored evaluations, no planner (reweighs_due)
    UNEVALUATED, // a re-weighting needs configurations never evaluated: plan them now
};
const char *to_string(Reason reason);

// Asks the coordinator to re-evaluate one design problem for a new D.
struct Request {
    std::string problem_id;
    Reason reason = Reason::DRIFT;
    Distribution estimate;          // the D to evaluate (tasks absent: probability 0)
    Distribution reference;         // the D of the design in force
    double distance = 0;            // TV(reference, estimate)
    double samples = 0;             // effective samples behind the estimate
    std::vector<NewTask> new_tasks; // tasks to add to the problem first
};
// Why `request` was made, one line: "drift: D {...} vs the design's {...} (TV 0.310, 100
// samples)", and the new tasks if any.
std::string describe(const Request &request);

enum class Use { REJECTED, ESTIMATED, NEW_TASK, UNKNOWN_TASK };

struct Outcome {
    Verdict verdict = Verdict::ACCEPTED;
    Use use = Use::REJECTED;
    bool first_of_name = false; // UNKNOWN_TASK: the first arrival of this task name (of the
                                // first MAX_UNKNOWN_NAMES names)
    bool held_back = false;     // UNKNOWN_TASK: a new task beyond max_new_tasks or the rate
    bool clock_skewed = false;  // accepted though stamped beyond max_future_s ahead
    std::optional<Request> request;
};

// One design problem's view: what is published on the bus as its estimate.
struct ProblemStatus {
    std::string problem_id;
    Distribution estimate;
    Distribution reference;
    double samples = 0;
    double distance = 0;
    DriftState state = DriftState::ARMED;
    long long estimated = 0;    // arrivals in the estimate, ever
    long long unknown_task = 0; // arrivals of tasks the problem does not have
    long long new_tasks = 0;    // new tasks taken in
    long long refused_tasks = 0;
    long long new_tasks_held_back = 0; // beyond max_new_tasks or the rate
    long long requests = 0;
    long long timeouts = 0;
    long long reweighs = 0; // re-weightings asked for (reweighs_due)
    // Arrivals per unknown task name; the first MAX_UNKNOWN_NAMES names only (a flood of
    // made-up names must not grow the bridge without bound), the rest only in unknown_task.
    std::map<std::string, long long> unknown_task_names;
    static constexpr std::size_t MAX_UNKNOWN_NAMES = 1000;
};

class ArrivalTracker {
public:
    explicit ArrivalTracker(TrackerConfig config);

    // Tracks a design problem whose design in force was made for `reference` (its tasks are
    // the problem's tasks). Replaces an earlier one with the same id.
    void add_problem(const std::string &id, const Distribution &reference);
    bool tracks(const std::string &id) const { return problems_.count(id) > 0; }

    // A request for problem `id` went out that the tracker did not make (the INITIAL one):
    // no other goes out until it is answered. Returns that request.
    Request initial_request(const std::string &id, double now);

    // `now`: seconds on a monotonic clock; `now_utime`: wall clock, microseconds since epoch.
    Outcome receive(const Arrival &arrival, double now, int64_t now_utime);

    // A design for problem `id` is now in force, made for `reference` (its tasks are the
    // problem's tasks from now on). Returns a request when new tasks are still waiting.
    std::optional<Request> answered(const std::string &id, const Distribution &reference,
                                    double now);

    // Requests that fall due on the clock alone (called periodically, arrivals or not): a
    // request unanswered for answer_timeout_s times out, and is asked again at once if it
    // was the INITIAL one (no design yet) or the estimate has drifted; HELD retries.
    std::vector<Request> requests_due(double now);

    // Problems whose estimate changed since their last re-weighting, at most one request per
    // problem and reweigh_interval_s; none while a request of theirs is pending or new tasks
    // wait (the redesign for those comes first). The requests' D is the estimate.
    std::vector<Request> reweighs_due(double now);
    // A re-weighting for `reference` proved its design optimal: that design is in force and
    // the drift detector measures from `reference` (ignored while a request is pending: its
    // answer sets the reference).
    void reweighed(const std::string &id, const Distribution &reference);
    // A re-weighting for the estimate could not finish from stored evaluations: a request
    // (UNEVALUATED) for the estimate now, whatever the distance, unless one is pending or the
    // estimate rests on fewer than min_samples (the detector's evidence rule). Not
    // gated by the threshold: every evaluation it plans is stored, so such requests end once
    // the configurations the estimates need are evaluated, and until then the design in
    // force would be stale for as long as the estimate takes to move `threshold`.
    std::optional<Request> unevaluated(const std::string &id, double now);

    std::optional<ProblemStatus> status(const std::string &id) const;
    std::vector<std::string> problem_ids() const;
    const IntakeCounters &counters() const { return intake_.counters(); }

private:
    struct Problem {
        std::string id;
        std::set<std::string> tasks;             // the problem's tasks
        std::map<std::string, NewTask> proposed; // new tasks not yet answered
        std::set<std::string> sent;              // proposed tasks already in a request
        std::set<std::string> refused;
        DistributionEstimator estimator;
        DriftDetector detector;
        ProblemStatus status;
        long long reweighed_estimated = 0; // status.estimated at the last re-weighting
        double reweighed_at = -1e300;
        double new_task_tokens = -1; // the new-task token bucket (-1: full, not yet used)
        double new_task_at = 0;      // when it was last filled
        bool designed = false;       // a design was answered for it
    };

    Use classify(Problem &p, const Arrival &arrival, double now, Outcome &out);
    bool new_task_token(Problem &p, double now);
    Request make_request(Problem &p, Reason reason);

    TrackerConfig config_;
    ArrivalIntake intake_;
    std::map<std::string, Problem> problems_;
};

} // namespace envdesign::arrivals
