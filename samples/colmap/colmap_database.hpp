// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// Reading a COLMAP database (SQLite; 3.x, or 3.12+ with rigs: colmap_schema.hpp): cameras, images,
// keypoints, raw matches and the configuration of the two-view geometries already stored. Blobs are
// read as COLMAP writes them: row-major, little-endian float32 keypoints (rows x cols, cols 2, 4 or
// 6, x and y first) and uint32 match pairs (rows x 2). Every malformed blob is a DatabaseError
// naming its row.

#ifndef ESSENTIAL_SAMPLES_COLMAP_COLMAP_DATABASE_HPP
#define ESSENTIAL_SAMPLES_COLMAP_COLMAP_DATABASE_HPP

#include "colmap/camera_models.hpp"
#include "colmap/colmap_schema.hpp"
#include "colmap/sqlite_connection.hpp"

#include <opencv2/core.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace essential_colmap {

/** A row of the images table. */
struct ColmapImage
{
    std::int64_t id = 0;
    std::string name;
    std::int64_t cameraId = 0;
};

/** One match: keypoint indices in the pair's first (lower id) and second image. */
typedef std::array<std::uint32_t, 2> FeatureMatch;
static_assert(sizeof(FeatureMatch) == 8, "matches are read as packed uint32 pairs");

/** What a two_view_geometries row holds now (for --pairs unverified and the dry run's report). */
struct StoredGeometry
{
    int config = 0;
    std::int64_t inliers = 0;
};

/** An open COLMAP database whose schema has been checked. */
class ColmapDatabase
{
public:
    /** Opens an existing file and checks it is a COLMAP database (checkColmapSchema). */
    ColmapDatabase(const std::string& path, bool readOnly);

    /** The schema generation found when the file was opened. */
    ColmapSchema schema() const { return schema_; }

    std::map<std::int64_t, ColmapCamera> cameras();
    std::map<std::int64_t, ColmapImage> images();
    /** The keypoints of an image (x, y; COLMAP's pixel coordinates); empty when it has none. */
    std::vector<cv::Point2f> keypoints(std::int64_t imageId);
    /** The pair ids of the matches table, ascending. */
    std::vector<std::int64_t> matchedPairs();
    /** The matches of a pair; empty when it has none (no row, zero rows or a NULL blob). */
    std::vector<FeatureMatch> matches(std::int64_t pairId);
    /** The two-view geometries stored now, by pair id. */
    std::map<std::int64_t, StoredGeometry> storedGeometries();

    SqliteConnection& connection() { return connection_; }

private:
    SqliteConnection connection_;
    ColmapSchema schema_;
};

} // namespace essential_colmap

#endif
