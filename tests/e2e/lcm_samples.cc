// lcm_samples URL [--count N] [--period-ms MS]: publishes one well-formed message of each
// envdesign type on its channel, N times (default 1), for the LCM tool checks
// (lcm_tools_test.sh): a normal run never sends some of them (a cancel, a spec need). The
// samples name no real coordinator or planner, so services on the URL ignore them. Signed
// with $ENVDESIGN_KEY_FILE when it is set, as the services are.

#include "bus/bus.h"
#include "bus/channels.h"
#include "bus/log.h"
#include "envdesign/cancel_t.hpp"
#include "envdesign/design_progress_t.hpp"
#include "envdesign/design_request_t.hpp"
#include "envdesign/design_result_t.hpp"
#include "envdesign/evaluation_t.hpp"
#include "envdesign/job_t.hpp"
#include "envdesign/planner_heartbeat_t.hpp"
#include "envdesign/spec_chunk_t.hpp"
#include "envdesign/spec_need_t.hpp"

#include <spdlog/sinks/null_sink.h>

#include <string>
#include <thread>

namespace {

using namespace envdesign;

const std::string SAMPLE = "samples/nobody";

void publish_all(bus::Bus &bus) {
    std::int64_t now = bus::now_utime();
    design_request_t request{};
    request.utime = now;
    request.request_id = 0; // no coordinator serves request 0
    request.sender = SAMPLE;
    request.spec.name = "sample.textproto";
    bus.publish(bus::REQUEST, request);
    cancel_t cancel{};
    cancel.utime = now;
    cancel.sender = SAMPLE;
    cancel.reason = "sample";
    bus.publish(bus::CANCEL, cancel);
    design_progress_t progress{};
    progress.utime = now;
    progress.sender = SAMPLE;
    progress.client = SAMPLE;
    bus.publish(bus::PROGRESS, progress);
    design_result_t result{};
    result.utime = now;
    result.sender = SAMPLE;
    result.client = SAMPLE;
    result.status = "error";
    result.error = "sample";
    bus.publish(bus::RESULT, result);
    spec_chunk_t chunk{};
    chunk.utime = now;
    chunk.sender = SAMPLE;
    chunk.spec_hash = std::string(64, '0');
    chunk.total_bytes = 3;
    chunk.num_chunks = 1;
    chunk.data = {1, 2, 3};
    chunk.num_bytes = 3;
    bus.publish(bus::SPEC, chunk);
    spec_need_t need{};
    need.utime = now;
    need.sender = SAMPLE;
    need.coordinator = SAMPLE;
    need.spec_hash = std::string(64, '0');
    bus.publish(bus::SPEC_NEED, need);
    job_t job{};
    job.utime = now;
    job.sender = SAMPLE;
    job.planner = SAMPLE;
    job.spec_hash = std::string(64, '0');
    job.kind = job_t::KIND_EXPLICABILITY;
    bus.publish(bus::JOB, job);
    evaluation_t evaluation{};
    evaluation.utime = now;
    evaluation.sender = SAMPLE;
    evaluation.coordinator = SAMPLE;
    evaluation.kind = job_t::KIND_EXPLICABILITY;
    evaluation.plan = {"(move c00 c10)"};
    evaluation.plan_length = 1;
    bus.publish(bus::EVALUATION, evaluation);
    planner_heartbeat_t beat{};
    beat.utime = now;
    beat.sender = SAMPLE;
    beat.period_ms = 1000;
    beat.capacity = 1;
    beat.stopping = true; // never taken as a planner
    bus.publish(bus::HEARTBEAT, beat);
}

} // namespace

int main(int argc, char **argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: lcm_samples URL [--count N] [--period-ms MS]\n");
        return 2;
    }
    int count = 1, period_ms = 100;
    for (int i = 2; i + 1 < argc; i += 2) {
        std::string flag = argv[i];
        (flag == "--count" ? count : period_ms) = std::atoi(argv[i + 1]);
    }
    std::shared_ptr<const bus::KeyRing> keys; // signed like the services when they are
    if (auto path = bus::key_file_path(""))
        keys = std::make_shared<const bus::KeyRing>(bus::load_key_file(*path));
    bus::Bus bus(argv[1],
                 std::make_shared<spdlog::logger>("samples",
                                                  std::make_shared<spdlog::sinks::null_sink_mt>()),
                 keys);
    for (int i = 0; i < count; ++i) {
        publish_all(bus);
        std::this_thread::sleep_for(std::chrono::milliseconds(period_ms));
    }
    return 0;
}
