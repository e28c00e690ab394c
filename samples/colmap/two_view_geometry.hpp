// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// A row of COLMAP's two_view_geometries table and its writing. COLMAP 3.8's columns: pair_id, the
// inlier matches (rows x 2 uint32 blob, as matches), config, and F, E, H (3 x 3 float64,
// row-major), qvec (w, x, y, z) and tvec (float64): the relative pose X2 = R(qvec) X1 + tvec, image
// 1 being the pair's lower image id, and x2^T E x1 = 0 between normalised points (x2^T F x1 = 0 in
// pixels).

#ifndef ESSENTIAL_SAMPLES_COLMAP_TWO_VIEW_GEOMETRY_HPP
#define ESSENTIAL_SAMPLES_COLMAP_TWO_VIEW_GEOMETRY_HPP

#include "colmap/colmap_database.hpp"

#include <opencv2/core.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace essential_colmap {

/** COLMAP's TwoViewGeometry::ConfigurationType values (3.8). */
enum TwoViewConfig {
    CONFIG_UNDEFINED = 0,
    CONFIG_DEGENERATE = 1,          //!< no geometry (too few inliers, no overlap)
    CONFIG_CALIBRATED = 2,          //!< an essential matrix, both focal lengths known
    CONFIG_UNCALIBRATED = 3,        //!< a fundamental matrix (a focal length is a guess)
    CONFIG_PLANAR = 4,              //!< a homography: a plane seen with a baseline
    CONFIG_PANORAMIC = 5,           //!< a homography: pure rotation, no baseline
    CONFIG_PLANAR_OR_PANORAMIC = 6, //!< a homography, one of the two
    CONFIG_WATERMARK = 7,
    CONFIG_MULTIPLE = 8,
};

/** COLMAP's name of a config value ("CALIBRATED"), or "config N". */
const char* twoViewConfigName(int config);

/** One two_view_geometries row. */
struct TwoViewGeometryRecord
{
    std::int64_t pairId = 0;
    int config = CONFIG_UNDEFINED;
    std::vector<FeatureMatch> inlierMatches;
    cv::Matx33d F = cv::Matx33d::zeros(), E = cv::Matx33d::zeros(), H = cv::Matx33d::zeros();
    cv::Vec4d qvec = cv::Vec4d(0, 0, 0, 0); //!< w, x, y, z
    cv::Vec3d tvec = cv::Vec3d(0, 0, 0);
};

/** The unit quaternion (w, x, y, z, w >= 0) of a rotation matrix. */
cv::Vec4d quaternionOf(const cv::Matx33d& R);

/** Called after each row written with the number written so far; it may throw to abort. The
tests use it to make a write fail part-way. */
typedef std::function<void(std::size_t written)> RowWritten;

/** Inserts or replaces the rows of `records` in two_view_geometries, in one transaction: on any
error (SQLite's, or an exception from `afterRow`) nothing is written. No other row or table is
touched. A database that fails SQLite's quick_check is refused (DatabaseError) before any row. */
void writeTwoViewGeometries(ColmapDatabase& database,
                            const std::vector<TwoViewGeometryRecord>& records,
                            const RowWritten& afterRow = RowWritten());

} // namespace essential_colmap

#endif
