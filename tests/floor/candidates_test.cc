// Candidates (FLOORS.md "Candidate modifications"): tapes, then lanes, then zones; their
// names, costs and edits; zone files and their faults.

#include "floor/building_map.h"
#include "floor/candidates.h"
#include "floor/zones.h"

#include "map_text.h"

#include "pddl/parse_error.h"

#include <gtest/gtest.h>

namespace envdesign::floor {
namespace {

using testing::MapText;

// A square 4 m a side: a (0,0) - v1 (0,4) - b (4,4) - c (4,0) along lanes, two-way. People
// also see a-b, a-c and v1-c.
Floor square() {
    MapText m;
    m.coordinate_system = "cartesian_meters";
    m.vertices = {{0, 0, "a"}, {0, 4, ""}, {4, 4, "b"}, {4, 0, "c"}};
    m.lanes = {{0, 1, true}, {1, 2, true}, {2, 3, true}};
    return parse_building_map(m.yaml(), "t.building.yaml", {});
}

const char *ZONES = R"({"zones": [
  {"zoneId": "aisle-gate", "zoneType": "BLOCKED", "cost": 3,
   "vertices": [{"x": -0.5, "y": 1}, {"x": 0.5, "y": 1}, {"x": 0.5, "y": 2}, {"x": -0.5, "y": 2}]},
  {"zoneId": "corner-marks", "zoneType": "LINE_GUIDED", "cost": 2.5,
   "vertices": [{"x": 3.5, "y": -0.5}, {"x": 4.5, "y": -0.5}, {"x": 4.5, "y": 0.5}, {"x": 3.5, "y": 0.5}]},
  {"zoneId": "slow", "zoneType": "SPEED_LIMIT", "vertices": []},
  {"zoneId": "far-away", "zoneType": "BLOCKED", "cost": 1,
   "vertices": [{"x": 50, "y": 50}, {"x": 51, "y": 50}, {"x": 51, "y": 51}]}
]})";

struct Made {
    std::vector<Candidate> candidates;
    std::vector<std::string> warnings;
};

Made make(CandidateOptions options = {}) {
    Floor f = square();
    Made made;
    auto zones = parse_zones(ZONES, "zones.json", made.warnings);
    made.candidates = make_candidates(f, build_floor_graph(f, 10), zones, options, made.warnings);
    return made;
}

std::string edits(const Candidate &c) {
    std::string out;
    for (const auto &e : c.edits)
        out += std::string(e.model == EditModel::HUMAN   ? "H"
                           : e.model == EditModel::ROBOT ? "R"
                                                         : "B") +
               (e.add ? "+" : "-") + std::to_string(e.edge.from) + std::to_string(e.edge.to) + " ";
    return out;
}

TEST(Candidates, TapesThenLanesByPairThenZonesInFileOrder) {
    Made made = make();
    std::vector<std::string> names;
    for (const auto &c : made.candidates)
        names.push_back(c.name);
    std::vector<std::string> expected{"tape-v0-v2", "tape-v0-v3", "tape-v1-v3", "lane-v0-v2",
                                      "lane-v0-v3", "lane-v1-v3", "aisle-gate", "corner-marks"};
    EXPECT_EQ(names, expected);
}

TEST(Candidates, CostsArePerMetreOfTheExactLengthRoundedToCents) {
    Made made = make({true, true, true, 1.5, 10});
    EXPECT_DOUBLE_EQ(made.candidates[0].cost, 8.49);  // 1.5 x 5.6569 m
    EXPECT_DOUBLE_EQ(made.candidates[1].cost, 6);     // 1.5 x 4 m
    EXPECT_DOUBLE_EQ(made.candidates[3].cost, 56.57); // 10 x 5.6569 m
    EXPECT_DOUBLE_EQ(made.candidates[6].cost, 3);     // a zone's own cost
    EXPECT_DOUBLE_EQ(round_cents(0.125), 0.13);       // halves away from zero
    EXPECT_DOUBLE_EQ(round_cents(-0.125), -0.13);
}

TEST(Candidates, TapeRemovesThePairsHumanOnlyEdgesFromPeopleLaneAddsThemForTheRobot) {
    Made made = make();
    EXPECT_EQ(edits(made.candidates[0]), "H-02 H-20 ");
    EXPECT_EQ(edits(made.candidates[3]), "R+02 R+20 ");
}

TEST(Candidates, BlockedZoneRemovesRobotEdgesFromBothModelsAndSightLinesFromPeople) {
    Made made = make();
    EXPECT_EQ(made.candidates[6].name, "aisle-gate");
    EXPECT_EQ(edits(made.candidates[6]), "B-01 B-10 ");
    EXPECT_EQ(made.candidates[6].zone_type, "BLOCKED");
}

TEST(Candidates, LineGuidedZoneRemovesOnlyHumanOnlyEdgesMeetingIt) {
    Made made = make();
    // It covers c's corner: the lane b-c meets it but stays; the sight lines a-c and v1-c go.
    EXPECT_EQ(edits(made.candidates[7]), "H-03 H-13 H-30 H-31 ");
}

TEST(Candidates, OtherZoneTypesAndZonesMeetingNothingAreSkippedWithAWarning) {
    Made made = make();
    ASSERT_EQ(made.warnings.size(), 2u);
    EXPECT_NE(made.warnings[0].find("zone 'slow' of type SPEED_LIMIT skipped"), std::string::npos);
    EXPECT_NE(made.warnings[1].find("zone 'far-away' is no candidate"), std::string::npos);
}

TEST(Candidates, KindsCanBeLeftOut) {
    Made made = make({false, true, false, 1, 10});
    ASSERT_EQ(made.candidates.size(), 3u);
    EXPECT_EQ(made.candidates[0].name, "lane-v0-v2");
}

std::string zone_error(const std::string &json) {
    std::vector<std::string> warnings;
    try {
        parse_zones(json, "zones.json", warnings);
    } catch (const pddl::ParseError &e) {
        return e.what();
    }
    return "no error";
}

TEST(Zones, FaultsAreAtTheirLine) {
    std::string e = zone_error("{\"zones\": [\n  {\"zoneId\": \"a\",,}\n]}");
    EXPECT_NE(
        e.find("zones.json:2:18: error: malformed JSON: syntax error while parsing object key"),
        std::string::npos)
        << e;
    e = zone_error(
        "{\"zones\": [\n {\"zoneId\": \"a\", \"zoneType\": \"BLOCKED\",\n"
        "  \"vertices\": [{\"x\": 0, \"y\": 0}, {\"x\": 1, \"y\": 0}, {\"x\": 1, \"y\": 1}]}\n]}");
    EXPECT_NE(e.find("zones.json:2:2: error: zone 0: zone 'a' has no cost"), std::string::npos)
        << e;
    e = zone_error("{\"zones\": [\n {\"zoneId\": \"a\", \"zoneType\": \"BLOCKED\", \"cost\": 1,\n"
                   "  \"vertices\": [{\"x\": 0, \"y\": 0}, {\"x\": 1, \"y\": 0}]}\n]}");
    EXPECT_NE(e.find("zones.json:3:15: error: zone 0: 'vertices' is not a list of at least 3"),
              std::string::npos)
        << e;
    e = zone_error(
        "{\"zones\": [{\"zoneId\": \"a\", \"zoneType\": \"BLOCKED\", \"cost\": 1,"
        " \"vertices\": [{\"x\": 0, \"y\": 0}, {\"x\": 1e9, \"y\": 0}, {\"x\": 1, \"y\": 1}]}]}");
    EXPECT_NE(e.find("is not a finite number within 1e6"), std::string::npos) << e;
    e = zone_error("{\"zones\": [{\"zoneId\": \"a\", \"zoneType\": \"SPEED_LIMIT\"},\n"
                   " {\"zoneId\": \"a\", \"zoneType\": \"SPEED_LIMIT\"}]}");
    EXPECT_NE(e.find("zones.json:2:13: error: zone 1: zoneId 'a' is given twice"),
              std::string::npos)
        << e;
    EXPECT_NE(zone_error("[]").find("zones.json:1:1: error: a zone file is"), std::string::npos);
}

// Issue 21 (fuzz_floor_inputs): a zone's id is a modification's name in the spec and a name
// in floor.json; a control character in it is refused where it is written.
TEST(Zones, AnIdThatCannotBeWrittenIsRefused) {
    std::string e = zone_error(
        "{\"zones\": [\n {\"zoneId\": \"gap\\r\", \"zoneType\": \"BLOCKED\", \"cost\": 1,"
        " \"vertices\": [{\"x\": 0, \"y\": 0}, {\"x\": 1, \"y\": 0}, {\"x\": 1, \"y\": 1}]}]}");
    EXPECT_NE(
        e.find("zones.json:2:13: error: zone 0: its zoneId holds a control character (byte 3)"),
        std::string::npos)
        << e;
}

} // namespace
} // namespace envdesign::floor
