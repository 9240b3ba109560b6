#include "design/evaluation/evaluation_record.h"

#include "design/model/numbers.h"

#include <bit>
#include <cstdint>

namespace envdesign::design {
namespace {

// Little-endian fixed-width fields, so a file means the same on any machine.
class Writer {
public:
    void byte(int b) { out_.push_back(static_cast<char>(b)); }
    void u64(std::uint64_t v) {
        for (int i = 0; i < 8; ++i)
            byte(static_cast<int>((v >> (8 * i)) & 0xff));
    }
    void real(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
    void text(const std::string &s) {
        u64(s.size());
        out_ += s;
    }
    void texts(const std::vector<std::string> &list) {
        u64(list.size());
        for (const auto &s : list)
            text(s);
    }
    std::string take() { return std::move(out_); }

private:
    std::string out_;
};

// Every read checks the size left; a short or malformed record reads as !ok().
class Reader {
public:
    explicit Reader(const std::string &in) : in_(in) {}
    int byte() { return need(1) ? static_cast<unsigned char>(in_[at_++]) : 0; }
    std::uint64_t u64() {
        std::uint64_t v = 0;
        for (int i = 0; i < 8; ++i)
            v |= static_cast<std::uint64_t>(byte()) << (8 * i);
        return v;
    }
    double real() { return std::bit_cast<double>(u64()); }
    std::string text() {
        std::uint64_t size = u64();
        if (!need(size))
            return {};
        std::string s = in_.substr(at_, size);
        at_ += size;
        return s;
    }
    std::vector<std::string> texts() {
        std::uint64_t n = u64();
        std::vector<std::string> list;
        for (std::uint64_t i = 0; i < n && ok_; ++i)
            list.push_back(text());
        return list;
    }
    bool ok() const { return ok_ && at_ == in_.size(); }
    bool at_end() const { return at_ == in_.size(); }

private:
    bool need(std::uint64_t n) {
        ok_ = ok_ && n <= in_.size() - at_;
        return ok_;
    }
    const std::string &in_;
    std::size_t at_ = 0;
    bool ok_ = true;
};

constexpr int EVALUATION_TAG = 'E';
constexpr int BOUND_TAG = 'B';

} // namespace

TaskKey digest_key(const std::string &text) {
    store::Digest d = store::sha256(text);
    TaskKey key;
    for (int i = 0; i < 8; ++i) {
        key.high = key.high << 8 | d.bytes[i];
        key.low = key.low << 8 | d.bytes[8 + i];
    }
    return key;
}

store::Digest record_name(RecordKind kind, const TaskKey &scope, const Configuration &configuration,
                          const TaskKey &task) {
    std::string text = "envdesign evaluation record " + std::to_string(RECORD_VERSION) + "\n";
    text += kind == RecordKind::EXPLICABILITY ? "explicability\n" : "robot-bound\n";
    text += scope.hex() + "\n";
    for (int m : configuration)
        text += std::to_string(m) + ",";
    text += "\n" + task.hex();
    return store::sha256(text);
}

std::string encode_evaluation(const TaskExplicability &e) {
    Writer w;
    w.byte(RECORD_VERSION);
    w.byte(EVALUATION_TAG);
    w.byte(e.status == ExplicabilityStatus::SOLVED ? 1 : 2);
    w.real(e.ie);
    w.real(e.robot_cost);
    w.real(e.human_plan_cost);
    w.byte(e.human_optimal_cost ? 1 : 0);
    w.real(e.human_optimal_cost.value_or(0));
    w.texts(e.plan);
    w.byte(e.human_plan ? 1 : 0);
    w.texts(e.human_plan.value_or(std::vector<std::string>{}));
    TaskExplanation x = e.explanation.value_or(TaskExplanation{});
    w.byte(e.explanation ? 1 : 0);
    w.byte(x.found ? 1 : 0);
    w.real(x.robot_optimal_cost);
    w.texts(x.robot_plan);
    w.texts(x.differences);
    if (e.optimal_actions) { // COST_OPTIMAL modes only: records of the others stay as they were
        w.byte(1);
        w.texts(*e.optimal_actions);
    }
    return w.take();
}

std::optional<TaskExplicability> decode_evaluation(const std::string &bytes) {
    Reader r(bytes);
    if (r.byte() != RECORD_VERSION || r.byte() != EVALUATION_TAG)
        return std::nullopt;
    TaskExplicability e;
    int status = r.byte();
    if (status != 1 && status != 2)
        return std::nullopt;
    e.status = status == 1 ? ExplicabilityStatus::SOLVED : ExplicabilityStatus::INEXPLICABLE;
    e.ie = r.real();
    e.robot_cost = r.real();
    e.human_plan_cost = r.real();
    bool has_optimal = r.byte() == 1;
    double optimal = r.real();
    if (has_optimal)
        e.human_optimal_cost = optimal;
    e.plan = r.texts();
    bool has_human_plan = r.byte() == 1;
    auto human_plan = r.texts();
    if (has_human_plan)
        e.human_plan = std::move(human_plan);
    bool has_explanation = r.byte() == 1;
    TaskExplanation x;
    x.found = r.byte() == 1;
    x.robot_optimal_cost = r.real();
    x.robot_plan = r.texts();
    x.differences = r.texts();
    if (has_explanation)
        e.explanation = std::move(x);
    if (!r.at_end()) { // optional, appended by COST_OPTIMAL modes
        if (r.byte() != 1)
            return std::nullopt;
        e.optimal_actions = r.texts();
    }
    if (!r.ok() || evaluation_problem(e)) // values re-checked as the wire checks them
        return std::nullopt;
    return e;
}

std::string encode_robot_bound(const RobotBound &bound) {
    Writer w;
    w.byte(RECORD_VERSION);
    w.byte(BOUND_TAG);
    w.real(bound.cost);
    if (bound.ie_floor) { // optional, appended: older records end after the cost
        w.byte(1);
        w.real(*bound.ie_floor);
    }
    if (bound.ie_floor && bound.explanation_floor) { // appended too, only after a floor
        w.byte(2);
        w.u64(static_cast<std::uint64_t>(*bound.explanation_floor));
    }
    return w.take();
}

std::optional<RobotBound> decode_robot_bound(const std::string &bytes) {
    Reader r(bytes);
    if (r.byte() != RECORD_VERSION || r.byte() != BOUND_TAG)
        return std::nullopt;
    RobotBound bound{r.real(), std::nullopt};
    if (!r.at_end()) {
        if (r.byte() != 1)
            return std::nullopt;
        bound.ie_floor = r.real();
    }
    if (!r.at_end()) {
        if (r.byte() != 2)
            return std::nullopt;
        std::uint64_t told = r.u64();
        if (!valid_explanation_floor(static_cast<double>(told)))
            return std::nullopt;
        bound.explanation_floor = static_cast<int>(told);
    }
    if (!r.ok() || !r.at_end() || !valid_plan_cost(bound.cost) ||
        (bound.ie_floor && !valid_ie(*bound.ie_floor)))
        return std::nullopt;
    return bound;
}

} // namespace envdesign::design
