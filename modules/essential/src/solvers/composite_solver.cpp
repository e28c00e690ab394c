// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "solvers/composite_solver.hpp"

#include <algorithm>
#include <cstdlib>

namespace cv {
namespace essential {
namespace solvers {

CompositeSolver::CompositeSolver(std::vector<Ptr<EssentialSolver>> parts, std::vector<int> weights)
    : parts_(std::move(parts)), weights_(std::move(weights))
{
    CV_Assert(!parts_.empty() && parts_.size() == weights_.size());
    for (size_t i = 0; i < parts_.size(); ++i) {
        sampleSize_ = std::max(sampleSize_, parts_[i]->sampleSize());
        maxSolutions_ = std::max(maxSolutions_, parts_[i]->maxSolutions());
        totalWeight_ += weights_[i];
    }
    // Next to a direct solver, iterative parts start from R = I only (IdentityStartOnly).
    bool hasDirectPart = false;
    for (const Ptr<EssentialSolver>& part : parts_)
        hasDirectPart |= part->successRate() >= 0.99;
    if (hasDirectPart)
        for (const Ptr<EssentialSolver>& part : parts_)
            if (auto* iterative = dynamic_cast<IdentityStartOnly*>(part.get()))
                iterative->useIdentityStartOnly();
    // Interleave: at each step pick the part furthest behind its share (smooth weighted
    // round-robin), so "gn:3+nister:1" runs gn, gn, nister, gn rather than three gn in a row.
    std::vector<int> credit(parts_.size(), 0);
    for (int step = 0; step < totalWeight_; ++step) {
        size_t pick = 0;
        for (size_t i = 0; i < parts_.size(); ++i) {
            credit[i] += weights_[i];
            if (credit[i] > credit[pick]) pick = i;
        }
        credit[pick] -= totalWeight_;
        schedule_.push_back(static_cast<int>(pick));
    }
}

int CompositeSolver::solve(const Point2d* x1, const Point2d* x2, RNG& rng, Matx33d* solutions)
{
    EssentialSolver& part = *parts_[static_cast<size_t>(schedule_[next_])];
    next_ = (next_ + 1) % schedule_.size();
    return part.solve(x1, x2, rng, solutions);
}

double CompositeSolver::successRate() const
{
    double sum = 0.0;
    for (size_t i = 0; i < parts_.size(); ++i)
        sum += weights_[i] * parts_[i]->successRate();
    return sum / totalWeight_;
}

double CompositeSolver::hitProbability(double inlierRatio) const
{
    double sum = 0.0;
    for (size_t i = 0; i < parts_.size(); ++i)
        sum += weights_[i] * parts_[i]->hitProbability(inlierRatio);
    return sum / totalWeight_;
}

double CompositeSolver::hitProbabilityAt(double inlierRatio, const Matx33d& model) const
{
    double sum = 0.0;
    for (size_t i = 0; i < parts_.size(); ++i)
        sum += weights_[i] * parts_[i]->hitProbabilityAt(inlierRatio, model);
    return sum / totalWeight_;
}

void CompositeSolver::useIdentityStartOnly(bool keepCheirality)
{
    for (const Ptr<EssentialSolver>& part : parts_)
        if (auto* iterative = dynamic_cast<IdentityStartOnly*>(part.get()))
            iterative->useIdentityStartOnly(keepCheirality);
}

void CompositeSolver::setThreshold(double normalisedThreshold)
{
    for (const Ptr<EssentialSolver>& part : parts_)
        part->setThreshold(normalisedThreshold);
}

void parseCompositeName(const std::string& name, std::vector<std::string>& parts,
                        std::vector<int>& weights)
{
    parts.clear();
    weights.clear();
    size_t begin = 0;
    while (begin <= name.size()) {
        const size_t end = std::min(name.find('+', begin), name.size());
        const std::string item = name.substr(begin, end - begin);
        const size_t colon = item.find(':');
        const std::string part = item.substr(0, colon);
        int weight = 1;
        if (colon != std::string::npos) {
            const std::string w = item.substr(colon + 1);
            char* stop = nullptr;
            const long value = std::strtol(w.c_str(), &stop, 10);
            if (w.empty() || *stop != '\0' || value < 1 || value > 1000)
                CV_Error(Error::StsBadArg, "solver '" + name + "': the weight of '" + part +
                                               "' must be an integer from 1 to 1000");
            weight = static_cast<int>(value);
        }
        if (part.empty()) CV_Error(Error::StsBadArg, "solver '" + name + "' has an empty part");
        parts.push_back(part);
        weights.push_back(weight);
        begin = end + 1;
    }
}

} // namespace solvers
} // namespace essential
} // namespace cv
