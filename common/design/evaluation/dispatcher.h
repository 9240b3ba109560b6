#pragma once
// Which piece of work to do next for a batch of configurations, and what is known so far;
// the bookkeeping half of an Evaluator, free of any transport. LocalEvaluator runs the jobs
// on threads; an evaluator over LCM (issue 5) sends the same jobs to planner services.
//
// Per configuration, the dispatcher first asks for the robot's optimal cost of every task
// (ROBOT_BOUND jobs: cheap, and usually cache hits, since most modifications leave the robot
// alone; an evaluator may add a floor on the task's IE), then for the explicability of each
// task (EXPLICABILITY jobs: the compiled task and the human's task), asking `abandon`
// whether the configuration can still win after each answer and before each
// EXPLICABILITY job. Configurations are served in batch order;
// while one waits for answers, the next one's jobs go out.

#include "design/design_problem.h"
#include "design/evaluation/evaluator.h"

#include <optional>
#include <vector>

namespace envdesign::design {

enum class JobKind { ROBOT_BOUND, EXPLICABILITY };

// Whether ROBOT_BOUND jobs are worth asking for `problem`: its objective weighs the robot's
// cost (kappa > 0), or the answers carry IE floors (ie_floors_hold, explicability.h).
bool asks_robot_bounds(const DesignProblem &problem);

struct Job {
    int configuration = 0; // index into the batch
    int task = 0;
    JobKind kind = JobKind::EXPLICABILITY;
    // ROBOT_BOUND: a lower bound on c_R* already known (the configuration grew from one whose
    // robot model it only restricts); the answer gives it back with the IE floor it yields,
    // and only the human's model is solved.
    std::optional<double> robot_bound;
};

struct JobAnswer {
    Job job;
    std::optional<double> robot_bound; // ROBOT_BOUND: c_R* (INF: no plan), unset: no bound
    std::optional<double> ie_floor;    // ROBOT_BOUND: a lower bound on the task's IE, if any
    TaskExplicability explicability;   // EXPLICABILITY
    // ROBOT_BOUND, a robot that may explain: a lower bound on the differences any explanation
    // tells (explanation_floor.h), where the floor is above the least IE.
    std::optional<int> explanation_floor = std::nullopt;
};

class Dispatcher {
public:
    // `robot_bounds`: whether to ask for ROBOT_BOUND jobs at all (asks_robot_bounds);
    // `ie_floors`: whether their answers carry IE floors (ie_floors_hold), so that a task whose
    // robot bound is given is still asked for its floor. `callbacks` must outlive the
    // dispatcher. `exact_bounds_first`: a configuration that survives its bounds has each given
    // (inherited) robot bound replaced by c_R* before a task is evaluated, another chance to
    // abandon it; for evaluations that find c_R* anyway (the explaining robot's pi_R), whose
    // robot A* is then a plan-cache hit.
    Dispatcher(const std::vector<ConfigurationEvaluation> &batch, int tasks, bool robot_bounds,
               bool ie_floors, const EvaluationCallbacks &callbacks,
               bool exact_bounds_first = false);

    // The next job to send, or nullopt when nothing can be sent before more answers come.
    std::optional<Job> next_job();
    void receive(JobAnswer answer);
    // Everything not finished ran out of time: reported LIMIT once its jobs are back.
    void finish_rest();

private:
    struct Progress {
        std::vector<int> bounds_needed; // tasks whose robot bound is asked for
        std::vector<int> exact_needed;  // tasks whose given bound is asked for again, exactly
        int exact_sent = 0;
        int exact_known = 0;
        std::vector<int> tasks_needed; // tasks to evaluate
        int bounds_sent = 0;           // of bounds_needed
        int bounds_known = 0;
        int tasks_sent = 0; // of tasks_needed
        int in_flight = 0;
        std::optional<EvaluationStatus> stopped;
        bool finished = false;
    };

    std::optional<Job> next_job_of(int c);
    static int needed(const Progress &p);
    bool complete(int c) const;
    void stop(int c, EvaluationStatus status);
    void finish_if_idle(int c);
    bool abandon(int c);

    const EvaluationCallbacks &callbacks_;
    bool robot_bounds_;
    std::vector<ConfigurationEvaluation> state_;
    std::vector<Progress> progress_;
    int first_open_ = 0; // configurations before this one need nothing more
};

} // namespace envdesign::design
