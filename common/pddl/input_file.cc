#include "pddl/input_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace envdesign::pddl {
namespace {

std::string kind_of(mode_t mode) {
    if (S_ISDIR(mode))
        return "a directory";
    if (S_ISFIFO(mode))
        return "a FIFO";
    if (S_ISCHR(mode) || S_ISBLK(mode))
        return "a device";
    if (S_ISSOCK(mode))
        return "a socket";
    return "not a regular file";
}

class FileDescriptor {
public:
    explicit FileDescriptor(int fd) : fd_(fd) {}
    ~FileDescriptor() {
        if (fd_ >= 0)
            ::close(fd_);
    }
    FileDescriptor(const FileDescriptor &) = delete;
    FileDescriptor &operator=(const FileDescriptor &) = delete;
    int get() const { return fd_; }

private:
    int fd_;
};

} // namespace

std::string read_input_file(const std::string &path, std::size_t max_bytes) {
    Location where{path, 0, 0};
    // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused just below.
    FileDescriptor fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
    if (fd.get() < 0)
        throw ParseError(where, "cannot open file: " + std::string(std::strerror(errno)));
    struct stat info {};
    if (::fstat(fd.get(), &info) != 0)
        throw ParseError(where, "cannot read file: " + std::string(std::strerror(errno)));
    if (!S_ISREG(info.st_mode))
        throw ParseError(where, "not a regular file (" + kind_of(info.st_mode) + ")");
    std::string too_large = "the file is larger than " + std::to_string(max_bytes) + " bytes";
    if (static_cast<std::size_t>(info.st_size) > max_bytes)
        throw ParseError(where, too_large);
    std::string text;
    text.reserve(static_cast<std::size_t>(info.st_size));
    char buffer[65536];
    while (true) {
        ssize_t n = ::read(fd.get(), buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            throw ParseError(where, "cannot read file: " + std::string(std::strerror(errno)));
        if (n == 0)
            return text;
        if (text.size() + static_cast<std::size_t>(n) > max_bytes)
            throw ParseError(where, too_large);
        text.append(buffer, static_cast<std::size_t>(n));
    }
}

} // namespace envdesign::pddl
