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

// What the tools read and write, as COLMAP 3.8's database_creator makes it (4.2's has them all).
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

const char* schemaName(ColmapSchema schema)
{
    return schema == ColmapSchema::WithRigs ? "COLMAP 3.12+ (rigs)" : "COLMAP 3.x";
}

ColmapSchema checkColmapSchema(SqliteConnection& connection)
{
    const std::string notColmap = "'" + connection.path() + "' is not a COLMAP database: ";
    const bool rigs = !columnsOf(connection, "rigs").empty();
    const bool frames = !columnsOf(connection, "frames").empty();
    if (rigs != frames)
        throw DatabaseError(notColmap + "it has a table '" + (rigs ? "rigs" : "frames") +
                            "' but no table '" + (rigs ? "frames" : "rigs") +
                            "' (COLMAP 3.12 and later make both)");
    for (const TableColumns& required : kRequired) {
        const std::vector<std::string> present = columnsOf(connection, required.table);
        if (present.empty()) throw DatabaseError(notColmap + "no table '" + required.table + "'");
        for (const char* column : required.columns)
            if (std::find(present.begin(), present.end(), column) == present.end())
                throw DatabaseError(notColmap + "table '" + required.table + "' has no column '" +
                                    column + "'");
    }
    return rigs ? ColmapSchema::WithRigs : ColmapSchema::Colmap3;
}

} // namespace essential_colmap
