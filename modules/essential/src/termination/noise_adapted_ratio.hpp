// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#ifndef OPENCV_ESSENTIAL_TERMINATION_NOISE_ADAPTED_RATIO_HPP
#define OPENCV_ESSENTIAL_TERMINATION_NOISE_ADAPTED_RATIO_HPP

#include <algorithm>
#include <cmath>

namespace cv {
namespace essential {
namespace termination {

/** The inlier ratio for the stopping rule when the threshold lies below the noise.

The stopping rule counts the samples needed to draw one whose points are all correct matches. With
a threshold below the noise (OpenCV's default 1 px on a camera whose matches are 2 px off) most
correct matches fall outside it: the best model's inlier ratio is a fraction of the correct ones',
and the rule, raised to the fifth power, asks for tens of times the samples (a 50% correct set
looks like 22%: 14 000 samples instead of 230). The correct matches are still visible in the
distances to the best model: they pile up over several threshold-wide bands, where the outliers'
distances, spread over the whole image, add about as much to every band.

From the counts of distanceBands (band k: k t < d <= (k + 1) t): the outlier level is the mean
count of the far bands [kOutlierBandsFrom, kBands); the correct matches are the excess over that
level of the bands from 0 up to the first whose excess is not significant (under
kSignificance Poisson deviations of the level, at least one point). Used only when the noise is
visibly as wide as the threshold (the excess of bands 1 and 2 at least kSpread times band 0's): for
a threshold at two or more noise deviations, they hold a few per cent of band 0 and the ratio is
the inlier ratio itself. Errors lean to the safe side: correct matches beyond the far bands' start
raise the outlier level and lower the estimate, so the rule asks for more samples, never fewer. */
class NoiseAdaptedRatio
{
public:
    /** Bands counted: out to 16 thresholds. */
    static constexpr int kBands = 16;
    /** The outlier level from bands 8 to 15 (distances of 8 to 16 thresholds): past nearly all
    correct matches for a noise deviation up to three thresholds (8 t = 2.7 deviations: 99.3% of
    them inside), near enough to the model for the outliers' density to be the one near it. */
    static constexpr int kOutlierBandsFrom = 8;
    /** Noise as wide as the threshold or wider: the excess of bands 1 and 2 together at least half
    of band 0's. A Gaussian distance of deviation s gives (band 1 + band 2) / band 0 = 0.05 at t =
    2 s, 0.19 at t = 1.4 s, 0.46 at t = s, 0.57 at t = 0.9 s and 1.41 at t = 0.43 s (the wide
    camera at 1 px: s = 2.35 px along the epipolar normal). Two bands, not band 1 alone: with 150
    correct matches at s = 3 t one band's count varies by a third (test_noise_adapted_ratio). */
    static constexpr double kSpread = 0.5;
    /** A band's excess is significant above this many Poisson deviations of the outlier level. */
    static constexpr double kSignificance = 2.0;

    /** Points the bands are counted on, at most: a larger set is read every k-th point. Its
    Poisson noise moves the estimate by about 1% of the points (test_noise_adapted_ratio, at 500);
    the whole set cost the rail sequences (2 000 to 14 000 matches, a pass per new best model) 5%
    of their time. */
    static constexpr int kMaxPoints = 1000;

    /** The estimated fraction of correct matches among the `n` points counted, at least
    `apparent` (the inlier ratio), from the band counts `counts[0..kBands)` of the same model. */
    static double ratio(const int* counts, int n, double apparent)
    {
        if (n <= 0) return apparent;
        double level = 0.0;
        for (int k = kOutlierBandsFrom; k < kBands; ++k)
            level += counts[k];
        level /= (kBands - kOutlierBandsFrom);
        const double first = counts[0] - level, next = counts[1] + counts[2] - 2.0 * level;
        if (!(first > 0.0) || next < kSpread * first) return apparent;
        const double margin = std::max(1.0, kSignificance * std::sqrt(level));
        double correct = 0.0;
        for (int k = 0; k < kOutlierBandsFrom; ++k) {
            const double excess = counts[k] - level;
            if (excess <= margin) break;
            correct += excess;
        }
        return std::max(apparent, std::min(1.0, correct / n));
    }
};

} // namespace termination
} // namespace essential
} // namespace cv

#endif
