#include "cluster/answer_memory.h"

namespace envdesign::cluster {

std::string job_content(const envdesign::job_t &job) {
    std::string content = job.spec_hash + '/' + std::to_string(job.kind) + '/' +
                          std::to_string(job.heuristic) + '/' + std::to_string(job.task) + '/';
    for (auto m : job.modifications)
        content += std::to_string(m) + ',';
    return content;
}

envdesign::evaluation_t readdressed(const envdesign::evaluation_t &answer,
                                    const envdesign::job_t &job, const std::string &sender) {
    envdesign::evaluation_t out = answer;
    out.request_id = job.request_id;
    out.sender = sender;
    out.coordinator = job.sender;
    out.job_id = job.job_id;
    out.planner_runs = 0;
    out.cache_hits = 0;
    out.groundings_skipped = 0;
    out.planner_seconds = 0;
    out.seconds = 0;
    out.queued_seconds = 0;
    return out;
}

bool AnswerMemory::keepable(const envdesign::evaluation_t &answer) {
    return answer.status == envdesign::evaluation_t::STATUS_SOLVED ||
           answer.status == envdesign::evaluation_t::STATUS_INEXPLICABLE;
}

std::optional<envdesign::evaluation_t> AnswerMemory::find(const std::string &content) {
    auto it = entries_.find(content);
    if (it == entries_.end())
        return std::nullopt;
    recent_.splice(recent_.begin(), recent_, it->second.second);
    return it->second.first;
}

void AnswerMemory::keep(const std::string &content, const envdesign::evaluation_t &answer) {
    if (capacity_ == 0 || !keepable(answer) || entries_.count(content))
        return;
    recent_.push_front(content);
    entries_.emplace(content, std::make_pair(answer, recent_.begin()));
    while (entries_.size() > capacity_) {
        entries_.erase(recent_.back());
        recent_.pop_back();
    }
}

} // namespace envdesign::cluster
