// `envdesign watch`: what passes on a bus (results, progress, task distribution estimates,
// optionally status). In text a message is one line, but for a result: a header line and
// the result's text; with JSON, one object a line for every message.

#include "bus/channels.h"
#include "bus/lcm_url.h"
#include "client_bus.h"
#include "envdesign/client/client.h"
#include "envdesign/design_progress_t.hpp"
#include "envdesign/design_result_t.hpp"
#include "envdesign/service_status_t.hpp"
#include "envdesign/task_distribution_t.hpp"
#include "result_format.h"

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>

#include <cmath>

namespace envdesign::client {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

// Infinity as the result JSON writes it ("inf"); NaN (not known) as null.
json number(double value) {
    if (std::isnan(value))
        return nullptr;
    if (std::isinf(value))
        return value > 0 ? "inf" : "-inf";
    return value;
}

std::string request_name(const std::string &client, long long request_id) {
    return client + "#" + std::to_string(request_id);
}

const char *state_name(int state) {
    static const char *STATES[] = {"queued", "loading", "searching", "done"};
    return state >= 0 && state < 4 ? STATES[state] : "unknown";
}

std::string progress_line(const design_progress_t &p, bool as_json) {
    if (as_json)
        return json{{"kind", "progress"},
                    {"channel", bus::PROGRESS},
                    {"utime", p.utime},
                    {"coordinator", p.sender},
                    {"client", p.client},
                    {"request_id", p.request_id},
                    {"state", state_name(p.state)},
                    {"done", p.done},
                    {"total", p.total},
                    {"best_objective", number(p.best_objective)},
                    {"planner_runs", p.planner_runs},
                    {"evaluations", p.evaluations},
                    {"jobs_in_flight", p.jobs_in_flight},
                    {"planners", p.planners},
                    {"seconds", p.seconds}}
            .dump();
    std::string best =
        std::isinf(p.best_objective) ? "none yet" : fmt::format("{:.6g}", p.best_objective);
    return fmt::format("progress {}: {} {}/{}, best {}, {} planner(s), {:.1f} s",
                       request_name(p.client, p.request_id), state_name(p.state), p.done, p.total,
                       best, p.planners, p.seconds);
}

std::string result_line(const design_result_t &r, bool as_json) {
    if (as_json)
        return json{{"kind", "result"},         {"channel", bus::RESULT},
                    {"utime", r.utime},         {"coordinator", r.sender},
                    {"client", r.client},       {"request_id", r.request_id},
                    {"exit_code", r.exit_code}, {"result", json::parse(result_json(r))}}
            .dump();
    std::string text = result_text(r);
    while (!text.empty() && text.back() == '\n')
        text.pop_back();
    return fmt::format("result {} (exit code {}):\n{}", request_name(r.client, r.request_id),
                       r.exit_code, text);
}

std::string distribution_line(const task_distribution_t &d, bool as_json) {
    if (as_json) {
        json tasks = json::object(), reference = json::object();
        for (int i = 0; i < d.num_tasks; ++i) {
            tasks[d.tasks[i]] = number(d.probabilities[i]);
            reference[d.tasks[i]] = number(d.reference[i]);
        }
        return json{{"kind", "distribution"},
                    {"channel", bus::TASK_DISTRIBUTION},
                    {"utime", d.utime},
                    {"bridge", d.sender},
                    {"problem_id", d.problem_id},
                    {"estimator", d.estimator},
                    {"samples", d.samples},
                    {"probabilities", tasks},
                    {"reference", reference},
                    {"distance", number(d.distance)},
                    {"threshold", d.threshold},
                    {"design", d.design},
                    {"objective", number(d.objective)},
                    {"last_change", d.last_change}}
            .dump();
    }
    std::string tasks;
    for (int i = 0; i < d.num_tasks; ++i)
        tasks += fmt::format("{}{} {:.3f}", i ? ", " : "", d.tasks[i], d.probabilities[i]);
    return fmt::format("distribution {}: {} ({:.0f} samples; TV {:.3f} from the design's D, "
                       "threshold {:.3g}; design {{{}}})",
                       d.problem_id, tasks, d.samples, d.distance, d.threshold,
                       fmt::join(d.design, ", "));
}

std::string status_line(const service_status_t &s, bool as_json) {
    if (as_json)
        return json{{"kind", "status"},       {"channel", bus::STATUS},
                    {"utime", s.utime},       {"name", s.sender},
                    {"service", s.kind},      {"version", s.version},
                    {"uptime_s", s.uptime_s}, {"requests_open", s.requests_open},
                    {"planners", s.planners}, {"jobs_in_flight", s.jobs_in_flight}}
            .dump();
    return fmt::format("status {} {}: up {:.0f} s, {} open, {} planner(s), {} job(s) in flight",
                       s.kind, s.sender, s.uptime_s, s.requests_open, s.planners, s.jobs_in_flight);
}

} // namespace

WatchReport watch_bus(const std::string &lcm_url, const WatchOptions &options,
                      const std::function<void(const std::string &)> &on_line) {
    WatchReport report;
    auto opened = open_client_bus(lcm_url, options.key_file, bus::instance_name("watch"));
    if (auto *error = std::get_if<std::pair<int, std::string>>(&opened)) {
        report.exit_code = error->first;
        report.error = error->second;
        return report;
    }
    bus::Bus &on = *std::get<std::unique_ptr<bus::Bus>>(opened);
    auto emit = [&](const std::string &line) {
        ++report.messages;
        on_line(line);
    };
    const bool as_json = options.json;
    auto results = on.subscribe<design_result_t>(
        bus::RESULT, [&](const design_result_t &r) { emit(result_line(r, as_json)); });
    auto progress = on.subscribe<design_progress_t>(
        bus::PROGRESS, [&](const design_progress_t &p) { emit(progress_line(p, as_json)); });
    auto estimates = on.subscribe<task_distribution_t>(
        bus::TASK_DISTRIBUTION,
        [&](const task_distribution_t &d) { emit(distribution_line(d, as_json)); });
    std::optional<bus::Subscription> status;
    if (options.status)
        status = on.subscribe<service_status_t>(
            bus::STATUS, [&](const service_status_t &s) { emit(status_line(s, as_json)); });
    auto end = Clock::now() + std::chrono::duration<double>(options.seconds);
    while (options.seconds <= 0 || Clock::now() < end) {
        if (options.stop_requested && options.stop_requested())
            break;
        // A signal (the stop asked for) interrupts LCM's wait: that is no failure.
        if (on.handle(std::chrono::milliseconds(50)) < 0 &&
            !(options.stop_requested && options.stop_requested())) {
            report.exit_code = 1;
            report.error =
                "LCM failed while watching " + (lcm_url.empty() ? default_url() : lcm_url);
            break;
        }
    }
    return report;
}

} // namespace envdesign::client
