// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// End to end on the paper's synthetic protocol (synthetic_scene.hpp defaults: 90 degree field of
// view, inverse depth uniform from depth 1, rotation up to 35 degrees, baseline 0.1..1, 0.5 px
// noise at f = 500): the drop-in overload with default parameters, then recoverPose, gives the
// true pose; the module's own overload fills a consistent report.

#include "opencv2/essential.hpp"
#include "synthetic_scene.hpp"

#include "essential_test.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using essential_test::essentialDistance;
using essential_test::makeScene;
using essential_test::rotationErrorDeg;
using essential_test::SceneConfig;
using essential_test::skewMatrix;
using essential_test::SyntheticScene;
using essential_test::translationErrorDeg;

constexpr int kProblems = 200;

/** Points whose Sampson distance to the true E is within `threshold` (normalised units). */
int pointsWithinThreshold(const SyntheticScene& s, double threshold)
{
    int count = 0;
    for (size_t i = 0; i < s.x1.size(); ++i) {
        const cv::Vec3d a(s.x1[i].x, s.x1[i].y, 1.0), b(s.x2[i].x, s.x2[i].y, 1.0);
        const cv::Vec3d Ea = s.E * a, Etb = s.E.t() * b;
        const double r = b.dot(Ea);
        const double d2 =
            r * r / (Ea[0] * Ea[0] + Ea[1] * Ea[1] + Etb[0] * Etb[0] + Etb[1] * Etb[1]);
        count += d2 <= threshold * threshold ? 1 : 0;
    }
    return count;
}

SceneConfig paperScene()
{
    SceneConfig cfg; // the paper's protocol
    cfg.numPoints = 500;
    cfg.inlierRatio = 0.5;
    return cfg;
}

TEST(EndToEnd, DropInDefaultsRecoverThePose)
{
    int good = 0, failures = 0;
    std::vector<double> rotErr, transErr;
    for (int k = 0; k < kProblems; ++k) {
        const uint64_t seed = 1000 + static_cast<uint64_t>(k);
        const SyntheticScene s = makeScene(paperScene(), seed);
        cv::Mat mask;
        // Pixel coordinates, K from the scene, every other argument at its default.
        const cv::Mat E = cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K),
                                                              cv::RANSAC, 0.999, 1.0, 1000, mask);
        if (E.rows != 3 || E.cols != 3) {
            ++failures;
            continue;
        }
        cv::Mat R, t;
        cv::Mat inFront = mask.clone();
        const int n = cv::essential::recoverPoseIter(E, s.px1, s.px2, cv::Mat(s.K), R, t, inFront);
        const double re = rotationErrorDeg(cv::Matx33d(R), s.R);
        const double te = translationErrorDeg(cv::Vec3d(t), s.t);
        rotErr.push_back(re);
        transErr.push_back(te);
        // The pose is that of the most inliers.
        EXPECT_GT(n, cv::countNonZero(mask) / 2) << "seed " << seed;
        if (re < 1.0 && te < 3.0) ++good;
    }
    std::sort(rotErr.begin(), rotErr.end());
    std::sort(transErr.begin(), transErr.end());
    const double medianRot = rotErr.empty() ? -1 : rotErr[rotErr.size() / 2];
    const double medianTrans = transErr.empty() ? -1 : transErr[transErr.size() / 2];
    RecordProperty("good", good);
    RecordProperty("failures", failures);
    RecordProperty("medianRotationErrorMilliDeg", static_cast<int>(1000 * medianRot));
    RecordProperty("medianTranslationErrorMilliDeg", static_cast<int>(1000 * medianTrans));
    if (!rotErr.empty()) {
        RecordProperty("maxRotationErrorMilliDeg", static_cast<int>(1000 * rotErr.back()));
        RecordProperty("maxTranslationErrorMilliDeg", static_cast<int>(1000 * transErr.back()));
    }
    EXPECT_GE(good, (99 * kProblems + 99) / 100)
        << good << " of " << kProblems << " within 1 deg / 3 deg; " << failures
        << " failures; median errors " << medianRot << " / " << medianTrans << " deg";
}

TEST(EndToEnd, ReportIsConsistent)
{
    // The module's own overload with a report, on a subset of the same problems.
    const double gnSuccess = cv::essential::createSolver("gn")->successRate();
    ASSERT_GT(gnSuccess, 0.0);
    double minRatio = 10, maxRatio = 0;
    for (int k = 0; k < 40; ++k) {
        const uint64_t seed = 1000 + static_cast<uint64_t>(k);
        SCOPED_TRACE(seed);
        const SyntheticScene s = makeScene(paperScene(), seed);
        const int N = static_cast<int>(s.px1.size());
        cv::essential::EssentialParams params;
        cv::essential::EssentialReport report;
        cv::Mat mask;
        const cv::Mat E =
            cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, mask, &report);
        ASSERT_EQ(E.rows, 3);
        ASSERT_EQ(E.cols, 3);
        ASSERT_TRUE(report.success);
        EXPECT_EQ(report.numPoints, N);

        // Returned E and report E are the same matrix, of unit Frobenius norm as OpenCV's, and
        // close to the truth.
        const cv::Matx33d Em(E);
        EXPECT_LT(cv::norm(Em - report.E, cv::NORM_INF), 1e-12);
        EXPECT_NEAR(cv::norm(report.E), 1.0, 1e-12);
        EXPECT_LT(essentialDistance(report.E, s.E), 0.05);

        // Inliers: the mask's count, and close to the best possible: the number of points within
        // the threshold of the true E (about 95% of the correct matches at 0.5 px noise and 1 px,
        // plus the odd wrong match). Measured over these 40 problems: 94.5% to 101.7% of it (the
        // low end on a short-baseline scene, seed 1012, where OpenCV marks 218 points, we 223 and
        // the true E 236).
        EXPECT_EQ(report.inliers, cv::countNonZero(mask));
        const int best = pointsWithinThreshold(s, 1.0 / s.K(0, 0));
        const double ratio = double(report.inliers) / best;
        minRatio = std::min(minRatio, ratio);
        maxRatio = std::max(maxRatio, ratio);
        EXPECT_GE(ratio, 0.93) << report.inliers << " vs " << best;
        EXPECT_LE(ratio, 1.05) << report.inliers << " vs " << best;
        EXPECT_GE(report.inliers, static_cast<int>(0.85 * s.numInliers));
        EXPECT_LE(report.inliers, static_cast<int>(1.05 * s.numInliers));
        int trueMarked = 0;
        for (int i = 0; i < N; ++i)
            trueMarked += (mask.at<uchar>(i) && s.inlier[static_cast<size_t>(i)]) ? 1 : 0;
        EXPECT_GE(trueMarked, static_cast<int>(0.95 * report.inliers));

        // Pose: recovered, consistent with E ([t]x R proportional to E), close to the truth, and
        // the same as recoverPose on the returned mask.
        ASSERT_TRUE(report.poseRecovered);
        EXPECT_NEAR(cv::norm(report.t), 1.0, 1e-9);
        EXPECT_NEAR(cv::determinant(report.R), 1.0, 1e-9);
        EXPECT_LT(essentialDistance(skewMatrix(report.t) * report.R, report.E), 1e-9);
        EXPECT_LT(rotationErrorDeg(report.R, s.R), 1.0);
        EXPECT_LT(translationErrorDeg(report.t, s.t), 3.0);
        cv::Mat R, t, inFront = mask.clone();
        const int n = cv::essential::recoverPoseIter(E, s.px1, s.px2, cv::Mat(s.K), R, t, inFront);
        EXPECT_EQ(report.pointsInFront, n);
        EXPECT_LT(cv::norm(cv::Matx33d(R) - report.R, cv::NORM_INF), 1e-12);
        EXPECT_LT(cv::norm(cv::Vec3d(t) - report.t, cv::NORM_INF), 1e-12);
        EXPECT_GT(report.pointsInFront, report.inliers / 2);
        EXPECT_LE(report.pointsInFront, report.inliers);

        // Counts.
        EXPECT_GT(report.iterations, 0);
        // maxIters is in OpenCV's units: up to maxIters / successRate samples (params.hpp).
        EXPECT_LE(report.iterations, static_cast<int>(std::ceil(params.maxIterations / gnSuccess)));
        EXPECT_GE(report.hypothesesGenerated, report.iterations);
        EXPECT_GT(report.hypothesesConverged, 0);
        EXPECT_GT(report.hypothesesScored, 0);
        EXPECT_LE(report.hypothesesScored, report.hypothesesConverged);
        EXPECT_GT(report.refineIterations, 0);

        // Times.
        EXPECT_GE(report.timeSetupMs, 0.0);
        EXPECT_GE(report.timeSearchMs, 0.0);
        EXPECT_GE(report.timeRefineMs, 0.0);
        EXPECT_GE(report.timePoseMs, 0.0);
        EXPECT_GT(report.timeTotalMs, 0.0);
        EXPECT_GE(report.timeTotalMs + 1e-9, report.timeSetupMs + report.timeSearchMs +
                                                 report.timeRefineMs + report.timePoseMs);
    }
    RecordProperty("minInlierRatioPermille", static_cast<int>(1000 * minRatio));
    RecordProperty("maxInlierRatioPermille", static_cast<int>(1000 * maxRatio));
}

TEST(EndToEnd, ReportWithoutPoseAndWithoutRefinement)
{
    const SyntheticScene s = makeScene(paperScene(), 2000);
    cv::essential::EssentialParams params;
    params.recoverPose = false;
    params.refine = false;
    cv::essential::EssentialReport report;
    cv::Mat mask;
    const cv::Mat E =
        cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, mask, &report);
    ASSERT_EQ(E.rows, 3);
    EXPECT_TRUE(report.success);
    EXPECT_FALSE(report.poseRecovered);
    EXPECT_EQ(report.refineIterations, 0);
    EXPECT_EQ(report.pointsInFront, 0);
    EXPECT_LT(essentialDistance(cv::Matx33d(E), s.E), 0.1);
    EXPECT_EQ(report.inliers, cv::countNonZero(mask));
}

TEST(EndToEnd, SameSeedSameResult)
{
    const SyntheticScene s = makeScene(paperScene(), 2001);
    cv::essential::EssentialParams params;
    cv::Mat m1, m2, m3;
    const cv::Mat E1 = cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, m1);
    const cv::Mat E2 = cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, m2);
    EXPECT_EQ(cv::norm(E1, E2, cv::NORM_INF), 0.0);
    EXPECT_EQ(cv::countNonZero(m1 != m2), 0);
    // Another seed runs another search (a different sample sequence) and still finds the pose.
    params.seed = 42;
    cv::essential::EssentialReport r3;
    const cv::Mat E3 =
        cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, m3, &r3);
    ASSERT_EQ(E3.rows, 3);
    EXPECT_LT(essentialDistance(cv::Matx33d(E3), s.E), 0.05);
}

} // namespace
