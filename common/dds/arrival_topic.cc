#include "dds/arrival_topic.h"

#include "task_arrival.h"

#include <algorithm>
#include <chrono>

namespace envdesign::dds {
namespace {

dds_duration_t nanoseconds(double seconds) {
    return seconds <= 0 ? 0 : static_cast<dds_duration_t>(std::min(seconds, 1e9) * 1e9);
}

Entity make_participant(dds_domainid_t domain) {
    return Entity(dds_create_participant(domain, nullptr, nullptr), "create DDS participant");
}

Entity make_topic(const Entity &participant) {
    return Entity(dds_create_topic(participant.get(), &envdesign_dds_TaskArrival_desc,
                                   ARRIVAL_TOPIC, nullptr, nullptr),
                  "create TaskArrival topic");
}

arrivals::Arrival from_sample(const envdesign_dds_TaskArrival &s) {
    auto text = [](const char *p) { return p ? std::string(p) : std::string(); };
    return {text(s.problem_id), text(s.site),         text(s.task), s.sequence_number, s.utime,
            text(s.problem),    text(s.human_problem)};
}

} // namespace

ArrivalWriter::ArrivalWriter(dds_domainid_t domain, int history)
    : participant_(make_participant(domain)), topic_(make_topic(participant_)) {
    Qos qos = arrival_writer_qos(history);
    writer_ = Entity(dds_create_writer(participant_.get(), topic_.get(), qos.get(), nullptr),
                     "create TaskArrival writer");
}

void ArrivalWriter::write(const arrivals::Arrival &a) {
    // The C sample only borrows the strings; dds_write serialises before returning.
    envdesign_dds_TaskArrival sample{};
    sample.problem_id = const_cast<char *>(a.problem_id.c_str());
    sample.site = const_cast<char *>(a.site.c_str());
    sample.task = const_cast<char *>(a.task.c_str());
    sample.sequence_number = a.sequence;
    sample.utime = a.utime;
    sample.problem = const_cast<char *>(a.problem.c_str());
    sample.human_problem = const_cast<char *>(a.human_problem.c_str());
    check(dds_write(writer_.get(), &sample), "write TaskArrival");
}

int ArrivalWriter::matched_readers() const {
    dds_publication_matched_status_t status;
    check(dds_get_publication_matched_status(writer_.get(), &status),
          "get publication matched status");
    return static_cast<int>(status.current_count);
}

bool ArrivalWriter::wait_for_readers(int count, double timeout_s) {
    Entity waitset(dds_create_waitset(participant_.get()), "create waitset");
    check(dds_set_status_mask(writer_.get(), DDS_PUBLICATION_MATCHED_STATUS),
          "set writer status mask");
    check(dds_waitset_attach(waitset.get(), writer_.get(), 0), "attach writer to waitset");
    auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (matched_readers() < count) {
        double left =
            std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
        if (left <= 0)
            return false;
        check(dds_waitset_wait(waitset.get(), nullptr, 0, nanoseconds(left)), "wait for readers");
    }
    return true;
}

bool ArrivalWriter::wait_for_acks(double timeout_s) {
    dds_return_t rc = dds_wait_for_acks(writer_.get(), nanoseconds(timeout_s));
    if (rc == DDS_RETCODE_TIMEOUT)
        return false;
    check(rc, "wait for acknowledgements");
    return true;
}

ArrivalReader::ArrivalReader(dds_domainid_t domain, int history)
    : participant_(make_participant(domain)), topic_(make_topic(participant_)) {
    Qos qos = arrival_reader_qos(history);
    reader_ = Entity(dds_create_reader(participant_.get(), topic_.get(), qos.get(), nullptr),
                     "create TaskArrival reader");
    data_ = Entity(dds_create_readcondition(reader_.get(), DDS_ANY_STATE), "create read condition");
    guard_ = Entity(dds_create_guardcondition(participant_.get()), "create guard condition");
    waitset_ = Entity(dds_create_waitset(participant_.get()), "create waitset");
    check(dds_waitset_attach(waitset_.get(), data_.get(), 0), "attach read condition");
    check(dds_waitset_attach(waitset_.get(), guard_.get(), 0), "attach guard condition");
}

bool ArrivalReader::wait(double timeout_s) {
    dds_return_t n = check(dds_waitset_wait(waitset_.get(), nullptr, 0, nanoseconds(timeout_s)),
                           "wait for arrivals");
    bool woken = false;
    check(dds_take_guardcondition(guard_.get(), &woken), "reset guard condition");
    return n > 0 && dds_triggered(data_.get()) > 0;
}

std::size_t ArrivalReader::take(std::vector<arrivals::Arrival> &out, std::size_t max) {
    constexpr int BATCH = 256;
    void *samples[BATCH];
    dds_sample_info_t infos[BATCH];
    std::size_t taken = 0;
    while (taken < max) {
        int want = static_cast<int>(std::min<std::size_t>(BATCH, max - taken));
        samples[0] = nullptr; // loaned samples: no copies of the strings until from_sample
        dds_return_t n =
            check(dds_take(reader_.get(), samples, infos, want, want), "take TaskArrival samples");
        for (int i = 0; i < n; ++i) {
            if (!infos[i].valid_data)
                continue;
            out.push_back(from_sample(*static_cast<envdesign_dds_TaskArrival *>(samples[i])));
            ++taken;
        }
        if (n > 0)
            check(dds_return_loan(reader_.get(), samples, n), "return loan");
        if (n < want)
            break;
    }
    return taken;
}

void ArrivalReader::wake() {
    check(dds_set_guardcondition(guard_.get(), true), "set guard condition");
}

int ArrivalReader::matched_writers() const {
    dds_subscription_matched_status_t status;
    check(dds_get_subscription_matched_status(reader_.get(), &status),
          "get subscription matched status");
    return static_cast<int>(status.current_count);
}

} // namespace envdesign::dds
