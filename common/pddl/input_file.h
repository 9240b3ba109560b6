#pragma once
// Reading an input file (PDDL, design problem, plan) whole, with bounds: anything that is
// not a regular file (a FIFO would block, /dev/zero never ends, a directory has no text) and
// anything larger than a limit is refused before it is read.
//
//   std::string text = read_input_file("domain.pddl");   // throws ParseError "PATH: error: ..."

#include "pddl/parse_error.h"

#include <cstddef>
#include <string>

namespace envdesign::pddl {

// Far above any planning benchmark or design problem (IPC's largest PDDL files are a few MB).
inline constexpr std::size_t MAX_INPUT_FILE_BYTES = 64u << 20;

// The content of `path`. Throws ParseError at PATH (line 0: the whole file; printed as
// "PATH: error: cannot open file: No such file or directory") when it cannot be opened, is not a
// regular file, or holds more than `max_bytes` bytes (checked while reading too, in case the
// file grows).
std::string read_input_file(const std::string &path, std::size_t max_bytes = MAX_INPUT_FILE_BYTES);

} // namespace envdesign::pddl
