// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Spatially local sampling (NAPSAC, Nasuto and Craddock; the progressive variant of Barath et al.
// mixes local and global samples). Inliers of real pairs cluster: textured objects, a wall, the
// ground near the camera, while wrong matches scatter. A sample whose points are neighbours in both
// images is then far more likely to be outlier-free than a uniform one: at 10% inliers overall, a
// region where half the matches are right gives 0.5^5 = 3% clean samples against 0.001%.

#ifndef OPENCV_ESSENTIAL_SAMPLING_NAPSAC_SAMPLER_HPP
#define OPENCV_ESSENTIAL_SAMPLING_NAPSAC_SAMPLER_HPP

#include "input/problem.hpp"

#include <opencv2/core.hpp>

#include <vector>

namespace cv {
namespace essential {
namespace sampling {

/** Local samples from a multi-resolution grid over both images. Each level divides the bounding
box of the points in image 1 and, separately, in image 2 into c x c cells (c = 16, 8, 4, 2); two
correspondences are neighbours at a level when they share a cell in both images (a cell of the
4-dimensional correspondence space, as P-NAPSAC's grids). A local sample picks a seed uniformly, a
level among those whose cell around the seed holds at least the sample size, and the other points
uniformly from that cell. */
class NapsacSampler
{
public:
    /** Samples of `m` of the correspondences `points` (any units). */
    NapsacSampler(const Problem& points, int m);

    /** Draws a local sample into `indices` (m distinct indices); false (nothing drawn) when the
    seed has fewer than m - 1 neighbours at every level. */
    bool draw(RNG& rng, int* indices);

private:
    struct Level
    {
        std::vector<int> order;     //!< point indices sorted by cell
        std::vector<int> cellBegin; //!< per point: where its cell starts in `order`
        std::vector<int> cellEnd;   //!< per point: where its cell ends
    };
    int n_, m_;
    std::vector<Level> levels_;
};

} // namespace sampling
} // namespace essential
} // namespace cv

#endif
