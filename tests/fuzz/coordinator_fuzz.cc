// The coordinator core's LCM handlers (requests, cancels, spec needs, evaluations,
// heartbeats) on bytes from the bus: whatever arrives, it must neither crash nor hang.

#include "bus_records.h"

#include "bus/channels.h"
#include "cluster/coordinator.h"

#include <filesystem>

namespace {

using namespace envdesign;

const char *const CHANNELS[] = {bus::REQUEST, bus::CANCEL, bus::SPEC_NEED, bus::EVALUATION,
                                bus::HEARTBEAT};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    bus::Bus bus("memq://", fuzz::quiet_logger());
    cluster::CoordinatorConfig config;
    config.instance = "coordinator";
    config.max_active = 2;
    config.max_waiting = 2;
    cluster::Coordinator coordinator(bus, config);
    for (const auto &record : fuzz::read_records(data, size, 5)) {
        bus.publish_raw(CHANNELS[record.channel], record.bytes.data(),
                        static_cast<int>(record.bytes.size()));
        while (bus.handle(std::chrono::milliseconds(0)) > 0)
            coordinator.tick();
    }
    coordinator.tick();
    return 0; // the destructor cancels and joins what was started
}
