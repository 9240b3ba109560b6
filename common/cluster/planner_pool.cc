#include "cluster/planner_pool.h"

#include "bus/log.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace envdesign::cluster {

std::optional<std::string> heartbeat_problem(const envdesign::planner_heartbeat_t &beat) {
    if (beat.sender.empty())
        return "no sender";
    if (beat.capacity < 1)
        return "capacity " + std::to_string(beat.capacity) + " is below 1";
    design::NumberRange period_ms{HEARTBEAT_PERIOD_S.low * 1000, HEARTBEAT_PERIOD_S.high * 1000};
    if (auto why = design::number_problem(beat.period_ms, period_ms))
        return "period_ms " + *why;
    if (!std::isfinite(beat.busy_seconds) || beat.busy_seconds < 0) {
        std::ostringstream why;
        why << "busy_seconds must be finite and at least 0 (got " << beat.busy_seconds << ")";
        return why.str();
    }
    return std::nullopt;
}

std::vector<envdesign::job_t> PlannerPool::submit(std::uint64_t owner, envdesign::job_t job,
                                                  Clock::time_point now) {
    std::lock_guard lock(mutex_);
    std::int64_t id = job.job_id;
    jobs_[id] = JobRecord{owner, std::move(job), {}, {}, {}};
    queue_.push_back(id);
    return assign(now);
}

std::vector<envdesign::job_t> PlannerPool::heartbeat(const envdesign::planner_heartbeat_t &beat,
                                                     Clock::time_point now, Events *events) {
    std::lock_guard lock(mutex_);
    if (beat.stopping) {
        drop_planner(beat.sender, events, "is stopping");
        return assign(now);
    }
    auto [it, joined] = planners_.try_emplace(beat.sender);
    if (joined) {
        ++counters_.planners_joined;
        if (events)
            events->push_back("planner " + beat.sender + " joined with " +
                              std::to_string(beat.capacity) + " worker(s)");
    }
    it->second.workers = std::max(1, static_cast<int>(beat.capacity));
    it->second.slots = it->second.workers * config_.jobs_per_slot;
    it->second.last_beat = now;
    if (beat.busy_seconds > it->second.busy_seconds)
        it->second.busy_grew = now;
    it->second.busy_seconds = beat.busy_seconds;
    std::set<std::int64_t> held(beat.jobs.begin(), beat.jobs.end());
    std::erase_if(it->second.overdue, [&](const auto &job) { return !held.count(job.first); });
    for (auto w = it->second.withdrawn.begin(); w != it->second.withdrawn.end();) {
        if (held.count(w->first)) {
            ++w;
            continue;
        }
        keep_for(it->second, w->second, now); // let go: the slot is its taker's
        w = it->second.withdrawn.erase(w);
    }
    auto lost_before = now - std::chrono::duration_cast<Clock::duration>(
                                 std::chrono::duration<double>(config_.lost_after_s));
    std::vector<std::int64_t> lost;
    for (auto &[id, record] : jobs_)
        if (record.planner == beat.sender && record.sent < lost_before && !held.count(id))
            lost.push_back(id);
    for (std::int64_t id : lost)
        requeue(id);
    return assign(now);
}

std::optional<JobRecord> PlannerPool::answer(std::int64_t job_id, const std::string &from,
                                             std::vector<envdesign::job_t> &to_send,
                                             Clock::time_point now) {
    std::lock_guard lock(mutex_);
    auto it = jobs_.find(job_id);
    note_answer_time(from, job_id, it == jobs_.end() ? nullptr : &it->second, now);
    if (auto planner = planners_.find(from); planner != planners_.end()) {
        auto w = planner->second.withdrawn.find(job_id); // answered before the withdrawal came
        if (w != planner->second.withdrawn.end()) {
            keep_for(planner->second, w->second, now);
            planner->second.withdrawn.erase(w);
        }
    }
    if (it != jobs_.end() && it->second.planner == from)
        fair_.add_service(client_of(it->second.owner),
                          std::chrono::duration<double>(now - it->second.sent).count(), now);
    if (it == jobs_.end()) {
        ++counters_.duplicates; // answered already, or never ours
        if (auto a = answered_.find(job_id); a != answered_.end())
            if (auto owner = owners_.find(a->second); owner != owners_.end())
                ++owner->second.duplicates;
        return std::nullopt;
    }
    // A late answer to a job queued again for another planner still counts.
    queue_.erase(std::remove(queue_.begin(), queue_.end(), job_id), queue_.end());
    JobRecord record = std::move(it->second);
    if (auto planner = planners_.find(record.planner);
        planner != planners_.end() && record.planner == from && contended())
        keep_for(planner->second, client_of(record.owner), now);
    release(record);
    jobs_.erase(it);
    counters_.answered_by.insert(from);
    owners_[record.owner].answered_by.insert(from);
    remember_answered(job_id, record.owner);
    to_send = assign(now);
    return record;
}

std::vector<envdesign::job_t> PlannerPool::expire(Clock::time_point now, Events *events) {
    std::lock_guard lock(mutex_);
    auto silent_since = now - std::chrono::duration_cast<Clock::duration>(
                                  std::chrono::duration<double>(config_.planner_timeout_s));
    std::vector<std::string> gone;
    for (const auto &[name, planner] : planners_)
        if (planner.last_beat < silent_since)
            gone.push_back(name);
    for (const auto &name : gone)
        drop_planner(name, events, "went silent");
    take_overdue(now, events);
    return assign(now);
}

// Jobs past their deadline go back to the queue (a planner that lists a job and never answers
// would hold it for good); their holders' slots stay taken until they let go of them.
void PlannerPool::take_overdue(Clock::time_point now, Events *events) {
    std::vector<std::int64_t> overdue;
    for (const auto &[id, record] : jobs_)
        if (!record.planner.empty() && this->overdue(record, now))
            overdue.push_back(id);
    for (std::int64_t id : overdue) {
        JobRecord &record = jobs_.at(id);
        Planner &holder = planners_.at(record.planner);
        holder.overdue[id] = record.sent;
        ++counters_.deadlines_missed;
        if (++holder.misses >= config_.demote_after && !holder.demoted) {
            holder.demoted = true;
            ++counters_.planners_demoted;
            if (events)
                events->push_back("planner " + record.planner + " missed " +
                                  std::to_string(holder.misses) +
                                  " job deadlines in a row: demoted");
        }
        if (events)
            events->push_back("job " + std::to_string(id) + " missed its deadline at " +
                              record.planner + "; sent again");
        requeue(id);
    }
}

// How long planners take: the deadline grows with the slowest answer, so that honest
// planners on hard problems are not taken for stuck ones; an answer in time clears misses.
void PlannerPool::note_answer_time(const std::string &from, std::int64_t job_id,
                                   const JobRecord *record, Clock::time_point now) {
    auto planner = planners_.find(from);
    if (planner == planners_.end())
        return;
    std::optional<Clock::time_point> sent;
    if (auto late = planner->second.overdue.find(job_id); late != planner->second.overdue.end()) {
        sent = late->second;
        planner->second.overdue.erase(late);
    } else if (record && record->planner == from) {
        sent = record->sent;
        planner->second.misses = 0;
        planner->second.demoted = false;
    }
    if (sent)
        longest_answer_s_ =
            std::max(longest_answer_s_, std::chrono::duration<double>(now - *sent).count());
}

// A planner is working while its busy time grew within the last second (it counts the jobs
// it runs; one that only lists jobs does not).
bool PlannerPool::Planner::working(Clock::time_point now) const {
    return now - busy_grew < std::chrono::seconds(1);
}

bool PlannerPool::overdue(const JobRecord &record, Clock::time_point now) const {
    if (now - record.sent <= deadline())
        return false;
    auto holder = planners_.find(record.planner);
    if (holder == planners_.end() || !holder->second.working(now))
        return true;
    double limit = record.message.time_limit_s;
    return limit > 0 && std::chrono::duration<double>(now - record.sent).count() >
                            limit + config_.working_grace_s;
}

PlannerPool::Clock::duration PlannerPool::deadline() const {
    double seconds = std::max(config_.job_deadline_s, config_.deadline_factor * longest_answer_s_);
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

double PlannerPool::deadline_s() const {
    std::lock_guard lock(mutex_);
    return std::chrono::duration<double>(deadline()).count();
}

bool PlannerPool::sent_to(std::int64_t job_id, const std::string &planner) const {
    std::lock_guard lock(mutex_);
    auto it = jobs_.find(job_id);
    return it == jobs_.end() || it->second.tried.count(planner) > 0;
}

bool PlannerPool::demoted(const std::string &planner) const {
    std::lock_guard lock(mutex_);
    auto it = planners_.find(planner);
    return it != planners_.end() && it->second.demoted;
}

void PlannerPool::forget(const std::vector<std::int64_t> &job_ids) {
    std::lock_guard lock(mutex_);
    for (std::int64_t id : job_ids) {
        auto it = jobs_.find(id);
        if (it == jobs_.end())
            continue;
        // A held job is withdrawn: its planner would work on for no one (a never-ending
        // search of a dropped request); the slot frees when the planner lets go of it.
        if (auto holder = planners_.find(it->second.planner); holder != planners_.end()) {
            holder->second.withdrawn.emplace(id, 0);
            withdrawals_.push_back(it->second.message);
        }
        release(it->second);
        jobs_.erase(it);
        queue_.erase(std::remove(queue_.begin(), queue_.end(), id), queue_.end());
    }
}

std::optional<std::int8_t> PlannerPool::kind_of(std::int64_t job_id) const {
    std::lock_guard lock(mutex_);
    auto it = jobs_.find(job_id);
    return it == jobs_.end() ? std::nullopt : std::optional<std::int8_t>(it->second.message.kind);
}

int PlannerPool::capacity() const {
    std::lock_guard lock(mutex_);
    int slots = 0;
    for (const auto &[name, planner] : planners_)
        slots += planner.slots;
    return slots;
}

int PlannerPool::live_planners() const {
    std::lock_guard lock(mutex_);
    return static_cast<int>(planners_.size());
}

int PlannerPool::jobs_in_flight(std::uint64_t owner) const {
    std::lock_guard lock(mutex_);
    return static_cast<int>(std::count_if(jobs_.begin(), jobs_.end(),
                                          [&](const auto &j) { return j.second.owner == owner; }));
}

int PlannerPool::jobs_in_flight() const {
    std::lock_guard lock(mutex_);
    return static_cast<int>(jobs_.size());
}

void PlannerPool::forget_owner(std::uint64_t owner) {
    std::vector<std::int64_t> ids;
    {
        std::lock_guard lock(mutex_);
        for (const auto &[id, record] : jobs_)
            if (record.owner == owner)
                ids.push_back(id);
        owners_.erase(owner);
        clients_.erase(owner); // the client's service stays: it is the client's history
    }
    forget(ids);
}

PoolCounters PlannerPool::counters() const {
    std::lock_guard lock(mutex_);
    return counters_;
}

PoolCounters PlannerPool::counters(std::uint64_t owner) const {
    std::lock_guard lock(mutex_);
    auto it = owners_.find(owner);
    return it == owners_.end() ? PoolCounters{} : it->second;
}

void PlannerPool::remember_answered(std::int64_t job_id, std::uint64_t owner) {
    constexpr std::size_t REMEMBERED = 65536;
    answered_[job_id] = owner;
    answered_order_.push_back(job_id);
    if (answered_order_.size() > REMEMBERED) {
        answered_.erase(answered_order_.front());
        answered_order_.pop_front();
    }
}

// Sends queued jobs while some live planner has a free slot.
std::vector<envdesign::job_t> PlannerPool::assign(Clock::time_point now) {
    std::vector<envdesign::job_t> out;
    bool contended = this->contended();
    while (!queue_.empty()) {
        auto next = next_fair(contended, now);
        auto planner = pick_planner(jobs_.at(*next), contended, now);
        if (!planner && (next = kept_job(contended, now)) != queue_.end())
            planner = pick_planner(jobs_.at(*next), contended, now);
        if (!planner)
            break;
        JobRecord &record = jobs_.at(*next);
        queue_.erase(next);
        Planner &to = planners_[*planner];
        ++to.holding;
        to.kept_until = {}; // taken: by the client it was kept for, or it expired
        record.planner = *planner;
        record.sent = now;
        record.message.planner = *planner;
        record.message.attempt = static_cast<std::int16_t>(record.tried.size());
        record.message.utime = bus::now_utime();
        PoolCounters &owner = owners_[record.owner];
        if (!record.tried.empty()) {
            ++counters_.jobs_resent;
            ++owner.jobs_resent;
        }
        record.tried.insert(*planner);
        ++counters_.jobs_sent;
        ++owner.jobs_sent;
        out.push_back(record.message);
    }
    if (!queue_.empty())
        withdraw_for_waiting(now, contended);
    return out;
}

void PlannerPool::set_client(std::uint64_t owner, std::uint64_t client) {
    std::lock_guard lock(mutex_);
    clients_[owner] = client;
}

std::uint64_t PlannerPool::client_of(std::uint64_t owner) const {
    auto it = clients_.find(owner);
    return it == clients_.end() ? owner : it->second;
}

// Round robin over planners with a free slot, preferring one that has not had this job;
// demoted planners only when no other has a free slot.
std::optional<std::string> PlannerPool::pick_planner(const JobRecord &record, bool contended,
                                                     Clock::time_point now) {
    std::uint64_t client = client_of(record.owner);
    for (bool demoted : {false, true}) {
        std::optional<std::string> fallback;
        auto start = planners_.upper_bound(last_pick_);
        for (std::size_t i = 0; i < planners_.size(); ++i, ++start) {
            if (start == planners_.end())
                start = planners_.begin();
            const auto &[name, planner] = *start;
            if (!planner.free(contended) || planner.demoted != demoted)
                continue;
            if (planner.kept_until > now && planner.kept_for != client)
                continue; // kept a moment for its last client's next job
            if (!record.tried.count(name)) {
                last_pick_ = name;
                return name;
            }
            if (!fallback)
                fallback = name;
        }
        if (fallback) {
            last_pick_ = *fallback;
            return fallback;
        }
    }
    return std::nullopt;
}

void PlannerPool::requeue(std::int64_t job_id) {
    JobRecord &record = jobs_.at(job_id);
    release(record);
    queue_.push_front(job_id); // resends first: they are the oldest work
}

void PlannerPool::release(JobRecord &record) {
    if (record.planner.empty())
        return;
    if (auto it = planners_.find(record.planner); it != planners_.end() && it->second.holding > 0)
        --it->second.holding;
    record.planner.clear();
}

void PlannerPool::drop_planner(const std::string &name, Events *events, const char *why) {
    if (!planners_.count(name))
        return;
    std::vector<std::int64_t> held;
    for (const auto &[id, record] : jobs_)
        if (record.planner == name)
            held.push_back(id);
    for (std::int64_t id : held)
        requeue(id);
    planners_.erase(name);
    ++counters_.planners_lost;
    if (events)
        events->push_back("planner " + name + " " + why + "; " + std::to_string(held.size()) +
                          " job(s) go to others");
}

} // namespace envdesign::cluster
