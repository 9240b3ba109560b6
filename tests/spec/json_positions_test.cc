// Hostile JSON specs (issue 10): deep nesting and numbers beyond a double fail as input
// errors naming the line and column, before any recursive reader sees them.

#include "../cli/run_command.h"
#include "spec/json_positions.h"
#include "spec/spec_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace envdesign::spec {
namespace {

std::string nested_arrays(int depth) {
    return "{\"task\": " + std::string(depth, '[') + std::string(depth, ']') + "}";
}

TEST(JsonLimits, DeepNestingIsAnErrorAtTheLevelTooDeep) {
    // 100 000 levels crashed the coordinator (SIGSEGV in the position scanner).
    try {
        read_spec_text(nested_arrays(100'000), "deep.json");
        FAIL() << "no error";
    } catch (const pddl::ParseError &e) {
        // '{' is level 1, so the 100th '[' (column 10 + 99) is level 101.
        EXPECT_EQ(e.location().to_string(), "deep.json:1:109");
        EXPECT_NE(std::string(e.what()).find("nested more than 100 deep"), std::string::npos);
    }
}

TEST(JsonLimits, NestingUpToTheLimitIsNotRejectedForDepth) {
    try {
        check_json_limits(nested_arrays(MAX_JSON_DEPTH - 1), "ok.json");
    } catch (const pddl::ParseError &e) {
        FAIL() << e.what();
    }
    // Brackets inside strings do not count.
    EXPECT_NO_THROW(check_json_limits("{\"a\": \"" + std::string(1000, '[') + "\"}", "s.json"));
}

TEST(JsonLimits, NumbersBeyondADoubleNameTheirPosition) {
    for (const char *number : {"1e400", "-1e400", "123456789e999"}) {
        std::string text = std::string("{\"alpha\": 1,\n \"beta\": ") + number + "}";
        try {
            read_spec_text(text, "big.json");
            FAIL() << number << ": no error";
        } catch (const pddl::ParseError &e) {
            EXPECT_EQ(e.location().to_string(), "big.json:2:10") << number;
            EXPECT_NE(std::string(e.what()).find("beyond the range of a double"),
                      std::string::npos);
        }
    }
    EXPECT_NO_THROW(check_json_limits("{\"beta\": 1e-400, \"alpha\": 1.5e300}", "fine.json"));
}

// The command line: exit 2 and FILE:LINE:COL, not exit 1 without a position.
TEST(JsonLimits, TheCliExitsTwoNamingTheFile) {
    auto dir = std::filesystem::temp_directory_path() / "envdesign-json-limits";
    std::filesystem::create_directories(dir);
    std::string big = (dir / "big.json").string();
    std::ofstream(big) << "{\"alpha\": 1e400}\n";
    auto result = envdesign::testing::run_envdesign("design " + big + " --json");
    EXPECT_EQ(result.exit_code, 2) << result.out;
    EXPECT_NE(result.out.find(big + ":1:11: error:"), std::string::npos) << result.out;
    std::string deep = (dir / "deep.json").string();
    std::ofstream(deep) << nested_arrays(100'000);
    result = envdesign::testing::run_envdesign("design " + deep);
    EXPECT_EQ(result.exit_code, 2) << result.out;
    EXPECT_NE(result.out.find(deep + ":1:109: error:"), std::string::npos) << result.out;
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace envdesign::spec
