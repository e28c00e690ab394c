// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Input checks and normalisation: from whatever the caller passed (OpenCV point layouts, camera
// matrices, distortion) to a Problem of normalised correspondences the engine can work on.

#ifndef OPENCV_ESSENTIAL_INPUT_PROBLEM_HPP
#define OPENCV_ESSENTIAL_INPUT_PROBLEM_HPP

#include "opencv2/essential/params.hpp"

#include <opencv2/core.hpp>

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

/** Normalised correspondences in structure-of-arrays layout, so that scoring loops vectorise, plus
the same points as Point2d arrays for the solvers' samples. */
struct Problem
{
    std::vector<double> x1, y1, x2, y2;
    std::vector<Point2d> p1, p2;
    /** The call's inlier threshold on `distance`, in normalised units (inlierTest()). */
    double threshold = 0.0;
    /** The distance the call's inlier test compares with the threshold. */
    EssentialDistance distance = DISTANCE_SAMPSON;

    int size() const { return static_cast<int>(x1.size()); }
    /** The call's inlier test, as the caller set it. */
    InlierTest inlierTest() const { return InlierTest{threshold, distance}; }
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

/** Builds the Problem from normalised points and a threshold already in normalised units, on the
given inlier distance. */
Problem makeProblem(std::vector<Point2d> n1, std::vector<Point2d> n2, double threshold,
                    EssentialDistance distance = DISTANCE_SAMPSON);

/** The points `indices[0..count)` of `problem`, in that order, as a problem with the given inlier
test: what a refinement on the points near a model fits. */
Problem subsetProblem(const Problem& problem, const int* indices, int count, InlierTest test);

/** The same for the points whose `mask` entry is non-zero, in their order. */
Problem maskedProblem(const Problem& problem, const uchar* mask, InlierTest test);

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
