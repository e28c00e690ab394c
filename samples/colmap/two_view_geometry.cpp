// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "colmap/two_view_geometry.hpp"

#include <opencv2/calib3d.hpp>

#include <algorithm>
#include <cmath>

namespace essential_colmap {

const char* twoViewConfigName(int config)
{
    switch (config) {
    case CONFIG_UNDEFINED:
        return "UNDEFINED";
    case CONFIG_DEGENERATE:
        return "DEGENERATE";
    case CONFIG_CALIBRATED:
        return "CALIBRATED";
    case CONFIG_UNCALIBRATED:
        return "UNCALIBRATED";
    case CONFIG_PLANAR:
        return "PLANAR";
    case CONFIG_PANORAMIC:
        return "PANORAMIC";
    case CONFIG_PLANAR_OR_PANORAMIC:
        return "PLANAR_OR_PANORAMIC";
    case CONFIG_WATERMARK:
        return "WATERMARK";
    case CONFIG_MULTIPLE:
        return "MULTIPLE";
    default:
        return "unknown config";
    }
}

cv::Vec4d quaternionOf(const cv::Matx33d& R)
{
    // The rotation vector's angle and axis, then (cos(a/2), sin(a/2) axis): stable at every
    // angle, unlike reading the quaternion off the trace alone.
    cv::Vec3d rvec;
    cv::Rodrigues(cv::Mat(R), rvec);
    const double angle = cv::norm(rvec);
    if (angle == 0.0) return cv::Vec4d(1, 0, 0, 0);
    const cv::Vec3d axis = rvec / angle;
    const double s = std::sin(angle / 2);
    return cv::Vec4d(std::cos(angle / 2), s * axis[0], s * axis[1], s * axis[2]);
}

void writeTwoViewGeometries(ColmapDatabase& database,
                            const std::vector<TwoViewGeometryRecord>& records,
                            const RowWritten& afterRow)
{
    SqliteConnection& connection = database.connection();
    SqliteTransaction transaction(connection);
    // A corrupt file that SQLite reads without complaint (two b-tree pages claiming the same child
    // page: the colmap fuzz target's third finding) can be damaged for good by a write that SQLite
    // reports as done. Refuse to write into one. quick_check reads every page once (a few ms for
    // the rail test database of 2 MB); it skips only the index-against-table comparisons.
    {
        SqliteStatement check(connection, "PRAGMA quick_check(1)");
        const std::string verdict = check.step() ? check.text(0) : std::string("no answer");
        if (verdict != "ok")
            throw DatabaseError("database '" + connection.path() +
                                "' is corrupt, nothing written (SQLite's quick_check: " + verdict +
                                ")");
    }
    SqliteStatement insert(connection, "INSERT OR REPLACE INTO two_view_geometries "
                                       "(pair_id, rows, cols, data, config, F, E, H, qvec, tvec) "
                                       "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    std::size_t written = 0;
    for (const TwoViewGeometryRecord& r : records) {
        insert.bind(1, r.pairId);
        insert.bind(2, static_cast<std::int64_t>(r.inlierMatches.size()));
        insert.bind(3, std::int64_t(2));
        insert.bindBlob(4, r.inlierMatches.data(), r.inlierMatches.size() * sizeof(FeatureMatch));
        insert.bind(5, std::int64_t(r.config));
        // cv::Matx33d stores its entries row by row, as COLMAP's blobs.
        insert.bindBlob(6, r.F.val, sizeof(r.F.val));
        insert.bindBlob(7, r.E.val, sizeof(r.E.val));
        insert.bindBlob(8, r.H.val, sizeof(r.H.val));
        insert.bindBlob(9, r.qvec.val, sizeof(r.qvec.val));
        insert.bindBlob(10, r.tvec.val, sizeof(r.tvec.val));
        insert.step();
        insert.reset();
        ++written;
        if (afterRow) afterRow(written);
    }
    transaction.commit();
}

} // namespace essential_colmap
