// The PDDL reader and the grounder: a domain and a problem, separated by the first NUL byte.
// Bad input must end in pddl::ParseError (or a grounding stopped by its time limit), never
// in a crash, a hang or undefined behaviour.

#include "ground/grounder.h"
#include "pddl/parser.h"
#include "pddl/sexpr.h"

#include <chrono>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace envdesign;
    std::string input(reinterpret_cast<const char *>(data), size);
    auto nul = input.find('\0');
    std::string domain_text = input.substr(0, nul);
    std::string problem_text = nul == std::string::npos ? "" : input.substr(nul + 1);
    try {
        pddl::Domain domain = pddl::parse_domain(pddl::read_sexpr(domain_text, "d.pddl"), "d.pddl");
        pddl::Problem problem =
            pddl::parse_problem(pddl::read_sexpr(problem_text, "p.pddl"), "p.pddl", domain);
        // Small inputs can still ground to a lot: half a second, as a time limit would.
        auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
        ground::ground(domain, problem, nullptr,
                       [&] { return std::chrono::steady_clock::now() > until; });
    } catch (const pddl::ParseError &) {
    } catch (const ground::GroundingStopped &) {
    }
    return 0;
}
