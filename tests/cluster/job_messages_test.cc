// job_t's robot bound: it survives encoding and is checked like every number from the bus.

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

envdesign::job_t through_the_wire(const envdesign::job_t &m) {
    std::vector<std::uint8_t> bytes(m.getEncodedSize());
    EXPECT_EQ(m.encode(bytes.data(), 0, static_cast<int>(bytes.size())),
              static_cast<int>(bytes.size()));
    envdesign::job_t out;
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

} // namespace
} // namespace envdesign::wire
