#pragma once
// The LCM channels of envdesign (SPEC.md "LCM"), each with its one message type. Clients
// speak to the coordinator on the first five; the next six are between the coordinator and
// its planners; then the bridge's two; every service sends its status on the last
// (services/README.md draws the message flow; docs/messages.md lists the fields).

namespace envdesign::bus {

// client -> coordinator
inline constexpr const char *REQUEST = "ENVDESIGN_REQUEST"; // design_request_t
inline constexpr const char *CANCEL = "ENVDESIGN_CANCEL";   // cancel_t
// "still waiting", every CLIENT_KEEPALIVE_S while a client waits for a result: a request
// not heard of for the coordinator's --client-timeout is dropped (its client is gone)
inline constexpr const char *KEEPALIVE = "ENVDESIGN_KEEPALIVE"; // keepalive_t
inline constexpr double CLIENT_KEEPALIVE_S = 2.0;
// coordinator -> clients
inline constexpr const char *PROGRESS = "ENVDESIGN_PROGRESS"; // design_progress_t
inline constexpr const char *RESULT = "ENVDESIGN_RESULT";     // design_result_t
// coordinator -> planners
inline constexpr const char *SPEC = "ENVDESIGN_SPEC"; // spec_chunk_t
inline constexpr const char *JOB = "ENVDESIGN_JOB";   // job_t
// the job, as sent, taken back from its planner for a request that held none
// (cluster/fair_share.h): the planner stops it and does not answer
inline constexpr const char *WITHDRAW = "ENVDESIGN_WITHDRAW"; // job_t
// planners -> coordinator
inline constexpr const char *SPEC_NEED = "ENVDESIGN_SPEC_NEED";   // spec_need_t
inline constexpr const char *EVALUATION = "ENVDESIGN_EVALUATION"; // evaluation_t
inline constexpr const char *HEARTBEAT = "ENVDESIGN_HEARTBEAT";   // planner_heartbeat_t
// envdesign-bridge -> anyone (common/bridge): each design problem's estimate of the task
// distribution, and each re-evaluation it asks for (same type, with the reason)
inline constexpr const char *TASK_DISTRIBUTION =
    "ENVDESIGN_TASK_DISTRIBUTION";                                // task_distribution_t
inline constexpr const char *REEVALUATE = "ENVDESIGN_REEVALUATE"; // task_distribution_t
// every service -> anyone, once a second (bus/status.h)
inline constexpr const char *STATUS = "ENVDESIGN_STATUS"; // service_status_t

// Every channel above, for tools and tests.
inline constexpr const char *ALL_CHANNELS[] = {
    REQUEST,   CANCEL,     KEEPALIVE, PROGRESS,          RESULT,     SPEC,  JOB, WITHDRAW,
    SPEC_NEED, EVALUATION, HEARTBEAT, TASK_DISTRIBUTION, REEVALUATE, STATUS};

} // namespace envdesign::bus
