// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The bad-input table of docs/ROBUSTNESS.md, row by row, through every public overload: the seven
// findEssentialMatIter overloads and the four recoverPose overloads. Each row either raises a
// cv::Exception whose message names the argument, or returns the documented result; never a crash,
// a hang or an uninitialised output. (test_bad_input.cpp has the first checks on the main overload;
// this file extends every row to every overload, and adds the rows it lacked.)

#include "opencv2/essential.hpp"
#include "synthetic_scene.hpp"

#include "essential_test.hpp"

#include <climits>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace ess = cv::essential;
using essential_test::makeScene;
using essential_test::SceneConfig;
using essential_test::SyntheticScene;

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

const SyntheticScene& scene()
{
    static const SyntheticScene s = [] {
        SceneConfig cfg;
        cfg.numPoints = 120;
        cfg.inlierRatio = 0.8;
        return makeScene(cfg, 11);
    }();
    return s;
}

/** The arguments of one call; each overload takes those it has. */
struct Args
{
    cv::Mat p1 = essential_test::pointColumn(scene().px1);
    cv::Mat p2 = essential_test::pointColumn(scene().px2);
    cv::Mat K1 = cv::Mat(scene().K, true);
    cv::Mat K2 = cv::Mat(scene().K, true);
    cv::Mat d1, d2;
    double focal = scene().K(0, 0);
    cv::Point2d pp = cv::Point2d(scene().K(0, 2), scene().K(1, 2));
    int method = cv::RANSAC;
    double prob = 0.999;
    double threshold = 1.0;
    int maxIters = 1000;
    cv::Mat E = cv::Mat(scene().E, true);
};

/** What an overload takes, so that each row runs on the overloads it applies to. */
enum Takes : unsigned {
    kCameraMatrix = 1, // a camera matrix K (K1)
    kSecondCamera = 2, // a second camera matrix K2 and distortion
    kFocal = 4,        // focal and pp instead of a matrix
    kMethod = 8,       // a method flag
    kProb = 16,        // prob / confidence and threshold
    kMaxIters = 32,    // an iteration cap
    kEstimates = 64,   // returns E (findEssentialMatIter); otherwise recoverPose
    kNeedsFivePoints = 128,
    kUndistorts = 256,  // reads points as cv::undistortPoints (CV_32F / CV_64F only)
    kUsacReading = 512, // reads points as OpenCV's USAC (N x k, k x N, first two coordinates)
};

struct Overload
{
    std::string name;
    unsigned takes;
    /** Runs the call; returns E (findEssentialMatIter) or an empty Mat (recoverPose) and fills
    `mask`. */
    std::function<cv::Mat(const Args&, cv::Mat& mask)> call;
};

const std::vector<Overload>& overloads()
{
    static const std::vector<Overload> list = {
        {"findEssentialMatIter(K, method, prob, threshold, maxIters, mask)",
         kCameraMatrix | kMethod | kProb | kMaxIters | kEstimates | kNeedsFivePoints,
         [](const Args& a, cv::Mat& mask) {
             return ess::findEssentialMatIter(a.p1, a.p2, a.K1, a.method, a.prob, a.threshold,
                                              a.maxIters, mask);
         }},
#if CV_VERSION_MAJOR < 5 // the forms without maxIters, as OpenCV 4.x has them
        {"findEssentialMatIter(K, method, prob, threshold, mask)",
         kCameraMatrix | kMethod | kProb | kEstimates | kNeedsFivePoints,
         [](const Args& a, cv::Mat& mask) {
             return ess::findEssentialMatIter(a.p1, a.p2, a.K1, a.method, a.prob, a.threshold,
                                              mask);
         }},
#endif
        {"findEssentialMatIter(focal, pp, method, prob, threshold, maxIters, mask)",
         kFocal | kMethod | kProb | kMaxIters | kEstimates | kNeedsFivePoints,
         [](const Args& a, cv::Mat& mask) {
             return ess::findEssentialMatIter(a.p1, a.p2, a.focal, a.pp, a.method, a.prob,
                                              a.threshold, a.maxIters, mask);
         }},
#if CV_VERSION_MAJOR < 5
        {"findEssentialMatIter(focal, pp, method, prob, threshold, mask)",
         kFocal | kMethod | kProb | kEstimates | kNeedsFivePoints,
         [](const Args& a, cv::Mat& mask) {
             return ess::findEssentialMatIter(a.p1, a.p2, a.focal, a.pp, a.method, a.prob,
                                              a.threshold, mask);
         }},
#endif
        {"findEssentialMatIter(K1, d1, K2, d2, method, prob, threshold, mask)",
         kCameraMatrix | kSecondCamera | kMethod | kProb | kEstimates | kNeedsFivePoints |
             kUndistorts,
         [](const Args& a, cv::Mat& mask) {
             return ess::findEssentialMatIter(a.p1, a.p2, a.K1, a.d1, a.K2, a.d2, a.method, a.prob,
                                              a.threshold, mask);
         }},
        {"findEssentialMatIter(K1, K2, d1, d2, mask, UsacParams)",
         kCameraMatrix | kSecondCamera | kProb | kMaxIters | kEstimates | kNeedsFivePoints |
             kUsacReading, // Args has no distortion coefficients
         [](const Args& a, cv::Mat& mask) {
             cv::UsacParams usac;
             usac.confidence = a.prob;
             usac.threshold = a.threshold;
             usac.maxIterations = a.maxIters;
             return ess::findEssentialMatIter(a.p1, a.p2, a.K1, a.K2, a.d1, a.d2, mask, usac);
         }},
        {"findEssentialMatIter(K, EssentialParams, mask, report)",
         kCameraMatrix | kProb | kMaxIters | kEstimates | kNeedsFivePoints | kUsacReading,
         [](const Args& a, cv::Mat& mask) {
             ess::EssentialParams params;
             // The params form has a score, not a method flag (its bad values: the Option table).
             params.score = a.method == cv::LMEDS ? cv::SCORE_METHOD_LMEDS : cv::SCORE_METHOD_MSAC;
             params.confidence = a.prob;
             params.threshold = a.threshold;
             params.maxIterations = a.maxIters;
             ess::EssentialReport report;
             cv::Mat E = ess::findEssentialMatIter(a.p1, a.p2, a.K1, params, mask, &report);
             EXPECT_EQ(report.success, !E.empty());
             return E;
         }},
        {"recoverPose(E, K, R, t, mask)", kCameraMatrix,
         [](const Args& a, cv::Mat& mask) {
             cv::Mat R, t;
             const int n = ess::recoverPoseIter(a.E, a.p1, a.p2, a.K1, R, t, mask);
             EXPECT_GE(n, 0);
             EXPECT_EQ(R.size(), cv::Size(3, 3));
             EXPECT_EQ(t.size(), cv::Size(1, 3));
             return cv::Mat();
         }},
        {"recoverPose(E, R, t, focal, pp, mask)", kFocal,
         [](const Args& a, cv::Mat& mask) {
             cv::Mat R, t;
             const int n = ess::recoverPoseIter(a.E, a.p1, a.p2, R, t, a.focal, a.pp, mask);
             EXPECT_GE(n, 0);
             EXPECT_EQ(R.size(), cv::Size(3, 3));
             EXPECT_EQ(t.size(), cv::Size(1, 3));
             return cv::Mat();
         }},
        {"recoverPose(E, K, R, t, distanceThresh, mask, triangulatedPoints)", kCameraMatrix,
         [](const Args& a, cv::Mat& mask) {
             cv::Mat R, t, X;
             const int n = ess::recoverPoseIter(a.E, a.p1, a.p2, a.K1, R, t, 50.0, mask, X);
             EXPECT_GE(n, 0);
             EXPECT_EQ(R.size(), cv::Size(3, 3));
             EXPECT_EQ(t.size(), cv::Size(1, 3));
             EXPECT_EQ(X.size(), cv::Size(a.p1.rows, 4));
             return cv::Mat();
         }},
        {"recoverPose(K1, d1, K2, d2, E, R, t, method, prob, threshold, mask)",
         kCameraMatrix | kSecondCamera | kMethod | kProb | kEstimates | kNeedsFivePoints |
             kUndistorts,
         [](const Args& a, cv::Mat& mask) {
             cv::Mat E, R, t;
             const int n = ess::recoverPoseIter(a.p1, a.p2, a.K1, a.d1, a.K2, a.d2, E, R, t,
                                                a.method, a.prob, a.threshold, mask);
             EXPECT_GE(n, 0);
             EXPECT_EQ(R.size(), cv::Size(3, 3));
             EXPECT_EQ(t.size(), cv::Size(1, 3));
             return E;
         }},
    };
    return list;
}

/** Runs `call`, expects a cv::Exception whose message contains every one of `needles`. */
void expectThrowsWith(const std::function<void()>& call, const std::vector<std::string>& needles)
{
    try {
        call();
        ADD_FAILURE() << "no exception; expected one mentioning '" << needles.front() << "'";
    } catch (const cv::Exception& e) {
        for (const std::string& needle : needles)
            EXPECT_NE(e.err.find(needle), std::string::npos)
                << "message '" << e.err << "' lacks '" << needle << "'";
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not a cv::Exception: " << e.what();
    }
}

/** Counts the calls made with bad input, printed when the process ends (docs/ROBUSTNESS.md quotes
the count of a run of all BadInputTable tests in one process). */
struct CallCounter
{
    int calls = 0;
    ~CallCounter()
    {
        if (calls > 0) std::printf("BadInputTable: %d calls through the public overloads\n", calls);
    }
};
CallCounter callCounter;

/** Runs the row on every overload that takes all of `needs`; returns how many ran. */
int forEachOverload(unsigned needs, const std::function<void(const Overload&)>& row)
{
    int ran = 0;
    for (const Overload& o : overloads()) {
        if ((o.takes & needs) != needs) continue;
        SCOPED_TRACE(o.name);
        row(o);
        ++ran;
        ++callCounter.calls;
    }
    return ran;
}

/** Of the rows' counts below, those written for OpenCV 4.x's overload set: OpenCV 5 (and the
module built against it) has no camera-matrix and focal forms without maxIters, so each count
loses the ones of those two that take all of `needs`. */
int removedInOpenCv5(unsigned needs)
{
#if CV_VERSION_MAJOR < 5
    (void)needs;
    return 0;
#else
    const unsigned withoutMaxIters[] = {kCameraMatrix | kMethod | kProb | kEstimates |
                                            kNeedsFivePoints,
                                        kFocal | kMethod | kProb | kEstimates | kNeedsFivePoints};
    int n = 0;
    for (const unsigned takes : withoutMaxIters)
        n += (takes & needs) == needs ? 1 : 0;
    return n;
#endif
}

void expectThrowsOnAll(unsigned needs, const Args& args, const std::vector<std::string>& needles,
                       int expectedOverloads)
{
    expectedOverloads -= removedInOpenCv5(needs);
    const int ran = forEachOverload(needs, [&](const Overload& o) {
        expectThrowsWith(
            [&] {
                cv::Mat mask;
                o.call(args, mask);
            },
            needles);
    });
    EXPECT_EQ(ran, expectedOverloads);
}

/** Expects the documented "no essential matrix" result: empty E, N x 1 CV_8U all-zero mask. */
void expectEmptyResult(const cv::Mat& E, const cv::Mat& mask, int n)
{
    EXPECT_TRUE(E.empty()) << "E is " << E.rows << " x " << E.cols;
    ASSERT_EQ(mask.rows, n);
    ASSERT_EQ(mask.cols, 1);
    ASSERT_EQ(mask.type(), CV_8U);
    EXPECT_EQ(cv::countNonZero(mask), 0);
}

/** Angle in degrees between E and the scene's E (both up to scale and sign). */
double essentialDistance(const cv::Mat& E, const cv::Matx33d& truth)
{
    cv::Matx33d e;
    E.rowRange(0, 3).convertTo(cv::Mat(3, 3, CV_64F, e.val), CV_64F);
    const double ne = cv::norm(e), nt = cv::norm(truth);
    return std::min(cv::norm(e / ne - truth * (1.0 / nt)), cv::norm(e / ne + truth * (1.0 / nt)));
}

constexpr int kAll = 11, kEstimators = 8;

TEST(BadInputTable, EmptyPoints)
{
    Args a;
    a.p1 = cv::Mat();
    expectThrowsOnAll(0, a, {"points1", "empty"}, kAll);
    Args b;
    b.p2 = cv::Mat();
    expectThrowsOnAll(0, b, {"points2", "empty"}, kAll);
    Args c;
    c.p1 = cv::Mat(0, 2, CV_64F);
    expectThrowsOnAll(0, c, {"points1", "empty"}, kAll);
}

TEST(BadInputTable, FewerThanFivePoints)
{
    for (int n = 1; n <= 4; ++n) {
        SCOPED_TRACE(n);
        Args a;
        a.p1 = a.p1.rowRange(0, n).clone();
        a.p2 = a.p2.rowRange(0, n).clone();
        expectThrowsOnAll(kNeedsFivePoints, a, {"at least 5", "got " + std::to_string(n)},
                          kEstimators);
        // recoverPose needs no minimum: it counts the points in front of the cameras.
        forEachOverload(0, [&](const Overload& o) {
            if (o.takes & kEstimates) return;
            cv::Mat mask;
            o.call(a, mask);
            ASSERT_EQ(mask.rows, n);
            EXPECT_LE(cv::countNonZero(mask), n);
        });
    }
}

TEST(BadInputTable, MismatchedSizes)
{
    Args a;
    a.p2 = a.p2.rowRange(0, 100).clone();
    expectThrowsOnAll(0, a, {"differ in size", "120", "100"}, kAll);
}

TEST(BadInputTable, NonFiniteCoordinates)
{
    for (const double bad : {kNaN, kInf, -kInf}) {
        SCOPED_TRACE(bad);
        Args a;
        a.p2.at<cv::Point2d>(17).y = bad;
        expectThrowsOnAll(0, a, {"points2", "non-finite", "17"}, kAll);
        Args b;
        cv::Mat f;
        b.p1.convertTo(f, CV_32FC2);
        f.at<cv::Vec2f>(3)[0] = static_cast<float>(bad);
        b.p1 = f;
        expectThrowsOnAll(0, b, {"points1", "non-finite", "3"}, kAll);
    }
}

TEST(BadInputTable, IntegerDepths)
{
    // As OpenCV: converted to double, except by the forms that undistort (cv::undistortPoints
    // takes CV_32F or CV_64F only).
    for (const int depth : {CV_8U, CV_16S, CV_32S}) {
        SCOPED_TRACE(depth);
        Args a;
        a.p1.convertTo(a.p1, CV_MAKETYPE(depth, 2));
        expectThrowsOnAll(kUndistorts, a, {"points1", "CV_32F or CV_64F"}, 2);
        forEachOverload(0, [&](const Overload& o) {
            if (o.takes & kUndistorts) return;
            cv::Mat mask;
            const cv::Mat E = o.call(a, mask); // CV_8U saturates: any result, but no exception
            EXPECT_EQ(mask.rows, a.p1.rows);
            if ((o.takes & kEstimates) && depth != CV_8U) {
                ASSERT_FALSE(E.empty());
                EXPECT_LT(essentialDistance(E, scene().E), 0.05);
            }
        });
    }
}

TEST(BadInputTable, WrongChannelsOrShape)
{
    const int n = static_cast<int>(scene().px1.size());
    // No reading takes these (measured with cv::findEssentialMat: test_drop_in_layouts.cpp).
    const std::vector<cv::Mat> bad = {cv::Mat(n, 1, CV_64F, cv::Scalar(1)),
                                      cv::Mat(1, 2 * n, CV_64F, cv::Scalar(1)),
                                      cv::Mat(2 * n, 1, CV_64F, cv::Scalar(1))};
    for (size_t k = 0; k < bad.size(); ++k) {
        SCOPED_TRACE(k);
        Args a;
        a.p2 = bad[k];
        expectThrowsOnAll(0, a, {"points2"}, kAll);
    }
    // Homogeneous points (N x 3, N x 1 three-channel): only OpenCV's USAC reading takes them, as
    // their first two coordinates; the others reject them naming the layouts they take.
    cv::Mat homogeneous;
    cv::convertPointsToHomogeneous(essential_test::pointColumn(scene().px2),
                                   homogeneous); // N x 1 CV_64FC3
    for (const cv::Mat& points : {homogeneous, homogeneous.reshape(1, n)}) {
        Args a;
        a.p2 = points;
        forEachOverload(0, [&](const Overload& o) {
            if (o.takes & kUsacReading) {
                cv::Mat mask;
                const cv::Mat E = o.call(a, mask);
                ASSERT_FALSE(E.empty());
                EXPECT_LT(essentialDistance(E, scene().E), 0.02);
            } else {
                expectThrowsWith(
                    [&] {
                        cv::Mat mask;
                        o.call(a, mask);
                    },
                    {"points2", "2D points"});
            }
        });
    }
}

TEST(BadInputTable, HugeCoordinatesWithinRangeAreOrdinaryOutliers)
{
    // A pixel coordinate of 1e8 (2e5 focal lengths) is accepted; such a point fits no plausible
    // model and ends up an outlier, while the rest is estimated as usual.
    Args a;
    a.p1.at<cv::Point2d>(5) = cv::Point2d(1e8, -1e8);
    a.p2.at<cv::Point2d>(9) = cv::Point2d(-1e8, 3e7);
    forEachOverload(kEstimates, [&](const Overload& o) {
        cv::Mat mask;
        const cv::Mat E = o.call(a, mask);
        ASSERT_FALSE(E.empty());
        ASSERT_TRUE(cv::checkRange(E));
        EXPECT_LT(essentialDistance(E, scene().E), 0.02);
        EXPECT_EQ(mask.at<uchar>(5), 0);
        EXPECT_EQ(mask.at<uchar>(9), 0);
        // Most true inliers are kept: measured 86+ of 96 on the Sampson overloads, 64 to 69 on the
        // UsacParams form (clang -O1, GCC -O3), whose symmetric epipolar distance (OpenCV's USAC)
        // is at least twice the Sampson distance at the same threshold.
        EXPECT_GT(cv::countNonZero(mask), scene().numInliers * 11 / 20);
    });
}

TEST(BadInputTable, CoordinatesBeyondRangeAreRejected)
{
    // 1e12 pixels at f = 500 are 2e9 focal lengths from the principal point: beyond the 1e8 bound
    // that keeps the Sampson distance's fourth powers finite.
    Args a;
    a.p1.at<cv::Point2d>(7) = cv::Point2d(1e12, 0);
    expectThrowsOnAll(0, a, {"points1", "index 7", "1e8 focal lengths"}, kAll);
    Args b;
    b.p2.at<cv::Point2d>(2) = cv::Point2d(0, -1e300);
    expectThrowsOnAll(0, b, {"points2", "index 2"}, kAll);
}

TEST(BadInputTable, SeveralFaultsReportTheFirstCheckInOrder)
{
    // The points are read, normalised and checked in one pass; input with several faults must
    // still get the exception of the first check in the documented order: finite coordinates
    // (points1, then points2), the number of points, then the normalised range (points1, then
    // points2).
    Args a; // beyond range in points1, non-finite in points2: the finite check comes first
    a.p1.at<cv::Point2d>(4) = cv::Point2d(1e12, 0);
    a.p2.at<cv::Point2d>(9).x = kNaN;
    expectThrowsOnAll(0, a, {"points2", "non-finite", "9"}, kAll);
    Args b; // non-finite in both: points1's index
    b.p1.at<cv::Point2d>(30).y = kInf;
    b.p2.at<cv::Point2d>(2).x = kNaN;
    expectThrowsOnAll(0, b, {"points1", "non-finite", "30"}, kAll);
    Args c; // three points, one beyond range: too few points comes first
    c.p1 = c.p1.rowRange(0, 3).clone();
    c.p2 = c.p2.rowRange(0, 3).clone();
    c.p2.at<cv::Point2d>(1) = cv::Point2d(0, 1e13);
    expectThrowsOnAll(kNeedsFivePoints, c, {"at least 5", "got 3"}, kEstimators);
    Args d; // three points, one not finite: the finite check comes before the count
    d.p1 = d.p1.rowRange(0, 3).clone();
    d.p2 = d.p2.rowRange(0, 3).clone();
    d.p1.at<cv::Point2d>(2).x = kNaN;
    expectThrowsOnAll(0, d, {"points1", "non-finite", "2"}, kAll);
    Args e; // beyond range in both: points1's index, the last point (the pass covers all)
    const int last = e.p1.rows - 1;
    e.p1.at<cv::Point2d>(last) = cv::Point2d(-1e12, 0);
    e.p2.at<cv::Point2d>(0) = cv::Point2d(0, 1e12);
    expectThrowsOnAll(0, e, {"points1", "index " + std::to_string(last), "1e8 focal lengths"},
                      kAll);
}

TEST(BadInputTable, DuplicatedPointsGiveTheSameModel)
{
    // Every correspondence given twice: the same E as once (within the refinement's tolerance),
    // and both copies of a point get the same mask value.
    Args once;
    Args twice;
    cv::vconcat(once.p1, once.p1, twice.p1);
    cv::vconcat(once.p2, once.p2, twice.p2);
    const int n = once.p1.rows;
    forEachOverload(kEstimates, [&](const Overload& o) {
        cv::Mat mask;
        const cv::Mat E = o.call(twice, mask);
        ASSERT_FALSE(E.empty());
        EXPECT_LT(essentialDistance(E, scene().E), 0.02);
        ASSERT_EQ(mask.rows, 2 * n);
        for (int i = 0; i < n; ++i)
            EXPECT_EQ(mask.at<uchar>(i), mask.at<uchar>(i + n)) << i;
    });
}

TEST(BadInputTable, AllPointsIdentical)
{
    Args a;
    const int n = 60;
    a.p1 = cv::Mat(n, 1, CV_64FC2, cv::Scalar(321.5, 123.25));
    a.p2 = cv::Mat(n, 1, CV_64FC2, cv::Scalar(300.0, 140.0));
    forEachOverload(0, [&](const Overload& o) {
        // A stale mask of another shape is replaced (recoverPose reads its mask: none given).
        cv::Mat mask = o.takes & kEstimates ? cv::Mat(2, 2, CV_32F, cv::Scalar(7)) : cv::Mat();
        const cv::Mat E = o.call(a, mask);
        if (o.takes & kEstimates) {
            expectEmptyResult(E, mask, n);
        } else {
            // recoverPose of a valid E: one point repeated is either in front or not, all alike.
            ASSERT_EQ(mask.rows, n);
            const int inFront = cv::countNonZero(mask);
            EXPECT_TRUE(inFront == 0 || inFront == n) << inFront;
        }
    });
    // Five distinct points, each repeated twelve times: no sample of five distinct points exists
    // beyond those five, which any E fits; no support beyond chance, so no model.
    Args b;
    std::vector<cv::Point2d> q1, q2;
    for (int r = 0; r < 12; ++r)
        for (int i = 0; i < 5; ++i) {
            q1.push_back(scene().px1[static_cast<size_t>(i)]);
            q2.push_back(scene().px2[static_cast<size_t>(i)]);
        }
    b.p1 = cv::Mat(q1, true);
    b.p2 = cv::Mat(q2, true);
    forEachOverload(kEstimates, [&](const Overload& o) {
        cv::Mat mask;
        const cv::Mat E = o.call(b, mask);
        expectEmptyResult(E, mask, 60);
    });
}

TEST(BadInputTable, CameraMatrixNot3x3)
{
    const std::vector<cv::Mat> bad = {cv::Mat::eye(2, 3, CV_64F), cv::Mat::eye(4, 4, CV_64F),
                                      cv::Mat(9, 1, CV_64F, cv::Scalar(1)),
                                      cv::Mat(3, 3, CV_64FC2, cv::Scalar(1, 0))};
    for (size_t k = 0; k < bad.size(); ++k) {
        SCOPED_TRACE(k);
        Args a;
        a.K1 = bad[k];
        // Named cameraMatrix in the one-camera forms, cameraMatrix1 in the two-camera ones.
        expectThrowsOnAll(kCameraMatrix, a, {"cameraMatrix", "3 x 3"}, 8);
        Args b;
        b.K2 = bad[k];
        expectThrowsOnAll(kSecondCamera, b, {"cameraMatrix2", "3 x 3"}, 3);
    }
    Args e;
    e.K1 = cv::Mat();
    expectThrowsOnAll(kCameraMatrix, e, {"cameraMatrix", "empty"}, 8);
    Args i;
    // Integer depths are accepted, as OpenCV converts them
    // (DropInParity.IntegerCameraAndDistortion); half floats are not.
    i.K1 = cv::Mat::eye(3, 3, CV_16F);
    expectThrowsOnAll(kCameraMatrix, i, {"cameraMatrix", "CV_16F"}, 8);
}

TEST(BadInputTable, CameraMatrixNonFiniteSingularOrNegativeFocal)
{
    struct Case
    {
        int row, col;
        double value;
        std::string needle;
    };
    const std::vector<Case> cases = {
        {0, 2, kNaN, "non-finite"},       {1, 1, kInf, "non-finite"},
        {0, 0, 0.0, "positive focal"},    {0, 0, -500.0, "positive focal"},
        {1, 1, -500.0, "positive focal"}, {2, 2, 0.0, "last row of 0 0 1"},
        {2, 0, 0.5, "last row of 0 0 1"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.needle + " at " + std::to_string(c.row) + "," + std::to_string(c.col));
        Args a;
        a.K1.at<double>(c.row, c.col) = c.value;
        expectThrowsOnAll(kCameraMatrix, a, {"cameraMatrix", c.needle}, 8);
        Args b;
        b.K2.at<double>(c.row, c.col) = c.value;
        expectThrowsOnAll(kSecondCamera, b, {"cameraMatrix2", c.needle}, 3);
    }
    // Positive focal lengths, dependent rows (skew chosen so that the first two rows are parallel).
    Args s;
    s.K1 = cv::Mat(cv::Matx<double, 3, 3>(500, 1000, 0, 250, 500, 0, 0, 0, 1));
    expectThrowsOnAll(kCameraMatrix, s, {"cameraMatrix", "singular"}, 8);
    // The focal forms.
    for (const double focal : {0.0, -500.0, kNaN, kInf}) {
        SCOPED_TRACE(focal);
        Args f;
        f.focal = focal;
        expectThrowsOnAll(kFocal, f, {"focal"}, 3);
    }
    Args p;
    p.pp = cv::Point2d(kNaN, 0);
    expectThrowsOnAll(kFocal, p, {"pp", "finite"}, 3);
}

TEST(BadInputTable, DistortionCoefficients)
{
    // Lengths OpenCV does not know.
    for (const int len : {1, 3, 6, 7, 13, 15}) {
        SCOPED_TRACE(len);
        Args a;
        a.d1 = cv::Mat::zeros(1, len, CV_64F);
        expectThrowsOnAll(kSecondCamera, a,
                          {"distCoeffs1", "4, 5, 8, 12 or 14", "got " + std::to_string(len)}, 3);
        Args b;
        b.d2 = cv::Mat::zeros(len, 1, CV_32F);
        expectThrowsOnAll(kSecondCamera, b, {"distCoeffs2", "got " + std::to_string(len)}, 3);
    }
    Args nan;
    nan.d1 = cv::Mat(cv::Matx<double, 1, 5>(0.1, kNaN, 0, 0, 0));
    expectThrowsOnAll(kSecondCamera, nan, {"distCoeffs1", "non-finite"}, 3);
    Args depth;
    depth.d2 = cv::Mat::zeros(1, 5, CV_16F);
    expectThrowsOnAll(kSecondCamera, depth, {"distCoeffs2", "CV_16F"}, 3);
    // Zero coefficients of every valid length: the same model as without distortion.
    for (const int len : {4, 5, 8, 12, 14}) {
        SCOPED_TRACE(len);
        Args z;
        z.d1 = cv::Mat::zeros(1, len, CV_64F);
        z.d2 = cv::Mat::zeros(len, 1, CV_64F);
        forEachOverload(kSecondCamera, [&](const Overload& o) {
            cv::Mat mask;
            const cv::Mat E = o.call(z, mask);
            ASSERT_FALSE(E.empty());
            EXPECT_LT(essentialDistance(E, scene().E), 0.02);
        });
    }
    // Absurd coefficients: either rejected, naming the undistorted points, or a finite result.
    Args wild;
    wild.d1 = cv::Mat(cv::Matx<double, 1, 5>(1e300, -1e300, 1e300, 1e300, 1e300));
    forEachOverload(kSecondCamera, [&](const Overload& o) {
        try {
            cv::Mat mask;
            const cv::Mat E = o.call(wild, mask);
            EXPECT_TRUE(E.empty() || cv::checkRange(E));
            EXPECT_EQ(mask.rows, wild.p1.rows);
        } catch (const cv::Exception& e) {
            EXPECT_NE(e.err.find("points1 (undistorted with distCoeffs1)"), std::string::npos)
                << e.err;
        }
    });
}

TEST(BadInputTable, ProbOutsideZeroOne)
{
    for (const double prob : {0.0, -0.5, 1.0, 1.5, kNaN, kInf}) {
        SCOPED_TRACE(prob);
        Args a;
        a.prob = prob;
        expectThrowsOnAll(kProb, a, {"prob"}, kEstimators);
    }
}

TEST(BadInputTable, ThresholdNotPositiveOrNotFinite)
{
    for (const double threshold : {0.0, -1.0, -0.0, kNaN, kInf, -kInf}) {
        SCOPED_TRACE(threshold);
        Args a;
        a.threshold = threshold;
        expectThrowsOnAll(kProb, a, {"threshold"}, kEstimators);
    }
    // A threshold so small in pixels that it is zero in normalised units with a huge focal length.
    Args tiny;
    tiny.threshold = std::numeric_limits<double>::denorm_min();
    tiny.focal = 1e10;
    expectThrowsOnAll(kFocal | kEstimates, tiny, {"threshold"}, 2);
}

TEST(BadInputTable, MaxItersNotPositive)
{
    for (const int maxIters : {0, -1, INT_MIN}) {
        SCOPED_TRACE(maxIters);
        Args a;
        a.maxIters = maxIters;
        // "maxIters" in the drop-in forms, "...::maxIterations" in the UsacParams and
        // EssentialParams forms.
        expectThrowsOnAll(kMaxIters, a, {"maxIter"}, 4);
    }
}

TEST(BadInputTable, LargeMaxItersStillStopsAtTheConfidence)
{
    // INT_MAX is a valid cap: the search stops when the confidence is reached, long before it.
    Args a;
    a.maxIters = INT_MAX;
    forEachOverload(kMaxIters, [&](const Overload& o) {
        cv::Mat mask;
        const cv::Mat E = o.call(a, mask);
        ASSERT_FALSE(E.empty());
        EXPECT_LT(essentialDistance(E, scene().E), 0.02);
    });
}

TEST(BadInputTable, UnknownMethod)
{
    for (const int method : {12345, -1, 1, static_cast<int>(cv::RHO)}) {
        SCOPED_TRACE(method);
        Args a;
        a.method = method;
        expectThrowsOnAll(kMethod, a, {"method", std::to_string(method)}, 6);
    }
}

TEST(BadInputTable, UnknownSolverEngineSamplerOrOption)
{
    const cv::Mat K(scene().K);
    auto run = [&](const ess::EssentialParams& p) {
        cv::Mat mask;
        ess::findEssentialMatIter(scene().px1, scene().px2, K, p, mask);
    };
    for (const char* solver :
         {"no-such-solver", "", "gn+", "gn:0", "gn:x", "+nister", "gn:1001", "gn+no-such-solver"}) {
        SCOPED_TRACE(solver);
        ess::EssentialParams p;
        p.solver = solver;
        try {
            run(p);
            ADD_FAILURE() << "solver '" << solver << "' accepted";
        } catch (const cv::Exception& e) {
            EXPECT_NE(e.err.find("solver"), std::string::npos) << e.err;
        }
    }
    struct Option
    {
        std::function<void(ess::EssentialParams&)> set;
        std::string needle;
    };
    const std::vector<Option> options = {
        // Values outside an enumeration, which a caller can make only by a cast.
        {[](ess::EssentialParams& p) { p.engine = static_cast<ess::EssentialEngine>(7); },
         "engine"},
        {[](ess::EssentialParams& p) { p.engine = static_cast<ess::EssentialEngine>(-1); },
         "engine"},
        {[](ess::EssentialParams& p) { p.sampler = static_cast<cv::SamplingMethod>(99); },
         "sampler"},
        {[](ess::EssentialParams& p) { p.score = static_cast<cv::ScoreMethod>(99); }, "score"},
        // Settings the module does not implement: StsNotImplemented naming them.
        {[](ess::EssentialParams& p) { p.score = cv::SCORE_METHOD_RANSAC; }, "SCORE_METHOD_RANSAC"},
        {[](ess::EssentialParams& p) { p.score = cv::SCORE_METHOD_MAGSAC; }, "SCORE_METHOD_MAGSAC"},
        {[](ess::EssentialParams& p) {
             p.sampler = cv::SAMPLING_NAPSAC;
             p.score = cv::SCORE_METHOD_LMEDS;
         },
         "SAMPLING_NAPSAC"},
        {[](ess::EssentialParams& p) {
             p.sampleBudget = static_cast<ess::EssentialSampleBudget>(2);
         },
         "sampleBudget"},
        {[](ess::EssentialParams& p) { p.loIterations = -1; }, "loIterations"},
        {[](ess::EssentialParams& p) { p.loSampleSize = 3; }, "loSampleSize"},
        {[](ess::EssentialParams& p) { p.preemptiveBlockSize = 0; }, "preemptiveBlockSize"},
        {[](ess::EssentialParams& p) { p.preemptiveHypotheses = -1; }, "preemptiveHypotheses"},
        {[](ess::EssentialParams& p) { p.timeBudgetMs = -1; }, "timeBudgetMs"},
        {[](ess::EssentialParams& p) { p.timeBudgetMs = kNaN; }, "timeBudgetMs"},
        {[](ess::EssentialParams& p) {
             p.engine = ess::ENGINE_PREEMPTIVE;
             p.score = cv::SCORE_METHOD_LMEDS;
         },
         "ENGINE_PREEMPTIVE"},
    };
    for (size_t k = 0; k < options.size(); ++k) {
        SCOPED_TRACE(options[k].needle);
        ess::EssentialParams p;
        options[k].set(p);
        expectThrowsWith([&] { run(p); }, {options[k].needle});
    }
    // UsacParams fields.
    struct UsacOption
    {
        std::function<void(cv::UsacParams&)> set;
        std::string needle;
    };
    const std::vector<UsacOption> usacOptions = {
        {[](cv::UsacParams& u) { u.score = static_cast<cv::ScoreMethod>(99); }, "score"},
        {[](cv::UsacParams& u) { u.sampler = static_cast<cv::SamplingMethod>(99); }, "sampler"},
        {[](cv::UsacParams& u) { u.loMethod = static_cast<cv::LocalOptimMethod>(99); }, "loMethod"},
        {[](cv::UsacParams& u) { u.loIterations = -2; }, "loIterations"},
        {[](cv::UsacParams& u) { u.loSampleSize = 4; }, "loSampleSize"},
    };
    for (const UsacOption& o : usacOptions) {
        SCOPED_TRACE(o.needle);
        cv::UsacParams u;
        u.threshold = 1.0;
        o.set(u);
        expectThrowsWith(
            [&] {
                cv::Mat mask;
                ess::findEssentialMatIter(scene().px1, scene().px2, K, K, cv::Mat(), cv::Mat(),
                                          mask, u);
            },
            {"UsacParams::" + o.needle});
    }
}

TEST(BadInputTable, RecoverPoseEssentialMatrixAndMask)
{
    const cv::Mat K(scene().K);
    cv::Mat R, t;
    const std::vector<std::pair<cv::Mat, std::string>> badE = {
        {cv::Mat(), "empty"},
        {cv::Mat::eye(3, 4, CV_64F), "3 x 3"},
        {cv::Mat::eye(3, 3, CV_32S), "CV_32F or CV_64F"},
        {cv::Mat(cv::Matx<double, 3, 3>(0, kNaN, 0, 0, 0, 0, 0, 0, 0)), "non-finite"},
    };
    for (const auto& item : badE) {
        const cv::Mat& E = item.first; // not a structured binding: lambdas capture it
        const std::string& needle = item.second;
        SCOPED_TRACE(needle);
        expectThrowsWith([&] { ess::recoverPoseIter(E, scene().px1, scene().px2, K, R, t); },
                         {"E", needle});
        expectThrowsWith([&] { ess::recoverPoseIter(E, scene().px1, scene().px2, R, t, 500.0); },
                         {"E", needle});
    }
    // The zero matrix cannot be decomposed: no pose (R = I, t = 0), no point in front.
    cv::Mat mask;
    const int n =
        ess::recoverPoseIter(cv::Mat::zeros(3, 3, CV_64F), scene().px1, scene().px2, K, R, t, mask);
    EXPECT_EQ(n, 0);
    EXPECT_EQ(cv::norm(R, cv::Mat::eye(3, 3, CV_64F)), 0.0);
    EXPECT_EQ(cv::norm(t), 0.0);
    EXPECT_EQ(cv::countNonZero(mask), 0);
    // distanceThresh must be positive (+inf: no cut).
    for (const double d : {0.0, -1.0, kNaN, -kInf}) {
        SCOPED_TRACE(d);
        expectThrowsWith(
            [&] { ess::recoverPoseIter(cv::Mat(scene().E), scene().px1, scene().px2, K, R, t, d); },
            {"distanceThresh"});
    }
    // A mask of the wrong size or type.
    cv::Mat shortMask(10, 1, CV_8U, cv::Scalar(1));
    expectThrowsWith(
        [&] {
            ess::recoverPoseIter(cv::Mat(scene().E), scene().px1, scene().px2, K, R, t, shortMask);
        },
        {"mask", "one entry per point"});
    cv::Mat floatMask(static_cast<int>(scene().px1.size()), 1, CV_32F, cv::Scalar(1));
    expectThrowsWith(
        [&] {
            ess::recoverPoseIter(cv::Mat(scene().E), scene().px1, scene().px2, K, R, t, floatMask);
        },
        {"mask", "CV_8U"});
}

// User-registered solvers that misbehave. Names are unique to this file: the registry is
// process-wide.

struct ThrowingSolver : ess::EssentialSolver
{
    int kind; // 0: std::runtime_error, 1: cv::Exception, 2: an int
    explicit ThrowingSolver(int k) : kind(k) {}
    int sampleSize() const override { return 5; }
    int maxSolutions() const override { return 1; }
    int solve(const cv::Point2d*, const cv::Point2d*, cv::RNG&, cv::Matx33d*) override
    {
        if (kind == 0) throw std::runtime_error("disk on fire");
        if (kind == 1) CV_Error(cv::Error::StsInternal, "solver gave up loudly");
        throw 42;
    }
};

struct GarbageSolver : ess::EssentialSolver
{
    int kind; // 0: NaN, 1: +inf, 2: all zero, 3: count above maxSolutions, 4: negative count
    explicit GarbageSolver(int k) : kind(k) {}
    int sampleSize() const override { return 5; }
    int maxSolutions() const override { return 2; }
    int solve(const cv::Point2d*, const cv::Point2d*, cv::RNG&, cv::Matx33d* out) override
    {
        const double v = kind == 0 ? kNaN : kind == 1 ? kInf : 0.0;
        for (int h = 0; h < 2; ++h)
            out[h] = cv::Matx33d::all(v);
        if (kind == 3) return 1000;
        if (kind == 4) return -7;
        return 2;
    }
    double successRate() const override { return kind == 3 ? kNaN : 1.0; }
    double hitProbability(double) const override { return kind == 4 ? -3.0 : 0.5; }
};

struct BadSizeSolver : ess::EssentialSolver
{
    int sample, solutions;
    BadSizeSolver(int s, int n) : sample(s), solutions(n) {}
    int sampleSize() const override { return sample; }
    int maxSolutions() const override { return solutions; }
    int solve(const cv::Point2d*, const cv::Point2d*, cv::RNG&, cv::Matx33d*) override { return 0; }
};

std::vector<ess::EssentialParams> engineVariants(const std::string& solver)
{
    std::vector<ess::EssentialParams> v;
    ess::EssentialParams p;
    p.solver = solver;
    p.maxIterations = 200;
    v.push_back(p); // adaptive MSAC
    p.score = cv::SCORE_METHOD_LMEDS;
    v.push_back(p);
    p.score = cv::SCORE_METHOD_MSAC;
    p.engine = ess::ENGINE_PREEMPTIVE;
    p.preemptiveHypotheses = 50;
    v.push_back(p);
    if (ess::isOpenCvLoopAvailable()) {
        p.engine = ess::ENGINE_OPENCV;
        v.push_back(p);
    }
    return v;
}

TEST(BadInputTable, UserSolverThatThrows)
{
    ess::registerSolver("badinput_throws_std", [] { return cv::makePtr<ThrowingSolver>(0); });
    ess::registerSolver("badinput_throws_cv", [] { return cv::makePtr<ThrowingSolver>(1); });
    ess::registerSolver("badinput_throws_int", [] { return cv::makePtr<ThrowingSolver>(2); });
    ess::registerSolver("badinput_factory_throws", []() -> cv::Ptr<ess::EssentialSolver> {
        throw std::logic_error("no solver today");
    });
    const cv::Mat K(scene().K);
    const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
        {"badinput_throws_std", {"badinput_throws_std", "solve()", "disk on fire"}},
        {"badinput_throws_cv", {"solver gave up loudly"}},
        {"badinput_throws_int", {"badinput_throws_int", "non-standard exception"}},
        {"badinput_factory_throws", {"badinput_factory_throws", "factory", "no solver today"}},
        {"gn+badinput_throws_std", {"badinput_throws_std", "disk on fire"}},
    };
    for (const auto& [name, needles] : cases) {
        for (const ess::EssentialParams& p : engineVariants(name)) {
            SCOPED_TRACE(name + " engine " + std::to_string(static_cast<int>(p.engine)) +
                         " score " + std::to_string(static_cast<int>(p.score)));
            cv::Mat mask;
            expectThrowsWith(
                [&] { ess::findEssentialMatIter(scene().px1, scene().px2, K, p, mask); }, needles);
        }
    }
}

TEST(BadInputTable, UserSolverThatReturnsGarbage)
{
    for (int kind = 0; kind < 5; ++kind)
        ess::registerSolver("badinput_garbage_" + std::to_string(kind),
                            [kind] { return cv::makePtr<GarbageSolver>(kind); });
    const cv::Mat K(scene().K);
    const int n = static_cast<int>(scene().px1.size());
    for (int kind = 0; kind < 5; ++kind) {
        const std::string name = "badinput_garbage_" + std::to_string(kind);
        for (const ess::EssentialParams& p : engineVariants(name)) {
            SCOPED_TRACE(name + " engine " + std::to_string(static_cast<int>(p.engine)) +
                         " score " + std::to_string(static_cast<int>(p.score)));
            cv::Mat mask;
            ess::EssentialReport report;
            const cv::Mat E =
                ess::findEssentialMatIter(scene().px1, scene().px2, K, p, mask, &report);
            // Nothing usable came out of the solver: the documented empty result.
            expectEmptyResult(E, mask, n);
            EXPECT_FALSE(report.success);
            EXPECT_EQ(report.hypothesesScored, 0);
        }
        // Exactly five points (all solutions listed): none either.
        cv::Mat mask;
        ess::EssentialParams p;
        p.solver = name;
        const std::vector<cv::Point2d> p1(scene().px1.begin(), scene().px1.begin() + 5);
        const std::vector<cv::Point2d> p2(scene().px2.begin(), scene().px2.begin() + 5);
        const cv::Mat E = ess::findEssentialMatIter(p1, p2, K, p, mask);
        expectEmptyResult(E, mask, 5);
    }
    // Mixed with a working solver, garbage costs samples but not the answer.
    ess::EssentialParams p;
    p.solver = "nister+badinput_garbage_0";
    cv::Mat mask;
    const cv::Mat E = ess::findEssentialMatIter(scene().px1, scene().px2, K, p, mask);
    ASSERT_FALSE(E.empty());
    EXPECT_LT(essentialDistance(E, scene().E), 0.02);
}

TEST(BadInputTable, UserSolverWithImpossibleSizes)
{
    const std::vector<std::pair<int, int>> sizes = {
        {4, 1}, {5, 0}, {1001, 1}, {5, 1001}, {INT_MAX, 1}, {5, INT_MAX}, {-5, 1}};
    const cv::Mat K(scene().K);
    for (size_t k = 0; k < sizes.size(); ++k) {
        const auto [sample, solutions] = sizes[k];
        const std::string name = "badinput_size_" + std::to_string(k);
        ess::registerSolver(name, [sample = sample, solutions = solutions] {
            return cv::makePtr<BadSizeSolver>(sample, solutions);
        });
        SCOPED_TRACE(name);
        ess::EssentialParams p;
        p.solver = name;
        cv::Mat mask;
        expectThrowsWith([&] { ess::findEssentialMatIter(scene().px1, scene().px2, K, p, mask); },
                         {name, "sampleSize()", "maxSolutions()"});
    }
}

} // namespace
