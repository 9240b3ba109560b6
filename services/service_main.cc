#include "service_main.h"

#include "service/config_file.h"
#include "service/systemd_notify.h"

#include "bus/lcm_url.h"
#include "bus/log.h"

#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <csignal>
#include <iostream>
#include <map>
#include <set>

namespace envdesign::services {
namespace {

std::atomic<int> g_signal{0}; // the one global: signal handlers cannot reach anything else

extern "C" void on_signal(int signal) { g_signal = signal; }

// The value of --config in `args`, if given.
std::optional<std::string> config_path(const std::vector<std::string> &args) {
    for (std::size_t i = 1; i < args.size(); ++i) {
        if (args[i] == "--config" && i + 1 < args.size())
            return args[i + 1];
        if (args[i].starts_with("--config="))
            return args[i].substr(9);
    }
    return std::nullopt;
}

// The long flags named in `args` ("--name" or "--name=value").
std::set<std::string> named_flags(const std::vector<std::string> &args) {
    std::set<std::string> names;
    for (std::size_t i = 1; i < args.size(); ++i)
        if (args[i].starts_with("--") && args[i].size() > 2)
            names.insert(args[i].substr(2, args[i].find('=') - 2));
    return names;
}

// Where a setting of the config file is: "FILE:LINE:COL", by flag name.
using SettingPlaces = std::map<std::string, std::string>;

// The settings of the config file as "--key=value" arguments, those the command line does
// not override; throws service::ConfigError for a key that names no flag of `app` (nor a
// flag that is no setting: "version = true" made a service print its version and exit 0).
std::vector<std::string> config_arguments(const CLI::App &app, const std::string &program,
                                          const std::string &path,
                                          const std::set<std::string> &on_command_line,
                                          SettingPlaces &places) {
    static const std::set<std::string> NOT_SETTINGS = {"config", "check-config", "help", "version"};
    std::vector<std::string> out;
    for (const envdesign::service::ConfigSetting &s : envdesign::service::read_config_file(path)) {
        places["--" + s.key] =
            path + ":" + std::to_string(s.line) + ":" + std::to_string(s.key_column);
        if (NOT_SETTINGS.count(s.key) || app.get_option_no_throw("--" + s.key) == nullptr)
            throw envdesign::service::ConfigError(path + ":" + std::to_string(s.line) + ":" +
                                                  std::to_string(s.key_column) +
                                                  ": error: unknown setting '" + s.key + "' (" +
                                                  program + " has no --" + s.key + ")");
        if (!on_command_line.count(s.key))
            out.push_back("--" + s.key + "=" + s.value);
    }
    return out;
}

// A flag's error names its place in the config file when the file set it.
std::string placed(const std::string &message, const SettingPlaces &places) {
    for (const auto &[flag, place] : places) {
        auto at = message.find(flag);
        if (at != std::string::npos &&
            (at + flag.size() == message.size() ||
             (!std::isalnum(message[at + flag.size()]) && message[at + flag.size()] != '-')))
            return place + ": error: " + message;
    }
    return message;
}

// What start-up would fail on beyond the flags' own checks: the LCM URL and the key file.
std::optional<std::string> startup_problem(const CLI::App &app) {
    std::string url = app.get_option("--lcm-url")->as<std::string>();
    if (url.empty())
        url = bus::default_url();
    if (auto problem = bus::url_problem(url))
        return "--lcm-url: " + *problem;
    if (!lcm::LCM(url).good()) // an address or port it cannot use
        return "--lcm-url: LCM cannot start on '" + url + "'";
    try {
        if (auto path = bus::key_file_path(app.get_option("--key-file")->as<std::string>()))
            bus::load_key_file(*path);
    } catch (const bus::KeyFileError &e) {
        return std::string("--key-file: ") + e.what();
    }
    return std::nullopt;
}

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
    app.add_option("--config", flags.config,
                   "settings file: 'flag-name = value' a line; command-line flags win");
    app.add_flag("--check-config", flags.check_config,
                 "check the flags and --config, then exit (0: all good)");
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
    s.keys = keys;
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
                                      const std::function<void()> &check,
                                      const StartupCheck &startup) {
    std::vector<std::string> args(argv, argv + argc);
    SettingPlaces places;
    try {
        if (auto path = config_path(args)) {
            std::string program = args[0].substr(args[0].rfind('/') + 1);
            std::vector<std::string> settings =
                config_arguments(app, program, *path, named_flags(args), places);
            args.insert(args.begin() + 1, settings.begin(), settings.end());
        }
    } catch (const envdesign::service::ConfigError &e) {
        std::cerr << e.what() << std::endl;
        return 2;
    }
    std::vector<char *> pointers;
    for (auto &a : args)
        pointers.push_back(a.data());
    try {
        app.parse(static_cast<int>(pointers.size()), pointers.data());
        if (check)
            check();
    } catch (const CLI::ParseError &e) {
        if (e.get_exit_code() == 0) // --help
            return app.exit(e);
        if (places.empty())
            app.exit(e); // CLI11's message
        else
            std::cerr << placed(e.what(), places) << std::endl;
        return 2;
    }
    if (app.get_option("--check-config")->count() > 0) {
        std::string program = args[0].substr(args[0].rfind('/') + 1);
        auto problem = startup_problem(app);
        if (!problem && startup)
            problem = startup();
        if (problem) {
            std::cerr << program << ": " << *problem << std::endl;
            return 2;
        }
        std::cout << program << ": configuration OK" << std::endl;
        return 0;
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
    envdesign::service::SystemdNotifier systemd;
    // The watchdog is fed from this loop only, so no wait may outlast its period.
    int max_wait_ms =
        systemd.period() ? std::max<int>(1, systemd.period()->count() / 1000) : 1 << 30;
    systemd.ready("on " + service.bus->url());
    int failures = 0; // in a row; a signal interrupting the wait fails one too
    int wait_ms = 0;
    while (g_signal == 0) {
        bool failed = service.bus->handle(std::chrono::milliseconds(wait_ms)) < 0;
        failures = failed && g_signal == 0 ? failures + 1 : 0;
        if (failures >= 100) {
            service.log->error("request - | LCM keeps failing; stopping");
            systemd.stopping();
            return 1;
        }
        wait_ms = std::min(tick(), max_wait_ms);
        systemd.tick();
    }
    service.log->info("request - | signal {}: stopping", g_signal.load());
    systemd.stopping();
    return 0;
}

int run_until_signal(Service &service, const std::function<void()> &tick, int period_ms) {
    return run_until_signal(service, std::function<int()>([&] {
                                tick();
                                return period_ms;
                            }));
}

} // namespace envdesign::services
