#include "cluster/planner.h"

#include "bus/channels.h"
#include "bus/log.h"
#include "cluster/worker_caches.h"
#include "envdesign/planner_heartbeat_t.hpp"
#include "envdesign/spec_need_t.hpp"
#include "pddl/parse_error.h"
#include "wire/job_messages.h"

#include <algorithm>
#include <cmath>

namespace envdesign::cluster {

Planner::Planner(bus::Bus &bus, PlannerConfig config)
    : bus_(bus), config_(std::move(config)), specs_(config_.max_specs, config_.spec_limits),
      memory_(static_cast<std::size_t>(std::max(0, config_.remembered_answers))),
      status_(bus, "planner", config_.instance) {
    subscriptions_.push_back(bus_.subscribe<envdesign::job_t>(
        bus::JOB, [this](const envdesign::job_t &job) { on_job(job); }));
    subscriptions_.push_back(bus_.subscribe<envdesign::spec_chunk_t>(
        bus::SPEC, [this](const envdesign::spec_chunk_t &chunk) { on_chunk(chunk); }));
    subscriptions_.push_back(bus_.subscribe<envdesign::job_t>(
        bus::WITHDRAW, [this](const envdesign::job_t &job) { on_withdraw(job); }));
    for (int i = 0; i < std::max(1, config_.workers); ++i)
        workers_.emplace_back([this] { work(); });
    heartbeat(false);
}

Planner::~Planner() {
    subscriptions_.clear();
    queue_.close();
    for (auto &worker : workers_)
        worker.join();
}

void Planner::tick() {
    auto now = Clock::now();
    if (now - last_tick_ < std::chrono::milliseconds(5))
        return; // the loop calls after every message; housekeeping needs less
    last_tick_ = now;
    if (std::chrono::duration<double>(now - last_beat_.load()).count() >=
        config_.heartbeat_period_s)
        heartbeat(stopping_);
    status_.tick([this](envdesign::service_status_t &s) { fill_status(s); });
    guard_memory();
    drop_stale_parked(now);
    ask_for_specs(now);
    specs_.expire();
}

// The backstop of the job budgets (job_search_budget): the process's resident memory, read
// every tick, stops the running searches before it passes workers x job_memory_bytes.
void Planner::guard_memory() {
    std::size_t limit =
        config_.job_memory_bytes * static_cast<std::size_t>(std::max(1, config_.workers));
    std::size_t resident = resident_bytes();
    std::lock_guard lock(mutex_);
    if (running_.empty()) {
        idle_resident_ = resident;
        return;
    }
    if (!past_memory_guard(resident, idle_resident_, limit))
        return;
    for (auto &[id, run] : running_)
        if (!run.over_memory) {
            run.over_memory = true;
            *run.stop = true;
            bus_.log().warn("request - | job {} stopped: the planner holds {} MiB, its limit is "
                            "{} MiB (--job-memory-mb x --workers)",
                            id, resident >> 20, limit >> 20);
        }
}

void Planner::drop_stale_parked(Clock::time_point now) {
    std::vector<envdesign::job_t> dropped;
    {
        std::lock_guard lock(mutex_);
        for (auto it = parked_.begin(); it != parked_.end();) {
            auto &jobs = it->second;
            for (auto job = jobs.begin(); job != jobs.end();) {
                if (std::chrono::duration<double>(now - job->received).count() <
                    config_.park_limit_s) {
                    ++job;
                    continue;
                }
                held_.erase(job->job.job_id);
                dropped.push_back(job->job);
                auto waiting = followers_.find(job_content(job->job)); // lack the spec too
                if (waiting != followers_.end()) {
                    for (const auto &follower : waiting->second) {
                        held_.erase(follower.job_id);
                        dropped.push_back(follower);
                    }
                    followers_.erase(waiting);
                }
                job = jobs.erase(job);
            }
            if (jobs.empty()) {
                asked_.erase(it->first);
                it = parked_.erase(it);
            } else {
                ++it;
            }
        }
    }
    for (const auto &job : dropped)
        bus_.log().warn("request {} | job {} dropped: spec {} never came", job.request_id,
                        job.job_id, job.spec_hash.substr(0, 12));
}

void Planner::stop() {
    stopping_ = true;
    heartbeat(true); // first: the coordinators move the jobs before their searches stop
    cancelled_ = true;
    std::lock_guard lock(mutex_);
    for (auto &[id, run] : running_)
        *run.stop = true;
    bus_.log().info("request - | stopping: no more jobs, running ones stopped");
}

void Planner::fill_status(envdesign::service_status_t &status) const {
    std::lock_guard lock(mutex_);
    status.jobs_in_flight = static_cast<std::int32_t>(held_.size());
    status.jobs_done = stats_.jobs_done;
    status.stored_evaluations = static_cast<std::int64_t>(memory_.size());
}

PlannerStats Planner::stats() const {
    std::lock_guard lock(mutex_);
    return stats_;
}

void Planner::on_job(const envdesign::job_t &job) {
    if (job.planner != config_.instance || stopping_)
        return; // another planner's
    if (job.spec_hash.size() != 64 || job.sender.empty()) {
        bus_.reject(bus::JOB, "job " + std::to_string(job.job_id) + " without spec or sender");
        return;
    }
    std::unique_lock lock(mutex_);
    if (auto it = answers_.find(job.job_id); it != answers_.end()) {
        ++stats_.answers_repeated;
        envdesign::evaluation_t answer = it->second;
        lock.unlock();
        bus_.log().info("request {} | job {} answered again (attempt {})", job.request_id,
                        job.job_id, job.attempt);
        bus_.publish(bus::EVALUATION, answer);
        return;
    }
    if (!held_.insert(job.job_id).second) {
        ++stats_.duplicates;
        return;
    }
    std::string content = job_content(job);
    if (auto kept = memory_.find(content)) {
        held_.erase(job.job_id);
        ++stats_.answers_remembered;
        lock.unlock();
        bus_.publish(bus::EVALUATION, readdressed(*kept, job, config_.instance));
        return;
    }
    if (auto leader = followers_.find(content); leader != followers_.end()) {
        leader->second.push_back(job); // answered with the job computing the same content
        return;
    }
    followers_[content]; // this job computes it
    Pending pending{job, Clock::now()};
    if (specs_.complete(job.spec_hash)) {
        queue_.push(std::move(pending));
        return;
    }
    parked_[job.spec_hash].push_back(std::move(pending));
    asked_.try_emplace(job.spec_hash, job.sender, Clock::time_point{});
    lock.unlock();
    ask_for_specs(Clock::now());
}

// A job its coordinator took back for another request (cluster/fair_share.h): stopped if it
// runs, skipped if it waits; either way not answered.
void Planner::on_withdraw(const envdesign::job_t &job) {
    if (job.planner != config_.instance)
        return;
    {
        std::lock_guard lock(mutex_);
        if (!held_.count(job.job_id))
            return; // answered already, or never here
        bus_.log().info("request {} | job {} withdrawn by {}", job.request_id, job.job_id,
                        job.sender);
        if (auto run = running_.find(job.job_id); run != running_.end()) {
            *run->second.stop = true; // its worker beats when it lets go
            return;
        }
        auto waiting = [&](const Pending &p) { return p.job.job_id == job.job_id; };
        auto parked = parked_.find(job.spec_hash);
        auto same = followers_.find(job_content(job));
        if (queue_.remove_if(waiting) > 0 ||
            (parked != parked_.end() && std::erase_if(parked->second, waiting) > 0)) {
            abandon(job); // a job waiting for its content's answer takes its place
        } else if (same != followers_.end() &&
                   std::erase_if(same->second, [&](const envdesign::job_t &follower) {
                       return follower.job_id == job.job_id;
                   }) > 0) {
            held_.erase(job.job_id); // it waited for another job's answer
        } else {
            withdrawn_.insert(job.job_id);
            return;
        }
    }
    // Let go of it now, not a heartbeat period later: its slot went to a client that waits
    // (issue 21's flood: forty requests of one spec wait for one another's answers here).
    heartbeat(false);
}

// Under mutex_: a job dropped unanswered. Jobs waiting for the same content go on: the
// first computes it.
void Planner::abandon(const envdesign::job_t &job) {
    held_.erase(job.job_id);
    running_.erase(job.job_id);
    auto it = followers_.find(job_content(job));
    if (it == followers_.end())
        return;
    std::vector<envdesign::job_t> waiting = std::move(it->second);
    followers_.erase(it);
    if (waiting.empty())
        return;
    queue_.push({waiting.front(), Clock::now()});
    followers_[job_content(job)].assign(waiting.begin() + 1, waiting.end());
}

void Planner::on_chunk(const envdesign::spec_chunk_t &chunk) {
    std::string why;
    auto added = specs_.add_chunk(chunk, why);
    if (added == PlannerSpecs::Added::BAD) {
        bus_.reject(bus::SPEC, "spec chunk from " + chunk.sender + ": " + why);
        return;
    }
    if (added != PlannerSpecs::Added::COMPLETED)
        return;
    std::vector<Pending> ready;
    {
        std::lock_guard lock(mutex_);
        if (auto it = parked_.find(chunk.spec_hash); it != parked_.end()) {
            ready = std::move(it->second);
            parked_.erase(it);
        }
        asked_.erase(chunk.spec_hash);
        for (auto &p : ready)
            queue_.push(std::move(p));
    }
    bus_.log().info("request {} | spec {} received", chunk.request_id,
                    chunk.spec_hash.substr(0, 12));
}

// Asks the coordinator of parked jobs for their spec, again after need_retry_s.
void Planner::ask_for_specs(Clock::time_point now) {
    std::vector<envdesign::spec_need_t> needs;
    {
        std::lock_guard lock(mutex_);
        for (auto &[hash, asked] : asked_) {
            if (std::chrono::duration<double>(now - asked.second).count() < config_.need_retry_s)
                continue;
            asked.second = now;
            envdesign::spec_need_t need{};
            need.utime = bus::now_utime();
            auto parked = parked_.find(hash);
            need.request_id = parked == parked_.end() || parked->second.empty()
                                  ? 0
                                  : parked->second.front().job.request_id;
            need.sender = config_.instance;
            need.coordinator = asked.first;
            need.spec_hash = hash;
            for (int i : specs_.missing(hash))
                need.missing.push_back(static_cast<std::int16_t>(i));
            need.num_missing = static_cast<std::int16_t>(need.missing.size());
            needs.push_back(std::move(need));
        }
    }
    for (const auto &need : needs) {
        bus_.log().info("request {} | asking {} for spec {}", need.request_id, need.coordinator,
                        need.spec_hash.substr(0, 12));
        bus_.publish(bus::SPEC_NEED, need);
    }
}

void Planner::heartbeat(bool stopping) {
    envdesign::planner_heartbeat_t beat{};
    beat.utime = bus::now_utime();
    beat.sender = config_.instance;
    beat.period_ms = static_cast<std::int32_t>(std::lround(config_.heartbeat_period_s * 1000));
    beat.capacity = static_cast<std::int16_t>(std::max(1, config_.workers));
    {
        std::lock_guard lock(mutex_);
        for (auto id : held_) {
            if (beat.jobs.size() >= 32767)
                break;
            beat.jobs.push_back(id);
        }
        beat.jobs_done = stats_.jobs_done;
        // Running jobs count as they run: coordinators see a long search is being worked on
        // and do not send it to a second planner (planner_pool.h).
        beat.busy_seconds = stats_.busy_seconds;
        auto now = Clock::now();
        for (const auto &[id, run] : running_)
            beat.busy_seconds += std::chrono::duration<double>(now - run.start).count();
    }
    beat.num_jobs = static_cast<std::int16_t>(beat.jobs.size());
    beat.specs_cached = specs_.size();
    beat.malformed = bus_.malformed() + bus_.auth_drops().total(); // lcm-spy shows attacks
    beat.stopping = stopping;
    bus_.publish(bus::HEARTBEAT, beat);
    last_beat_ = Clock::now();
}

void Planner::work() {
    WorkerCaches caches(config_.max_specs, config_.job_memory_bytes, config_.workers);
    while (auto next = queue_.pop()) { // nullopt: closed and drained
        Pending pending = std::move(*next);
        std::shared_ptr<std::atomic<bool>> stop;
        {
            std::unique_lock lock(mutex_);
            if (withdrawn_.erase(pending.job.job_id) || cancelled_) {
                abandon(pending.job);
                lock.unlock();
                if (!stopping_)
                    heartbeat(false); // let go: the coordinator frees its slot now
                continue;
            }
            stop = std::make_shared<std::atomic<bool>>(false);
            running_[pending.job.job_id] = {Clock::now(), stop};
        }
        auto start = Clock::now();
        envdesign::evaluation_t answer = evaluate(pending, caches, stop.get());
        bool over_memory = false;
        {
            std::lock_guard lock(mutex_);
            over_memory = running_.at(pending.job.job_id).over_memory;
        }
        if (stop->load() && !over_memory) { // withdrawn or stopping: the job went elsewhere
            {
                std::lock_guard lock(mutex_);
                abandon(pending.job);
            }
            // The coordinator frees the slot when a heartbeat no longer lists the job: say so
            // now, not up to a period later (the request it yielded to waits for it).
            if (!stopping_)
                heartbeat(false);
            continue;
        }
        answer.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        answer.queued_seconds = std::chrono::duration<double>(start - pending.received).count();
        bus_.publish(bus::EVALUATION, answer);
        auto shared = answered(pending.job, answer);
        for (const auto &a : shared)
            bus_.publish(bus::EVALUATION, a);
        release(shared);
    }
}

std::vector<envdesign::evaluation_t> Planner::answered(const envdesign::job_t &job,
                                                       const envdesign::evaluation_t &answer) {
    std::vector<envdesign::evaluation_t> shared;
    {
        std::lock_guard lock(mutex_);
        held_.erase(answer.job_id); // after publishing: a heartbeat never misses a job between
        running_.erase(answer.job_id);
        ++stats_.jobs_done;
        stats_.busy_seconds += answer.seconds;
        remember_by_id(answer);
        std::string content = job_content(job);
        memory_.keep(content, answer);
        auto it = followers_.find(content);
        if (it == followers_.end())
            return shared;
        std::vector<envdesign::job_t> waiting = std::move(it->second);
        followers_.erase(it);
        if (AnswerMemory::keepable(answer)) {
            for (const auto &follower : waiting)
                shared.push_back(readdressed(answer, follower, config_.instance));
            stats_.answers_remembered += static_cast<long long>(waiting.size());
            return shared;
        }
        if (waiting.empty())
            return shared;
        // Out of time (or failed): the waiting jobs had their own time; the first computes.
        queue_.push({waiting.front(), Clock::now()});
        followers_[content].assign(waiting.begin() + 1, waiting.end());
    }
    return shared;
}

void Planner::release(const std::vector<envdesign::evaluation_t> &answers) {
    std::lock_guard lock(mutex_);
    for (const auto &answer : answers) {
        held_.erase(answer.job_id);
        remember_by_id(answer);
    }
}

void Planner::remember_by_id(const envdesign::evaluation_t &answer) {
    answers_[answer.job_id] = answer;
    answer_order_.push_back(answer.job_id);
    while (static_cast<int>(answer_order_.size()) > config_.answers_kept) {
        answers_.erase(answer_order_.front());
        answer_order_.pop_front();
    }
}

envdesign::evaluation_t Planner::evaluate(const Pending &pending, WorkerCaches &caches,
                                          const std::atomic<bool> *stop) {
    const envdesign::job_t &job = pending.job;
    envdesign::evaluation_t answer{};
    answer.utime = bus::now_utime();
    answer.request_id = job.request_id;
    answer.sender = config_.instance;
    answer.coordinator = job.sender;
    answer.job_id = job.job_id;
    answer.kind = job.kind;
    try {
        auto spec = specs_.load(job.spec_hash);
        if (!spec || !spec->problem) {
            answer.status = envdesign::evaluation_t::STATUS_BAD_INPUT;
            answer.error = spec ? spec->error : "the spec was dropped";
            return answer;
        }
        if (auto problem = wire::job_problem(job, *spec->problem)) {
            bus_.reject(bus::JOB, "job " + std::to_string(job.job_id) + ": " + *problem);
            answer.status = envdesign::evaluation_t::STATUS_BAD_INPUT;
            answer.error = "bad job: " + *problem;
            return answer;
        }
        design::LocalEvaluator &evaluator = caches.get(spec, job.heuristic);
        // The time left when the job arrived, less its wait here; 0 stays "no limit".
        double waited = std::chrono::duration<double>(Clock::now() - pending.received).count();
        design::Deadline deadline =
            design::Deadline::in(job.time_limit_s > 0 ? std::max(job.time_limit_s - waited, 1e-3)
                                                      : 0)
                .with_stop(stop);
        design::Configuration configuration = wire::configuration_of(job);
        design::EvaluatorCounters before = evaluator.counters();
        wire::put_answer(evaluator.answer(configuration, wire::job_of(job), deadline), answer);
        design::EvaluatorCounters after = evaluator.counters();
        answer.planner_runs = static_cast<std::int32_t>(after.planner_runs - before.planner_runs);
        answer.cache_hits = static_cast<std::int32_t>(after.cache_hits - before.cache_hits);
        answer.groundings_skipped =
            static_cast<std::int32_t>(after.groundings_skipped - before.groundings_skipped);
        answer.planner_seconds = after.planner_seconds - before.planner_seconds;
    } catch (const pddl::ParseError &e) {
        answer.status = envdesign::evaluation_t::STATUS_BAD_INPUT;
        answer.error = e.what();
    } catch (const std::exception &e) {
        answer.status = envdesign::evaluation_t::STATUS_ERROR;
        answer.error = e.what();
    }
    if (answer.status >= envdesign::evaluation_t::STATUS_BAD_INPUT)
        bus_.log().warn("request {} | job {} failed: {}", job.request_id, job.job_id, answer.error);
    return answer;
}

} // namespace envdesign::cluster
