// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// termination::NoiseAdaptedRatio and scoring::distanceBands: the correct matches' ratio when the
// threshold lies below the noise, and the stop it allows the adaptive MSAC search (the wide camera
// with OpenCV's default 1 px threshold, issue 27).

#include "refinement_fixtures.hpp"
#include "scoring/msac_score.hpp"
#include "synthetic_scene.hpp"
#include "termination/noise_adapted_ratio.hpp"
#include "termination/opencv_time_budget.hpp"

#include "essential_test.hpp"

#include <opencv2/essential.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

using cv::essential::termination::NoiseAdaptedRatio;
using essential_test::makeScene;
using essential_test::problemOf;
using essential_test::SceneConfig;
using essential_test::SyntheticScene;
using essential_test::wideCameraConfig;

constexpr int kBands = NoiseAdaptedRatio::kBands;

/** Band counts of distances (in thresholds) as distanceBands defines them. */
std::vector<int> bandsOf(const std::vector<double>& distances)
{
    std::vector<int> counts(kBands, 0);
    for (double d : distances) {
        const int band = d <= 1.0 ? 0 : static_cast<int>(std::ceil(d)) - 1;
        if (band < kBands) ++counts[static_cast<size_t>(band)];
    }
    return counts;
}

/** `correct` distances |N(0, sigma)| and `outliers` uniform in [0, 300] (thresholds). */
std::vector<double> mixture(int correct, double sigma, int outliers, uint64_t seed)
{
    std::mt19937_64 g(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    std::uniform_real_distribution<double> far(0.0, 300.0);
    std::vector<double> d;
    for (int i = 0; i < correct; ++i)
        d.push_back(std::abs(noise(g)));
    for (int i = 0; i < outliers; ++i)
        d.push_back(far(g));
    return d;
}

int inliersOf(const std::vector<double>& d)
{
    int count = 0;
    for (double x : d)
        count += x <= 1.0;
    return count;
}

TEST(NoiseAdaptedRatio, DistanceBandsCountEachPointInItsBand)
{
    // The bands from the distances squaredDistances gives, computed here by definition; the
    // threshold is chosen so that bands hold points of several widths.
    SceneConfig cfg = wideCameraConfig();
    cfg.inlierRatio = 0.5;
    for (uint64_t seed = 1; seed <= 3; ++seed) {
        const SyntheticScene s = makeScene(cfg, seed);
        const cv::essential::Problem problem = problemOf(s);
        const cv::essential::InlierTest test{1.0 / cfg.focal};
        std::vector<double> squared(static_cast<size_t>(problem.size()));
        cv::essential::scoring::squaredDistances(s.E, problem, test, squared.data());
        std::vector<double> distances;
        for (double e : squared)
            distances.push_back(std::sqrt(e) / test.threshold);
        int counts[kBands];
        cv::essential::scoring::distanceBands(s.E, problem, test, kBands, counts);
        const std::vector<int> expected = bandsOf(distances);
        for (int k = 0; k < kBands; ++k)
            EXPECT_EQ(counts[k], expected[static_cast<size_t>(k)]) << "band " << k;
        // Band 0 is the inlier count of the threshold test.
        std::vector<uchar> mask(static_cast<size_t>(problem.size()));
        EXPECT_EQ(counts[0], cv::essential::scoring::inlierMask(s.E, problem, test, mask.data()));
    }
}

TEST(NoiseAdaptedRatio, IsTheInlierRatioWhenTheThresholdIsAboveTheNoise)
{
    // Noise deviations of 0.4 and 0.7 thresholds (a threshold at 2.5 and 1.4 deviations): bands 1
    // and 2 hold 1% and 19% of band 0, below kSpread, and the apparent ratio is returned exactly.
    for (double sigma : {0.4, 0.7})
        for (uint64_t seed = 1; seed <= 20; ++seed) {
            const std::vector<double> d = mixture(250, sigma, 250, seed);
            const std::vector<int> counts = bandsOf(d);
            const int inliers = inliersOf(d);
            EXPECT_EQ(NoiseAdaptedRatio::ratio(counts.data(), 500, inliers / 500.0),
                      inliers / 500.0)
                << "sigma " << sigma << ", seed " << seed;
        }
    // No correct matches at all: outliers alone.
    for (uint64_t seed = 1; seed <= 20; ++seed) {
        const std::vector<double> d = mixture(0, 1.0, 500, seed);
        const std::vector<int> counts = bandsOf(d);
        EXPECT_EQ(NoiseAdaptedRatio::ratio(counts.data(), 500, inliersOf(d) / 500.0),
                  inliersOf(d) / 500.0);
    }
}

TEST(NoiseAdaptedRatio, FindsTheCorrectMatchesWhenTheThresholdIsBelowTheNoise)
{
    // The wide camera at 1 px (deviation 2.35 thresholds along the epipolar normal) and a wider
    // case (3 thresholds), at 50% and 30% correct: the apparent ratio is 11-20% and 7-12%; the
    // estimate must reach 85% of the true ratio and never pass it by more than 3% of the points
    // (measured on these seeds: 0.47-0.51 at 50%, 0.28-0.32 at 30%).
    for (double sigma : {2.35, 3.0})
        for (double truth : {0.5, 0.3})
            for (uint64_t seed = 1; seed <= 20; ++seed) {
                const int correct = static_cast<int>(500 * truth);
                const std::vector<double> d = mixture(correct, sigma, 500 - correct, seed);
                const std::vector<int> counts = bandsOf(d);
                const int inliers = inliersOf(d);
                const double r = NoiseAdaptedRatio::ratio(counts.data(), 500, inliers / 500.0);
                EXPECT_GT(r, 0.85 * truth) << sigma << " " << truth << " seed " << seed;
                EXPECT_LT(r, truth + 0.03) << sigma << " " << truth << " seed " << seed;
                EXPECT_GT(r, 1.5 * inliers / 500.0);
            }
}

/** The drop-in's defaults (EssentialParams overload) on 20 wide-camera scenes (1.66 px noise,
threshold 1 px, N = 500) at `ratio` correct: each pose is asserted within 2 / 5 degrees; returns
the samples each call drew. */
std::vector<int> wideCameraSamples(double ratio)
{
    SceneConfig cfg = wideCameraConfig();
    cfg.inlierRatio = ratio;
    std::vector<int> samples;
    for (uint64_t seed = 0; seed < 20; ++seed) {
        const SyntheticScene s = makeScene(cfg, 1000003ULL + seed);
        cv::essential::EssentialParams params;
        cv::essential::EssentialReport report;
        cv::Mat mask;
        const cv::Mat E =
            cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, mask, &report);
        EXPECT_FALSE(E.empty()) << "seed " << seed;
        EXPECT_TRUE(report.poseRecovered) << "seed " << seed;
        samples.push_back(report.iterations);
        if (!report.poseRecovered) continue;
        EXPECT_LT(essential_test::rotationErrorDeg(report.R, s.R), 2.0) << "seed " << seed;
        EXPECT_LT(essential_test::translationErrorDeg(report.t, s.t), 5.0) << "seed " << seed;
    }
    return samples;
}

TEST(NoiseAdaptedRatio, WideCameraAtTheDefaultThresholdStopsAtTheConfidenceCap)
{
    // 50% correct. Before the noise-adapted stop the apparent ratio of about 22% made the search
    // extend its budget: 1 162 to 3 518 samples on these seeds, every one of the 20. Now it stops
    // within OpenCV's own cap, with the pose as reliable (all 20 within 2 / 5 degrees). Not every
    // call: a best model that is still off when the rule is read spreads the correct matches'
    // distances like noise, and the search then extends. Measured on 200 other wide-camera scenes
    // (N = 500, 50%), 8 calls of 200 extended with the polish on all points and 7 with the polish
    // on 100 (loSampleSize); on these 20 seeds, 196 to 276 samples with all points, and 196 to 280
    // but seed 10 (1 247) with 100. So at most two of the 20 may pass the cap, and the median is
    // far below it.
    const int maxIterations = cv::essential::EssentialParams().maxIterations;
    std::vector<int> samples = wideCameraSamples(0.5);
    int beyond = 0;
    for (size_t i = 0; i < samples.size(); ++i)
        beyond += samples[i] >= maxIterations;
    EXPECT_LE(beyond, 2);
    std::nth_element(samples.begin(), samples.begin() + 10, samples.end());
    EXPECT_LT(samples[10], maxIterations / 3);
}

TEST(NoiseAdaptedRatio, WideCameraAtThirtyPercentShortensTheExtension)
{
    // At 30% correct the correct matches' ratio still needs more samples than the confidence cap,
    // so the search extends its budget; once the best model's basin is confirmed the extension
    // samples for that ratio instead of the apparent 9-12%. Before, every one of these scenes ran
    // the whole OpenCV-time budget (20 086 samples at N = 500); measured now: 1 004 to 11 299,
    // median 1 883 over 100 scenes, all within 2 / 5 degrees. Asserted: the median of 20 below a
    // quarter of the budget, and every pose within 2 / 5 degrees.
    const int budget = cv::essential::termination::opencvTimeSamples(
        cv::essential::EssentialParams().maxIterations, 500);
    std::vector<int> samples = wideCameraSamples(0.3);
    std::sort(samples.begin(), samples.end());
    EXPECT_LT(samples[samples.size() / 2], budget / 4);
}

} // namespace
