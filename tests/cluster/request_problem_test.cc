// The coordinator's check of a design request's numbers (issue 21, coordinator.h
// request_problem): a time limit that is not finite (-inf passed: only NaN was refused) and a
// max_design_size above design::DESIGN_SIZE (not checked at all) are that request's error;
// what a client sends by default (-1: the spec's) and the tops of the ranges pass.

#include "cluster/coordinator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace envdesign::cluster {
namespace {

envdesign::design_request_t sound_request() {
    envdesign::design_request_t r{};
    r.sender = "client";
    r.spec.name = "spec.textproto";
    r.time_limit_s = -1;
    r.max_design_size = -1;
    return r;
}

TEST(RequestProblem, DefaultsAndTheTopsOfTheRangesPass) {
    envdesign::design_request_t r = sound_request();
    EXPECT_EQ(request_problem(r, 1 << 20), std::nullopt);
    r.time_limit_s = 1e7;
    r.max_design_size = 100000;
    EXPECT_EQ(request_problem(r, 1 << 20), std::nullopt);
    r.time_limit_s = 0;
    r.max_design_size = 0;
    EXPECT_EQ(request_problem(r, 1 << 20), std::nullopt);
}

TEST(RequestProblem, TimeLimitsThatAreNoNumberOrTooLargeAreRefused) {
    const double inf = std::numeric_limits<double>::infinity();
    for (double limit : {-inf, inf, std::nan(""), 1e7 + 1, 1e10}) {
        envdesign::design_request_t r = sound_request();
        r.time_limit_s = limit;
        auto why = request_problem(r, 1 << 20);
        ASSERT_TRUE(why.has_value()) << limit;
        EXPECT_EQ(why->rfind("the time limit must be a number in", 0), 0u) << *why;
    }
}

TEST(RequestProblem, ADesignSizeAboveItsRangeIsRefused) {
    envdesign::design_request_t r = sound_request();
    r.max_design_size = 100001;
    EXPECT_EQ(request_problem(r, 1 << 20), "max_design_size 100001 is above 100000");
    r.max_design_size = std::numeric_limits<std::int32_t>::max();
    EXPECT_TRUE(request_problem(r, 1 << 20).has_value());
}

} // namespace
} // namespace envdesign::cluster
