#include "floor_command.h"

#include "cli_error.h"

#include "floor/floor_draw.h"
#include "floor/floor_error.h"
#include "service/number_flag.h"

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <set>

namespace envdesign::cli {

namespace {

// Where `floor import` reads a floor: how far people see, in metres (a million: the whole
// floor at once), and a candidate's cost per metre (at most what a modification may cost,
// docs/numbers.md; the spec's reader checks each candidate's cost again).
constexpr design::NumberRange SIGHT_M{0, 1e6};
constexpr design::NumberRange COST_PER_M{0, design::MODIFICATION_COST.high};

void add_import_flags(CLI::App &import, FloorFlags &f) {
    floor::ImportOptions &o = f.options;
    import
        .add_option("map", o.map,
                    "Open-RMF building map (*.building.yaml) or Nav2 route graph "
                    "(*.geojson)")
        ->required();
    import.add_option("-o,--output", o.out_dir, "folder to write the design problem into")
        ->required();
    import.add_option("--level", f.level, "the level to read (default: the only one)");
    import.add_option("--graph", o.map_options.graph, "the fleet graph (lanes' graph_idx)")
        ->capture_default_str();
    import.add_option("--tasks", o.tasks_csv,
                      "CSV from,to,weight (default: every ordered "
                      "pair of named places)");
    import.add_option("--map", o.occupancy_yaml,
                      "with a route graph: map_server's map.yaml, "
                      "whose occupied cells block sight lines");
    import.add_option("--zones", o.zones_json, "VDA 5050 zoneSet JSON of candidate zones");
    import.add_option("--sight", o.sight_m, "metres people see a straight move across")
        ->check(service::number_in(SIGHT_M))
        ->capture_default_str();
    import.add_option("--tape-cost", o.candidates.tape_cost_per_m, "cost of tape per metre")
        ->check(service::number_in(COST_PER_M))
        ->capture_default_str();
    import.add_option("--lane-cost", o.candidates.lane_cost_per_m, "cost of a new lane per metre")
        ->check(service::number_in(COST_PER_M))
        ->capture_default_str();
    import.add_option("--candidates", f.candidates, "kinds of candidates: tape,lane,zones")
        ->delimiter(',')
        ->check(CLI::IsMember({"tape", "lane", "zones"}))
        ->capture_default_str();
    import.add_option("--alpha", o.weights.alpha, "weight of inexplicability")
        ->check(service::number_in(design::WEIGHT))
        ->capture_default_str();
    import.add_option("--beta", o.weights.beta, "weight of the design cost")
        ->check(service::number_in(design::WEIGHT))
        ->capture_default_str();
    import.add_option("--kappa", o.weights.kappa, "weight of the robot's cost")
        ->check(service::number_in(design::WEIGHT))
        ->capture_default_str();
    import.add_option("--horizon", o.weights.horizon, "times the tasks are done")
        ->check(service::number_in(design::HORIZON))
        ->capture_default_str();
    import.add_option("--gamma", o.weights.gamma, "discount over the horizon")
        ->check(service::number_in(design::DISCOUNT))
        ->capture_default_str();
    import.add_flag("--json", f.json, "print the summary as JSON");
}

void add_export_flags(CLI::App &exp, FloorFlags &f) {
    exp.add_option("dir", f.export_options.dir, "a folder `floor import` wrote")->required();
    exp.add_option("--design", f.design, "the chosen candidates, NAME,NAME,...")
        ->delimiter(',')
        ->required();
    exp.add_option("-o,--output", f.export_options.out_dir, "folder to write into")->required();
}

int run_export(FloorFlags &flags) {
    flags.export_options.design = flags.design;
    floor::ExportReport report;
    try {
        report = floor::export_design(flags.export_options);
    } catch (const floor::FloorError &e) {
        throw CommandError(2, e.what());
    }
    for (const auto &file : report.written)
        std::cout << "wrote " << file << "\n";
    return 0;
}

int run_draw(const FloorFlags &flags) {
    // A floor.json that does not read throws pddl::ParseError: main() reports it (exit 2).
    nlohmann::json floor = floor::read_floor_json(flags.draw_dir);
    std::set<std::string> names;
    for (const auto &c : floor["candidates"])
        names.insert(c.value("name", ""));
    floor::FloorDrawing drawing;
    for (const auto &name : flags.draw_design) {
        if (!names.count(name))
            throw CommandError(2,
                               "no candidate '" + name + "' in " + flags.draw_dir + "/floor.json");
        drawing.design.insert(name);
    }
    std::string svg;
    try {
        svg = floor::floor_svg(floor, drawing);
    } catch (const floor::FloorError &e) {
        throw CommandError(2, e.what());
    }
    std::ofstream out(flags.draw_out);
    out << svg;
    out.close();
    if (!out)
        throw CommandError(1, "cannot write " + flags.draw_out);
    std::cout << "wrote " << flags.draw_out << "\n";
    return 0;
}

bool chosen(const std::vector<std::string> &kinds, const std::string &kind) {
    return std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
}

void print_report(const floor::ImportReport &r, bool json) {
    if (json) {
        nlohmann::json out = {{"status", "ok"},
                              {"spec", r.spec_path},
                              {"places", r.places},
                              {"robot_edges", r.robot_edges},
                              {"human_only_edges", r.human_only_edges},
                              {"tasks", r.tasks},
                              {"candidates", r.candidates},
                              {"warnings", r.warnings}};
        std::cout << out.dump() << "\n";
        return;
    }
    std::cout << "wrote " << r.spec_path << ": " << r.places << " places, " << r.robot_edges
              << " robot edges, " << r.human_only_edges << " human-only edges, " << r.tasks
              << " tasks, " << r.candidates << " candidates\n"
              << "next: envdesign design " << r.spec_path << "\n";
}

} // namespace

void add_floor_flags(CLI::App &command, FloorFlags &flags) {
    command.require_subcommand(1);
    flags.import = command.add_subcommand(
        "import", "an Open-RMF building map -> a design problem (design.textproto, PDDL, "
                  "floor.json)");
    add_import_flags(*flags.import, flags);
    flags.export_ = command.add_subcommand(
        "export", "a design back to the site: the map with its new lanes, GeoJSON, keepout mask");
    add_export_flags(*flags.export_, flags);
    flags.draw = command.add_subcommand("draw", "the floor as SVG, with a design drawn on it");
    flags.draw->add_option("dir", flags.draw_dir, "a folder `floor import` wrote")->required();
    flags.draw->add_option("--design", flags.draw_design, "the candidates to draw, NAME,...")
        ->delimiter(',');
    flags.draw->add_option("-o,--output", flags.draw_out, "the SVG file")->required();
}

int run_floor(FloorFlags &flags) {
    if (*flags.export_)
        return run_export(flags);
    if (*flags.draw)
        return run_draw(flags);
    floor::ImportOptions &o = flags.options;
    if (!flags.level.empty())
        o.map_options.level = flags.level;
    o.candidates.tapes = chosen(flags.candidates, "tape");
    o.candidates.lanes = chosen(flags.candidates, "lane");
    o.candidates.zones = chosen(flags.candidates, "zones");
    floor::ImportReport report;
    try {
        report = floor::import_floor(o);
    } catch (const floor::FloorError &e) {
        throw CommandError(2, e.what());
    }
    for (const auto &w : report.warnings)
        spdlog::warn("{}", w);
    print_report(report, flags.json);
    return 0;
}

} // namespace envdesign::cli
