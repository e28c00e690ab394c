// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// A small feature front end for the samples: FAST-9 corners on an image pyramid, an ORB (rBRIEF)
// descriptor per corner, and brute-force matching that keeps the best fraction of the matches.
// It uses OpenCV only; nothing here is part of the opencv_essential library.

#ifndef ESSENTIAL_SAMPLES_FRONTEND_HPP
#define ESSENTIAL_SAMPLES_FRONTEND_HPP

#include <opencv2/core.hpp>

#include <cstdint>
#include <vector>

namespace essential_samples {

/** Settings of the front end. */
struct FrontEndParams
{
    /** FAST-9 (TYPE_9_16) intensity threshold. */
    int fastThreshold = 20;

    /** Non-maximum suppression of the FAST corners on each level. */
    bool nonmaxSuppression = true;

    /** Smallest pyramid level, in pixels along the shorter side: the pyramid (scales 1, 2/3, 1/2,
    1/3, 1/4, 1/6, ...) stops before a level would be smaller than this. */
    int minLevelSize = 80;

    /** Corners closer than this (in pixels of their own level) to the level's border get no
    descriptor and are dropped. At least 16, the radius of the orientation patch plus one. */
    int border = 20;

    /** Describe every corner without orientation (BRIEF on ORB's pattern, not rotated). The
    default computes ORB's intensity-centroid orientation, so descriptors are rBRIEF. */
    bool upright = false;

    /** Fraction of the matches kept, the best by descriptor distance; in (0, 1]. */
    double keepFraction = 0.2;

    /** Seed of the shuffle that puts the kept matches in random order. */
    std::uint64_t shuffleSeed = 0x5eed;
};

/** The scales of the pyramid levels of an image of the given size: 1, 2/3, 1/2, 1/3, 1/4, 1/6,
1/8, ... while the shorter side of a level stays >= minLevelSize (level 0 is always present). */
std::vector<double> pyramidScales(cv::Size imageSize, int minLevelSize);

/** Corners and descriptors of one image. */
struct Features
{
    /** Corners in level-0 pixel coordinates; `octave` is the pyramid level they were found on,
    `size` the descriptor patch diameter in level-0 pixels, `angle` the orientation in degrees. */
    std::vector<cv::KeyPoint> keypoints;
    /** One 32-byte ORB descriptor (CV_8U row) per keypoint. */
    cv::Mat descriptors;
    /** Corners found by FAST on all levels, before the border filter. */
    int cornersDetected = 0;
    /** Number of pyramid levels. */
    int levels = 0;
};

/** Detects FAST-9 corners on every pyramid level of `image` (8-bit, 1 or 3 channels) and computes
their ORB descriptors. */
Features detectAndDescribe(const cv::Mat& image, const FrontEndParams& params = FrontEndParams());

/** Matched correspondences, in random order. */
struct Matches
{
    std::vector<cv::Point2f> points1; //!< in image 1 (level-0 pixel coordinates)
    std::vector<cv::Point2f> points2; //!< the corresponding points in image 2
    std::vector<int> distances;       //!< Hamming distance of each kept match
    int candidates = 0;               //!< matches before the selection (one per corner of image 2)
    int maxDistance = 0;              //!< largest distance kept
};

/** Matches every corner of image 2 to its nearest corner of image 1 by Hamming distance (brute
force, no distance limit, no ratio or cross check), keeps the best `keepFraction` of these matches
and shuffles them with `shuffleSeed`. */
Matches matchFeatures(const Features& features1, const Features& features2,
                      const FrontEndParams& params = FrontEndParams());

} // namespace essential_samples

#endif // ESSENTIAL_SAMPLES_FRONTEND_HPP
