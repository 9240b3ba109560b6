#include "occupancy_map.h"

#include "yaml_fields.h"

#include "pddl/input_file.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>

namespace envdesign::floor {

namespace {

// Reads the netpbm header fields: magic, width, height, maxval (comments skipped).
class PgmReader {
public:
    PgmReader(const std::string &bytes, std::string path) : bytes_(bytes), path_(std::move(path)) {}

    [[noreturn]] void fail(const std::string &message) const {
        throw pddl::ParseError({path_, 1, 1}, message);
    }

    long number() {
        skip_blanks();
        std::size_t start = at_;
        while (at_ < bytes_.size() && std::isdigit(static_cast<unsigned char>(bytes_[at_])))
            ++at_;
        if (start == at_ || at_ - start > 9)
            fail("not a PGM image: a number expected at byte " + std::to_string(start));
        return std::stol(bytes_.substr(start, at_ - start));
    }

    GreyImage read() {
        std::string magic = bytes_.substr(0, 2);
        if (magic != "P5" && magic != "P2")
            fail("not a PGM image (netpbm P5 or P2); other formats are not read");
        at_ = 2;
        GreyImage image;
        image.width = static_cast<int>(number());
        image.height = static_cast<int>(number());
        long maxval = number();
        if (image.width < 1 || image.height < 1 || maxval < 1 || maxval > 65535)
            fail("not a PGM image: bad width, height or maxval");
        std::size_t cells = std::size_t(image.width) * std::size_t(image.height);
        if (cells > MAX_MAP_CELLS)
            fail("the map has " + std::to_string(cells) + " cells, more than " +
                 std::to_string(MAX_MAP_CELLS));
        image.grey.resize(cells);
        if (magic == "P5")
            raster(image, maxval);
        else
            for (std::size_t i = 0; i < cells; ++i)
                image.grey[i] = scaled(number(), maxval);
        return image;
    }

private:
    void skip_blanks() {
        while (at_ < bytes_.size()) {
            if (bytes_[at_] == '#')
                while (at_ < bytes_.size() && bytes_[at_] != '\n')
                    ++at_;
            else if (std::isspace(static_cast<unsigned char>(bytes_[at_])))
                ++at_;
            else
                return;
        }
    }

    std::uint8_t scaled(long v, long maxval) const {
        if (v > maxval)
            fail("not a PGM image: a value above maxval");
        return static_cast<std::uint8_t>((v * 255 + maxval / 2) / maxval);
    }

    void raster(GreyImage &image, long maxval) {
        ++at_; // the single blank after maxval
        std::size_t bytes_per = maxval > 255 ? 2 : 1;
        if (bytes_.size() < at_ + image.grey.size() * bytes_per)
            fail("not a PGM image: the raster is shorter than width x height");
        for (std::size_t i = 0; i < image.grey.size(); ++i) {
            const auto *p = reinterpret_cast<const unsigned char *>(&bytes_[at_ + i * bytes_per]);
            long v = bytes_per == 2 ? (p[0] << 8) | p[1] : p[0];
            image.grey[i] = scaled(v, maxval);
        }
    }

    const std::string &bytes_;
    std::string path_;
    std::size_t at_ = 0;
};

double field(const YamlFields &yaml, const YAML::Node &root, const std::string &key,
             double fallback) {
    YAML::Node node = root[key];
    return node.IsDefined() ? yaml.number(node, key) : fallback;
}

struct Thresholds {
    bool negate = false;
    double occupied = 0.65;
};

Thresholds thresholds(const YamlFields &yaml, const YAML::Node &root) {
    Thresholds t;
    t.negate = field(yaml, root, "negate", 0) != 0;
    t.occupied = field(yaml, root, "occupied_thresh", 0.65);
    YAML::Node mode = root["mode"];
    if (mode.IsDefined() && yaml.text(mode, "mode") != "trinary")
        yaml.fail(mode, "map mode '" + mode.Scalar() + "' is not supported (only trinary)");
    return t;
}

void read_geometry(const YamlFields &yaml, const YAML::Node &root, OccupancyGrid &grid) {
    grid.resolution = yaml.number(yaml.required(root, "resolution", "the map"), "resolution");
    if (!(grid.resolution > 0))
        yaml.fail(root["resolution"], "resolution must be > 0 metres a cell");
    YAML::Node origin = yaml.sequence(yaml.required(root, "origin", "the map"), "origin");
    if (origin.size() < 2)
        yaml.fail(origin, "origin is not [x, y, yaw]");
    grid.origin = {yaml.number(origin[0], "origin x"), yaml.number(origin[1], "origin y")};
    if (origin.size() > 2 && yaml.number(origin[2], "origin yaw") != 0)
        yaml.fail(origin, "a rotated map (origin yaw != 0) is not supported");
}

} // namespace

GreyImage parse_pgm(const std::string &bytes, const std::string &path) {
    return PgmReader(bytes, path).read();
}

OccupancyGrid read_occupancy_map(const std::string &yaml_path) {
    return parse_occupancy_map(
        pddl::read_input_file(yaml_path), yaml_path,
        [](const std::string &image) { return pddl::read_input_file(image); });
}

OccupancyGrid
parse_occupancy_map(const std::string &yaml_text, const std::string &yaml_path,
                    const std::function<std::string(const std::string &)> &read_image) {
    YamlFields yaml(yaml_path);
    YAML::Node root = yaml.load(yaml_text);
    if (!root.IsMap())
        throw pddl::ParseError({yaml_path, 1, 1}, "a map is a YAML map with 'image'");
    OccupancyGrid grid;
    read_geometry(yaml, root, grid);
    Thresholds t = thresholds(yaml, root);
    std::filesystem::path image_path = yaml.text(yaml.required(root, "image", "the map"), "image");
    if (image_path.is_relative())
        image_path = std::filesystem::path(yaml_path).parent_path() / image_path;
    GreyImage image = parse_pgm(read_image(image_path.string()), image_path.string());
    grid.width = image.width;
    grid.height = image.height;
    grid.occupied.resize(image.grey.size());
    for (int row = 0; row < grid.height; ++row) // the image's top row is the grid's last
        for (int col = 0; col < grid.width; ++col) {
            double v = image.grey[std::size_t(grid.height - 1 - row) * grid.width + col];
            double p = t.negate ? v / 255.0 : (255.0 - v) / 255.0;
            grid.occupied[std::size_t(row) * grid.width + col] = p > t.occupied;
        }
    return grid;
}

namespace {

// The part [t0, t1] of p + t (q - p), t in [0, 1], inside the box [0, w] x [0, h]
// (Liang-Barsky); false if none.
bool clip(Point p, Point q, double w, double h, double &t0, double &t1) {
    t0 = 0, t1 = 1;
    double dx = q.x - p.x, dy = q.y - p.y;
    double ps[4] = {-dx, dx, -dy, dy}, qs[4] = {p.x, w - p.x, p.y, h - p.y};
    for (int k = 0; k < 4; ++k) {
        if (ps[k] == 0) {
            if (qs[k] < 0)
                return false; // parallel to this side and outside it
            continue;
        }
        double r = qs[k] / ps[k];
        if (ps[k] < 0)
            t0 = std::max(t0, r);
        else
            t1 = std::min(t1, r);
    }
    return t0 <= t1;
}

} // namespace

bool OccupancyGrid::blocks(const Segment &s) const {
    Point a{(s.a.x - origin.x) / resolution, (s.a.y - origin.y) / resolution};
    Point b{(s.b.x - origin.x) / resolution, (s.b.y - origin.y) / resolution};
    double t0 = 0, t1 = 1;
    if (!clip(a, b, width, height, t0, t1))
        return false;
    // The cells of the endpoints themselves never block.
    long sx = std::lround(std::floor(a.x)), sy = std::lround(std::floor(a.y));
    long ex = std::lround(std::floor(b.x)), ey = std::lround(std::floor(b.y));
    double x0 = a.x + t0 * (b.x - a.x), y0 = a.y + t0 * (b.y - a.y);
    double x1 = a.x + t1 * (b.x - a.x), y1 = a.y + t1 * (b.y - a.y);
    long cx = std::lround(std::floor(x0)), cy = std::lround(std::floor(y0));
    long lx = std::lround(std::floor(x1)), ly = std::lround(std::floor(y1));
    double dx = x1 - x0, dy = y1 - y0, inf = std::numeric_limits<double>::infinity();
    int step_x = (dx > 0) - (dx < 0), step_y = (dy > 0) - (dy < 0);
    double t_max_x = dx != 0 ? (step_x > 0 ? cx + 1 - x0 : x0 - cx) / std::abs(dx) : inf;
    double t_max_y = dy != 0 ? (step_y > 0 ? cy + 1 - y0 : y0 - cy) / std::abs(dy) : inf;
    double t_delta_x = dx != 0 ? 1 / std::abs(dx) : inf;
    double t_delta_y = dy != 0 ? 1 / std::abs(dy) : inf;
    for (long steps = std::labs(lx - cx) + std::labs(ly - cy); steps >= 0; --steps) {
        bool endpoint = (cx == sx && cy == sy) || (cx == ex && cy == ey);
        if (!endpoint && cx >= 0 && cy >= 0 && cx < width && cy < height && occupied_at(cx, cy))
            return true;
        if (t_max_x < t_max_y)
            cx += step_x, t_max_x += t_delta_x;
        else
            cy += step_y, t_max_y += t_delta_y;
    }
    return false;
}

} // namespace envdesign::floor
