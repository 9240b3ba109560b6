#pragma once
// Where the bridge takes arrivals from (common/bridge): DDS in deployment
// (dds::ArrivalReader), an in-process queue in tests and replays (ArrivalQueue).
//
//   ArrivalQueue queue;
//   queue.push({"restaurant", "dock-1", "serve-g1", 1, utime, "", ""});
//   std::vector<Arrival> batch;
//   if (queue.wait(0.2)) queue.take(batch, 4096);

#include "arrivals/arrival.h"
#include "concurrency/blocking_queue.h"

#include <cstddef>
#include <vector>

namespace envdesign::arrivals {

class ArrivalSource {
public:
    virtual ~ArrivalSource();
    // Blocks until arrivals are waiting, wake() is called, or `timeout_s` passes. True when
    // something is there to take.
    virtual bool wait(double timeout_s) = 0;
    // Takes up to `max` arrivals in the order they came, appending them to `out`; returns
    // how many.
    virtual std::size_t take(std::vector<Arrival> &out, std::size_t max) = 0;
    // Makes a wait() in another thread return; thread-safe.
    virtual void wake() = 0;
};

// An unbounded in-process source: push() from any thread, wait()/take() from one.
class ArrivalQueue : public ArrivalSource {
public:
    void push(Arrival arrival);
    std::size_t size() const;

    bool wait(double timeout_s) override;
    std::size_t take(std::vector<Arrival> &out, std::size_t max) override;
    void wake() override;

private:
    concurrency::BlockingQueue<Arrival> queue_;
};

} // namespace envdesign::arrivals
