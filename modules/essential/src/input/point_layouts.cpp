// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "input/point_layouts.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/core/check.hpp>

#include <cmath>
#include <string>

namespace cv {
namespace essential {

namespace {

[[noreturn]] void badArg(const std::string& message)
{
    CV_Error(Error::StsBadArg, message);
}

std::string describe(const Mat& m, bool isVector = false)
{
    if (isVector)
        return "a std::vector of " + std::to_string(m.total()) + " " + typeToString(m.type()) +
               " elements";
    if (m.dims > 2) return "a " + std::to_string(m.dims) + "-dimensional array";
    return "a " + std::to_string(m.rows) + " x " + std::to_string(m.cols) + " " +
           typeToString(m.type()) + " array" +
           (m.isContinuous() ? "" : " (a view, not continuous in memory)");
}

/** What each reading accepts, for the error messages. */
const char* acceptedLayouts(PointReading how)
{
    switch (how) {
    case PointReading::Classic:
        return "with RANSAC or LMEDS (and in recoverPose from E) points must be a vector of 2D "
               "points, an N x 2 one-channel matrix or an N x 1 / 1 x N two-channel matrix, as "
               "for cv::findEssentialMat; 2 x N and N x 3 arrays are read with the USAC flags only";
    case PointReading::Usac:
        return "with the USAC flags points must be an array of N >= 2-coordinate points, one per "
               "row (N x k, k >= 2, or N x 1 with k channels) or one per column (k x N), as for "
               "cv::findEssentialMat";
    case PointReading::Undistort:
    case PointReading::UndistortCopy:
        return "the forms with distortion coefficients undistort the points first and, as "
               "cv::undistortPoints, need a CV_32F or CV_64F vector of 2D points, N x 2 or 2 x N "
               "one-channel or N x 1 / 1 x N two-channel matrix, continuous in memory";
    }
    return "";
}

[[noreturn]] void badLayout(const char* name, const Mat& m, bool isVector, PointReading how)
{
    badArg(std::string(name) + " is " + describe(m, isVector) + ": " + acceptedLayouts(how));
}

/** The points of `m` as an N x k one-channel double matrix whose first two columns are x and y
(k = 2 for Classic and Undistort). */
Mat readAsRows(const Mat& m, bool isVector, const char* name, PointReading how)
{
    if (m.dims > 2) badLayout(name, m, isVector, how);
    switch (how) {
    case PointReading::Classic: {
        // OpenCV converts to double first (any depth, views copied), then asks for 2D points.
        const int n = m.checkVector(2, -1, /*requireContinuous*/ false);
        if (n < 0) badLayout(name, m, isVector, how);
        // Doubles in one block are read where they are (nothing writes to the rows).
        if (m.depth() == CV_64F && m.isContinuous()) return m.reshape(1, n);
        Mat converted;
        m.convertTo(converted, CV_64F);
        return converted.reshape(1, n);
    }
    case PointReading::Usac: {
        // OpenCV converts to float in place: a float view stays a view, and a view of several
        // columns of a multi-channel array cannot then be flattened to one point per element.
        if (m.channels() > 1 && m.depth() == CV_32F && !m.isContinuous() &&
            static_cast<size_t>(m.rows) != m.total())
            badArg(std::string(name) + " is " + describe(m, isVector) +
                   ": as for cv::findEssentialMat with the USAC flags, a multi-channel view of "
                   "several columns must be copied first");
        Mat converted;
        m.convertTo(converted, CV_64F);
        // A vector of 2D points or an N x 2 matrix is taken as it is, so that too few points (one
        // point would otherwise be transposed into a 2 x 1 array of no point) are reported as such.
        const int n = m.checkVector(2, -1, /*requireContinuous*/ false);
        if (n >= 0) return converted.reshape(1, n);
        if (converted.channels() > 1)
            converted = converted.reshape(1, static_cast<int>(converted.total()));
        if (converted.rows < converted.cols) converted = converted.t();
        if (converted.cols < 2) badLayout(name, m, isVector, how);
        return converted;
    }
    case PointReading::Undistort:
    case PointReading::UndistortCopy: {
        if (m.depth() != CV_32F && m.depth() != CV_64F) badLayout(name, m, isVector, how);
        Mat src = (how == PointReading::UndistortCopy && !m.isContinuous()) ? m.clone() : m;
        int n = src.checkVector(2); // continuous only
        if (n < 0) {
            src = src.t(); // a continuous copy
            n = src.checkVector(2);
        }
        if (n < 0) badLayout(name, m, isVector, how);
        Mat converted;
        src.convertTo(converted, CV_64F);
        return converted.reshape(1, n);
    }
    }
    badLayout(name, m, isVector, how);
}

} // namespace

std::vector<Point2d> pointsFromRows(const Mat& rows, const char* name)
{
    std::vector<Point2d> out(static_cast<size_t>(rows.rows));
    for (int i = 0; i < rows.rows; ++i) {
        const double* r = rows.ptr<double>(i);
        if (!std::isfinite(r[0]) || !std::isfinite(r[1]))
            badArg(std::string(name) + " has a non-finite coordinate at index " +
                   std::to_string(i));
        out[static_cast<size_t>(i)] = Point2d(r[0], r[1]);
    }
    return out;
}

void readPointRows(InputArray points1, InputArray points2, PointReading how, Mat& rows1, Mat& rows2)
{
    if (points1.empty()) badArg("points1 is empty: at least 5 points are needed");
    if (points2.empty()) badArg("points2 is empty: at least 5 points are needed");
    const Mat m1 = points1.getMat(), m2 = points2.getMat();
    const bool vector1 = points1.kind() == _InputArray::STD_VECTOR;
    const bool vector2 = points2.kind() == _InputArray::STD_VECTOR;
    rows1 = readAsRows(m1, vector1, "points1", how);
    rows2 = readAsRows(m2, vector2, "points2", how);
    if (rows1.rows != rows2.rows)
        badArg("points1 and points2 differ in size (" + std::to_string(rows1.rows) + " vs " +
               std::to_string(rows2.rows) + " points)");
    if (how == PointReading::Classic && m1.channels() != m2.channels())
        badArg("points1 (" + describe(m1, vector1) + ") and points2 (" + describe(m2, vector2) +
               ") must have the same number of channels with RANSAC or LMEDS (and in recoverPose "
               "from E), as for cv::findEssentialMat: pass both as vectors of points or both as "
               "N x 2 matrices");
}

void readPointPair(InputArray points1, InputArray points2, PointReading how,
                   std::vector<Point2d>& out1, std::vector<Point2d>& out2)
{
    Mat rows1, rows2;
    readPointRows(points1, points2, how, rows1, rows2);
    out1 = pointsFromRows(rows1, "points1");
    out2 = pointsFromRows(rows2, "points2");
}

PointReading readingForMethod(int method)
{
    return method >= USAC_DEFAULT && method <= USAC_MAGSAC ? PointReading::Usac
                                                           : PointReading::Classic;
}

} // namespace essential
} // namespace cv
