// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The process-wide table of solver factories, keyed by name. The built-in solvers are put in on
// first use (not by static initialisers, whose order across translation units is unspecified and
// which a static link may drop).

#include "opencv2/essential/solver.hpp"

#include "solvers/checked_solver.hpp"
#include "solvers/composite_solver.hpp"
#include "solvers/gauss_newton.hpp"
#include "solvers/levenberg_marquardt.hpp"
#include "solvers/nister_five_point.hpp"
#include "solvers/robust_irls.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

namespace cv {
namespace essential {

EssentialSolver::~EssentialSolver() {}

double EssentialSolver::hitProbability(double inlierRatio) const
{
    const double w = std::min(1.0, std::max(0.0, inlierRatio));
    return successRate() * std::pow(w, sampleSize());
}

double EssentialSolver::hitProbabilityAt(double inlierRatio, const Matx33d& /*model*/) const
{
    return hitProbability(inlierRatio);
}

namespace {

/** Largest sampleSize() and maxSolutions() a solver may declare: the engines allocate that much
per estimate, and no essential-matrix solver needs more (the built-in ones: 10 and 10). */
constexpr int kMaxSolverSize = 1000;

struct Entry
{
    EssentialSolverFactory factory;
    /** A user's factory (registerSolver()): its solvers are wrapped in a CheckedSolver. */
    bool user = false;
};

struct Registry
{
    std::mutex mutex;
    std::map<std::string, Entry> factories;

    Registry()
    {
        factories["gn"] = {[] { return makePtr<solvers::GaussNewtonSolver>(); }, false};
        factories["lm"] = {[] { return makePtr<solvers::LevenbergMarquardtSolver>(); }, false};
        factories["nister"] = {[] { return makePtr<solvers::NisterFivePointSolver>(); }, false};
        factories["robust"] = {[] { return makePtr<solvers::RobustIrlsSolver>(); }, false};
    }
};

Registry& registry()
{
    static Registry instance;
    return instance;
}

} // namespace

void registerSolver(const std::string& name, const EssentialSolverFactory& factory)
{
    if (name.empty()) CV_Error(Error::StsBadArg, "registerSolver: the solver name is empty");
    if (name.find_first_of("+:") != std::string::npos)
        CV_Error(Error::StsBadArg,
                 "registerSolver: '" + name + "' contains '+' or ':', which compose solver names");
    if (!factory)
        CV_Error(Error::StsBadArg, "registerSolver: the factory of solver '" + name + "' is empty");
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    r.factories[name] = Entry{factory, true};
}

Ptr<EssentialSolver> createSolver(const std::string& name)
{
    if (name.find('+') != std::string::npos || name.find(':') != std::string::npos) {
        std::vector<std::string> partNames;
        std::vector<int> weights;
        solvers::parseCompositeName(name, partNames, weights);
        std::vector<Ptr<EssentialSolver>> parts;
        for (const std::string& part : partNames)
            parts.push_back(createSolver(part));
        return makePtr<solvers::CompositeSolver>(std::move(parts), std::move(weights));
    }
    Entry entry;
    {
        Registry& r = registry();
        std::lock_guard<std::mutex> lock(r.mutex);
        auto it = r.factories.find(name);
        if (it == r.factories.end()) {
            std::string known;
            for (const auto& kv : r.factories)
                known += (known.empty() ? "" : ", ") + kv.first;
            CV_Error(Error::StsBadArg,
                     "createSolver: unknown solver '" + name + "' (registered: " + known + ")");
        }
        entry = it->second;
    }
    Ptr<EssentialSolver> solver =
        solvers::callUserCode(name, "the factory", [&] { return entry.factory(); });
    if (!solver)
        CV_Error(Error::StsError, "createSolver: the factory of '" + name + "' returned null");
    const int sampleSize =
        solvers::callUserCode(name, "sampleSize()", [&] { return solver->sampleSize(); });
    const int maxSolutions =
        solvers::callUserCode(name, "maxSolutions()", [&] { return solver->maxSolutions(); });
    if (sampleSize < 5 || maxSolutions < 1 || sampleSize > kMaxSolverSize ||
        maxSolutions > kMaxSolverSize)
        CV_Error(Error::StsBadArg,
                 "createSolver: solver '" + name + "' must have sampleSize() in [5, " +
                     std::to_string(kMaxSolverSize) + "] and maxSolutions() in [1, " +
                     std::to_string(kMaxSolverSize) + "] (got " + std::to_string(sampleSize) +
                     " and " + std::to_string(maxSolutions) + ")");
    if (entry.user) return makePtr<solvers::CheckedSolver>(solver, name, sampleSize, maxSolutions);
    return solver;
}

std::vector<std::string> listSolvers()
{
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    std::vector<std::string> names;
    for (const auto& kv : r.factories)
        names.push_back(kv.first);
    return names;
}

} // namespace essential
} // namespace cv
