// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "input/problem.hpp"

#include "input/point_layouts.hpp"
#include "simd_dispatch.hpp"

#include <opencv2/calib3d.hpp>

#include <cmath>
#include <string>

namespace cv {
namespace essential {

namespace {

[[noreturn]] void badArg(const std::string& message)
{
    CV_Error(Error::StsBadArg, message);
}

} // namespace

void checkPointSets(const std::vector<Point2d>& p1, const std::vector<Point2d>& p2, int minPoints)
{
    if (p1.size() != p2.size())
        badArg("points1 and points2 differ in size (" + std::to_string(p1.size()) + " vs " +
               std::to_string(p2.size()) + ")");
    if (static_cast<int>(p1.size()) < minPoints)
        badArg("at least " + std::to_string(minPoints) + " point correspondences are needed (got " +
               std::to_string(p1.size()) + ")");
}

Matx33d readCameraMatrix(InputArray cameraMatrix, const char* name)
{
    const std::string arg(name);
    if (cameraMatrix.empty()) badArg(arg + " is empty: a 3 x 3 camera matrix is needed");
    Mat m = cameraMatrix.getMat();
    if (m.rows != 3 || m.cols != 3 || m.channels() != 1)
        badArg(arg + " must be a 3 x 3 one-channel matrix (got " + std::to_string(m.rows) + " x " +
               std::to_string(m.cols) + " with " + std::to_string(m.channels()) + " channels)");
    // Any integer or floating depth, as cv::findEssentialMat converts it (CV_16F aside).
    if (m.depth() == CV_16F) badArg(arg + " must not be CV_16F");
    Matx33d K;
    Mat(m).convertTo(Mat(3, 3, CV_64F, K.val), CV_64F);
    for (int i = 0; i < 9; ++i)
        if (!std::isfinite(K.val[i])) badArg(arg + " has a non-finite entry");
    // A negative focal length mirrors the image: cv::findEssentialMat accepts it silently, but
    // then the cheirality test and the pixel threshold mean something else; reject it.
    if (!(K(0, 0) > 0.0) || !(K(1, 1) > 0.0))
        badArg(arg + " must have positive focal lengths (got fx = " + std::to_string(K(0, 0)) +
               ", fy = " + std::to_string(K(1, 1)) + ")");
    if (std::abs(K(2, 0)) > 1e-9 || std::abs(K(2, 1)) > 1e-9 || std::abs(K(2, 2) - 1.0) > 1e-9)
        badArg(arg + " must have a last row of 0 0 1");
    const double det = determinant(K);
    if (!(std::abs(det) > 1e-12 * std::abs(K(0, 0) * K(1, 1)))) badArg(arg + " is singular");
    return K;
}

Matx33d cameraFromFocal(double focal, Point2d pp)
{
    if (!std::isfinite(focal) || !(focal > 0.0))
        badArg("focal must be finite and positive, got " + std::to_string(focal));
    if (!std::isfinite(pp.x) || !std::isfinite(pp.y)) badArg("pp must be finite");
    return Matx33d(focal, 0, pp.x, 0, focal, pp.y, 0, 0, 1);
}

namespace {

/** K^-1 for an upper-triangular K with K(2,2) = 1: y = (v - cy) / fy, x = (u - cx - s y) / fx. The
one formula of normalisePoints and normalisedProblem's pass, so both give the same values. */
struct Normalisation
{
    double fx, fy, s, cx, cy;

    explicit Normalisation(const Matx33d& K)
        : fx(K(0, 0)), fy(K(1, 1)), s(K(0, 1)), cx(K(0, 2)), cy(K(1, 2))
    {
    }

    /** Writes the normalised point; returns 1 if a coordinate is not finite or beyond
    kMaxNormalised (as every non-finite pixel coordinate makes one: fx and fy are finite and
    positive), else 0. */
    int apply(double u, double v, double& x, double& y) const
    {
        y = (v - cy) / fy;
        x = (u - cx - s * y) / fx;
        return !(std::abs(x) <= kMaxNormalised) | !(std::abs(y) <= kMaxNormalised);
    }
};

} // namespace

std::vector<Point2d> normalisePoints(const std::vector<Point2d>& pixels, const Matx33d& K)
{
    const Normalisation k(K);
    std::vector<Point2d> out(pixels.size());
    for (size_t i = 0; i < pixels.size(); ++i)
        k.apply(pixels[i].x, pixels[i].y, out[i].x, out[i].y);
    return out;
}

void checkNormalisedPoints(const std::vector<Point2d>& normalised, const char* name)
{
    for (size_t i = 0; i < normalised.size(); ++i) {
        const Point2d& p = normalised[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !(std::abs(p.x) <= kMaxNormalised) ||
            !(std::abs(p.y) <= kMaxNormalised))
            badArg(std::string(name) + " at index " + std::to_string(i) +
                   " is more than 1e8 focal lengths from the principal point (or not finite) "
                   "once normalised by the camera matrix: no camera sees such a point");
    }
}

namespace {

/** normalisedProblem's pass over one array: `n` rows of `stride` doubles (x, y first) into x / y;
returns how many points are out of range. Counted, not branched on, so that the loop has no early
exit; the common stride of 2 (N x 2 rows) gets a loop of its own, which the compiler vectorises. */
ESSENTIAL_SIMD_CLONES int normaliseRows(const Normalisation& k, const double* r, size_t stride,
                                        int n, double* x, double* y)
{
    int outside = 0;
    if (stride == 2) {
        for (int i = 0; i < n; ++i)
            outside += k.apply(r[2 * i], r[2 * i + 1], x[i], y[i]);
    } else {
        for (int i = 0; i < n; ++i, r += stride)
            outside += k.apply(r[0], r[1], x[i], y[i]);
    }
    return outside;
}

bool normaliseRows(const Mat& rows, const Matx33d& K, double* x, double* y)
{
    if (rows.rows == 0) return true;
    const Normalisation k(K);
    return normaliseRows(k, rows.ptr<double>(0), rows.step1(), rows.rows, x, y) == 0;
}

} // namespace

Problem normalisedProblem(const Mat& rows1, const Mat& rows2, const Matx33d& K, int minPoints)
{
    CV_Assert(rows1.rows == rows2.rows && rows1.type() == CV_64FC1 && rows2.type() == CV_64FC1 &&
              rows1.cols >= 2 && rows2.cols >= 2);
    Problem p;
    const size_t n = static_cast<size_t>(rows1.rows);
    p.x1.resize(n);
    p.y1.resize(n);
    p.x2.resize(n);
    p.y2.resize(n);
    if (rows1.rows >= minPoints && normaliseRows(rows1, K, p.x1.data(), p.y1.data()) &&
        normaliseRows(rows2, K, p.x2.data(), p.y2.data()))
        return p;
    // A check fails: the step-by-step path throws its exception. (Both paths normalise with
    // Normalisation::apply; should a compiler still round one inlined copy differently at the
    // kMaxNormalised bound, this path returns the Problem it checked.)
    const std::vector<Point2d> p1 = pointsFromRows(rows1, "points1");
    const std::vector<Point2d> p2 = pointsFromRows(rows2, "points2");
    checkPointSets(p1, p2, minPoints);
    const std::vector<Point2d> n1 = normalisePoints(p1, K), n2 = normalisePoints(p2, K);
    checkNormalisedPoints(n1, "points1");
    checkNormalisedPoints(n2, "points2");
    return makeProblem(n1, n2);
}

double normalisedThreshold(double threshold, double meanFocal)
{
    const double t = threshold / meanFocal;
    if (!(t > 0.0) || !std::isfinite(t))
        badArg("threshold / focal length is not a positive finite number (threshold " +
               std::to_string(threshold) + ", focal " + std::to_string(meanFocal) + ")");
    return t;
}

Problem makeProblem(const std::vector<Point2d>& n1, const std::vector<Point2d>& n2)
{
    CV_Assert(n1.size() == n2.size());
    Problem p;
    const size_t n = n1.size();
    p.x1.resize(n);
    p.y1.resize(n);
    p.x2.resize(n);
    p.y2.resize(n);
    for (size_t i = 0; i < n; ++i) {
        p.x1[i] = n1[i].x;
        p.y1[i] = n1[i].y;
        p.x2[i] = n2[i].x;
        p.y2[i] = n2[i].y;
    }
    return p;
}

void gatherProblem(const Problem& problem, const int* indices, int count, Problem& out)
{
    const size_t n = static_cast<size_t>(count);
    out.x1.resize(n);
    out.y1.resize(n);
    out.x2.resize(n);
    out.y2.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const size_t k = static_cast<size_t>(indices[i]);
        out.x1[i] = problem.x1[k];
        out.y1[i] = problem.y1[k];
        out.x2[i] = problem.x2[k];
        out.y2[i] = problem.y2[k];
    }
}

Problem subsetProblem(const Problem& problem, const int* indices, int count)
{
    Problem p;
    gatherProblem(problem, indices, count, p);
    return p;
}

Problem maskedProblem(const Problem& problem, const uchar* mask)
{
    // Every index is written, the count advanced only for a marked point: no branch per point.
    std::vector<int, UninitialisedAllocator<int>> indices(static_cast<size_t>(problem.size()));
    int count = 0;
    for (int i = 0; i < problem.size(); ++i) {
        indices[static_cast<size_t>(count)] = i;
        count += mask[i] != 0;
    }
    return subsetProblem(problem, indices.data(), count);
}

void toPoint2d(const Problem& problem, std::vector<Point2d>& p1, std::vector<Point2d>& p2)
{
    const int n = problem.size();
    p1.resize(static_cast<size_t>(n));
    p2.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        p1[static_cast<size_t>(i)] = problem.point1(i);
        p2[static_cast<size_t>(i)] = problem.point2(i);
    }
}

void checkConfidence(double prob)
{
    if (!(prob > 0.0 && prob < 1.0))
        badArg("prob (confidence) must be in (0, 1), got " + std::to_string(prob));
}

void checkThreshold(double threshold)
{
    if (!(threshold > 0.0) || !std::isfinite(threshold))
        badArg("threshold must be positive and finite, got " + std::to_string(threshold));
}

void checkMaxIters(int maxIters, const char* name)
{
    if (maxIters <= 0)
        badArg(std::string(name) + " must be positive, got " + std::to_string(maxIters));
}

void checkMethod(int method)
{
    const bool usac = method >= USAC_DEFAULT && method <= USAC_MAGSAC;
    if (method != RANSAC && method != LMEDS && !usac)
        badArg("method " + std::to_string(method) +
               " is not supported: use RANSAC, LMEDS or a USAC_* flag");
}

} // namespace essential
} // namespace cv
