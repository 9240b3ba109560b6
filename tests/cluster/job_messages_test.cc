// job_t's robot bound, and evaluation_t's floors: they survive encoding and are checked like
// every number from the bus.

#include "envdesign/evaluation_t.hpp"
#include "envdesign/job_t.hpp"
#include "spec/design_spec.h"
#include "wire/job_messages.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace envdesign::wire {
namespace {

design::DesignProblem paper() {
    return spec::load_design_problem(std::string(ENVDESIGN_TEST_DATA_ROOT) +
                                     "/tests/data/paper/blocksworld/20/design-t1.textproto");
}

// `m` encoded and decoded again, as a planner or the coordinator receives it.
template <class Message> Message through_the_wire(const Message &m) {
    std::vector<std::uint8_t> bytes(m.getEncodedSize());
    EXPECT_EQ(m.encode(bytes.data(), 0, static_cast<int>(bytes.size())),
              static_cast<int>(bytes.size()));
    Message out;
    EXPECT_EQ(out.decode(bytes.data(), 0, static_cast<int>(bytes.size())),
              static_cast<int>(bytes.size()));
    return out;
}

TEST(JobMessages, AGivenRobotBoundRoundTrips) {
    design::DesignProblem problem = paper();
    design::Job job{0, 2, design::JobKind::ROBOT_BOUND, 22.0};
    envdesign::job_t m = through_the_wire(job_message(job, {0, 3}, 7, "hash", 0, {}));
    EXPECT_FALSE(job_problem(m, problem));
    design::Job back = job_of(m);
    EXPECT_EQ(back.kind, design::JobKind::ROBOT_BOUND);
    EXPECT_EQ(back.task, 2);
    ASSERT_TRUE(back.robot_bound);
    EXPECT_EQ(*back.robot_bound, 22.0);

    design::Job none{0, 1, design::JobKind::ROBOT_BOUND, std::nullopt};
    EXPECT_FALSE(job_of(through_the_wire(job_message(none, {}, 7, "hash", 0, {}))).robot_bound);
}

TEST(JobMessages, ABadRobotBoundIsRejected) {
    design::DesignProblem problem = paper();
    envdesign::job_t m = job_message({0, 0, design::JobKind::ROBOT_BOUND, 5.0}, {}, 7, "h", 0, {});
    for (double bad : {-1.0, std::nan(""), 1e300}) {
        m.robot_bound = bad;
        auto why = job_problem(m, problem);
        ASSERT_TRUE(why) << bad;
        EXPECT_NE(why->find("robot bound"), std::string::npos) << *why;
    }
    m.robot_bound = INFINITY; // unsolvable: a bound like any other
    EXPECT_FALSE(job_problem(m, problem));
    envdesign::job_t explicability =
        job_message({0, 0, design::JobKind::EXPLICABILITY, std::nullopt}, {}, 7, "h", 0, {});
    explicability.has_robot_bound = true;
    explicability.robot_bound = 3;
    ASSERT_TRUE(job_problem(explicability, problem));
}

// The explaining robot's explanation floor travels with the IE floor, and only with it.
TEST(JobMessages, AnExplanationFloorTravelsWithItsIeFloor) {
    design::Job job{0, 1, design::JobKind::ROBOT_BOUND, std::nullopt};
    design::JobAnswer answer{job, 22.0, std::exp(8.0), {}, 2};
    envdesign::evaluation_t e{};
    put_answer(answer, e);
    e.kind = envdesign::job_t::KIND_ROBOT_BOUND;
    envdesign::evaluation_t back_message = through_the_wire(e);
    EXPECT_FALSE(evaluation_problem(back_message, envdesign::job_t::KIND_ROBOT_BOUND));
    design::JobAnswer back = job_answer(job, back_message);
    ASSERT_TRUE(back.explanation_floor);
    EXPECT_EQ(*back.explanation_floor, 2);
    EXPECT_EQ(*back.ie_floor, std::exp(8.0));

    answer.ie_floor.reset(); // no IE floor: no explanation floor either
    envdesign::evaluation_t bare{};
    put_answer(answer, bare);
    EXPECT_FALSE(bare.has_explanation_floor);

    for (int bad : {-1, 1048577}) {
        envdesign::evaluation_t forged = back_message;
        forged.explanation_floor = bad;
        auto why = evaluation_problem(forged, envdesign::job_t::KIND_ROBOT_BOUND);
        ASSERT_TRUE(why) << bad;
        EXPECT_NE(why->find("explanation floor"), std::string::npos) << *why;
    }
}

} // namespace
} // namespace envdesign::wire
