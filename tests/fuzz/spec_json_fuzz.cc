// The design problem reader, protobuf JSON (with the position scan and the depth and number
// checks): bad input must end in pddl::ParseError.

#include "spec/spec_reader.h"

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    try {
        envdesign::spec::read_spec_text(std::string(reinterpret_cast<const char *>(data), size),
                                        "fuzz.json");
    } catch (const envdesign::pddl::ParseError &) {
    }
    return 0;
}
