// The arrivals topic's QoS. Everything is set explicitly, so that a Cyclone default or an
// XML profile changing cannot change what the bridge sees.

#include "dds/arrival_topic.h"

namespace envdesign::dds {
namespace {

// Shared by both sides: the reader must ask for at least what the writer offers, or they
// do not match (RELIABLE and TRANSIENT_LOCAL are requested/offered policies).
void set_common(const Qos &qos, int history) {
    // An arrival is a count: a lost one biases D, so delivery is reliable. A writer whose
    // readers fall behind blocks at most a second, then write() reports TIMEOUT.
    dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    // The writer keeps its recent samples for readers that join later: a bridge started
    // (or restarted) late still gets recent arrivals from every live site. TRANSIENT would
    // need a durability service, which Cyclone 0.10 does not have.
    dds_qset_durability(qos.get(), DDS_DURABILITY_TRANSIENT_LOCAL);
    // Per instance, i.e. per (problem, site): each site's recent history in its real mix.
    dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, history);
    // In the order received: a site is one writer, whose samples arrive in its order; the
    // arrival's own utime is data, checked by the bridge, not a delivery order.
    dds_qset_destination_order(qos.get(), DDS_DESTINATIONORDER_BY_RECEPTION_TIMESTAMP);
}

} // namespace

Qos arrival_writer_qos(int history) {
    Qos qos;
    set_common(qos, history);
    // What a late reader gets: Cyclone keeps a TRANSIENT_LOCAL writer's samples for late
    // joiners by the durability service's history (default KEEP_LAST 1), not by HISTORY.
    dds_qset_durability_service(qos.get(), 0, DDS_HISTORY_KEEP_LAST, history, DDS_LENGTH_UNLIMITED,
                                DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED);
    // A site that goes away does not dispose its instance: its arrivals happened; the
    // estimate forgets them by later arrivals (estimator.h), not by writer liveliness.
    dds_qset_writer_data_lifecycle(qos.get(), false);
    return qos;
}

Qos arrival_reader_qos(int history) {
    // KEEP_LAST bounds the reader's memory per instance: a flood overwrites the oldest
    // unread samples instead of blocking every writer behind a full KEEP_ALL history.
    Qos qos;
    set_common(qos, history);
    return qos;
}

} // namespace envdesign::dds
