// spec_load_benchmark SPEC... [--repeat N]: how long a planner takes to load a spec it got
// over the bus, median of N (5) runs each:
// - before: what planners did until issue 11: the inlined files written to a scratch
//   directory, the spec loaded from there with the full check, the directory removed;
// - full: the same check from the message in memory (what the coordinator still does);
// - trusted: the message in memory, parsed only (Checks::TRUSTED_BY_HASH, planners now).
// Not run by ctest: `build/bin/spec_load_benchmark tests/data/paper/*/*/design-t10.textproto`.

#include "spec/design_spec.h"
#include "spec/spec_bundle.h"
#include "spec/spec_message.h"
#include "spec/spec_reader.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace envdesign;

// The pre-issue-11 planner path, rebuilt here only to measure it against: each file written
// as I.pddl, the spec's path fields pointed at the copies, a load from disk, all removed.
void load_through_scratch_directory(const envdesign::spec_t &message) {
    fs::path dir = fs::temp_directory_path() / ("spec-load-benchmark-" + std::to_string(getpid()));
    fs::create_directories(dir);
    std::map<std::string, std::string> copies;
    for (std::size_t i = 0; i < message.files.size(); ++i) {
        fs::path copy = dir / (std::to_string(i) + ".pddl");
        std::ofstream(copy, std::ios::binary) << message.files[i].content;
        copies[message.files[i].path] = copy.string();
    }
    spec::SpecFile spec = spec::read_spec_text(message.text, message.name);
    auto point = [&](std::string *path) {
        if (!path->empty())
            *path = copies.at(*path);
    };
    auto &m = spec.message;
    point(m.mutable_robot_domain());
    point(m.mutable_human_domain());
    for (auto &task : *m.mutable_task()) {
        point(task.mutable_problem());
        point(task.mutable_human_problem());
    }
    spec::load_design_problem(spec);
    fs::remove_all(dir);
}

double median_ms(int repeat, const std::function<void()> &run) {
    std::vector<double> ms;
    for (int i = 0; i < repeat; ++i) {
        auto start = std::chrono::steady_clock::now();
        run();
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
    }
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
}

} // namespace

int main(int argc, char **argv) {
    int repeat = 5;
    std::vector<std::string> specs;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--repeat" && i + 1 < argc)
            repeat = std::max(1, std::atoi(argv[++i]));
        else
            specs.push_back(arg);
    }
    std::printf("spec\ttasks\tmodifications\tbytes\tbefore_ms\tfull_ms\ttrusted_ms\n");
    for (const auto &path : specs) {
        envdesign::spec_t message = spec::bundle_spec(path);
        auto problem = spec::load_spec(message, spec::Checks::FULL);
        std::size_t bytes = message.text.size();
        for (const auto &f : message.files)
            bytes += f.content.size();
        double before = median_ms(repeat, [&] { load_through_scratch_directory(message); });
        double full = median_ms(repeat, [&] { spec::load_spec(message, spec::Checks::FULL); });
        double trusted =
            median_ms(repeat, [&] { spec::load_spec(message, spec::Checks::TRUSTED_BY_HASH); });
        std::printf("%s\t%zu\t%zu\t%zu\t%.2f\t%.2f\t%.2f\n", path.c_str(), problem.tasks.size(),
                    problem.modifications.size(), bytes, before, full, trusted);
    }
    return 0;
}
