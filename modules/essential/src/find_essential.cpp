// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The public findEssentialMatIter overloads: each checks its arguments and turns them into the
// module's settings (input/params_from_opencv, input/check_params) and normalised correspondences
// with a normalised threshold (input/), then runs the one pipeline (pipeline/estimate).

#include "opencv2/essential.hpp"

#include "drop_in_estimate.hpp"
#include "input/check_params.hpp"
#include "input/mask_output.hpp"
#include "input/params_from_opencv.hpp"
#include "input/point_layouts.hpp"
#include "input/problem.hpp"
#include "pipeline/estimate.hpp"

#include <opencv2/calib3d.hpp>

#include <utility>
#include <vector>

namespace cv {
namespace essential {

namespace {

/** The distance the call's threshold applies to: LMedS ranks by the Sampson distance whatever
was asked (as OpenCV's LMEDS), everything else uses EssentialParams::distance. */
EssentialDistance inlierDistance(const EssentialParams& params)
{
    return params.score == SCORE_METHOD_LMEDS ? DISTANCE_SAMPSON : params.distance;
}

Mat estimateWithCamera(InputArray points1, InputArray points2, const Matx33d& K,
                       const EssentialParams& params, PointReading reading, OutputArray mask,
                       MaskWriting maskWriting, EssentialReport* report, int64 start)
{
    Mat rows1, rows2;
    readPointRows(points1, points2, reading, rows1, rows2);
    const Problem problem = normalisedProblem(rows1, rows2, K, 5);
    const double meanFocal = 0.5 * (K(0, 0) + K(1, 1));
    const InlierTest test{normalisedThreshold(params.threshold, meanFocal), inlierDistance(params)};
    return estimate(problem, test, params, mask, maskWriting, report, start);
}

} // namespace

Mat estimateTwoCameras(InputArray points1, InputArray points2, InputArray cameraMatrix1,
                       InputArray distCoeffs1, InputArray cameraMatrix2, InputArray distCoeffs2,
                       const EssentialParams& params, PointReading reading, OutputArray mask,
                       MaskWriting maskWriting, std::vector<Point2d>* normalised1,
                       std::vector<Point2d>* normalised2)
{
    const int64 start = getTickCount();
    std::vector<Point2d> p1, p2;
    readPointPair(points1, points2, reading, p1, p2);
    checkPointSets(p1, p2, 5);
    const Matx33d K1 = readCameraMatrix(cameraMatrix1, "cameraMatrix1");
    const Matx33d K2 = readCameraMatrix(cameraMatrix2, "cameraMatrix2");
    checkDistortion(distCoeffs1, "distCoeffs1");
    checkDistortion(distCoeffs2, "distCoeffs2");
    std::vector<Point2d> n1, n2;
    undistortPoints(p1, n1, K1, distCoeffs1);
    undistortPoints(p2, n2, K2, distCoeffs2);
    // Extreme distortion coefficients can send undistorted points to infinity or NaN.
    checkNormalisedPoints(n1, "points1 (undistorted with distCoeffs1)");
    checkNormalisedPoints(n2, "points2 (undistorted with distCoeffs2)");
    if (normalised1) *normalised1 = n1;
    if (normalised2) *normalised2 = n2;
    const double meanFocal = 0.25 * (K1(0, 0) + K1(1, 1) + K2(0, 0) + K2(1, 1));
    const InlierTest test{normalisedThreshold(params.threshold, meanFocal), inlierDistance(params)};
    return estimate(makeProblem(n1, n2), test, params, mask, maskWriting, nullptr, start);
}

Mat findEssentialMatIter(InputArray points1, InputArray points2, InputArray cameraMatrix,
                         int method, double prob, double threshold, int maxIters, OutputArray mask)
{
    const int64 start = getTickCount();
    const EssentialParams params = dropInParams(method, prob, threshold, maxIters);
    const Matx33d K = readCameraMatrix(cameraMatrix, "cameraMatrix");
    return estimateWithCamera(points1, points2, K, params, readingForMethod(method), mask,
                              maskWritingForMethod(method), nullptr, start);
}

#if CV_VERSION_MAJOR < 5
Mat findEssentialMatIter(InputArray points1, InputArray points2, InputArray cameraMatrix,
                         int method, double prob, double threshold, OutputArray mask)
{
    return findEssentialMatIter(points1, points2, cameraMatrix, method, prob, threshold, 1000,
                                mask);
}
#endif

Mat findEssentialMatIter(InputArray points1, InputArray points2, double focal, Point2d pp,
                         int method, double prob, double threshold, int maxIters, OutputArray mask)
{
    const int64 start = getTickCount();
    const EssentialParams params = dropInParams(method, prob, threshold, maxIters);
    return estimateWithCamera(points1, points2, cameraFromFocal(focal, pp), params,
                              readingForMethod(method), mask, maskWritingForMethod(method), nullptr,
                              start);
}

#if CV_VERSION_MAJOR < 5
Mat findEssentialMatIter(InputArray points1, InputArray points2, double focal, Point2d pp,
                         int method, double prob, double threshold, OutputArray mask)
{
    return findEssentialMatIter(points1, points2, focal, pp, method, prob, threshold, 1000, mask);
}
#endif

Mat findEssentialMatIter(InputArray points1, InputArray points2, InputArray cameraMatrix1,
                         InputArray distCoeffs1, InputArray cameraMatrix2, InputArray distCoeffs2,
                         int method, double prob, double threshold, OutputArray mask)
{
    const EssentialParams params = dropInParams(method, prob, threshold, 1000);
    // OpenCV undistorts first (cv::undistortPoints reads the points), whatever the method.
    return estimateTwoCameras(points1, points2, cameraMatrix1, distCoeffs1, cameraMatrix2,
                              distCoeffs2, params, PointReading::Undistort, mask,
                              maskWritingForMethod(method));
}

Mat findEssentialMatIter(InputArray points1, InputArray points2, InputArray cameraMatrix1,
                         InputArray cameraMatrix2, InputArray distCoeffs1, InputArray distCoeffs2,
                         OutputArray mask, const UsacParams& usac)
{
    const EssentialParams params = usacParams(usac);
    // OpenCV's USAC undistorts (a continuous copy of) the points only when there are coefficients.
    const PointReading reading = distCoeffs1.empty() && distCoeffs2.empty()
                                     ? PointReading::Usac
                                     : PointReading::UndistortCopy;
    return estimateTwoCameras(points1, points2, cameraMatrix1, distCoeffs1, cameraMatrix2,
                              distCoeffs2, params, reading, mask, MaskWriting::Usac);
}

Mat findEssentialMatIter(InputArray points1, InputArray points2, InputArray cameraMatrix,
                         const EssentialParams& params, OutputArray mask, EssentialReport* report)
{
    const int64 start = getTickCount();
    checkEssentialParams(params);
    const Matx33d K = readCameraMatrix(cameraMatrix, "cameraMatrix");
    // The module's own overload reads every layout of any drop-in form (the USAC reading accepts
    // them all) and writes the mask as N x 1.
    return estimateWithCamera(points1, points2, K, params, PointReading::Usac, mask,
                              MaskWriting::Usac, report, start);
}

Mat findEssentialMatIter(InputArray points1, InputArray points2, InputArray cameraMatrix,
                         const EssentialParams& params, OutputArray mask, EssentialReport& report)
{
    return findEssentialMatIter(points1, points2, cameraMatrix, params, mask, &report);
}

} // namespace essential
} // namespace cv
