#pragma once
// What changed between a client's last design and a new result, in one line, for the
// `change` of a result (design_result_t) and for logs: "design {a} -> {a, b}", "design {a}
// unchanged", "design {a}" (no earlier one), or "no design (best_found)".

#include "envdesign/design_result_t.hpp"

#include <string>
#include <vector>

namespace envdesign::cluster {

// "{a, b}"
std::string braced(const std::vector<std::string> &names);

// `before`: the client's last design, null if it had none.
std::string design_change(const std::vector<std::string> *before,
                          const envdesign::design_result_t &result);

} // namespace envdesign::cluster
