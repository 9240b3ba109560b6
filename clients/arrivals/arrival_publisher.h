#pragma once
// The C++ API for warehouse systems (and tests) that announce task arrivals to envdesign:
// one publisher per (design problem, site), numbering its arrivals 1, 2, 3, ... as the
// bridge expects (arrivals/intake.h).
//
// Example:
//   ArrivalPublisher pub({.domain = 0, .problem_id = "restaurant", .site = "dock-1"});
//   pub.wait_for_bridge(5.0);       // optional: the bridge also gets recent history late
//   pub.publish("serve-g1");
//   pub.publish("clean-g3", pddl_text);   // a new task, with its problem
//   pub.flush(2.0);                 // every arrival acknowledged
//
// Threads: one publisher is not thread-safe; use one per thread or site. Errors are
// dds::DdsError.

#include "arrivals/arrival.h"
#include "dds/arrival_topic.h"

#include <cstdint>
#include <string>

namespace envdesign::arrivals_client {

struct PublisherOptions {
    int domain = 0;                    // DDS domain id
    std::string problem_id;            // the design problem
    std::string site = "site";         // this publisher's site
    int history = dds::WRITER_HISTORY; // arrivals kept per site for bridges that join late
};

class ArrivalPublisher {
public:
    explicit ArrivalPublisher(PublisherOptions options);

    // Publishes an arrival of `task` now, with the next sequence number, which it returns.
    // `problem` (PDDL text) makes it a new task for the design problem.
    int64_t publish(const std::string &task, const std::string &problem = "",
                    const std::string &human_problem = "");
    // Publishes `arrival` exactly as given (no numbering, no defaults): for replays and for
    // tests of bad samples.
    void publish_raw(const arrivals::Arrival &arrival);

    // True once a bridge (any reader of the topic) is matched, false after `timeout_s`.
    bool wait_for_bridge(double timeout_s) { return writer_.wait_for_readers(1, timeout_s); }
    // True once every matched reader that has discovered this writer has acknowledged every
    // arrival. A reader that matched but is still discovering the writer is not waited for
    // (Cyclone counts only readers that answered): keep the publisher alive a moment longer
    // (the CLI's --linger) and that reader gets the history when it has.
    bool flush(double timeout_s) { return writer_.wait_for_acks(timeout_s); }

    int64_t last_sequence() const { return sequence_; }

private:
    PublisherOptions options_;
    dds::ArrivalWriter writer_;
    int64_t sequence_ = 0;
};

// Microseconds since the Unix epoch.
int64_t now_utime();

} // namespace envdesign::arrivals_client
