// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// Geometric verification of a COLMAP database's matched image pairs with the module's batch API:
// keypoints undistorted by each camera's own model, an essential matrix per pair estimated in
// parallel, and the two_view_geometries rows COLMAP's own verification would write (config, inlier
// matches, E, F, relative pose). Reads the database only; writing is writeTwoViewGeometries().

#ifndef ESSENTIAL_SAMPLES_COLMAP_VERIFY_PAIRS_HPP
#define ESSENTIAL_SAMPLES_COLMAP_VERIFY_PAIRS_HPP

#include "colmap/colmap_database.hpp"
#include "colmap/two_view_geometry.hpp"

#include <opencv2/essential.hpp>

#include <cstdint>
#include <vector>

namespace essential_colmap {

struct VerificationOptions
{
    /** Solver, engine, iteration cap, seed; `threshold` in pixels (Sampson distance), converted to
    normalised units by the mean focal length of the pair's two cameras, as COLMAP does with its
    max_error. Default 4 px: COLMAP 3.8's SiftMatching.max_error. */
    cv::essential::EssentialParams params = defaultParams();
    /** A pair with fewer inliers is DEGENERATE (COLMAP's min_num_inliers, default 15). At least 6:
    the module returns several candidate matrices for exactly five points. */
    int minInliers = 15;
    int threads = 0;             //!< 0: cv::getNumThreads()
    bool unverifiedOnly = false; //!< only pairs without a two_view_geometries row
    /** Pairs estimated per batch call (bounds the memory held in points: the seeds are those of one
    batch of all pairs whatever the chunk size). */
    int chunkSize = 512;
    cv::essential::BatchProgress progress; //!< done / total pairs, as the batch reports them

    static cv::essential::EssentialParams defaultParams()
    {
        cv::essential::EssentialParams p;
        p.threshold = 4.0;
        return p;
    }
};

/** What verification found for one pair, beside its record. */
struct PairVerification
{
    std::int64_t image1 = 0, image2 = 0;
    int matches = 0;               //!< raw matches
    int unusableMatches = 0;       //!< matches of keypoints whose undistortion did not converge
    bool estimated = false;        //!< false: too few matches to try
    bool degenerateReport = false; //!< the module's EssentialReport::degenerate
    double rotationOnlyFraction = 0, homographyFraction = 0;
};

struct Verification
{
    std::vector<TwoViewGeometryRecord> records;
    std::vector<PairVerification> pairs; //!< parallel to records
    double readMs = 0;                   //!< reading the database and undistorting keypoints
    double estimateMs = 0;               //!< the batch estimates (wall time over all threads)
};

/** Verifies the selected pairs. Throws DatabaseError for a malformed database (unknown camera or
image, unsupported camera model, a match index past an image's keypoints) before any estimate. */
Verification verifyPairs(ColmapDatabase& database, const VerificationOptions& options);

} // namespace essential_colmap

#endif
