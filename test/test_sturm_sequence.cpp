// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The Sturm sequence of the five-point solver (solvers/sturm_sequence.hpp): it counts the real
// roots of a polynomial on an interval, and its recurrence evaluation counts sign changes exactly
// as evaluating every member on its own does, on the solver's own polynomials d(z).

// The lane test below passes 32-byte vectors to the header's inlined templates, which GCC reports
// (an ABI change without AVX); no such vector crosses an ABI, and test/CMakeLists.txt compiles this
// file with -Wno-psabi.

#include "solvers/nister_five_point.hpp"
#include "solvers/sturm_sequence.hpp"
#include "synthetic_scene.hpp"

#include "essential_test.hpp"

#include <cstdint>
#include <cstdio>
#include <vector>

namespace {

using cv::essential::solvers::SturmSequence;

/** Coefficients, lowest power first, of scale * prod (z - roots[i]). */
std::vector<double> fromRoots(const std::vector<double>& roots, double scale)
{
    std::vector<double> c = {scale};
    for (double r : roots) {
        std::vector<double> next(c.size() + 1, 0.0);
        for (size_t i = 0; i < c.size(); ++i) {
            next[i + 1] += c[i];
            next[i] -= r * c[i];
        }
        c = next;
    }
    return c;
}

/** The five-point solver's d(z) on a five-point scene (`seed`; all inliers or random points, with
`noise`): its degree, 0 when d vanishes; d points into the solver's diagnostics. */
int solverPolynomial(cv::essential::solvers::NisterFivePointSolver& solver, cv::RNG& rng,
                     double inlierRatio, double noise, uint64_t seed, const double*& d)
{
    essential_test::SceneConfig cfg;
    cfg.numPoints = 5;
    cfg.inlierRatio = inlierRatio;
    cfg.noiseSigma = noise;
    const essential_test::SyntheticScene p = essential_test::makeScene(cfg, seed);
    cv::Matx33d E[10];
    solver.solve(p.x1.data(), p.x2.data(), rng, E);
    d = solver.lastDiagnostics().polynomial;
    int degree = 10;
    while (degree > 0 && d[degree] == 0.0)
        --degree;
    return degree;
}

TEST(SturmSequence, CountsTheRealRootsOfAKnownPolynomial)
{
    // Ten distinct real roots, spread like those of d(z) (most of order 1, some large).
    const std::vector<double> roots = {-73.0, -4.5, -1.25, -0.3, 0.02, 0.4, 0.9, 2.5, 11.0, 60.0};
    const std::vector<double> d = fromRoots(roots, -0.7);
    SturmSequence s;
    s.build(d.data(), 10);
    const double points[] = {-100, -50, -2, -1, 0, 0.5, 1, 3, 20, 100};
    for (double a : points)
        for (double b : points) {
            if (!(a < b)) continue;
            int inside = 0;
            for (double r : roots)
                inside += r > a && r <= b;
            EXPECT_EQ(s.signChanges(a) - s.signChanges(b), inside) << a << " " << b;
            EXPECT_EQ(s.signChanges(a), s.signChangesDirect(a)) << a;
        }
    // A quadratic factor without real roots adds none.
    std::vector<double> e = fromRoots({-3.0, 0.5, 7.0}, 2.0); // times (z^2 + 1)
    std::vector<double> f(e.size() + 2, 0.0);
    for (size_t i = 0; i < e.size(); ++i) {
        f[i] += e[i];
        f[i + 2] += e[i];
    }
    s.build(f.data(), 5);
    EXPECT_EQ(s.signChanges(-100) - s.signChanges(100), 3);
    EXPECT_EQ(s.signChanges(0) - s.signChanges(100), 2);
}

// Measured: 0 disagreements in 6 003 000 evaluations (3000 problems, 2001 points each on
// [-100, 100], half of them with the protocol's noise); here 400 problems.
TEST(SturmSequence, RecurrenceCountsLikeDirectEvaluationOnTheSolversPolynomials)
{
    cv::essential::solvers::NisterFivePointSolver solver;
    cv::RNG rng(1);
    long evaluations = 0, disagreements = 0, built = 0;
    for (int i = 0; i < 400; ++i) {
        const double* d = nullptr;
        const int degree = solverPolynomial(solver, rng, 1.0, i % 2 ? 0.0 : 0.001, 91000 + i, d);
        if (degree < 1) continue;
        ++built;
        SturmSequence s;
        s.build(d, degree);
        for (int k = -1000; k <= 1000; ++k) {
            const double t = 0.1 * k + 0.0137;
            ++evaluations;
            disagreements += s.signChanges(t) != s.signChangesDirect(t);
        }
    }
    std::printf("[sturm] %ld polynomials, %ld evaluations, %ld disagreements\n", built, evaluations,
                disagreements);
    EXPECT_GT(built, 390);
    EXPECT_EQ(disagreements, 0);
}

#if defined(__GNUC__) && !defined(__clang__)
typedef double TestLanes __attribute__((vector_size(4 * sizeof(double))));
typedef long long TestMask __attribute__((vector_size(4 * sizeof(double))));

/** The counts of signChangesInLanes at four points against signChanges at each. */
int laneDisagreements(const SturmSequence& s, const std::vector<double>& points)
{
    int disagreements = 0;
    for (size_t i = 0; i + 4 <= points.size(); i += 4) {
        int counts[4];
        s.signChangesInLanes<TestLanes, TestMask, 4>(
            TestLanes{points[i], points[i + 1], points[i + 2], points[i + 3]}, counts);
        for (int l = 0; l < 4; ++l)
            disagreements += counts[l] != s.signChanges(points[i + l]);
    }
    return disagreements;
}

// The five-point solver isolates its roots with the counts of four split points at once
// (nister_five_point.cpp, isolateRootsInLanes); they must be the scalar counts exactly, zeros of
// members included (integer roots evaluate to an exact 0).
TEST(SturmSequence, LanesCountLikeOneAtATime)
{
    SturmSequence s;
    const std::vector<double> integer = fromRoots({-3.0, -1.0, 1.0, 2.0, 5.0}, 1.0);
    s.build(integer.data(), 5);
    ASSERT_TRUE(s.allLinear());
    std::vector<double> points;
    for (int k = -24; k <= 24; ++k)
        points.push_back(0.25 * k); // the roots, the derivative's simple ones, and between
    EXPECT_EQ(laneDisagreements(s, points), 0);

    cv::essential::solvers::NisterFivePointSolver solver;
    cv::RNG rng(2);
    int compared = 0, disagreements = 0;
    for (int i = 0; i < 200; ++i) {
        const double* d = nullptr;
        const int degree =
            solverPolynomial(solver, rng, i % 3 ? 1.0 : 0.0, i % 2 ? 0.0 : 0.001, 93000 + i, d);
        if (degree < 1) continue;
        s.build(d, degree);
        if (!s.allLinear()) continue;
        points.clear();
        for (int k = -400; k < 400; ++k)
            points.push_back(0.25 * k + 0.003 * (i % 7));
        disagreements += laneDisagreements(s, points);
        compared += static_cast<int>(points.size());
    }
    std::printf("[sturm] lanes: %d counts compared, %d disagreements\n", compared, disagreements);
    EXPECT_GT(compared, 100000);
    EXPECT_EQ(disagreements, 0);
}
#endif

} // namespace
