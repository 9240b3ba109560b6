// A planner's specs (planner_specs.h): assembled from chunks, checked against their hash, and
// loaded trusting that hash (the coordinator ran the full check on these bytes).

#include "harness.h"

#include "bus/codec.h"
#include "cluster/planner_specs.h"
#include "cluster/spec_chunks.h"
#include "spec/spec_message.h"

namespace envdesign::cluster::testing {
namespace {

// `spec` encoded, cut into chunks and given to `specs`; its hash.
std::string give(PlannerSpecs &specs, const envdesign::spec_t &spec) {
    std::string bytes = bus::encode_message(spec);
    std::string hash = content_hash(bytes);
    std::string why;
    for (const auto &chunk : split_spec(bytes, hash, 1, "coordinator"))
        EXPECT_NE(specs.add_chunk(chunk, why), PlannerSpecs::Added::BAD) << why;
    return hash;
}

// remove-absent: a modification removes an init atom no task has; the coordinator's full
// check rejects it, a planner given the same bytes parses it without re-checking.
TEST(PlannerSpecs, LoadsWithoutTheFullCheck) {
    envdesign::spec_t spec =
        spec::bundle_spec(in_repo("tests/data/design/bad/remove-absent.textproto"));
    EXPECT_THROW(spec::load_spec(spec, spec::Checks::FULL), pddl::ParseError);
    PlannerSpecs specs(4);
    auto loaded = specs.load(give(specs, spec));
    ASSERT_TRUE(loaded);
    ASSERT_TRUE(loaded->problem) << loaded->error;
    EXPECT_EQ(loaded->problem->modifications.size(), 1u);
}

// Hostile bytes whose hash matches: a parse error is the spec's error, never a crash.
TEST(PlannerSpecs, ABadSpecIsAnError) {
    envdesign::spec_t spec =
        spec::bundle_spec(in_repo("examples/restaurant/c-two-tasks-t10.textproto"));
    spec.files[0].content = "(define (domain";
    PlannerSpecs specs(4);
    auto loaded = specs.load(give(specs, spec));
    ASSERT_TRUE(loaded);
    EXPECT_FALSE(loaded->problem);
    EXPECT_NE(loaded->error.find("domain.pddl:1:"), std::string::npos) << loaded->error;
}

} // namespace
} // namespace envdesign::cluster::testing
