// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// With exactly five points the drop-in returns every distinct root stacked (as
// cv::findEssentialMat does). Distinct means distinct up to sign: E and -E are one essential
// matrix, also when the sign convention is ambiguous (two entries of equal magnitude).

#include "synthetic_scene.hpp"

#include <opencv2/essential.hpp>

#include "essential_test.hpp"

namespace {

/** Five noise-free correspondences of a scene with rotation R and translation direction t. */
void fivePoints(const cv::Matx33d& R, const cv::Vec3d& t, uint64_t seed,
                std::vector<cv::Point2d>& a, std::vector<cv::Point2d>& b)
{
    std::mt19937_64 g(seed);
    std::uniform_real_distribution<double> u(-0.8, 0.8), depth(2.0, 10.0);
    a.clear();
    b.clear();
    while (a.size() < 5) {
        const double z = depth(g);
        const cv::Vec3d X(u(g) * z, u(g) * z, z);
        const cv::Vec3d Y = R * X + 0.5 * t;
        if (Y[2] <= 0.5) continue;
        a.emplace_back(X[0] / X[2], X[1] / X[2]);
        b.emplace_back(Y[0] / Y[2], Y[1] / Y[2]);
    }
}

void expectNoTwoEqualUpToSign(const cv::Mat& stacked)
{
    ASSERT_EQ(stacked.rows % 3, 0);
    for (int i = 0; i < stacked.rows; i += 3)
        for (int j = i + 3; j < stacked.rows; j += 3) {
            const cv::Matx33d A(stacked.rowRange(i, i + 3).clone());
            const cv::Matx33d B(stacked.rowRange(j, j + 3).clone());
            EXPECT_GT(essential_test::essentialDistance(A, B), 1e-4)
                << "solutions " << i / 3 << " and " << j / 3 << " are the same up to sign";
        }
}

TEST(FivePointStack, TiedEntriesDoNotDuplicateARoot)
{
    // Forward motion without rotation: E = [e_z]x has the entries -1 and +1, a tie for the
    // largest magnitude, so the canonical sign flips between copies of the same root found from
    // different starts. gn runs 120 rotated copies of the problem (search/minimal_set.cpp), so it
    // finds the true root many times over.
    for (const char* solver : {"gn", "lm", "nister", "gn+nister"}) {
        SCOPED_TRACE(solver);
        for (uint64_t seed = 1; seed <= 5; ++seed) {
            std::vector<cv::Point2d> a, b;
            fivePoints(cv::Matx33d::eye(), cv::Vec3d(0, 0, 1), seed, a, b);
            cv::essential::EssentialParams params;
            params.solver = solver;
            params.threshold = 1e-3;
            cv::Mat mask;
            const cv::Mat E =
                cv::essential::findEssentialMatIter(a, b, cv::Mat::eye(3, 3, CV_64F), params, mask);
            ASSERT_FALSE(E.empty());
            expectNoTwoEqualUpToSign(E);
            const cv::Matx33d truth(0, -1, 0, 1, 0, 0, 0, 0, 0);
            double best = 1e9;
            for (int r = 0; r < E.rows; r += 3)
                best = std::min(best, essential_test::essentialDistance(
                                          cv::Matx33d(E.rowRange(r, r + 3).clone()), truth));
            EXPECT_LT(best, 1e-6) << "seed " << seed;
        }
    }
}

} // namespace
