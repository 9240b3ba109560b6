// The arrival intake on arbitrary arrivals: no undefined behaviour (UBSan), and its counters
// never go negative (they are published by the bridge).

#include "arrivals/intake.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

using namespace envdesign::arrivals;

// Reads fixed-size fields from the front of the input; zeros once it runs out.
class Reader {
public:
    Reader(const std::uint8_t *data, std::size_t size) : data_(data), size_(size) {}
    bool empty() const { return at_ >= size_; }
    template <typename T> T number() {
        T value{};
        std::size_t n = std::min(sizeof(T), size_ - std::min(at_, size_));
        std::memcpy(&value, data_ + std::min(at_, size_), n);
        at_ += sizeof(T);
        return value;
    }
    std::string text() {
        std::size_t length = number<std::uint8_t>();
        std::size_t n = std::min(length, size_ - std::min(at_, size_));
        std::string s(reinterpret_cast<const char *>(data_ + std::min(at_, size_)), n);
        at_ += length;
        return s;
    }

private:
    const std::uint8_t *data_;
    std::size_t size_;
    std::size_t at_ = 0;
};

void expect_sane(const IntakeCounters &c) {
    bool sane =
        c.received >= 0 && c.sequence_gaps >= 0 && c.sequence_unseen >= 0 && c.site_restarts >= 0;
    for (long long n : c.by_verdict)
        sane = sane && n >= 0;
    if (!sane)
        std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    Reader in(data, size);
    IntakeConfig config;
    config.max_rate = in.number<std::uint8_t>() % 4 == 0 ? 0 : 5;
    config.max_sites = 4;
    ArrivalIntake intake(config);
    constexpr std::int64_t NOW = 1'700'000'000'000'000;
    double now = 0;
    while (!in.empty()) {
        Arrival a;
        a.problem_id = in.text();
        a.site = in.text();
        a.task = in.text();
        a.sequence = in.number<std::int64_t>();
        a.utime = in.number<std::uint8_t>() % 2 ? NOW : in.number<std::int64_t>();
        now += in.number<std::uint8_t>() * 0.01;
        intake.check(a, in.number<std::uint8_t>() % 8 != 0, now, NOW);
        expect_sane(intake.counters());
    }
    return 0;
}
