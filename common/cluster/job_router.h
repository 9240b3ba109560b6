#pragma once
// The coordinator's side of the planner channels, shared by all requests it serves: jobs go
// out through one PlannerPool (planner_pool.h), answers come back on the bus thread and are
// routed to the Inbox of the request whose job they answer. The search threads of several
// requests send through one JobRouter at once.
//
//   Inbox inbox;                                   // a request's search thread
//   std::uint64_t owner = router.open(inbox);
//   std::int64_t id = router.send(owner, job);     // publishes when a planner slot is free
//   auto answer = inbox.pop_until(deadline);       // (job_id, evaluation_t)
//   router.close(owner);

#include "bus/bus.h"
#include "cluster/planner_pool.h"
#include "concurrency/blocking_queue.h"
#include "envdesign/evaluation_t.hpp"

#include <atomic>
#include <map>
#include <mutex>
#include <optional>
#include <string>

namespace envdesign::cluster {

// Answers for one request, from the bus thread to its search thread: pop_until(deadline)
// returns nullopt once the deadline passed or wake() was called.
using Inbox = concurrency::BlockingQueue<envdesign::evaluation_t>;

class JobRouter {
public:
    // `instance`: this coordinator's name; jobs carry it and answers must name it.
    JobRouter(bus::Bus &bus, PoolConfig config, std::string instance);

    // A new owner of jobs (a request) whose answers go to `inbox`; `client` is the unit of the
    // planners' fair shares it counts for (fair_share.h: its process or its name).
    std::uint64_t open(Inbox &inbox, const std::string &client = "");
    void close(std::uint64_t owner);
    // Sends `job` (request_id, spec and content filled) for `owner`; returns its job_id.
    std::int64_t send(std::uint64_t owner, envdesign::job_t job);
    // Stops waiting for these jobs; planners holding them are told to stop (WITHDRAW).
    void forget(const std::vector<std::int64_t> &job_ids);

    // Bus thread.
    void on_evaluation(const envdesign::evaluation_t &answer);
    void on_heartbeat(const envdesign::planner_heartbeat_t &beat);
    void tick();

    const PlannerPool &pool() const { return pool_; }
    const std::string &instance() const { return instance_; }

private:
    void publish(const std::vector<envdesign::job_t> &jobs);
    void log_events(const PlannerPool::Events &events);

    bus::Bus &bus_;
    PlannerPool pool_;
    std::string instance_;
    std::atomic<std::int64_t> next_job_id_;
    std::atomic<std::uint64_t> next_owner_{1};
    std::mutex inboxes_mutex_;
    std::map<std::uint64_t, Inbox *> inboxes_;
};

} // namespace envdesign::cluster
