// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The arguments the fuzz targets build from a fuzzer's bytes (FuzzInput): points in the layouts
// the API accepts or a wrong one, correspondences with geometry, arbitrary matrices of any shape,
// depth, channel count and continuity, camera matrices, distortion, methods and numbers. Shared
// by the input-layer and engine targets, so that one decoder serves both.

#ifndef OPENCV_ESSENTIAL_FUZZ_BUILDERS_HPP
#define OPENCV_ESSENTIAL_FUZZ_BUILDERS_HPP

#include "fuzz_input.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/essential/params.hpp>

#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

namespace essential_fuzz {

/** Correspondences with geometry, so that the fuzzer reaches the paths after a successful search
(refinement, pose, the degeneracy measures): points in front of camera 1 (camera 500, 320, 240)
moved by a fuzzed rotation and translation (zero allowed), projected, then a few coordinates
overwritten by fuzzed values. */
inline void makeScenePoints(FuzzInput& in, int n, std::vector<cv::Point2d>& a,
                            std::vector<cv::Point2d>& b)
{
    const cv::Vec3d rvec(in.unit() - 0.5, in.unit() - 0.5, in.unit() - 0.5);
    cv::Matx33d R;
    cv::Rodrigues(rvec, R);
    const double scale = in.pick(4) == 0 ? 0.0 : in.unit();
    const cv::Vec3d t = scale * cv::Vec3d(in.unit() - 0.5, in.unit() - 0.5, in.unit() - 0.5);
    const bool planar = in.pick(4) == 0;
    a.resize(static_cast<size_t>(n));
    b.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double u = 2.0 * in.unit() - 1.0, v = 2.0 * in.unit() - 1.0;
        const double depth = planar ? 4.0 : 1.0 + 20.0 * in.unit();
        const cv::Vec3d X(u * depth, v * depth, depth);
        const cv::Vec3d Y = R * X + t;
        a[static_cast<size_t>(i)] = cv::Point2d(500 * u + 320, 500 * v + 240);
        const double z = std::abs(Y[2]) > 1e-6 ? Y[2] : 1e-6;
        b[static_cast<size_t>(i)] = cv::Point2d(500 * Y[0] / z + 320, 500 * Y[1] / z + 240);
    }
    for (int k = in.pick(4); k > 0 && n > 0; --k) {
        std::vector<cv::Point2d>& side = in.pick(2) ? a : b;
        cv::Point2d& p = side[static_cast<size_t>(in.pick(n))];
        (in.pick(2) ? p.x : p.y) = in.anyDouble();
    }
}

/** Points in one of the layouts the API accepts (or a wrong one): vector<Point2d>, vector<Point2f>,
N x 2 one-channel, N x 1 two-channel, 1 x N two-channel, or another depth. `given` holds the
coordinates, or is empty for coordinates read from the input. */
inline cv::Mat makePoints(FuzzInput& in, int n, std::vector<cv::Point2d> given = {})
{
    // Mostly valid layouts, so that most inputs get past the input checks.
    static const int layouts[] = {0, 1, 2, 3, 7, 0, 1, 2, 3, 7, 0, 2, 4, 5, 6, 7};
    const int layout = layouts[in.pick(16)];
    std::vector<cv::Point2d> pts = std::move(given);
    if (pts.empty()) {
        pts.resize(static_cast<size_t>(n));
        for (cv::Point2d& p : pts) {
            p.x = in.coordinate();
            p.y = in.coordinate();
        }
    }
    n = static_cast<int>(pts.size());
    cv::Mat m(pts, true); // N x 1 CV_64FC2
    switch (layout) {
    case 0:
        return m;
    case 1: {
        cv::Mat f;
        m.convertTo(f, CV_32FC2);
        return f;
    }
    case 2:
        return m.reshape(1, n); // N x 2 one-channel
    case 3:
        return m.reshape(2, 1); // 1 x N two-channel
    case 4: {
        cv::Mat i;
        m.convertTo(i, CV_32SC2); // wrong depth
        return i;
    }
    case 5:
        return cv::Mat(n, 3, CV_64F, cv::Scalar(in.coordinate())); // wrong shape
    case 6:
        return cv::Mat(); // empty
    default: {
        cv::Mat f;
        m.reshape(1, n).convertTo(f, CV_32F);
        return f;
    }
    }
}

/** A camera matrix: mostly a plausible one with fuzzed entries, sometimes any 3 x 3 or a wrong
shape. */
inline cv::Mat makeCamera(FuzzInput& in)
{
    switch (in.pick(12)) {
    case 0: {
        cv::Mat k(3, 3, CV_64F);
        for (int i = 0; i < 9; ++i)
            k.at<double>(i / 3, i % 3) = in.anyDouble();
        return k;
    }
    case 1:
        return cv::Mat::eye(in.pick(5), in.pick(5), CV_64F);
    case 2: {
        cv::Mat k = cv::Mat(cv::Matx<float, 3, 3>(500, 0, 320, 0, 500, 240, 0, 0, 1));
        k.at<float>(in.pick(3), in.pick(3)) = static_cast<float>(in.anyDouble());
        return k;
    }
    default: {
        const double f = in.pick(8) == 0 ? in.anyDouble() : 100.0 + in.pick(1000);
        const double fy = in.pick(8) == 0 ? -f : f;
        const double skew = in.pick(8) == 0 ? in.anyDouble() : 0.0;
        // Drawn in this order (a constructor's arguments have none), as the seeds expect.
        const double cx = in.pick(640), cy = in.pick(480);
        return cv::Mat(cv::Matx<double, 3, 3>(f, skew, cx, 0, fy, cy, 0, 0, 1));
    }
    }
}

inline cv::Mat makeDistortion(FuzzInput& in)
{
    static const int lengths[] = {0, 0, 0, 4, 5, 8, 12, 14, 3, 6};
    const int len = lengths[in.pick(10)];
    if (len == 0) return cv::Mat();
    cv::Mat d(1, len, CV_64F);
    for (int i = 0; i < len; ++i)
        d.at<double>(i) = in.pick(3) == 0 ? in.anyDouble() : 0.01 * (in.pick(21) - 10.0);
    return d;
}

inline int makeMethod(FuzzInput& in)
{
    static const int methods[] = {cv::RANSAC,
                                  cv::LMEDS,
                                  cv::USAC_DEFAULT,
                                  cv::USAC_PARALLEL,
                                  cv::USAC_FM_8PTS,
                                  cv::USAC_FAST,
                                  cv::USAC_ACCURATE,
                                  cv::USAC_PROSAC,
                                  cv::USAC_MAGSAC,
                                  -1,
                                  12345,
                                  1};
    return in.pick(8) == 0 ? methods[in.pick(12)] : methods[in.pick(9)];
}

/** Stores any int in an enum field, values outside the enumeration included (a caller can make
those by a cast, and the library must reject them). The bytes are copied: converting an out-of-range
value to the enum type is undefined behaviour, which UBSan would report in the harness itself. */
template <typename Enum> void setEnumBits(Enum& field, int value)
{
    static_assert(sizeof(Enum) == sizeof(int), "int-sized enums only");
    std::memcpy(&field, &value, sizeof value);
}

/** EssentialParams::score: the two the module implements, often; the two it refuses
(SCORE_METHOD_RANSAC, SCORE_METHOD_MAGSAC) and values outside ScoreMethod, sometimes. */
inline void setScore(FuzzInput& in, cv::essential::EssentialParams& params, int rareOdds)
{
    static const int scores[] = {cv::SCORE_METHOD_MSAC,
                                 cv::SCORE_METHOD_LMEDS,
                                 cv::SCORE_METHOD_RANSAC,
                                 cv::SCORE_METHOD_MAGSAC,
                                 -1,
                                 17};
    setEnumBits(params.score, in.pick(rareOdds) == 0 ? scores[in.pick(6)] : scores[in.pick(2)]);
}

inline double makeProb(FuzzInput& in)
{
    return in.pick(8) == 0 ? in.anyDouble() : 0.5 + 0.499 * in.unit();
}

inline double makeThreshold(FuzzInput& in)
{
    return in.pick(8) == 0 ? in.anyDouble() : 0.1 + 5.0 * in.unit();
}

/** Iteration caps stay small: a cap of 1e9 on data without geometry is a legitimate long run (the
bad-input tests check large caps), not something a fuzzer should wait for. `cap` bounds the usual
values (the input-layer target keeps it at a few samples so that the checks dominate). */
inline int makeMaxIters(FuzzInput& in, int cap = 200)
{
    return in.pick(8) - 2 + (in.pick(2) ? 0 : in.pick(cap));
}

/** Any matrix: 2-D of 0 to `maxSide` rows and columns or n-D, any depth (CV_16F included) and 1 to
4 channels, sometimes a non-continuous view into a larger one, values of any kind (specials, raw
bits, pixel coordinates). Arguments of every kind reach the input checks this way. */
inline cv::Mat anyMat(FuzzInput& in, int maxSide = 8)
{
    static const int depths[] = {CV_8U, CV_8S, CV_16U, CV_16S, CV_32S, CV_32F, CV_64F, CV_16F};
    const int depth = depths[in.pick(8)];
    const int channels = 1 + in.pick(4);
    cv::Mat m;
    if (in.pick(16) == 0) {
        const int sizes[] = {1 + in.pick(3), 1 + in.pick(3), 1 + in.pick(3)};
        m.create(3, sizes, CV_MAKETYPE(depth, channels));
    } else {
        const int rows = in.pick(maxSide + 1), cols = in.pick(maxSide + 1);
        if (in.pick(4) == 0 && rows > 0 && cols > 0) {
            // A view that skips a column: not continuous.
            cv::Mat big(rows, cols + 1, CV_MAKETYPE(depth, channels));
            m = big.colRange(0, cols);
        } else {
            m.create(rows, cols, CV_MAKETYPE(depth, channels));
        }
    }
    if (m.empty()) return m;
    cv::Mat f64(m.dims, m.size.p, CV_MAKETYPE(CV_64F, channels));
    for (size_t i = 0; i < f64.total() * static_cast<size_t>(channels); ++i)
        reinterpret_cast<double*>(f64.data)[i] = in.pick(4) == 0 ? in.anyDouble() : in.coordinate();
    if (m.dims > 2 || m.isContinuous()) {
        f64.convertTo(m, m.type());
    } else {
        cv::Mat converted;
        f64.convertTo(converted, m.type());
        converted.copyTo(m); // into the view: it stays non-continuous
    }
    return m;
}

} // namespace essential_fuzz

#endif // OPENCV_ESSENTIAL_FUZZ_BUILDERS_HPP
