#pragma once
// A child process for the real-process tests (tests/e2e, tests/bridge): started with
// posix_spawn, its output in a log file, stopped with SIGTERM (then SIGKILL) when the test
// is done with it.

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <fstream>
#include <optional>
#include <spawn.h>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

extern char **environ;

namespace envdesign::testing {

class Process {
public:
    // Runs `argv[0]` (a path) with `argv`; `env` adds or replaces variables; stdout and
    // stderr go to `log`.
    Process(std::vector<std::string> argv, const std::vector<std::string> &env, std::string log)
        : log_(std::move(log)) {
        std::vector<std::string> environment = env;
        for (char **e = environ; *e; ++e) {
            std::string var(*e);
            std::string name = var.substr(0, var.find('='));
            bool replaced = false;
            for (const auto &x : env)
                replaced = replaced || x.substr(0, x.find('=')) == name;
            if (!replaced)
                environment.push_back(var);
        }
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, 1, log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                         0644);
        posix_spawn_file_actions_adddup2(&actions, 1, 2);
        std::vector<char *> args, envp;
        for (auto &a : argv)
            args.push_back(a.data());
        args.push_back(nullptr);
        for (auto &e : environment)
            envp.push_back(e.data());
        envp.push_back(nullptr);
        int rc = posix_spawn(&pid_, args[0], &actions, nullptr, args.data(), envp.data());
        posix_spawn_file_actions_destroy(&actions);
        if (rc != 0)
            throw std::runtime_error("cannot start " + argv[0]);
    }
    Process(std::vector<std::string> argv, std::string log)
        : Process(std::move(argv), {}, std::move(log)) {}
    ~Process() { stop(); }
    Process(const Process &) = delete;
    Process &operator=(const Process &) = delete;

    // The exit code once it exited within `timeout`; nullopt if it is still running.
    std::optional<int> wait(std::chrono::milliseconds timeout) {
        auto until = std::chrono::steady_clock::now() + timeout;
        while (!status_) {
            int status = 0;
            pid_t r = waitpid(pid_, &status, WNOHANG);
            if (r == pid_)
                status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
            else if (std::chrono::steady_clock::now() >= until)
                return std::nullopt;
            else
                std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return status_;
    }
    // The exit code (128 + signal if killed), once it exits.
    int wait() {
        while (!wait(std::chrono::hours(1)))
            ;
        return *status_;
    }
    bool running() { return !wait(std::chrono::milliseconds(0)); }
    pid_t pid() const { return pid_; }
    void signal(int s) const { ::kill(pid_, s); }

    // SIGTERM, then SIGKILL after 5 s; the exit code.
    int stop() {
        if (!status_ && running()) {
            kill(pid_, SIGTERM);
            if (!wait(std::chrono::seconds(5))) {
                kill(pid_, SIGKILL);
                wait(std::chrono::seconds(5));
            }
        }
        return status_.value_or(-1);
    }

    std::string output() const {
        std::ifstream in(log_);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }

private:
    std::string log_;
    pid_t pid_ = -1;
    std::optional<int> status_;
};

} // namespace envdesign::testing
