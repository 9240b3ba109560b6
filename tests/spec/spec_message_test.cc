// A spec received over the bus (spec_t) loads in memory as the same file does from disk; its
// errors name the client's files; the planner's trusted load parses without the full check.

#include "design/evaluation/evaluate_design.h"
#include "design/evaluation/local_evaluator.h"
#include "spec/design_spec.h"
#include "spec/spec_bundle.h"
#include "spec/spec_message.h"
#include "spec/spec_reader.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <unistd.h>

namespace envdesign::spec {
namespace {

namespace fs = std::filesystem;

std::string in_repo(const std::string &relative) {
    return std::string(ENVDESIGN_TEST_DATA_ROOT) + "/" + relative;
}

const std::string RESTAURANT_C = in_repo("examples/restaurant/c-two-tasks-t10.textproto");

// The message error `e` would be at `field` of the spec file `path`.
pddl::Location field_of(const std::string &path, const std::string &field) {
    return read_spec_file(path).at(field);
}

// Sets TMPDIR to a fresh empty directory for the test's duration.
class EmptyTmpdir {
public:
    EmptyTmpdir() {
        dir_ = fs::path(::testing::TempDir()) / ("specmem-" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        const char *old = std::getenv("TMPDIR");
        if (old)
            old_ = old;
        ::setenv("TMPDIR", dir_.c_str(), 1);
    }
    ~EmptyTmpdir() {
        if (old_)
            ::setenv("TMPDIR", old_->c_str(), 1);
        else
            ::unsetenv("TMPDIR");
        fs::remove_all(dir_);
    }
    bool empty() const { return fs::is_empty(dir_); }

private:
    fs::path dir_;
    std::optional<std::string> old_;
};

TEST(SpecMessage, LoadsInMemoryAsTheFileDoes) {
    envdesign::spec_t message = bundle_spec(RESTAURANT_C);
    EXPECT_EQ(message.files.size(), 5u);
    EmptyTmpdir tmp;
    design::DesignProblem remote = load_spec(message, Checks::FULL);
    EXPECT_TRUE(tmp.empty()) << "loading wrote to $TMPDIR";
    design::DesignProblem local = load_design_problem(RESTAURANT_C);
    ASSERT_EQ(remote.tasks.size(), local.tasks.size());
    for (std::size_t t = 0; t < local.tasks.size(); ++t) {
        EXPECT_EQ(remote.tasks[t].name, local.tasks[t].name);
        EXPECT_DOUBLE_EQ(remote.tasks[t].probability, local.tasks[t].probability);
        EXPECT_EQ(remote.tasks[t].robot_problem.init.size(),
                  local.tasks[t].robot_problem.init.size());
    }
    ASSERT_EQ(remote.modifications.size(), local.modifications.size());
    for (std::size_t m = 0; m < local.modifications.size(); ++m)
        EXPECT_EQ(remote.modifications[m].name, local.modifications[m].name);
    EXPECT_EQ(remote.weights.horizon, 10);
    // The paper's restaurant (c): the two barriers at 85.263215599 (tests/design/restaurant).
    design::LocalEvaluator evaluator(remote, 1);
    design::DesignResult r = design::evaluate_design(
        remote, evaluator, design::configuration_of(remote, {"barrier-00-01", "barrier-10-11"}),
        design::Deadline{});
    ASSERT_TRUE(r.best);
    EXPECT_NEAR(r.best->objective.value, 85.263215599, 1e-6);
}

TEST(SpecMessage, JsonSpecsToo) {
    envdesign::spec_t message = bundle_spec(in_repo("tests/data/design/restaurant-c.json"));
    EXPECT_FALSE(message.files.empty());
    EXPECT_EQ(load_spec(message, Checks::FULL).modifications.size(), 6u);
}

TEST(SpecMessage, AFileTheRequestDoesNotCarryIsAnErrorAtItsField) {
    envdesign::spec_t message = bundle_spec(RESTAURANT_C);
    const std::string problem = read_spec_file(RESTAURANT_C).message.task(1).problem();
    std::erase_if(message.files, [&](const auto &f) { return f.path == problem; });
    message.num_files = static_cast<std::int16_t>(message.files.size());
    try {
        load_spec(message, Checks::TRUSTED_BY_HASH);
        FAIL() << "no error";
    } catch (const pddl::ParseError &e) {
        EXPECT_EQ(e.message(), "the request does not carry '" + problem + "' (task[1].problem)");
        pddl::Location want = field_of(RESTAURANT_C, "task[1].problem");
        EXPECT_EQ(e.location().to_string(), want.to_string());
        EXPECT_GT(want.line, 1);
    }
}

TEST(SpecMessage, APddlErrorNamesTheClientsFileAndPosition) {
    envdesign::spec_t message = bundle_spec(RESTAURANT_C);
    auto &file = message.files[1];
    file.content = "(define (problem p) (:domain restaurant)\n  (:objects x - nothing))";
    try {
        load_spec(message, Checks::FULL);
        FAIL() << "no error";
    } catch (const pddl::ParseError &e) {
        EXPECT_EQ(e.location().file, path_beside(RESTAURANT_C, file.path)) << e.what();
        EXPECT_EQ(e.location().line, 2) << e.what();
        EXPECT_EQ(e.location().column, 17) << e.what();
        EXPECT_NE(std::string(e.what()).find("note: in the file named by"), std::string::npos);
    }
}

// remove-absent: a modification removes an init atom no task has. Only the full check
// (applying every modification STRICT) finds that; the parse is fine.
TEST(SpecMessage, TrustedByHashParsesWithoutTheFullCheck) {
    std::string path = in_repo("tests/data/design/bad/remove-absent.textproto");
    envdesign::spec_t message = bundle_spec(path);
    try {
        load_spec(message, Checks::FULL);
        FAIL() << "the full check accepted a modification that cannot apply";
    } catch (const pddl::ParseError &e) {
        EXPECT_NE(e.message().find("is not in the initial state"), std::string::npos) << e.what();
        EXPECT_EQ(e.location().file, path);
        EXPECT_EQ(e.location().line, 6);
    }
    design::DesignProblem trusted = load_spec(message, Checks::TRUSTED_BY_HASH);
    ASSERT_EQ(trusted.modifications.size(), 1u);
    EXPECT_EQ(trusted.modifications[0].edits.size(), 1u);
}

// What the full check would have rejected reaches a planner's evaluator only through hostile
// bytes with a matching hash: evaluating such a design is an error (or, for edits that a
// LENIENT apply skips, a result), never a crash. The planner answers a thrown error as
// STATUS_BAD_INPUT (planner.cc).
TEST(SpecMessage, TrustedSpecsFailPerEvaluationNotPerProcess) {
    struct Case {
        const char *file;
        bool throws;
    };
    for (Case c : {Case{"remove-absent", false}, Case{"unknown-action", false}, Case{"arity", true},
                   Case{"unknown-object", true}, Case{"unknown-parameter", true}}) {
        std::string path = in_repo("tests/data/design/bad/") + c.file + ".textproto";
        envdesign::spec_t message = bundle_spec(path);
        EXPECT_THROW(load_spec(message, Checks::FULL), pddl::ParseError) << c.file;
        design::DesignProblem problem = load_spec(message, Checks::TRUSTED_BY_HASH);
        design::LocalEvaluator evaluator(problem, 1);
        auto evaluate = [&] {
            return design::evaluate_design(
                problem, evaluator, design::configuration_of(problem, {"m"}), design::Deadline{});
        };
        if (c.throws)
            EXPECT_THROW(evaluate(), pddl::ParseError) << c.file;
        else
            EXPECT_TRUE(evaluate().best) << c.file;
    }
}

TEST(SpecMessage, TrustedByHashStillParses) {
    envdesign::spec_t message = bundle_spec(RESTAURANT_C);
    message.text += "\nmodification { name: \"x\" edit { add_init: \"(open\" } }\n";
    EXPECT_THROW(load_spec(message, Checks::TRUSTED_BY_HASH), pddl::ParseError);
    message = bundle_spec(RESTAURANT_C);
    message.files[0].content = "(define (domain";
    EXPECT_THROW(load_spec(message, Checks::TRUSTED_BY_HASH), pddl::ParseError);
}

TEST(SpecBundle, FindsThePathFieldsOfTheTextFormat) {
    auto paths =
        named_paths("# comment robot_domain: \"no\"\n"
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

// The same message as a local load gives for the same file (design_spec.h, DiskFiles).
TEST(SpecBundle, MissingFileIsTheLocalMessage) {
    std::string path = in_repo("tests/data/design/bad/missing-file.textproto");
    std::string local, bundled;
    try {
        load_design_problem(path);
    } catch (const pddl::ParseError &e) {
        local = e.what();
    }
    try {
        bundle_spec(path);
    } catch (const pddl::ParseError &e) {
        bundled = e.what();
    }
    EXPECT_NE(local.find("missing-file.textproto:"), std::string::npos) << local;
    EXPECT_NE(local.find("cannot open"), std::string::npos) << local;
    EXPECT_EQ(bundled, local);
}

} // namespace
} // namespace envdesign::spec
