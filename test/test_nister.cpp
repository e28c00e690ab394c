// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The five-point solver "nister" (Rosten et al., Algorithm 4) on noise-free minimal problems: the
// generated constraint matrix, how often the true E is among the solutions for general, sideways,
// forward and short-baseline motion, that every solution is an exact essential matrix of its
// sample, the number of solutions against OpenCV's own five-point solver, and the whole estimate
// with solver = "nister".

#include "simd_dispatch.hpp" // ESSENTIAL_INLINE_INTO_CLONES, which nister_coefficients.inc uses
#include "solvers/nister_five_point.hpp"
#include "synthetic_scene.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/essential.hpp>

#include "essential_test.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace generated {
#include "solvers/nister_coefficients.inc"
} // namespace generated

namespace {

using cv::essential::solvers::NisterFivePointSolver;
using cv::essential::solvers::NisterSettings;
using essential_test::essentialDistance;
using essential_test::SyntheticScene;

enum class Motion {
    General,   //!< the paper's protocol (synthetic_scene.hpp defaults)
    Sideways,  //!< translation along +-x
    Forward,   //!< translation along the optic axis, camera moving forward
    ShortBase, //!< the paper's protocol with a baseline of 0.01
};

const char* motionName(Motion m)
{
    switch (m) {
    case Motion::General:
        return "general";
    case Motion::Sideways:
        return "sideways";
    case Motion::Forward:
        return "forward";
    case Motion::ShortBase:
        return "baseline 0.01";
    }
    return "?";
}

/** Five noise-free correspondences. General motion is makeScene() itself; the others follow the
same protocol (rotation up to 35 degrees about a uniform axis, points uniform in the image and in
inverse depth from depth 1 to 1000, visible in both views) with the translation chosen. */
SyntheticScene minimalProblem(Motion motion, uint64_t seed)
{
    essential_test::SceneConfig cfg;
    cfg.numPoints = 5;
    cfg.inlierRatio = 1.0;
    cfg.noiseSigma = 0.0;
    if (motion == Motion::General) return essential_test::makeScene(cfg, seed);

    std::mt19937_64 g(seed * 7919 + static_cast<uint64_t>(motion));
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    SyntheticScene s;
    s.R = essential_test::axisAngle(essential_test::randomUnit(g),
                                    uni(g) * cfg.maxRotationDeg * CV_PI / 180.0);
    s.baseline = cfg.minTranslation + uni(g) * (cfg.maxTranslation - cfg.minTranslation);
    if (motion == Motion::Sideways)
        s.t = cv::Vec3d(uni(g) < 0.5 ? -1.0 : 1.0, 0.0, 0.0);
    else if (motion == Motion::Forward)
        s.t = cv::Vec3d(0.0, 0.0, -1.0); // X2 = R X1 + b t: the scene comes closer
    else {
        s.t = essential_test::randomUnit(g);
        s.baseline = 0.01;
    }
    s.E = essential_test::skewMatrix(s.t) * s.R;
    while (s.x1.size() < 5) {
        const double u = 2.0 * uni(g) - 1.0, v = 2.0 * uni(g) - 1.0;
        const double depth =
            1.0 / (1.0 / cfg.maxDepth + uni(g) * (1.0 / cfg.minDepth - 1.0 / cfg.maxDepth));
        const cv::Vec3d X2 = s.R * cv::Vec3d(u * depth, v * depth, depth) + s.baseline * s.t;
        if (X2[2] <= 1e-9) continue;
        const double u2 = X2[0] / X2[2], v2 = X2[1] / X2[2];
        if (std::abs(u2) > 1.0 || std::abs(v2) > 1.0) continue;
        s.x1.push_back(cv::Point2d(u, v));
        s.x2.push_back(cv::Point2d(u2, v2));
    }
    return s;
}

/** OpenCV's five-point solver: with exactly five points cv::findEssentialMat returns all its
solutions stacked as a 3n x 3 Mat. */
std::vector<cv::Matx33d> openCvSolutions(const SyntheticScene& s)
{
    const cv::Mat E =
        cv::findEssentialMat(s.x1, s.x2, cv::Mat::eye(3, 3, CV_64F), cv::RANSAC, 0.999, 1e-3);
    std::vector<cv::Matx33d> out;
    for (int i = 0; i + 3 <= E.rows; i += 3)
        out.push_back(cv::Matx33d(E.rowRange(i, i + 3)));
    return out;
}

struct Measurement
{
    int problems = 0;
    int found = 0, foundCv = 0; //!< problems where the true E is among the solutions
    long solutions = 0, solutionsCv = 0;
    long cvRootsMissed = 0;          //!< OpenCV solutions with none of ours within 1e-6
    double worstEpipolar = 0.0;      //!< max |q2^T E q1| over all solutions and points
    double worstEssential = 0.0;     //!< max essentialResidual() over all solutions
    long inexact = 0, inexactCv = 0; //!< solutions with essentialResidual() above 1e-6
    double rate() const { return found / double(problems); }
    double rateCv() const { return foundCv / double(problems); }
    double meanSolutions() const { return solutions / double(problems); }
    double meanSolutionsCv() const { return solutionsCv / double(problems); }
};

/** How far E is from an essential matrix: max(|det E|, ||2 E E^T E - trace(E E^T) E||_F) after
scaling E to Frobenius norm sqrt(2). */
double essentialResidual(cv::Matx33d E)
{
    E *= std::sqrt(2.0) / cv::norm(E);
    const cv::Matx33d EEt = E * E.t();
    return std::max(std::abs(cv::determinant(E)), cv::norm(2.0 * EEt * E - cv::trace(EEt) * E));
}

bool contains(const cv::Matx33d* E, int n, const cv::Matx33d& target, double tolerance)
{
    for (int i = 0; i < n; ++i)
        if (essentialDistance(E[i], target) < tolerance) return true;
    return false;
}

Measurement measure(Motion motion, int problems, double tolerance, bool withOpenCv,
                    const NisterSettings& settings = NisterSettings())
{
    NisterFivePointSolver solver(settings);
    cv::RNG rng(3);
    Measurement m;
    m.problems = problems;
    for (int t = 0; t < problems; ++t) {
        const SyntheticScene s = minimalProblem(motion, 70000 + static_cast<uint64_t>(t));
        cv::Matx33d E[10];
        const int n = solver.solve(s.x1.data(), s.x2.data(), rng, E);
        EXPECT_GE(n, 0);
        EXPECT_LE(n, solver.maxSolutions());
        m.solutions += n;
        m.found += contains(E, n, s.E, tolerance);
        for (int k = 0; k < n; ++k) {
            for (int i = 0; i < 5; ++i) {
                const cv::Vec3d q1(s.x1[i].x, s.x1[i].y, 1.0), q2(s.x2[i].x, s.x2[i].y, 1.0);
                m.worstEpipolar = std::max(m.worstEpipolar, std::abs(q2.dot(E[k] * q1)));
            }
            const double r = essentialResidual(E[k]);
            m.worstEssential = std::max(m.worstEssential, r);
            m.inexact += r > 1e-6;
        }
        if (withOpenCv) {
            const std::vector<cv::Matx33d> cv5 = openCvSolutions(s);
            m.solutionsCv += static_cast<long>(cv5.size());
            m.foundCv += contains(cv5.data(), static_cast<int>(cv5.size()), s.E, tolerance);
            for (const cv::Matx33d& F : cv5) {
                m.cvRootsMissed += !contains(E, n, F, 1e-4);
                m.inexactCv += essentialResidual(F) > 1e-6;
            }
        }
    }
    return m;
}

void report(Motion motion, double tolerance, const Measurement& m)
{
    std::printf("[nister] %-13s true E within %.0e: %.2f%% (OpenCV %.2f%%); solutions %.3f "
                "(OpenCV %.3f); OpenCV roots with none of ours within 1e-4: %ld of %ld (%.2f%%)\n",
                motionName(motion), tolerance, 100.0 * m.rate(), 100.0 * m.rateCv(),
                m.meanSolutions(), m.meanSolutionsCv(), m.cvRootsMissed, m.solutionsCv,
                m.solutionsCv ? 100.0 * m.cvRootsMissed / double(m.solutionsCv) : 0.0);
    std::printf("[nister] %-13s worst |q2^T E q1| %.1e; essential residual above 1e-6: %.2f%% of "
                "solutions (OpenCV %.2f%%), worst %.1e\n",
                motionName(motion), m.worstEpipolar, 100.0 * m.inexact / double(m.solutions),
                m.solutionsCv ? 100.0 * m.inexactCv / double(m.solutionsCv) : 0.0,
                m.worstEssential);
    const std::string prefix = std::string(motionName(motion)) + "_";
    ::testing::Test::RecordProperty(prefix + "found", std::to_string(m.rate()));
    ::testing::Test::RecordProperty(prefix + "found_opencv", std::to_string(m.rateCv()));
    ::testing::Test::RecordProperty(prefix + "solutions", std::to_string(m.meanSolutions()));
    ::testing::Test::RecordProperty(prefix + "solutions_opencv",
                                    std::to_string(m.meanSolutionsCv()));
}

/** Every returned E fits its five points to rounding (measured worst 1e-14), and is an essential
matrix to the accuracy of its root: 0.1% to 0.4% of the solutions have an essential residual
(|det E|, ||2 E E^T E - trace(E E^T) E||) above 1e-6, from ill-conditioned samples (OpenCV's: 0.2%
to 0.5%); none is above the solver's maxEssentialResidual (1e-2). */
void expectExact(const Measurement& m, double maxInexact = 0.01)
{
    EXPECT_LT(m.worstEpipolar, 1e-10);
    EXPECT_LE(m.worstEssential, NisterSettings().maxEssentialResidual);
    EXPECT_LT(m.inexact, maxInexact * m.solutions);
    if (m.solutionsCv > 0) {
        EXPECT_LE(m.inexact, m.inexactCv + 0.003 * m.solutionsCv);
    }
}

constexpr int kProblems = 2000;

// The rates below were measured on 4000 problems per motion (seeds 1000..4999 of the same
// generators, the tests use others): true E within 1e-6 for 99.78% (general; OpenCV 99.72%),
// 99.95% (sideways; 99.75%), 99.75% (forward; 99.38%) and, with a baseline of 0.01, 98.0% within
// 1e-6 and 99.65% within 1e-4 (the problem itself is ill-conditioned: OpenCV reaches 50% and 71%).
// The bounds leave more than three standard errors (about 0.35% at 2000 problems) of margin. Most
// of the misses are true roots with |z| > 100, which the paper abandons (without that bound: 99.95%
// general).
TEST(Nister, FindsTheTrueEssentialMatrixForGeneralMotion)
{
    const Measurement m = measure(Motion::General, kProblems, 1e-6, true);
    report(Motion::General, 1e-6, m);
    expectExact(m);
    EXPECT_GE(m.rate(), 0.99);
    // OpenCV's solver finds the true E for 99.7% of the same problems; ours is not worse by more
    // than the margin.
    EXPECT_GE(m.rate(), m.rateCv() - 0.005);
}

TEST(Nister, FindsTheTrueEssentialMatrixForSidewaysMotion)
{
    const Measurement m = measure(Motion::Sideways, kProblems, 1e-6, true);
    report(Motion::Sideways, 1e-6, m);
    expectExact(m);
    EXPECT_GE(m.rate(), 0.99);
    EXPECT_GE(m.rate(), m.rateCv() - 0.005);
}

TEST(Nister, FindsTheTrueEssentialMatrixForForwardMotion)
{
    const Measurement m = measure(Motion::Forward, kProblems, 1e-6, true);
    report(Motion::Forward, 1e-6, m);
    expectExact(m);
    EXPECT_GE(m.rate(), 0.99);
    EXPECT_GE(m.rate(), m.rateCv() - 0.005);
}

TEST(Nister, FindsTheTrueEssentialMatrixForShortBaselines)
{
    const Measurement loose = measure(Motion::ShortBase, kProblems, 1e-4, true);
    report(Motion::ShortBase, 1e-4, loose);
    expectExact(loose, 0.02); // measured 1.0% (OpenCV 29%)
    EXPECT_GE(loose.rate(), 0.985);
    EXPECT_GE(loose.rate(), loose.rateCv());
    const Measurement tight = measure(Motion::ShortBase, kProblems, 1e-6, false);
    std::printf("[nister] %-13s true E within 1e-6: %.2f%%\n", motionName(Motion::ShortBase),
                100.0 * tight.rate());
    EXPECT_GE(tight.rate(), 0.96);
}

// Mean number of solutions: measured 4.786 against OpenCV's 4.796 (general), 4.745 / 4.754
// (sideways), 4.820 / 4.830 (forward): the roots abandoned beyond |z| = 100 and near-repeated
// ones. With a baseline of 0.01 OpenCV loses more roots than we do (4.88 against 4.73).
TEST(Nister, SolutionCountsMatchOpenCv)
{
    for (Motion motion : {Motion::General, Motion::Sideways, Motion::Forward}) {
        const Measurement m = measure(motion, 1000, 1e-6, true);
        report(motion, 1e-6, m);
        EXPECT_LT(std::abs(m.meanSolutions() - m.meanSolutionsCv()), 0.05) << motionName(motion);
        // OpenCV roots with none of ours within 1e-4: measured 0.35% to 0.45% (the roots beyond
        // |z| = 100, and OpenCV's own inaccurate ones).
        EXPECT_LT(m.cvRootsMissed, 0.01 * m.solutionsCv) << motionName(motion);
    }
    const Measurement m = measure(Motion::ShortBase, 1000, 1e-4, true);
    EXPECT_GT(m.meanSolutions(), m.meanSolutionsCv() - 0.05);
}

// Why the solver works in rotated coordinate frames: in camera coordinates (the paper's choice)
// E(2,2) is the pivot entry set to -1, and E = [t]x R has a zero third row for forward motion, so
// the true E cannot be represented at all; one frame alone is right for general motion only 96.7%
// of the time (ill-conditioned samples), three frames 99.8%.
TEST(Nister, CoordinateFramesAreNeeded)
{
    NisterSettings camera;
    camera.frames = 0;
    const Measurement forward = measure(Motion::Forward, 300, 1e-6, false, camera);
    std::printf("[nister] camera coordinates, forward motion: %.2f%%\n", 100.0 * forward.rate());
    EXPECT_LT(forward.rate(), 0.05);
    NisterSettings one;
    one.frames = 1;
    const Measurement general = measure(Motion::General, 1000, 1e-6, false, one);
    std::printf("[nister] one frame, general motion: %.2f%%\n", 100.0 * general.rate());
    EXPECT_LT(general.rate(), measure(Motion::General, 1000, 1e-6, false).rate());
}

TEST(Nister, SuccessRateIsNotAboveTheMeasuredRate)
{
    NisterFivePointSolver solver;
    const Measurement m = measure(Motion::General, kProblems, 1e-6, false);
    EXPECT_LE(solver.successRate(), m.rate() + 0.003);
    EXPECT_GT(solver.successRate(), 0.98);
}

// The generated code against a direct evaluation: for random A and (x, y, z), M times the monomial
// vector equals det(E) and the nine entries of 2 E E^T E - trace(E E^T) E, with E from the basis
// [A^T | -I].
TEST(Nister, GeneratedConstraintMatrixMatchesTheConstraints)
{
    std::mt19937_64 g(5);
    std::normal_distribution<double> n(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        double A[5][4];
        for (auto& row : A)
            for (double& a : row)
                a = n(g);
        const double x = n(g), y = n(g), z = n(g);
        cv::Matx33d E;
        for (int i = 0; i < 5; ++i)
            E.val[i] = A[i][0] * x + A[i][1] * y + A[i][2] * z + A[i][3];
        E.val[5] = -x;
        E.val[6] = -y;
        E.val[7] = -z;
        E.val[8] = -1.0;
        const cv::Matx33d EEt = E * E.t();
        const cv::Matx33d T = 2.0 * EEt * E - cv::trace(EEt) * E;
        double expected[10] = {cv::determinant(E)};
        for (int i = 0; i < 9; ++i)
            expected[1 + i] = T.val[i];
        double M[10][20];
        generated::nisterConstraintMatrix(A, M);
        const double mono[20] = {x * x * x, y * y * y, x * x * y, x * y * y, x * x * z,
                                 x * x,     y * y * z, y * y,     x * y * z, x * y,
                                 x * z * z, x * z,     x,         y * z * z, y * z,
                                 y,         z * z * z, z * z,     z,         1.0};
        for (int r = 0; r < 10; ++r) {
            double v = 0.0, scale = 0.0;
            for (int c = 0; c < 20; ++c) {
                v += M[r][c] * mono[c];
                scale += std::abs(M[r][c] * mono[c]);
            }
            EXPECT_NEAR(v, expected[r], 1e-12 * std::max(1.0, scale)) << "row " << r;
        }
    }
}

TEST(Nister, DegenerateSamplesGiveNoSolutionOrFiniteOnes)
{
    NisterFivePointSolver solver;
    cv::RNG rng(1);
    cv::Matx33d E[10];
    const std::vector<cv::Point2d> same1(5, cv::Point2d(0.1, 0.2)),
        same2(5, cv::Point2d(0.15, 0.22));
    EXPECT_EQ(solver.solve(same1.data(), same2.data(), rng, E), 0);
    // Four points on a line in both views, plus one: rank-deficient constraints.
    const std::vector<cv::Point2d> line1 = {
        {0, 0}, {0.1, 0.1}, {0.2, 0.2}, {0.3, 0.3}, {0.5, -0.2}};
    const std::vector<cv::Point2d> line2 = {
        {0, 0}, {0.1, 0.1}, {0.2, 0.2}, {0.3, 0.3}, {0.4, -0.1}};
    const int n = solver.solve(line1.data(), line2.data(), rng, E);
    EXPECT_GE(n, 0);
    EXPECT_LE(n, 10);
    for (int k = 0; k < n; ++k)
        for (double v : E[k].val)
            EXPECT_TRUE(std::isfinite(v));
    // A non-finite coordinate gives nothing rather than NaN matrices.
    SyntheticScene s = minimalProblem(Motion::General, 3);
    s.x1[2].x = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(solver.solve(s.x1.data(), s.x2.data(), rng, E), 0);
    s.x1[2].x = std::numeric_limits<double>::infinity();
    EXPECT_EQ(solver.solve(s.x1.data(), s.x2.data(), rng, E), 0);
}

TEST(Nister, IsRegistered)
{
    const auto names = cv::essential::listSolvers();
    EXPECT_NE(std::find(names.begin(), names.end(), "nister"), names.end());
    auto solver = cv::essential::createSolver("nister");
    EXPECT_EQ(solver->sampleSize(), 5);
    EXPECT_EQ(solver->maxSolutions(), 10);
    const SyntheticScene s = minimalProblem(Motion::General, 12);
    cv::RNG rng(1);
    cv::Matx33d E[10];
    const int n = solver->solve(s.x1.data(), s.x2.data(), rng, E);
    EXPECT_TRUE(contains(E, n, s.E, 1e-6));
}

// The whole estimate with solver = "nister" on the paper's protocol (500 points, 50% inliers,
// 0.001 noise): the pose is right.
TEST(Nister, EstimateWithNisterRecoversThePose)
{
    int good = 0;
    const int problems = 20;
    for (int k = 0; k < problems; ++k) {
        essential_test::SceneConfig cfg;
        cfg.numPoints = 500;
        cfg.inlierRatio = 0.5;
        const SyntheticScene s = essential_test::makeScene(cfg, 500 + static_cast<uint64_t>(k));
        cv::essential::EssentialParams params;
        params.solver = "nister";
        cv::essential::EssentialReport rep;
        cv::Mat mask;
        const cv::Mat E =
            cv::essential::findEssentialMatIter(s.px1, s.px2, cv::Mat(s.K), params, mask, &rep);
        ASSERT_EQ(E.rows, 3);
        ASSERT_TRUE(rep.poseRecovered);
        const double re = essential_test::rotationErrorDeg(rep.R, s.R);
        const double te = essential_test::translationErrorDeg(rep.t, s.t);
        EXPECT_GT(rep.inliers, 200) << "seed " << 500 + k;
        good += re < 1.0 && te < 3.0;
    }
    EXPECT_GE(good, problems - 1);
}

} // namespace

TEST(Nister, EverySolutionIsEssentialWithinTheDocumentedTolerance)
{
    // The solver fuzz target's first finding (fuzz/regression/solvers/): on a random sample a kept
    // root had singular values (1.000019, 0.999981, 1.2e-8), outside the 1e-6 first written in
    // solver.hpp but inside what the trace-constraint test (residual <= 1e-2) admits. The
    // documented bound is now 1e-2 s; this checks it, and the scale, on random and pose samples.
    cv::Ptr<cv::essential::EssentialSolver> solver = cv::essential::createSolver("nister");
    cv::RNG rng(7);
    std::array<cv::Matx33d, 10> solutions;
    double worstGap = 0.0;
    for (int trial = 0; trial < 3000; ++trial) {
        cv::Point2d x1[5], x2[5];
        for (int i = 0; i < 5; ++i) {
            x1[i] = cv::Point2d(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
            x2[i] = cv::Point2d(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
        }
        const int n = solver->solve(x1, x2, rng, solutions.data());
        for (int k = 0; k < n; ++k) {
            cv::Vec3d w;
            cv::SVD::compute(solutions[static_cast<size_t>(k)], w, cv::SVD::NO_UV);
            EXPECT_NEAR(cv::norm(solutions[static_cast<size_t>(k)]), std::sqrt(2.0), 1e-9);
            EXPECT_LE(w[0] - w[1], 1e-2 * w[0]);
            EXPECT_LE(w[2], 1e-2 * w[0]);
            worstGap = std::max(worstGap, (w[0] - w[1]) / w[0]);
        }
    }
    std::printf("worst relative singular-value gap over 3000 random samples: %.2e\n", worstGap);
}
