// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// "robust": iteratively reweighted least squares on a non-minimal sample (Rosten et al.,
// Algorithm 3). A sample of 10 has far better odds of holding five inliers than a sample of five
// has of being clean; the robust fit then finds the model of its inliers despite its outliers.

#ifndef OPENCV_ESSENTIAL_SOLVERS_ROBUST_IRLS_HPP
#define OPENCV_ESSENTIAL_SOLVERS_ROBUST_IRLS_HPP

#include "geometry/essential_parameterisation.hpp"
#include "opencv2/essential/solver.hpp"

#include <vector>

namespace cv {
namespace essential {
namespace solvers {

/** Settings of the robust solver; docs/SOLVERS.md records the measurements behind the defaults. */
struct RobustIrlsSettings
{
    /** Correspondences per sample (the paper found 10 best). At least 6. */
    int sampleSize = 10;
    /** Outer IRLS iterations (each one LM step with fixed weights). */
    int maxIterations = 30;
    /** Cauchy scale of the first iteration, in normalised units (about 25 px at f = 500), shrunk
    by `scaleDecay` per iteration down to `finalScale`: a graduated fit that first explains the
    bulk of the sample, then locks onto the inliers it agrees with. */
    double initialScale = 0.05;
    double scaleDecay = 0.7;
    double finalScale = 0.002;
    /** A sample point is an inlier of the result when both epipolar distances are below this;
    a result with fewer than `minInliers` inliers in its own sample is rejected (any five points fit
    some E exactly, so only a sixth agreeing point is evidence). */
    double inlierDistance = 0.004;
    int minInliers = 6;
    /** Also fit from R = I and the least-squares translation, keeping the better of the two fits.
     */
    bool twoStarts = true;
    /** Measured probability of reaching the true E from a sample with k inliers, k = 0..sampleSize
    (filled in by the constructor for sampleSize 10; see hitProbability()). */
    std::vector<double> rateByInliers;
};

/** The robust IRLS solver: from R = I and the least-squares translation for it, Levenberg-Marquardt
steps on the reweighted sum of squared epipolar distances g and g' (paper equation 5) of all sample
points, with Cauchy weights w = 1 / (1 + (g / sigma)^2) under an annealed scale sigma.

Cauchy rather than Tukey: from a start that may be far from the truth Tukey's weights are zero for
everything beyond its cut-off and the fit can stall on a wrong subset; Cauchy's never vanish, and
the annealed scale gives the same down-weighting of outliers once the fit is close. */
class RobustIrlsSolver : public EssentialSolver
{
public:
    explicit RobustIrlsSolver(const RobustIrlsSettings& settings = RobustIrlsSettings());
    int sampleSize() const override { return settings_.sampleSize; }
    int maxSolutions() const override { return 1; }
    int solve(const Point2d* x1, const Point2d* x2, RNG& rng, Matx33d* solutions) override;
    double successRate() const override;
    /** sum over k of Binomial(k; n, w) * rate(k) with the measured rates by inlier count. */
    double hitProbability(double inlierRatio) const override;

private:
    double fit(geometry::EssentialPose& pose, const Point2d* x1, const Point2d* x2) const;

    RobustIrlsSettings settings_;
};

} // namespace solvers
} // namespace essential
} // namespace cv

#endif
