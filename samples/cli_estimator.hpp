// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// The estimator options both command-line programs take, with the same names, values and help:
// --solver, --engine, --method, --sampler, --threshold-px, --max-iterations, --budget-ms, --seed
// (essential_sequence takes lists for --solver and --budget-ms, essential_pair one of each), and
// the cv::essential::EssentialParams they make. Header-only; nothing here is part of the library.

#ifndef ESSENTIAL_SAMPLES_CLI_ESTIMATOR_HPP
#define ESSENTIAL_SAMPLES_CLI_ESTIMATOR_HPP

#include "cli_common.hpp"
#include "cli_parser.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/essential.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace essential_samples {

/** The estimator's settings from the command line. */
struct EstimatorOptions
{
    std::vector<std::string> solvers = {cv::essential::EssentialParams().solver};
    /** Time budgets in ms, 0 for none. */
    std::vector<double> budgetsMs = {0.0};
    cv::essential::EssentialEngine engine = cv::essential::ENGINE_ADAPTIVE;
    /** --method lmeds: least median of squares for both estimators; otherwise RANSAC (scored
    with MSAC by cv::essential). */
    bool lmeds = false;
    /** The module's default (uniform, with local samples past the confidence cap). PROSAC on the
    descriptor order is an option, not the default: on the front end's best 20% of the rail
    matches it took twice the time and got one pose of 54 wrong where uniform got none
    (docs/HARD_PAIRS.md). */
    cv::SamplingMethod sampler = cv::SAMPLING_UNIFORM;
    double thresholdPx = cv::essential::EssentialParams().threshold;
    int maxIterations = cv::essential::EssentialParams().maxIterations;
    bool maxIterationsGiven = false;
    std::uint64_t seed = cv::essential::EssentialParams().seed;
};

/** The estimator options and the old spellings they replace (deprecated, still accepted). */
inline std::vector<OptionSpec> estimatorOptionSpecs()
{
    return {{"solver", true, ""},
            {"engine", true, ""},
            {"method", true, ""},
            {"sampler", true, ""},
            {"threshold-px", true, ""},
            {"max-iterations", true, ""},
            {"budget-ms", true, ""},
            {"seed", true, ""},
            {"solvers", true, "solver"},
            {"budgets-ms", true, "budget-ms"},
            {"threshold", true, "threshold-px"},
            {"max-iters", true, "max-iterations"}};
}

/** The engines of EssentialParams::engine by their command-line names. */
inline constexpr NamedValue<cv::essential::EssentialEngine> kEngineNames[] = {
    {"adaptive", cv::essential::ENGINE_ADAPTIVE},
    {"preemptive", cv::essential::ENGINE_PREEMPTIVE},
    {"opencv", cv::essential::ENGINE_OPENCV}};

inline const char* engineName(cv::essential::EssentialEngine engine)
{
    return nameOfValue(kEngineNames, engine, "adaptive");
}

/** Applies the option `name` (an estimator option, see estimatorOptionSpecs()) to `options` and
returns true; false when `name` is not one. Fails (exit status 2) on a bad value; `lists` allows
several solvers and budgets. */
inline bool applyEstimatorOption(const GivenOption& option, bool lists, EstimatorOptions& options)
{
    const std::string& name = option.name;
    const std::string& value = option.value;
    if (name == "solver") {
        options.solvers = parseSolverList("--solver", value);
        if (!lists && options.solvers.size() != 1)
            fail("--solver takes one solver or mix here, not a list ('" + value + "')", 2);
    } else if (name == "budget-ms") {
        options.budgetsMs.clear();
        for (const std::string& part : split(value, ',')) {
            double budget;
            if (!parseDouble(part, budget) || budget < 0)
                fail("--budget-ms: '" + part + "' is not a time budget in ms (>= 0, 0 for none)",
                     2);
            options.budgetsMs.push_back(budget);
        }
        if (!lists && options.budgetsMs.size() != 1)
            fail("--budget-ms takes one budget here, not a list ('" + value + "')", 2);
    } else if (name == "engine") {
        if (!parseNamedValue(kEngineNames, value, options.engine))
            fail("--engine must be adaptive, preemptive or opencv, not '" + value + "'", 2);
        if (options.engine == cv::essential::ENGINE_OPENCV &&
            !cv::essential::isOpenCvLoopAvailable())
            fail("--engine opencv: this build cannot run solvers in OpenCV's loop", 2);
    } else if (name == "method") {
        if (value != "ransac" && value != "lmeds")
            fail("--method must be ransac or lmeds, not '" + value + "'", 2);
        options.lmeds = value == "lmeds";
    } else if (name == "sampler") {
        if (!parseSampler(value, options.sampler))
            fail("--sampler must be uniform, prosac, napsac or pnapsac, not '" + value + "'", 2);
    } else if (name == "threshold-px") {
        if (!parseDouble(value, options.thresholdPx) || !(options.thresholdPx > 0.0))
            fail("--threshold-px must be a positive number of pixels, not '" + value + "'", 2);
    } else if (name == "max-iterations") {
        long long iterations;
        if (!parseInt(value, iterations) || iterations < 1 || iterations > 100000000)
            fail("--max-iterations must be a positive integer, not '" + value + "'", 2);
        options.maxIterations = static_cast<int>(iterations);
        options.maxIterationsGiven = true;
    } else if (name == "seed") {
        if (!parseSeed(value, options.seed))
            fail("--seed must be a non-negative integer, not '" + value + "'", 2);
    } else {
        return false;
    }
    return true;
}

/** The settings of one estimate: `solver` with the time budget `budgetMs` (0: none). */
inline cv::essential::EssentialParams estimatorParams(const EstimatorOptions& options,
                                                      const std::string& solver, double budgetMs)
{
    cv::essential::EssentialParams params;
    params.solver = solver;
    params.engine = options.engine;
    params.score = options.lmeds ? cv::SCORE_METHOD_LMEDS : cv::SCORE_METHOD_MSAC;
    params.sampler = options.sampler;
    params.threshold = options.thresholdPx;
    params.maxIterations = options.maxIterations;
    params.seed = options.seed;
    if (budgetMs > 0) {
        // The budget, not the confidence or (unless given) the cap, ends the search.
        params.timeBudgetMs = budgetMs;
        params.confidence = 1.0 - 1e-12;
        if (!options.maxIterationsGiven) params.maxIterations = 100000000;
    }
    return params;
}

/** Fails (exit status 2) when the library rejects a combination of the options (an engine with a
method, sampler or budget it does not support), before any image is read: one call of
findEssentialMatIter per solver and budget on ten made-up correspondences, capped at one
iteration (and a budget of 1 us), so that it takes microseconds. */
inline void checkEstimatorCombination(const EstimatorOptions& options)
{
    std::vector<cv::Point2f> points1, points2;
    for (int i = 0; i < 10; ++i) {
        points1.emplace_back(static_cast<float>(37 * i % 11), static_cast<float>(53 * i % 7));
        points2.emplace_back(points1.back().x + 0.5f, points1.back().y + 0.25f * (i % 3));
    }
    for (const std::string& solver : options.solvers)
        for (double budgetMs : options.budgetsMs) {
            cv::essential::EssentialParams params =
                estimatorParams(options, solver, budgetMs > 0 ? 1e-3 : 0.0);
            params.maxIterations = 1;
            try {
                cv::essential::findEssentialMatIter(points1, points2, cv::Matx33d::eye(), params,
                                                    cv::noArray());
            } catch (const cv::Exception& e) {
                fail("these options do not go together: " + e.err, 2);
            }
        }
}

/** The method of cv::findEssentialMat for the comparison run. */
inline int opencvMethod(const EstimatorOptions& options)
{
    return options.lmeds ? cv::LMEDS : cv::RANSAC;
}

/** Help lines of the estimator options; `lists` for the program that takes lists. */
inline std::string estimatorHelp(bool lists)
{
    std::string solvers;
    for (const std::string& name : cv::essential::listSolvers())
        solvers += (solvers.empty() ? "" : ", ") + name;
    std::string help = "estimator (cv::essential::findEssentialMatIter):\n";
    if (lists)
        help += "  --solver LIST          solvers or mixes, comma separated: registered solvers\n"
                "                         (" +
                solvers +
                ") or mixes such as gn+nister or\n"
                "                         gn:3+nister:1 (default nister)\n"
                "  --budget-ms LIST       time budgets in milliseconds, comma separated, 0 for\n"
                "                         none (default 0).\n"
                "                         ";
    else
        help += "  --solver NAME          a registered solver (" + solvers +
                ")\n"
                "                         or a mix such as gn+nister or gn:3+nister:1 (default\n"
                "                         nister)\n"
                "  --budget-ms T          time budget in milliseconds, 0 for none (default 0).\n"
                "                         ";
    help += "With a budget the search stops when it is spent or at\n"
            "                         confidence 1 - 1e-12 (no iteration cap unless\n"
            "                         --max-iterations is given); OpenCV has no budget\n";
    help += "  --engine E             adaptive (default: the module's MSAC/LMedS loop),\n"
            "                         preemptive (Nister's preemptive RANSAC, as the paper) or\n"
            "                         opencv (OpenCV's RANSAC loop with the solver; ";
    help += cv::essential::isOpenCvLoopAvailable() ? "available" : "not available";
    help += " in\n                         this build; no budget)\n";
    help += "  --method M             ransac (default; cv::essential scores with MSAC) or lmeds,\n"
            "                         for cv::essential and for OpenCV's comparison run\n";
    help += "  --sampler S            uniform (default, the module's own: uniform until the\n"
            "                         confidence cap, then local and uniform in turn), prosac\n"
            "                         (the matches handed over best first: by descriptor\n"
            "                         distance, or in a matches file's order), napsac (all\n"
            "                         samples local) or pnapsac (local and uniform in turn)\n";
    help +=
        "  --threshold-px PX      inlier threshold on the Sampson distance, pixels (default 1)\n";
    help += "  --max-iterations N     iteration cap of both estimators (default 1000, as OpenCV)\n";
    help += "  --seed S               seed of cv::essential's random generator (decimal or 0x)\n";
    help += "  (deprecated spellings, accepted with a warning: --solvers, --budgets-ms,\n"
            "  --threshold, --max-iters, --keep)\n";
    return help;
}

} // namespace essential_samples

#endif
