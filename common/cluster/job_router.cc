#include "cluster/job_router.h"

#include "bus/channels.h"
#include "bus/log.h"
#include "wire/job_messages.h"

#include <functional>
#include <random>

namespace envdesign::cluster {

namespace {

// Job ids start at a random point so that ids of a restarted coordinator (or of another
// one on the same bus) do not meet the old ones in a planner's memory of answers.
std::int64_t first_job_id() {
    std::random_device random;
    std::uint64_t high = (static_cast<std::uint64_t>(random()) & 0x3fffff) << 40;
    return static_cast<std::int64_t>(high | 1);
}

} // namespace

JobRouter::JobRouter(bus::Bus &bus, PoolConfig config, std::string instance)
    : bus_(bus), pool_(config), instance_(std::move(instance)), next_job_id_(first_job_id()) {}

std::uint64_t JobRouter::open(Inbox &inbox, const std::string &client) {
    std::uint64_t owner = next_owner_++;
    if (!client.empty())
        pool_.set_client(owner, std::hash<std::string>{}(client));
    std::lock_guard lock(inboxes_mutex_);
    inboxes_[owner] = &inbox;
    return owner;
}

void JobRouter::close(std::uint64_t owner) {
    {
        std::lock_guard lock(inboxes_mutex_);
        inboxes_.erase(owner);
    }
    pool_.forget_owner(owner);
    publish({}); // the withdrawals of its jobs still held
}

void JobRouter::forget(const std::vector<std::int64_t> &job_ids) {
    pool_.forget(job_ids);
    publish({});
}

std::int64_t JobRouter::send(std::uint64_t owner, envdesign::job_t job) {
    job.job_id = next_job_id_++;
    job.sender = instance_;
    std::int64_t id = job.job_id;
    publish(pool_.submit(owner, std::move(job), PlannerPool::Clock::now()));
    return id;
}

void JobRouter::on_evaluation(const envdesign::evaluation_t &answer) {
    if (answer.coordinator != instance_)
        return; // another coordinator's
    if (!pool_.sent_to(answer.job_id, answer.sender)) {
        bus_.reject(bus::EVALUATION, "job " + std::to_string(answer.job_id) + " answered by " +
                                         answer.sender + ", which it was not sent to");
        return;
    }
    auto kind = pool_.kind_of(answer.job_id);
    if (kind) {
        if (auto problem = wire::evaluation_problem(answer, *kind)) {
            bus_.reject(bus::EVALUATION, "job " + std::to_string(answer.job_id) + " from " +
                                             answer.sender + ": " + *problem);
            return; // the job stays out; a resend will ask again
        }
    }
    bus_.log().debug("request {} | job {} answered by {}: {:.3f} s planning, {:.3f} s queued",
                     answer.request_id, answer.job_id, answer.sender, answer.seconds,
                     answer.queued_seconds);
    std::vector<envdesign::job_t> to_send;
    auto record = pool_.answer(answer.job_id, answer.sender, to_send, PlannerPool::Clock::now());
    publish(to_send);
    if (!record) {
        bus_.log().debug("request {} | duplicate answer to job {} from {} ignored",
                         answer.request_id, answer.job_id, answer.sender);
        return;
    }
    std::lock_guard lock(inboxes_mutex_);
    if (auto it = inboxes_.find(record->owner); it != inboxes_.end())
        it->second->push(answer);
}

void JobRouter::on_heartbeat(const envdesign::planner_heartbeat_t &beat) {
    if (auto why = heartbeat_problem(beat)) {
        bus_.reject(bus::HEARTBEAT,
                    "a heartbeat from '" + beat.sender.substr(0, 64) + "' not used: " + *why);
        return;
    }
    PlannerPool::Events events;
    publish(pool_.heartbeat(beat, PlannerPool::Clock::now(), &events));
    log_events(events);
}

void JobRouter::tick() {
    PlannerPool::Events events;
    publish(pool_.expire(PlannerPool::Clock::now(), &events));
    log_events(events);
}

void JobRouter::publish(const std::vector<envdesign::job_t> &jobs) {
    for (const auto &job : pool_.take_withdrawals()) {
        bus_.log().info("request {} | job {} withdrawn from {} (its slot goes to a request "
                        "that had none, or its request stopped waiting)",
                        job.request_id, job.job_id, job.planner);
        bus_.publish(bus::WITHDRAW, job);
    }
    for (const auto &job : jobs) {
        if (job.attempt > 0)
            bus_.log().info("request {} | job {} re-sent to {} (attempt {})", job.request_id,
                            job.job_id, job.planner, job.attempt);
        else
            bus_.log().debug("request {} | job {} sent to {}", job.request_id, job.job_id,
                             job.planner);
        bus_.publish(bus::JOB, job);
    }
}

void JobRouter::log_events(const PlannerPool::Events &events) {
    for (const auto &event : events)
        bus_.log().info("request - | {}", event);
}

} // namespace envdesign::cluster
