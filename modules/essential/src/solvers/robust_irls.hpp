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

/** Settings of the robust solver; docs/SOLVERS.md records the measurements behind the defaults.
Distances are in units of the caller's threshold (setThreshold(), the Sampson distance of an
inlier in normalised units), so that they mean the same number of pixels at any focal length. */
struct RobustIrlsSettings
{
    /** Correspondences per sample (the paper found 10 best). 8 to 10: the starts are the exact
    eight-point fits of the sample's subsets of eight. */
    int sampleSize = 10;
    /** The threshold until setThreshold() is called: 1 px at a focal length of 500. */
    double threshold = 0.002;
    /** Starts refined by IRLS: the best of the subset fits (and of the least-squares fit on the
    whole sample and of R = I with its least-squares translation), each made essential, by their
    truncated cost on the sample. Measured (exploratory runs of essential_robust_sample_rates with
    the settings changed, 800 samples per inlier count, noise 0.5 px, threshold 1 px): refining the
    best two instead of one changed the rates by less than their standard error (9 inliers 0.884
    against 0.880, 8 inliers 0.583 against 0.609) at 14% more time. */
    int refinedStarts = 1;
    /** A start's truncated cost counts each point's squared Sampson distance up to
    (startGate * threshold)^2. An exact fit of eight noisy points carries their noise (made
    essential, the clean subset's fit is within 0.05 of the truth in only 42% of samples with 8
    inliers), so the gate is wide: gates of 2 / 3 / 5 / 10 thresholds ranked the clean subset's fit
    first in 52 / 54 / 60 / 61% of such samples; 5 gave the best rates. */
    double startGate = 5.0;
    /** IRLS iterations (each one LM step with the weights fixed), the Cauchy scale going from
    initialScale to finalScale thresholds by the factor scaleDecay per iteration. From a start
    close to the truth a long schedule only costs time: 8 iterations from 4 thresholds reached the
    same rates as 12 from 8 (and 20 from 8, or 15 from 20: 9 inliers 0.86 / 0.81). */
    int maxIterations = 8;
    double initialScale = 4.0;
    double scaleDecay = 0.5;
    double finalScale = 1.0;
    /** A sample point is an inlier of the result when both epipolar distances g, g' are below
    inlierDistance thresholds (a point at Sampson distance d has g, g' of about sqrt(2) d); a
    result with fewer than `minInliers` inliers in its own sample is rejected (any five points fit
    some E exactly, so only a sixth agreeing point is evidence). */
    double inlierDistance = 2.0;
    int minInliers = 6;
    /** Measured probability of reaching the true E from a sample with k inliers, k = 0..sampleSize
    (filled in by the constructor for sampleSize 10; see hitProbability()). */
    std::vector<double> rateByInliers;
};

/** The robust IRLS solver. Starts: the exact eight-point fit of each subset of eight of the
sample (45 for ten points; with one or two outliers in the sample some subsets are clean and fit
the true E up to noise), the least-squares eight-point fit of the whole sample, and R = I with the
least-squares translation; they are ranked by their truncated Sampson cost on the sample. From the
best `refinedStarts` of them, Levenberg-Marquardt steps on the Cauchy-weighted epipolar distances
g and g' (paper equation 5) of all sample points, with an annealed scale, down to the caller's
threshold; the lowest final robust cost wins.

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
    /** Sets the loss scale and the inlier test (RobustIrlsSettings::threshold). */
    void setThreshold(double normalisedThreshold) override;

private:
    double fit(geometry::EssentialPose& pose, const Point2d* x1, const Point2d* x2) const;

    RobustIrlsSettings settings_;
};

} // namespace solvers
} // namespace essential
} // namespace cv

#endif
