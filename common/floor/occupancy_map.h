#pragma once
// A ROS occupancy map (map_server's `map.yaml` beside a PGM image) as a grid of cells that
// block sight lines. A cell is occupied as map_server's trinary mode reads it: with p the
// darkness of its pixel, (255 - v) / 255 (v / 255 with `negate: 1`), occupied iff
// p > occupied_thresh. Free and unknown cells do not block.
//
//   OccupancyGrid grid = read_occupancy_map("map.yaml");
//   grid.blocks({p, q})   // does the segment pass through an occupied cell?

#include "geometry.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace envdesign::floor {

inline constexpr std::size_t MAX_MAP_CELLS = std::size_t(1) << 26; // 8192 x 8192

struct OccupancyGrid {
    int width = 0; // cells
    int height = 0;
    double resolution = 1;              // metres a cell
    Point origin;                       // metres: the lower-left corner of the lower-left cell
    std::vector<std::uint8_t> occupied; // row 0 at the bottom (y up), width x height

    bool occupied_at(int col, int row) const {
        return occupied[static_cast<std::size_t>(row) * width + col];
    }

    // True if the segment passes through an occupied cell other than the cells holding its
    // endpoints (a place drawn on an obstacle's edge still sees out). The cells are those a
    // grid traversal visits (Amanatides & Woo); a line exactly through a cell corner visits
    // the cells on one side of it.
    bool blocks(const Segment &s) const;
};

// Reads map.yaml (image, resolution, origin, negate, occupied_thresh, free_thresh, mode) and
// its image, a PGM (netpbm P5 or P2) relative to the YAML. Throws pddl::ParseError at
// FILE:LINE:COL for a fault in either; a mode other than trinary, a rotated origin (yaw
// != 0) and images of other formats are refused.
OccupancyGrid read_occupancy_map(const std::string &yaml_path);

// read_occupancy_map of the text `yaml_text` (named `yaml_path` in errors); `read_image` gives
// the bytes of the image its `image` names (a path relative to the YAML made absolute as
// read_occupancy_map does) or throws pddl::ParseError.
OccupancyGrid
parse_occupancy_map(const std::string &yaml_text, const std::string &yaml_path,
                    const std::function<std::string(const std::string &)> &read_image);

// The PGM image in `bytes` (for tests): width, height, and the grey values row by row from
// the top, scaled to 0..255.
struct GreyImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> grey;
};
GreyImage parse_pgm(const std::string &bytes, const std::string &path);

} // namespace envdesign::floor
