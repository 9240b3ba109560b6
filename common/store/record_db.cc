#include "store/record_db.h"

#include <openssl/crypto.h>
#include <sqlite3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>

namespace envdesign::store {
namespace {

namespace fs = std::filesystem;

constexpr const char *TABLE = "CREATE TABLE records (key BLOB PRIMARY KEY NOT NULL, value BLOB "
                              "NOT NULL, last_used INTEGER NOT NULL) WITHOUT ROWID";
constexpr const char *INDEX = "CREATE INDEX records_by_use ON records (last_used)";

// The first 16 bytes of every SQLite 3 database file.
bool has_sqlite_header(const std::string &path) {
    std::ifstream in(path, std::ios::binary);
    std::array<char, 16> header{};
    if (!in.read(header.data(), header.size()))
        return false;
    return std::memcmp(header.data(), "SQLite format 3", 16) == 0;
}

std::string utc_stamp() {
    std::time_t now = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&now, &tm);
    char buffer[32];
    std::strftime(buffer, sizeof buffer, "%Y%m%dT%H%M%SZ", &tm);
    return buffer;
}

constexpr std::size_t TAG_SIZE = sizeof(Digest::bytes);

// HMAC-SHA256 with `secret`, or SHA-256 without one, over the record's name and value.
Digest record_tag(const std::string *secret, const Digest &key, std::string_view value) {
    std::string text = "envdesign record tag 2\n";
    text.append(reinterpret_cast<const char *>(key.bytes.data()), key.bytes.size());
    text += value;
    return secret ? hmac_sha256(*secret, text) : sha256(text);
}

} // namespace

struct RecordDb::Statement {
    sqlite3_stmt *stmt = nullptr;
    sqlite3 *db;

    Statement(sqlite3 *db, const char *sql) : db(db) {
        if (sqlite3_prepare_v2(db, sql, -1, &stmt, nullptr) != SQLITE_OK)
            throw StoreError(std::string("SQLite: ") + sqlite3_errmsg(db));
    }
    ~Statement() { sqlite3_finalize(stmt); }
    Statement &bind(int i, const Digest &key) {
        sqlite3_bind_blob(stmt, i, key.bytes.data(), key.bytes.size(), SQLITE_STATIC);
        return *this;
    }
    Statement &bind(int i, const std::string &text) {
        sqlite3_bind_blob(stmt, i, text.data(), static_cast<int>(text.size()), SQLITE_STATIC);
        return *this;
    }
    Statement &bind(int i, std::int64_t value) {
        sqlite3_bind_int64(stmt, i, value);
        return *this;
    }
    // True while there is a row; throws on an error.
    bool step() {
        int rc = sqlite3_step(stmt);
        if (rc == SQLITE_ROW)
            return true;
        if (rc != SQLITE_DONE) {
            std::string message = sqlite3_errmsg(db);
            sqlite3_reset(stmt);
            throw StoreError("SQLite: " + message);
        }
        return false;
    }
    void reset() {
        sqlite3_reset(stmt);
        sqlite3_clear_bindings(stmt);
    }
    std::int64_t integer(int column) { return sqlite3_column_int64(stmt, column); }
    std::string text(int column) {
        const void *data = sqlite3_column_blob(stmt, column);
        int size = sqlite3_column_bytes(stmt, column);
        return data ? std::string(static_cast<const char *>(data), size) : std::string();
    }
};

RecordDb::RecordDb(std::string path, RecordDbOptions options)
    : path_(std::move(path)), options_(options) {
    if (options_.max_records < 1)
        options_.max_records = 1;
    fs::path dir = fs::path(path_).parent_path();
    if (!dir.empty() && !fs::is_directory(dir))
        throw StoreError("the state directory " + dir.string() + " does not exist");
    open_checked();
}

RecordDb::~RecordDb() {
    try {
        flush();
    } catch (const StoreError &) {
        // the last uses only order eviction; losing them loses nothing stored
    }
    close();
}

void RecordDb::open_checked() {
    if (fs::exists(path_) && fs::file_size(path_) > 0 && !has_sqlite_header(path_))
        set_aside("not an SQLite database (bad header)");
    if (sqlite3_open_v2(path_.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) !=
        SQLITE_OK) {
        std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
        close();
        throw StoreError("cannot open " + path_ + ": " + message);
    }
    sqlite3_busy_timeout(db_, 5000);
    std::optional<std::string> why;
    try {
        why = problem();
    } catch (const StoreError &e) {
        why = e.what();
    }
    if (why) {
        close();
        set_aside(*why);
        return open_checked(); // the file is gone now: this opens an empty one
    }
    exec("PRAGMA journal_mode=WAL");
    exec(options_.sync ? "PRAGMA synchronous=FULL" : "PRAGMA synchronous=NORMAL");
    prepare();
    Statement count(db_, "SELECT count(*), coalesce(sum(length(key) + length(value)), 0), "
                         "coalesce(max(last_used), 0) FROM records");
    count.step();
    records_ = report_.records = static_cast<std::size_t>(count.integer(0));
    bytes_ = static_cast<std::size_t>(count.integer(1));
    clock_ = count.integer(2);
}

// Why the open file cannot be trusted; makes the schema in an empty one.
std::optional<std::string> RecordDb::problem() {
    Statement id(db_, "PRAGMA application_id");
    id.step();
    std::int64_t application_id = id.integer(0);
    Statement objects(db_, "SELECT group_concat(sql, ';') FROM (SELECT sql FROM sqlite_master "
                           "WHERE sql IS NOT NULL ORDER BY name)");
    objects.step();
    std::string schema = objects.text(0);
    if (application_id == 0 && schema.empty()) {
        create_schema();
        return std::nullopt;
    }
    if (application_id != APPLICATION_ID) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "%08llx", static_cast<unsigned long long>(application_id));
        return "a foreign database (application_id 0x" + std::string(hex) + ")";
    }
    Statement version(db_, "PRAGMA user_version");
    version.step();
    std::int64_t format = version.integer(0);
    if (format != FORMAT_VERSION && format != 1)
        return "format version " + std::to_string(format) + ", this build keeps " +
               std::to_string(FORMAT_VERSION);
    if (schema != std::string(TABLE) + ";" + INDEX)
        return "an unexpected schema: " + schema;
    auto start = std::chrono::steady_clock::now();
    Statement check(db_, "PRAGMA integrity_check(1)");
    check.step();
    report_.check_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (check.text(0) != "ok")
        return "integrity check failed: " + check.text(0);
    if (format == 1)
        tag_old_records();
    return std::nullopt;
}

// Format 1 stored values without tags: they were trusted then, and are tagged once now.
void RecordDb::tag_old_records() {
    exec("BEGIN IMMEDIATE");
    try {
        // The keys first: updating rows while a statement walks the table may revisit them.
        std::vector<Digest> keys;
        Statement all(db_, "SELECT key FROM records");
        while (all.step()) {
            std::string bytes = all.text(0);
            Digest key;
            if (bytes.size() != key.bytes.size())
                continue; // unreadable by get(); evicted in time
            std::copy(bytes.begin(), bytes.end(), key.bytes.begin());
            keys.push_back(key);
        }
        Statement read(db_, "SELECT value FROM records WHERE key = ?1");
        Statement update(db_, "UPDATE records SET value = ?2 WHERE key = ?1");
        for (const Digest &key : keys) {
            read.bind(1, key);
            bool found = read.step();
            std::string value = found ? tagged(key, read.text(0)) : std::string();
            read.reset();
            if (!found)
                continue;
            update.bind(1, key).bind(2, value);
            update.step();
            update.reset();
        }
        exec(("PRAGMA user_version=" + std::to_string(FORMAT_VERSION)).c_str());
        exec("COMMIT");
    } catch (...) {
        sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
        throw;
    }
}

std::string RecordDb::tagged(const Digest &key, const std::string &value) const {
    const std::string *secret = options_.secrets.empty() ? nullptr : &options_.secrets.front();
    Digest tag = record_tag(secret, key, value);
    return value + std::string(reinterpret_cast<const char *>(tag.bytes.data()), TAG_SIZE);
}

bool RecordDb::verified(const Digest &key, const std::string &stored) const {
    if (stored.size() < TAG_SIZE)
        return false;
    std::string_view value(stored.data(), stored.size() - TAG_SIZE);
    auto matches = [&](const std::string *secret) {
        Digest tag = record_tag(secret, key, value);
        return CRYPTO_memcmp(tag.bytes.data(), stored.data() + value.size(), TAG_SIZE) == 0;
    };
    if (options_.secrets.empty())
        return matches(nullptr);
    return std::any_of(options_.secrets.begin(), options_.secrets.end(),
                       [&](const std::string &secret) { return matches(&secret); });
}

void RecordDb::create_schema() {
    exec("BEGIN IMMEDIATE");
    try {
        exec(TABLE);
        exec(INDEX);
        exec(("PRAGMA application_id=" + std::to_string(APPLICATION_ID)).c_str());
        exec(("PRAGMA user_version=" + std::to_string(FORMAT_VERSION)).c_str());
        exec("COMMIT");
    } catch (...) {
        sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
        throw;
    }
    report_.created = true;
}

// Renames the file (and its WAL) out of the way, never to be read again.
void RecordDb::set_aside(const std::string &reason) {
    std::string target = path_ + ".corrupt-" + utc_stamp();
    for (int n = 1; fs::exists(target); ++n)
        target = path_ + ".corrupt-" + utc_stamp() + "-" + std::to_string(n);
    std::error_code error;
    fs::rename(path_, target, error);
    if (error)
        throw StoreError("cannot set aside " + path_ + " (" + reason + "): " + error.message());
    if (fs::exists(path_ + "-wal"))
        fs::rename(path_ + "-wal", target + "-wal", error);
    fs::remove(path_ + "-shm", error);
    report_.set_aside = target;
    report_.reason = reason;
}

void RecordDb::prepare() {
    get_ = std::make_unique<Statement>(db_, "SELECT value FROM records WHERE key = ?1");
    put_ = std::make_unique<Statement>(
        db_, "INSERT INTO records (key, value, last_used) VALUES (?1, ?2, ?3) ON CONFLICT (key) "
             "DO NOTHING");
    touch_ = std::make_unique<Statement>(db_, "UPDATE records SET last_used = ?2 WHERE key = ?1");
    erase_ = std::make_unique<Statement>(
        db_, "DELETE FROM records WHERE key = ?1 RETURNING length(key) + length(value)");
    evict_ = std::make_unique<Statement>(
        db_, "DELETE FROM records WHERE key IN (SELECT key FROM records ORDER BY last_used "
             "LIMIT ?1) RETURNING length(key) + length(value)");
}

void RecordDb::close() {
    get_.reset();
    put_.reset();
    touch_.reset();
    evict_.reset();
    erase_.reset();
    if (db_)
        sqlite3_close_v2(db_);
    db_ = nullptr;
}

void RecordDb::exec(const char *sql) {
    char *error = nullptr;
    if (sqlite3_exec(db_, sql, nullptr, nullptr, &error) != SQLITE_OK) {
        std::string message = error ? error : sqlite3_errmsg(db_);
        sqlite3_free(error);
        throw StoreError("SQLite: " + message);
    }
}

std::optional<std::string> RecordDb::get(const Digest &key) {
    std::lock_guard lock(mutex_);
    get_->bind(1, key);
    std::optional<std::string> value;
    if (get_->step())
        value = get_->text(0);
    get_->reset();
    if (value && !verified(key, *value)) {
        erase(key);
        return std::nullopt;
    }
    if (value) {
        value->resize(value->size() - TAG_SIZE);
        touched_[key] = ++clock_;
        if (touched_.size() >= 4096) { // bounds memory; rare
            exec("BEGIN IMMEDIATE");
            write_touches();
            exec("COMMIT");
        }
    }
    return value;
}

void RecordDb::put(const Digest &key, const std::string &value) {
    std::lock_guard lock(mutex_);
    exec("BEGIN IMMEDIATE");
    try {
        write_touches();
        std::string stored = tagged(key, value);
        put_->bind(1, key).bind(2, stored).bind(3, ++clock_);
        put_->step();
        put_->reset();
        if (sqlite3_changes(db_) > 0) {
            ++records_;
            bytes_ += key.bytes.size() + stored.size();
        }
        evict();
        exec("COMMIT");
    } catch (...) {
        sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
        throw;
    }
}

void RecordDb::reject(const Digest &key) {
    std::lock_guard lock(mutex_);
    erase(key);
}

// Under the lock: deletes a bad record at once (committed on its own), so that the next
// put() of the same name can store a good value.
void RecordDb::erase(const Digest &key) {
    touched_.erase(key);
    erase_->bind(1, key);
    while (erase_->step()) {
        --records_;
        bytes_ -= std::min<std::size_t>(bytes_, erase_->integer(0));
        ++rejected_;
    }
    erase_->reset();
}

void RecordDb::flush() {
    std::lock_guard lock(mutex_);
    if (touched_.empty() || !db_)
        return;
    exec("BEGIN IMMEDIATE");
    write_touches();
    exec("COMMIT");
}

void RecordDb::write_touches() {
    for (const auto &[key, used] : touched_) {
        touch_->bind(1, key).bind(2, used);
        touch_->step();
        touch_->reset();
    }
    touched_.clear();
}

// Deletes the least recently used records, down to 90% of the bound, if it is exceeded.
void RecordDb::evict() {
    if (records_ <= options_.max_records && bytes_ <= options_.max_bytes)
        return;
    std::size_t keep_records = options_.max_records - options_.max_records / 10;
    std::size_t keep_bytes = options_.max_bytes - options_.max_bytes / 10;
    while (records_ > 1 && (records_ > keep_records || bytes_ > keep_bytes)) {
        std::size_t excess = records_ > keep_records ? records_ - keep_records : 1;
        if (bytes_ > keep_bytes && records_ > 0) // by the mean record size
            excess = std::max(excess, (bytes_ - keep_bytes) / (bytes_ / records_ + 1) + 1);
        excess = std::min(excess, records_ - 1); // never the record just written
        evict_->bind(1, static_cast<std::int64_t>(excess));
        while (evict_->step()) {
            --records_;
            bytes_ -= std::min<std::size_t>(bytes_, evict_->integer(0));
            ++evicted_;
        }
        evict_->reset();
    }
}

std::size_t RecordDb::records() const {
    std::lock_guard lock(mutex_);
    return records_;
}

std::size_t RecordDb::bytes() const {
    std::lock_guard lock(mutex_);
    return bytes_;
}

long long RecordDb::evicted() const {
    std::lock_guard lock(mutex_);
    return evicted_;
}

long long RecordDb::rejected() const {
    std::lock_guard lock(mutex_);
    return rejected_;
}

} // namespace envdesign::store
