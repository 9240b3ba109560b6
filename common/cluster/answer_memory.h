#pragma once
// A planner's memory of recent answers by content: (spec hash, job kind, heuristic, task,
// configuration). The same content always has the same answer, whichever coordinator asks,
// so a job another coordinator (or this one before a restart) had done is answered at once.
// Only SOLVED and INEXPLICABLE answers are kept: a LIMIT answer depends on the time the job
// had. Bounded: past `capacity` answers, the least recently used go.
// Not thread-safe (the planner's mutex guards it).

#include "envdesign/evaluation_t.hpp"
#include "envdesign/job_t.hpp"

#include <list>
#include <optional>
#include <string>
#include <unordered_map>

namespace envdesign::cluster {

// What a job asks, independent of who asks and when.
std::string job_content(const envdesign::job_t &job);

// `answer` as the answer to `job`: its ids and coordinator, no planner work counted.
envdesign::evaluation_t readdressed(const envdesign::evaluation_t &answer,
                                    const envdesign::job_t &job, const std::string &sender);

class AnswerMemory {
public:
    explicit AnswerMemory(std::size_t capacity) : capacity_(capacity) {}

    // The answer kept for `job`'s content (now the most recently used).
    std::optional<envdesign::evaluation_t> find(const std::string &content);
    // Keeps `answer` if it is one to keep (see above).
    void keep(const std::string &content, const envdesign::evaluation_t &answer);
    static bool keepable(const envdesign::evaluation_t &answer);
    std::size_t size() const { return entries_.size(); }

private:
    std::size_t capacity_;
    std::list<std::string> recent_; // most recently used first
    std::unordered_map<std::string,
                       std::pair<envdesign::evaluation_t, std::list<std::string>::iterator>>
        entries_;
};

} // namespace envdesign::cluster
