#pragma once
// A durable, bounded store of content-addressed records in one SQLite file (WAL mode).
//
// Records are immutable values named by a digest of what they mean (digest.h): a record
// once written is never changed, so a second write of the same name is a no-op, and any
// process that computes the same name may use the value. The coordinator keeps its task
// evaluations here (design/evaluation/evaluation_store.h), so that they survive restarts.
//
// Durability: put() returns after its transaction committed. With sync (the default) the
// WAL is fsync'ed on every commit, so a record that put() returned survives a power loss
// too; without it, it survives the process being killed at any instant (SIGKILL), not a
// crash of the machine.
//
// Trust: open checks the file before using it: SQLite's header, application_id,
// user_version (FORMAT_VERSION), the schema and PRAGMA integrity_check. A file that fails
// any check (corrupt, foreign, another format version) is renamed aside as
// PATH.corrupt-YYYYMMDDTHHMMSSZ (its -wal too) and an empty store is made; report() says
// so and why. Nothing of such a file is ever read.
//
// Integrity: every value is stored with a 32-byte tag over its name and bytes, HMAC-SHA256
// with the first of `secrets` (the bus keys) or, without keys, a SHA-256 checksum. get()
// verifies it (any of the secrets may have written it: keys rotate); a record that fails is
// deleted and counted in rejected(), never returned. A writer holding neither the key nor
// the file's checksum rule changes nothing; without keys the checksum still catches damage
// and edits that do not know the rule. A file of format 1 (no tags) is tagged at open.
//
// Bound: past max_records records or max_bytes bytes of keys and values, the records used
// least recently (written or found) are deleted, down to 90% of the bound so that eviction
// runs rarely. Last use is a counter kept in the file (not the clock); finds update it in
// memory and it is written with the next put or flush() (losing a few on a kill only
// changes which records go first).
//
//   RecordDb db("/var/lib/envdesign/evaluations.db", {});
//   if (!db.report().set_aside.empty()) log.warn(...);
//   db.put(sha256("v1 ..."), bytes);
//   std::optional<std::string> value = db.get(sha256("v1 ..."));
//
// Thread-safe (one connection, one mutex). Errors throw StoreError.

#include "store/digest.h"

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

struct sqlite3;
struct sqlite3_stmt;

namespace envdesign::store {

class StoreError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct RecordDbOptions {
    std::size_t max_records = 200'000; // at least 1
    std::size_t max_bytes = std::size_t{1} << 30;
    bool sync = true;                 // fsync the WAL at every commit (survives power loss)
    std::vector<std::string> secrets; // tag with secrets[0], verify with any; empty: checksum
};

struct OpenReport {
    bool created = false;     // the store was made empty (new, or the old file set aside)
    std::string set_aside;    // where an unusable file was moved; empty: none was
    std::string reason;       // why it was unusable
    std::size_t records = 0;  // found at open
    double check_seconds = 0; // the integrity check's time
};

class RecordDb {
public:
    // The file's format: a store of another format is set aside, not read.
    static constexpr int FORMAT_VERSION = 2; // 2: tagged values (1 is tagged at open)
    static constexpr std::int32_t APPLICATION_ID = 0x45445631; // "EDV1"

    // Opens (or creates) the store at `path`; its directory must exist.
    RecordDb(std::string path, RecordDbOptions options);
    ~RecordDb(); // writes pending last uses
    RecordDb(const RecordDb &) = delete;
    RecordDb &operator=(const RecordDb &) = delete;

    const OpenReport &report() const { return report_; }
    const std::string &path() const { return path_; }

    // The value stored under `key`, if any and its tag verifies (else deleted, counted).
    std::optional<std::string> get(const Digest &key);
    // Deletes a record whose value its reader found unusable; counted in rejected().
    void reject(const Digest &key);
    // Committed when it returns; a key stored already keeps its value.
    void put(const Digest &key, const std::string &value);
    void flush(); // writes pending last uses

    std::size_t records() const;
    std::size_t bytes() const;
    long long evicted() const;
    long long rejected() const; // records deleted because their tag or value was bad

private:
    struct Statement;
    void open_checked();
    std::optional<std::string> problem();
    void create_schema();
    void set_aside(const std::string &reason);
    void prepare();
    void close();
    void exec(const char *sql);
    void write_touches();
    void evict();
    void tag_old_records();
    std::string tagged(const Digest &key, const std::string &value) const;
    bool verified(const Digest &key, const std::string &stored) const;
    void erase(const Digest &key);

    std::string path_;
    RecordDbOptions options_;
    OpenReport report_;
    mutable std::mutex mutex_;
    sqlite3 *db_ = nullptr;
    std::unique_ptr<Statement> get_, put_, touch_, evict_, erase_;
    std::map<Digest, std::int64_t> touched_; // last uses not yet written
    std::int64_t clock_ = 0;                 // the last use counter
    std::size_t records_ = 0;
    std::size_t bytes_ = 0;
    long long evicted_ = 0;
    long long rejected_ = 0;
};

} // namespace envdesign::store
