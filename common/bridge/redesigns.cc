#include "bridge/redesigns.h"

#include "bridge/spec_request.h"

#include "bus/channels.h"
#include "bus/log.h"
#include "cluster/design_change.h"
#include "envdesign/design_request_t.hpp"
#include "envdesign/keepalive_t.hpp"
#include "pddl/parse_error.h"
#include "wire/job_messages.h"

#include <cmath>
#include <limits>

namespace envdesign::bridge {
namespace {

constexpr double NOT_KNOWN = std::numeric_limits<double>::quiet_NaN();

} // namespace

RedesignBackend::~RedesignBackend() = default;

void RedesignBackend::on_result(const envdesign::design_result_t &) {}
void RedesignBackend::on_progress(const envdesign::design_progress_t &) {}
void RedesignBackend::tick(double) {}

LocalRedesigns::LocalRedesigns(bus::Bus &bus, std::string instance,
                               std::map<std::string, design::DesignProblem> problems,
                               arrivals::RedesignOptions options, Answered answered)
    : bus_(bus), instance_(std::move(instance)), answered_(std::move(answered)) {
    for (auto &[id, problem] : problems)
        redesigners_[id] = std::make_unique<arrivals::Redesigner>(std::move(problem), options);
    thread_ = std::thread([this] { run(); });
}

LocalRedesigns::~LocalRedesigns() {
    jobs_.close(concurrency::Leftovers::drop); // the running redesign finishes, no other
    thread_.join();
}

void LocalRedesigns::start(std::int64_t request_id, const arrivals::Request &request) {
    jobs_.push({request_id, request});
}

void LocalRedesigns::reweigh(std::int64_t request_id, const arrivals::Request &request) {
    jobs_.replace_or_push({request_id, request, true}, [&](const Job &queued) {
        return queued.reweigh && queued.request.problem_id == request.problem_id;
    });
}

void LocalRedesigns::run() {
    while (auto job = jobs_.pop()) {
        if (job->reweigh)
            reweigh(*job);
        else
            redesign(*job);
    }
}

void LocalRedesigns::reweigh(const Job &job) {
    const std::string &id = job.request.problem_id;
    arrivals::Redesigner &r = *redesigners_.at(id);
    Answer answer{id, job.request_id, std::nullopt, {}, true, false};
    try {
        if (auto out = r.reweigh(job.request.estimate)) {
            answer.reference = r.distribution();
            answer.changed = out->change.changed;
            answer.design = {out->change.after_names, out->change.objective_after,
                             "re-weighted: " + out->change.explanation, job.request_id};
            if (answer.changed) {
                envdesign::design_result_t message = wire::result_message(r.problem(), *out);
                message.change = answer.design.last_change;
                message.utime = bus::now_utime();
                message.request_id = job.request_id;
                message.sender = message.client = instance_;
                bus_.publish(bus::RESULT, message);
                bus_.log().info("request {} | {}: re-weighted: {} (0 planner runs, {} "
                                "configurations from the store, {:.3f} ms)",
                                bus::request_name(instance_, job.request_id), id,
                                out->change.explanation, out->change.stored_answers,
                                out->change.seconds * 1e3);
            }
        }
    } catch (const std::exception &e) { // the design in force stays; the drift path retries
        bus_.log().error("request {} | {}: re-weighting failed: {}",
                         bus::request_name(instance_, job.request_id), id, e.what());
    }
    answered_(std::move(answer));
}

void LocalRedesigns::redesign(const Job &job) {
    const std::string &id = job.request.problem_id;
    arrivals::Redesigner &r = *redesigners_.at(id);
    envdesign::design_result_t message;
    Answer answer{id, job.request_id, std::nullopt, {}};
    try {
        arrivals::Redesign out = r.redesign(job.request.estimate, job.request.new_tasks);
        message = wire::result_message(r.problem(), out);
        message.change = out.change.explanation + "; " + arrivals::describe(job.request);
        answer.design = {out.change.after_names, out.change.objective_after, out.change.explanation,
                         job.request_id};
        answer.reference = r.distribution();
        bus_.log().info("request {} | {}: {} ({} planner runs, {} configurations from the store, "
                        "{:.3f} ms)",
                        bus::request_name(instance_, job.request_id), id, out.change.explanation,
                        out.change.planner_runs, out.change.stored_answers,
                        out.change.seconds * 1e3);
    } catch (const std::exception &e) { // a spec model that does not ground: keep the design
        message = wire::error_result(dynamic_cast<const pddl::ParseError *>(&e) ? 2 : 1, e.what());
        answer.design = {
            {}, NOT_KNOWN, std::string("re-evaluation failed: ") + e.what(), job.request_id};
        bus_.log().error("request {} | {}: {}", bus::request_name(instance_, job.request_id), id,
                         e.what());
    }
    if (r.current())
        answer.design.design = design::design_names(r.problem(), r.current()->ranked.configuration);
    message.utime = bus::now_utime();
    message.request_id = job.request_id;
    message.sender = instance_;
    message.client = instance_;
    bus_.publish(bus::RESULT, message);
    answered_(std::move(answer));
}

CoordinatorRedesigns::CoordinatorRedesigns(bus::Bus &bus, std::string instance,
                                           std::map<std::string, envdesign::spec_t> specs,
                                           std::map<std::string, design::DesignProblem> problems,
                                           CoordinatorRequestOptions options, Answered answered)
    : bus_(bus), instance_(std::move(instance)), options_(options), answered_(std::move(answered)),
      specs_(std::move(specs)), problems_(std::move(problems)) {}

void CoordinatorRedesigns::start(std::int64_t request_id, const arrivals::Request &request) {
    envdesign::design_request_t m{};
    std::vector<arrivals::NewTask> good;
    for (const auto &task : request.new_tasks) {
        try {
            arrivals::parse_new_task(problems_.at(request.problem_id), task);
            good.push_back(task);
        } catch (const pddl::ParseError &e) { // the answer will lack it: refused
            bus_.log().warn("request {} | {}: new task refused: {}",
                            bus::request_name(instance_, request_id), request.problem_id, e.what());
        }
    }
    m.request_id = request_id;
    m.sender = instance_;
    m.time_limit_s = options_.time_limit_s;
    m.max_design_size = -1;
    m.prune = envdesign::design_request_t::PRUNE_NONE;
    m.heuristic = options_.heuristic;
    m.reason = arrivals::describe(request);
    m.utime = bus::now_utime();
    {
        std::lock_guard lock(mutex_);
        m.spec = with_distribution(specs_.at(request.problem_id), request.estimate, good);
        // The bridge asks again only after giving up on the last request (--answer-timeout):
        // a late answer to that one must not replace the design for this newer D.
        std::erase_if(pending_,
                      [&](const auto &p) { return p.second.problem_id == request.problem_id; });
        pending_[request_id] = {request.problem_id, m, now_s_, now_s_};
    }
    bus_.publish(bus::REQUEST, m);
}

void CoordinatorRedesigns::on_progress(const envdesign::design_progress_t &progress) {
    std::lock_guard lock(mutex_);
    if (auto it = pending_.find(progress.request_id);
        progress.client == instance_ && it != pending_.end())
        it->second.heard_at = now_s_;
}

void CoordinatorRedesigns::tick(double now_s) {
    std::vector<envdesign::design_request_t> again;
    std::vector<std::int64_t> waiting; // kept alive (a repeat says it too)
    {
        std::lock_guard lock(mutex_);
        now_s_ = now_s;
        for (auto &[id, pending] : pending_) {
            if (now_s - pending.heard_at >= options_.resend_after_s) {
                pending.heard_at = pending.kept_alive_at = now_s;
                pending.request.utime = bus::now_utime();
                again.push_back(pending.request);
            } else if (now_s - pending.kept_alive_at >= bus::CLIENT_KEEPALIVE_S) {
                pending.kept_alive_at = now_s;
                waiting.push_back(id);
            }
        }
    }
    for (std::int64_t id : waiting) {
        envdesign::keepalive_t keepalive{};
        keepalive.utime = bus::now_utime();
        keepalive.request_id = id;
        keepalive.sender = instance_;
        bus_.publish(bus::KEEPALIVE, keepalive);
    }
    for (const auto &request : again) {
        bus_.publish(bus::REQUEST, request);
        bus_.log().info("request {} | no word from a coordinator in {:g} s: sent again",
                        bus::request_name(instance_, request.request_id), options_.resend_after_s);
    }
}

void CoordinatorRedesigns::on_result(const envdesign::design_result_t &result) {
    Answer answer;
    {
        std::lock_guard lock(mutex_);
        if (result.client != instance_)
            return; // another client's
        auto it = pending_.find(result.request_id);
        if (it == pending_.end()) {
            bus_.log().info("request {} | answer ignored: the request was answered before or "
                            "asked again since",
                            bus::request_name(instance_, result.request_id));
            return;
        }
        Pending pending = std::move(it->second);
        pending_.erase(it);
        const std::string &id = pending.problem_id;
        answer = {id, result.request_id, std::nullopt, {}};
        std::vector<std::string> &before = designs_[id];
        if (!result.has_design) {
            answer.design = {before, NOT_KNOWN,
                             "the coordinator gave no design (" + result.status +
                                 "): " + result.error,
                             result.request_id};
        } else {
            specs_[id] = pending.request.spec; // the new tasks are the problem's now
            answer.reference = references_[id] = distribution_of(result);
            bool first = answered_once_.insert(id).second;
            std::string what = cluster::design_change(first ? nullptr : &before, result);
            answer.design = {result.design, result.best.objective,
                             what + " for D " + arrivals::to_string(references_[id]) + " (" +
                                 std::to_string(result.counters.planner_runs) +
                                 " planner runs and " +
                                 std::to_string(result.counters.stored_answers) +
                                 " configurations from stored evaluations on the coordinator)",
                             result.request_id};
            before = result.design;
        }
    }
    answered_(std::move(answer));
}

} // namespace envdesign::bridge
