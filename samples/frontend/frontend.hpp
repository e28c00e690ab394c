// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// A small feature front end for the samples: FAST-9 corners on an image pyramid, a descriptor per
// corner (upright BRIEF on ORB's pattern by default, ORB's rotated rBRIEF or a normalised grey
// patch on request), and brute-force matching that keeps the best fraction of the matches; or, on
// request, the standard structure-from-motion front end: OpenCV's SIFT with Lowe's ratio test.
// It uses OpenCV only; nothing here is part of the opencv_essential library.

#ifndef ESSENTIAL_SAMPLES_FRONTEND_HPP
#define ESSENTIAL_SAMPLES_FRONTEND_HPP

#include <opencv2/core.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace essential_samples {

/** How the keypoints are found. */
enum class Detector {
    /** FAST-9 corners on every level of this front end's pyramid, described by
    FrontEndParams::descriptor. */
    Fast9Pyramid,
    /** OpenCV's SIFT (cv::SIFT, difference-of-Gaussians keypoints with their own 128-float
    descriptor, L2 distance), matched with Lowe's ratio test (FrontEndParams::ratio). */
    Sift
};

/** "fast" or "sift". */
const char* detectorName(Detector detector);

/** Parses "fast" or "sift"; false for anything else. */
bool parseDetector(const std::string& name, Detector& detector);

/** The descriptor computed on every corner. */
enum class Descriptor {
    /** ORB's 256-bit BRIEF pattern, not rotated: binary, Hamming distance. */
    UprightBrief,
    /** ORB's rBRIEF: the same pattern rotated by the intensity-centroid orientation. */
    RotatedBrief,
    /** An 8 x 8 grey patch sampled every 2 pixels from the Gaussian-smoothed level (sigma 1.2),
    zero mean and unit norm: float, L2 distance (a monotonic function of the NCC). */
    Patch,
    /** SIFT's own 128-float descriptor, L2 distance: what Detector::Sift computes (FAST corners
    cannot have it). */
    Sift
};

/** "brief", "orb", "patch" or "sift". */
const char* descriptorName(Descriptor descriptor);

/** Parses "brief", "orb", "patch" or "sift"; false for anything else. */
bool parseDescriptor(const std::string& name, Descriptor& descriptor);

/** How matchFeatures() finds the nearest corner of image 1 for each corner of image 2. */
enum class Matcher {
    /** Every corner against every corner (OpenCV's BFMatcher): exact, quadratic in the corners. */
    BruteForce,
    /** Only the strongest corners (FAST score) of each cell of a kGridCells x kGridCells grid over
    the image, at most kGridCorners per image, then brute force: a fixed cost whatever the image. */
    Grid,
    /** Approximate nearest neighbours with FLANN: locality-sensitive hashing for the binary
    descriptors, randomised k-d trees for the patch and SIFT; some nearest neighbours are missed.
    */
    Flann
};

/** "brute-force", "grid" or "flann". */
const char* matcherName(Matcher matcher);

/** Parses "brute-force", "grid" or "flann"; false for anything else. */
bool parseMatcher(const std::string& name, Matcher& matcher);

/** Matcher::Grid: the grid over the image and the corners it keeps per image. */
const int kGridCells = 8;
const int kGridCorners = 2048;

/** Settings of the front end. */
struct FrontEndParams
{
    /** The keypoints: FAST-9 on the pyramid by default (with `descriptor`), or SIFT. The FAST-9
    settings below (fastThreshold to border) and `descriptor` apply to Detector::Fast9Pyramid,
    siftFeatures and ratio to Detector::Sift. */
    Detector detector = Detector::Fast9Pyramid;

    /** Detector::Sift: the nfeatures of cv::SIFT::create, the strongest keypoints kept per image
    (by response); 0 keeps them all. Default 4000. */
    int siftFeatures = 4000;

    /** Detector::Sift: Lowe's ratio test. Each keypoint of image 2 gets its two nearest keypoints
    of image 1, and the match to the nearest is kept only when its distance is below `ratio` times
    the second's (an ambiguous match, in repeated texture, is dropped). In (0, 1]; default 0.8,
    Lowe's value (2004: on his data it drops 90% of the false matches and under 5% of the right
    ones). Unused by Detector::Fast9Pyramid, which keeps the nearest neighbour however close the
    second is. */
    double ratio = 0.8;

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

    /** The descriptor. Upright BRIEF by default, chosen on the rail-a sequences (camera on a rail,
    rotation below 1 degree; docs/FRONTEND.md, "Choice of the descriptor"): the fraction of the kept
    matches within 1 px (Sampson) of the true E, mean of 4 pairs per offset,

        offset N            1     5     10    20    40    60    mean
        horizontal brief  0.999 0.980 0.955 0.876 0.686 0.579  0.846
                   orb    0.996 0.960 0.898 0.700 0.453 0.380  0.731
                   patch  0.997 0.947 0.887 0.788 0.627 0.565  0.802
        optic      brief  0.994 0.975 0.947 0.904 0.754 0.571  0.857
                   orb    0.992 0.959 0.922 0.832 0.589 0.364  0.776
                   patch  0.992 0.955 0.918 0.860 0.714 0.548  0.831

    Upright BRIEF is best at every offset, and also the fastest to compute with the patch (about
    11 ms per 640 x 480 image against 27 ms for rBRIEF). Video from a rotating (hand-held)
    camera may prefer RotatedBrief. Detector::Sift computes its own descriptor (Descriptor::Sift);
    with it this must be Sift or left at the default. */
    Descriptor descriptor = Descriptor::UprightBrief;

    /** How the corners are matched; brute force by default (exact). Matcher::Grid is the fast mode
    (docs/FRONTEND.md, "Faster matching": 10-82 ms of matching on the rail and real pairs, 5 to 420
    times less than brute force). Grid limits the corners when they are detected, so
    detectAndDescribe() and matchFeatures() must get the same setting. With Detector::Sift, Grid
    keeps the SIFT keypoints of highest response per cell in the same way, and Flann uses
    randomised k-d trees. */
    Matcher matcher = Matcher::BruteForce;

    /** Fraction of the matches kept, the best by descriptor distance; in (0, 1]. Default 0.2.
    With Detector::Sift it applies to the matches that pass the ratio test, and essential_pair's
    default is then 1 (every ratio-test survivor: the ratio test has filtered them already). */
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
    `size` the descriptor patch diameter in level-0 pixels, `angle` the orientation in degrees.
    SIFT keypoints are cv::SIFT's as it returns them (`octave` packed as cv::SIFT packs it). */
    std::vector<cv::KeyPoint> keypoints;
    /** One descriptor per keypoint: a 32-byte CV_8U row (BRIEF), a 64-float CV_32F row (patch) or a
    128-float CV_32F row (SIFT). */
    cv::Mat descriptors;
    /** Which descriptor `descriptors` holds. */
    Descriptor descriptor = Descriptor::UprightBrief;
    /** Corners found by FAST on all levels, before the border filter; or the keypoints SIFT
    returned (before Matcher::Grid's selection, as for FAST). */
    int cornersDetected = 0;
    /** Number of pyramid levels; for SIFT, the number of octaves its keypoints come from. */
    int levels = 0;
};

/** Detects FAST-9 corners on every pyramid level of `image` (8-bit, 1, 3 or 4 channels) and
computes their descriptors (params.descriptor); or, with params.detector == Detector::Sift, runs
cv::SIFT (params.siftFeatures) on the grey image for its keypoints and 128-float descriptors. */
Features detectAndDescribe(const cv::Mat& image, const FrontEndParams& params = FrontEndParams());

/** Matched correspondences, in random order. */
struct Matches
{
    std::vector<cv::Point2f> points1; //!< in image 1 (level-0 pixel coordinates)
    std::vector<cv::Point2f> points2; //!< the corresponding points in image 2
    std::vector<float> distances;     //!< descriptor distance of each kept match
    /** Matches before the selection: one per corner of image 2; for SIFT, one per keypoint of
    image 2 that has two neighbours in image 1. */
    int candidates = 0;
    float maxDistance = 0; //!< largest distance kept
    /** SIFT: the candidates that pass the ratio test, the matches keepFraction then selects from;
    otherwise equal to candidates. */
    int ratioTestPassed = 0;
};

/** Matches every corner of image 2 to its nearest corner of image 1 by descriptor distance (Hamming
for BRIEF, L2 for the patch; params.matcher: brute force by default, or approximate; no distance
limit, no ratio or cross check), keeps the best `keepFraction` of these matches and shuffles them
with `shuffleSeed`. Both feature sets must hold the same descriptor.

SIFT descriptors (Detector::Sift) are matched the standard way instead: the two nearest keypoints
of image 1 for each keypoint of image 2 (L2; brute force, or k-d trees with Matcher::Flann), a
candidate per keypoint of image 2 that has two, kept when the nearest distance is below
params.ratio times the second (Lowe's ratio test); then the best `keepFraction` of those and the
shuffle as above. */
Matches matchFeatures(const Features& features1, const Features& features2,
                      const FrontEndParams& params = FrontEndParams());

} // namespace essential_samples

#endif // ESSENTIAL_SAMPLES_FRONTEND_HPP
