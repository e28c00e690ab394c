// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// PROSAC (Chum and Matas, "Matching with PROSAC - progressive sample consensus", CVPR 2005): when
// the correspondences are sorted by a quality measure, best first, samples are drawn from a pool of
// the best n points that grows with the number of samples drawn, so that good correspondences are
// tried first, and the search may stop as soon as a model is well supported within such a pool.

#ifndef OPENCV_ESSENTIAL_SAMPLING_PROSAC_SAMPLER_HPP
#define OPENCV_ESSENTIAL_SAMPLING_PROSAC_SAMPLER_HPP

#include <opencv2/core.hpp>

#include <vector>

namespace cv {
namespace essential {
namespace sampling {

/** The PROSAC sampler with the paper's growth schedule.

The schedule: with T_N samples of size m drawn uniformly from all N points, T_n = T_N C(n, m) /
C(N, m) of them would on average come from the best n only; T'_m = 1 and T'_{n+1} = T'_n +
ceil(T_{n+1} - T_n). Sample t (counted from 1) first grows the pool from n to n + 1 when t reaches
T'_n (and n is below the termination length); if t has passed T'_n it is the point u_n (the n-th
best) with m - 1 points drawn uniformly from the best n - 1, otherwise m points drawn uniformly from
the best n. After T_N samples the sampler is uniform over all N points (PROSAC has become RANSAC).
*/
class ProsacSampler
{
public:
    /** `n` points sorted best first, samples of `m` points, T_N = `growthMaxSamples` (the engine
    uses its sample cap, so that the pool has grown to all N points when the cap is reached). */
    ProsacSampler(int n, int m, int growthMaxSamples);

    /** Draws the next sample's m distinct indices into `indices`. */
    void draw(RNG& rng, int* indices);

    /** Size n of the current sampling pool (the best n points). */
    int poolSize() const { return pool_; }
    /** Samples drawn so far (t). */
    int samplesDrawn() const { return t_; }
    /** True once T_N samples have been drawn: every further sample is uniform over all points. */
    bool isUniform() const { return t_ >= growthMax_; }
    /** The paper's termination length n*: the pool no longer grows beyond it (clamped to
    [poolSize(), N]). Initially N. */
    void setTerminationLength(int nStar);
    int terminationLength() const { return termination_; }

private:
    int n_, m_, growthMax_;
    int pool_ = 0, termination_ = 0, t_ = 0;
    /** growth_[k] = T'_k for k in [m, N]: the sample at which the pool reaches k points. */
    std::vector<double> growth_;
};

/** PROSAC's stopping rule (the paper's section 2.2): the search may stop when, for some termination
length n, the inliers I_n of the best model among the best n points are
 - non-random: I_n >= I_min(n), the least count that n - m points (besides the m of the sample)
   reach by chance with probability below psi = 0.05, each being an inlier of a wrong model with
   probability beta = 0.05 (the paper's and OpenCV's values; binomial tail, computed exactly on a
   grid of at most 65 lengths and rounded up in between, which only makes it stricter);
 - maximal: the samples drawn entirely from the best n points reach the number the confidence
   needs for an inlier ratio I_n / n.
*/
class ProsacTermination
{
public:
    ProsacTermination(int n, int m);
    /** I_min(n) of the non-randomness condition, for n in [m, N]. */
    int minInliers(int n) const;
    /** Minimum termination length considered (as OpenCV's PROSAC: 100 points, or N if fewer). */
    int minLength() const { return minLength_; }

private:
    int minLength_;
    std::vector<int> gridLength_, gridMin_;
};

} // namespace sampling
} // namespace essential
} // namespace cv

#endif
