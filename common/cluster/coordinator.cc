#include "cluster/coordinator.h"

#include "bus/channels.h"
#include "bus/log.h"
#include "cluster/design_change.h"
#include "cluster/spec_chunks.h"
#include "design/model/numbers.h"
#include "store/state_dir.h"
#include "wire/job_messages.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace envdesign::cluster {
namespace {

using envdesign::design_progress_t;
using envdesign::design_request_t;

std::size_t spec_bytes(const envdesign::spec_t &spec) {
    std::size_t bytes = spec.name.size() + spec.text.size();
    for (const auto &file : spec.files)
        bytes += file.path.size() + file.content.size();
    return bytes;
}

constexpr int MOST_RANKED = 100000; // as `envdesign design --ranking`
// Client names are a host, a program and a process id: 128 bytes is room to spare, and a
// refused name of 30 KB is not echoed back in a result.
constexpr std::size_t MAX_CLIENT_NAME = 128;

bool progress_changed(const design_progress_t &a, const design_progress_t &b) {
    return a.state != b.state || a.done != b.done || a.total != b.total ||
           a.evaluations != b.evaluations || a.best_objective != b.best_objective;
}

} // namespace

std::optional<std::string> request_problem(const design_request_t &r, std::size_t max_spec_bytes) {
    if (r.search != design_request_t::SEARCH_WITNESS &&
        r.search != design_request_t::SEARCH_EXHAUSTIVE)
        return "unknown search " + std::to_string(r.search);
    if (r.prune != design_request_t::PRUNE_NONE && r.prune != design_request_t::PRUNE_RELEVANT)
        return "unknown prune " + std::to_string(r.prune);
    if (r.heuristic < design_request_t::HEURISTIC_LMCUT ||
        r.heuristic > design_request_t::HEURISTIC_BLIND)
        return "unknown heuristic " + std::to_string(r.heuristic);
    if (r.ranking < 0 || r.ranking > MOST_RANKED)
        return "ranking " + std::to_string(r.ranking) + " is not in 0.." +
               std::to_string(MOST_RANKED);
    if (r.ranking_all != 0 && r.ranking_all != 1)
        return "ranking_all " + std::to_string(r.ranking_all) + " is not 0 or 1";
    // < 0: the spec's limit; -inf is no number to send for it.
    if (!std::isfinite(r.time_limit_s) ||
        (r.time_limit_s >= 0 && design::number_problem(r.time_limit_s, design::TIME_LIMIT_S)))
        return "the time limit " + *design::number_problem(r.time_limit_s, design::TIME_LIMIT_S);
    if (r.max_design_size > design::DESIGN_SIZE.high) // < 0: the spec's; 0: no limit
        return "max_design_size " + std::to_string(r.max_design_size) + " is above " +
               std::to_string(static_cast<int>(design::DESIGN_SIZE.high));
    if (r.spec.name.empty())
        return "the spec has no name";
    if (std::size_t bytes = spec_bytes(r.spec); bytes > max_spec_bytes)
        return "the spec and its files are " + std::to_string(bytes) + " bytes, more than the " +
               std::to_string(max_spec_bytes) + " taken";
    return std::nullopt;
}

namespace {

// The evaluation file of config.state_dir, checked (store/state_dir.h); null without a
// state directory. Throws store::StoreError.
std::shared_ptr<store::RecordDb> open_evaluation_file(const CoordinatorConfig &config,
                                                      spdlog::logger &log) {
    if (!config.state_dir.empty() && config.stored_evaluations == 0) {
        log.warn("request - | --state-dir ignored: --stored-evaluations 0 keeps nothing");
        return nullptr;
    }
    store::RecordDbOptions options;
    options.max_records = config.stored_evaluations;
    options.max_bytes = config.state_max_bytes;
    options.sync = config.state_sync;
    options.secrets = config.state_secrets;
    return store::open_state_file(config.state_dir, options, log);
}

} // namespace

Coordinator::Coordinator(bus::Bus &bus, CoordinatorConfig config)
    : bus_(bus), config_(std::move(config)), router_(bus, config_.pool, config_.instance),
      specs_(config_.instance),
      stores_(config_.stored_evaluations, open_evaluation_file(config_, bus.log())),
      status_(bus, "coordinator", config_.instance),
      election_(config_.instance, status_.started_utime(), config_.election, Clock::now(),
                bus.auth_sender()) {
    subscriptions_.push_back(bus_.subscribe<envdesign::service_status_t>(
        bus::STATUS, [this](const envdesign::service_status_t &s) {
            election_.heard(s, Clock::now(), bus_.message_sender());
        }));
    subscriptions_.push_back(bus_.subscribe<design_request_t>(
        bus::REQUEST, [this](const design_request_t &r) { on_request(r); }));
    subscriptions_.push_back(bus_.subscribe<envdesign::cancel_t>(
        bus::CANCEL, [this](const envdesign::cancel_t &c) { on_cancel(c); }));
    subscriptions_.push_back(bus_.subscribe<envdesign::keepalive_t>(
        bus::KEEPALIVE, [this](const envdesign::keepalive_t &k) { on_keepalive(k); }));
    subscriptions_.push_back(bus_.subscribe<envdesign::spec_need_t>(
        bus::SPEC_NEED, [this](const envdesign::spec_need_t &n) { on_spec_need(n); }));
    subscriptions_.push_back(bus_.subscribe<envdesign::evaluation_t>(
        bus::EVALUATION, [this](const envdesign::evaluation_t &e) { router_.on_evaluation(e); }));
    subscriptions_.push_back(bus_.subscribe<envdesign::planner_heartbeat_t>(
        bus::HEARTBEAT,
        [this](const envdesign::planner_heartbeat_t &b) { router_.on_heartbeat(b); }));
}

Coordinator::~Coordinator() {
    subscriptions_.clear();
    for (auto &[name, open] : open_)
        open.run->cancel();
}

void Coordinator::on_request(const design_request_t &request) {
    if (request.sender.empty() || request.request_id == 0) {
        bus_.reject(bus::REQUEST, "a request without client name or request id");
        return;
    }
    if (request.sender.size() > MAX_CLIENT_NAME) { // nothing of it is kept, not even a result
        bus_.reject(bus::REQUEST, "a client name of " + std::to_string(request.sender.size()) +
                                      " bytes, more than " + std::to_string(MAX_CLIENT_NAME));
        return;
    }
    std::string name = bus::request_name(request.sender, request.request_id);
    if (election_.role() == Role::STANDBY) {
        bus_.log().debug("request {} | left to the active coordinator {}", name,
                         election_.active());
        return;
    }
    if (auto it = open_.find(name); it != open_.end()) {
        if (it->second.client_origin == bus_.message_sender())
            it->second.heard = Clock::now(); // its client still asks
        std::lock_guard lock(stats_mutex_);
        ++stats_.repeats;
        // "Still at it"; while discovering it says nothing yet (answer()).
        if (election_.role() == Role::ACTIVE)
            publish_progress(it->second, Clock::now(), true);
        return;
    }
    if (auto it = closed_.find(name); it != closed_.end()) {
        {
            std::lock_guard lock(stats_mutex_);
            ++stats_.repeats;
        }
        bus_.log().info("request {} | repeated; its result is sent again", name);
        publish_result(it->second.result);
        return;
    }
    if (auto problem = request_problem(request, config_.max_spec_bytes)) {
        bus_.reject(bus::REQUEST, name + ": " + *problem);
        auto result = wire::error_result(2, "bad request: " + *problem);
        result.request_id = request.request_id;
        result.client = request.sender;
        answer(std::move(result)); // not kept: a repeat is checked again, as cheaply
        return;
    }
    const std::string client = client_unit(bus_.message_origin(), request.sender);
    if (auto why = busy(client, request.sender)) {
        bus_.log().warn("request {} | refused, busy: {}", name, *why);
        auto result =
            wire::error_result(1, "the coordinator is busy (" + *why + "); try again later");
        result.request_id = request.request_id;
        result.client = request.sender;
        answer(std::move(result)); // not kept: a repeat later may find room
        std::lock_guard lock(stats_mutex_);
        ++stats_.busy;
        return;
    }
    bus_.log().info("request {} | accepted: spec {} with {} file(s)", name, request.spec.name,
                    request.spec.files.size());
    RunContext context{bus_,
                       router_,
                       specs_,
                       config_.grace_s,
                       config_.stored_evaluations > 0 ? &stores_ : nullptr,
                       config_.max_time_limit_s,
                       client};
    open_[name].run = std::make_unique<RequestRun>(context, request);
    open_[name].client = client;
    open_[name].client_origin = bus_.message_sender();
    open_[name].heard = Clock::now();
    waiting_.push_back(name);
    {
        std::lock_guard lock(stats_mutex_);
        ++stats_.accepted;
    }
    start_waiting();
}

std::string client_unit(std::uint64_t origin, const std::string &name) {
    if (origin == 0)
        return "client " + name;
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(origin));
    return std::string("process ") + hex;
}

// Why a new request of `sender` from `client` (its unit) cannot be taken now (nullopt: it can).
std::optional<std::string> Coordinator::busy(const std::string &client,
                                             const std::string &sender) const {
    int of_unit = 0, of_name = 0, active = 0;
    for (const auto &[name, open] : open_) {
        of_unit += open.client == client ? 1 : 0;
        of_name += open.run->request().sender == sender ? 1 : 0;
        active += open.started ? 1 : 0;
    }
    // Both: one process's many names, and one name's many processes (the client library
    // opens a bus, so an origin, per call).
    if (of_unit >= config_.max_per_client || of_name >= config_.max_per_client)
        return std::to_string(std::max(of_unit, of_name)) + " requests of " + sender + " (" +
               client + ") are open, at most " + std::to_string(config_.max_per_client);
    if (active >= config_.max_active && static_cast<int>(waiting_.size()) >= config_.max_waiting)
        return std::to_string(waiting_.size()) + " requests are waiting, at most " +
               std::to_string(config_.max_waiting);
    return std::nullopt;
}

void Coordinator::on_cancel(const envdesign::cancel_t &cancel) {
    std::string name = bus::request_name(cancel.sender, cancel.request_id);
    auto it = open_.find(name);
    if (it == open_.end())
        return; // finished already, or never here
    if (it->second.client_origin != bus_.message_sender()) {
        // Only the process that sent the request may cancel it (with keys, the name alone
        // could be claimed by any key holder's process).
        bus_.reject(bus::CANCEL, "request " + name + ": a cancel from another process");
        return;
    }
    bus_.log().info("request {} | cancelled by the client: {}", name, cancel.reason);
    it->second.run->cancel();
}

void Coordinator::on_keepalive(const envdesign::keepalive_t &keepalive) {
    auto it = open_.find(bus::request_name(keepalive.sender, keepalive.request_id));
    if (it == open_.end())
        return; // finished, dropped, or another coordinator's
    if (it->second.client_origin != bus_.message_sender()) {
        // As a cancel: only the process that sent the request keeps it alive.
        bus_.reject(bus::KEEPALIVE, "request " + it->first + ": a keepalive from another process");
        return;
    }
    it->second.heard = Clock::now();
}

// Requests whose client went silent serve no one: a searching one is cancelled (its result
// goes out and is kept as any other), a waiting one is forgotten.
void Coordinator::drop_silent(Clock::time_point now) {
    auto silent = now - std::chrono::duration_cast<Clock::duration>(
                            std::chrono::duration<double>(config_.client_timeout_s));
    for (auto it = open_.begin(); it != open_.end();) {
        Open &open = it->second;
        if (open.dropped || open.heard >= silent) {
            ++it;
            continue;
        }
        bus_.log().warn("request {} | dropped: nothing heard from its client in {:g} s", it->first,
                        config_.client_timeout_s);
        {
            std::lock_guard lock(stats_mutex_);
            ++stats_.dropped;
        }
        if (open.started) {
            open.dropped = true;
            open.run->cancel(); // its jobs are withdrawn from the planners (job_router.h)
            ++it;
            continue;
        }
        waiting_.erase(std::find(waiting_.begin(), waiting_.end(), it->first));
        it = open_.erase(it);
    }
}

void Coordinator::on_spec_need(const envdesign::spec_need_t &need) {
    if (need.coordinator != config_.instance)
        return;
    auto chunks =
        specs_.need(need.spec_hash, std::vector<int>(need.missing.begin(), need.missing.end()),
                    need.request_id, Clock::now());
    if (!chunks.empty())
        bus_.log().info("request {} | {} chunk(s) of spec {} sent to {}", need.request_id,
                        chunks.size(), need.spec_hash.substr(0, 12), need.sender);
    for (const auto &chunk : chunks)
        bus_.publish(bus::SPEC, chunk);
}

int Coordinator::tick() {
    // Results and starts at once: they are the latency a client sees.
    close_finished();
    start_waiting();
    bool searching = std::any_of(open_.begin(), open_.end(),
                                 [](const auto &open) { return open.second.started; });
    int wait_ms = searching ? 1 : 20;
    auto now = Clock::now();
    if (now - last_tick_ < std::chrono::milliseconds(5))
        return wait_ms; // the loop calls after every message; housekeeping needs less
    last_tick_ = now;
    elect(now);
    drop_silent(now);
    router_.tick();
    status_.tick([this](envdesign::service_status_t &s) { fill_status(s); });
    report_bad_records();
    for (auto &[name, open] : open_)
        if (open.started) // waiting ones are told when their client repeats them
            publish_progress(open, now, false);
    auto expired = now - std::chrono::duration_cast<Clock::duration>(
                             std::chrono::duration<double>(config_.keep_results_s));
    std::erase_if(closed_, [&](const auto &entry) { return entry.second.at < expired; });
    return wait_ms;
}

CoordinatorStats Coordinator::stats() const {
    std::lock_guard lock(stats_mutex_);
    return stats_;
}

// Steps down when a coordinator that started earlier is heard: what was open here is
// dropped unanswered, since that one heard the same requests (election.h).
void Coordinator::elect(Clock::time_point now) {
    auto change = election_.update(now);
    if (!change)
        return;
    if (election_.role() != Role::STANDBY) {
        bus_.log().info("request - | {}", *change);
        if (election_.role() == Role::ACTIVE)
            for (auto &result : std::exchange(held_, {}))
                publish_result(std::move(result));
        return;
    }
    bus_.log().warn("request - | {}; {} request(s) open here are left to it", *change,
                    open_.size());
    held_.clear();
    waiting_.clear();
    open_.clear(); // cancels and joins the searches; no result goes out
    std::lock_guard lock(stats_mutex_);
    stats_.open = 0;
}

// Fair between clients: the next to start is the oldest waiting request of the client with
// the fewest requests searching, so a client's requests wait behind its own.
void Coordinator::start_waiting() {
    int active = 0;
    std::map<std::string, int> searching; // by client
    for (const auto &[name, open] : open_)
        if (open.started) {
            ++active;
            ++searching[open.client];
        }
    while (election_.role() == Role::ACTIVE && active < config_.max_active && !waiting_.empty()) {
        auto next = waiting_.begin();
        for (auto it = waiting_.begin(); it != waiting_.end(); ++it)
            if (searching[open_.at(*it).client] < searching[open_.at(*next).client])
                next = it;
        Open &open = open_.at(*next);
        waiting_.erase(next);
        ++searching[open.client];
        open.run->start();
        open.started = true;
        ++active;
    }
    std::lock_guard lock(stats_mutex_);
    stats_.open = static_cast<int>(open_.size());
}

void Coordinator::close_finished() {
    for (auto it = open_.begin(); it != open_.end();) {
        if (!it->second.run->finished()) {
            ++it;
            continue;
        }
        publish_progress(it->second, Clock::now(), true); // the final count, state DONE
        envdesign::design_result_t result = it->second.run->result();
        note_change(it->second.run->request(), result);
        closed_[it->first] = {result, Clock::now()};
        it = open_.erase(it); // joins the finished thread
        publish_result(std::move(result));
    }
}

// A request with a reason (a re-evaluation) gets what changed since its client's last
// result for the same spec, and why.
void Coordinator::note_change(const design_request_t &request, envdesign::design_result_t &result) {
    if (request.reason.empty() || result.status == "error")
        return;
    std::string key = request.sender + '\n' + request.spec.name;
    auto before = last_designs_.find(key);
    result.change =
        design_change(before == last_designs_.end() ? nullptr : &before->second, result) + ": " +
        request.reason;
    if (result.has_design)
        last_designs_[key] = result.design;
    bus_.log().info("request {} | {}", bus::request_name(request.sender, request.request_id),
                    result.change);
}

void Coordinator::publish_progress(Open &open, Clock::time_point now, bool force) {
    design_progress_t p = open.run->progress();
    auto since = std::chrono::duration<double>(now - open.last_progress).count();
    bool due = since >= config_.keepalive_s ||
               (since >= config_.progress_interval_s && progress_changed(p, open.last_sent));
    if (!force && !due)
        return;
    p.utime = bus::now_utime();
    p.sender = config_.instance;
    p.planners = static_cast<std::int16_t>(router_.pool().live_planners());
    bus_.publish(bus::PROGRESS, p);
    open.last_progress = now;
    open.last_sent = p;
}

// Records of the state file whose tag or values failed their check were deleted, never used
// (store/record_db.h): said once per new batch, and counted in the status.
void Coordinator::report_bad_records() {
    const auto &db = stores_.db();
    long long rejected = db ? db->rejected() : 0;
    if (rejected == bad_records_reported_)
        return;
    bus_.log().warn("request - | {} record(s) of {} failed their check (tag or values) and were "
                    "deleted; they will be planned again",
                    rejected - bad_records_reported_, db->path());
    bad_records_reported_ = rejected;
}

void Coordinator::fill_status(envdesign::service_status_t &status) const {
    status.requests_waiting = static_cast<std::int32_t>(waiting_.size());
    status.requests_open = static_cast<std::int32_t>(open_.size()) - status.requests_waiting;
    status.planners = router_.pool().live_planners();
    status.jobs_in_flight = router_.pool().jobs_in_flight();
    status.stored_evaluations = static_cast<std::int64_t>(stores_.records());
    status.role = to_string(election_.role());
    if (bad_records_reported_ > 0)
        bus::add_drop(status, "store:evaluations.db", "bad-record", bad_records_reported_);
    std::lock_guard lock(stats_mutex_);
    status.jobs_done = stats_.results;
}

// While discovering, another coordinator may be answering: what this one would say waits
// until it knows it is active (and goes when it stands by), one answer a request however
// often its client re-sends it. Beyond max_waiting held answers the client's re-send asks
// again.
void Coordinator::answer(envdesign::design_result_t result) {
    if (election_.role() == Role::ACTIVE) {
        publish_result(std::move(result));
        return;
    }
    auto same = std::find_if(held_.begin(), held_.end(), [&](const auto &held) {
        return held.request_id == result.request_id && held.client == result.client;
    });
    if (same != held_.end())
        *same = std::move(result);
    else if (static_cast<int>(held_.size()) < config_.max_waiting)
        held_.push_back(std::move(result));
}

void Coordinator::publish_result(envdesign::design_result_t result) {
    result.utime = bus::now_utime();
    result.sender = config_.instance;
    bus_.publish(bus::RESULT, result);
    std::lock_guard lock(stats_mutex_);
    ++stats_.results;
}

} // namespace envdesign::cluster
