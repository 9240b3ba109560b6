#include "arrivals/arrival_source.h"

#include <chrono>

namespace envdesign::arrivals {

ArrivalSource::~ArrivalSource() = default;

void ArrivalQueue::push(Arrival arrival) { queue_.push(std::move(arrival)); }

std::size_t ArrivalQueue::size() const { return queue_.size(); }

bool ArrivalQueue::wait(double timeout_s) {
    return queue_.wait_for(std::chrono::duration<double>(timeout_s));
}

std::size_t ArrivalQueue::take(std::vector<Arrival> &out, std::size_t max) {
    return queue_.take(out, max);
}

void ArrivalQueue::wake() { queue_.wake(); }

} // namespace envdesign::arrivals
