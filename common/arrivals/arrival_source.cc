#include "arrivals/arrival_source.h"

#include <chrono>

namespace envdesign::arrivals {

ArrivalSource::~ArrivalSource() = default;

void ArrivalQueue::push(Arrival arrival) {
    {
        std::lock_guard lock(mutex_);
        queue_.push_back(std::move(arrival));
    }
    changed_.notify_all();
}

std::size_t ArrivalQueue::size() const {
    std::lock_guard lock(mutex_);
    return queue_.size();
}

bool ArrivalQueue::wait(double timeout_s) {
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, std::chrono::duration<double>(timeout_s),
                      [&] { return woken_ || !queue_.empty(); });
    woken_ = false; // one wake() ends one wait
    return !queue_.empty();
}

std::size_t ArrivalQueue::take(std::vector<Arrival> &out, std::size_t max) {
    std::lock_guard lock(mutex_);
    std::size_t n = 0;
    for (; n < max && !queue_.empty(); ++n) {
        out.push_back(std::move(queue_.front()));
        queue_.pop_front();
    }
    return n;
}

void ArrivalQueue::wake() {
    {
        std::lock_guard lock(mutex_);
        woken_ = true;
    }
    changed_.notify_all();
}

} // namespace envdesign::arrivals
