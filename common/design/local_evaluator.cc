#include "design/local_evaluator.h"

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>

namespace envdesign::design {

Evaluator::~Evaluator() = default;

namespace {

struct Job {
    int configuration = 0;
    int task = 0;
};

struct Answer {
    Job job;
    TaskExplicability value;
    std::exception_ptr error;
};

// Jobs go to the workers, answers come back to the dispatcher.
class Channel {
public:
    void send(Job job) {
        {
            std::lock_guard lock(mutex_);
            jobs_.push_back(job);
        }
        job_ready_.notify_one();
    }
    // Blocks until a job arrives; nullopt once closed.
    std::optional<Job> receive_job() {
        std::unique_lock lock(mutex_);
        job_ready_.wait(lock, [&] { return closed_ || !jobs_.empty(); });
        if (jobs_.empty())
            return std::nullopt;
        Job job = jobs_.front();
        jobs_.pop_front();
        return job;
    }
    void answer(Answer a) {
        {
            std::lock_guard lock(mutex_);
            answers_.push_back(std::move(a));
        }
        answer_ready_.notify_one();
    }
    Answer receive_answer() {
        std::unique_lock lock(mutex_);
        answer_ready_.wait(lock, [&] { return !answers_.empty(); });
        Answer a = std::move(answers_.front());
        answers_.pop_front();
        return a;
    }
    void close() {
        {
            std::lock_guard lock(mutex_);
            closed_ = true;
        }
        job_ready_.notify_all();
    }

private:
    std::mutex mutex_;
    std::condition_variable job_ready_, answer_ready_;
    std::deque<Job> jobs_;
    std::deque<Answer> answers_;
    bool closed_ = false;
};

// The dispatcher's view of one batch: what is in flight, what is known, what is finished.
class Batch {
public:
    Batch(const std::vector<Configuration> &configurations, int tasks,
          const EvaluationCallbacks &callbacks)
        : callbacks_(callbacks), tasks_(tasks), in_flight_(configurations.size(), 0),
          stopped_(configurations.size()), finished_(configurations.size(), false) {
        for (const auto &c : configurations)
            state_.push_back({c, EvaluationStatus::LIMIT, std::vector<std::optional<TaskExplicability>>(tasks)});
    }

    // The next job to start, or nullopt when the batch has none left.
    std::optional<Job> next_job() {
        while (next_.configuration < static_cast<int>(state_.size())) {
            int c = next_.configuration;
            if (!stopped_[c] && callbacks_.abandon && callbacks_.abandon(state_[c]))
                stop(c, EvaluationStatus::CUT_OFF);
            if (stopped_[c] || next_.task >= tasks_) {
                next_ = {c + 1, 0};
                continue;
            }
            ++in_flight_[c];
            return Job{c, next_.task++};
        }
        return std::nullopt;
    }

    void receive(Answer &a) {
        int c = a.job.configuration;
        --in_flight_[c];
        if (a.value.status == ExplicabilityStatus::LIMIT)
            stop(c, EvaluationStatus::LIMIT);
        else
            state_[c].tasks[a.job.task] = std::move(a.value);
        if (!stopped_[c] && complete(c)) {
            stop(c, EvaluationStatus::COMPLETE);
        } else if (!stopped_[c] && callbacks_.abandon && callbacks_.abandon(state_[c])) {
            stop(c, EvaluationStatus::CUT_OFF);
        }
        finish_if_idle(c);
    }

    // Everything not finished yet ran out of time.
    void finish_rest() {
        for (std::size_t c = 0; c < state_.size(); ++c) {
            stop(static_cast<int>(c), EvaluationStatus::LIMIT);
            finish_if_idle(static_cast<int>(c));
        }
    }

private:
    bool complete(int c) const {
        for (const auto &t : state_[c].tasks)
            if (!t)
                return false;
        return true;
    }

    void stop(int c, EvaluationStatus status) {
        if (!stopped_[c])
            stopped_[c] = status;
    }

    void finish_if_idle(int c) {
        if (finished_[c] || !stopped_[c] || in_flight_[c] > 0)
            return;
        finished_[c] = true;
        state_[c].status = *stopped_[c];
        callbacks_.done(std::move(state_[c]));
    }

    const EvaluationCallbacks &callbacks_;
    int tasks_;
    std::vector<ConfigurationEvaluation> state_;
    std::vector<int> in_flight_;
    std::vector<std::optional<EvaluationStatus>> stopped_;
    std::vector<bool> finished_;
    Job next_;
};

}  // namespace

LocalEvaluator::LocalEvaluator(const DesignProblem &problem, int workers,
                               planning::PlannerOptions options)
    : problem_(problem), workers_(std::max(1, workers)), cache_(std::move(options)) {}

TaskExplicability LocalEvaluator::evaluate_task(const Configuration &configuration, int task,
                                                const Deadline &deadline) {
    ModelPair models = configured_models(problem_, configuration, task);
    return evaluate_explicability(models, problem_.weights.distance, cache_, deadline);
}

void LocalEvaluator::evaluate(const std::vector<Configuration> &batch, const Deadline &deadline,
                              const EvaluationCallbacks &callbacks) {
    Batch state(batch, static_cast<int>(problem_.tasks.size()), callbacks);
    Channel channel;
    std::vector<std::thread> threads;
    for (int i = 0; i < workers_; ++i) {
        threads.emplace_back([&] {
            while (auto job = channel.receive_job()) {
                Answer a{*job, {}, nullptr};
                try {
                    a.value = evaluate_task(batch[job->configuration], job->task, deadline);
                } catch (...) {
                    a.error = std::current_exception();
                }
                channel.answer(std::move(a));
            }
        });
    }
    std::exception_ptr error;
    int in_flight = 0;
    while (true) {
        while (in_flight < workers_ && !error && !deadline.expired()) {
            auto job = state.next_job();
            if (!job)
                break;
            channel.send(*job);
            ++in_flight;
        }
        if (in_flight == 0)
            break;
        Answer a = channel.receive_answer();
        --in_flight;
        ++task_evaluations_;
        if (a.error && !error)
            error = a.error;
        if (!a.error)
            state.receive(a);
    }
    channel.close();
    for (auto &t : threads)
        t.join();
    if (error)
        std::rethrow_exception(error);
    state.finish_rest();
}

EvaluatorCounters LocalEvaluator::counters() const {
    CacheCounters c = cache_.counters();
    return {task_evaluations_, c.planner_runs, c.cache_hits, c.planner_seconds};
}

}  // namespace envdesign::design
