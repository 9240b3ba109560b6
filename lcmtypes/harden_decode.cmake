# Run after lcm-gen on its C++ headers (cmake -DDIR=<cpp dir> -P harden_decode.cmake).
# lcm-gen 1.3.1's decoders check a string's length from the wire only from above: a negative
# one passes, `len - 1` overflows and std::string::assign reads gigabytes past the datagram, so
# one forged message crashes any service (SIGSEGV; found by tests/fuzz, planner target).
# The encoders always count the terminating NUL, so a length below 1 is refused like one that
# runs past the end.
file(GLOB headers ${DIR}/envdesign/*.hpp)
foreach(header ${headers})
    file(READ ${header} text)
    string(REGEX REPLACE "if\\((__[A-Za-z0-9_]+_len__) > maxlen - pos\\) return -1;"
        "if(\\1 < 1 || \\1 > maxlen - pos) return -1;" patched "${text}")
    if(NOT patched STREQUAL text)
        file(WRITE ${header} "${patched}")
    endif()
endforeach()
