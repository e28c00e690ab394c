// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The runners-up of a search: the few lowest-cost hypotheses that are distinct from one another.
// On narrow fields of view a wrong model can fit nearly as many points as the true one (rotation
// and sideways translation are confounded: on a real pair a pure-translation model fitted 465 of
// 506 matches within 1 px where the true pose fitted 488). When the wrong model is drawn first and
// polished by local optimisation, a later hypothesis from the true model, not yet polished, costs
// more than it and would be dropped; kept here, it is polished at the end of the search and wins.

#ifndef OPENCV_ESSENTIAL_LOCAL_OPTIMISATION_CANDIDATE_POOL_HPP
#define OPENCV_ESSENTIAL_LOCAL_OPTIMISATION_CANDIDATE_POOL_HPP

#include "geometry/same_model.hpp"

#include <opencv2/core.hpp>

#include <array>
#include <cmath>

namespace cv {
namespace essential {
namespace local_optimisation {

/** The kSize lowest-cost hypotheses offered, no two within kSameModel of each other (distance of
the unit-norm matrices up to sign). Fixed-size: offering allocates nothing. */
class CandidatePool
{
public:
    static constexpr int kSize = 4;

    /** Matrices nearer than this (Frobenius, both scaled to unit norm, up to sign) count as one
    model; the pool keeps the cheaper. */
    static constexpr double kSameModel = geometry::kSameModelDistance;
    /** Runners-up costing more than this many times the best model are not kept: a model of the
    true basin drawn from a noisy sample costs up to about 1.5 times the polished wrong one on the
    real pairs where the pool matters. */
    static constexpr double kCostFactor = 2.0;

    struct Entry
    {
        Matx33d E;
        double cost = HUGE_VAL;
    };

    /** The cost a hypothesis must beat to enter: the worst entry's once the pool is full. */
    double entryCost() const { return count_ < kSize ? HUGE_VAL : entries_[worst_].cost; }

    /** Offers a scored hypothesis. */
    void offer(const Matx33d& E, double cost)
    {
        if (!(cost < entryCost()) && count_ == kSize) return;
        const Matx33d unit = geometry::unitNorm(E);
        for (int i = 0; i < count_; ++i)
            if (same(unit, entries_[i].E)) {
                if (cost < entries_[i].cost) {
                    entries_[i] = Entry{unit, cost};
                    findWorst();
                }
                return;
            }
        if (count_ < kSize)
            entries_[count_++] = Entry{unit, cost};
        else
            entries_[worst_] = Entry{unit, cost};
        findWorst();
    }

    int size() const { return count_; }
    const Entry& operator[](int i) const { return entries_[i]; }

    /** Whether E is the model of one of the entries (kSameModel). */
    static bool same(const Matx33d& unitA, const Matx33d& unitB)
    {
        return geometry::sameUnitModel(unitA, unitB);
    }

private:
    void findWorst()
    {
        worst_ = 0;
        for (int i = 1; i < count_; ++i)
            if (entries_[i].cost > entries_[worst_].cost) worst_ = i;
    }

    std::array<Entry, kSize> entries_{};
    int count_ = 0, worst_ = 0;
};

} // namespace local_optimisation
} // namespace essential
} // namespace cv

#endif
