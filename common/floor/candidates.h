#pragma once
// The candidate modifications of a floor (FLOORS.md "Candidate modifications"), each a set
// of init edits of `(connected p q)`, so the design search applies unchanged:
//   tape-vI-vJ  (HUMAN remove) tape or a sign: people no longer expect the pair's sight lines;
//   lane-vI-vJ  (ROBOT add)    a new lane along them;
//   <zoneId>    BLOCKED: every edge meeting the zone leaves the model(s) it is in;
//               LINE_GUIDED: every human-only edge meeting it leaves the human model.
// Listed tapes first, then lanes (each by I, then J), then zones in file order.

#include "floor.h"
#include "floor_graph.h"
#include "zones.h"

#include <string>
#include <vector>

namespace envdesign::floor {

enum class EditModel { HUMAN, ROBOT, BOTH };

struct InitEdit {
    EditModel model = EditModel::BOTH;
    bool add = false; // add_init, else remove_init
    Edge edge;        // the atom (connected vFROM vTO)
};

enum class CandidateKind { TAPE, LANE, ZONE };

struct Candidate {
    std::string name;
    CandidateKind kind = CandidateKind::TAPE;
    double cost = 0;
    std::vector<InitEdit> edits;
    std::vector<Edge> pairs;    // the unordered pairs (first < second) it acts on, for drawing
    std::vector<Point> polygon; // a zone's corners, metres
    std::string zone_type;      // "BLOCKED" or "LINE_GUIDED" for a zone
};

struct CandidateOptions {
    bool tapes = true;
    bool lanes = true;
    bool zones = true;
    double tape_cost_per_m = 1;
    double lane_cost_per_m = 10;
};

// Rounds to 2 decimals, halves away from zero.
double round_cents(double value);

// The candidates, in the order of the spec. A zone meeting no edge it would remove is no
// candidate (a warning says so).
std::vector<Candidate> make_candidates(const Floor &floor, const FloorGraph &graph,
                                       const std::vector<Zone> &zones,
                                       const CandidateOptions &options,
                                       std::vector<std::string> &warnings);

} // namespace envdesign::floor
