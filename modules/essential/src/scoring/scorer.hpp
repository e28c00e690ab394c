// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The score a search and its local optimisation give every hypothesis and polished model: plain
// MSAC, or the in-front MSAC of a second search (SearchSettings::scoreInFront), on the points the
// search scores (a shuffled copy under SPRT), with the same early exit at the bound.

#ifndef OPENCV_ESSENTIAL_SCORING_SCORER_HPP
#define OPENCV_ESSENTIAL_SCORING_SCORER_HPP

#include "input/problem.hpp"
#include "scoring/in_front_score.hpp"
#include "scoring/msac_score.hpp"

#include <opencv2/core.hpp>

namespace cv {
namespace essential {
namespace scoring {

struct Scorer
{
    const Problem* points = nullptr;
    InlierTest test;
    bool inFront = false;

    Score operator()(const Matx33d& E, double bound) const
    {
        return inFront ? scoreMsacInFront(E, *points, test, bound)
                       : scoreMsac(E, *points, test, bound);
    }
};

} // namespace scoring
} // namespace essential
} // namespace cv

#endif
