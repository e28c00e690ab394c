// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The threshold the LMedS engine derives from the data: 2.5 robust standard deviations of the
// median Sampson error (with the finite-sample correction 1 + 5 / (n - p)), never below 0.001
// normalised units, as cv::findEssentialMat's LMedS (OpenCV 4.6, calib3d/src/ptsetreg.cpp); and
// no division by zero when the number of points equals the solver's sample size.

#include "input/problem.hpp"
#include "scoring/msac_score.hpp"
#include "search/search.hpp"
#include "synthetic_scene.hpp"

#include <opencv2/essential.hpp>

#include "essential_test.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using essential_test::makeScene;
using essential_test::SceneConfig;
using essential_test::SyntheticScene;

/** Sampson distance (not squared) of a normalised correspondence to E. */
double sampson(const cv::Matx33d& E, const cv::Point2d& a, const cv::Point2d& b)
{
    const cv::Vec3d x1(a.x, a.y, 1.0), x2(b.x, b.y, 1.0);
    const cv::Vec3d l2 = E * x1, l1 = E.t() * x2;
    const double r = x2.dot(l2);
    return std::abs(r) / std::sqrt(l2[0] * l2[0] + l2[1] * l2[1] + l1[0] * l1[0] + l1[1] * l1[1]);
}

/** Moves the second point of a correspondence across its epipolar line until its Sampson distance
to E is `target` (normalised units). */
cv::Point2d atSampsonDistance(const cv::Matx33d& E, const cv::Point2d& a, const cv::Point2d& b,
                              double target)
{
    const cv::Vec3d l = E * cv::Vec3d(a.x, a.y, 1.0);
    const cv::Point2d normal = cv::Point2d(l[0], l[1]) * (1.0 / std::hypot(l[0], l[1]));
    // The distance grows linearly with the shift, up to the small change of the denominator:
    // two secant steps land within 1e-9 of the target.
    double shift = target;
    for (int k = 0; k < 2; ++k)
        shift *= target / sampson(E, a, b + shift * normal);
    return b + shift * normal;
}

TEST(LmedsThreshold, FloorOfOneThousandthAsOpenCV)
{
    // Noise-free inliers, so that the median error is at the round-off level and only the floor
    // decides: 20 points moved to a Sampson distance of 0.0005 (a quarter pixel at f = 500) are
    // inliers, 20 moved to 0.002 are not, for cv::findEssentialMat's LMEDS as for ours.
    SceneConfig cfg;
    cfg.numPoints = 120;
    cfg.inlierRatio = 1.0;
    cfg.noiseSigma = 1e-9;
    cfg.maxDepth = 20.0;
    SyntheticScene s = makeScene(cfg, 31);
    const double f = s.K(0, 0);
    for (int i = 0; i < 40; ++i) {
        const double target = i < 20 ? 0.0005 : 0.002;
        s.x2[i] = atSampsonDistance(s.E, s.x1[i], s.x2[i], target);
        ASSERT_NEAR(sampson(s.E, s.x1[i], s.x2[i]), target, 1e-9);
        s.px2[i] = cv::Point2d(f * s.x2[i].x + s.K(0, 2), f * s.x2[i].y + s.K(1, 2));
    }
    cv::Mat maskCv, maskUs;
    const cv::Mat K(s.K);
    const cv::Mat Ecv = cv::findEssentialMat(s.px1, s.px2, K, cv::LMEDS, 0.999, 1.0, 1000, maskCv);
    const cv::Mat Eus =
        cv::essential::findEssentialMatIter(s.px1, s.px2, K, cv::LMEDS, 0.999, 1.0, 1000, maskUs);
    ASSERT_FALSE(Ecv.empty());
    ASSERT_FALSE(Eus.empty());
    // Refined on all its inliers, the 20 moved ones included: close to, not exactly, the truth.
    EXPECT_LT(essential_test::essentialDistance(cv::Matx33d(Eus), s.E), 2e-3);
    for (int i = 0; i < cfg.numPoints; ++i) {
        const int expected = i < 20 || i >= 40 ? 1 : 0;
        EXPECT_EQ(maskUs.at<uchar>(i), expected) << i;
        EXPECT_EQ(maskCv.at<uchar>(i), expected) << i;
    }
}

TEST(LmedsThreshold, PointsAsManyAsTheSampleSize)
{
    // The robust solver draws 10 points: with exactly 10, every sample is every point and
    // n - p = 0 in the finite-sample correction, which used to divide by zero (an infinite or NaN
    // threshold). The correction is taken at n - p = 1.
    SceneConfig cfg;
    cfg.numPoints = 10;
    cfg.inlierRatio = 1.0;
    cfg.noiseSigma = 1e-5; // 0.005 px
    cfg.maxDepth = 20.0;
    const SyntheticScene s = makeScene(cfg, 32);
    cv::essential::EssentialParams params;
    params.solver = "robust";
    params.score = cv::SCORE_METHOD_LMEDS;
    cv::Mat mask;
    cv::essential::EssentialReport report;
    const cv::Mat E =
        cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, mask, &report);
    ASSERT_FALSE(E.empty());
    ASSERT_TRUE(cv::checkRange(E));
    EXPECT_LT(essential_test::essentialDistance(cv::Matx33d(E), s.E), 1e-3);
    EXPECT_EQ(cv::countNonZero(mask), 10);
}

/** The threshold searchLmeds derives: 2.5 * 1.4826 * (1 + 5 / max(n - p, 1)) * sqrt(median of the
squared Sampson errors of its E), at least 0.001. */
double expectedThreshold(const cv::essential::Problem& problem, const cv::Matx33d& E,
                         int sampleSize)
{
    const int n = problem.size();
    std::vector<double> errors(static_cast<size_t>(n));
    cv::essential::scoring::sampsonErrors(E, problem, errors.data());
    std::nth_element(errors.begin(), errors.begin() + n / 2, errors.end());
    const double correction = 1.0 + 5.0 / std::max(n - sampleSize, 1);
    return std::max(2.5 * 1.4826 * correction * std::sqrt(errors[static_cast<size_t>(n / 2)]),
                    0.001);
}

TEST(LmedsThreshold, FormulaAtEveryNumberOfPoints)
{
    // n = p = 10 used to give an infinite (or, with a zero median, NaN) threshold.
    SceneConfig cfg;
    cfg.inlierRatio = 0.8;
    cfg.noiseSigma = 0.002; // a median well above the floor
    for (const int n : {10, 11, 20, 60}) {
        SCOPED_TRACE(n);
        cfg.numPoints = n;
        const SyntheticScene s = makeScene(cfg, 33);
        const cv::essential::Problem problem = cv::essential::makeProblem(s.x1, s.x2);
        const cv::Ptr<cv::essential::EssentialSolver> solver =
            cv::essential::createSolver("robust");
        cv::RNG rng(1);
        cv::essential::search::SearchSettings settings;
        settings.test.threshold = 1e-3;
        settings.maxIters = 50;
        const cv::essential::search::SearchResult r =
            cv::essential::search::searchLmeds(problem, *solver, rng, settings);
        ASSERT_TRUE(r.found);
        ASSERT_TRUE(std::isfinite(r.threshold));
        EXPECT_NEAR(r.threshold, expectedThreshold(problem, r.E, solver->sampleSize()),
                    1e-12 * r.threshold);
        EXPECT_GT(r.threshold, 0.001); // the median decides here, not the floor
    }
}

} // namespace
