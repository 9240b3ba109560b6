// PlannerPool's side of the fair shares (planner_pool.h, fair_share.h): which queued job
// goes next, which held jobs are withdrawn for a waiting client, and the slots kept a moment
// for a client's next job.

#include "cluster/planner_pool.h"

#include <algorithm>
#include <tuple>

namespace envdesign::cluster {

// A freed slot waits anticipate_s for `client`'s job (0: for no one).
void PlannerPool::keep_for(Planner &planner, std::uint64_t client, Clock::time_point now) {
    if (client == 0)
        return;
    planner.kept_for = client;
    planner.kept_until = now + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double>(config_.anticipate_s));
}

// The oldest queued job of a client a free slot is kept for (anticipate_s); end() if none.
std::deque<std::int64_t>::iterator PlannerPool::kept_job(bool contended, Clock::time_point now) {
    std::set<std::uint64_t> kept;
    for (const auto &[name, planner] : planners_)
        if (planner.kept_until > now && planner.free(contended))
            kept.insert(planner.kept_for);
    return std::find_if(queue_.begin(), queue_.end(), [&](std::int64_t id) {
        return kept.count(client_of(jobs_.at(id).owner)) > 0;
    });
}

// What the fair shares are decided on: while clients contend a planner's slots are its
// workers (planner_pool.h), and a slot withdrawn for a client is on its way to it.
FairShare::View PlannerPool::fair_view(bool contended, Clock::time_point now) const {
    FairShare::View view;
    view.now = now;
    view.slots = 0;
    for (const auto &[name, planner] : planners_) {
        view.slots += contended ? planner.workers : planner.slots;
        for (const auto &[job, taker] : planner.withdrawn)
            if (taker != 0)
                ++view.incoming[taker];
    }
    for (std::int64_t id : queue_)
        view.queued.push_back(client_of(jobs_.at(id).owner));
    for (const auto &[id, record] : jobs_)
        if (!record.planner.empty())
            view.running.push_back({id, client_of(record.owner),
                                    std::chrono::duration<double>(now - record.sent).count(),
                                    record.preemptions});
    return view;
}

std::deque<std::int64_t>::iterator PlannerPool::next_fair(bool contended, Clock::time_point now) {
    return queue_.begin() + static_cast<std::ptrdiff_t>(fair_.next(fair_view(contended, now)));
}

bool PlannerPool::contended() const {
    std::optional<std::uint64_t> first;
    for (const auto &[id, record] : jobs_) {
        std::uint64_t client = client_of(record.owner);
        if (first && *first != client)
            return true;
        first = client;
    }
    return false;
}

// No slot is free and jobs wait: withdraw the jobs that give waiting clients the slots the
// fair shares say are theirs (fair_share.h). A withdrawn job's slot frees when its planner
// lets go of it, so the withdrawals still pending count as slots on the way to their takers.
void PlannerPool::withdraw_for_waiting(Clock::time_point now, bool contended) {
    for (std::size_t held = jobs_.size(); held > 0; --held) { // each job yields at most once
        auto taken = fair_.victim(fair_view(contended, now));
        if (!taken)
            return;
        std::string from = jobs_.at(taken->job).planner;
        withdraw(taken->job, taken->client, now);
        if (contended)
            withdraw_queued(from);
    }
}

// While clients contend a planner's slots are its workers: the jobs it was sent beyond them
// (queued behind a running one, jobs_per_slot) are withdrawn too, or the slot withdrawn for
// a waiting client would not free. They have not run: nothing of them is lost.
void PlannerPool::withdraw_queued(const std::string &name) {
    Planner &planner = planners_.at(name);
    std::vector<JobRecord *> held;
    for (auto &[id, record] : jobs_)
        if (record.planner == name)
            held.push_back(&record);
    std::sort(held.begin(), held.end(), [](const JobRecord *a, const JobRecord *b) {
        return std::tie(a->sent, a->message.job_id) > std::tie(b->sent, b->message.job_id);
    });
    for (JobRecord *record : held) {
        if (planner.holding + static_cast<int>(planner.overdue.size()) < planner.workers)
            break;
        std::int64_t id = record->message.job_id;
        planner.withdrawn.emplace(id, 0);
        ++counters_.withdrawn;
        withdrawals_.push_back(record->message);
        requeue(id);
    }
}

void PlannerPool::withdraw(std::int64_t id, std::uint64_t taker, Clock::time_point now) {
    JobRecord &record = jobs_.at(id);
    planners_.at(record.planner).withdrawn.emplace(id, taker);
    ++record.preemptions;
    ++counters_.withdrawn;
    fair_.add_service(client_of(record.owner),
                      std::chrono::duration<double>(now - record.sent).count(), now);
    withdrawals_.push_back(record.message);
    requeue(id);
    queue_.erase(std::find(queue_.begin(), queue_.end(), id));
    queue_.push_back(id); // behind the waiting work it yielded to
}

std::vector<envdesign::job_t> PlannerPool::take_withdrawals() {
    std::lock_guard lock(mutex_);
    return std::exchange(withdrawals_, {});
}

} // namespace envdesign::cluster
