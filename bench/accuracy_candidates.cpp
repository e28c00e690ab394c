// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Where the final estimate's precision is won or lost (docs/ACCURACY.md, "Analysis"): the search of
// the drop-in call (adaptive MSAC, gn+nister, SPRT, local optimisation) is run once per problem,
// then each candidate final stage (which points the refinement sees, its loss and scale, its
// iteration cap and stopping rule, how the pose is read off) starts from the same search winner.
// Unlike the other programs under bench/ it reaches the module's internals (src/), as the tests do.
//
//   essential_accuracy_candidates [--n 500] [--ratios 0.9,0.7,0.5,0.25] [--problems 100]
//                                 [--max-iters 1000] [--camera paper|wide] [--threshold 1]
//                                 [--lo 5] [--lo-band 2] [--lo-scale 1] [--seed 1] [--only
//                                 NAME_PART,NAME_PART]

#include "synthetic_scene.hpp"

#include "bench_common.hpp"
#include "bench_options.hpp"
#include "pose_accuracy.hpp"

#include "geometry/essential_decomposition.hpp"
#include "input/problem.hpp"
#include "pose/pose_recovery.hpp"
#include "refine/final_refinement.hpp"
#include "refine/irls_refinement.hpp"
#include "scoring/msac_score.hpp"
#include "search/search.hpp"

#include <opencv2/essential.hpp>

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

using namespace essential_bench;
namespace ce = cv::essential;

namespace {

struct Args
{
    int n = 500;
    std::vector<double> ratios = {0.9, 0.7, 0.5, 0.25};
    int problems = 100;
    int maxIters = 1000;
    std::string camera = "paper";
    double threshold = 1.0;
    int lo = 5;
    double loBand = 2.0, loScale = 1.0; // the library's (pipeline/estimate.cpp)
    uint64_t seed = 1;
    std::vector<std::string> only; //!< run only candidates whose name contains one of these
};

Args parse(int argc, char** argv)
{
    Args a;
    Options opts("essential_accuracy_candidates");
    opts.add("n", a.n);
    opts.add("problems", a.problems);
    opts.add("max-iters", a.maxIters);
    opts.add("camera", a.camera);
    opts.add("threshold", a.threshold);
    opts.add("lo", a.lo);
    opts.add("lo-band", a.loBand);
    opts.add("lo-scale", a.loScale);
    opts.add("seed", a.seed);
    opts.add("ratios", a.ratios);
    opts.add("only", a.only, ';'); // the names hold commas
    opts.parse(argc, argv);
    return a;
}

/** What a candidate final stage gets: the problem, the search winner and the truth (for the oracle
only). */
struct Input
{
    const ce::Problem* problem;
    double threshold; //!< the inlier threshold on the Sampson distance, normalised
    cv::Matx33d searchE;
    const essential_test::SyntheticScene* scene;
};

struct Output
{
    cv::Matx33d E;
    std::vector<uchar> mask; //!< the points the pose's cheirality vote uses
};

ce::Problem subset(const ce::Problem& p, const std::vector<uchar>& mask)
{
    return ce::maskedProblem(p, mask.data());
}

std::vector<uchar> inliersOf(const cv::Matx33d& E, const ce::Problem& p, double threshold)
{
    std::vector<uchar> mask(static_cast<size_t>(p.size()));
    ce::scoring::inlierMask(E, p, ce::InlierTest{threshold}, mask.data());
    return mask;
}

/** The inliers of E that also lie in front of both cameras for E's pose (PoseLib's inlier rule). */
std::vector<uchar> inliersInFront(const cv::Matx33d& E, const ce::Problem& p, double threshold)
{
    std::vector<uchar> mask = inliersOf(E, p, threshold);
    ce::pose::PoseResult pr;
    ce::pose::recoverPoseNormalised(E, p, mask.data(), mask.data(), pr);
    return mask;
}

struct Candidate
{
    std::string name;
    std::function<Output(const Input&)> run;
};

ce::refine::IrlsSettings irls(int maxIterations, double tolerance)
{
    ce::refine::IrlsSettings s;
    s.maxIterations = maxIterations;
    s.relativeTolerance = tolerance;
    return s;
}

/** The final stage of the library before this work: IRLS on all points at half the threshold, 20
iterations, relative cost decrease 1e-6, kept unless 5% worse on the MSAC cost. */
Output current(const Input& in)
{
    const ce::Problem& p = *in.problem;
    Output o;
    o.E = in.searchE;
    const auto r = ce::refine::refineIrls(p, in.searchE, 0.5 * in.threshold);
    if (r.improved) {
        const double before =
            ce::scoring::scoreMsac(in.searchE, p, ce::InlierTest{in.threshold}).cost;
        const double after = ce::scoring::scoreMsac(r.E, p, ce::InlierTest{in.threshold}).cost;
        if (after <= 1.05 * before) o.E = r.E;
    }
    o.mask = inliersOf(o.E, p, in.threshold);
    return o;
}

/** Refinement on a point set chosen from the search winner. */
Output onPoints(const Input& in, const std::vector<uchar>& use, double scale,
                const ce::refine::IrlsSettings& s)
{
    const ce::Problem& p = *in.problem;
    Output o;
    const auto r = ce::refine::refineIrls(subset(p, use), in.searchE, scale, s);
    o.E = r.improved ? r.E : in.searchE;
    o.mask = inliersOf(o.E, p, in.threshold);
    return o;
}

} // namespace

int main(int argc, char** argv)
{
    const Args args = parse(argc, argv);
    cv::setNumThreads(1);
    const bool wide = args.camera == "wide";

    std::vector<Candidate> candidates;
    candidates.push_back({"search winner, no refinement", [](const Input& in) {
                              Output o;
                              o.E = in.searchE;
                              o.mask = inliersOf(o.E, *in.problem, in.threshold);
                              return o;
                          }});
    candidates.push_back({"before: all points, Cauchy 0.5 thr, 20 it, tol 1e-6", current});
    candidates.push_back(
        {"after: refineFinal (library)", [](const Input& in) {
             Output o;
             o.E = ce::refine::refineFinal(*in.problem, in.searchE, ce::InlierTest{in.threshold}).E;
             o.mask = inliersOf(o.E, *in.problem, in.threshold);
             return o;
         }});
    // The library's final stage with other settings.
    struct FinalVariant
    {
        const char* name;
        double window, minBand, bandSigmas, minScale, scaleSigmas;
        int rounds;
        double tukey;
        int firstTukey = 1;
    };
    const FinalVariant finals[] = {
        {"final: sigma = thr/2, band 2 thr, scale thr", 0, 2, 4, 1, 2, 1, 0},
        {"final: sigma = thr/2, band 2 thr, scale thr, 2 rounds", 0, 2, 4, 1, 2, 2, 0},
        {"final: est. sigma, band max(2 thr, 4 s), scale max(thr, 2 s)", 4, 2, 4, 1, 2, 1, 0},
        {"final: est. sigma, band max(2 thr, 4 s), scale max(thr, 2 s), 2 rounds", 4, 2, 4, 1, 2, 2,
         0},
        {"final: est. sigma, band 4 s, scale 2 s", 4, 0, 4, 0, 2, 1, 0},
        {"final: est. sigma, band 4 s, scale 2 s, 2 rounds", 4, 0, 4, 0, 2, 2, 0},
        {"final: est. sigma, band 3 s, scale 2 s, 2 rounds", 4, 0, 3, 0, 2, 2, 0},
        {"final: est. sigma, band 5 s, scale 2 s, 2 rounds", 4, 0, 5, 0, 2, 2, 0},
        {"final: est. sigma, band 4 s, scale 3 s, 2 rounds", 4, 0, 4, 0, 3, 2, 0},
        {"final: est. sigma, band 6 s, scale 3 s, 2 rounds", 4, 0, 6, 0, 3, 2, 0},
        {"final: est. sigma (window 6), band 4 s, scale 2 s, 2 rounds", 6, 0, 4, 0, 2, 2, 0},
        {"final: est. sigma, band max(thr, 4 s), scale max(thr/2, 2 s), 2 rounds", 4, 1, 4, 0.5, 2,
         2, 0},
        {"final: est. sigma, Cauchy then Tukey 4.685 s", 4, 2, 4, 1, 2, 2, 4.685},
        {"final: est. sigma, Cauchy then Tukey 3.5 s", 4, 2, 4, 1, 2, 2, 3.5},
        {"final: est. sigma, Cauchy then Tukey 6 s", 4, 2, 4, 1, 2, 2, 6},
        {"final: est. sigma, Cauchy then Tukey 4.685 s twice", 4, 2, 4, 1, 2, 3, 4.685},
        {"final: est. sigma, Tukey 4.685 s, 1 round", 4, 2, 4, 1, 2, 1, 4.685, 0},
        {"final: est. sigma, Tukey 4.685 s, 2 rounds", 4, 2, 4, 1, 2, 2, 4.685, 0},
        {"final: library default", 4, 2, 4, 1, 2, -1, 4.685, 0},
    };
    for (const FinalVariant& v : finals)
        candidates.push_back({v.name, [v](const Input& in) {
                                  ce::refine::FinalRefinementSettings fs;
                                  fs.noiseWindow = v.window;
                                  fs.minBand = v.minBand;
                                  fs.bandInSigmas = v.bandSigmas;
                                  fs.minScale = v.minScale;
                                  fs.scaleInSigmas = v.scaleSigmas;
                                  if (v.rounds > 0) { // else the library's rule
                                      fs.maxRounds = v.rounds;
                                      fs.nextRoundBelow = 1e300; // every round runs
                                  }
                                  fs.tukeyInSigmas = v.tukey;
                                  fs.firstTukeyRound = v.firstTukey;
                                  Output o;
                                  o.E = ce::refine::refineFinal(*in.problem, in.searchE,
                                                                ce::InlierTest{in.threshold}, fs)
                                            .E;
                                  o.mask = inliersOf(o.E, *in.problem, in.threshold);
                                  return o;
                              }});
    candidates.push_back({"all points, Cauchy 0.5 thr, 100 it, tol 1e-12", [](const Input& in) {
                              std::vector<uchar> all(in.problem->size(), 1);
                              return onPoints(in, all, 0.5 * in.threshold, irls(100, 1e-12));
                          }});
    candidates.push_back({"all points, Cauchy 1 thr, 100 it, tol 1e-12", [](const Input& in) {
                              std::vector<uchar> all(in.problem->size(), 1);
                              return onPoints(in, all, in.threshold, irls(100, 1e-12));
                          }});
    candidates.push_back({"inliers, Cauchy 0.5 thr, 20 it, tol 1e-6", [](const Input& in) {
                              const double t = in.threshold;
                              return onPoints(in, inliersOf(in.searchE, *in.problem, t), 0.5 * t,
                                              irls(20, 1e-6));
                          }});
    candidates.push_back({"inliers, Cauchy 0.5 thr, 100 it, tol 1e-12", [](const Input& in) {
                              const double t = in.threshold;
                              return onPoints(in, inliersOf(in.searchE, *in.problem, t), 0.5 * t,
                                              irls(100, 1e-12));
                          }});
    candidates.push_back({"inliers, Cauchy 1 thr, 100 it, tol 1e-12", [](const Input& in) {
                              const double t = in.threshold;
                              return onPoints(in, inliersOf(in.searchE, *in.problem, t), t,
                                              irls(100, 1e-12));
                          }});
    candidates.push_back({"inliers, least squares, 100 it, tol 1e-12", [](const Input& in) {
                              const double t = in.threshold;
                              return onPoints(in, inliersOf(in.searchE, *in.problem, t), 1e3 * t,
                                              irls(100, 1e-12));
                          }});
    candidates.push_back(
        {"inliers in front, Cauchy 1 thr, 100 it, tol 1e-12 (PoseLib's)", [](const Input& in) {
             const double t = in.threshold;
             return onPoints(in, inliersInFront(in.searchE, *in.problem, t), t, irls(100, 1e-12));
         }});
    candidates.push_back(
        {"inliers, Cauchy 1 thr, 100 it, then re-selected inliers again", [](const Input& in) {
             const double t = in.threshold;
             Output first =
                 onPoints(in, inliersOf(in.searchE, *in.problem, t), t, irls(100, 1e-12));
             Input again = in;
             again.searchE = first.E;
             return onPoints(again, first.mask, t, irls(100, 1e-12));
         }});
    // Points within `band` thresholds of the current model, refined with a Cauchy loss of
    // `scale` thresholds, `rounds` times (each round re-selects the points around the last result).
    auto banded = [](double band, double scale, int rounds, bool inFront) {
        return [=](const Input& in) {
            const double t = in.threshold;
            Input cur = in;
            Output o;
            for (int r = 0; r < rounds; ++r) {
                const std::vector<uchar> use =
                    inFront ? inliersInFront(cur.searchE, *in.problem, band * t)
                            : inliersOf(cur.searchE, *in.problem, band * t);
                o = onPoints(cur, use, scale * t, irls(100, 1e-12));
                cur.searchE = o.E;
            }
            return o;
        };
    };
    for (bool inFront : {false, true})
        for (double band : {2.0, 3.0})
            for (double scale : {0.5, 0.75, 1.0, 1.5})
                for (int rounds : {1, 2}) {
                    char name[160];
                    std::snprintf(name, sizeof name,
                                  "within %.0f thr%s, Cauchy %.2f thr, %d round%s", band,
                                  inFront ? " in front" : "", scale, rounds, rounds > 1 ? "s" : "");
                    candidates.push_back({name, banded(band, scale, rounds, inFront)});
                }
    // Stopping rules on the banded selection (2 thresholds, in front, Cauchy at the threshold).
    for (int cap : {5, 10, 20, 50, 100})
        for (double tol : {1e-6, 1e-8, 1e-10}) {
            char name[160];
            std::snprintf(name, sizeof name,
                          "stop: within 2 thr in front, Cauchy 1 thr, cap %d, tol %.0e", cap, tol);
            candidates.push_back({name, [cap, tol](const Input& in) {
                                      const double t = in.threshold;
                                      return onPoints(
                                          in, inliersInFront(in.searchE, *in.problem, 2 * t), t,
                                          irls(cap, tol));
                                  }});
        }
    // Oracles of the selection: the true inliers only, from the search winner.
    for (double scale : {0.5, 1.0, 1e3}) {
        char name[160];
        std::snprintf(name, sizeof name, "oracle selection: true inliers, Cauchy %.2g thr", scale);
        candidates.push_back({name, [scale](const Input& in) {
                                  std::vector<uchar> truth(in.problem->size());
                                  for (int i = 0; i < in.problem->size(); ++i)
                                      truth[i] = in.scene->inlier[i] ? 1 : 0;
                                  return onPoints(in, truth, scale * in.threshold,
                                                  irls(100, 1e-12));
                              }});
    }
    candidates.push_back(
        {"oracle selection: true inliers within 3 thr, Cauchy 0.5 thr", [](const Input& in) {
             std::vector<uchar> use = inliersOf(in.searchE, *in.problem, 3 * in.threshold);
             for (int i = 0; i < in.problem->size(); ++i)
                 use[i] = use[i] && in.scene->inlier[i];
             return onPoints(in, use, 0.5 * in.threshold, irls(100, 1e-12));
         }});
    candidates.push_back(
        {"oracle: true inliers, least squares, from the truth", [](const Input& in) {
             std::vector<uchar> truth(in.problem->size());
             for (int i = 0; i < in.problem->size(); ++i)
                 truth[i] = in.scene->inlier[i] ? 1 : 0;
             Input fromTruth = in;
             fromTruth.searchE = in.scene->E;
             return onPoints(fromTruth, truth, 1e3 * in.threshold, irls(100, 1e-12));
         }});

    if (!args.only.empty()) {
        std::vector<Candidate> kept;
        for (const Candidate& c : candidates)
            for (const std::string& part : args.only)
                if (c.name.find(part) != std::string::npos) {
                    kept.push_back(c);
                    break;
                }
        candidates = kept;
    }
    std::printf(
        "camera %s, N = %d, %d problems per ratio, maxIters %d, threshold %.2f px, LO %d\n\n",
        args.camera.c_str(), args.n, args.problems, args.maxIters, args.threshold, args.lo);
    std::printf(
        "| inliers | final stage | AUC@1 | AUC@5 | AUC@10 | reliable 2/5 | median err deg | "
        "median rot | median trans | final stage us |\n|---|---|---|---|---|---|---|---|---|"
        "---|\n");
    for (double ratio : args.ratios) {
        std::vector<std::vector<PoseOutcome>> outcomes(candidates.size());
        std::vector<double> searchMs;
        double samples = 0;
        for (int p = 0; p < args.problems; ++p) {
            essential_test::SceneConfig cfg =
                wide ? essential_test::wideCameraConfig() : essential_test::SceneConfig();
            cfg.numPoints = args.n;
            cfg.inlierRatio = ratio;
            const auto s = essential_test::makeScene(cfg, args.seed * 1000003ULL + p);
            const double f = cfg.focal;
            const ce::Problem problem = ce::makeProblem(s.x1, s.x2);
            const double threshold = args.threshold / f;

            ce::EssentialParams params;
            cv::Ptr<ce::EssentialSolver> solver = ce::createSolver(params.solver);
            cv::RNG rng(params.seed);
            ce::search::SearchSettings settings;
            settings.confidence = params.confidence;
            settings.maxIters = args.maxIters;
            settings.lo.iterations = args.lo;
            settings.test.threshold = threshold;
            settings.lo.scale = args.loScale * threshold;
            settings.lo.band = args.loBand;
            settings.sprt = params.sprt;
            const double s0 = threadCpuMs();
            const ce::search::SearchResult found =
                ce::search::searchMsac(problem, *solver, rng, settings);
            searchMs.push_back(threadCpuMs() - s0);
            samples += found.iterations;
            for (size_t c = 0; c < candidates.size(); ++c) {
                PoseOutcome o;
                if (found.found) {
                    const double t0 = threadCpuMs();
                    const Output out = candidates[c].run({&problem, threshold, found.E, &s});
                    o.ms = threadCpuMs() - t0;
                    ce::pose::PoseResult pr;
                    if (ce::pose::recoverPoseNormalised(out.E, problem, out.mask.data(), nullptr,
                                                        pr)) {
                        o.rotErr = essential_test::rotationErrorDeg(pr.R, s.R);
                        o.transErr = essential_test::translationErrorDeg(pr.t, s.t);
                    }
                }
                outcomes[c].push_back(o);
            }
        }
        std::printf(
            "| %.0f%% | (search: median %.3f ms CPU, %.0f samples on average) | | | | | | | "
            "| |\n",
            100 * ratio, median(searchMs), samples / args.problems);
        for (size_t c = 0; c < candidates.size(); ++c) {
            const AccuracySummary a = summarise(outcomes[c]);
            std::printf("| %.0f%% | %s | %.3f | %.3f | %.3f | %.3f | %.4f | %.4f | %.4f | %.0f |\n",
                        100 * ratio, candidates[c].name.c_str(), a.auc1, a.auc5, a.auc10,
                        a.reliableLoose, a.medianError, a.medianRot, a.medianTrans,
                        1e3 * a.medianMs);
        }
        std::fflush(stdout);
    }
    return 0;
}
