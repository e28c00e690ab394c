// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// The check that a SQLite file is a COLMAP 3.8 database: every table and column the tools read or
// write is there, and none of the tables a later COLMAP schema added (rigs, frames: COLMAP 3.12 and
// 4.x moved the camera of an image into them, so that a 3.8 reading would be wrong).

#ifndef ESSENTIAL_SAMPLES_COLMAP_COLMAP_SCHEMA_HPP
#define ESSENTIAL_SAMPLES_COLMAP_COLMAP_SCHEMA_HPP

namespace essential_colmap {

class SqliteConnection;

/** Throws DatabaseError naming the first missing table or column, or the later schema's table. */
void checkColmapSchema(SqliteConnection& connection);

} // namespace essential_colmap

#endif
