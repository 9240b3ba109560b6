// Records read back from the coordinator's state file (design/evaluation/evaluation_record.h): any
// bytes either decode to values design/model/numbers.h accepts, which encode and decode again to
// the same record, or are refused; never a crash, never NaN or 1e308 let through (issue 21).

#include "design/evaluation/evaluation_record.h"
#include "design/model/numbers.h"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace envdesign::design;
    std::string bytes(reinterpret_cast<const char *>(data), size);
    if (auto e = decode_evaluation(bytes)) {
        if (evaluation_problem(*e))
            std::abort(); // a value the wire would refuse came out of the store
        std::string again = encode_evaluation(*e);
        auto back = decode_evaluation(again);
        if (!back || encode_evaluation(*back) != again)
            std::abort();
    }
    if (auto bound = decode_robot_bound(bytes)) {
        if (!valid_plan_cost(bound->cost) || (bound->ie_floor && !valid_ie(*bound->ie_floor)) ||
            (bound->explanation_floor && !valid_explanation_floor(*bound->explanation_floor)))
            std::abort();
        auto back = decode_robot_bound(encode_robot_bound(*bound));
        if (!back || back->cost != bound->cost || back->ie_floor != bound->ie_floor ||
            back->explanation_floor != bound->explanation_floor)
            std::abort();
    }
    return 0;
}
