// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// A thin RAII layer over libsqlite3 for the COLMAP tools: a connection, prepared statements with
// typed binding and reading, and a transaction that rolls back unless committed. Every SQLite
// failure becomes a DatabaseError naming the file and the statement. Nothing here is part of the
// opencv_essential library.

#ifndef ESSENTIAL_SAMPLES_COLMAP_SQLITE_CONNECTION_HPP
#define ESSENTIAL_SAMPLES_COLMAP_SQLITE_CONNECTION_HPP

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

struct sqlite3;
struct sqlite3_stmt;

namespace essential_colmap {

/** A failure to open, read or write a database, or a database that is not what was expected. */
struct DatabaseError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

class SqliteConnection;

/** One prepared statement. Bind parameters are numbered from 1, result columns from 0. */
class SqliteStatement
{
public:
    SqliteStatement(SqliteConnection& connection, const std::string& sql);
    ~SqliteStatement();
    SqliteStatement(const SqliteStatement&) = delete;
    SqliteStatement& operator=(const SqliteStatement&) = delete;

    void bind(int index, std::int64_t value);
    void bind(int index, const std::string& text);
    /** Binds `bytes` bytes from `data` as a blob (copied by SQLite); an empty blob when bytes = 0.
     */
    void bindBlob(int index, const void* data, std::size_t bytes);

    /** Runs one step: true when a row is ready to read, false when the statement is done. */
    bool step();
    /** Resets the statement for another run with new bindings. */
    void reset();

    std::int64_t integer(int column) const;
    std::string text(int column) const;
    /** The column's bytes (empty for NULL or an empty blob). */
    std::vector<unsigned char> blob(int column) const;
    bool isNull(int column) const;

private:
    SqliteConnection& connection_;
    sqlite3_stmt* statement_ = nullptr;
    std::string sql_;
};

/** An open SQLite database file. */
class SqliteConnection
{
public:
    /** Opens an existing file (never creates one): read-only, or read-write. */
    SqliteConnection(const std::string& path, bool readOnly);
    ~SqliteConnection();
    SqliteConnection(const SqliteConnection&) = delete;
    SqliteConnection& operator=(const SqliteConnection&) = delete;

    /** Runs SQL statements that return no rows. */
    void execute(const std::string& sql);
    const std::string& path() const { return path_; }
    sqlite3* handle() { return db_; }
    /** "<path>: <what> (<SQLite's message>)" as a DatabaseError. */
    [[noreturn]] void fail(const std::string& what);

private:
    sqlite3* db_ = nullptr;
    std::string path_;
};

/** BEGIN IMMEDIATE on construction (the write lock is taken at once, so no other writer can slip in
between reading and writing); ROLLBACK on destruction unless commit() was called, so that an
exception anywhere between the two leaves the database as it was. */
class SqliteTransaction
{
public:
    explicit SqliteTransaction(SqliteConnection& connection);
    ~SqliteTransaction();
    SqliteTransaction(const SqliteTransaction&) = delete;
    SqliteTransaction& operator=(const SqliteTransaction&) = delete;
    void commit();

private:
    SqliteConnection& connection_;
    bool open_ = true;
};

} // namespace essential_colmap

#endif
