// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Local optimisation of the adaptive MSAC search (LO-RANSAC, Chum, Matas and Kittler): each new
// best model is polished by IRLS on its inliers and, when its inlier ratio is low, first gets an
// inner RANSAC on the points near it; at the end of the search the runners-up of other basins
// (CandidatePool) are polished too. A polished model replaces the best one only when its MSAC cost
// on all points is lower and it keeps at least a sample's worth of inliers.

#ifndef OPENCV_ESSENTIAL_LOCAL_OPTIMISATION_LOCAL_OPTIMISATION_HPP
#define OPENCV_ESSENTIAL_LOCAL_OPTIMISATION_LOCAL_OPTIMISATION_HPP

#include "input/problem.hpp"
#include "local_optimisation/candidate_pool.hpp"
#include "sampling/sample_buffer.hpp"
#include "scoring/scorer.hpp"

#include "opencv2/essential/solver.hpp"

#include <opencv2/core.hpp>

#include <vector>

namespace cv {
namespace essential {
namespace local_optimisation {

struct LocalOptimisationSettings
{
    /** IRLS iterations of a polish (0: no local optimisation). */
    int iterations = 0;
    /** The polish fits all the points within `band` thresholds of the model (sampleSize 0) or a
    random subset of sampleSize of them. */
    int sampleSize = 0;
    double band = 1.0;
    /** The IRLS Cauchy scale, normalised units. */
    double scale = 0.0;
};

/** What local optimisation adds to the search's counters (SearchResult). */
struct LocalOptimisationCounters
{
    int hypothesesGenerated = 0; //!< inner-sample solver calls
    int hypothesesConverged = 0; //!< matrices they returned (all of them scored)
    int64 pointsScored = 0;      //!< Sampson distances of inner hypotheses and polished models
    int polishes = 0;            //!< IRLS polishes run
    int polishesKept = 0;        //!< of which replaced the best model
};

/** The best model of a search and its MSAC score; local optimisation may replace both. */
struct BestModel
{
    Matx33d E;
    scoring::Score score;
};

class LocalOptimisation
{
public:
    /** `searchRngState` seeds the inner samples' own generator, so that the search draws the same
    samples whatever local optimisation does; `minInliers` is what a replacement must keep. */
    LocalOptimisation(const Problem& problem, EssentialSolver& solver,
                      const LocalOptimisationSettings& settings, const scoring::Scorer& score,
                      bool sampleCheirality, uint64 searchRngState, int minInliers);

    bool enabled() const { return settings_.iterations > 0; }

    /** Optimises a new best model after `samplesDrawn` samples of the search. Returns true when
    its inner samples were deferred (kInnerMinSamples: too early to trust a low-support model);
    the search then calls again once it has drawn that many, for the model it then holds. The
    polish draws its subset (LocalOptimisationSettings::sampleSize) from `rng`. */
    bool improveBest(int samplesDrawn, RNG& rng, BestModel& best,
                     LocalOptimisationCounters& counters);

    /** Polishes the runners-up of other basins that cost within CandidatePool::kCostFactor of the
    best; one may descend below it. */
    void polishRunnersUp(const CandidatePool& pool, RNG& rng, BestModel& best,
                         LocalOptimisationCounters& counters);

    /** Samples the search draws before a low-support best model gets its inner samples. */
    static int innerMinSamples();

private:
    void innerSampling(BestModel& best, LocalOptimisationCounters& counters);
    /** IRLS from `start`, replacing `best` if it is better. */
    void polish(const Matx33d& start, RNG& rng, BestModel& best,
                LocalOptimisationCounters& counters);

    const Problem& problem_;
    EssentialSolver& solver_;
    LocalOptimisationSettings settings_;
    scoring::Scorer score_;
    int minInliers_;
    std::vector<uchar> mask_;
    std::vector<int> chosen_;
    Problem subset_; //!< the points a polish fits, its storage kept from one polish to the next
    sampling::SampleBuffer inner_;
    RNG innerRng_;
};

} // namespace local_optimisation
} // namespace essential
} // namespace cv

#endif
