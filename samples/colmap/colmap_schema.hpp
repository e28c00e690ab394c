// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// The check that a SQLite file is a COLMAP database the tools can read and write: every table and
// column they read or write is there. Two generations are read: COLMAP 3.x up to 3.11 (Debian 12's
// 3.8, Debian 13's 3.10) and the schema with rigs and frames (COLMAP 3.12 and 4.x; Debian
// unstable's 4.2). The later schema adds tables (rigs, rig_sensors, frames, frame_data,
// pose_priors) and two_view_geometries columns (camera1, camera2), but an image keeps its
// camera_id, the pair id keeps its encoding and two_view_geometries keeps every column the tools
// write, so a pair is verified and written the same way in both; the added columns are left NULL,
// as COLMAP 4.2's own matcher leaves them for a calibrated pair (checked on its database of the
// rail frames).

#ifndef ESSENTIAL_SAMPLES_COLMAP_COLMAP_SCHEMA_HPP
#define ESSENTIAL_SAMPLES_COLMAP_COLMAP_SCHEMA_HPP

namespace essential_colmap {

class SqliteConnection;

/** The schema generation of a COLMAP database. */
enum class ColmapSchema {
    Colmap3, ///< no rigs table: COLMAP 3.0 to 3.11
    WithRigs ///< rigs and frames tables: COLMAP 3.12 and 4.x
};

/** The name of a generation, as the tools print it ("COLMAP 3.x", "COLMAP 3.12+ (rigs)"). */
const char* schemaName(ColmapSchema schema);

/** Throws DatabaseError naming the first missing table or column; returns the generation. A rigs
table without a frames table (or the other way round) is neither generation and is refused. */
ColmapSchema checkColmapSchema(SqliteConnection& connection);

} // namespace essential_colmap

#endif
