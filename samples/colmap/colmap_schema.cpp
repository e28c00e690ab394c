// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "colmap/colmap_schema.hpp"

#include "colmap/sqlite_connection.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace essential_colmap {

namespace {

struct TableColumns
{
    const char* table;
    std::vector<const char*> columns;
};

// What the tools read and write, as COLMAP 3.8's database_creator makes it.
const TableColumns kRequired[] = {
    {"cameras", {"camera_id", "model", "width", "height", "params", "prior_focal_length"}},
    {"images", {"image_id", "name", "camera_id"}},
    {"keypoints", {"image_id", "rows", "cols", "data"}},
    {"matches", {"pair_id", "rows", "cols", "data"}},
    {"two_view_geometries",
     {"pair_id", "rows", "cols", "data", "config", "F", "E", "H", "qvec", "tvec"}},
};

std::vector<std::string> columnsOf(SqliteConnection& connection, const std::string& table)
{
    // PRAGMA table_info lists no rows for a table that does not exist.
    SqliteStatement info(connection, "PRAGMA table_info(" + table + ")");
    std::vector<std::string> columns;
    while (info.step())
        columns.push_back(info.text(1));
    return columns;
}

} // namespace

void checkColmapSchema(SqliteConnection& connection)
{
    const std::string notColmap = "'" + connection.path() + "' is not a COLMAP 3.8 database: ";
    for (const char* later : {"rigs", "frames"})
        if (!columnsOf(connection, later).empty())
            throw DatabaseError(notColmap + "it has a table '" + later +
                                "' (a later COLMAP schema, which this tool does not read)");
    for (const TableColumns& required : kRequired) {
        const std::vector<std::string> present = columnsOf(connection, required.table);
        if (present.empty()) throw DatabaseError(notColmap + "no table '" + required.table + "'");
        for (const char* column : required.columns)
            if (std::find(present.begin(), present.end(), column) == present.end())
                throw DatabaseError(notColmap + "table '" + required.table + "' has no column '" +
                                    column + "'");
    }
}

} // namespace essential_colmap
