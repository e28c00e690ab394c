// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Input checks and normalisation: from whatever the caller passed (OpenCV point layouts, camera
// matrices, distortion) to a Problem of normalised correspondences the engine can work on.

#ifndef OPENCV_ESSENTIAL_INPUT_PROBLEM_HPP
#define OPENCV_ESSENTIAL_INPUT_PROBLEM_HPP

#include "opencv2/essential/params.hpp"

#include <opencv2/core.hpp>

#include <memory>
#include <utility>
#include <vector>

namespace cv {
namespace essential {

/** What makes a correspondence an inlier of a model: its `distance` (Sampson or symmetric
epipolar) at most `threshold` (normalised units). Scoring takes it by value beside the points, so a
stage testing with another threshold (LMedS's, the plane check's looser band, local optimisation's
inner one) changes a double, not a copy of the points. */
struct InlierTest
{
    double threshold = 0.0;
    EssentialDistance distance = DISTANCE_SAMPSON;

    InlierTest withThreshold(double t) const { return InlierTest{t, distance}; }
};

/** std::allocator, except that resize() leaves new elements uninitialised instead of zeroing them:
for arrays written in full right after they are sized (every Problem's coordinates: a call sizes
several, and its local optimisation resizes a subset per new best model; scratch index and
distance lists), where the zeroing would be wasted stores. */
template <class T> struct UninitialisedAllocator : std::allocator<T>
{
    template <class U> struct rebind
    {
        using other = UninitialisedAllocator<U>;
    };
    UninitialisedAllocator() = default;
    template <class U> UninitialisedAllocator(const UninitialisedAllocator<U>&) noexcept {}
    /** Value-initialisation (what resize() asks for) becomes default-initialisation. */
    template <class U> void construct(U* p) noexcept { ::new (static_cast<void*>(p)) U; }
    template <class U, class... Args> void construct(U* p, Args&&... args)
    {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

/** One coordinate of every correspondence of a Problem. */
using Coordinates = std::vector<double, UninitialisedAllocator<double>>;

/** The normalised correspondences of one call, stored once, in structure-of-arrays layout so that
scoring loops vectorise; point1() / point2() read one correspondence (a solver's sample is gathered
with them). What makes a point an inlier is not part of it: the stages that test points take an
InlierTest beside it. */
struct Problem
{
    Coordinates x1, y1, x2, y2;

    int size() const { return static_cast<int>(x1.size()); }
    Point2d point1(int i) const
    {
        return Point2d(x1[static_cast<size_t>(i)], y1[static_cast<size_t>(i)]);
    }
    Point2d point2(int i) const
    {
        return Point2d(x2[static_cast<size_t>(i)], y2[static_cast<size_t>(i)]);
    }
};

/** Checks that the two point sets have the same size and at least `minPoints` points. */
void checkPointSets(const std::vector<Point2d>& p1, const std::vector<Point2d>& p2, int minPoints);

/** Reads a 3 x 3 camera matrix (any depth but CV_16F, as cv::findEssentialMat reads it; finite, fx
and fy positive, last row 0 0 1, invertible). */
Matx33d readCameraMatrix(InputArray cameraMatrix, const char* name);

/** The camera matrix of the focal/principal-point overloads; checks focal (finite, positive). */
Matx33d cameraFromFocal(double focal, Point2d pp);

/** Pixel points to normalised coordinates with K^-1 (skew included). */
std::vector<Point2d> normalisePoints(const std::vector<Point2d>& pixels, const Matx33d& K);

/** Largest magnitude of a normalised coordinate: a point 1e8 focal lengths from the principal
point is a ray within 1e-8 radians of the image plane. The bound keeps every product of the
scoring (up to the fourth power of a coordinate in the Sampson distance) far from overflow; a
pixel coordinate of 1e8 with a focal length of 500 (2e5 normalised) is well inside it. */
constexpr double kMaxNormalised = 1e8;

/** Checks normalised points (after K^-1 or undistortion): finite and within kMaxNormalised;
throws naming `name` and the index otherwise. */
void checkNormalisedPoints(const std::vector<Point2d>& normalised, const char* name);

/** The pixel threshold in normalised units; throws if it is not positive and finite (a huge
threshold with a tiny focal length, or the converse). */
double normalisedThreshold(double threshold, double meanFocal);

/** The Problem of the pixel points of readPointRows' `rows1` <-> `rows2` normalised by K^-1, with
the checks of the step-by-step path (pointsFromRows' finite coordinates for points1 then points2,
checkPointSets' `minPoints`, checkNormalisedPoints for points1 then points2) and the same
exceptions, in the same order. The points are read, normalised and checked in one pass over them
into the Problem's arrays; only input that fails a check goes the step-by-step way, to throw. */
Problem normalisedProblem(const Mat& rows1, const Mat& rows2, const Matx33d& K, int minPoints);

/** The Problem of normalised points n1[i] <-> n2[i]. */
Problem makeProblem(const std::vector<Point2d>& n1, const std::vector<Point2d>& n2);

/** The points `indices[0..count)` of `problem`, in that order: what a refinement on the points
near a model fits. */
Problem subsetProblem(const Problem& problem, const int* indices, int count);

/** subsetProblem into `out`, whose storage is reused: a caller that gathers subsets again and
again (the local optimisation, once per new best model) allocates only when a subset is larger
than every one before. */
void gatherProblem(const Problem& problem, const int* indices, int count, Problem& out);

/** The points whose `mask` entry is non-zero, in their order. */
Problem maskedProblem(const Problem& problem, const uchar* mask);

/** The points as Point2d arrays, for OpenCV's RANSAC loop (which takes a Mat of them). */
void toPoint2d(const Problem& problem, std::vector<Point2d>& p1, std::vector<Point2d>& p2);

/** Argument checks shared by every overload; messages name the argument. */
void checkConfidence(double prob);
void checkThreshold(double threshold);
/** `name` is the caller's spelling: "maxIters" (the drop-in forms) or
"EssentialParams::maxIterations", "UsacParams::maxIterations". */
void checkMaxIters(int maxIters, const char* name = "maxIters");
void checkMethod(int method);

} // namespace essential
} // namespace cv

#endif
