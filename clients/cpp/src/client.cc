#include "envdesign/client/client.h"

#include "bus/bus.h"
#include "bus/channels.h"
#include "bus/lcm_url.h"
#include "bus/log.h"
#include "bus/status.h"
#include "client_bus.h"
#include "envdesign/cancel_t.hpp"
#include "envdesign/design_progress_t.hpp"
#include "envdesign/design_request_t.hpp"
#include "envdesign/design_result_t.hpp"
#include "envdesign/keepalive_t.hpp"
#include "pddl/parse_error.h"
#include "result_format.h"
#include "spec/spec_bundle.h"

#include <cstdio>
#include <optional>
#include <random>
#include <unistd.h>

namespace envdesign::client {
namespace {

using Clock = std::chrono::steady_clock;
using envdesign::design_request_t;

double since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

Result failure(int exit_code, const std::string &message) {
    Result r;
    r.exit_code = exit_code;
    r.status = "error";
    r.error = message;
    r.text = message;
    return r;
}

std::optional<std::int8_t> prune_code(const std::string &prune) {
    if (prune == "none")
        return design_request_t::PRUNE_NONE;
    if (prune == "relevant")
        return design_request_t::PRUNE_RELEVANT;
    return std::nullopt;
}

std::optional<std::int8_t> search_code(const std::string &search) {
    if (search == "witness")
        return design_request_t::SEARCH_WITNESS;
    if (search == "exhaustive")
        return design_request_t::SEARCH_EXHAUSTIVE;
    return std::nullopt;
}

std::optional<std::int8_t> heuristic_code(const std::string &heuristic) {
    if (heuristic == "lmcut")
        return design_request_t::HEURISTIC_LMCUT;
    if (heuristic == "hmax")
        return design_request_t::HEURISTIC_HMAX;
    if (heuristic == "blind")
        return design_request_t::HEURISTIC_BLIND;
    return std::nullopt;
}

Progress progress_of(const envdesign::design_progress_t &p) {
    static const char *STATES[] = {"queued", "loading", "searching", "done"};
    Progress out;
    out.state = p.state >= 0 && p.state <= 3 ? STATES[p.state] : "unknown";
    out.done = p.done;
    out.total = p.total;
    out.best_objective = p.best_objective;
    out.planner_runs = p.planner_runs;
    out.cache_hits = p.cache_hits;
    out.evaluations = p.evaluations;
    out.jobs_in_flight = p.jobs_in_flight;
    out.planners = p.planners;
    out.seconds = p.seconds;
    return out;
}

// One request from publishing to its result.
class RemoteRun {
public:
    RemoteRun(bus::Bus &bus, design_request_t request, const Options &options)
        : bus_(bus), request_(std::move(request)), options_(options), board_(bus) {}

    Result run() {
        auto progress = bus_.subscribe<envdesign::design_progress_t>(
            bus::PROGRESS, [this](const envdesign::design_progress_t &p) { on_progress(p); });
        auto result = bus_.subscribe<envdesign::design_result_t>(
            bus::RESULT, [this](const envdesign::design_result_t &r) { on_result(r); });
        auto start = Clock::now();
        send();
        while (!result_) {
            bus_.handle(std::chrono::milliseconds(50));
            if (result_)
                break;
            if (options_.timeout_s > 0 && since(start) >= options_.timeout_s)
                return cancel("the client's timeout passed");
            if (options_.stop_requested && options_.stop_requested())
                return cancel("the client was stopped");
            // A coordinator says so once a second: a silent bus need not be waited on.
            double quiet = options_.no_coordinator_after_s;
            if (quiet > 0 && !answered_ && !board_.heard("coordinator") && since(start) >= quiet)
                return failure(1, no_coordinator_message(bus_, quiet));
            if (since(heard_) >= options_.give_up_after_s)
                return failure(1, "no coordinator answered on " + bus_.url());
            if (since(sent_) >= options_.resend_after_s &&
                since(heard_) >= options_.resend_after_s) {
                coordinator_.reset(); // it went silent: whoever takes the request now
                send();               // the request or the coordinator's answers were lost
            }
            if (since(kept_alive_) >= bus::CLIENT_KEEPALIVE_S)
                keep_alive();
        }
        return finish(*result_);
    }

private:
    // Ours, and from the coordinator that took the request: the first to answer, until it
    // goes silent. Another one's answers (a second coordinator on the bus, a rogue under
    // another name) are ignored.
    template <typename Message> bool mine(const Message &m) {
        if (m.request_id != request_.request_id || m.client != request_.sender)
            return false;
        if (!coordinator_)
            coordinator_ = m.sender;
        if (m.sender == *coordinator_)
            return true;
        bus_.log().warn("request {} | ignored a {} from {}: {} took the request",
                        bus::request_name(request_.sender, request_.request_id),
                        Message::getTypeName(), m.sender, *coordinator_);
        return false;
    }
    void on_progress(const envdesign::design_progress_t &p) {
        if (!mine(p))
            return;
        heard_ = Clock::now();
        answered_ = true;
        if (options_.on_progress)
            options_.on_progress(progress_of(p));
    }
    void on_result(const envdesign::design_result_t &r) {
        if (mine(r))
            result_ = r;
    }
    void send() {
        request_.utime = bus::now_utime();
        bus_.publish(bus::REQUEST, request_);
        sent_ = kept_alive_ = Clock::now(); // a repeat says it too
    }
    // "Still waiting": a request its client stops asking for is dropped (a killed client).
    void keep_alive() {
        envdesign::keepalive_t keepalive{};
        keepalive.utime = bus::now_utime();
        keepalive.request_id = request_.request_id;
        keepalive.sender = request_.sender;
        bus_.publish(bus::KEEPALIVE, keepalive);
        kept_alive_ = Clock::now();
    }
    // Our timeout passed or we were stopped: ask the coordinator to stop and take what it has.
    Result cancel(const std::string &why) {
        envdesign::cancel_t cancel{};
        cancel.utime = bus::now_utime();
        cancel.request_id = request_.request_id;
        cancel.sender = request_.sender;
        cancel.reason = why;
        bus_.publish(bus::CANCEL, cancel);
        auto asked = Clock::now();
        while (!result_ && since(asked) < 5)
            bus_.handle(std::chrono::milliseconds(50));
        if (!result_)
            return failure(4, why + " and the coordinator sent no result");
        Result r = finish(*result_);
        r.exit_code = r.exit_code == 0 ? 4 : r.exit_code;
        return r;
    }
    static Result finish(const envdesign::design_result_t &r) {
        if (r.status == "error")
            return failure(r.exit_code, r.error);
        Result out;
        out.exit_code = r.exit_code;
        out.status = r.status;
        out.json = result_json(r);
        out.text = result_text(r);
        out.warnings = r.warnings;
        return out;
    }

    bus::Bus &bus_;
    design_request_t request_;
    const Options &options_;
    Clock::time_point sent_ = Clock::now();
    Clock::time_point heard_ = Clock::now();
    Clock::time_point kept_alive_ = Clock::now();
    std::optional<envdesign::design_result_t> result_;
    std::optional<std::string> coordinator_;
    bool answered_ = false;  // a coordinator took the request
    bus::StatusBoard board_; // who is on the bus
};

std::int64_t new_request_id() {
    std::random_device random;
    std::uint64_t id = (static_cast<std::uint64_t>(random()) << 31) ^ random();
    return static_cast<std::int64_t>(id & 0x3fffffffffffffffULL) | 1;
}

} // namespace

std::string default_url() { return bus::default_url(); }

Result run_design_remote(const std::string &spec_path, const std::string &lcm_url,
                         const Options &options) {
    auto prune = prune_code(options.prune);
    auto heuristic = heuristic_code(options.heuristic);
    auto search = search_code(options.search);
    if (!prune || !heuristic || !search)
        return failure(2, "unknown search '" + options.search + "', prune '" + options.prune +
                              "' or heuristic '" + options.heuristic + "'");
    design_request_t request{};
    try {
        request.spec = spec::bundle_spec(spec_path);
    } catch (const pddl::ParseError &e) {
        return failure(2, e.what());
    }
    request.sender = bus::instance_name("client");
    request.request_id = new_request_id();
    request.time_limit_s = options.time_limit_s;
    request.max_design_size = options.max_design_size;
    request.ranking = options.ranking;
    request.ranking_all = options.ranking_all ? 1 : 0;
    request.prune = *prune;
    request.search = *search;
    request.heuristic = *heuristic;
    auto opened = open_client_bus(lcm_url, options.key_file, request.sender);
    if (auto *error = std::get_if<std::pair<int, std::string>>(&opened))
        return failure(error->first, error->second);
    try {
        bus::Bus &on = *std::get<std::unique_ptr<bus::Bus>>(opened);
        return RemoteRun(on, std::move(request), options).run();
    } catch (const std::exception &e) {
        return failure(1, e.what());
    }
}

std::function<void(const Progress &)> stderr_progress() {
    bool live = isatty(fileno(stderr));
    auto last = std::make_shared<Clock::time_point>();
    return [live, last](const Progress &p) {
        if (!live || (since(*last) < 0.1 && p.state != "done"))
            return;
        *last = Clock::now();
        std::fprintf(stderr,
                     "\r\033[K%s %lld/%lld configurations, best %g, %d planner(s), %lld "
                     "evaluations",
                     p.state.c_str(), p.done, p.total, p.best_objective, p.planners, p.evaluations);
        if (p.state == "done")
            std::fprintf(stderr, "\r\033[K");
        std::fflush(stderr);
    };
}

} // namespace envdesign::client
