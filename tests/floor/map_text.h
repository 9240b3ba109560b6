#pragma once
// Small building maps written by the tests themselves: a builder of the YAML traffic-editor
// writes, and a scratch folder for the files.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace envdesign::floor::testing {

struct MapText {
    struct Vertex {
        double x, y;
        std::string name;
    };
    struct Lane {
        int from, to;
        std::optional<bool> bidirectional = std::nullopt; // absent: no parameter written
        int graph = 0;
    };
    std::string coordinate_system; // empty: no key
    std::string level = "L1";
    std::vector<Vertex> vertices;
    std::vector<Lane> lanes;
    std::vector<std::pair<int, int>> walls;
    std::vector<std::pair<int, int>> doors;
    struct Measurement {
        int from, to;
        double metres;
    };
    std::vector<Measurement> measurements;

    std::string yaml() const {
        std::ostringstream out;
        if (!coordinate_system.empty())
            out << "coordinate_system: " << coordinate_system << "\n";
        out << "levels:\n  " << level << ":\n    elevation: 0\n    vertices:\n";
        for (const auto &v : vertices)
            out << "      - [" << v.x << ", " << v.y << ", 0, \"" << v.name << "\"]\n";
        out << "    lanes:\n";
        for (const auto &l : lanes) {
            out << "      - [" << l.from << ", " << l.to << ", {";
            if (l.bidirectional)
                out << "bidirectional: [4, " << (*l.bidirectional ? "true" : "false") << "], ";
            out << "graph_idx: [2, " << l.graph << "], orientation: [1, \"\"]}]\n";
        }
        out << "    walls:\n";
        for (const auto &[a, b] : walls)
            out << "      - [" << a << ", " << b << ", {texture_name: [1, default]}]\n";
        if (!doors.empty()) {
            out << "    doors:\n";
            for (const auto &[a, b] : doors)
                out << "      - [" << a << ", " << b << ", {name: [1, door], type: [1, hinged]}]\n";
        }
        if (!measurements.empty()) {
            out << "    measurements:\n";
            for (const auto &m : measurements)
                out << "      - [" << m.from << ", " << m.to << ", {distance: [3, " << m.metres
                    << "]}]\n";
        }
        out << "lifts: {}\nname: building\n";
        return out.str();
    }
};

// The scratch folders of this process, removed when it ends.
struct ScratchFolders {
    std::vector<std::filesystem::path> made;
    ~ScratchFolders() {
        std::error_code ec;
        for (const auto &dir : made)
            std::filesystem::remove_all(dir, ec);
    }
};
inline ScratchFolders scratch_folders;

// A fresh folder under the system's temporary folder.
inline std::filesystem::path scratch_dir(const std::string &name) {
    auto dir = std::filesystem::temp_directory_path() /
               ("envdesign-floor-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    scratch_folders.made.push_back(dir);
    return dir;
}

inline std::string write_text(const std::filesystem::path &path, const std::string &text) {
    std::ofstream(path) << text;
    return path.string();
}

inline std::string read_text(const std::filesystem::path &path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace envdesign::floor::testing
