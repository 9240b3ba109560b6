#include "arrivals/intake.h"

#include <algorithm>
#include <limits>

namespace envdesign::arrivals {
namespace {

bool good_name(const std::string &name, std::size_t max_length) {
    if (name.size() > max_length)
        return false;
    return std::none_of(name.begin(), name.end(), [](char c) {
        auto u = static_cast<unsigned char>(c);
        return u < 0x20 || u == 0x7f;
    });
}

// Counters stop at the largest value instead of overflowing: sequence numbers near INT64_MAX
// (a forged or corrupt sample) would otherwise make them negative on the bus.
void add_saturating(long long &counter, long long amount) {
    counter = amount > std::numeric_limits<long long>::max() - counter
                  ? std::numeric_limits<long long>::max()
                  : counter + amount;
}

} // namespace

const char *to_string(Verdict verdict) {
    switch (verdict) {
    case Verdict::ACCEPTED:
        return "accepted";
    case Verdict::UNKNOWN_PROBLEM:
        return "unknown_problem";
    case Verdict::EMPTY_TASK:
        return "empty_task";
    case Verdict::BAD_NAME:
        return "bad_name";
    case Verdict::TOO_LARGE:
        return "too_large";
    case Verdict::BAD_TIMESTAMP:
        return "bad_timestamp";
    case Verdict::BAD_SEQUENCE:
        return "bad_sequence";
    case Verdict::DUPLICATE:
        return "duplicate";
    case Verdict::TOO_MANY_SITES:
        return "too_many_sites";
    case Verdict::RATE_LIMITED:
        return "rate_limited";
    }
    return "?";
}

Verdict ArrivalIntake::check(const Arrival &arrival, bool problem_known, double now,
                             int64_t now_utime) {
    ++counters_.received;
    Verdict verdict = check_fields(arrival, problem_known, now_utime);
    // The sequence is followed for every sample that names a known problem and a usable
    // site, good content or not: a sample that arrived is not a lost one.
    bool trackable =
        problem_known && arrival.sequence > 0 && good_name(arrival.site, config_.max_name_length);
    if (trackable) {
        auto key = std::make_pair(arrival.problem_id, arrival.site);
        auto it = sites_.find(key);
        if (it == sites_.end() && sites_.size() >= config_.max_sites) {
            if (verdict == Verdict::ACCEPTED)
                verdict = Verdict::TOO_MANY_SITES;
        } else {
            if (it == sites_.end())
                it = sites_.emplace(key, Site{0, config_.burst, now}).first;
            Verdict order = check_sequence(it->second, arrival.sequence);
            if (verdict == Verdict::ACCEPTED)
                verdict = order;
            if (verdict == Verdict::ACCEPTED && !take_token(it->second, now))
                verdict = Verdict::RATE_LIMITED;
        }
    }
    ++counters_.by_verdict[static_cast<int>(verdict)];
    double ahead_s = (static_cast<double>(arrival.utime) - static_cast<double>(now_utime)) * 1e-6;
    last_skewed_ = verdict == Verdict::ACCEPTED && ahead_s > config_.max_future_s;
    if (last_skewed_) {
        ++counters_.clock_skewed;
        counters_.last_skew_s = ahead_s;
    }
    return verdict;
}

Verdict ArrivalIntake::check_fields(const Arrival &a, bool problem_known, int64_t now_utime) const {
    if (!problem_known)
        return Verdict::UNKNOWN_PROBLEM;
    if (a.task.empty())
        return Verdict::EMPTY_TASK;
    std::size_t n = config_.max_name_length;
    if (!good_name(a.task, n) || !good_name(a.site, n) || !good_name(a.problem_id, n))
        return Verdict::BAD_NAME;
    if (a.problem.size() + a.human_problem.size() > config_.max_problem_bytes)
        return Verdict::TOO_LARGE;
    // In double seconds, so that absurd values (INT64_MIN, INT64_MAX) cannot overflow.
    double ahead_s = (static_cast<double>(a.utime) - static_cast<double>(now_utime)) * 1e-6;
    // Ahead by more than max_future_s but less than max_age_s: a skewed clock (check()
    // counts it); further ahead than any clock is wrong: garbage.
    if (a.utime <= 0 || ahead_s > config_.max_age_s || -ahead_s > config_.max_age_s)
        return Verdict::BAD_TIMESTAMP;
    if (a.sequence <= 0)
        return Verdict::BAD_SEQUENCE;
    return Verdict::ACCEPTED;
}

Verdict ArrivalIntake::check_sequence(Site &site, int64_t sequence) {
    if (site.last_sequence == 0) { // the first arrival seen from this site
        add_saturating(counters_.sequence_unseen, sequence - 1);
        site.last_sequence = sequence;
        return Verdict::ACCEPTED;
    }
    if (sequence == 1 && site.last_sequence > 1) {
        ++counters_.site_restarts;
        site.last_sequence = 1;
        return Verdict::ACCEPTED;
    }
    if (sequence <= site.last_sequence)
        return Verdict::DUPLICATE;
    add_saturating(counters_.sequence_gaps, sequence - site.last_sequence - 1);
    site.last_sequence = sequence;
    return Verdict::ACCEPTED;
}

bool ArrivalIntake::take_token(Site &site, double now) {
    if (config_.max_rate <= 0)
        return true;
    site.tokens =
        std::min(config_.burst, site.tokens + (now - site.refilled_at) * config_.max_rate);
    site.refilled_at = now;
    if (site.tokens < 1)
        return false;
    site.tokens -= 1;
    return true;
}

LogThrottle::Decision LogThrottle::should_log(Verdict verdict, double now) {
    Kind &k = kinds_[static_cast<int>(verdict)];
    ++k.seen;
    if (k.seen <= first_ || now - k.logged_at >= interval_s_) {
        Decision d{true, k.suppressed};
        k.suppressed = 0;
        k.logged_at = now;
        return d;
    }
    ++k.suppressed;
    return {};
}

std::vector<std::pair<Verdict, long long>> LogThrottle::overdue(double now) {
    std::vector<std::pair<Verdict, long long>> out;
    for (int v = 0; v < VERDICTS; ++v) {
        Kind &k = kinds_[v];
        if (k.suppressed > 0 && now - k.logged_at >= interval_s_) {
            out.emplace_back(static_cast<Verdict>(v), k.suppressed);
            k.suppressed = 0;
            k.logged_at = now;
        }
    }
    return out;
}

} // namespace envdesign::arrivals
