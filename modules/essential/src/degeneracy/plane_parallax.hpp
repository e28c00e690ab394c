// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The plane-and-parallax check of a search's winner. When most inliers of a scene lie on one plane,
// a minimal sample drawn from the plane does not fix E: the plane's homography decomposes into two
// poses (the "twins"), and noise moves the solutions along a whole family that fits the plane. Only
// the points off the plane tell them apart, and a search that stops on a model supported by the
// plane alone keeps whichever it met first, often degrees off. Given the
// plane's homography H (calibrated: H ~ R + t n^T / d), every true E is [e']x H with e' ~ t the
// epipole of view 2, and each off-plane correspondence (x1, x2) puts e' on the line (H x1) x x2:
// two of them give e' and a full E. Sampling pairs among the points H does not explain is a 2-point
// search (as DEGENSAC does for fundamental matrices), so the off-plane inliers are found with few
// samples even when they are a small share of the data.

#ifndef OPENCV_ESSENTIAL_DEGENERACY_PLANE_PARALLAX_HPP
#define OPENCV_ESSENTIAL_DEGENERACY_PLANE_PARALLAX_HPP

#include "input/problem.hpp"
#include "scoring/msac_score.hpp"

#include <opencv2/core.hpp>

namespace cv {
namespace essential {
namespace degeneracy {

struct PlaneParallaxResult
{
    bool improved = false;   //!< E below has a lower MSAC cost than the model checked
    Matx33d E;               //!< the better model (when improved)
    scoring::Score score;    //!< its MSAC score on all points (when improved)
    bool planeFound = false; //!< the model's inliers are dominated by one homography
    int planeInliers = 0;    //!< points of the whole problem within the homography's band
    int samples = 0;         //!< 2-point parallax samples drawn
    /** Inliers among the points off the plane: of the model checked, of the best polished
    2-point model, and the median over the first 2-point models drawn (what a model of the plane
    with a wrong epipole gathers by chance). */
    int offPlaneBefore = 0, offPlaneAfter = 0, offPlaneChance = 0;
};

/** Checks the model E (MSAC score `score` on `problem`) when its inliers are fewer than half of the
points (an easy search has already weighed the off-plane points): after quick 4-point probes for a
plane among its inliers, fits a homography to them (OpenCV's RANSAC homography), and when it
explains at least kPlaneShare of them, draws kMaxParallaxSamples pairs of points the homography does
not explain, builds E = [e']x H from each (projected onto the essential manifold), polishes the
best few by IRLS and keeps the best polished model if its MSAC cost is lower than `score`'s and its
gain of inliers off the plane is well beyond chance. */
PlaneParallaxResult checkPlaneAndParallax(const Problem& problem, InlierTest test, const Matx33d& E,
                                          const scoring::Score& score, RNG& rng);

} // namespace degeneracy
} // namespace essential
} // namespace cv

#endif
