#include "floor_command.h"

#include "cli_error.h"

#include "floor/floor_error.h"

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

namespace envdesign::cli {

namespace {

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
        ->capture_default_str();
    import.add_option("--tape-cost", o.candidates.tape_cost_per_m, "cost of tape per metre")
        ->capture_default_str();
    import.add_option("--lane-cost", o.candidates.lane_cost_per_m, "cost of a new lane per metre")
        ->capture_default_str();
    import.add_option("--candidates", f.candidates, "kinds of candidates: tape,lane,zones")
        ->delimiter(',')
        ->check(CLI::IsMember({"tape", "lane", "zones"}))
        ->capture_default_str();
    import.add_option("--alpha", o.weights.alpha, "weight of inexplicability")
        ->capture_default_str();
    import.add_option("--beta", o.weights.beta, "weight of the design cost")->capture_default_str();
    import.add_option("--kappa", o.weights.kappa, "weight of the robot's cost")
        ->capture_default_str();
    import.add_option("--horizon", o.weights.horizon, "times the tasks are done")
        ->capture_default_str();
    import.add_option("--gamma", o.weights.gamma, "discount over the horizon")
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

// The picture of floor.json: metres -> pixels, y flipped, 1000 px across.
class FloorPicture {
public:
    explicit FloorPicture(const nlohmann::json &floor) : floor_(floor) {
        for (const auto &p : floor["places"])
            extend(p["x"].get<double>(), p["y"].get<double>());
        for (const auto &w : floor["walls"])
            for (const auto &q : w)
                extend(q[0].get<double>(), q[1].get<double>());
        scale_ = 1000 / std::max({max_x_ - min_x_, max_y_ - min_y_, 1e-9});
    }

    std::string svg(const std::set<std::string> &design) {
        out_ << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << x(max_x_) + 40
             << "\" height=\"" << y(min_y_) + 40 << "\" font-family=\"sans-serif\">\n"
             << "<title>" << escaped(floor_["source"]["map"].get<std::string>()) << "</title>\n";
        for (const auto &c : floor_["candidates"])
            if (design.count(c["name"].get<std::string>()))
                candidate(c);
        for (const auto &w : floor_["walls"])
            line(w[0], w[1], "stroke=\"#222\" stroke-width=\"4\"");
        edges("robot_edges", "stroke=\"#777\" stroke-width=\"2\"");
        // On top: where people expect a move the lanes do not offer (a one-way lane's reverse).
        edges("human_only_edges", "stroke=\"#5b9bd5\" stroke-dasharray=\"6 4\"");
        for (const auto &p : floor_["places"])
            place(p);
        out_ << "<text x=\"20\" y=\"" << y(min_y_) + 32 << "\" font-size=\"12\">grey: lanes; "
             << "blue dashed: what people expect; orange: tape; green: new lane; red: barrier; "
                "yellow: marked area</text>\n</svg>\n";
        return out_.str();
    }

private:
    void extend(double px, double py) {
        min_x_ = std::min(min_x_, px), max_x_ = std::max(max_x_, px);
        min_y_ = std::min(min_y_, py), max_y_ = std::max(max_y_, py);
    }
    double x(double metres) const { return 20 + (metres - min_x_) * scale_; }
    double y(double metres) const { return 20 + (max_y_ - metres) * scale_; }

    static std::string escaped(const std::string &text) {
        std::string out;
        for (char c : text)
            out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
        return out;
    }

    void line(const nlohmann::json &a, const nlohmann::json &b, const std::string &style) {
        out_ << "<line x1=\"" << x(a[0]) << "\" y1=\"" << y(a[1]) << "\" x2=\"" << x(b[0])
             << "\" y2=\"" << y(b[1]) << "\" " << style << "/>\n";
    }

    void edges(const char *key, const std::string &style) {
        std::map<std::string, nlohmann::json> at;
        for (const auto &p : floor_["places"])
            at[p["object"].get<std::string>()] = {p["x"], p["y"]};
        for (const auto &e : floor_[key])
            line(at[e[0].get<std::string>()], at[e[1].get<std::string>()], style);
    }

    void candidate(const nlohmann::json &c) {
        std::string kind = c["kind"];
        if (kind == "zone") {
            bool blocked = c["zone_type"] == "BLOCKED";
            out_ << "<polygon class=\"zone\" points=\"";
            for (const auto &q : c["polygon"])
                out_ << x(q[0]) << "," << y(q[1]) << " ";
            out_ << "\" fill=\"" << (blocked ? "#e0303080" : "#f0d02080") << "\"><title>"
                 << escaped(c["name"]) << "</title></polygon>\n";
            return;
        }
        std::string colour = kind == "tape" ? "#f08000" : "#20a040";
        for (const auto &s : c["segments"])
            line(s[0], s[1],
                 "class=\"" + kind + "\" stroke=\"" + colour +
                     "\" stroke-width=\"8\" stroke-opacity=\"0.7\"");
    }

    void place(const nlohmann::json &p) {
        std::string name = p["name"].get<std::string>();
        double px = x(p["x"]), py = y(p["y"]);
        out_ << "<circle cx=\"" << px << "\" cy=\"" << py << "\" r=\"5\" fill=\""
             << (name.empty() ? "#999" : "#000") << "\"/>\n<text x=\"" << px + 7 << "\" y=\""
             << py - 7 << "\" font-size=\"13\">"
             << escaped(p["object"].get<std::string>() + (name.empty() ? "" : " " + name))
             << "</text>\n";
    }

    const nlohmann::json &floor_;
    std::ostringstream out_;
    double min_x_ = 1e300, max_x_ = -1e300, min_y_ = 1e300, max_y_ = -1e300, scale_ = 1;
};

int run_draw(const FloorFlags &flags) {
    std::string path = flags.draw_dir + "/floor.json";
    std::ifstream in(path);
    nlohmann::json floor = nlohmann::json::parse(in, nullptr, false);
    if (!in || floor.is_discarded() || floor.value("format", "") != "envdesign-floor")
        throw CommandError(2, path + " is not a floor.json written by envdesign floor import");
    std::set<std::string> names;
    for (const auto &c : floor["candidates"])
        names.insert(c["name"].get<std::string>());
    for (const auto &name : flags.draw_design)
        if (!names.count(name))
            throw CommandError(2, "no candidate '" + name + "' in " + path);
    std::ofstream out(flags.draw_out);
    out << FloorPicture(floor).svg({flags.draw_design.begin(), flags.draw_design.end()});
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
