#pragma once
// Where the PDDL files a spec names come from. A spec's path fields (robot_domain,
// task[i].problem, ...) are read through a FileSource: from disk, relative to the spec file
// (a local run, a client packing its request), or from the files a spec_t message carries
// (the coordinator and the planners). Loading never writes a file.
//
//   DiskFiles disk("examples/restaurant/c-two-tasks-t10.textproto");
//   SourceFile f = disk.read("domain.pddl", "robot_domain");
//   // f.name == "examples/restaurant/domain.pddl", f.content: the file's text

#include "envdesign/spec_t.hpp"

#include <map>
#include <stdexcept>
#include <string>

namespace envdesign::spec {

struct SourceFile {
    std::string name;    // what errors call it: the path as the client knows it
    std::string content; // the whole text
};

// A file the spec names that the source cannot give; the message names the path as written
// and the field ("cannot open 'x' (robot_domain, looked for ...)"). The loader puts it at
// the field's position in the spec.
class MissingFile : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class FileSource {
public:
    virtual ~FileSource();
    // The file written as `path` in the spec's field `field` ("task[1].problem"). Throws
    // MissingFile.
    virtual SourceFile read(const std::string &path, const std::string &field) const = 0;
};

// Files on disk; relative paths are relative to the directory of the spec file. Reads with
// pddl::read_input_file's bounds (no FIFO, device or oversized file).
class DiskFiles : public FileSource {
public:
    explicit DiskFiles(std::string spec_path) : spec_path_(std::move(spec_path)) {}
    SourceFile read(const std::string &path, const std::string &field) const override;

private:
    std::string spec_path_;
};

// The files a spec_t carries, by the path its text writes. Names in errors are the client's
// (the spec's name's directory joined with the path as written), never a local path.
// `spec` must outlive this.
class MessageFiles : public FileSource {
public:
    explicit MessageFiles(const envdesign::spec_t &spec);
    SourceFile read(const std::string &path, const std::string &field) const override;

private:
    std::string spec_name_;
    std::map<std::string, const std::string *> files_; // path as written -> content
};

// "dir/of/spec/path" for `path` written in the spec `spec_path` (`path` itself if absolute).
std::string path_beside(const std::string &spec_path, const std::string &path);

} // namespace envdesign::spec
