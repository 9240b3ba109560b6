#include "report_floor.h"

#include "floor/floor_draw.h"
#include "floor/floor_error.h"
#include "pddl/parse_error.h"
#include "result_format.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <numeric>
#include <sstream>

namespace envdesign::cli {
namespace {

namespace fs = std::filesystem;
using client::html_escape;
using nlohmann::json;

// "v19 pick_a" -> "v19 (pick_a)": how the page names a place.
std::string place_name(const json &floor, const std::string &object) {
    for (const auto &p : floor["places"])
        if (p.value("object", "") == object) {
            std::string name = p.value("name", "");
            return name.empty() ? object : object + " (" + name + ")";
        }
    return object;
}

// The tasks drawn: most probable first, ties by the larger IE before the design, then in
// spec order.
std::vector<std::size_t> drawn_tasks(const envdesign::design_result_t &r) {
    std::vector<std::size_t> order(std::min(r.tasks.size(), r.explanation.tasks.size()));
    std::iota(order.begin(), order.end(), 0);
    auto ie_before = [&](std::size_t i) {
        const auto &e = r.explanation.tasks[i];
        return e.has_baseline ? e.baseline.ie : 0.0;
    };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (r.tasks[a].probability != r.tasks[b].probability)
            return r.tasks[a].probability > r.tasks[b].probability;
        return ie_before(a) > ie_before(b);
    });
    order.resize(std::min(order.size(), FLOOR_TASKS_DRAWN));
    return order;
}

floor::DrawnPath path(const std::vector<std::string> &plan, floor::PathStyle style,
                      const std::string &title) {
    return {floor::plan_places(plan), style, title};
}

// One task before and after, side by side.
void task_pictures(std::ostream &out, const json &floor, const envdesign::design_result_t &r,
                   std::size_t i, const client::ReportExtras &extras) {
    const auto &t = r.tasks[i];
    const auto &e = r.explanation.tasks[i];
    floor::FloorDrawing before, after;
    before.width_px = after.width_px = 400;
    before.label_path_places_only = after.label_path_places_only = true;
    before.legend = after.legend = false;
    after.design = {r.design.begin(), r.design.end()};
    if (e.has_baseline)
        before.paths.push_back(path(e.baseline.plan, floor::PathStyle::ROBOT, "the robot, before"));
    if (i < extras.expected_before.size() && extras.expected_before[i])
        before.paths.push_back(path(*extras.expected_before[i], floor::PathStyle::EXPECTED,
                                    "what people expected, before"));
    after.paths.push_back(path(t.plan, floor::PathStyle::ROBOT, "the robot, after"));
    if (e.has_expected_plan)
        after.paths.push_back(
            path(e.expected_plan, floor::PathStyle::EXPECTED, "what people expect, after"));
    std::vector<std::string> places = floor::plan_places(t.plan);
    out << "<h3>Task " << html_escape(t.name);
    if (!places.empty())
        out << ": " << html_escape(place_name(floor, places.front())) << " to "
            << html_escape(place_name(floor, places.back()));
    out << " (probability " << client::shown(t.probability) << ")</h3>\n<div class=floorpair>"
        << "<figure class=before>" << floor::floor_svg(floor, before) << "<figcaption>Before: IE "
        << (e.has_baseline ? client::shown(e.baseline.ie) : "?")
        << "</figcaption></figure><figure class=after>" << floor::floor_svg(floor, after)
        << "<figcaption>After: IE " << client::shown(t.ie) << "</figcaption></figure></div>\n";
}

std::string section(const json &floor, const envdesign::design_result_t &r,
                    const client::ReportExtras &extras) {
    std::ostringstream out;
    floor::FloorDrawing overview;
    overview.design = {r.design.begin(), r.design.end()};
    out << "<h2>The floor</h2>\n<figure class=floor>" << floor::floor_svg(floor, overview)
        << "<figcaption>The floor with the chosen modifications.</figcaption></figure>\n"
        << "<p class=muted>Below, the most probable tasks: the robot's path (wide, purple) and "
           "the path people expect (dashed, dark blue), before the design and after it; a ring "
           "marks where the robot starts.</p>\n";
    for (std::size_t i : drawn_tasks(r))
        task_pictures(out, floor, r, i, extras);
    return out.str();
}

} // namespace

std::string report_floor_section(const std::string &spec_path,
                                 const envdesign::design_result_t &result,
                                 const client::ReportExtras &extras) {
    fs::path dir = fs::path(spec_path).parent_path();
    if (dir.empty())
        dir = ".";
    if (!fs::exists(dir / "floor.json"))
        return "";
    try {
        return section(floor::read_floor_json(dir.string()), result, extras);
    } catch (const pddl::ParseError &e) {
        spdlog::warn("the floor is not drawn: {}", e.what());
        return "<h2>The floor</h2>\n<p>Not drawn: " + html_escape(e.what()) + "</p>\n";
    } catch (const floor::FloorError &e) {
        spdlog::warn("the floor is not drawn: {}", e.what());
        return "<h2>The floor</h2>\n<p>Not drawn: " + html_escape(e.what()) + "</p>\n";
    }
}

} // namespace envdesign::cli
