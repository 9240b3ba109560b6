#include "arrival_publisher.h"

#include <chrono>

namespace envdesign::arrivals_client {

int64_t now_utime() {
    return std::chrono::duration_cast<std::chrono::microseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
}

ArrivalPublisher::ArrivalPublisher(PublisherOptions options)
    : options_(std::move(options)), writer_(options_.domain, options_.history) {}

int64_t ArrivalPublisher::publish(const std::string &task, const std::string &problem,
                                  const std::string &human_problem) {
    writer_.write({options_.problem_id, options_.site, task, sequence_ + 1, now_utime(), problem,
                   human_problem});
    return ++sequence_; // only once written: a failed write does not skip a number
}

void ArrivalPublisher::publish_raw(const arrivals::Arrival &arrival) { writer_.write(arrival); }

} // namespace envdesign::arrivals_client
