// A test-only LD_PRELOAD library that injects loss, duplication and reordering into the UDP
// datagrams a process sends (netem is not available on our machines, PLATFORM.md §11). It
// wraps send, sendto, sendmsg and sendmmsg (LCM 1.3.1's udpm sends with sendmsg, Cyclone DDS
// with sendmsg, Python's socket module with sendto); only AF_INET/AF_INET6 datagram sockets
// are touched, so sd_notify's unix socket and every stream pass through as they are.
//
//   env ENVDESIGN_SHIM_LOSS=5 ENVDESIGN_SHIM_DUPLICATE=5 ENVDESIGN_SHIM_REORDER=10
//       ENVDESIGN_SHIM_SEED=42 ENVDESIGN_SHIM_COUNTS=/tmp/shim-%p.txt
//       LD_PRELOAD=build/lib/libenvdesign_udp_shim.so envdesign-planner ...
//
// Rates are percentages per datagram, drawn from one seeded generator per process (the same
// seed and the same sends give the same faults). Loss: the datagram is not sent (the call
// still reports it sent, as a lossy wire would). Duplication: it is sent twice in a row.
// Reordering: it is held back and sent right after the process's next datagram, or after
// ENVDESIGN_SHIM_HOLD_MS (5) if none follows, or when the program exits.
//
// ENVDESIGN_SHIM_COUNTS names a file ("%p": the pid) that holds the counts as one line of
// text, kept in a shared mapping so that it is current even after a SIGKILL. A bad value
// stops the process at start with exit code 2 and the variable's name.

#include <dlfcn.h>
#include <fcntl.h>
#include <pthread.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

namespace {

using SendmsgFn = ssize_t (*)(int, const msghdr *, int);

struct Config {
    double loss = 0, duplicate = 0, reorder = 0; // probabilities, 0..1
    long hold_ms = 5;
    bool active = false;
};

// A datagram held back for reordering, with a dup of its socket so that a close() by the
// program cannot make us send on another file that reused the number.
struct Held {
    bool present = false;
    int fd = -1;
    int flags = 0;
    sockaddr_storage name;
    socklen_t name_len = 0;
    char *data = nullptr;
    size_t size = 0;
    char *control = nullptr;
    size_t control_size = 0;
    timespec deadline;
};

struct Counts {
    unsigned long long datagrams = 0, dropped = 0, duplicated = 0, reordered = 0, delayed = 0;
};

Config g_config;
SendmsgFn g_sendmsg = nullptr;
pthread_mutex_t g_mutex = PTHREAD_MUTEX_INITIALIZER; // guards everything below
pthread_cond_t g_held_cond = PTHREAD_COND_INITIALIZER;
std::uint64_t g_random = 0;
Held g_held;
Counts g_counts;
bool g_flusher_started = false;
char *g_counts_map = nullptr; // the counts file's mapping, or null
constexpr size_t COUNTS_BYTES = 160;

[[noreturn]] void fail(const char *variable, const char *value, const char *why) {
    std::fprintf(stderr, "udp_shim: %s=%s: %s\n", variable, value, why);
    _exit(2);
}

double percent(const char *variable) {
    const char *value = std::getenv(variable);
    if (!value || !*value)
        return 0;
    char *end = nullptr;
    errno = 0;
    double p = std::strtod(value, &end);
    if (errno || *end || p < 0 || p > 100)
        fail(variable, value, "expected a percentage from 0 to 100");
    return p / 100;
}

std::uint64_t splitmix64() {
    std::uint64_t z = (g_random += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// True with probability `p`; g_mutex held.
bool chance(double p) { return p > 0 && static_cast<double>(splitmix64() >> 11) * 0x1.0p-53 < p; }

// Rewrites the counts line in place (fixed width, so a reader never sees a shorter line);
// g_mutex held.
void write_counts() {
    if (!g_counts_map)
        return;
    char line[COUNTS_BYTES];
    int n = std::snprintf(line, sizeof line,
                          "datagrams=%012llu dropped=%012llu duplicated=%012llu "
                          "reordered=%012llu delayed=%012llu\n",
                          g_counts.datagrams, g_counts.dropped, g_counts.duplicated,
                          g_counts.reordered, g_counts.delayed);
    std::memcpy(g_counts_map, line, static_cast<size_t>(n)); // no NUL: the rest stays blank
}

void map_counts(const char *pattern) {
    char path[4096];
    size_t n = 0;
    for (const char *p = pattern; *p && n + 24 < sizeof path; ++p) {
        if (p[0] == '%' && p[1] == 'p') {
            n += std::snprintf(path + n, sizeof path - n, "%ld", static_cast<long>(getpid()));
            ++p;
        } else {
            path[n++] = *p;
        }
    }
    path[n] = '\0';
    int fd = open(path, O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0 || ftruncate(fd, COUNTS_BYTES) != 0)
        fail("ENVDESIGN_SHIM_COUNTS", pattern, std::strerror(errno));
    void *map = mmap(nullptr, COUNTS_BYTES, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
    close(fd);
    if (map == MAP_FAILED)
        fail("ENVDESIGN_SHIM_COUNTS", pattern, std::strerror(errno));
    g_counts_map = static_cast<char *>(map);
    std::memset(g_counts_map, ' ', COUNTS_BYTES);
    write_counts();
}

void forget_held() {
    if (g_held.present)
        close(g_held.fd);
    std::free(g_held.data);
    std::free(g_held.control);
    g_held = Held{};
}

// In a forked child the flusher thread does not exist and the parent's held datagram is
// not ours to send.
void after_fork_in_child() {
    pthread_mutex_init(&g_mutex, nullptr);
    pthread_cond_init(&g_held_cond, nullptr);
    g_flusher_started = false;
    forget_held();
}

__attribute__((constructor)) void start() {
    g_sendmsg = reinterpret_cast<SendmsgFn>(dlsym(RTLD_NEXT, "sendmsg"));
    if (!g_sendmsg) {
        std::fprintf(stderr, "udp_shim: no sendmsg to wrap: %s\n", dlerror());
        _exit(2);
    }
    g_config.loss = percent("ENVDESIGN_SHIM_LOSS");
    g_config.duplicate = percent("ENVDESIGN_SHIM_DUPLICATE");
    g_config.reorder = percent("ENVDESIGN_SHIM_REORDER");
    g_config.active = g_config.loss > 0 || g_config.duplicate > 0 || g_config.reorder > 0;
    if (const char *hold = std::getenv("ENVDESIGN_SHIM_HOLD_MS"); hold && *hold) {
        char *end = nullptr;
        g_config.hold_ms = std::strtol(hold, &end, 10);
        if (*end || g_config.hold_ms < 1 || g_config.hold_ms > 10000)
            fail("ENVDESIGN_SHIM_HOLD_MS", hold, "expected milliseconds from 1 to 10000");
    }
    const char *seed = std::getenv("ENVDESIGN_SHIM_SEED");
    if (seed && *seed) {
        char *end = nullptr;
        errno = 0;
        g_random = std::strtoull(seed, &end, 10);
        if (errno || *end)
            fail("ENVDESIGN_SHIM_SEED", seed, "expected an unsigned integer");
    } else {
        g_random = static_cast<std::uint64_t>(time(nullptr)) * 1000003u + getpid();
    }
    if (const char *counts = std::getenv("ENVDESIGN_SHIM_COUNTS"); counts && *counts)
        map_counts(counts);
    pthread_atfork(nullptr, nullptr, after_fork_in_child);
}

bool is_udp(int fd) {
    int type = 0, domain = 0;
    socklen_t size = sizeof type;
    if (getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &size) != 0 || type != SOCK_DGRAM)
        return false;
    size = sizeof domain;
    return getsockopt(fd, SOL_SOCKET, SO_DOMAIN, &domain, &size) == 0 &&
           (domain == AF_INET || domain == AF_INET6);
}

size_t total_size(const msghdr *m) {
    size_t n = 0;
    for (size_t i = 0; i < m->msg_iovlen; ++i)
        n += m->msg_iov[i].iov_len;
    return n;
}

// Copies `m` into g_held; false if it cannot (then the datagram is sent as it is).
bool hold(int fd, const msghdr *m, int flags) {
    Held h;
    h.size = total_size(m);
    h.data = static_cast<char *>(std::malloc(h.size ? h.size : 1));
    h.control_size = m->msg_controllen;
    h.control = static_cast<char *>(std::malloc(h.control_size ? h.control_size : 1));
    h.fd = dup(fd);
    if (!h.data || !h.control || h.fd < 0 || m->msg_namelen > sizeof h.name) {
        if (h.fd >= 0)
            close(h.fd);
        std::free(h.data);
        std::free(h.control);
        return false;
    }
    size_t at = 0;
    for (size_t i = 0; i < m->msg_iovlen; ++i) {
        std::memcpy(h.data + at, m->msg_iov[i].iov_base, m->msg_iov[i].iov_len);
        at += m->msg_iov[i].iov_len;
    }
    if (h.control_size)
        std::memcpy(h.control, m->msg_control, h.control_size);
    h.name_len = m->msg_name ? m->msg_namelen : 0;
    if (h.name_len)
        std::memcpy(&h.name, m->msg_name, h.name_len);
    h.flags = flags;
    clock_gettime(CLOCK_MONOTONIC, &h.deadline);
    h.deadline.tv_nsec += g_config.hold_ms * 1000000L;
    h.deadline.tv_sec += h.deadline.tv_nsec / 1000000000L;
    h.deadline.tv_nsec %= 1000000000L;
    h.present = true;
    g_held = h;
    return true;
}

// Sends a datagram taken out of g_held (without g_mutex) and frees it.
void send_held(Held h) {
    iovec iov{h.data, h.size};
    msghdr m{};
    m.msg_name = h.name_len ? &h.name : nullptr;
    m.msg_namelen = h.name_len;
    m.msg_iov = &iov;
    m.msg_iovlen = 1;
    m.msg_control = h.control_size ? h.control : nullptr;
    m.msg_controllen = h.control_size;
    g_sendmsg(h.fd, &m, h.flags);
    close(h.fd);
    std::free(h.data);
    std::free(h.control);
}

// Takes the held datagram out (g_mutex held); `present` false if there was none.
Held take_held() {
    Held h = g_held;
    g_held = Held{};
    return h;
}

// Sends what stays held past its deadline: no later datagram came to overtake it.
void *flusher(void *) {
    pthread_mutex_lock(&g_mutex);
    for (;;) {
        if (!g_held.present) {
            pthread_cond_wait(&g_held_cond, &g_mutex);
            continue;
        }
        timespec deadline = g_held.deadline;
        if (pthread_cond_timedwait(&g_held_cond, &g_mutex, &deadline) != ETIMEDOUT)
            continue;
        if (!g_held.present)
            continue;
        Held h = take_held();
        ++g_counts.delayed;
        write_counts();
        pthread_mutex_unlock(&g_mutex);
        send_held(h);
        pthread_mutex_lock(&g_mutex);
    }
    return nullptr;
}

// A datagram still held when the program exits goes out then (a SIGKILL loses it).
__attribute__((destructor)) void finish() {
    pthread_mutex_lock(&g_mutex);
    Held h = take_held();
    g_counts.delayed += h.present;
    write_counts();
    pthread_mutex_unlock(&g_mutex);
    if (h.present)
        send_held(h);
}

// g_mutex held. The condition variable waits on CLOCK_MONOTONIC, as the deadlines are.
void start_flusher() {
    if (g_flusher_started)
        return;
    pthread_condattr_t attr;
    pthread_condattr_init(&attr);
    pthread_condattr_setclock(&attr, CLOCK_MONOTONIC);
    pthread_cond_init(&g_held_cond, &attr);
    pthread_condattr_destroy(&attr);
    pthread_t thread;
    if (pthread_create(&thread, nullptr, flusher, nullptr) == 0) {
        pthread_detach(thread);
        g_flusher_started = true;
    }
}

// One datagram through the faults; what sendmsg would return.
ssize_t shim_sendmsg(int fd, const msghdr *m, int flags) {
    if (!g_config.active || !is_udp(fd))
        return g_sendmsg(fd, m, flags);
    ssize_t size = static_cast<ssize_t>(total_size(m));
    pthread_mutex_lock(&g_mutex);
    ++g_counts.datagrams;
    bool drop = chance(g_config.loss);
    bool held = !drop && !g_held.present && chance(g_config.reorder);
    bool twice = !drop && !held && chance(g_config.duplicate);
    g_counts.dropped += drop;
    if (held) {
        start_flusher();
        held = g_flusher_started && hold(fd, m, flags);
        if (held)
            pthread_cond_signal(&g_held_cond);
    }
    Held overtaken{};
    if (!drop && !held && g_held.present) {
        overtaken = take_held();
        ++g_counts.reordered;
    }
    g_counts.duplicated += twice;
    write_counts();
    pthread_mutex_unlock(&g_mutex);
    if (drop || held)
        return size;
    ssize_t sent = g_sendmsg(fd, m, flags);
    if (twice)
        g_sendmsg(fd, m, flags);
    if (overtaken.present)
        send_held(overtaken);
    return sent;
}

} // namespace

extern "C" {

ssize_t sendmsg(int fd, const msghdr *m, int flags) {
    if (!g_sendmsg) // called before our constructor ran (another library's constructor)
        g_sendmsg = reinterpret_cast<SendmsgFn>(dlsym(RTLD_NEXT, "sendmsg"));
    return shim_sendmsg(fd, m, flags);
}

ssize_t sendto(int fd, const void *buffer, size_t size, int flags, const sockaddr *to,
               socklen_t to_len) {
    iovec iov{const_cast<void *>(buffer), size};
    msghdr m{};
    m.msg_name = const_cast<sockaddr *>(to);
    m.msg_namelen = to ? to_len : 0;
    m.msg_iov = &iov;
    m.msg_iovlen = 1;
    return sendmsg(fd, &m, flags);
}

ssize_t send(int fd, const void *buffer, size_t size, int flags) {
    return sendto(fd, buffer, size, flags, nullptr, 0);
}

int sendmmsg(int fd, mmsghdr *messages, unsigned int count, int flags) {
    unsigned int i = 0;
    for (; i < count; ++i) {
        ssize_t n = sendmsg(fd, &messages[i].msg_hdr, flags);
        if (n < 0)
            return i > 0 ? static_cast<int>(i) : -1;
        messages[i].msg_len = static_cast<unsigned int>(n);
    }
    return static_cast<int>(i);
}

} // extern "C"
