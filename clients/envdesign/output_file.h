#pragma once
// Files the CLI writes (`report -o`, `plan --plan-file`): the path is checked before the work
// starts, so that a typo fails at once and not after a long search, and every failure names
// the OS's reason. Both throw CommandError with exit code 1 (docs/cli.md: the output cannot be
// written), e.g. "cannot write 'out/r.html': out: No such file or directory".

#include <string>

namespace envdesign::cli {

// Throws unless `path` could be created or replaced now: its directory exists, is a
// directory and is writable, and `path` is not itself a directory. Writes nothing.
void check_output_path(const std::string &path);

// Writes `text` to `path` (replacing it); throws on any failure, a full disk included.
void write_output_file(const std::string &path, const std::string &text);

} // namespace envdesign::cli
