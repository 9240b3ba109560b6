#include "cluster/design_change.h"

namespace envdesign::cluster {

std::string braced(const std::vector<std::string> &names) {
    std::string out = "{";
    for (const auto &n : names)
        out += (out.size() > 1 ? ", " : "") + n;
    return out + "}";
}

std::string design_change(const std::vector<std::string> *before,
                          const envdesign::design_result_t &result) {
    if (!result.has_design)
        return "no design (" + result.status + ")";
    if (!before)
        return "design " + braced(result.design);
    if (*before == result.design)
        return "design " + braced(result.design) + " unchanged";
    return "design " + braced(*before) + " -> " + braced(result.design);
}

} // namespace envdesign::cluster
