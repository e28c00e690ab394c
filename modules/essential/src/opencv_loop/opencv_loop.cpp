// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// ENGINE_OPENCV: any registered solver run inside OpenCV's own exported RANSAC or LMedS loop (the
// loops cv::findEssentialMat uses with its 5-point kernel), through a PointSetRegistrator::Callback
// adapter. The declaration of that private OpenCV interface is ours
// (opencv_loop/opencv_point_set_registrator.hpp); the configure-time probe
// (cmake/ProbeOpenCvLoop.cmake) defines ESSENTIAL_HAVE_OPENCV_LOOP only when it matches the
// installed library. Without it, this file compiles to functions that raise StsNotImplemented.
//
// What OpenCV's loop does differently from the module's own (search_msac.cpp, search_lmeds.cpp):
// - it draws its samples itself, with its own generator seeded with a constant (the same samples
//   for every call on the same data); EssentialParams::seed only reaches the solver's rng;
// - its RANSAC counts inliers (error <= threshold^2) instead of the MSAC cost, and its number of
//   iterations follows log(1 - confidence) / log(1 - w^m) with m = sampleSize() for the best inlier
//   ratio w so far, capped at maxIters (passed as given). That formula assumes a direct solver,
//   which solves every outlier-free sample: an iterative solver that succeeds only on a fraction s
//   < 1 of them (EssentialSolver::successRate(), 0.28 to 0.41 for gn by rotation) does not reach
//   the requested confidence when the loop stops; the real confidence is 1 - (1 - confidence)^s,
//   about 0.86 instead of 0.999 for gn at s = 0.28. The module's own loop divides by s; OpenCV's
//   loop is used unchanged.
// - its LMedS draws a fixed number of samples for an assumed 45% of outliers, the same formula
//   without s, and floors the data-derived inlier threshold at 0.001 (normalised units here);
// - it cannot be interrupted: SearchSettings::deadline is not honoured (findEssentialMatIter
//   rejects a time budget with this engine).

#include "search/search.hpp"

#include "opencv2/essential/params.hpp"

#ifdef ESSENTIAL_HAVE_OPENCV_LOOP
#include "opencv_loop/opencv_point_set_registrator.hpp"
#include "scoring/msac_score.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>
#endif

namespace cv {
namespace essential {

#ifdef ESSENTIAL_HAVE_OPENCV_LOOP

namespace search {

namespace {

/** Normalised points closer than this (squared) are the same point (as SampleBuffer). */
constexpr double kCoincident2 = 1e-18;

/** Reads the 2D points of a sample or data array, in any layout the loop may pass, into `out`. */
void readSample(InputArray in, std::vector<Point2d>& out)
{
    Mat m = in.getMat();
    const int count = m.checkVector(2);
    CV_Assert(count >= 0);
    if (m.type() != CV_64FC2 || !m.isContinuous()) {
        Mat converted;
        m.convertTo(converted, CV_64F);
        m = converted.reshape(2, count);
    }
    out.resize(static_cast<size_t>(count));
    const Point2d* p = m.ptr<Point2d>();
    std::copy(p, p + count, out.begin());
}

/** The 3 x 3 model at the top of `model`, as Matx33d. */
Matx33d readModel(InputArray model)
{
    const Mat m = model.getMat();
    CV_Assert(m.rows >= 3 && m.cols == 3 && m.channels() == 1);
    Mat E64;
    m.rowRange(0, 3).convertTo(E64, CV_64F); // a fresh, continuous copy
    return Matx33d(E64.ptr<double>());
}

/** The solver as OpenCV's kernel. The data handed to the loop are the problem's points as Point2d
arrays (N x 1 CV_64FC2, `handed` the first view's), so a sample arrives as modelPoints x 1
CV_64FC2 and the errors of all points can be computed on the problem itself. Counts the calls, which
OpenCV's loop does not report. */
class SolverCallback : public PointSetRegistrator::Callback
{
public:
    SolverCallback(const Problem& problem, InlierTest test, const Point2d* handed,
                   EssentialSolver& solver, RNG& rng)
        : problem_(problem), test_(test), handed_(handed), solver_(solver), rng_(rng),
          solutions_(static_cast<size_t>(std::max(1, solver.maxSolutions()))),
          errors_(static_cast<size_t>(problem.size()))
    {
    }

    /** Runs the solver once on the sample OpenCV drew (it draws nothing itself) and writes the
    finite solutions stacked as a 3n x 3 CV_64F matrix. */
    int runKernel(InputArray m1, InputArray m2, OutputArray model) const override
    {
        readSample(m1, x1_);
        readSample(m2, x2_);
        CV_Assert(x1_.size() == x2_.size() && static_cast<int>(x1_.size()) >= solver_.sampleSize());
        ++kernelCalls;
        const int count = std::min(solver_.solve(x1_.data(), x2_.data(), rng_, solutions_.data()),
                                   static_cast<int>(solutions_.size()));
        int kept = 0;
        for (int h = 0; h < count; ++h) {
            const Matx33d& E = solutions_[h];
            bool finite = true;
            for (int i = 0; i < 9; ++i)
                finite &= std::isfinite(E.val[i]);
            if (finite && norm(E) > 0) solutions_[kept++] = E;
        }
        modelsReturned += kept;
        if (kept == 0) return 0;
        model.create(3 * kept, 3, CV_64F);
        Mat out = model.getMat();
        for (int h = 0; h < kept; ++h)
            Mat(solutions_[h]).copyTo(out.rowRange(3 * h, 3 * h + 3));
        return kept;
    }

    /** Squared inlier distance (the problem's; always Sampson with LMEDS, see find_essential.cpp)
    of every point (CV_32F, N x 1): OpenCV's RANSAC compares it with threshold^2, its LMedS takes
    the median. Non-finite values become FLT_MAX (an outlier for both;
    the LMedS loop sorts the floats as integers, which needs non-negative, non-NaN values). */
    void computeError(InputArray m1, InputArray m2, InputArray model,
                      OutputArray err) const override
    {
        const Matx33d E = readModel(model);
        const Mat a = m1.getMat();
        const int n = a.checkVector(2);
        if (a.data == reinterpret_cast<const uchar*>(handed_) && n == problem_.size()) {
            scoring::squaredDistances(E, problem_, test_, errors_.data());
        } else {
            // Data other than the problem's arrays (not done by OpenCV 4.6's loops): read them.
            readSample(m1, x1_);
            readSample(m2, x2_);
            const Problem other = makeProblem(x1_, x2_);
            errors_.resize(static_cast<size_t>(other.size()));
            scoring::squaredDistances(E, other, test_, errors_.data());
        }
        const int count = static_cast<int>(errors_.size());
        err.create(count, 1, CV_32F);
        float* e = err.getMat().ptr<float>();
        for (int i = 0; i < count; ++i) {
            const double v = errors_[static_cast<size_t>(i)];
            e[i] = v >= 0.0 && v < double(FLT_MAX) ? static_cast<float>(v) : FLT_MAX;
        }
    }

    /** Rejects a sample with two coincident points in either view, as the module's own loop does:
    it constrains E less than its size says (and all-identical data would otherwise fit anything).
    */
    bool checkSubset(InputArray m1, InputArray m2, int count) const override
    {
        readSample(m1, x1_);
        readSample(m2, x2_);
        const int n = std::min(count, static_cast<int>(std::min(x1_.size(), x2_.size())));
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < i; ++j) {
                const Point2d d1 = x1_[i] - x1_[j], d2 = x2_[i] - x2_[j];
                if (d1.dot(d1) < kCoincident2 || d2.dot(d2) < kCoincident2) return false;
            }
        return true;
    }

    mutable int kernelCalls = 0;    //!< solver calls (one per loop iteration, see below)
    mutable int modelsReturned = 0; //!< matrices handed to the loop (each is scored once)

private:
    const Problem& problem_;
    const InlierTest test_;
    const Point2d* handed_;
    EssentialSolver& solver_;
    RNG& rng_;
    mutable std::vector<Matx33d> solutions_;
    mutable std::vector<Point2d> x1_, x2_;
    mutable std::vector<double> errors_;
};

} // namespace

SearchResult searchOpenCvLoop(const Problem& problem, EssentialSolver& solver, RNG& rng,
                              const SearchSettings& settings, int method)
{
    SearchResult result;
    result.threshold = settings.test.threshold;
    const int n = problem.size();
    const int modelPoints = solver.sampleSize();
    if (n < modelPoints || modelPoints <= 0) return result;

    // Once per estimate (EssentialSolver); LMedS has no inlier threshold of its own.
    if (method != LMEDS) solver.setThreshold(settings.test.threshold);
    std::vector<Point2d> p1, p2; // what OpenCV's loop reads the points from
    toPoint2d(problem, p1, p2);
    // makePtr would copy the const references
    Ptr<SolverCallback> callback(
        new SolverCallback(problem, settings.test, p1.data(), solver, rng));
    const bool lmeds = method == LMEDS;
    // maxIters is passed as given: OpenCV's loop applies its own confidence formula (see above).
    Ptr<PointSetRegistrator> loop =
        lmeds ? createLMeDSPointSetRegistrator(callback, modelPoints, settings.confidence,
                                               settings.maxIters)
              : createRANSACPointSetRegistrator(callback, modelPoints, settings.test.threshold,
                                                settings.confidence, settings.maxIters);
    CV_Assert(!loop.empty());

    Mat model, mask;
    const bool ok = loop->run(p1, p2, model, mask);

    // OpenCV's loops report neither counts nor scores. Both call runKernel exactly once per
    // iteration (a sample that fails checkSubset is redrawn within the iteration, and a failure to
    // draw any acceptable sample ends the loop), and both score every model runKernel returns once,
    // so the iterations, solver calls and scored models are known from the callback's counters.
    // What stays unknown is the loop's own stopping target (its required number of iterations).
    result.iterations = callback->kernelCalls;
    result.hypothesesGenerated = callback->kernelCalls;
    result.hypothesesConverged = callback->modelsReturned;
    result.hypothesesScored = callback->modelsReturned;
    if (!ok || model.rows < 3 || model.cols != 3 || mask.total() != static_cast<size_t>(n))
        return result;

    result.E = readModel(model);
    result.inliers = countNonZero(mask);

    if (lmeds && n > modelPoints) {
        // The threshold OpenCV's LMedS loop used for its mask, recomputed as it does: from the
        // median of the (float) squared Sampson errors of the returned model,
        // sigma = 2.5 * 1.4826 * (1 + 5 / (N - m)) * sqrt(median), floored at 0.001. (With
        // N = m the loop returns the kernel's model with every point marked; the problem's
        // threshold is kept.)
        Mat err;
        callback->computeError(p1, p2, model.rowRange(0, 3), err);
        float* e = err.ptr<float>();
        std::nth_element(e, e + n / 2, e + n);
        const double median = e[n / 2];
        const double sigma = 2.5 * 1.4826 * (1.0 + 5.0 / (n - modelPoints)) * std::sqrt(median);
        result.threshold = std::max(sigma, 0.001);
    }
    result.found = result.inliers >= modelPoints;
    return result;
}

} // namespace search

bool isOpenCvLoopAvailable()
{
    return true;
}

#else // !ESSENTIAL_HAVE_OPENCV_LOOP

namespace search {

SearchResult searchOpenCvLoop(const Problem& problem, EssentialSolver& solver, RNG& rng,
                              const SearchSettings& settings, int method)
{
    (void)problem;
    (void)solver;
    (void)rng;
    (void)settings;
    (void)method;
    CV_Error(Error::StsNotImplemented,
             "EssentialParams::engine = ENGINE_OPENCV is not available in this build: OpenCV's "
             "exported RANSAC loop (cv::createRANSACPointSetRegistrator) was not found usable by "
             "the configure-time probe (cmake/ProbeOpenCvLoop.cmake; see the CMake output), or "
             "the module was built inside an OpenCV tree, where the probe is skipped");
}

} // namespace search

bool isOpenCvLoopAvailable()
{
    return false;
}

#endif // ESSENTIAL_HAVE_OPENCV_LOOP

} // namespace essential
} // namespace cv
