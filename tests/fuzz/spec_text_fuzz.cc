// The design problem reader, protobuf text format: bad input must end in pddl::ParseError.

#include "spec/spec_reader.h"

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    try {
        envdesign::spec::read_spec_text(std::string(reinterpret_cast<const char *>(data), size),
                                        "fuzz.textproto");
    } catch (const envdesign::pddl::ParseError &) {
    }
    return 0;
}
