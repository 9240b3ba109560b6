#pragma once
// Runs the built envdesign binary as a real process and captures what it prints.

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace envdesign::testing {

// tests/data; here once, as test files of a unity batch share their file-local names.
inline const std::string DATA = ENVDESIGN_TEST_DATA;
// A file under tests/data.
inline std::string data(const std::string &name) { return DATA + "/" + name; }

struct CommandResult {
    int exit_code = -1;
    std::string out; // stdout and, with `merge_stderr`, stderr
};

// A shell command line, its stdout captured (redirect stderr in `command` to keep it too).
inline CommandResult run_shell(const std::string &command) {
    CommandResult result;
    FILE *pipe = popen(command.c_str(), "r");
    if (!pipe)
        return result;
    std::array<char, 4096> buffer;
    while (std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe))
        result.out.append(buffer.data(), n);
    int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

inline CommandResult run_envdesign(const std::string &arguments, bool merge_stderr = true) {
    return run_shell(std::string(ENVDESIGN_BIN_DIR) + "/envdesign " + arguments +
                     (merge_stderr ? " 2>&1" : " 2>/dev/null"));
}

} // namespace envdesign::testing
