// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Mixed hypothesis sources: the paper's conclusion suggests drawing hypotheses from GN and Nister
// together. A composite solver takes turns among its parts in a fixed proportion.

#ifndef OPENCV_ESSENTIAL_SOLVERS_COMPOSITE_SOLVER_HPP
#define OPENCV_ESSENTIAL_SOLVERS_COMPOSITE_SOLVER_HPP

#include "opencv2/essential/solver.hpp"
#include "solvers/iterative_minimal_solver.hpp"

#include <string>
#include <vector>

namespace cv {
namespace essential {
namespace solvers {

/** Calls its parts in turn, part i on `weights[i]` of every sum(weights) samples, in a fixed
interleaved order. The sample is the largest any part needs; a part that needs fewer points uses
the first ones (a random subset of a random sample is a random sample). */
class CompositeSolver : public EssentialSolver, public IdentityStartOnly
{
public:
    CompositeSolver(std::vector<Ptr<EssentialSolver>> parts, std::vector<int> weights);
    int sampleSize() const override { return sampleSize_; }
    int maxSolutions() const override { return maxSolutions_; }
    int solve(const Point2d* x1, const Point2d* x2, RNG& rng, Matx33d* solutions) override;
    /** The parts' rates averaged with their weights. */
    double successRate() const override;
    double hitProbability(double inlierRatio) const override;
    /** The parts' hitProbabilityAt() averaged with their weights. */
    double hitProbabilityAt(double inlierRatio, const Matx33d& model) const override;
    /** Passed on to every part. */
    void setThreshold(double normalisedThreshold) override;
    /** Passed on to every iterative part. */
    void useIdentityStartOnly(bool keepCheirality = true) override;

private:
    std::vector<Ptr<EssentialSolver>> parts_;
    std::vector<int> schedule_; // part index for each call of one round
    std::vector<int> weights_;
    size_t next_ = 0;
    int sampleSize_ = 0, maxSolutions_ = 0, totalWeight_ = 0;
};

/** Parses "a+b", "a:3+b:1" (weights default to 1) into part names and weights. Throws
cv::Exception (StsBadArg) for an empty part or a weight that is not a positive integer. */
void parseCompositeName(const std::string& name, std::vector<std::string>& parts,
                        std::vector<int>& weights);

} // namespace solvers
} // namespace essential
} // namespace cv

#endif
