#include "output_file.h"

#include "cli_error.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace envdesign::cli {
namespace {

[[noreturn]] void fail(const std::string &path, const std::string &what, int error) {
    throw CommandError(1, "cannot write '" + path + "': " + (what.empty() ? "" : what + ": ") +
                              std::strerror(error));
}

} // namespace

void check_output_path(const std::string &path) {
    std::string directory = std::filesystem::path(path).parent_path().string();
    const std::string shown = directory; // empty: the working directory, not worth naming
    if (directory.empty())
        directory = ".";
    struct stat info {};
    if (::stat(directory.c_str(), &info) != 0)
        fail(path, shown, errno);
    if (!S_ISDIR(info.st_mode))
        fail(path, shown, ENOTDIR);
    if (::access(directory.c_str(), W_OK) != 0)
        fail(path, shown, errno);
    if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
        fail(path, "", EISDIR);
}

void write_output_file(const std::string &path, const std::string &text) {
    errno = 0;
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (!file)
        fail(path, "", errno ? errno : EIO);
    file << text;
    file.close(); // flushes: a full disk shows only here
    if (!file)
        fail(path, "", errno ? errno : EIO);
}

} // namespace envdesign::cli
