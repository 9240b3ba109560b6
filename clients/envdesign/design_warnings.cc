#include "design_warnings.h"

#include <iostream>

namespace envdesign::cli {

void print_warnings(const std::vector<std::string> &warnings) {
    for (const auto &line : warnings)
        std::cerr << (line.find(": warning: ") == std::string::npos ? "warning: " : "") << line
                  << "\n";
}

} // namespace envdesign::cli
