// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The public names under the using-directives OpenCV users write. `using namespace cv;` and
// `using namespace cv::essential;` together, with cv:: arguments (so that argument-dependent lookup
// also finds every cv:: function): the module's functions must be callable unqualified without
// ambiguity. That this file compiles is half the test; the other half checks that the original
// spelling cv::essential::recoverPose, kept for existing callers, is the same function.

#include "opencv2/essential.hpp"
#include "synthetic_scene.hpp"

#include "essential_test.hpp"
#include <opencv2/calib3d.hpp>

#include <vector>

namespace {

using namespace cv;
using namespace cv::essential;

essential_test::SyntheticScene scene()
{
    essential_test::SceneConfig cfg;
    cfg.numPoints = 200;
    cfg.inlierRatio = 0.7;
    return essential_test::makeScene(cfg, 11);
}

TEST(ApiNames, UnqualifiedCallsUnderBothUsingDirectivesCompileAndRun)
{
    const essential_test::SyntheticScene s = scene();
    const Mat K(s.K);
    Mat mask, R, t;
    // The trap this guards against: with both directives, an unqualified
    // recoverPose(E, p1, p2, K, R, t) is ambiguous between cv::recoverPose and
    // cv::essential::recoverPose (same signature). The Iter names cannot collide.
    const Mat E = findEssentialMatIter(s.px1, s.px2, K, RANSAC, 0.999, 1.0, 1000, mask);
    ASSERT_FALSE(E.empty());
    const int inFront = recoverPoseIter(E, s.px1, s.px2, K, R, t, mask);
    EXPECT_GT(inFront, 0.6 * s.numInliers);
    EXPECT_LT(essential_test::rotationErrorDeg(Matx33d(R), s.R), 1.0);
    EXPECT_LT(essential_test::translationErrorDeg(Vec3d(t), s.t), 3.0);

    // The module's own form and its typed settings, unqualified too.
    EssentialParams params;
    params.score = SCORE_METHOD_MSAC;
    params.engine = ENGINE_ADAPTIVE;
    params.sampler = SAMPLING_UNIFORM;
    params.sampleBudget = BUDGET_OPENCV_TIME;
    params.maxIterations = 1000;
    EssentialReport report;
    const Mat E2 = findEssentialMatIter(s.px1, s.px2, K, params, noArray(), &report);
    ASSERT_FALSE(E2.empty());
    EXPECT_TRUE(report.poseRecovered);
    EXPECT_LT(essential_test::rotationErrorDeg(report.R, s.R), 1.0);
}

TEST(ApiNames, OriginalRecoverPoseSpellingIsTheSameFunction)
{
    const essential_test::SyntheticScene s = scene();
    const Mat K(s.K);
    Mat mask;
    const Mat E = findEssentialMatIter(s.px1, s.px2, K, RANSAC, 0.999, 1.0, 1000, mask);
    ASSERT_FALSE(E.empty());
    Mat R1, t1, m1 = mask.clone(), R2, t2, m2 = mask.clone();
    const int n1 = cv::essential::recoverPose(E, s.px1, s.px2, K, R1, t1, m1);
    const int n2 = recoverPoseIter(E, s.px1, s.px2, K, R2, t2, m2);
    EXPECT_EQ(n1, n2);
    EXPECT_EQ(cv::norm(R1, R2, NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(t1, t2, NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(m1, m2, NORM_INF), 0.0);

    Mat Ea, Ra, ta, ma, Eb, Rb, tb, mb;
    const Mat noDist;
    const int na = cv::essential::recoverPose(s.px1, s.px2, K, noDist, K, noDist, Ea, Ra, ta,
                                              RANSAC, 0.999, 1.0, ma);
    const int nb =
        recoverPoseIter(s.px1, s.px2, K, noDist, K, noDist, Eb, Rb, tb, RANSAC, 0.999, 1.0, mb);
    EXPECT_EQ(na, nb);
    EXPECT_EQ(cv::norm(Ea, Eb, NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(ma, mb, NORM_INF), 0.0);
}

} // namespace
