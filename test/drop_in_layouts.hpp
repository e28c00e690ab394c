// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Point arrays in every layout cv::findEssentialMat (OpenCV 4.6) reads in one of its code paths,
// and some that no path reads: shared by test/test_drop_in_layouts.cpp, which compares the module
// with OpenCV on each, and bench/drop_in_table.cpp, which prints the accept/reject table.

#ifndef OPENCV_ESSENTIAL_TEST_DROP_IN_LAYOUTS_HPP
#define OPENCV_ESSENTIAL_TEST_DROP_IN_LAYOUTS_HPP

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include <vector>

namespace essential_test {

/** Holds one point array in a layout; `arr()` refers to it. */
struct PointArray
{
    std::vector<cv::Point2f> v2f;
    std::vector<cv::Point2d> v2d;
    std::vector<cv::Point> v2i;
    std::vector<cv::Point3d> v3d;
    cv::Mat m;
    enum Kind { Mat, V2f, V2d, V2i, V3d } kind = Mat;

    cv::_InputArray arr() const
    {
        switch (kind) {
        case V2f:
            return cv::_InputArray(v2f);
        case V2d:
            return cv::_InputArray(v2d);
        case V2i:
            return cv::_InputArray(v2i);
        case V3d:
            return cv::_InputArray(v3d);
        case Mat:
            break;
        }
        return cv::_InputArray(m);
    }
};

struct Layout
{
    const char* name;
    PointArray (*make)(const std::vector<cv::Point2d>& pts);
};

/** N x 2 CV_64F copy of the points. */
inline cv::Mat nx2(const std::vector<cv::Point2d>& pts)
{
    return cv::Mat(pts, true).reshape(1, static_cast<int>(pts.size()));
}

/** N x 3 CV_64F homogeneous copy (w = 1). */
inline cv::Mat nx3(const std::vector<cv::Point2d>& pts)
{
    cv::Mat h;
    cv::convertPointsToHomogeneous(cv::Mat(pts), h);
    return h.reshape(1, static_cast<int>(pts.size())).clone();
}

inline PointArray asMat(const cv::Mat& m)
{
    PointArray a;
    a.m = m;
    return a;
}

inline const Layout kLayouts[] = {
    {"vector<Point2f>",
     [](const std::vector<cv::Point2d>& p) {
         PointArray a;
         a.kind = PointArray::V2f;
         a.v2f.assign(p.begin(), p.end());
         return a;
     }},
    {"vector<Point2d>",
     [](const std::vector<cv::Point2d>& p) {
         PointArray a;
         a.kind = PointArray::V2d;
         a.v2d = p;
         return a;
     }},
    {"vector<Point> (int)",
     [](const std::vector<cv::Point2d>& p) {
         PointArray a;
         a.kind = PointArray::V2i;
         for (const cv::Point2d& q : p)
             a.v2i.emplace_back(cvRound(q.x), cvRound(q.y));
         return a;
     }},
    {"vector<Point3d> (homogeneous)",
     [](const std::vector<cv::Point2d>& p) {
         PointArray a;
         a.kind = PointArray::V3d;
         for (const cv::Point2d& q : p)
             a.v3d.emplace_back(q.x, q.y, 1.0);
         return a;
     }},
    {"N x 2 CV_32F",
     [](const std::vector<cv::Point2d>& p) {
         cv::Mat m;
         nx2(p).convertTo(m, CV_32F);
         return asMat(m);
     }},
    {"N x 2 CV_64F", [](const std::vector<cv::Point2d>& p) { return asMat(nx2(p)); }},
    {"N x 2 CV_32S",
     [](const std::vector<cv::Point2d>& p) {
         cv::Mat m;
         nx2(p).convertTo(m, CV_32S);
         return asMat(m);
     }},
    {"N x 1 CV_32FC2",
     [](const std::vector<cv::Point2d>& p) {
         cv::Mat m;
         cv::Mat(p).convertTo(m, CV_32FC2);
         return asMat(m);
     }},
    {"N x 1 CV_64FC2", [](const std::vector<cv::Point2d>& p) { return asMat(cv::Mat(p, true)); }},
    {"1 x N CV_64FC2",
     [](const std::vector<cv::Point2d>& p) { return asMat(cv::Mat(p, true).reshape(2, 1)); }},
    {"2 x N CV_32F",
     [](const std::vector<cv::Point2d>& p) {
         cv::Mat m;
         cv::Mat(nx2(p).t()).convertTo(m, CV_32F);
         return asMat(m);
     }},
    {"2 x N CV_64F", [](const std::vector<cv::Point2d>& p) { return asMat(nx2(p).t()); }},
    {"N x 3 CV_64F (homogeneous)", [](const std::vector<cv::Point2d>& p) { return asMat(nx3(p)); }},
    {"3 x N CV_64F (homogeneous)",
     [](const std::vector<cv::Point2d>& p) { return asMat(nx3(p).t()); }},
    {"view: colRange(0, 2) of N x 3 CV_64F",
     [](const std::vector<cv::Point2d>& p) { return asMat(nx3(p).colRange(0, 2)); }},
    {"view: colRange(0, 2) of N x 3 CV_32F",
     [](const std::vector<cv::Point2d>& p) {
         cv::Mat f;
         nx3(p).convertTo(f, CV_32F);
         return asMat(f.colRange(0, 2));
     }},
    {"view: 2 x N columns of a 2 x (N + 7) CV_64F",
     [](const std::vector<cv::Point2d>& p) {
         const int n = static_cast<int>(p.size());
         cv::Mat wide(2, n + 7, CV_64F, cv::Scalar(0));
         cv::Mat(nx2(p).t()).copyTo(wide.colRange(0, n));
         return asMat(wide.colRange(0, n));
     }},
    {"view: column 0 of an N x 2 CV_64FC2",
     [](const std::vector<cv::Point2d>& p) {
         cv::Mat wide(static_cast<int>(p.size()), 2, CV_64FC2, cv::Scalar(0, 0));
         cv::Mat(p).copyTo(wide.col(0));
         return asMat(wide.col(0));
     }},
    // No code path of OpenCV reads these.
    {"N x 1 CV_64F (one coordinate)",
     [](const std::vector<cv::Point2d>& p) { return asMat(nx2(p).col(0).clone()); }},
    {"1 x 2N CV_64F (flattened)",
     [](const std::vector<cv::Point2d>& p) { return asMat(nx2(p).reshape(1, 1)); }},
    {"N x 2 x 1 three-dimensional",
     [](const std::vector<cv::Point2d>& p) {
         const int sizes[3] = {static_cast<int>(p.size()), 2, 1};
         cv::Mat m(3, sizes, CV_64F);
         nx2(p).copyTo(cv::Mat(sizes[0], 2, CV_64F, m.data));
         return asMat(m);
     }},
};

/** Number of entries of kLayouts; the last kRejectedLayouts are read by no code path of OpenCV. */
constexpr int kLayoutCount = static_cast<int>(sizeof(kLayouts) / sizeof(kLayouts[0]));
constexpr int kRejectedLayouts = 3;

} // namespace essential_test

#endif
