#include "bridge/bridge.h"

#include "bridge/spec_request.h"

#include "bus/channels.h"
#include "bus/log.h"
#include "spec/design_spec.h"
#include "spec/spec_bundle.h"

#include <cmath>
#include <limits>

namespace envdesign::bridge {
namespace {

constexpr double WAIT_S = 0.2;      // the reader thread checks for shutdown this often
constexpr double HEARTBEAT_S = 1.0; // estimates of idle problems, this often
constexpr std::size_t BATCH = 4096; // samples taken at once

arrivals::Distribution spec_distribution(const design::DesignProblem &problem) {
    arrivals::Distribution d;
    for (const auto &t : problem.tasks)
        d[t.name] = t.probability;
    return d;
}

std::string quoted(const std::string &s) {
    // Samples are untrusted: keep log lines short and on one line.
    std::string out = s.substr(0, 60);
    for (char &c : out)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            c = '?';
    return "'" + out + (s.size() > 60 ? "...'" : "'");
}

// The coordinator keeps its store to itself: only --redesign local can re-weigh.
arrivals::TrackerConfig with_reweighing(const BridgeConfig &config) {
    arrivals::TrackerConfig c = config.tracker;
    if (config.mode != Mode::LOCAL)
        c.reweigh_interval_s = 0;
    return c;
}

} // namespace

Bridge::Bridge(bus::Bus &bus, BridgeConfig config, arrivals::ArrivalSource &source,
               const Clock &clock)
    : bus_(bus), config_(std::move(config)), source_(source), clock_(clock),
      tracker_(with_reweighing(config_)) {
    std::map<std::string, design::DesignProblem> problems;
    std::map<std::string, envdesign::spec_t> specs;
    for (const auto &source : config_.problems) {
        design::DesignProblem problem = spec::load_design_problem(source.spec_path);
        tracker_.add_problem(source.id, spec_distribution(problem));
        problems_[source.id].design.objective = std::numeric_limits<double>::quiet_NaN();
        if (config_.mode == Mode::COORDINATOR)
            specs[source.id] = spec::bundle_spec(source.spec_path);
        problems.emplace(source.id, std::move(problem));
    }
    Answered answered = [this](Answer a) { on_answer(std::move(a)); };
    if (config_.mode == Mode::LOCAL) {
        auto local = std::make_unique<LocalRedesigns>(bus_, config_.instance, std::move(problems),
                                                      config_.local, answered);
        local_ = local.get();
        backend_ = std::move(local);
    } else
        backend_ = std::make_unique<CoordinatorRedesigns>(bus_, config_.instance, std::move(specs),
                                                          std::move(problems), config_.coordinator,
                                                          answered);
    results_.emplace(bus_.subscribe<envdesign::design_result_t>(
        bus::RESULT, [this](const envdesign::design_result_t &r) { backend_->on_result(r); }));
    progress_.emplace(bus_.subscribe<envdesign::design_progress_t>(
        bus::PROGRESS,
        [this](const envdesign::design_progress_t &p) { backend_->on_progress(p); }));
    {
        std::lock_guard lock(mutex_);
        for (const auto &source : config_.problems)
            send(tracker_.initial_request(source.id, now()));
    }
    if (config_.reader_thread)
        reader_thread_ = std::thread([this] { read_arrivals(); });
}

Bridge::~Bridge() {
    {
        std::lock_guard lock(mutex_); // an answer being handled finishes first
        stopping_ = true;
    }
    source_.wake();
    if (reader_thread_.joinable())
        reader_thread_.join();
    backend_.reset(); // joins the local worker; its last answer sees stopping_
}

double Bridge::now() const { return clock_.seconds(); }

void Bridge::read_arrivals() {
    std::vector<arrivals::Arrival> batch;
    while (!stopping_) {
        try {
            if (source_.wait(WAIT_S))
                take_batch(batch);
        } catch (const std::exception &e) { // the source (DDS) failed: say so, try again later
            bus_.log().error("request - | reading arrivals: {}", e.what());
            std::this_thread::sleep_for(std::chrono::seconds(1));
        }
    }
}

std::size_t Bridge::pump(double wait_s) {
    std::vector<arrivals::Arrival> batch;
    return source_.wait(wait_s) ? take_batch(batch) : 0;
}

std::size_t Bridge::take_batch(std::vector<arrivals::Arrival> &batch) {
    batch.clear();
    source_.take(batch, BATCH);
    bus_.log().trace("request - | took {} arrivals", batch.size());
    std::lock_guard lock(mutex_);
    double t = now();
    std::int64_t utime = clock_.utime();
    for (const auto &arrival : batch)
        receive(arrival, t, utime);
    reweigh(t);
    for (const auto &[id, published] : problems_)
        publish_estimate(id, t, false);
    return batch.size();
}

void Bridge::receive(const arrivals::Arrival &arrival, double t, std::int64_t utime) {
    arrivals::Outcome outcome = tracker_.receive(arrival, t, utime);
    if (outcome.verdict != arrivals::Verdict::ACCEPTED ||
        outcome.use == arrivals::Use::UNKNOWN_TASK)
        log_rejected(arrival, outcome, t);
    if (outcome.clock_skewed) {
        arrivals::LogThrottle::Decision d = skew_throttle_.should_log(outcome.verdict, t);
        if (d.log)
            bus_.log().warn("request - | {}: site {} stamps arrivals {:.0f} s ahead of this "
                            "clock (beyond --max-future): estimating from arrival order{}",
                            arrival.problem_id, quoted(arrival.site),
                            tracker_.counters().last_skew_s,
                            d.suppressed ? fmt::format(" ({} more not logged)", d.suppressed) : "");
    }
    if (outcome.use == arrivals::Use::NEW_TASK)
        bus_.log().info("request - | {}: new task {} from site {}, with its problem ({} bytes)",
                        arrival.problem_id, quoted(arrival.task), quoted(arrival.site),
                        arrival.problem.size());
    if (outcome.request)
        send(*outcome.request);
}

void Bridge::log_rejected(const arrivals::Arrival &a, const arrivals::Outcome &outcome, double t) {
    if (outcome.held_back) { // a flood of made-up new tasks must not flood the log
        arrivals::LogThrottle::Decision d = held_back_throttle_.should_log(outcome.verdict, t);
        if (d.log)
            bus_.log().warn("request - | {}: new task {} from site {} held back (taken in: at "
                            "most {} per problem, {} at once, then one per {} s): counted as an "
                            "unknown task{}",
                            a.problem_id, quoted(a.task), quoted(a.site),
                            config_.tracker.max_new_tasks, config_.tracker.new_task_burst,
                            config_.tracker.new_task_interval_s,
                            d.suppressed ? fmt::format(" ({} more not logged)", d.suppressed) : "");
        return;
    }
    if (outcome.verdict == arrivals::Verdict::ACCEPTED) { // an unknown task: once per name
        if (outcome.first_of_name)
            bus_.log().warn("request - | {}: arrivals of unknown task {} (site {}) are counted, "
                            "not estimated; send its problem to add it",
                            a.problem_id, quoted(a.task), quoted(a.site));
        return;
    }
    arrivals::LogThrottle::Decision d = throttle_.should_log(outcome.verdict, t);
    if (!d.log)
        return;
    bus_.log().warn("request - | bad arrival ({}): problem {} site {} task {} sequence {} utime "
                    "{}{}",
                    arrivals::to_string(outcome.verdict), quoted(a.problem_id), quoted(a.site),
                    quoted(a.task), a.sequence, a.utime,
                    d.suppressed ? fmt::format(" ({} more of this kind not logged)", d.suppressed)
                                 : "");
}

void Bridge::send(const arrivals::Request &request) {
    std::int64_t id = ++next_request_id_;
    ++requests_;
    Published &p = problems_[request.problem_id];
    p.design.request_id = id;
    auto status = tracker_.status(request.problem_id);
    envdesign::task_distribution_t m =
        request_message(request, *status, tracker_.counters(), config_.tracker, p.design);
    m.utime = clock_.utime();
    m.request_id = id;
    m.sender = config_.instance;
    bus_.publish(bus::REEVALUATE, m);
    bus_.log().info("request {} | {}: re-evaluate, {}", bus::request_name(config_.instance, id),
                    request.problem_id, arrivals::describe(request));
    backend_->start(id, request);
    publish_estimate(request.problem_id, now(), true);
}

void Bridge::publish_estimate(const std::string &id, double t, bool force) {
    Published &p = problems_[id];
    if (!force && t - p.at < 1.0 / config_.publish_hz)
        return; // before copying the status: this runs after every batch
    auto status = tracker_.status(id);
    if (!force && status->estimated == p.estimated && t - p.at < HEARTBEAT_S)
        return;
    envdesign::task_distribution_t m =
        distribution_message(*status, tracker_.counters(), config_.tracker, p.design);
    m.utime = clock_.utime();
    m.sender = config_.instance;
    bus_.publish(bus::TASK_DISTRIBUTION, m);
    p.at = t;
    p.estimated = status->estimated;
}

void Bridge::reweigh(double t) {
    if (!local_)
        return;
    for (const auto &request : tracker_.reweighs_due(t))
        local_->reweigh(++next_request_id_, request);
}

void Bridge::on_reweighed(const Answer &answer) {
    ++reweighs_;
    if (!answer.reference) { // needs planners: they run now (tracker.h, unevaluated)
        ++reweigh_planning_;
        if (auto request = tracker_.unevaluated(answer.problem_id, now()))
            send(*request);
        return;
    }
    tracker_.reweighed(answer.problem_id, *answer.reference);
    if (!answer.changed)
        return;
    ++reweigh_changes_;
    Published &p = problems_[answer.problem_id];
    std::int64_t last_request = p.design.request_id;
    p.design = answer.design;
    p.design.request_id = last_request;
    publish_estimate(answer.problem_id, now(), true);
}

void Bridge::on_answer(Answer answer) {
    std::lock_guard lock(mutex_);
    if (stopping_)
        return;
    if (answer.reweigh) {
        on_reweighed(answer);
        return;
    }
    ++answers_;
    Published &p = problems_[answer.problem_id];
    std::int64_t last_request = p.design.request_id;
    p.design = answer.design;
    p.design.request_id = last_request;
    arrivals::Distribution reference =
        answer.reference ? *answer.reference : tracker_.status(answer.problem_id)->reference;
    auto level = config_.mode == Mode::LOCAL ? spdlog::level::debug : spdlog::level::info;
    bus_.log().log(level, "request {} | {}: {}",
                   bus::request_name(config_.instance, answer.request_id), answer.problem_id,
                   answer.design.last_change);
    auto next = tracker_.answered(answer.problem_id, reference, now());
    publish_estimate(answer.problem_id, now(), true);
    if (next)
        send(*next);
}

void Bridge::tick() {
    std::lock_guard lock(mutex_);
    double t = now();
    for (const auto &request : tracker_.requests_due(t))
        send(request);
    backend_->tick(t);
    reweigh(t); // the last arrivals of a burst, held back by the rate limit
    for (const auto &[id, published] : problems_)
        publish_estimate(id, t, false);
    for (const auto &[verdict, count] : skew_throttle_.overdue(t))
        bus_.log().warn("request - | {} more arrivals with skewed clocks not logged", count);
    for (const auto &[verdict, count] : held_back_throttle_.overdue(t))
        bus_.log().warn("request - | {} more new tasks held back not logged", count);
    for (const auto &[verdict, count] : throttle_.overdue(t))
        bus_.log().warn("request - | {} more bad arrivals ({}) not logged", count,
                        arrivals::to_string(verdict));
}

DesignInForce Bridge::design(const std::string &problem_id) const {
    std::lock_guard lock(mutex_);
    return problems_.at(problem_id).design;
}

BridgeStats Bridge::stats() const {
    std::lock_guard lock(mutex_);
    BridgeStats stats{tracker_.counters(), requests_,        answers_,
                      reweighs_,           reweigh_changes_, reweigh_planning_};
    for (const auto &id : tracker_.problem_ids())
        stats.new_tasks_held_back += tracker_.status(id)->new_tasks_held_back;
    return stats;
}

} // namespace envdesign::bridge
