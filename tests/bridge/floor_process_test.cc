// A floor, live (issue 22): the example warehouse imported by `envdesign floor import`, its
// tasks named vI-vJ by their places, followed by real processes over loopback:
// envdesign-arrivals (DDS) -> envdesign-bridge -> ENVDESIGN_RESULT. The trips are replayed as
// a fleet logs them, from and to by the places' names (`--floor DIR` names their tasks). Under the
// spec's equal weights the design is {gap-barrier, top-aisle-marking}; when nearly every arrival is
// pick_a -> dock (v19-v16, the 40 m detour round the racks) and the rest dock -> pack
// (v16-v24, straight), the gap in the southern rack no longer pays and the design becomes
// {top-aisle-marking}: the one a self-contained `envdesign design` gives for the final D.

#include "harness.h"

#include <nlohmann/json.hpp>

#include <regex>

namespace envdesign::testing {
namespace {

using namespace std::chrono_literals;

constexpr int PORT = 7771, DOMAIN = 71;

// Runs `command` and returns its standard output.
std::string output_of(const std::string &command) {
    std::string out;
    FILE *pipe = popen(command.c_str(), "r");
    char buffer[4096];
    while (pipe && fgets(buffer, sizeof buffer, pipe))
        out += buffer;
    if (pipe)
        pclose(pipe);
    return out;
}

// The imported spec with the task probabilities `d`, beside it (its PDDL paths are
// relative), designed by the CLI alone.
nlohmann::json self_contained(const std::string &floor, const std::map<std::string, double> &d) {
    std::ifstream in(floor + "/design.textproto");
    std::string spec, line;
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_search(line, m, std::regex("^task \\{ name: \"([^\"]+)\"")))
            line = std::regex_replace(line, std::regex("^task \\{ name: \"[^\"]+\""),
                                      m.str(0) + " probability: " +
                                          std::to_string(d.count(m.str(1)) ? d.at(m.str(1)) : 0));
        spec += line + "\n";
    }
    std::ofstream(floor + "/self-contained.textproto") << spec;
    return nlohmann::json::parse(output_of(BIN + "/envdesign design " + floor +
                                           "/self-contained.textproto --json 2>/dev/null"));
}

std::vector<std::string> mix(int count, const std::string &most, const std::string &rest) {
    std::vector<std::string> rows;
    for (int i = 0; i < count; ++i)
        rows.push_back(i % 10 < 9 ? most : rest);
    return rows;
}

TEST(FloorLive, ArrivalsOfFloorTasksChangeTheDesign) {
    std::string dir = scratch("floor-live");
    std::string floor = dir + "/warehouse";
    std::string ex = SOURCE + "/examples/floor/";
    std::string imported =
        output_of(BIN + "/envdesign floor import " + ex + "warehouse.building.yaml --zones " + ex +
                  "zones.json -o " + floor + " 2>&1");
    ASSERT_NE(imported.find("20 tasks, 8 candidates"), std::string::npos) << imported;

    Listener lcm(lcm_url(PORT));
    Process bridge({BIN + "/envdesign-bridge", "--problem",
                    "warehouse=" + floor + "/design.textproto", "--domain", std::to_string(DOMAIN),
                    "--lcm-url", lcm_url(PORT), "--name", "bridge/floor", "--publish-hz", "50",
                    "--estimator", "window:100", "--threshold", "0.3", "--min-samples", "50",
                    "--holdoff", "20"},
                   dds_env(), dir + "/bridge.log");
    ASSERT_TRUE(lcm.wait_until([&] { return !lcm.results().empty(); }, 30s)) << bridge.output();
    EXPECT_EQ(lcm.results().front().message.design,
              (std::vector<std::string>{"gap-barrier", "top-aisle-marking"}));

    // pick_a -> dock is v19-v16; dock -> pack, v16-v24 (by number, as a log may also say).
    std::string replay =
        write_replay(dir + "/trips.csv", "from,to", mix(200, "pick_a,dock", "v16,pack"));
    Process arrivals({BIN + "/envdesign-arrivals", "--replay", replay, "--floor", floor,
                      "--problem", "warehouse", "--site", "fleet-1", "--domain",
                      std::to_string(DOMAIN), "--wait-bridge", "20", "--rate", "1000"},
                     dds_env(), dir + "/arrivals.log");
    auto rc = arrivals.wait(60s);
    ASSERT_TRUE(rc) << arrivals.output();
    EXPECT_EQ(*rc, 0) << arrivals.output();
    const std::vector<std::string> aisle_only{"top-aisle-marking"};
    ASSERT_TRUE(lcm.wait_until(
        [&] {
            auto m = lcm.last_estimate("warehouse");
            return m && m->estimated == 200 && m->design == aisle_only;
        },
        60s))
        << bridge.output();

    auto estimate = *lcm.last_estimate("warehouse");
    EXPECT_EQ(estimate.accepted, 200);
    EXPECT_EQ(estimate.unknown_task, 0); // the trips' names are the spec's task names
    EXPECT_NEAR(probability(estimate, "v19-v16"), 0.9, 1e-12);
    EXPECT_NEAR(probability(estimate, "v16-v24"), 0.1, 1e-12);
    auto last = lcm.results().back().message;
    EXPECT_EQ(last.exit_code, 0) << last.error;
    EXPECT_EQ(last.design, aisle_only);
    EXPECT_NE(last.change.find("{gap-barrier, top-aisle-marking} -> {top-aisle-marking}"),
              std::string::npos)
        << last.change;
    // The design in force is the self-contained run's, for the D of its result and for the
    // final estimate (a later D that keeps the design publishes no new result).
    std::map<std::string, double> d;
    for (const auto &t : last.tasks)
        d[t.name] = t.probability;
    auto independent = self_contained(floor, d);
    EXPECT_EQ(independent.at("design").get<std::vector<std::string>>(), last.design);
    EXPECT_NEAR(independent.at("objective").get<double>(), last.best.objective, 1e-9);
    std::map<std::string, double> final_d;
    for (int i = 0; i < estimate.num_tasks; ++i)
        final_d[estimate.tasks[i]] = estimate.probabilities[i];
    EXPECT_EQ(self_contained(floor, final_d).at("design").get<std::vector<std::string>>(),
              aisle_only);
    EXPECT_EQ(bridge.stop(), 0);
}

// Trips that name no task are bad input at their cell, before anything is published.
TEST(FloorLive, TripsNamingNoPlaceAreBadInput) {
    std::string dir = scratch("floor-trips");
    std::string floor = dir + "/warehouse";
    std::string ex = SOURCE + "/examples/floor/";
    output_of(BIN + "/envdesign floor import " + ex + "warehouse.building.yaml -o " + floor +
              " 2>&1");
    auto run = [&](const std::string &csv, bool with_floor) {
        std::vector<std::string> argv = {BIN + "/envdesign-arrivals",
                                         "--replay",
                                         csv,
                                         "--problem",
                                         "warehouse",
                                         "--domain",
                                         "72"};
        if (with_floor)
            argv.insert(argv.end(), {"--floor", floor});
        Process p(argv, dds_env(), dir + "/arrivals.log");
        auto rc = p.wait(10s);
        return std::make_pair(rc.value_or(-1), p.output());
    };
    std::string unknown =
        write_replay(dir + "/unknown.csv", "site,from,to", {"a,pick_a,dock", "a,pick_c,dock"});
    auto [code, out] = run(unknown, true);
    EXPECT_EQ(code, 2) << out;
    EXPECT_NE(out.find(unknown + ":3:3: error: no place 'pick_c'"), std::string::npos) << out;
    std::string same = write_replay(dir + "/same.csv", "from,to", {"dock,v16"});
    std::tie(code, out) = run(same, true);
    EXPECT_EQ(code, 2) << out;
    EXPECT_NE(out.find(same + ":2:1: error: from and to are the same place, v16"),
              std::string::npos)
        << out;
    std::tie(code, out) = run(unknown, false);
    EXPECT_EQ(code, 2) << out;
    EXPECT_NE(out.find(unknown + ":2:3: error: a trip (from, to) needs the floor: --floor DIR"),
              std::string::npos)
        << out;
}

} // namespace
} // namespace envdesign::testing
