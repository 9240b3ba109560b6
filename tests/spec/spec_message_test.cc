// A spec received over the bus loads as the same file does locally; its errors name the
// client's files.

#include "harness.h"

#include "cluster/spec_loader.h"

namespace envdesign::cluster::testing {
namespace {

TEST(SpecLoader, LoadsWhatTheClientBundled) {
    std::string path = in_repo("examples/restaurant/c-two-tasks-t10.textproto");
    envdesign::spec_t spec = client::bundle_spec(path);
    EXPECT_EQ(spec.files.size(), 5u);
    design::DesignProblem remote = load_spec(spec, std::filesystem::temp_directory_path());
    design::DesignProblem local = design::load_design_problem(path);
    EXPECT_EQ(remote.tasks.size(), local.tasks.size());
    EXPECT_EQ(remote.modifications.size(), local.modifications.size());
    EXPECT_EQ(remote.weights.horizon, 10);
}

TEST(SpecLoader, JsonSpecsToo) {
    std::string path = in_repo("tests/data/design/restaurant-c.json");
    envdesign::spec_t spec = client::bundle_spec(path);
    EXPECT_FALSE(spec.files.empty());
    EXPECT_NO_THROW(load_spec(spec, std::filesystem::temp_directory_path()));
}

TEST(SpecLoader, ErrorsNameTheClientsFiles) {
    std::string path = in_repo("examples/restaurant/c-two-tasks-t10.textproto");
    envdesign::spec_t spec = client::bundle_spec(path);
    spec.files[1].content = "(define (problem p) (:domain restaurant) (:objects x - nothing))";
    try {
        load_spec(spec, std::filesystem::temp_directory_path());
        FAIL() << "no error";
    } catch (const pddl::ParseError &e) {
        std::string message = e.what();
        EXPECT_EQ(message.find("envdesign-spec-"), std::string::npos) << message;
        EXPECT_NE(message.find(spec.files[1].path), std::string::npos) << message;
    }
}

TEST(SpecBundle, FindsThePathFieldsOfTheTextFormat) {
    auto paths =
        client::named_paths("# comment robot_domain: \"no\"\n"
                            "robot_domain: \"d.pddl\"\n"
                            "task { name: \"t\" problem: 'p' \"1.pddl\" }\n"
                            "task: { human_problem: \"h.pddl\" problem: \"p2.pddl\" }\n"
                            "modification { name: \"problem\" edit { add_init: \"(problem)\" } }\n",
                            false);
    ASSERT_EQ(paths.size(), 4u);
    EXPECT_EQ(paths[0].path, "d.pddl");
    EXPECT_EQ(paths[0].line, 2);
    EXPECT_EQ(paths[1].path, "p1.pddl");
    EXPECT_EQ(paths[1].field, "task[0].problem");
    EXPECT_EQ(paths[2].field, "task[1].human_problem");
    EXPECT_EQ(paths[3].path, "p2.pddl");
}

TEST(SpecBundle, MissingFileIsTheLocalMessage) {
    try {
        client::bundle_spec(in_repo("tests/data/design/bad/missing-file.textproto"));
        FAIL() << "no error";
    } catch (const client::SpecError &e) {
        EXPECT_NE(std::string(e.what()).find("missing-file.textproto:"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos);
    }
}

} // namespace
} // namespace envdesign::cluster::testing
