// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The public recoverPose overloads: cv::recoverPose's arguments, outputs and mask semantics (OpenCV
// 4.6), on top of the cheirality test of pose_recovery.cpp (no far-point cut) or, where the caller
// gives distanceThresh, of pose_recovery_dlt.cpp (OpenCV's test with that cut).

#include "opencv2/essential.hpp"

#include "drop_in_estimate.hpp"
#include "input/point_layouts.hpp"
#include "input/problem.hpp"
#include "pose/pose_recovery.hpp"
#include "pose/pose_recovery_dlt.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace cv {
namespace essential {

namespace {

[[noreturn]] void badArg(const std::string& message)
{
    CV_Error(Error::StsBadArg, message);
}

/** E as cv::recoverPose reads it: its nine entries reshaped to 3 x 3 (so 1 x 9, 9 x 1 and 3 x 1
three-channel arrays are accepted too), CV_32F or CV_64F, finite. */
Matx33d readEssential(InputArray E)
{
    if (E.empty()) badArg("E is empty: a 3 x 3 essential matrix is needed");
    Mat m = E.getMat();
    const bool nineEntries = m.dims <= 2 && m.total() * static_cast<size_t>(m.channels()) == 9;
    // Reshaping to three rows needs continuous memory unless the array already has three rows.
    if (!nineEntries || (m.rows != 3 && !m.isContinuous()))
        badArg("E must be a 3 x 3 one-channel matrix, or its nine entries in one continuous "
               "array (got " +
               std::to_string(m.rows) + " x " + std::to_string(m.cols) + " with " +
               std::to_string(m.channels()) +
               " channels); a stack of several essential matrices is not accepted");
    if (m.depth() != CV_32F && m.depth() != CV_64F) badArg("E must be CV_32F or CV_64F");
    Matx33d out;
    m.reshape(1, 3).convertTo(Mat(3, 3, CV_64F, out.val), CV_64F);
    for (int i = 0; i < 9; ++i)
        if (!std::isfinite(out.val[i])) badArg("E has a non-finite entry");
    return out;
}

/** The input mask, if any, as one byte per point (non-zero = take part); empty if none. As in
cv::recoverPose: a continuous row or column vector of CV_8U with one entry per point. */
std::vector<uchar> readMask(InputOutputArray mask, int n)
{
    std::vector<uchar> values;
    if (mask.empty()) return values;
    Mat m = mask.getMat();
    if (m.checkVector(1) != n)
        badArg("mask must be a row or column vector, continuous in memory, with one entry per "
               "point (" +
               std::to_string(n) + "), got " + std::to_string(m.rows) + " x " +
               std::to_string(m.cols) + " with " + std::to_string(m.channels()) + " channels" +
               (m.isContinuous() ? "" : ", not continuous"));
    if (m.type() != CV_8UC1) badArg("mask must be CV_8U, as for cv::recoverPose");
    values.resize(static_cast<size_t>(n));
    const uchar* p = m.ptr<uchar>();
    std::copy(p, p + n, values.begin());
    return values;
}

/** The output mask as cv::recoverPose writes it: for a given mask its own value (input & 255) at
the points in front of both cameras, 0 elsewhere; for a mask created here 255 at those points. The
result is copied into the caller's array as N x 1 CV_8U (a 1 x N mask is reallocated, as there). */
void writePoseMask(InputOutputArray mask, const std::vector<uchar>& maskIn,
                   const std::vector<uchar>& inFront)
{
    if (!mask.needed()) return;
    const int n = static_cast<int>(inFront.size());
    std::vector<uchar> values(static_cast<size_t>(n), 0);
    for (size_t i = 0; i < values.size(); ++i)
        if (inFront[i]) values[i] = maskIn.empty() ? uchar(255) : maskIn[i];
    if (mask.empty()) mask.create(n, 1, CV_8U);
    Mat(n, 1, CV_8U, values.data()).copyTo(mask);
}

void writePose(const pose::PoseResult& result, OutputArray R, OutputArray t)
{
    if (R.needed()) Mat(result.R).copyTo(R);
    if (t.needed()) Mat(result.t).copyTo(t);
}

/** The cheirality test on normalised points. distanceThresh <= 0 means the module's test without a
distance cut; a positive value OpenCV's DLT test with that cut (then triangulatedPoints, if
requested, receives 4 x N homogeneous points). Returns the number of points in front. */
int recoverPoseNormalisedPoints(const Matx33d& E, const Problem& points, OutputArray R,
                                OutputArray t, InputOutputArray mask, double distanceThresh,
                                OutputArray triangulatedPoints)
{
    const int n = points.size();
    const std::vector<uchar> maskIn = readMask(mask, n);
    const uchar* in = maskIn.empty() ? nullptr : maskIn.data();
    std::vector<uchar> inFront(static_cast<size_t>(n), 0);
    pose::PoseResult result;
    bool ok;
    if (distanceThresh > 0) {
        std::vector<Vec4d> X(triangulatedPoints.needed() ? static_cast<size_t>(n) : 0);
        ok = pose::recoverPoseDistanceThresh(E, points, in, distanceThresh, inFront.data(),
                                             X.empty() ? nullptr : X.data(), result);
        if (triangulatedPoints.needed()) {
            if (ok)
                transpose(Mat(n, 4, CV_64F, X.data()), triangulatedPoints);
            else
                triangulatedPoints.release();
        }
    } else {
        ok = pose::recoverPoseNormalised(E, points, in, inFront.data(), result);
    }
    // E cannot be decomposed (the zero matrix): no pose (R = I, t = 0), no point in front.
    if (!ok) result = pose::PoseResult();
    writePose(result, R, t);
    writePoseMask(mask, maskIn, inFront);
    return ok ? result.inFront : 0;
}

int recoverPoseFromEssential(InputArray E, InputArray points1, InputArray points2, const Matx33d& K,
                             OutputArray R, OutputArray t, InputOutputArray mask,
                             double distanceThresh, OutputArray triangulatedPoints)
{
    const Matx33d Em = readEssential(E);
    Mat rows1, rows2;
    readPointRows(points1, points2, PointReading::Classic, rows1, rows2);
    return recoverPoseNormalisedPoints(Em, normalisedProblem(rows1, rows2, K, 1), R, t, mask,
                                       distanceThresh, triangulatedPoints);
}

} // namespace

int recoverPoseIter(InputArray E, InputArray points1, InputArray points2, InputArray cameraMatrix,
                    OutputArray R, OutputArray t, InputOutputArray mask)
{
    const Matx33d K = readCameraMatrix(cameraMatrix, "cameraMatrix");
    return recoverPoseFromEssential(E, points1, points2, K, R, t, mask, 0.0, noArray());
}

int recoverPoseIter(InputArray E, InputArray points1, InputArray points2, OutputArray R,
                    OutputArray t, double focal, Point2d pp, InputOutputArray mask)
{
    return recoverPoseFromEssential(E, points1, points2, cameraFromFocal(focal, pp), R, t, mask,
                                    0.0, noArray());
}

int recoverPoseIter(InputArray E, InputArray points1, InputArray points2, InputArray cameraMatrix,
                    OutputArray R, OutputArray t, double distanceThresh, InputOutputArray mask,
                    OutputArray triangulatedPoints)
{
    if (!(distanceThresh > 0))
        badArg("distanceThresh must be positive (+inf: no distance cut), got " +
               std::to_string(distanceThresh));
    const Matx33d K = readCameraMatrix(cameraMatrix, "cameraMatrix");
    return recoverPoseFromEssential(E, points1, points2, K, R, t, mask, distanceThresh,
                                    triangulatedPoints);
}

int recoverPoseIter(InputArray points1, InputArray points2, InputArray cameraMatrix1,
                    InputArray distCoeffs1, InputArray cameraMatrix2, InputArray distCoeffs2,
                    OutputArray E, OutputArray R, OutputArray t, int method, double prob,
                    double threshold, InputOutputArray mask)
{
    const EssentialParams params = dropInParams(method, prob, threshold, 1000);
    std::vector<Point2d> n1, n2;
    // As OpenCV: E from the undistorted points, its inlier mask written into the caller's mask
    // (as findEssentialMat would for this method), then the pose from the points that mask marks
    // (all points when the caller passes no mask).
    const Mat found = estimateTwoCameras(
        points1, points2, cameraMatrix1, distCoeffs1, cameraMatrix2, distCoeffs2, params,
        PointReading::Undistort, mask, maskWritingForMethod(method), &n1, &n2);
    if (found.empty()) {
        // No essential matrix: no pose, and the mask stays all zero.
        if (E.needed()) E.release();
        writePose(pose::PoseResult(), R, t);
        return 0;
    }
    const Problem points = makeProblem(n1, n2);
    // Exactly five points may give several solutions (stacked): keep the one with the most
    // points in front of both cameras (the first on ties).
    Matx33d best;
    int bestInFront = -1;
    for (int s = 0; s + 3 <= found.rows; s += 3) {
        Matx33d candidate;
        found.rowRange(s, s + 3).copyTo(Mat(3, 3, CV_64F, candidate.val));
        pose::PoseResult result;
        if (pose::recoverPoseNormalised(candidate, points, nullptr, nullptr, result) &&
            result.inFront > bestInFront) {
            best = candidate;
            bestInFront = result.inFront;
        }
    }
    if (bestInFront < 0) found.rowRange(0, 3).copyTo(Mat(3, 3, CV_64F, best.val));
    if (E.needed()) Mat(best).copyTo(E);
    return recoverPoseNormalisedPoints(best, points, R, t, mask, 0.0, noArray());
}

// The original spellings, kept for existing callers: the same functions under cv::recoverPose's
// name (callable qualified; unqualified they collide with cv::recoverPose, see essential.hpp).

int recoverPose(InputArray E, InputArray points1, InputArray points2, InputArray cameraMatrix,
                OutputArray R, OutputArray t, InputOutputArray mask)
{
    return recoverPoseIter(E, points1, points2, cameraMatrix, R, t, mask);
}

int recoverPose(InputArray E, InputArray points1, InputArray points2, OutputArray R, OutputArray t,
                double focal, Point2d pp, InputOutputArray mask)
{
    return recoverPoseIter(E, points1, points2, R, t, focal, pp, mask);
}

int recoverPose(InputArray E, InputArray points1, InputArray points2, InputArray cameraMatrix,
                OutputArray R, OutputArray t, double distanceThresh, InputOutputArray mask,
                OutputArray triangulatedPoints)
{
    return recoverPoseIter(E, points1, points2, cameraMatrix, R, t, distanceThresh, mask,
                           triangulatedPoints);
}

int recoverPose(InputArray points1, InputArray points2, InputArray cameraMatrix1,
                InputArray distCoeffs1, InputArray cameraMatrix2, InputArray distCoeffs2,
                OutputArray E, OutputArray R, OutputArray t, int method, double prob,
                double threshold, InputOutputArray mask)
{
    return recoverPoseIter(points1, points2, cameraMatrix1, distCoeffs1, cameraMatrix2, distCoeffs2,
                           E, R, t, method, prob, threshold, mask);
}

} // namespace essential
} // namespace cv
