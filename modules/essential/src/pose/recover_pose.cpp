// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The public recoverPose overloads: cv::recoverPose's arguments, outputs and mask semantics, on
// top of the cheirality test of pose_recovery.cpp (which has no far-point cut).

#include "opencv2/essential.hpp"

#include "pose/pose_recovery.hpp"
#include "problem.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace cv {
namespace essential {

namespace {

Matx33d readEssential(InputArray E)
{
    if (E.empty()) CV_Error(Error::StsBadArg, "E is empty: a 3 x 3 essential matrix is needed");
    Mat m = E.getMat();
    if (m.rows != 3 || m.cols != 3 || m.channels() != 1)
        CV_Error(Error::StsBadArg, "E must be a 3 x 3 one-channel matrix (got " +
                                       std::to_string(m.rows) + " x " + std::to_string(m.cols) +
                                       " with " + std::to_string(m.channels()) + " channels)");
    if (m.depth() != CV_32F && m.depth() != CV_64F)
        CV_Error(Error::StsBadArg, "E must be CV_32F or CV_64F");
    Matx33d out;
    m.convertTo(Mat(3, 3, CV_64F, out.val), CV_64F);
    for (int i = 0; i < 9; ++i)
        if (!std::isfinite(out.val[i])) CV_Error(Error::StsBadArg, "E has a non-finite entry");
    return out;
}

/** The input mask, if any, as one byte per point (non-zero = take part); empty if none. */
std::vector<uchar> readMask(InputOutputArray mask, int n)
{
    std::vector<uchar> values;
    if (mask.empty()) return values;
    Mat m = mask.getMat();
    if (m.type() != CV_8UC1) CV_Error(Error::StsBadArg, "mask must be a CV_8U one-channel vector");
    if (m.checkVector(1) != n)
        CV_Error(Error::StsBadArg, "mask must have one entry per point (" + std::to_string(n) +
                                       "), got " + std::to_string(m.rows) + " x " +
                                       std::to_string(m.cols));
    values.resize(static_cast<size_t>(n));
    Mat src = m.isContinuous() ? m : m.clone();
    const uchar* p = src.ptr<uchar>();
    std::copy(p, p + n, values.begin());
    return values;
}

int recoverPoseWithCamera(InputArray E, InputArray points1, InputArray points2, const Matx33d& K,
                          OutputArray R, OutputArray t, InputOutputArray mask)
{
    const Matx33d Em = readEssential(E);
    const std::vector<Point2d> p1 = readPoints(points1, "points1");
    const std::vector<Point2d> p2 = readPoints(points2, "points2");
    checkPointSets(p1, p2, 1);
    const int n = static_cast<int>(p1.size());
    const std::vector<uchar> maskIn = readMask(mask, n);
    const std::vector<Point2d> n1 = normalisePoints(p1, K);
    const std::vector<Point2d> n2 = normalisePoints(p2, K);
    checkNormalisedPoints(n1, "points1");
    checkNormalisedPoints(n2, "points2");

    std::vector<uchar> inFront(static_cast<size_t>(n), 0);
    pose::PoseResult result;
    const bool ok = pose::recoverPoseNormalised(Em, n1.data(), n2.data(), n,
                                                maskIn.empty() ? nullptr : maskIn.data(),
                                                inFront.data(), result);
    if (!ok) {
        // E cannot be decomposed (the zero matrix): no pose, no point in front.
        result = pose::PoseResult();
    }

    if (R.needed()) Mat(result.R).copyTo(R);
    if (t.needed()) Mat(result.t).copyTo(t);
    if (mask.needed()) {
        // As cv::recoverPose: a given mask keeps its own value for the points in front of both
        // cameras (input & 255); a mask created here marks them with 255.
        std::vector<uchar> outValues(static_cast<size_t>(n));
        for (int i = 0; i < n; ++i)
            outValues[static_cast<size_t>(i)] =
                inFront[static_cast<size_t>(i)] ? (maskIn.empty() ? uchar(255) : maskIn[i]) : 0;
        mask.create(n, 1, CV_8U);
        Mat out = mask.getMat();
        for (int i = 0; i < n; ++i)
            out.at<uchar>(i) = outValues[static_cast<size_t>(i)];
    }
    return ok ? result.inFront : 0;
}

} // namespace

int recoverPose(InputArray E, InputArray points1, InputArray points2, InputArray cameraMatrix,
                OutputArray R, OutputArray t, InputOutputArray mask)
{
    const Matx33d K = readCameraMatrix(cameraMatrix, "cameraMatrix");
    return recoverPoseWithCamera(E, points1, points2, K, R, t, mask);
}

int recoverPose(InputArray E, InputArray points1, InputArray points2, OutputArray R, OutputArray t,
                double focal, Point2d pp, InputOutputArray mask)
{
    return recoverPoseWithCamera(E, points1, points2, cameraFromFocal(focal, pp), R, t, mask);
}

} // namespace essential
} // namespace cv
