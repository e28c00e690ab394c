// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// termination::BasinConfirmation: which hypotheses count as draws of the best model's basin, and
// the extended budget's confidence before and after the basin is confirmed.

#include "synthetic_scene.hpp"
#include "termination/basin_confirmation.hpp"

#include "essential_test.hpp"

#include <random>

namespace {

using cv::essential::termination::BasinConfirmation;
using essential_test::axisAngle;
using essential_test::randomUnit;
using essential_test::skewMatrix;

cv::Matx33d essentialOf(const cv::Vec3d& axis, double angle, const cv::Vec3d& t)
{
    return skewMatrix(t) * axisAngle(axis, angle);
}

TEST(BasinConfirmation, SameBasinIgnoresScaleAndSignAndSeparatesOtherPoses)
{
    std::mt19937_64 g(7);
    for (int trial = 0; trial < 200; ++trial) {
        SCOPED_TRACE(trial);
        const cv::Vec3d axis = randomUnit(g), t = randomUnit(g);
        const double angle = 0.2 + 0.002 * trial;
        const cv::Matx33d E = essentialOf(axis, angle, t);
        EXPECT_TRUE(BasinConfirmation::sameBasin(E, E));
        EXPECT_TRUE(BasinConfirmation::sameBasin(E, -3.0 * E));
        EXPECT_TRUE(BasinConfirmation::sameBasin(0.25 * E, E));
        // A pose one degree off (rotation and translation direction) is the same basin: the
        // unit-norm matrices differ by about 0.02.
        const double d = CV_PI / 180.0;
        const cv::Matx33d near =
            essentialOf(axis, angle + d, (t + d * randomUnit(g)) / cv::norm(t));
        EXPECT_TRUE(BasinConfirmation::sameBasin(near, E));
        // Translation direction 30 degrees off is another model.
        const cv::Vec3d u = randomUnit(g);
        const cv::Vec3d side = u - u.dot(t) * t;
        const double c = std::cos(30 * d), s = std::sin(30 * d);
        const cv::Vec3d t30 = c * t + s * side / cv::norm(side);
        EXPECT_FALSE(BasinConfirmation::sameBasin(essentialOf(axis, angle, t30), E));
    }
    EXPECT_FALSE(BasinConfirmation::sameBasin(cv::Matx33d::zeros(), cv::Matx33d::eye()));
    EXPECT_FALSE(BasinConfirmation::sameBasin(cv::Matx33d::eye(), cv::Matx33d::zeros()));
}

TEST(BasinConfirmation, ConfirmsAfterTheRefindsAndStartsAgainForANewBasin)
{
    const cv::Matx33d E = essentialOf(cv::Vec3d(0, 1, 0), 0.3, cv::Vec3d(1, 0, 0));
    const cv::Matx33d other = essentialOf(cv::Vec3d(0, 0, 1), 0.3, cv::Vec3d(0, 1, 0));
    const double confirmedConfidence = 0.5, cap = 0.999;
    BasinConfirmation basin;
    EXPECT_FALSE(basin.confirmed());
    EXPECT_EQ(basin.extendedConfidence(confirmedConfidence, cap),
              BasinConfirmation::kUnconfirmedConfidence);
    // Hypotheses of another basin do not count.
    EXPECT_FALSE(basin.offer(other, E));
    for (int i = 0; i < BasinConfirmation::kRefinds; ++i) {
        EXPECT_FALSE(basin.confirmed());
        EXPECT_TRUE(basin.offer(-2.0 * E, E));
    }
    EXPECT_TRUE(basin.confirmed());
    EXPECT_EQ(basin.extendedConfidence(confirmedConfidence, cap), confirmedConfidence);
    // Never above the caller's confidence.
    EXPECT_EQ(basin.extendedConfidence(0.9, 0.8), 0.8);
    basin.newBasin();
    EXPECT_FALSE(basin.confirmed());
    EXPECT_EQ(basin.extendedConfidence(confirmedConfidence, 0.95), 0.95);
}

} // namespace
