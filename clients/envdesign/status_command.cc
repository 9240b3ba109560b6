#include "status_command.h"

#include "cli_error.h"

#include "envdesign/client/client.h"
#include "service/number_flag.h"

#include <iostream>

namespace envdesign::cli {

void add_status_flags(CLI::App &command, StatusFlags &flags) {
    command.add_option("--connect", flags.connect,
                       "LCM URL of the bus (default: $LCM_DEFAULT_URL, else "
                       "udpm://239.255.76.67:7667?ttl=0)");
    command.add_option("--key-file", flags.key_file,
                       "bus keys (default: $ENVDESIGN_KEY_FILE; deploy/LAN.md)");
    command.add_option("--seconds", flags.seconds, "how long to listen")
        ->check(service::number_in({0.1, 3600.0}))
        ->capture_default_str();
    command.add_flag("--json", flags.json, "JSON lines, one object a service");
}

int run_status(const StatusFlags &flags) {
    client::StatusOptions options;
    options.seconds = flags.seconds;
    options.key_file = flags.key_file;
    client::StatusReport report = client::listen_status(flags.connect, options);
    if (report.exit_code == 2)
        throw CommandError(2, report.error);
    if (report.services > 0)
        std::cout << (flags.json ? report.json : report.text) << std::flush;
    if (report.exit_code != 0)
        throw CommandError(report.exit_code, report.error);
    return 0;
}

} // namespace envdesign::cli
