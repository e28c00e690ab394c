// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The solver-layer fuzz target: the built-in minimal solvers (gn, lm, nister, robust) and a
// composite (gn+nister), called directly as the engines call them, on arbitrary samples: random,
// from a true pose, degenerate (one point repeated, collinear, two points repeated), at extreme
// scales, with non-finite coordinates, or raw doubles. Contract (EssentialSolver in
// opencv2/essential/solver.hpp): solve() returns, in bounded time, a count in [0, maxSolutions()]
// of finite essential matrices scaled as E = [t]x R with a unit t (Frobenius norm sqrt(2)), whose
// singular values are (s, s, 0) within kEssentialTolerance.

#include "fuzz_contract.hpp"
#include "fuzz_input.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/essential.hpp>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace essential_fuzz;
namespace ess = cv::essential;

/** How far a returned matrix may be from the essential manifold: the gap between its two largest
singular values and its smallest one, relative to the largest. */
constexpr double kEssentialTolerance = 1e-6;

const std::vector<cv::Ptr<ess::EssentialSolver>>& solvers()
{
    // One instance each for the life of the process, as an engine keeps one for an estimate.
    static const std::vector<cv::Ptr<ess::EssentialSolver>> all = {
        ess::createSolver("gn"), ess::createSolver("lm"), ess::createSolver("nister"),
        ess::createSolver("robust"), ess::createSolver("gn+nister")};
    return all;
}

/** A sample of m correspondences of the kind `mode` picks. */
void makeSample(FuzzInput& in, int m, std::vector<cv::Point2d>& x1, std::vector<cv::Point2d>& x2)
{
    x1.assign(static_cast<size_t>(m), cv::Point2d());
    x2.assign(static_cast<size_t>(m), cv::Point2d());
    const int mode = in.pick(8);
    cv::Matx33d R;
    cv::Rodrigues(cv::Vec3d(in.unit() - 0.5, in.unit() - 0.5, in.unit() - 0.5), R);
    const cv::Vec3d t(in.unit() - 0.5, in.unit() - 0.5, in.unit() - 0.5);
    for (int i = 0; i < m; ++i) {
        cv::Point2d& a = x1[static_cast<size_t>(i)];
        cv::Point2d& b = x2[static_cast<size_t>(i)];
        switch (mode) {
        case 0: // random
            a = cv::Point2d(2 * in.unit() - 1, 2 * in.unit() - 1);
            b = cv::Point2d(2 * in.unit() - 1, 2 * in.unit() - 1);
            break;
        case 1: { // from a true pose (t may be near zero: a pure rotation)
            const cv::Vec3d X(2 * in.unit() - 1, 2 * in.unit() - 1, 1 + 10 * in.unit());
            const cv::Vec3d Y = R * X + t;
            a = cv::Point2d(X[0] / X[2], X[1] / X[2]);
            const double z = std::abs(Y[2]) > 1e-9 ? Y[2] : 1e-9;
            b = cv::Point2d(Y[0] / z, Y[1] / z);
            break;
        }
        case 2: // one correspondence repeated
            a = i == 0 ? cv::Point2d(in.unit(), in.unit()) : x1[0];
            b = i == 0 ? cv::Point2d(in.unit(), in.unit()) : x2[0];
            break;
        case 3: { // collinear in both views
            const double s = in.unit();
            a = cv::Point2d(s, 0.5 * s + 0.1);
            b = cv::Point2d(0.3 * s - 0.2, s);
            break;
        }
        case 4: // two correspondences repeated
            a = i < 2 ? cv::Point2d(in.unit(), in.unit()) : x1[static_cast<size_t>(i % 2)];
            b = i < 2 ? cv::Point2d(in.unit(), in.unit()) : x2[static_cast<size_t>(i % 2)];
            break;
        case 5: { // extreme scales
            const double scale = std::pow(10.0, in.pick(25) - 12);
            a = scale * cv::Point2d(in.unit() - 0.5, in.unit() - 0.5);
            b = scale * cv::Point2d(in.unit() - 0.5, in.unit() - 0.5);
            break;
        }
        case 6: // a pose, with one coordinate made non-finite or huge below
            a = cv::Point2d(in.unit(), in.unit());
            b = cv::Point2d(in.unit(), in.unit());
            break;
        default: // raw doubles
            a = cv::Point2d(in.anyDouble(), in.anyDouble());
            b = cv::Point2d(in.anyDouble(), in.anyDouble());
        }
    }
    if (mode == 6) {
        std::vector<cv::Point2d>& side = in.pick(2) ? x1 : x2;
        cv::Point2d& p = side[static_cast<size_t>(in.pick(m))];
        (in.pick(2) ? p.x : p.y) = in.anyDouble();
    }
}

void checkSolution(const cv::Matx33d& E)
{
    for (int k = 0; k < 9; ++k)
        if (!std::isfinite(E.val[k])) broken("non-finite solution");
    const double norm = cv::norm(E);
    if (std::abs(norm - std::sqrt(2.0)) > 1e-9) broken("solution's Frobenius norm is not sqrt(2)");
    cv::Vec3d w;
    cv::SVD::compute(E, w, cv::SVD::NO_UV);
    if (w[0] - w[1] > kEssentialTolerance * w[0] || w[2] > kEssentialTolerance * w[0])
        broken("solution not an essential matrix (singular values not (s, s, 0))");
}

void runOne(FuzzInput& in)
{
    const auto& all = solvers();
    ess::EssentialSolver& solver = *all[static_cast<size_t>(in.pick(static_cast<int>(all.size())))];
    // The engines set the threshold once per estimate (normalised units); fuzz it too.
    solver.setThreshold(in.pick(4) == 0 ? in.anyDouble() : 1e-4 + 1e-2 * in.unit());
    const int m = solver.sampleSize();
    std::vector<cv::Point2d> x1, x2;
    makeSample(in, m, x1, x2);
    std::array<cv::Matx33d, 64> solutions;
    if (solver.maxSolutions() > static_cast<int>(solutions.size())) broken("maxSolutions > 64");
    cv::RNG rng(static_cast<uint64>(in.pick(1 << 30)));
    const int n = solver.solve(x1.data(), x2.data(), rng, solutions.data());
    if (n < 0 || n > solver.maxSolutions()) broken("solution count out of range");
    for (int i = 0; i < n; ++i)
        checkSolution(solutions[static_cast<size_t>(i)]);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    FuzzInput in(data, size);
    return runGuarded([&] { runOne(in); });
}
