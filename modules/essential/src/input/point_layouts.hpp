// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The point arrays OpenCV 4.6 accepts. cv::findEssentialMat and cv::recoverPose read their points
// in one of three ways, depending on the overload and the method flag; the drop-in overloads read
// them the same way, so that they accept and reject exactly what OpenCV does (measured by calling
// OpenCV itself: test/test_drop_in_layouts.cpp, test/test_drop_in_recover_pose.cpp).

#ifndef OPENCV_ESSENTIAL_INPUT_POINT_LAYOUTS_HPP
#define OPENCV_ESSENTIAL_INPUT_POINT_LAYOUTS_HPP

#include <opencv2/core.hpp>

#include <vector>

namespace cv {
namespace essential {

/** How a point array is read: the three code paths of OpenCV 4.6. */
enum class PointReading {
    /** RANSAC and LMEDS (camera-matrix and focal forms), and recoverPose from E: any depth
    (converted to double); `std::vector<Point2f|Point2d|Point...>`, an N x 2 one-channel matrix, or
    an N x 1 or 1 x N two-channel matrix, views included; both arrays with the same number of
    channels (a vector of points, which has two, cannot be paired with an N x 2 matrix). */
    Classic,
    /** The USAC flags and the UsacParams form without distortion: any depth; a multi-channel
    array is read as one point per element; a matrix with fewer rows than columns is transposed
    (so 2 x N holds N points); at least two columns, of which the first two are x and y (the rest,
    for example a homogeneous coordinate, is ignored). */
    Usac,
    /** The two-camera form with distortion (and recoverPose's two-camera form), which undistorts
    first: CV_32F or CV_64F only; the Classic shapes or their transposes (2 x N), continuous in
    memory (a view such as `pts.colRange(0, 2)` is rejected; a 2 x N view is transposed into a
    copy and accepted). */
    Undistort,
    /** The UsacParams form with distortion coefficients: as Undistort, on a continuous copy of a
    non-continuous view. */
    UndistortCopy
};

/** Reads two point arrays the way `how` says into N x k one-channel CV_64F matrices (k >= 2, x and
y in the first two columns). Throws cv::Exception (StsBadArg, naming points1 or points2) for an
empty array, a layout or depth `how` does not accept, or two arrays of different sizes (or, for
Classic, different channel counts). Checks neither the coordinates nor the number of points. */
void readPointRows(InputArray points1, InputArray points2, PointReading how, Mat& rows1,
                   Mat& rows2);

/** The first two columns of readPointRows' `rows` as points; throws (naming `name` and the index)
at the first non-finite coordinate. */
std::vector<Point2d> pointsFromRows(const Mat& rows, const char* name);

/** Reads two point arrays the way `how` says into pixel coordinates. Throws cv::Exception
(StsBadArg, naming points1 or points2) for an empty array, a layout or depth `how` does not accept,
two arrays of different sizes (or, for Classic, different channel counts), or a non-finite
coordinate. Does not check the number of points. */
void readPointPair(InputArray points1, InputArray points2, PointReading how,
                   std::vector<Point2d>& out1, std::vector<Point2d>& out2);

/** The reading of the camera-matrix and focal forms for a `method` flag: Usac for the USAC flags,
Classic otherwise. */
PointReading readingForMethod(int method);

} // namespace essential
} // namespace cv

#endif
