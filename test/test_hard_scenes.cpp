// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The hard-scene generators (test/hard_scenes.hpp) keep their promises: sizes and inlier counts,
// the true E fits the true matches and not the wrong ones, the dominant plane is a plane, shifted
// groups are consistent wrong models, clusters stay in their discs, every point is in both images,
// and descriptor distances follow their kind.
//
// Tolerances: with noise sigma on all four coordinates, the Sampson distance of a true match is
// about |N(0, sigma)|, so P(> 3 sigma) = 0.27% and P(> 5 sigma) < 1e-6: at least 98% below
// 3 sigma and all below 5 sigma. A homography fitted by least squares to noisy true matches leaves
// an image-2 transfer error of about sigma * sqrt(2) per axis; P(radius > 5 sigma) = exp(-6.25)
// = 0.2%, so at least 97% within 5 sigma.

#include "hard_scenes.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "essential_test.hpp"

#include <cmath>
#include <vector>

namespace {

using namespace essential_test;

const double kRatios[] = {0.05, 0.10, 0.15, 0.25};

void expectCommonPromises(const HardScene& s, const HardSceneConfig& cfg)
{
    const size_t n = static_cast<size_t>(cfg.numPoints);
    ASSERT_EQ(s.px1.size(), n);
    ASSERT_EQ(s.px2.size(), n);
    ASSERT_EQ(s.x1.size(), n);
    ASSERT_EQ(s.inlier.size(), n);
    ASSERT_EQ(s.role.size(), n);
    ASSERT_EQ(s.distance.size(), n);
    EXPECT_EQ(s.numInliers, static_cast<int>(std::lround(cfg.numPoints * cfg.inlierRatio)));
    int counted = 0, inliersFit = 0, uniform = 0;
    double inlierDist = 0, uniformDist = 0;
    const double sigma = cfg.noisePx;
    for (size_t i = 0; i < n; ++i) {
        for (const cv::Point2d& p : {s.px1[i], s.px2[i]}) {
            EXPECT_TRUE(p.x >= 0 && p.y >= 0 && p.x < cfg.width && p.y < cfg.height)
                << "point " << i << " at " << p << " outside the image";
        }
        // Normalised and pixel coordinates agree.
        EXPECT_NEAR(s.K(0, 0) * s.x1[i].x + s.K(0, 2), s.px1[i].x, 1e-9);
        EXPECT_NEAR(s.K(1, 1) * s.x2[i].y + s.K(1, 2), s.px2[i].y, 1e-9);
        EXPECT_GE(s.distance[i], 0.0f);
        const double d = sampsonPx(s.F, s.px1[i], s.px2[i]);
        if (s.inlier[i]) {
            ++counted;
            inliersFit += d < 3 * sigma;
            EXPECT_LT(d, 5 * sigma) << "inlier " << i;
            inlierDist += s.distance[i];
        } else {
            EXPECT_GE(d, cfg.outlierMinSigmas * sigma) << "outlier " << i << " fits the true E";
        }
        if (s.role[i] == MatchRole::UniformOutlier) {
            ++uniform;
            uniformDist += s.distance[i];
        }
    }
    EXPECT_EQ(counted, s.numInliers);
    EXPECT_GE(inliersFit, 0.98 * counted);
    // The true pose: R a rotation within the configured angle, t of unit length, E = [t]x R.
    EXPECT_NEAR(cv::norm(s.t), 1.0, 1e-12);
    EXPECT_LE(rotationErrorDeg(s.R, cv::Matx33d::eye()), cfg.maxRotationDeg + 1e-9);
    EXPECT_LT(cv::norm(s.R.t() * s.R - cv::Matx33d::eye()), 1e-12);
    // Descriptor distances: means of N(35, 12) over >= 50 draws are within 3 sd = 5.1 of 35
    // (clamping at 0 moves them by < 0.01).
    ASSERT_GE(counted, 50);
    EXPECT_NEAR(inlierDist / counted, cfg.goodDistanceMean,
                3 * cfg.distanceSigma / std::sqrt(50.0));
    if (uniform >= 50) {
        EXPECT_NEAR(uniformDist / uniform, cfg.badDistanceMean,
                    3 * cfg.distanceSigma / std::sqrt(50.0));
    }
}

/** Fraction of the matches (a[i], b[i]) whose image-2 transfer error by H is below maxPx. */
double transferFraction(const cv::Matx33d& H, const std::vector<cv::Point2d>& a,
                        const std::vector<cv::Point2d>& b, double maxPx)
{
    int ok = 0;
    for (size_t i = 0; i < a.size(); ++i)
        ok += cv::norm(applyHomography(H, a[i]) - b[i]) < maxPx;
    return a.empty() ? 0.0 : double(ok) / a.size();
}

TEST(HardScenes, DominantPlaneKeepsItsPromises)
{
    for (double ratio : kRatios) {
        for (uint64_t seed = 1; seed <= 3; ++seed) {
            SCOPED_TRACE(testing::Message() << "ratio " << ratio << " seed " << seed);
            DominantPlaneConfig cfg;
            cfg.inlierRatio = ratio;
            const HardScene s = makeDominantPlane(cfg, seed);
            expectCommonPromises(s, cfg);
            std::vector<cv::Point2d> plane1, plane2, off1, off2;
            for (size_t i = 0; i < s.px1.size(); ++i) {
                if (s.role[i] == MatchRole::PlaneInlier) {
                    plane1.push_back(s.px1[i]);
                    plane2.push_back(s.px2[i]);
                } else if (s.role[i] == MatchRole::Inlier) {
                    off1.push_back(s.px1[i]);
                    off2.push_back(s.px2[i]);
                }
            }
            EXPECT_EQ(static_cast<int>(plane1.size()),
                      static_cast<int>(std::lround(s.numInliers * cfg.planeFraction)));
            // A homography fitted to the plane's matches fits them, and it is the plane's.
            const cv::Mat Hfit = cv::findHomography(plane1, plane2, 0);
            ASSERT_FALSE(Hfit.empty());
            const cv::Matx33d H(Hfit);
            EXPECT_GE(transferFraction(H, plane1, plane2, 5 * cfg.noisePx), 0.97);
            EXPECT_GE(transferFraction(s.planeHomography, plane1, plane2, 5 * cfg.noisePx), 0.97);
            // ... and not the off-plane inliers (generated >= 6 sigma off it; noise moves them by
            // about 1.4 sigma, so nearly all stay beyond 3 sigma).
            EXPECT_LE(transferFraction(H, off1, off2, 3 * cfg.noisePx), 0.1);
            // The plane fills a good part of image 1: its points' bounding box covers >= 25%.
            const cv::Rect box =
                cv::boundingRect(std::vector<cv::Point2f>(plane1.begin(), plane1.end()));
            EXPECT_GE(box.area(), 0.25 * cfg.width * cfg.height);
            // Both cameras see the plane's front: the same side of it.
            const cv::Vec3d C2 = -(s.R.t() * (s.baseline * s.t));
            EXPECT_GT((s.planeNormal.dot(C2) - s.planeOffset) * -s.planeOffset, 0.0);
        }
    }
}

TEST(HardScenes, RepeatedStructureGroupsAreConsistentWrongModels)
{
    for (double ratio : kRatios) {
        for (uint64_t seed = 1; seed <= 3; ++seed) {
            SCOPED_TRACE(testing::Message() << "ratio " << ratio << " seed " << seed);
            RepeatedStructureConfig cfg;
            cfg.inlierRatio = ratio;
            const HardScene s = makeRepeatedStructure(cfg, seed);
            expectCommonPromises(s, cfg);
            ASSERT_EQ(static_cast<int>(s.groupOffsets.size()), cfg.numGroups);
            const int outliers = cfg.numPoints - s.numInliers;
            int shifted = 0;
            double shiftedDist = 0;
            for (int gi = 0; gi < cfg.numGroups; ++gi) {
                const double period = cv::norm(s.groupOffsets[gi]);
                EXPECT_GE(period, cfg.minPeriodPx);
                EXPECT_LE(period, cfg.maxPeriodPx);
                std::vector<cv::Point2d> a, b;
                int fitsShifted = 0;
                for (size_t i = 0; i < s.px1.size(); ++i) {
                    if (s.role[i] != MatchRole::ShiftedOutlier || s.group[i] != gi) continue;
                    a.push_back(s.px1[i]);
                    b.push_back(s.px2[i]);
                    shiftedDist += s.distance[i];
                    // In its disc (noise moves a point by < 5 sigma).
                    EXPECT_LE(cv::norm(s.px1[i] - s.groupCentres[gi]),
                              s.groupRadiusPx + 5 * cfg.noisePx);
                    // Undoing the group's offset gives a true match.
                    fitsShifted +=
                        sampsonPx(s.F, s.px1[i], s.px2[i] - s.groupOffsets[gi]) < 3 * cfg.noisePx;
                }
                ASSERT_GE(a.size(), 20u);
                shifted += static_cast<int>(a.size());
                EXPECT_GE(fitsShifted, 0.98 * a.size());
                // One homography explains the whole group: a consistent wrong model.
                const cv::Mat Hfit = cv::findHomography(a, b, 0);
                ASSERT_FALSE(Hfit.empty());
                EXPECT_GE(transferFraction(cv::Matx33d(Hfit), a, b, 5 * cfg.noisePx), 0.97);
            }
            EXPECT_EQ(shifted, static_cast<int>(std::lround(outliers * cfg.shiftedFraction)));
            // Shifted outliers look like inliers: mean distance near the good mean.
            EXPECT_NEAR(shiftedDist / shifted, cfg.goodDistanceMean,
                        3 * cfg.distanceSigma / std::sqrt(double(shifted)));
        }
    }
}

TEST(HardScenes, ClusteredInliersStayInTheirDiscs)
{
    for (double ratio : kRatios) {
        for (uint64_t seed = 1; seed <= 3; ++seed) {
            SCOPED_TRACE(testing::Message() << "ratio " << ratio << " seed " << seed);
            ClusteredInliersConfig cfg;
            cfg.inlierRatio = ratio;
            const HardScene s = makeClusteredInliers(cfg, seed);
            expectCommonPromises(s, cfg);
            ASSERT_EQ(static_cast<int>(s.clusterCentres.size()), cfg.numClusters);
            EXPECT_NEAR(s.clusterRadiusPx, cfg.clusterRadiusFraction * cfg.width, 1e-9);
            std::vector<int> perCluster(cfg.numClusters, 0);
            for (size_t i = 0; i < s.px1.size(); ++i) {
                if (!s.inlier[i]) continue;
                ASSERT_GE(s.group[i], 0);
                ASSERT_LT(s.group[i], cfg.numClusters);
                ++perCluster[s.group[i]];
                EXPECT_LE(cv::norm(s.px1[i] - s.clusterCentres[s.group[i]]),
                          s.clusterRadiusPx + 5 * cfg.noisePx);
            }
            for (int c : perCluster)
                EXPECT_LE(std::abs(c - s.numInliers / cfg.numClusters), 1);
        }
    }
}

TEST(HardScenes, SameSeedSameSceneOtherSeedOtherScene)
{
    DominantPlaneConfig cfg;
    const HardScene a = makeDominantPlane(cfg, 7), b = makeDominantPlane(cfg, 7);
    const HardScene c = makeDominantPlane(cfg, 8);
    ASSERT_EQ(a.px1.size(), b.px1.size());
    for (size_t i = 0; i < a.px1.size(); ++i) {
        EXPECT_EQ(a.px1[i], b.px1[i]);
        EXPECT_EQ(a.px2[i], b.px2[i]);
        EXPECT_EQ(a.distance[i], b.distance[i]);
    }
    EXPECT_GT(essentialDistance(a.E, c.E), 1e-3);
}

} // namespace
