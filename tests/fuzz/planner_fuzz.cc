// The planner core's LCM handlers (jobs, spec chunks) on bytes from the bus: whatever
// arrives, it must neither crash nor hang, and what it holds stays bounded.

#include "bus_records.h"

#include "bus/channels.h"
#include "cluster/planner.h"

#include <filesystem>

namespace {

using namespace envdesign;

const char *const CHANNELS[] = {bus::JOB, bus::SPEC};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    bus::Bus bus("memq://", fuzz::quiet_logger());
    cluster::PlannerConfig config;
    config.instance = "planner"; // what make_seeds.cc addresses jobs to
    config.workers = 1;
    cluster::Planner planner(bus, config);
    for (const auto &record : fuzz::read_records(data, size, 2)) {
        bus.publish_raw(CHANNELS[record.channel], record.bytes.data(),
                        static_cast<int>(record.bytes.size()));
        while (bus.handle(std::chrono::milliseconds(0)) > 0)
            planner.tick();
    }
    planner.tick();
    planner.stop();
    return 0;
}
