// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The COLMAP database fuzz target: essential_colmap's reading, verification and writing
// (samples/colmap) on a database made from the fuzzer's bytes, written to a file per execution.
// Input: one options byte, then either a SQLite database file ("SQLite format 3" header: the
// fuzzer mutates the pages, the record headers, the schema text) or SQL run on an empty database
// (so that missing tables, wrong column types and declared types, blobs of wrong sizes and shapes
// are a few tokens away; fuzz/colmap.dict names them). The options byte picks what the tool does:
// a dry run (read-only), or verification and the write of two_view_geometries, with an injected
// failure after a given row or none; only the unverified pairs; the batch chunk size.
//
// Contract (docs/COLMAP.md, essential_colmap's exit status 1): a malformed database is a
// DatabaseError with a message, raised before anything is written; the file is then unchanged byte
// for byte, as it is after any dry run and after a failure part-way through the write (one
// transaction). A successful write can be read back: the database still passes the schema check
// and holds a row for every pair written. Anything else (another exception, a sanitizer report, a
// hang) aborts.

#include "fuzz_contract.hpp"

#include "colmap/colmap_database.hpp"
#include "colmap/two_view_geometry.hpp"
#include "colmap/verify_pairs.hpp"

#include <sqlite3.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace essential_colmap;
using essential_fuzz::broken;

const char kSqliteHeader[] = "SQLite format 3"; // 16 bytes with its terminating zero

/** The file an execution works on and SQLite's side files, in a directory of this process (tmpfs
when there is one: a file per execution). */
struct WorkFiles
{
    std::string db, journal, wal, shm;

    WorkFiles()
    {
        const char* base = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : std::getenv("TMPDIR");
        const std::string dir = std::string(base ? base : "/tmp") + "/essential_fuzz_colmap_" +
                                std::to_string(static_cast<long>(getpid()));
        mkdir(dir.c_str(), 0700);
        db = dir + "/input.db";
        journal = db + "-journal";
        wal = db + "-wal";
        shm = db + "-shm";
    }

    void removeAll() const
    {
        for (const std::string* f : {&db, &journal, &wal, &shm})
            unlink(f->c_str());
    }
};

const WorkFiles& workFiles()
{
    static const WorkFiles files;
    return files;
}

bool writeFile(const std::string& path, const uint8_t* data, size_t size)
{
    const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd < 0) return false;
    size_t done = 0;
    while (done < size) {
        const ssize_t n = write(fd, data + done, size - done);
        if (n <= 0) break;
        done += static_cast<size_t>(n);
    }
    close(fd);
    return done == size;
}

/** The file's bytes into `out` (reused between executions); false when it cannot be read. */
bool readFile(const std::string& path, std::vector<uint8_t>& out)
{
    out.clear();
    const int fd = open(path.c_str(), O_RDONLY);
    if (fd < 0) return false;
    uint8_t buffer[16384];
    for (;;) {
        const ssize_t n = read(fd, buffer, sizeof buffer);
        if (n <= 0) break;
        out.insert(out.end(), buffer, buffer + n);
    }
    close(fd);
    return true;
}

/** What the SQL of an input may do: build tables, indexes and rows, nothing that reaches outside
the file (ATTACH, VACUUM INTO) or changes how the tool's own connection behaves (PRAGMA, triggers,
views, virtual tables). */
int authorise(void*, int action, const char*, const char*, const char*, const char*)
{
    switch (action) {
    case SQLITE_CREATE_TABLE:
    case SQLITE_CREATE_INDEX:
    case SQLITE_DROP_TABLE:
    case SQLITE_DROP_INDEX:
    case SQLITE_ALTER_TABLE:
    case SQLITE_INSERT:
    case SQLITE_UPDATE:
    case SQLITE_DELETE:
    case SQLITE_READ:
    case SQLITE_SELECT:
    case SQLITE_FUNCTION:
    case SQLITE_RECURSIVE:
    case SQLITE_TRANSACTION:
    case SQLITE_SAVEPOINT:
        return SQLITE_OK;
    default:
        return SQLITE_DENY;
    }
}

/** Stops a statement after about 2e6 virtual-machine steps (a recursive query without end). */
int progress(void* steps)
{
    return ++*static_cast<int*>(steps) > 2000;
}

/** Builds the database from the input's SQL: an empty file, then the statements up to the first
that fails. False when no file came of it. */
bool buildFromSql(const std::string& path, const uint8_t* data, size_t size)
{
    sqlite3* db = nullptr;
    if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) !=
        SQLITE_OK) {
        sqlite3_close(db);
        return false;
    }
    // Small pages keep the database small; no journal and no sync: the file is scratch.
    sqlite3_exec(db, "PRAGMA page_size=512; PRAGMA journal_mode=OFF; PRAGMA synchronous=OFF",
                 nullptr, nullptr, nullptr);
    sqlite3_limit(db, SQLITE_LIMIT_LENGTH, 1 << 16);
    sqlite3_limit(db, SQLITE_LIMIT_ATTACHED, 0);
    sqlite3_set_authorizer(db, authorise, nullptr);
    int steps = 0;
    sqlite3_progress_handler(db, 1000, progress, &steps);
    const std::string sql(reinterpret_cast<const char*>(data), size);
    sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr);
    sqlite3_close(db);
    return true;
}

/** The tool's options from the input's first byte: dry run or write, the row after which the
write fails (0: none), unverified pairs only, the batch chunk size. Estimates stay small. */
struct RunOptions
{
    bool write;
    int failAfterRow;
    VerificationOptions verification;

    explicit RunOptions(uint8_t bits)
        : write(bits & 1), failAfterRow((bits >> 1) & 3), verification()
    {
        verification.unverifiedOnly = (bits >> 3) & 1;
        verification.chunkSize = 1 + ((bits >> 4) & 3);
        verification.threads = 1;
        verification.params.maxIterations = 20 + 10 * ((bits >> 6) & 3);
    }
};

struct InjectedFailure
{
};

/** Runs the tool's steps; true when a write was committed. */
bool runTool(const std::string& path, const RunOptions& options)
{
    std::vector<TwoViewGeometryRecord> records;
    {
        ColmapDatabase database(path, !options.write);
        database.storedGeometries();
        database.images();
        const Verification verification = verifyPairs(database, options.verification);
        if (verification.records.size() != verification.pairs.size())
            broken("records and pair reports differ in number");
        if (!options.write) return false;
        const int failAfter = options.failAfterRow;
        writeTwoViewGeometries(database, verification.records, [failAfter](std::size_t written) {
            if (failAfter > 0 && written == static_cast<std::size_t>(failAfter))
                throw InjectedFailure();
        });
        records = verification.records;
    }
    // What was written reads back.
    try {
        ColmapDatabase reopened(path, true);
        const auto stored = reopened.storedGeometries();
        for (const TwoViewGeometryRecord& r : records)
            if (!stored.count(r.pairId)) broken("a written two_view_geometries row is missing");
    } catch (const DatabaseError& e) {
        std::fprintf(stderr, "fuzz: %s\n", e.what());
        broken("the database cannot be read after a committed write");
    }
    return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    static const bool quiet = [] {
        cv::redirectError([](int, const char*, const char*, const char*, int, void*) { return 0; });
        return true;
    }();
    (void)quiet;
    if (size < 1) return 0;
    const WorkFiles& files = workFiles();
    files.removeAll();
    const RunOptions options(data[0]);
    const uint8_t* body = data + 1;
    const size_t bodySize = size - 1;
    const bool rawFile = bodySize >= sizeof kSqliteHeader &&
                         std::memcmp(body, kSqliteHeader, sizeof kSqliteHeader) == 0;
    const bool built =
        rawFile ? writeFile(files.db, body, bodySize) : buildFromSql(files.db, body, bodySize);
    static std::vector<uint8_t> before, after;
    if (!built || !readFile(files.db, before)) {
        files.removeAll();
        return 0;
    }

    bool committed = false;
    try {
        committed = runTool(files.db, options);
    } catch (const DatabaseError& e) {
        if (e.what()[0] == '\0') broken("a DatabaseError without a message");
    } catch (const InjectedFailure&) {
        // The write must have been rolled back: checked below.
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz: not a DatabaseError: %s\n", e.what());
        std::abort();
    }
    // Only a committed write may change the file.
    if (!committed) {
        if (!readFile(files.db, after) || after != before)
            broken("the database file changed without a successful write");
    }
    if (access(files.journal.c_str(), F_OK) == 0) broken("a rollback journal was left behind");
    files.removeAll();
    return 0;
}
