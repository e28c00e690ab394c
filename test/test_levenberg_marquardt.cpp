// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The module's one optimiser (optim/levenberg_marquardt.hpp) on small models whose behaviour is
// known in closed form: Gauss-Newton's one-step solution of a linear system and its divergence on
// the cube root, Levenberg-Marquardt's descent through Rosenbrock's valley, and each way of
// stopping (converged, stalled, the damping ceiling, the trial cap, a singular system), with the
// counts a solver reports as its iterations.

#include "optim/levenberg_marquardt.hpp"

#include "essential_test.hpp"

#include <cmath>
#include <limits>

namespace {

using namespace cv::essential::optim;

/** Five free parameters moved by addition. */
struct Point5
{
    Vector5 v = Vector5::Zero();
    void update(const Vector5& d) { v += d; }
};

/** A model of five residuals r(x) with an analytic Jacobian; counts its evaluations. */
template <class Residuals, bool Fused = false> struct SquareModel
{
    static constexpr bool kCostWithEquations = Fused;
    Residuals residuals;
    mutable int linearisations = 0;
    mutable int costs = 0;

    double linearise(const Point5& x, SquareSystem& system) const
    {
        ++linearisations;
        return system.write([&](Vector5& r, Matrix5& J) {
            residuals(x.v, r, &J);
            return r.squaredNorm();
        });
    }
    double cost(const Point5& x) const
    {
        ++costs;
        Vector5 r;
        residuals(x.v, r, nullptr);
        return r.squaredNorm();
    }
};

/** r = M x - b: Gauss-Newton solves it in one step. */
struct Linear
{
    void operator()(const Vector5& x, Vector5& r, Matrix5* J) const
    {
        Matrix5 M;
        M << 4, 1, 0, 0, 1, 1, 3, 1, 0, 0, 0, 1, 5, 2, 0, 0, 0, 2, 6, 1, 1, 0, 0, 1, 2;
        Vector5 b;
        b << 1, -2, 3, 0.5, 4;
        r = M * x - b;
        if (J) *J = M;
    }
};

/** Rosenbrock's valley in (x0, x1) plus three linear residuals: minimum 0 at (1, 1, 2, 0.5,
0.5). Undamped steps from (-1.2, 1) overshoot the curved valley; damped ones follow it. */
struct Rosenbrock
{
    void operator()(const Vector5& x, Vector5& r, Matrix5* J) const
    {
        r << 1.0 - x[0], 10.0 * (x[1] - x[0] * x[0]), x[2] - 2.0, x[3] + x[4] - 1.0, x[3] - x[4];
        if (!J) return;
        J->setZero();
        (*J)(0, 0) = -1.0;
        (*J)(1, 0) = -20.0 * x[0];
        (*J)(1, 1) = 10.0;
        (*J)(2, 2) = 1.0;
        (*J)(3, 3) = (*J)(3, 4) = 1.0;
        (*J)(4, 3) = 1.0;
        (*J)(4, 4) = -1.0;
    }
};

/** r_k = cbrt(x_k): the Gauss-Newton step -r / r' = -3 x takes x to -2 x, so the cost grows by
2^(2/3) per step from any start but 0. */
struct CubeRoot
{
    void operator()(const Vector5& x, Vector5& r, Matrix5* J) const
    {
        for (int k = 0; k < 5; ++k)
            r[k] = std::cbrt(x[k]);
        if (!J) return;
        J->setZero();
        for (int k = 0; k < 5; ++k)
            (*J)(k, k) = 1.0 / (3.0 * r[k] * r[k]);
    }
};

/** Residuals that do not depend on x: J = 0, a singular system. */
struct Constant
{
    void operator()(const Vector5&, Vector5& r, Matrix5* J) const
    {
        r.setConstant(1.0);
        if (J) J->setZero();
    }
};

/** A model whose trial costs are never lower than the linearisation's: every step is rejected. */
struct RejectEverything
{
    static constexpr bool kCostWithEquations = false;
    double linearise(const Point5& x, NormalEquations& system) const
    {
        system.A = Matrix5::Identity();
        system.g = x.v - Vector5::Ones();
        return 1.0;
    }
    double cost(const Point5&) const { return 2.0; }
};

/** Rosenbrock's start and minimum, and LM settings that reach the minimum from it. */
Point5 rosenbrockStart()
{
    Point5 x;
    x.v << -1.2, 1.0, 0.0, 0.0, 0.0;
    return x;
}

Vector5 rosenbrockMinimum()
{
    Vector5 m;
    m << 1.0, 1.0, 2.0, 0.5, 0.5;
    return m;
}

LmSettings levenbergMarquardt()
{
    LmSettings s;
    s.maxIterations = 200;
    s.damping.initial = 1e-3;
    s.damping.attempts = 10;
    s.stopCost = 1e-24;
    return s;
}

LmSettings gaussNewton()
{
    LmSettings s;
    s.damping.initial = 0.0;
    s.stopCost = 1e-24;
    s.divergenceFactor = 1e3;
    return s;
}

TEST(LevenbergMarquardt, GaussNewtonSolvesALinearSystemInOneStep)
{
    SquareModel<Linear> model;
    Point5 x;
    SquareSystem system;
    const LmResult result = minimise(model, x, system, gaussNewton());
    EXPECT_EQ(result.status, LmStatus::Converged);
    // One step, then the linearisation that finds the residual gone.
    EXPECT_EQ(result.iterations, 2);
    EXPECT_LT(result.cost, 1e-24);
    Vector5 r;
    model.residuals(x.v, r, nullptr);
    EXPECT_LT(r.norm(), 1e-12);
}

TEST(LevenbergMarquardt, GaussNewtonStopsWhenTheCostGrows)
{
    SquareModel<CubeRoot> model;
    Point5 x;
    x.v.setConstant(0.5);
    SquareSystem system;
    LmSettings s = gaussNewton();
    s.divergenceFactor = 1.5; // below the growth 2^(2/3) = 1.587 per step
    const LmResult result = minimise(model, x, system, s);
    EXPECT_EQ(result.status, LmStatus::Diverged);
    EXPECT_EQ(result.iterations, 2);
    EXPECT_NEAR(x.v[0], -1.0, 1e-12); // one step: 0.5 -> -2 * 0.5
    // Above the growth it runs to the cap and reports it.
    s.divergenceFactor = 1.6;
    x.v.setConstant(0.5);
    EXPECT_EQ(minimise(model, x, system, s).status, LmStatus::MaxIterations);
}

TEST(LevenbergMarquardt, GaussNewtonRefusesASingularSystem)
{
    SquareModel<Constant> model;
    Point5 x;
    SquareSystem system;
    const LmResult result = minimise(model, x, system, gaussNewton());
    EXPECT_EQ(result.status, LmStatus::Singular);
    EXPECT_EQ(result.iterations, 1);
}

TEST(LevenbergMarquardt, DampedStepsFollowRosenbrocksValley)
{
    SquareModel<Rosenbrock> model;
    Point5 x = rosenbrockStart();
    SquareSystem system;
    const LmResult result = minimise(model, x, system, levenbergMarquardt());
    EXPECT_EQ(result.status, LmStatus::Converged);
    EXPECT_LT((x.v - rosenbrockMinimum()).norm(), 1e-10);
    // Every step taken lowered the cost; the trials include the rejected ones.
    EXPECT_GE(result.trials, result.iterations);
    EXPECT_EQ(model.costs, result.trials);
    EXPECT_EQ(model.linearisations, result.iterations + 1); // the start and each accepted step
    EXPECT_LT(result.cost, result.initialCost);
}

TEST(LevenbergMarquardt, FusedTrialsReuseTheirLinearisation)
{
    SquareModel<Rosenbrock, true> model;
    Point5 x = rosenbrockStart();
    SquareSystem system;
    const LmResult result = minimise(model, x, system, levenbergMarquardt());
    ASSERT_EQ(result.status, LmStatus::Converged);
    // The first trial of each iteration is a linearisation; only the retries are cost-only, and
    // an iteration accepted on a retry linearises once more.
    EXPECT_EQ(model.costs, result.trials - result.iterations);
    EXPECT_GE(model.linearisations, 1 + result.iterations);
    EXPECT_LE(model.linearisations, 1 + result.iterations + model.costs);
    // The same optimum as without fusing.
    EXPECT_LT((x.v - rosenbrockMinimum()).norm(), 1e-10);
}

TEST(LevenbergMarquardt, StopsOnASmallRelativeDecrease)
{
    SquareModel<Rosenbrock> model;
    LmSettings s;
    s.maxIterations = 200;
    s.damping.attempts = 10;
    auto run = [&](double tolerance, Point5& x) {
        x = rosenbrockStart();
        SquareSystem system;
        s.relativeTolerance = tolerance;
        return minimise(model, x, system, s);
    };
    Point5 full, early;
    const LmResult toMinimum = run(0.0, full);
    const LmResult stopped = run(0.5, early);
    // Without a tolerance it runs until no step lowers the cost; with one it stops earlier, at a
    // higher cost, having lowered it.
    EXPECT_EQ(toMinimum.status, LmStatus::Stalled);
    EXPECT_LT(toMinimum.cost, 1e-20);
    EXPECT_EQ(stopped.status, LmStatus::Stalled);
    EXPECT_LT(stopped.iterations, toMinimum.iterations);
    EXPECT_GT(stopped.cost, toMinimum.cost);
    EXPECT_LT(stopped.cost, stopped.initialCost);
}

TEST(LevenbergMarquardt, PredictedDecreaseIsExactForALinearModel)
{
    // For linear residuals the linearisation is the model itself: the predicted decrease of any
    // step equals the cost's true decrease, in both systems' cost conventions (|r|^2 for the
    // square system, sum r^2 / 2 for the normal equations), to rounding.
    const Linear residuals;
    Point5 x;
    x.v << 0.3, -1.0, 2.0, 0.7, -0.2;
    Vector5 step;
    step << 0.5, 0.25, -1.5, 1.0, -0.75;
    Vector5 r0, r1;
    Matrix5 J;
    residuals(x.v, r0, &J);
    residuals(x.v + step, r1, nullptr);
    SquareSystem square;
    square.write([&](Vector5& r, Matrix5& Jw) {
        r = r0;
        Jw = J;
        return r.squaredNorm();
    });
    const double squareDecrease = r0.squaredNorm() - r1.squaredNorm();
    EXPECT_NEAR(square.predictedDecrease(step), squareDecrease, 1e-12 * r0.squaredNorm());
    NormalEquations normal;
    normal.A = J.transpose() * J;
    normal.g = J.transpose() * r0;
    EXPECT_NEAR(normal.predictedDecrease(step), 0.5 * squareDecrease, 1e-12 * r0.squaredNorm());
    // Towards the minimum the prediction is positive, away from it negative.
    Vector5 toMinimum;
    ASSERT_TRUE(normal.solve(0.0, toMinimum));
    EXPECT_GT(normal.predictedDecrease(toMinimum), 0.0);
    EXPECT_LT(normal.predictedDecrease(-toMinimum), 0.0);
}

/** Least squares with a residual left at the minimum: y = p0 exp(p1 t) + p2 sin(p3 t) + p4 fitted
to 20 samples of such a curve with a deterministic perturbation, through the normal equations
(cost sum r^2 / 2). Counts its evaluations. */
struct CurveFit
{
    static constexpr bool kCostWithEquations = false;
    mutable int linearisations = 0;
    mutable int costs = 0;

    static double sampleAt(int k) { return 0.1 * k; }
    static double observed(int k)
    {
        const double t = sampleAt(k);
        return 1.5 * std::exp(-0.8 * t) + 0.5 * std::sin(2.0 * t) + 0.2 + 0.01 * std::cos(7.0 * k);
    }
    static double residual(const Vector5& p, int k, double* J)
    {
        const double t = sampleAt(k), e = std::exp(p[1] * t), s = std::sin(p[3] * t);
        if (J) {
            J[0] = e;
            J[1] = p[0] * t * e;
            J[2] = s;
            J[3] = p[2] * t * std::cos(p[3] * t);
            J[4] = 1.0;
        }
        return p[0] * e + p[2] * s + p[4] - observed(k);
    }
    double linearise(const Point5& x, NormalEquations& system) const
    {
        ++linearisations;
        system.A.setZero();
        system.g.setZero();
        double c = 0.0;
        for (int k = 0; k < 20; ++k) {
            double J[5];
            const double r = residual(x.v, k, J);
            const Eigen::Map<const Vector5> j(J);
            system.A += j * j.transpose();
            system.g += r * j;
            c += 0.5 * r * r;
        }
        return c;
    }
    double cost(const Point5& x) const
    {
        ++costs;
        double c = 0.0;
        for (int k = 0; k < 20; ++k) {
            const double r = residual(x.v, k, nullptr);
            c += 0.5 * r * r;
        }
        return c;
    }
};

TEST(LevenbergMarquardt, StopsBeforeAStepPredictedToGainLittle)
{
    // With predictedTolerance the run ends at the first step the linearisation predicts to lower
    // the cost by less than that fraction of it, without evaluating the step: fewer evaluations,
    // every one counted as a trial, and a cost above the minimum's by about that fraction (near
    // the minimum the linearisation is close to exact).
    LmSettings s;
    s.maxIterations = 200;
    s.damping.attempts = 10;
    auto run = [&](double tolerance, Point5& x, const CurveFit& model) {
        x.v << 1.0, -0.5, 0.3, 1.8, 0.0;
        NormalEquations system;
        s.predictedTolerance = tolerance;
        return minimise(model, x, system, s);
    };
    Point5 full, early;
    const CurveFit fullModel, earlyModel;
    const double tolerance = 1e-6;
    const LmResult toMinimum = run(0.0, full, fullModel);
    const LmResult stopped = run(tolerance, early, earlyModel);
    ASSERT_EQ(toMinimum.status, LmStatus::Stalled);
    ASSERT_GT(toMinimum.cost, 1e-5); // a residual is left: the relative rule has a scale
    EXPECT_EQ(stopped.status, LmStatus::Stalled);
    EXPECT_LT(earlyModel.costs, fullModel.costs);
    EXPECT_EQ(earlyModel.costs, stopped.trials);
    EXPECT_GE(stopped.cost, toMinimum.cost);
    EXPECT_LT(stopped.cost, toMinimum.cost * (1.0 + 2.0 * tolerance));
    EXPECT_LT(stopped.cost, stopped.initialCost);
}

TEST(LevenbergMarquardt, EachWayOfStoppingOnRejections)
{
    const RejectEverything model;
    NormalEquations system;
    LmSettings s;
    s.damping.initial = 1e-4;
    // Six attempts, then the iteration stalls.
    s.damping.attempts = 6;
    Point5 x;
    LmResult result = minimise(model, x, system, s);
    EXPECT_EQ(result.status, LmStatus::Stalled);
    EXPECT_EQ(result.trials, 6);
    EXPECT_EQ(x.v, Vector5::Zero()); // no step taken
    // The ceiling: 1e-4 * 10^k > 1.5e6 first at k = 11.
    s.damping.attempts = 100;
    s.damping.ceiling = 1.5e6;
    result = minimise(model, x, system, s);
    EXPECT_EQ(result.status, LmStatus::DampingLimit);
    EXPECT_EQ(result.trials, 11);
    // The trial cap before the ceiling.
    s.maxTrials = 5;
    result = minimise(model, x, system, s);
    EXPECT_EQ(result.status, LmStatus::MaxIterations);
    EXPECT_EQ(result.trials, 5);
}

TEST(LevenbergMarquardt, NonFiniteStartIsReported)
{
    SquareModel<CubeRoot> model;
    Point5 x;
    x.v[2] = std::numeric_limits<double>::quiet_NaN();
    SquareSystem system;
    LmSettings s;
    EXPECT_EQ(minimise(model, x, system, s).status, LmStatus::NotFinite);
    EXPECT_EQ(minimise(model, x, system, gaussNewton()).status, LmStatus::NotFinite);
}

} // namespace
