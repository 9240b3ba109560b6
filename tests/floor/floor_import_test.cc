// What `floor import` writes: the spec's tasks, probabilities, candidates and weights, the
// two problems of a task, floor.json; by the library, on a map the test writes.

#include "floor/floor_import.h"

#include "map_text.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace envdesign::floor {
namespace {

namespace fs = std::filesystem;
using testing::MapText;

// dock (0,0) <-> v1 (0,4) <-> shelf (4,4) -> pack (8,4) (one way), in pixels of 0.1 m.
MapText site() {
    MapText m;
    m.vertices = {{0, 0, "dock"}, {0, -40, ""}, {40, -40, "shelf"}, {80, -40, "pack"}};
    m.lanes = {{0, 1, true}, {1, 2, true}, {2, 3, false}};
    m.measurements = {{0, 1, 4.0}};
    return m;
}

struct Imported {
    fs::path dir;
    ImportReport report;
    std::string spec;
};

Imported import_site(const std::string &name, const std::string &csv, Weights w = {}) {
    Imported out;
    out.dir = testing::scratch_dir(name);
    ImportOptions o;
    o.map = testing::write_text(out.dir / "site.building.yaml", site().yaml());
    o.out_dir = (out.dir / "out").string();
    if (!csv.empty())
        o.tasks_csv = testing::write_text(out.dir / "tasks.csv", csv);
    o.weights = w;
    out.report = import_floor(o);
    out.spec = testing::read_text(out.dir / "out/design.textproto");
    return out;
}

TEST(FloorImport, CsvWeightsBecomeProbabilitiesOverTheTasksKept) {
    // pack -> dock cannot be done (pack is a dead end): dropped, the rest normalised.
    Imported r = import_site("weights", "from,to,weight\ndock,shelf,3\npack,dock,4\nshelf,v1,1\n");
    ASSERT_EQ(r.report.warnings.size(), 1u);
    EXPECT_NE(r.report.warnings[0].find("task v3-v0 dropped"), std::string::npos);
    EXPECT_NE(r.spec.find("task { name: \"v0-v2\" problem: \"tasks/v0-v2.pddl\" human_problem: "
                          "\"tasks/v0-v2-human.pddl\" probability: 0.75 }"),
              std::string::npos)
        << r.spec;
    EXPECT_NE(r.spec.find("name: \"v2-v1\""), std::string::npos);
    EXPECT_NE(r.spec.find("probability: 0.25 }"), std::string::npos);
    EXPECT_EQ(r.spec.find("v3-v0"), std::string::npos);
}

TEST(FloorImport, WeightsAndDistanceAreWrittenAsGiven) {
    Imported r = import_site("flags", "", {2, 0.5, 0.25, 10, 0.9});
    EXPECT_NE(r.spec.find("alpha: 2 beta: 0.5 kappa: 0.25 gamma: 0.9 horizon: 10\n"
                          "distance: COST_DIFF"),
              std::string::npos)
        << r.spec;
}

TEST(FloorImport, TheTwoProblemsDifferOnlyInTheirConnectedAtoms) {
    Imported r = import_site("problems", "");
    std::string robot = testing::read_text(r.dir / "out/tasks/v0-v2.pddl");
    std::string human = testing::read_text(r.dir / "out/tasks/v0-v2-human.pddl");
    EXPECT_NE(robot.find("(:objects v0 v1 v2 v3 - place)"), std::string::npos) << robot;
    EXPECT_NE(robot.find("(:init (at v0) (= (total-cost) 0)"), std::string::npos);
    EXPECT_NE(robot.find("(:goal (at v2))"), std::string::npos);
    EXPECT_EQ(robot.find("(connected v0 v2)"), std::string::npos);
    EXPECT_NE(human.find("(connected v0 v2)"), std::string::npos);
    EXPECT_NE(human.find("(connected v3 v2)"), std::string::npos); // against the one-way lane
    // Both carry every length: 4 m lanes are 40 dm, the diagonal 5.657 m is 57.
    for (const std::string *text : {&robot, &human}) {
        EXPECT_NE(text->find("(= (length v0 v1) 40)"), std::string::npos);
        EXPECT_NE(text->find("(= (length v0 v2) 57)"), std::string::npos);
    }
    std::string domain = testing::read_text(r.dir / "out/domain.pddl");
    EXPECT_NE(domain.find("(increase (total-cost) (length ?from ?to))"), std::string::npos);
}

TEST(FloorImport, FloorJsonHasThePlacesInMetresAndTheCandidatesGeometry) {
    Imported r = import_site("json", "");
    auto floor = nlohmann::json::parse(testing::read_text(r.dir / "out/floor.json"));
    EXPECT_EQ(floor["format"], "envdesign-floor");
    EXPECT_EQ(floor["source"]["format"], "building_map");
    EXPECT_DOUBLE_EQ(floor["source"]["metres_per_unit"].get<double>(), 0.1);
    const auto &shelf = floor["places"][2];
    EXPECT_EQ(shelf["object"], "v2");
    EXPECT_EQ(shelf["name"], "shelf");
    EXPECT_DOUBLE_EQ(shelf["x"].get<double>(), 4);
    EXPECT_DOUBLE_EQ(shelf["y"].get<double>(), 4); // -(-40 px) x 0.1
    EXPECT_EQ(floor["robot_edges"].size(), r.report.robot_edges);
    EXPECT_EQ(floor["human_only_edges"].size(), r.report.human_only_edges);
    const auto &tape = floor["candidates"][0];
    EXPECT_EQ(tape["name"], "tape-v0-v2");
    EXPECT_EQ(tape["segments"], nlohmann::json::parse("[[[0.0, 0.0], [4.0, 4.0]]]"));
    EXPECT_EQ(tape["edges"], nlohmann::json::parse(R"([["v0", "v2"], ["v2", "v0"]])"));
}

} // namespace
} // namespace envdesign::floor
