#include "service_main.h"

#include "bus/lcm_url.h"
#include "bus/log.h"

#include <atomic>
#include <csignal>
#include <iostream>

namespace envdesign::services {
namespace {

std::atomic<int> g_signal{0}; // the one global: signal handlers cannot reach anything else

extern "C" void on_signal(int signal) { g_signal = signal; }

} // namespace

void add_common_flags(CLI::App &app, CommonFlags &flags) {
    app.add_option("--lcm-url", flags.lcm_url,
                   "LCM URL (default: $LCM_DEFAULT_URL, else udpm://239.255.76.67:7667?ttl=0)");
    app.add_option("--name", flags.name, "instance name on the bus (default: ROLE/HOST/PID)");
    app.add_option("--key-file", flags.key_file,
                   "bus keys, 'KEY_ID HEX_SECRET' a line, mode 0600 (default: "
                   "$ENVDESIGN_KEY_FILE; none: the bus is unauthenticated)");
    app.add_option("--log-level", flags.log_level, "trace|debug|info|warn|error|off")
        ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "critical", "off"}));
}

Service open_service(const std::string &role, const CommonFlags &flags) {
    Service s;
    s.instance = flags.name.empty() ? bus::instance_name(role) : flags.name;
    s.log = bus::make_logger(s.instance, spdlog::level::from_str(flags.log_level));
    std::string url =
        bus::with_receive_buffer(flags.lcm_url.empty() ? bus::default_url() : flags.lcm_url);
    std::shared_ptr<const bus::KeyRing> keys;
    if (auto path = bus::key_file_path(flags.key_file))
        keys = std::make_shared<const bus::KeyRing>(bus::load_key_file(*path));
    s.bus = std::make_unique<bus::Bus>(url, s.log, keys);
    s.log->info("request - | on {}", url);
    if (keys)
        s.log->info("request - | bus authenticated: signing with key '{}', {} key(s) accepted",
                    keys->keys.front().id, keys->keys.size());
    else
        s.log->warn("request - | the bus is unauthenticated (no --key-file or "
                    "ENVDESIGN_KEY_FILE): anyone on the network can change results");
    return s;
}

std::optional<int> parse_command_line(CLI::App &app, int argc, char **argv,
                                      const std::function<void()> &check) {
    try {
        app.parse(argc, argv);
        if (check)
            check();
    } catch (const CLI::ParseError &e) {
        int code = app.exit(e);
        return e.get_exit_code() == 0 ? code : 2;
    }
    return std::nullopt;
}

int serve(const std::string &role, const CommonFlags &flags,
          const std::function<int(Service &)> &run) {
    std::string url = flags.lcm_url.empty() ? bus::default_url() : flags.lcm_url;
    if (auto problem = bus::url_problem(url)) {
        std::cerr << "envdesign-" << role << ": --lcm-url: " << *problem << std::endl;
        return 2;
    }
    try {
        Service service = open_service(role, flags);
        return run(service);
    } catch (const bus::KeyFileError &e) {
        std::cerr << "envdesign-" << role << ": --key-file: " << e.what() << std::endl;
        return 2;
    } catch (const std::exception &e) {
        std::cerr << "envdesign-" << role << ": " << e.what() << std::endl;
        return 1;
    }
}

int run_until_signal(Service &service, const std::function<int()> &tick) {
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    std::signal(SIGPIPE, SIG_IGN);
    int failures = 0; // in a row; a signal interrupting the wait fails one too
    int wait_ms = 0;
    while (g_signal == 0) {
        bool failed = service.bus->handle(std::chrono::milliseconds(wait_ms)) < 0;
        failures = failed && g_signal == 0 ? failures + 1 : 0;
        if (failures >= 100) {
            service.log->error("request - | LCM keeps failing; stopping");
            return 1;
        }
        wait_ms = tick();
    }
    service.log->info("request - | signal {}: stopping", g_signal.load());
    return 0;
}

int run_until_signal(Service &service, const std::function<void()> &tick, int period_ms) {
    return run_until_signal(service, std::function<int()>([&] {
                                tick();
                                return period_ms;
                            }));
}

} // namespace envdesign::services
