// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "colmap/sqlite_connection.hpp"

#include <sqlite3.h>

#include <cstring>

namespace essential_colmap {

SqliteConnection::SqliteConnection(const std::string& path, bool readOnly) : path_(path)
{
    const int flags = readOnly ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE;
    if (sqlite3_open_v2(path.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
        const std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
        sqlite3_close(db_);
        db_ = nullptr;
        throw DatabaseError("cannot open database '" + path + "' (" + message + ")");
    }
    // A database another process is writing (COLMAP's GUI, a matcher) is waited for briefly rather
    // than failing at once.
    sqlite3_busy_timeout(db_, 5000);
}

SqliteConnection::~SqliteConnection()
{
    sqlite3_close(db_);
}

void SqliteConnection::fail(const std::string& what)
{
    throw DatabaseError("database '" + path_ + "': " + what + " (" + sqlite3_errmsg(db_) + ")");
}

void SqliteConnection::execute(const std::string& sql)
{
    char* message = nullptr;
    if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &message) != SQLITE_OK) {
        const std::string text = message ? message : "unknown error";
        sqlite3_free(message);
        throw DatabaseError("database '" + path_ + "': " + sql + " failed (" + text + ")");
    }
}

SqliteStatement::SqliteStatement(SqliteConnection& connection, const std::string& sql)
    : connection_(connection), sql_(sql)
{
    if (sqlite3_prepare_v2(connection.handle(), sql.c_str(), -1, &statement_, nullptr) != SQLITE_OK)
        connection_.fail("cannot prepare '" + sql + "'");
}

SqliteStatement::~SqliteStatement()
{
    sqlite3_finalize(statement_);
}

void SqliteStatement::bind(int index, std::int64_t value)
{
    if (sqlite3_bind_int64(statement_, index, value) != SQLITE_OK)
        connection_.fail("cannot bind parameter " + std::to_string(index) + " of '" + sql_ + "'");
}

void SqliteStatement::bind(int index, const std::string& text)
{
    if (sqlite3_bind_text(statement_, index, text.c_str(), static_cast<int>(text.size()),
                          SQLITE_TRANSIENT) != SQLITE_OK)
        connection_.fail("cannot bind parameter " + std::to_string(index) + " of '" + sql_ + "'");
}

void SqliteStatement::bindBlob(int index, const void* data, std::size_t bytes)
{
    // sqlite3_bind_blob with a null pointer binds NULL; an empty blob needs zeroblob.
    const int rc = bytes == 0
                       ? sqlite3_bind_zeroblob(statement_, index, 0)
                       : sqlite3_bind_blob64(statement_, index, data,
                                             static_cast<sqlite3_uint64>(bytes), SQLITE_TRANSIENT);
    if (rc != SQLITE_OK)
        connection_.fail("cannot bind parameter " + std::to_string(index) + " of '" + sql_ + "'");
}

bool SqliteStatement::step()
{
    const int rc = sqlite3_step(statement_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    connection_.fail("'" + sql_ + "' failed");
}

void SqliteStatement::reset()
{
    sqlite3_reset(statement_);
    sqlite3_clear_bindings(statement_);
}

std::int64_t SqliteStatement::integer(int column) const
{
    return sqlite3_column_int64(statement_, column);
}

std::string SqliteStatement::text(int column) const
{
    const unsigned char* value = sqlite3_column_text(statement_, column);
    return value ? std::string(reinterpret_cast<const char*>(value)) : std::string();
}

std::vector<unsigned char> SqliteStatement::blob(int column) const
{
    const void* data = sqlite3_column_blob(statement_, column);
    const int bytes = sqlite3_column_bytes(statement_, column);
    std::vector<unsigned char> out(static_cast<std::size_t>(bytes));
    if (bytes > 0) std::memcpy(out.data(), data, out.size());
    return out;
}

bool SqliteStatement::isNull(int column) const
{
    return sqlite3_column_type(statement_, column) == SQLITE_NULL;
}

SqliteTransaction::SqliteTransaction(SqliteConnection& connection) : connection_(connection)
{
    connection_.execute("BEGIN IMMEDIATE");
}

SqliteTransaction::~SqliteTransaction()
{
    if (!open_) return;
    // A destructor must not throw: a failed ROLLBACK leaves SQLite to roll back the journal when
    // the connection closes, which it does for any transaction left open.
    sqlite3_exec(connection_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
}

void SqliteTransaction::commit()
{
    connection_.execute("COMMIT");
    open_ = false;
}

} // namespace essential_colmap
