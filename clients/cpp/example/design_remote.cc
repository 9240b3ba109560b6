// design_remote SPEC [LCM_URL]: the optimal design of SPEC from a running coordinator,
// printed as SPEC.md's JSON; the exit code is the result's.

#include <envdesign/client/client.h>

#include <iostream>

int main(int argc, char **argv) {
    if (argc < 2 || argc > 3) {
        std::cerr << "usage: design_remote SPEC [LCM_URL]\n";
        return 2;
    }
    envdesign::client::Options options;
    options.on_progress = envdesign::client::stderr_progress();
    envdesign::client::Result result =
        envdesign::client::run_design_remote(argv[1], argc == 3 ? argv[2] : "", options);
    if (result.status == "error")
        std::cerr << result.error << "\n";
    else
        std::cout << result.json << "\n";
    return result.exit_code;
}
