#pragma once
// Who re-evaluates a design problem for the bridge, behind one interface:
//   - LocalRedesigns (--redesign local): in the bridge's own process, on one worker thread,
//     with a Redesigner per problem (arrivals/redesign.h): evaluations are stored, so a new
//     D is a re-weighting; it publishes the design_result_t on ENVDESIGN_RESULT itself.
//   - CoordinatorRedesigns (--redesign coordinator): sends the spec with the new D (and the
//     new tasks) to envdesign-coordinator as a design request on ENVDESIGN_REQUEST and takes
//     the coordinator's ENVDESIGN_RESULT as the answer, saying it still waits every 2 s
//     (ENVDESIGN_KEEPALIVE; a superseded request is no longer kept alive, so the
//     coordinator drops it). A request for a problem supersedes
//     the one still pending for it (the bridge gave up on that one): a late answer to the
//     older request is ignored, never taken as the design in force.
// Either way the bridge hears back through `Answered` (from any thread).

#include "bridge/messages.h"

#include "arrivals/redesign.h"
#include "bus/bus.h"
#include "concurrency/blocking_queue.h"
#include "envdesign/design_progress_t.hpp"
#include "envdesign/design_request_t.hpp"
#include "envdesign/design_result_t.hpp"
#include "envdesign/spec_t.hpp"

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <thread>

namespace envdesign::bridge {

struct Answer {
    std::string problem_id;
    std::int64_t request_id = 0;
    // The D the design in force was made for; unset: no new design (the re-evaluation
    // failed), the old one stays.
    std::optional<arrivals::Distribution> reference;
    DesignInForce design;
    // A re-weighting's answer (LocalRedesigns::reweigh): `reference` set when it proved its
    // design optimal, unset when it needs planners; `changed`: the design differs.
    bool reweigh = false;
    bool changed = false;
};
using Answered = std::function<void(Answer)>;

class RedesignBackend {
public:
    virtual ~RedesignBackend();
    // Starts re-evaluating `request.problem_id` for `request.estimate`; answers later.
    virtual void start(std::int64_t request_id, const arrivals::Request &request) = 0;
    // A design_result_t heard on ENVDESIGN_RESULT (bus thread).
    virtual void on_result(const envdesign::design_result_t &result);
    // A design_progress_t heard on ENVDESIGN_PROGRESS (bus thread).
    virtual void on_progress(const envdesign::design_progress_t &progress);
    // The bridge's clock, seconds, from the bus thread a few times a second.
    virtual void tick(double now_s);
};

class LocalRedesigns : public RedesignBackend {
public:
    // `bus` and `log` must outlive this; `answered` is called on the worker thread.
    LocalRedesigns(bus::Bus &bus, std::string instance,
                   std::map<std::string, design::DesignProblem> problems,
                   arrivals::RedesignOptions options, Answered answered);
    ~LocalRedesigns() override; // finishes the running redesign, drops the queued ones

    void start(std::int64_t request_id, const arrivals::Request &request) override;
    // Re-weighs stored evaluations for `request.estimate` (Redesigner::reweigh) after the
    // jobs queued before it; replaces a re-weighting of the same problem still queued (only
    // the latest estimate matters). Publishes a result only when the design changes.
    void reweigh(std::int64_t request_id, const arrivals::Request &request);

private:
    struct Job {
        std::int64_t request_id;
        arrivals::Request request;
        bool reweigh = false;
    };
    void run();
    void redesign(const Job &job);
    void reweigh(const Job &job);

    bus::Bus &bus_;
    std::string instance_;
    Answered answered_;
    std::map<std::string, std::unique_ptr<arrivals::Redesigner>> redesigners_;
    concurrency::BlockingQueue<Job> jobs_;
    std::thread thread_; // last: starts once the rest exists
};

struct CoordinatorRequestOptions {
    std::int8_t heuristic = 0; // design_request_t::HEURISTIC_*
    double time_limit_s = -1;  // < 0: the spec's
    // A pending request the coordinator has said nothing about (no progress, no result) for
    // this long is sent again, as the client does: the request, or all that the coordinator
    // said, was lost (or no coordinator listened yet). The coordinator answers a repeat
    // with its progress or its result, never with a second search.
    double resend_after_s = 3;
};

class CoordinatorRedesigns : public RedesignBackend {
public:
    // `specs`: each problem's spec file with its files inlined (spec_request.h); `problems`:
    // the same loaded, to check new tasks before they go out (one bad task would make the
    // coordinator refuse the whole request).
    CoordinatorRedesigns(bus::Bus &bus, std::string instance,
                         std::map<std::string, envdesign::spec_t> specs,
                         std::map<std::string, design::DesignProblem> problems,
                         CoordinatorRequestOptions options, Answered answered);

    void start(std::int64_t request_id, const arrivals::Request &request) override;
    void on_result(const envdesign::design_result_t &result) override;
    void on_progress(const envdesign::design_progress_t &progress) override;
    void tick(double now_s) override;

private:
    struct Pending {
        std::string problem_id;
        envdesign::design_request_t request; // as sent: its spec has the new tasks
        double heard_at = 0;                 // sent, or the coordinator said something of it
        double kept_alive_at = 0;            // sent, or a keepalive_t said we still wait
    };

    bus::Bus &bus_;
    std::string instance_;
    CoordinatorRequestOptions options_;
    Answered answered_;
    std::mutex mutex_; // start() on the DDS thread, on_result() on the bus thread
    std::map<std::string, envdesign::spec_t> specs_;           // with new tasks taken in
    std::map<std::string, design::DesignProblem> problems_;    // for checking new tasks
    std::map<std::string, std::vector<std::string>> designs_;  // the last design per problem
    std::map<std::string, arrivals::Distribution> references_; // its D
    std::map<std::int64_t, Pending> pending_;
    std::set<std::string> answered_once_; // problems with a design
    double now_s_ = 0;                    // the last tick's
};

} // namespace envdesign::bridge
