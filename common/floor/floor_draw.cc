#include "floor_draw.h"

#include "floor_error.h"
#include "json_file.h"

#include "pddl/input_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <sstream>

namespace envdesign::floor {
namespace {

using nlohmann::json;

std::string escaped(const std::string &text) {
    std::string out;
    for (char c : text)
        out += c == '<'   ? "&lt;"
               : c == '>' ? "&gt;"
               : c == '&' ? "&amp;"
               : c == '"' ? "&quot;"
                          : std::string(1, c);
    return out;
}

// Metres -> pixels: y flipped, a 20 px margin, the longer side `width_px` across.
class FloorPicture {
public:
    FloorPicture(const json &floor, const FloorDrawing &drawing)
        : floor_(floor), drawing_(drawing) {
        for (const auto &p : floor["places"]) {
            extend(p.at("x").get<double>(), p.at("y").get<double>());
            at_[p.at("object").get<std::string>()] = {p["x"], p["y"]};
        }
        for (const auto &w : floor["walls"])
            for (const auto &q : w)
                extend(q.at(0).get<double>(), q.at(1).get<double>());
        double across = std::max({max_x_ - min_x_, max_y_ - min_y_, 1e-9});
        scale_ = drawing.width_px / across;
        for (const auto &path : drawing.paths)
            for (const auto &place : path.places) {
                if (!at_.count(place))
                    throw FloorError("a path visits '" + place + "', no place of floor.json");
                on_path_.insert(place);
            }
    }

    std::string svg() {
        double bottom = y(min_y_) + (drawing_.legend ? 40 : 20);
        double right = x(max_x_) + 100; // room for the labels of the places there
        // The viewBox lets a page scale the picture down to its width.
        out_ << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << right << "\" height=\""
             << bottom << "\" viewBox=\"0 0 " << right << " " << bottom
             << "\" font-family=\"sans-serif\">\n"
             << "<title>" << escaped(floor_["source"]["map"].get<std::string>()) << "</title>\n";
        for (const auto &c : floor_["candidates"])
            if (drawing_.design.count(c.at("name").get<std::string>()))
                candidate(c);
        for (const auto &w : floor_["walls"])
            line(w.at(0), w.at(1), "class=\"wall\" stroke=\"#222\" stroke-width=\"4\"");
        edges("robot_edges", "class=\"robot-edge\" stroke=\"#777\" stroke-width=\"2\"");
        // On top: where people expect a move the lanes do not offer (a one-way lane's reverse).
        edges("human_only_edges",
              "class=\"human-edge\" stroke=\"#5b9bd5\" stroke-dasharray=\"6 4\"");
        for (const auto &path : drawing_.paths)
            if (path.style == PathStyle::ROBOT)
                polyline(path);
        for (const auto &path : drawing_.paths)
            if (path.style == PathStyle::EXPECTED)
                polyline(path);
        for (const auto &p : floor_["places"])
            place(p);
        if (drawing_.legend)
            legend(bottom - 8);
        out_ << "</svg>\n";
        return out_.str();
    }

private:
    void extend(double px, double py) {
        min_x_ = std::min(min_x_, px), max_x_ = std::max(max_x_, px);
        min_y_ = std::min(min_y_, py), max_y_ = std::max(max_y_, py);
    }
    double x(double metres) const { return 20 + (metres - min_x_) * scale_; }
    double y(double metres) const { return 20 + (max_y_ - metres) * scale_; }

    void line(const json &a, const json &b, const std::string &style) {
        out_ << "<line x1=\"" << x(a.at(0)) << "\" y1=\"" << y(a.at(1)) << "\" x2=\"" << x(b.at(0))
             << "\" y2=\"" << y(b.at(1)) << "\" " << style << "/>\n";
    }

    const json &place_at(const json &object) const {
        auto it = at_.find(object.get<std::string>());
        if (it == at_.end())
            throw FloorError("an edge names '" + object.get<std::string>() +
                             "', no place of floor.json");
        return it->second;
    }

    void edges(const char *key, const std::string &style) {
        for (const auto &e : floor_[key])
            line(place_at(e.at(0)), place_at(e.at(1)), style);
    }

    void candidate(const json &c) {
        std::string kind = c.at("kind");
        if (kind == "zone") {
            bool blocked = c.at("zone_type") == "BLOCKED";
            out_ << "<polygon class=\"zone\" points=\"";
            for (const auto &q : c.at("polygon"))
                out_ << x(q.at(0)) << "," << y(q.at(1)) << " ";
            out_ << "\" fill=\"" << (blocked ? "#e0303080" : "#f0d02080") << "\"><title>"
                 << escaped(c["name"]) << "</title></polygon>\n";
            return;
        }
        std::string colour = kind == "tape" ? "#f08000" : "#20a040";
        for (const auto &s : c.at("segments"))
            line(s.at(0), s.at(1),
                 "class=\"" + kind + "\" stroke=\"" + colour +
                     "\" stroke-width=\"8\" stroke-opacity=\"0.7\"");
    }

    // The robot's path wide and purple, the expected one dashed dark blue over it, so that
    // where the two agree both show; a ring marks the start.
    void polyline(const DrawnPath &path) {
        if (path.places.empty())
            return;
        bool robot = path.style == PathStyle::ROBOT;
        const char *colour = robot ? "#8e44ad" : "#1a3f8f";
        out_ << "<g class=\"" << (robot ? "robot-path" : "expected-path") << "\"><title>"
             << escaped(path.title) << "</title><polyline points=\"";
        for (const auto &p : path.places)
            out_ << x(at_.at(p)[0]) << "," << y(at_.at(p)[1]) << " ";
        out_ << "\" fill=\"none\" stroke=\"" << colour << "\" stroke-linejoin=\"round\" "
             << (robot ? "stroke-width=\"9\" stroke-opacity=\"0.55\""
                       : "stroke-width=\"3\" stroke-dasharray=\"9 5\"")
             << "/>";
        const json &start = at_.at(path.places.front());
        out_ << "<circle cx=\"" << x(start[0]) << "\" cy=\"" << y(start[1]) << "\" r=\""
             << (robot ? 11 : 8) << "\" fill=\"none\" stroke=\"" << colour
             << "\" stroke-width=\"2\"/></g>\n";
    }

    void place(const json &p) {
        std::string name = p.at("name").get<std::string>();
        std::string object = p.at("object").get<std::string>();
        double px = x(p["x"]), py = y(p["y"]);
        out_ << "<circle class=\"place\" cx=\"" << px << "\" cy=\"" << py << "\" r=\"5\" fill=\""
             << (name.empty() ? "#999" : "#000") << "\"/>\n";
        if (drawing_.label_path_places_only && !on_path_.count(object))
            return;
        out_ << "<text x=\"" << px + 7 << "\" y=\"" << py - 7 << "\" font-size=\"13\">"
             << escaped(object + (name.empty() ? "" : " " + name)) << "</text>\n";
    }

    void legend(double baseline) {
        out_ << "<text x=\"20\" y=\"" << baseline << "\" font-size=\"12\">grey: lanes; "
             << "blue dashed: what people expect; orange: tape; green: new lane; red: barrier; "
                "yellow: marked area";
        if (!drawing_.paths.empty())
            out_ << "; purple: the robot's path; dark blue dashed: the path people expect";
        out_ << "</text>\n";
    }

    const json &floor_;
    const FloorDrawing &drawing_;
    std::map<std::string, json> at_; // object -> [x, y]
    std::set<std::string> on_path_;
    std::ostringstream out_;
    double min_x_ = 1e300, max_x_ = -1e300, min_y_ = 1e300, max_y_ = -1e300, scale_ = 1;
};

std::vector<std::string> words(const std::string &step) {
    std::string text = step;
    std::replace(text.begin(), text.end(), '(', ' ');
    std::replace(text.begin(), text.end(), ')', ' ');
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string w; in >> w;)
        out.push_back(w);
    return out;
}

} // namespace

json read_floor_json(const std::string &dir) {
    std::string path = (std::filesystem::path(dir) / "floor.json").string();
    JsonFile file(pddl::read_input_file(path), path);
    const json &floor = file.doc();
    if (!floor.is_object() || floor.value("format", "") != "envdesign-floor")
        file.fail({}, "not a floor.json written by envdesign floor import");
    for (const char *key : {"places", "walls", "robot_edges", "human_only_edges", "candidates"})
        if (!floor.contains(key) || !floor[key].is_array())
            file.fail({}, std::string("floor.json has no list '") + key + "'");
    return floor;
}

std::string floor_svg(const json &floor, const FloorDrawing &drawing) {
    try {
        return FloorPicture(floor, drawing).svg();
    } catch (const json::exception &e) {
        throw FloorError(std::string("floor.json cannot be drawn: ") + e.what());
    }
}

std::vector<std::string> plan_places(const std::vector<std::string> &plan) {
    std::vector<std::string> out;
    for (const auto &step : plan) {
        std::vector<std::string> w = words(step);
        if (w.size() < 3 || w[0] != "move")
            continue;
        if (out.empty() || out.back() != w[1])
            out.push_back(w[1]);
        out.push_back(w[2]);
    }
    return out;
}

} // namespace envdesign::floor
