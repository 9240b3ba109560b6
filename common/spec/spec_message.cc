#include "spec/spec_message.h"

#include "spec/file_source.h"
#include "spec/spec_reader.h"

namespace envdesign::spec {

design::DesignProblem load_spec(const envdesign::spec_t &spec, Checks checks) {
    return load_design_problem(read_spec_text(spec.text, spec.name), MessageFiles(spec), checks);
}

} // namespace envdesign::spec
