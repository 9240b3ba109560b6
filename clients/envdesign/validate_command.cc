#include "validate_command.h"

#include "pddl/parser.h"
#include "validate/plan_validator.h"

#include <iostream>

namespace envdesign::cli {

void add_validate_flags(CLI::App &command, ValidateFlags &flags) {
    command.add_option("domain", flags.domain, "PDDL domain file")->required();
    command.add_option("problem", flags.problem, "PDDL problem file")->required();
    command.add_option("plan", flags.plan, "plan file (sas_plan format)")->required();
}

int run_validate(const ValidateFlags &flags) {
    // Bad input throws pddl::ParseError: main() reports it (exit 2).
    pddl::Domain domain = pddl::parse_domain_file(flags.domain);
    pddl::Problem problem = pddl::parse_problem_file(flags.problem, domain);
    auto plan = validate::read_plan_file(flags.plan);
    validate::Validation result = validate::validate_plan(domain, problem, plan);
    if (!result.valid) {
        std::cout << "invalid: " << result.error << "\n";
        return 1;
    }
    std::cout << "valid: cost = " << result.cost << ", " << plan.size() << " steps\n";
    return 0;
}

} // namespace envdesign::cli
