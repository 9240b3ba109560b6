// Writes the committed seed corpora (tests/fuzz/corpus/<target>/) from the repository's
// examples: valid messages of every kind a handler takes, and valid input files, for libFuzzer
// to mutate. Run once after a message type changes:
//   build/bin/fuzz_make_seeds SOURCE_DIR

#include "bus_records.h"

#include "bus/codec.h"
#include "cluster/spec_chunks.h"
#include "envdesign/cancel_t.hpp"
#include "envdesign/design_request_t.hpp"
#include "envdesign/evaluation_t.hpp"
#include "envdesign/job_t.hpp"
#include "envdesign/planner_heartbeat_t.hpp"
#include "envdesign/spec_need_t.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>

namespace {

using namespace envdesign;
namespace fs = std::filesystem;

std::string read(const fs::path &path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write(const fs::path &dir, const std::string &name, const std::string &bytes) {
    fs::create_directories(dir);
    std::ofstream(dir / name, std::ios::binary) << bytes;
}

envdesign::spec_t restaurant(const fs::path &source) {
    fs::path dir = source / "examples/restaurant";
    envdesign::spec_t spec;
    spec.name = "a-one-task-t1.textproto";
    spec.text = read(dir / spec.name);
    for (const char *file : {"domain.pddl", "serve-g1.pddl", "serve-g1-human.pddl"})
        spec.files.push_back({file, read(dir / file)});
    spec.num_files = static_cast<std::int16_t>(spec.files.size());
    return spec;
}

envdesign::design_request_t request(const envdesign::spec_t &spec, std::int64_t id) {
    envdesign::design_request_t r{};
    r.request_id = id;
    r.sender = "client";
    r.spec = spec;
    r.time_limit_s = 1;
    r.max_design_size = -1;
    return r;
}

template <typename M> std::string record(int channel, const M &message) {
    return fuzz::write_record(channel, bus::encode_message(message));
}

void coordinator_seeds(const fs::path &source, const fs::path &out) {
    envdesign::spec_t spec = restaurant(source);
    write(out, "request", record(0, request(spec, 1)));
    envdesign::spec_t json = spec;
    json.name = "spec.json";
    json.text = read(source / "tests/data/design/restaurant-c.json");
    write(out, "request-json", record(0, request(json, 2)));
    envdesign::spec_t deep = spec;
    deep.name = "deep.json";
    deep.text = "{\"task\": " + std::string(150, '[') + std::string(150, ']') + "}";
    write(out, "request-deep-json", record(0, request(deep, 3)));
    envdesign::cancel_t cancel{0, 1, "client", "seed"};
    write(out, "request-cancel", record(0, request(spec, 1)) + record(1, cancel));
    envdesign::spec_need_t need{};
    need.coordinator = "coordinator";
    need.spec_hash = cluster::content_hash(bus::encode_message(spec));
    need.sender = "planner";
    write(out, "spec-need", record(2, need));
    envdesign::planner_heartbeat_t beat{};
    beat.sender = "planner";
    beat.period_ms = 200;
    beat.capacity = 1;
    beat.jobs = {1, 2};
    beat.num_jobs = 2;
    envdesign::evaluation_t evaluation{};
    evaluation.request_id = 1;
    evaluation.sender = "planner";
    evaluation.coordinator = "coordinator";
    evaluation.job_id = 1;
    evaluation.kind = 2;
    evaluation.plan = {"(move c00 c01)"};
    evaluation.plan_length = 1;
    write(out, "heartbeat-evaluation",
          record(0, request(spec, 1)) + record(4, beat) + record(3, evaluation));
}

void planner_seeds(const fs::path &source, const fs::path &out) {
    std::string bytes = bus::encode_message(restaurant(source));
    std::string hash = cluster::content_hash(bytes);
    std::string chunks;
    for (const auto &chunk : cluster::split_spec(bytes, hash, 1, "coordinator"))
        chunks += record(1, chunk);
    envdesign::job_t job{};
    job.request_id = 1;
    job.sender = "coordinator";
    job.job_id = 1;
    job.planner = "planner";
    job.spec_hash = hash;
    job.kind = envdesign::job_t::KIND_EXPLICABILITY;
    job.modifications = {0};
    job.num_modifications = 1;
    job.time_limit_s = 1;
    write(out, "spec-then-job", chunks + record(0, job));
    job.kind = envdesign::job_t::KIND_ROBOT_BOUND;
    write(out, "job-then-spec", record(0, job) + chunks);
}

void file_seeds(const fs::path &source, const fs::path &corpus) {
    fs::path tiny = source / "tests/data/tiny";
    write(corpus / "pddl", "tiny", read(tiny / "domain.pddl") + '\0' + read(tiny / "problem.pddl"));
    fs::path restaurant = source / "examples/restaurant";
    write(corpus / "pddl", "restaurant",
          read(restaurant / "domain.pddl") + '\0' + read(restaurant / "serve-g1-human.pddl"));
    for (const char *spec : {"a-one-task-t1.textproto", "c-two-tasks-t10.textproto"})
        write(corpus / "spec_text", spec, read(restaurant / spec));
    write(corpus / "spec_text", "blocksworld",
          read(source / "examples/blocksworld" / "design.textproto"));
    write(corpus / "spec_json", "restaurant-c.json",
          read(source / "tests/data/design/restaurant-c.json"));
    write(corpus / "spec_json", "unknown-object.json",
          read(source / "tests/data/design/bad/unknown-object.json"));
    // Arrivals: (1 config byte) then per arrival: 3 length-prefixed names, sequence, utime
    // selector, clock step, known-problem byte.
    auto arrival = [](const char *site, std::int64_t sequence) {
        std::string a;
        for (const char *name : {"p", site, "a"})
            a += std::string(1, static_cast<char>(std::strlen(name))) + name;
        a.append(reinterpret_cast<const char *>(&sequence), sizeof sequence);
        return a + std::string("\1\1\1", 3);
    };
    write(corpus / "intake", "sequences",
          "\1" + arrival("s1", 1) + arrival("s1", 2) + arrival("s1", 5) + arrival("s1", 1));
    // Near INT64_MAX from two sites: the unseen-numbers counter once overflowed.
    write(corpus / "intake", "sequences-near-max",
          "\1" + arrival("s1", INT64_MAX) + arrival("s2", INT64_MAX) + arrival("s3", 1) +
              arrival("s3", INT64_MAX));
}

// wire_numbers: a selector byte (0 evaluation, 1 job, 2 heartbeat, 3 request), then the
// message; each sound, and with a number issue 21 found let through.
void wire_number_seeds(const fs::path &source, const fs::path &out) {
    auto seed = [&](const std::string &name, char selector, const std::string &bytes) {
        write(out, name, std::string(1, selector) + bytes);
    };
    envdesign::evaluation_t e{};
    e.sender = "planner";
    e.coordinator = "coordinator";
    e.kind = envdesign::job_t::KIND_EXPLICABILITY;
    e.status = envdesign::evaluation_t::STATUS_SOLVED;
    e.ie = 2;
    e.robot_cost = 7;
    e.human_plan_cost = 5;
    e.has_human_optimal_cost = true;
    e.human_optimal_cost = 3;
    seed("evaluation-solved", 0, bus::encode_message(e));
    e.ie = std::nan("");
    seed("evaluation-nan-ie", 0, bus::encode_message(e));
    e.kind = envdesign::job_t::KIND_ROBOT_BOUND;
    e.has_robot_bound = true;
    e.robot_bound = 1e308;
    seed("robot-bound-1e308", 0, bus::encode_message(e));
    e.robot_bound = 9;
    e.has_ie_floor = true;
    e.ie_floor = -1;
    seed("ie-floor-negative", 0, bus::encode_message(e));
    e.ie_floor = 20;
    e.has_explanation_floor = true;
    e.explanation_floor = -3;
    seed("explanation-floor-negative", 0, bus::encode_message(e));
    envdesign::job_t job{};
    job.sender = "coordinator";
    job.planner = "planner";
    job.kind = envdesign::job_t::KIND_EXPLICABILITY;
    job.task = 1;
    job.modifications = {0, 2};
    job.num_modifications = 2;
    job.time_limit_s = 30;
    seed("job", 1, bus::encode_message(job));
    job.time_limit_s = 1e10;
    seed("job-time-1e10", 1, bus::encode_message(job));
    envdesign::planner_heartbeat_t beat{};
    beat.sender = "planner";
    beat.period_ms = 200;
    beat.capacity = 2;
    beat.busy_seconds = 1.5;
    seed("heartbeat", 2, bus::encode_message(beat));
    beat.busy_seconds = std::nan("");
    beat.period_ms = 2147483647;
    seed("heartbeat-nan-busy", 2, bus::encode_message(beat));
    envdesign::design_request_t r = request(restaurant(source), 1);
    seed("request", 3, bus::encode_message(r));
    r.time_limit_s = -std::numeric_limits<double>::infinity();
    r.max_design_size = 1000000;
    seed("request-minus-inf-huge-size", 3, bus::encode_message(r));
}

// service_config: a byte (odd: --max-requests=7 on the command line too), then the file.
void service_config_seeds(const fs::path &out) {
    write(out, "coordinator.conf",
          std::string("\0") + "# /etc/envdesign/coordinator.conf\nmax-requests = 4\n"
                              "planner-timeout = 0.5   # seconds\nstate-fsync = true\n"
                              "log-level = \"warn\"\nmax-time-limit = 600\n");
    write(out, "planner.conf",
          std::string("\1") + "workers = 2\nheartbeat = 0.2\njob-memory-mb = 256\n"
                              "max-requests = 9\nname = planner-a\n");
    write(out, "bad-numbers.conf",
          std::string("\0") + "planner-timeout = nan\nheartbeat = 1e30\ndiscovery = -1\n"
                              "max-spec-bytes = -1\nversion = true\n");
}

// floor_inputs: a reader byte (0 building map, 1 route graph, 2 occupancy map and PGM after
// a NUL, 3 tasks CSV, 4 zone file; the last three over the target's fixed graph), then the
// file: the floor examples, and small files written here.
void floor_seeds(const fs::path &source, const fs::path &out) {
    fs::path floor = source / "examples/floor";
    write(out, "warehouse.building.yaml",
          std::string(1, '\0') + read(floor / "warehouse.building.yaml"));
    write(out, "cartesian.building.yaml",
          std::string(1, '\0') +
              "coordinate_system: cartesian_meters\nlevels:\n  L1:\n"
              "    vertices:\n      - [0, 0, 0, dock]\n      - [8, 0, 0, shelf]\n"
              "      - [8, 6, 0, \"\"]\n      - [4, -1, 0]\n      - [4, 1, 0]\n"
              "    lanes:\n      - [0, 2, {bidirectional: [4, true]}]\n"
              "      - [2, 1, {graph_idx: [2, 0]}]\n"
              "    walls:\n      - [3, 4, {texture_name: [1, default]}]\n");
    write(out, "route.geojson", "\1" + read(floor / "nav2/route.geojson"));
    write(out, "nav2-map",
          "\2" + read(floor / "nav2/map.yaml") + '\0' + read(floor / "nav2/map.pgm"));
    std::string pgm = "P2\n# a wall at x = 3 m\n7 7\n255\n";
    for (int row = 0; row < 7; ++row)
        for (int col = 0; col < 7; ++col)
            pgm += col == 3 && row > 0 && row < 6 ? "0 " : "255 ";
    write(out, "tiny-map",
          "\2image: map.pgm\nresolution: 1\norigin: [-0.5, -0.5, 0]\n"
          "negate: 0\noccupied_thresh: 0.65\n" +
              std::string(1, '\0') + pgm);
    write(out, "tasks.csv", "\3from,to,weight\ndock,b,2\nv1,c,1\r\nc , a, 0.5\n");
    write(out, "zones.json",
          "\4{\"zones\": [{\"zoneId\": \"middle\", \"zoneType\": \"BLOCKED\", \"cost\": 2.5,"
          " \"vertices\": [{\"x\": 2.5, \"y\": 2.5}, {\"x\": 3.5, \"y\": 2.5}, {\"x\": 3.5, \"y\": "
          "3.5}]},"
          " {\"zoneId\": \"mark\", \"zoneType\": \"LINE_GUIDED\", \"cost\": 0,"
          " \"vertices\": [{\"x\": 1, \"y\": 5}, {\"x\": 5, \"y\": 1}, {\"x\": 5, \"y\": 5}]},"
          " {\"zoneId\": \"lift\", \"zoneType\": \"SPEED_LIMITED\"}]}");
    write(out, "warehouse-zones.json", "\4" + read(floor / "zones.json"));
}

} // namespace

int main(int argc, char **argv) {
    if (argc != 2) {
        std::cerr << "usage: fuzz_make_seeds SOURCE_DIR\n";
        return 2;
    }
    fs::path source = argv[1];
    fs::path corpus = source / "tests/fuzz/corpus";
    coordinator_seeds(source, corpus / "coordinator");
    planner_seeds(source, corpus / "planner");
    file_seeds(source, corpus);
    wire_number_seeds(source, corpus / "wire_numbers");
    service_config_seeds(corpus / "service_config");
    floor_seeds(source, corpus / "floor_inputs");
    std::cout << "seeds written under " << corpus << "\n";
    return 0;
}
