#pragma once
// The TaskArrival topic (dds/task_arrival.idl) from C++: a writer for warehouse systems and
// tests (clients/arrivals), a reader for envdesign-bridge.
//
// QoS, set in code on both sides (arrival_qos.cc says why each):
//   RELIABLE, TRANSIENT_LOCAL, KEEP_LAST per instance (problem_id, site);
//   writer depth `history` (256): what a bridge started late gets of each live site;
//   reader depth `history` (4096): bounds the reader's memory; a flood the bridge cannot
//   keep up with overwrites the oldest unread samples instead of blocking the writers, and
//   the sequence numbers make the loss visible (arrivals/intake.h).
// The domain comes from the caller; the network from CYCLONEDDS_URI (deploy/ has a
// loopback-only one).
//
// Example:
//   ArrivalWriter writer(0);
//   writer.wait_for_readers(1, 5.0);
//   writer.write({"restaurant", "dock-1", "serve-g1", 1, now_us, "", ""});

#include "arrivals/arrival.h"
#include "arrivals/arrival_source.h"
#include "dds/entity.h"

#include <cstddef>
#include <vector>

namespace envdesign::dds {

inline constexpr const char *ARRIVAL_TOPIC = "envdesign_task_arrival";
inline constexpr int WRITER_HISTORY = 256;
inline constexpr int READER_HISTORY = 4096;

Qos arrival_writer_qos(int history);
Qos arrival_reader_qos(int history);

class ArrivalWriter {
public:
    explicit ArrivalWriter(dds_domainid_t domain, int history = WRITER_HISTORY);

    // Throws DdsError (e.g. TIMEOUT when reliable delivery stays blocked for a second).
    void write(const arrivals::Arrival &arrival);
    int matched_readers() const;
    // Blocks until at least `count` readers match or `timeout_s` passes; true if they did.
    bool wait_for_readers(int count, double timeout_s);
    // Blocks until every matched reader acknowledged every sample, or `timeout_s` passes.
    bool wait_for_acks(double timeout_s);

private:
    Entity participant_; // first: deleted last, and takes the rest along
    Entity topic_;
    Entity writer_;
};

// The bridge's arrival source in deployment (arrivals/arrival_source.h).
class ArrivalReader : public arrivals::ArrivalSource {
public:
    explicit ArrivalReader(dds_domainid_t domain, int history = READER_HISTORY);

    // Blocks until arrivals are waiting, wake() is called, or `timeout_s` passes.
    // True when something is there to take.
    bool wait(double timeout_s) override;
    // Takes up to `max` arrivals, appending them to `out`; returns how many. Samples that
    // carry no data (a writer going away) are skipped.
    std::size_t take(std::vector<arrivals::Arrival> &out, std::size_t max) override;
    // Makes a wait() in another thread return; thread-safe.
    void wake() override;
    int matched_writers() const;

private:
    Entity participant_;
    Entity topic_;
    Entity reader_;
    Entity data_;  // read condition: any sample
    Entity guard_; // wake()
    Entity waitset_;
};

} // namespace envdesign::dds
