#include "cluster/spec_loader.h"

#include "design/design_spec.h"
#include "design/spec_reader.h"

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <unistd.h>

namespace envdesign::cluster {
namespace {

namespace fs = std::filesystem;

// A directory removed with everything in it when this goes out of scope.
class ScratchDirectory {
public:
    explicit ScratchDirectory(const std::string &parent) {
        static std::atomic<int> counter{0};
        path_ = fs::path(parent) /
                ("envdesign-spec-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
        fs::create_directories(path_);
    }
    ~ScratchDirectory() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    const fs::path &path() const { return path_; }

private:
    fs::path path_;
};

// Writes each inlined file under `dir`; maps the path as written in the spec to the copy.
std::map<std::string, std::string> write_files(const envdesign::spec_t &spec, const fs::path &dir) {
    std::map<std::string, std::string> copies;
    for (std::size_t i = 0; i < spec.files.size(); ++i) {
        const auto &file = spec.files[i];
        fs::path copy = dir / (std::to_string(i) + ".pddl"); // never a name from the wire
        std::ofstream out(copy, std::ios::binary);
        out << file.content;
        if (!out)
            throw std::runtime_error("cannot write " + copy.string());
        copies[file.path] = copy.string();
    }
    return copies;
}

class PathRewriter {
public:
    PathRewriter(design::SpecFile &spec, const std::map<std::string, std::string> &copies)
        : spec_(spec), copies_(copies) {}

    // Points `value` (the field `field` of the spec) at its inlined copy.
    void rewrite(std::string *value, const std::string &field) {
        if (value->empty())
            return; // absent: the loader reports it if it is required
        auto it = copies_.find(*value);
        if (it == copies_.end())
            throw pddl::ParseError(spec_.at(field),
                                   "the request does not carry '" + *value + "' (" + field + ")");
        shown_[it->second] = (fs::path(spec_.path).parent_path() / *value).string();
        *value = it->second;
    }

    // `message` with every copy's path replaced by the name the client knows.
    std::string restore(std::string message) const {
        for (const auto &[copy, original] : shown_)
            for (auto at = message.find(copy); at != std::string::npos;
                 at = message.find(copy, at + original.size()))
                message.replace(at, copy.size(), original);
        return message;
    }

private:
    design::SpecFile &spec_;
    const std::map<std::string, std::string> &copies_;
    std::map<std::string, std::string> shown_;
};

} // namespace

std::string default_work_dir() {
    const char *tmp = std::getenv("TMPDIR");
    return tmp && *tmp ? tmp : "/tmp";
}

design::DesignProblem load_spec(const envdesign::spec_t &spec, const std::string &work_dir) {
    design::SpecFile file = design::read_spec_text(spec.text, spec.name);
    ScratchDirectory dir(work_dir);
    auto copies = write_files(spec, dir.path());
    PathRewriter paths(file, copies);
    auto &m = file.message;
    paths.rewrite(m.mutable_robot_domain(), "robot_domain");
    paths.rewrite(m.mutable_human_domain(), "human_domain");
    for (int i = 0; i < m.task_size(); ++i) {
        std::string at = "task[" + std::to_string(i) + "]";
        paths.rewrite(m.mutable_task(i)->mutable_problem(), at + ".problem");
        paths.rewrite(m.mutable_task(i)->mutable_human_problem(), at + ".human_problem");
    }
    try {
        return design::load_design_problem(file);
    } catch (const pddl::ParseError &e) {
        pddl::Location where = e.location();
        where.file = paths.restore(where.file);
        throw pddl::ParseError(where, paths.restore(e.message()));
    }
}

} // namespace envdesign::cluster
