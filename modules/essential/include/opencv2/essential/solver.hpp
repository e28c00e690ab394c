// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#ifndef OPENCV_ESSENTIAL_SOLVER_HPP
#define OPENCV_ESSENTIAL_SOLVER_HPP

#include <opencv2/core.hpp>

#include <functional>
#include <string>
#include <vector>

namespace cv {
namespace essential {

//! @addtogroup essential
//! @{

/** @brief A hypothesis generator: turns a sample of normalised correspondences into 0..k essential
matrices.

Solvers know nothing of RANSAC. The engine draws `sampleSize()` correspondences, calls `solve()`,
and scores whatever comes back. Coordinates are normalised image coordinates (the camera matrix
already removed, the homogeneous coordinate 1 implied), so that a correspondence satisfies
\f$[x_2\ y_2\ 1]\, E\, [x_1\ y_1\ 1]^T = 0\f$ for the true essential matrix \f$E\f$.

One engine owns one solver instance for the duration of one estimate, so an implementation may keep
mutable workspace in its members; it must not allocate inside `solve()` if it wants to be fast.

To add a solver, derive from this class and register a factory with registerSolver().
*/
class CV_EXPORTS EssentialSolver
{
public:
    virtual ~EssentialSolver();

    /** Number of correspondences in one sample (5 for a minimal solver). */
    virtual int sampleSize() const = 0;

    /** Upper bound on the number of essential matrices one call of solve() may return. */
    virtual int maxSolutions() const = 0;

    /** @brief Estimates essential matrices from one sample.

    @param x1 `sampleSize()` normalised points in the first view.
    @param x2 the corresponding `sampleSize()` normalised points in the second view.
    @param rng random source, for solvers that start from random initial values.
    @param solutions room for `maxSolutions()` matrices; the first n are written.
    @return n, the number of essential matrices written (0 when the solver gives up).

    The built-in solvers return, for any input (degenerate, non-finite or of any scale included)
    and in bounded time, finite essential matrices scaled as \f$E = [t]_\times R\f$ with a unit
    \f$t\f$ (Frobenius norm \f$\sqrt 2\f$), whose singular values are \f$(s, s, 0)\f$: exactly
    (within \f$10^{-9} s\f$) for gn, lm and robust, which write \f$[t]_\times R\f$ itself, and
    within \f$10^{-2} s\f$ for nister, which keeps a polynomial root when its trace-constraint
    residual is below \f$10^{-2}\f$; the solver fuzz target (fuzz/fuzz_solvers.cpp) checks it. The
    engines need only finite, non-zero matrices (any scale) from a registered solver.
    */
    virtual int solve(const Point2d* x1, const Point2d* x2, RNG& rng, Matx33d* solutions) = 0;

    /** @brief Probability that one call on an outlier-free sample returns the true model.

    A direct solver returns 1. An iterative solver that starts from a random point converges to the
    true solution only part of the time; the engine divides by this rate when it computes how many
    samples the requested confidence needs. The default is 1.
    */
    virtual double successRate() const { return 1.0; }

    /** @brief Probability that one call on a random sample from data with the given inlier ratio
    returns the true model; the engine's stopping rule needs it.

    The default, `successRate() * inlierRatio^sampleSize()`, suits solvers that need an outlier-free
    sample. A robust solver that tolerates outliers in its sample overrides it.
    */
    virtual double hitProbability(double inlierRatio) const;

    /** @brief hitProbability() for a search whose best model so far is `model` (an essential
    matrix in normalised coordinates).

    An iterative solver's success depends on the pose it has to find: started at R = I, it reaches
    small rotations far more often than large ones. Once the engine has a model it takes it as its
    estimate of the true pose, as it takes the model's support as its estimate of the inlier ratio,
    and uses this probability in its stopping rule and its sample cap. The default ignores the
    model and returns hitProbability(inlierRatio).
    */
    virtual double hitProbabilityAt(double inlierRatio, const Matx33d& model) const;

    /** @brief The caller's inlier threshold, for solvers whose own tolerances should scale with it.

    The engine calls this once per estimate, before the first solve(), with the threshold of the
    estimate in normalised image units (the pixel threshold divided by the focal length): the
    Sampson distance below which a correspondence counts as an inlier. LMedS, which derives its
    threshold from the data, does not call it. A solver that fits a robust
    loss to a non-minimal sample (the built-in "robust") sets its loss scale and its inlier test
    from it, so that they mean the same number of pixels at any focal length. The default does
    nothing; minimal solvers need no threshold.
    */
    virtual void setThreshold(double normalisedThreshold) { (void)normalisedThreshold; }
};

/** A function that makes a new, independent solver instance. */
typedef std::function<Ptr<EssentialSolver>()> EssentialSolverFactory;

/** @brief Registers (or replaces) the solver called `name`.

Thread-safe. The built-in solvers are `"gn"` (Gauss-Newton on a minimal set, Rosten et al.
Algorithm 2), `"lm"` (Levenberg-Marquardt on a minimal set, Algorithm 1), `"robust"` (IRLS on a
10-point sample, Algorithm 3) and `"nister"` (Nister's 5-point solver, Algorithm 4).
@throws cv::Exception (StsBadArg) if `name` is empty or contains '+' or ':' (reserved for composite
names, see createSolver()), or if `factory` is empty.
*/
CV_EXPORTS void registerSolver(const std::string& name, const EssentialSolverFactory& factory);

/** @brief Makes a new instance of the solver registered as `name`, or a composite of several.

A composite name such as `"gn+nister"` or `"gn:3+nister:1"` makes a solver that takes turns among
the named parts in the given proportion (weights 1 to 1000, default 1): the paper's suggestion of
drawing hypotheses from GN and Nister together. Its sample is the largest any part needs.
@throws cv::Exception (StsBadArg) naming the unknown solver and the known ones.
*/
CV_EXPORTS Ptr<EssentialSolver> createSolver(const std::string& name);

/** The names of all registered solvers, sorted (composites are not listed). */
CV_EXPORTS_W std::vector<std::string> listSolvers();

//! @}

} // namespace essential
} // namespace cv

#endif // OPENCV_ESSENTIAL_SOLVER_HPP
