# Run after lcm-gen on its C++ headers (cmake -DDIR=<cpp dir> -P harden_decode.cmake).
# lcm-gen 1.3.1's decoders check a string's length from the wire only from above: a negative
# one passes, `len - 1` overflows and std::string::assign reads gigabytes past the datagram, so
# one forged message crashes any service (SIGSEGV; found by tests/fuzz, planner target).
# The encoders always count the terminating NUL, so a length below 1 is refused like one that
# runs past the end; the same for the strings of a string array (`__elem_len`), which the
# first fix missed.
# An array's length from the wire was not checked at all before `resize`: a 200-byte
# evaluation_t with optimal_actions_length 0x15ff0000 made the decoder construct 11 GB of
# std::string (found by tests/fuzz, wire_numbers target). Every element takes at least one
# byte on the wire, so a length that is negative or above the bytes left is refused first.
file(GLOB headers ${DIR}/envdesign/*.hpp)
foreach(header ${headers})
    file(READ ${header} text)
    string(REGEX REPLACE "if\\((__[A-Za-z0-9_]+_len__) > maxlen - pos\\) return -1;"
        "if(\\1 < 1 || \\1 > maxlen - pos) return -1;" patched "${text}")
    string(REGEX REPLACE "if\\(__elem_len > maxlen - pos\\) return -1;"
        "if(__elem_len < 1 || __elem_len > maxlen - pos) return -1;" patched "${patched}")
    string(REGEX REPLACE "this->([A-Za-z0-9_]+)\\.resize\\(this->([A-Za-z0-9_]+)\\);"
        "if(this->\\2 < 0 || this->\\2 > maxlen - pos) return -1;\n    this->\\1.resize(this->\\2);"
        patched "${patched}")
    if(NOT patched STREQUAL text)
        file(WRITE ${header} "${patched}")
    endif()
endforeach()
