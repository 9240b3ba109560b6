// The numbers that come into the coordinator and the planners on the wire (issue 21): the
// first byte picks a message type, the rest is decoded as it (the LCM encoding, as a
// Bus handler would decode it) and put through the check its receiver runs:
//   evaluation_t         wire::evaluation_problem for either job kind (the router)
//   job_t                wire::job_problem against a 3-task, 4-modification problem
//   planner_heartbeat_t  cluster::heartbeat_problem (the planner pool)
//   design_request_t     cluster::request_problem (the coordinator)
// Whatever passes must hold only finite numbers in their ranges (INF only where it means
// "no plan"), written out here again, not by calling the checks; an evaluation that passes
// must also be one the store takes back (design/evaluation/evaluation_record.h). Never a crash.

#include "bus/codec.h"
#include "cluster/coordinator.h"
#include "cluster/planner_pool.h"
#include "design/evaluation/evaluation_record.h"
#include "design/model/numbers.h"
#include "design/search/deadline.h"
#include "envdesign/design_request_t.hpp"
#include "envdesign/evaluation_t.hpp"
#include "envdesign/job_t.hpp"
#include "envdesign/planner_heartbeat_t.hpp"
#include "wire/job_messages.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace {

using namespace envdesign;

constexpr double TOP_COST = 2147483647.0;

void require(bool ok) {
    if (!ok)
        std::abort();
}

// A plan cost: INF ("no plan") or a finite cost in [0, 2^31).
bool cost_or_none(double c) {
    return c == design::INF || (std::isfinite(c) && c >= 0 && c <= TOP_COST);
}

void evaluation(const evaluation_t &e) {
    for (std::int8_t kind : {job_t::KIND_ROBOT_BOUND, job_t::KIND_EXPLICABILITY}) {
        if (wire::evaluation_problem(e, kind))
            continue;
        design::Job job{};
        job.kind = kind == job_t::KIND_ROBOT_BOUND ? design::JobKind::ROBOT_BOUND
                                                   : design::JobKind::EXPLICABILITY;
        design::JobAnswer answer = wire::job_answer(job, e);
        if (kind == job_t::KIND_ROBOT_BOUND) {
            require(!answer.robot_bound || cost_or_none(*answer.robot_bound));
            require(!answer.ie_floor || (!std::isnan(*answer.ie_floor) && *answer.ie_floor >= 0));
            require(!answer.explanation_floor ||
                    (*answer.explanation_floor >= 0 && *answer.explanation_floor <= 1048576));
            continue;
        }
        const design::TaskExplicability &t = answer.explicability;
        if (t.status != design::ExplicabilityStatus::SOLVED &&
            t.status != design::ExplicabilityStatus::INEXPLICABLE)
            continue; // a LIMIT or an error carries no numbers on
        require(cost_or_none(t.robot_cost) && cost_or_none(t.human_plan_cost));
        require(!t.human_optimal_cost || cost_or_none(*t.human_optimal_cost));
        require(!t.explanation || cost_or_none(t.explanation->robot_optimal_cost));
        require(!std::isnan(t.ie) && t.ie >= 0);
        if (t.status == design::ExplicabilityStatus::SOLVED)
            require(std::isfinite(t.robot_cost));
        else
            require(t.ie == design::INF);
        // What the wire takes, the store takes back the same.
        auto stored = design::decode_evaluation(design::encode_evaluation(t));
        require(stored && !design::evaluation_problem(*stored));
        require(stored->robot_cost == t.robot_cost && stored->human_plan_cost == t.human_plan_cost);
    }
}

void job(const job_t &m) {
    design::DesignProblem problem;
    problem.tasks.resize(3);
    problem.modifications.resize(4);
    if (wire::job_problem(m, problem))
        return;
    require(m.kind == job_t::KIND_ROBOT_BOUND || m.kind == job_t::KIND_EXPLICABILITY);
    require(m.task >= 0 && m.task < 3);
    int previous = -1;
    for (int i : m.modifications) {
        require(i > previous && i < 4);
        previous = i;
    }
    require(m.heuristic >= design_request_t::HEURISTIC_LMCUT &&
            m.heuristic <= design_request_t::HEURISTIC_BLIND);
    require(std::isfinite(m.time_limit_s) && m.time_limit_s >= 0 &&
            m.time_limit_s <= design::TIME_LIMIT_S.high);
    if (m.has_robot_bound) // only a ROBOT_BOUND job's, a plan cost or "no plan"
        require(m.kind == job_t::KIND_ROBOT_BOUND &&
                (m.robot_bound == INFINITY ||
                 (m.robot_bound >= 0 && m.robot_bound <= design::PLAN_COST.high)));
    // The planner's deadline from it (UBSan: no overflow in the conversion).
    design::Deadline deadline = design::Deadline::in(m.time_limit_s);
    require(deadline.limited() == (m.time_limit_s > 0));
    if (deadline.limited())
        require(std::isfinite(deadline.remaining_seconds()));
}

void heartbeat(const planner_heartbeat_t &beat) {
    if (cluster::heartbeat_problem(beat))
        return;
    require(!beat.sender.empty() && beat.capacity >= 1);
    require(beat.period_ms >= cluster::HEARTBEAT_PERIOD_S.low * 1000 &&
            beat.period_ms <= cluster::HEARTBEAT_PERIOD_S.high * 1000);
    require(std::isfinite(beat.busy_seconds) && beat.busy_seconds >= 0);
}

void request(const design_request_t &r) {
    if (cluster::request_problem(r, 1 << 20))
        return;
    require(std::isfinite(r.time_limit_s) && r.time_limit_s <= design::TIME_LIMIT_S.high);
    require(r.max_design_size <= design::DESIGN_SIZE.high);
    require(r.ranking >= 0 && r.ranking <= 100000);
    require(r.heuristic >= design_request_t::HEURISTIC_LMCUT &&
            r.heuristic <= design_request_t::HEURISTIC_BLIND);
    require(!r.spec.name.empty());
}

template <typename Message, typename Check>
void decoded(const std::uint8_t *data, std::size_t size, Check check) {
    Message m{};
    if (bus::decode_message(data, static_cast<int>(size), m))
        check(m);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    if (size < 1 || size > 65536)
        return 0;
    const std::uint8_t *bytes = data + 1;
    std::size_t n = size - 1;
    switch (data[0] % 4) {
    case 0:
        decoded<evaluation_t>(bytes, n, evaluation);
        break;
    case 1:
        decoded<job_t>(bytes, n, job);
        break;
    case 2:
        decoded<planner_heartbeat_t>(bytes, n, heartbeat);
        break;
    default:
        decoded<design_request_t>(bytes, n, request);
    }
    return 0;
}
