// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The Python module cv_essential (pybind11): the drop-in findEssentialMatIter with cv2's
// conventions. Work in progress: the camera-matrix form only, so far (see python/README.md).

#include <opencv2/essential.hpp>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <string>
#include <utility>

namespace py = pybind11;

namespace {

/** cv2.error, the exception cv2 raises for cv::Exception; the module raises the same. */
py::object cv2Error()
{
    static py::object error = py::module_::import("cv2").attr("error");
    return error;
}

/** A numpy array as a cv::Mat sharing its memory (C-contiguous float32/float64/int32/uint8,
1 to 3 dimensions; the last dimension of a 3-D array becomes the channels, as cv2 reads it). */
cv::Mat asMat(const py::array& a, const char* name)
{
    const py::buffer_info info = a.request();
    int depth = -1;
    if (info.format == py::format_descriptor<float>::format())
        depth = CV_32F;
    else if (info.format == py::format_descriptor<double>::format())
        depth = CV_64F;
    else if (info.format == py::format_descriptor<int>::format())
        depth = CV_32S;
    else if (info.format == py::format_descriptor<unsigned char>::format())
        depth = CV_8U;
    if (depth < 0 || info.ndim < 1 || info.ndim > 3)
        throw py::type_error(std::string(name) +
                             ": expected a float32, float64, int32 or uint8 array of 1 to 3 "
                             "dimensions");
    const int rows = static_cast<int>(info.shape[0]);
    const int cols = info.ndim >= 2 ? static_cast<int>(info.shape[1]) : 1;
    const int channels = info.ndim == 3 ? static_cast<int>(info.shape[2]) : 1;
    return cv::Mat(rows, cols, CV_MAKETYPE(depth, channels), info.ptr);
}

py::array toArray(const cv::Mat& m)
{
    if (m.empty()) return py::array_t<double>(std::vector<py::ssize_t>{0, 0});
    cv::Mat c = m.isContinuous() ? m : m.clone();
    if (c.depth() == CV_8U) {
        py::array_t<unsigned char> out({c.rows, c.cols});
        std::memcpy(out.mutable_data(), c.data, c.total() * c.elemSize());
        return std::move(out);
    }
    cv::Mat d;
    c.convertTo(d, CV_64F);
    py::array_t<double> out({d.rows, d.cols * d.channels()});
    std::memcpy(out.mutable_data(), d.data, d.total() * d.elemSize());
    return std::move(out);
}

/** Runs `call` without the GIL and turns a cv::Exception into cv2.error. */
template <class Call> void withoutGil(Call call)
{
    try {
        py::gil_scoped_release release;
        call();
    } catch (const cv::Exception& e) {
        PyErr_SetString(cv2Error().ptr(), e.what());
        throw py::error_already_set();
    }
}

/** An optional array argument (None: empty). */
cv::Mat optionalMat(const py::object& o, const char* name)
{
    if (o.is_none()) return cv::Mat();
    return asMat(py::array::ensure(o), name);
}

/** A mask as cv2 returns it: the array, None when it was not written. */
py::object maskResult(const cv::Mat& mask)
{
    return mask.empty() ? py::object(py::none()) : py::object(toArray(mask));
}

/** (retval, mask) as cv2 returns them: E (or an empty array) and the mask. */
py::tuple essentialResult(const cv::Mat& E, const cv::Mat& mask)
{
    return py::make_tuple(toArray(E), maskResult(mask));
}

py::tuple findCamera(const py::array& points1, const py::array& points2,
                     const py::array& cameraMatrix, int method, double prob, double threshold,
                     int maxIters, const py::object& maskIn)
{
    const cv::Mat p1 = asMat(points1, "points1"), p2 = asMat(points2, "points2");
    const cv::Mat K = asMat(cameraMatrix, "cameraMatrix");
    cv::Mat E, mask = optionalMat(maskIn, "mask").clone();
    withoutGil([&] {
        E = cv::essential::findEssentialMatIter(p1, p2, K, method, prob, threshold, maxIters, mask);
    });
    return essentialResult(E, mask);
}

py::tuple findFocal(const py::array& points1, const py::array& points2, double focal,
                    std::pair<double, double> pp, int method, double prob, double threshold,
                    int maxIters, const py::object& maskIn)
{
    const cv::Mat p1 = asMat(points1, "points1"), p2 = asMat(points2, "points2");
    cv::Mat E, mask = optionalMat(maskIn, "mask").clone();
    withoutGil([&] {
        E = cv::essential::findEssentialMatIter(p1, p2, focal, cv::Point2d(pp.first, pp.second),
                                                method, prob, threshold, maxIters, mask);
    });
    return essentialResult(E, mask);
}

py::tuple findTwoCameras(const py::array& points1, const py::array& points2,
                         const py::array& cameraMatrix1, const py::object& distCoeffs1,
                         const py::array& cameraMatrix2, const py::object& distCoeffs2, int method,
                         double prob, double threshold, const py::object& maskIn)
{
    const cv::Mat p1 = asMat(points1, "points1"), p2 = asMat(points2, "points2");
    const cv::Mat K1 = asMat(cameraMatrix1, "cameraMatrix1");
    const cv::Mat K2 = asMat(cameraMatrix2, "cameraMatrix2");
    const cv::Mat d1 = optionalMat(distCoeffs1, "distCoeffs1");
    const cv::Mat d2 = optionalMat(distCoeffs2, "distCoeffs2");
    cv::Mat E, mask = optionalMat(maskIn, "mask").clone();
    withoutGil([&] {
        E = cv::essential::findEssentialMatIter(p1, p2, K1, d1, K2, d2, method, prob, threshold,
                                                mask);
    });
    return essentialResult(E, mask);
}

/** cv2.UsacParams (or any object with its attributes) as cv::UsacParams. */
cv::UsacParams usacParamsOf(const py::object& o)
{
    cv::UsacParams u;
    u.confidence = o.attr("confidence").cast<double>();
    u.isParallel = o.attr("isParallel").cast<bool>();
    u.loIterations = o.attr("loIterations").cast<int>();
    u.loMethod = static_cast<cv::LocalOptimMethod>(o.attr("loMethod").cast<int>());
    u.loSampleSize = o.attr("loSampleSize").cast<int>();
    u.maxIterations = o.attr("maxIterations").cast<int>();
    u.neighborsSearch =
        static_cast<cv::NeighborSearchMethod>(o.attr("neighborsSearch").cast<int>());
    u.randomGeneratorState = o.attr("randomGeneratorState").cast<int>();
    u.sampler = static_cast<cv::SamplingMethod>(o.attr("sampler").cast<int>());
    u.score = static_cast<cv::ScoreMethod>(o.attr("score").cast<int>());
    u.threshold = o.attr("threshold").cast<double>();
    return u;
}

py::tuple findUsac(const py::array& points1, const py::array& points2,
                   const py::array& cameraMatrix1, const py::array& cameraMatrix2,
                   const py::object& distCoeffs1, const py::object& distCoeffs2,
                   const py::object& params, const py::object& maskIn)
{
    const cv::Mat p1 = asMat(points1, "points1"), p2 = asMat(points2, "points2");
    const cv::Mat K1 = asMat(cameraMatrix1, "cameraMatrix1");
    const cv::Mat K2 = asMat(cameraMatrix2, "cameraMatrix2");
    const cv::Mat d1 = optionalMat(distCoeffs1, "dist_coeff1");
    const cv::Mat d2 = optionalMat(distCoeffs2, "dist_coeff2");
    const cv::UsacParams usac = usacParamsOf(params);
    cv::Mat E, mask = optionalMat(maskIn, "mask").clone();
    withoutGil(
        [&] { E = cv::essential::findEssentialMatIter(p1, p2, K1, K2, d1, d2, mask, usac); });
    return essentialResult(E, mask);
}

// recoverPose. cv2 returns R and t (and E, the triangulated points) as new arrays; the output
// arguments it accepts (R, t, E, triangulatedPoints) are taken and ignored, as their values are.

py::tuple poseFromCamera(const py::array& E, const py::array& points1, const py::array& points2,
                         const py::array& cameraMatrix, const py::object&, const py::object&,
                         const py::object& maskIn)
{
    const cv::Mat e = asMat(E, "E"), p1 = asMat(points1, "points1");
    const cv::Mat p2 = asMat(points2, "points2"), K = asMat(cameraMatrix, "cameraMatrix");
    cv::Mat R, t, mask = optionalMat(maskIn, "mask").clone();
    int inFront = 0;
    withoutGil([&] { inFront = cv::essential::recoverPose(e, p1, p2, K, R, t, mask); });
    return py::make_tuple(inFront, toArray(R), toArray(t), maskResult(mask));
}

py::tuple poseFromFocal(const py::array& E, const py::array& points1, const py::array& points2,
                        const py::object&, const py::object&, double focal,
                        std::pair<double, double> pp, const py::object& maskIn)
{
    const cv::Mat e = asMat(E, "E"), p1 = asMat(points1, "points1");
    const cv::Mat p2 = asMat(points2, "points2");
    cv::Mat R, t, mask = optionalMat(maskIn, "mask").clone();
    int inFront = 0;
    withoutGil([&] {
        inFront = cv::essential::recoverPose(e, p1, p2, R, t, focal,
                                             cv::Point2d(pp.first, pp.second), mask);
    });
    return py::make_tuple(inFront, toArray(R), toArray(t), maskResult(mask));
}

py::tuple poseWithDistance(const py::array& E, const py::array& points1, const py::array& points2,
                           const py::array& cameraMatrix, double distanceThresh, const py::object&,
                           const py::object&, const py::object& maskIn, const py::object&)
{
    const cv::Mat e = asMat(E, "E"), p1 = asMat(points1, "points1");
    const cv::Mat p2 = asMat(points2, "points2"), K = asMat(cameraMatrix, "cameraMatrix");
    cv::Mat R, t, points, mask = optionalMat(maskIn, "mask").clone();
    int inFront = 0;
    withoutGil([&] {
        inFront = cv::essential::recoverPose(e, p1, p2, K, R, t, distanceThresh, mask, points);
    });
    return py::make_tuple(inFront, toArray(R), toArray(t), maskResult(mask), toArray(points));
}

py::tuple poseFromTwoCameras(const py::array& points1, const py::array& points2,
                             const py::array& cameraMatrix1, const py::object& distCoeffs1,
                             const py::array& cameraMatrix2, const py::object& distCoeffs2,
                             const py::object&, const py::object&, const py::object&, int method,
                             double prob, double threshold, const py::object& maskIn)
{
    const cv::Mat p1 = asMat(points1, "points1"), p2 = asMat(points2, "points2");
    const cv::Mat K1 = asMat(cameraMatrix1, "cameraMatrix1");
    const cv::Mat K2 = asMat(cameraMatrix2, "cameraMatrix2");
    const cv::Mat d1 = optionalMat(distCoeffs1, "distCoeffs1");
    const cv::Mat d2 = optionalMat(distCoeffs2, "distCoeffs2");
    cv::Mat E, R, t, mask = optionalMat(maskIn, "mask").clone();
    int inFront = 0;
    withoutGil([&] {
        inFront = cv::essential::recoverPose(p1, p2, K1, d1, K2, d2, E, R, t, method, prob,
                                             threshold, mask);
    });
    return py::make_tuple(inFront, toArray(E), toArray(R), toArray(t), maskResult(mask));
}

// The module's own overload: EssentialParams in, (retval, mask, report) out.

py::tuple findWithParams(const py::array& points1, const py::array& points2,
                         const py::array& cameraMatrix,
                         const cv::essential::EssentialParams& params, const py::object& maskIn)
{
    const cv::Mat p1 = asMat(points1, "points1"), p2 = asMat(points2, "points2");
    const cv::Mat K = asMat(cameraMatrix, "cameraMatrix");
    cv::Mat E, mask = optionalMat(maskIn, "mask").clone();
    cv::essential::EssentialReport report;
    withoutGil([&] { E = cv::essential::findEssentialMatIter(p1, p2, K, params, mask, &report); });
    return py::make_tuple(toArray(E), maskResult(mask), report);
}

py::array matxArray(const cv::Matx33d& m)
{
    return toArray(cv::Mat(m));
}

/** A solver written in Python: `function(x1, x2)` takes two (m, 2) float64 arrays of normalised
points and returns a sequence of 3 x 3 essential matrices. solve() takes the GIL for the call only,
so other estimates keep running. Python exceptions become std::runtime_error, which the module's
solver guard turns into a cv::Exception naming the solver. */
class PythonSolver : public cv::essential::EssentialSolver
{
public:
    PythonSolver(const py::object* function, int sampleSize, int maxSolutions, double successRate)
        : function_(function), m_(sampleSize), k_(maxSolutions), rate_(successRate)
    {
    }
    int sampleSize() const override { return m_; }
    int maxSolutions() const override { return k_; }
    double successRate() const override { return rate_; }
    int solve(const cv::Point2d* x1, const cv::Point2d* x2, cv::RNG&,
              cv::Matx33d* solutions) override
    {
        py::gil_scoped_acquire gil;
        try {
            py::array_t<double> a({m_, 2}), b({m_, 2});
            auto pa = a.mutable_unchecked<2>();
            auto pb = b.mutable_unchecked<2>();
            for (int i = 0; i < m_; ++i) {
                pa(i, 0) = x1[i].x;
                pa(i, 1) = x1[i].y;
                pb(i, 0) = x2[i].x;
                pb(i, 1) = x2[i].y;
            }
            const py::object result = (*function_)(a, b);
            int n = 0;
            for (const py::handle item : result) {
                if (n >= k_) break;
                const auto e =
                    py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(item);
                if (!e || e.size() != 9)
                    throw std::runtime_error("a solution is not a 3 x 3 array");
                for (int k = 0; k < 9; ++k)
                    solutions[n].val[k] = e.data()[k];
                ++n;
            }
            return n;
        } catch (py::error_already_set& e) {
            throw std::runtime_error(e.what());
        }
    }

private:
    const py::object* function_;
    int m_, k_;
    double rate_;
};

void registerPythonSolver(const std::string& name, const py::function& function, int sampleSize,
                          int maxSolutions, double successRate)
{
    if (sampleSize < 5 || maxSolutions < 1 || !(successRate > 0 && successRate <= 1))
        throw py::value_error("registerSolver: sampleSize must be >= 5, maxSolutions >= 1 and "
                              "successRate in (0, 1]");
    // Kept alive for the life of the process: the registry may make solvers from it on any thread,
    // without the GIL, until the interpreter exits, so its reference is never released.
    const py::object* held = new py::object(function);
    try {
        cv::essential::registerSolver(name, [held, sampleSize, maxSolutions, successRate]() {
            return cv::Ptr<cv::essential::EssentialSolver>(
                new PythonSolver(held, sampleSize, maxSolutions, successRate));
        });
    } catch (const cv::Exception& e) {
        PyErr_SetString(cv2Error().ptr(), e.what());
        throw py::error_already_set();
    }
}

/** findEssentialMatBatch: `pairs` a sequence of (points1, points2, cameraMatrix); runs without
the GIL. `progress`: None, a callable(done, total) (called with the GIL), or True for a tqdm bar
when python3-tqdm is installed and stderr is a terminal (nothing otherwise). */
std::vector<cv::essential::EssentialPairResult> findBatch(const py::sequence& pairs,
                                                          const py::object& paramsIn, int threads,
                                                          const py::object& progress)
{
    std::vector<cv::essential::EssentialPair> input;
    input.reserve(pairs.size());
    for (const py::handle item : pairs) {
        const py::tuple t = py::reinterpret_borrow<py::object>(item).cast<py::tuple>();
        if (t.size() != 3)
            throw py::value_error("findEssentialMatBatch: each pair is (points1, points2, "
                                  "cameraMatrix)");
        cv::essential::EssentialPair p;
        // Copies: the workers read them without the GIL, whatever Python does with the arrays.
        p.points1 = asMat(py::array::ensure(t[0]), "points1").clone();
        p.points2 = asMat(py::array::ensure(t[1]), "points2").clone();
        p.cameraMatrix = asMat(py::array::ensure(t[2]), "cameraMatrix").clone();
        input.push_back(p);
    }
    const cv::essential::EssentialParams params =
        paramsIn.is_none() ? cv::essential::EssentialParams()
                           : paramsIn.cast<cv::essential::EssentialParams>();
    py::object callback = py::none();
    py::object bar = py::none();
    if (progress.is(py::bool_(true))) {
        const bool tty = py::module_::import("sys").attr("stderr").attr("isatty")().cast<bool>();
        if (tty) {
            try {
                bar = py::module_::import("tqdm").attr("tqdm")(py::arg("total") = input.size(),
                                                               py::arg("unit") = "pair");
            } catch (py::error_already_set&) {
                bar = py::none(); // no tqdm: no bar
            }
        }
    } else if (!progress.is_none() && !progress.is(py::bool_(false))) {
        callback = progress;
    }
    cv::essential::BatchProgress report;
    if (!callback.is_none() || !bar.is_none())
        report = [&](int done, int total) {
            py::gil_scoped_acquire gil;
            if (!bar.is_none()) bar.attr("update")(1);
            if (!callback.is_none()) callback(done, total);
        };
    std::vector<cv::essential::EssentialPairResult> results;
    try {
        py::gil_scoped_release release;
        results = cv::essential::findEssentialMatBatch(input, params, threads, report);
    } catch (const cv::Exception& e) {
        if (!bar.is_none()) bar.attr("close")();
        PyErr_SetString(cv2Error().ptr(), e.what());
        throw py::error_already_set();
    }
    if (!bar.is_none()) bar.attr("close")();
    return results;
}

} // namespace

PYBIND11_MODULE(cv_essential, m)
{
    m.doc() = "opencv_essential: essential-matrix estimation with iterative minimal-set solvers, "
              "a drop-in for cv2.findEssentialMat (work in progress)";
    const int ransac = static_cast<int>(cv::RANSAC);
    // The forms in cv2's order; pybind11 tries them in turn, as cv2's dispatcher does.
    m.def("findEssentialMatIter", &findCamera, py::arg("points1"), py::arg("points2"),
          py::arg("cameraMatrix"), py::arg("method") = ransac, py::arg("prob") = 0.999,
          py::arg("threshold") = 1.0, py::arg("maxIters") = 1000, py::arg("mask") = py::none(),
          "findEssentialMatIter(points1, points2, cameraMatrix[, method[, prob[, threshold[, "
          "maxIters[, mask]]]]]) -> retval, mask");
    m.def("findEssentialMatIter", &findFocal, py::arg("points1"), py::arg("points2"),
          py::arg("focal") = 1.0, py::arg("pp") = std::make_pair(0.0, 0.0),
          py::arg("method") = ransac, py::arg("prob") = 0.999, py::arg("threshold") = 1.0,
          py::arg("maxIters") = 1000, py::arg("mask") = py::none(),
          "findEssentialMatIter(points1, points2[, focal[, pp[, method[, prob[, threshold[, "
          "maxIters[, mask]]]]]]]) -> retval, mask");
    m.def("findEssentialMatIter", &findTwoCameras, py::arg("points1"), py::arg("points2"),
          py::arg("cameraMatrix1"), py::arg("distCoeffs1"), py::arg("cameraMatrix2"),
          py::arg("distCoeffs2"), py::arg("method") = ransac, py::arg("prob") = 0.999,
          py::arg("threshold") = 1.0, py::arg("mask") = py::none(),
          "findEssentialMatIter(points1, points2, cameraMatrix1, distCoeffs1, cameraMatrix2, "
          "distCoeffs2[, method[, prob[, threshold[, mask]]]]) -> retval, mask");
    m.def("findEssentialMatIter", &findUsac, py::arg("points1"), py::arg("points2"),
          py::arg("cameraMatrix1"), py::arg("cameraMatrix2"), py::arg("dist_coeff1"),
          py::arg("dist_coeff2"), py::arg("params"), py::arg("mask") = py::none(),
          "findEssentialMatIter(points1, points2, cameraMatrix1, cameraMatrix2, dist_coeff1, "
          "dist_coeff2, params[, mask]) -> retval, mask");
    // recoverPose in cv2 4.6's dispatch order. As in cv2, a positional fifth argument after the
    // camera matrix is the (ignored) output R, so distanceThresh must be given by keyword.
    m.def("recoverPose", &poseFromTwoCameras, py::arg("points1"), py::arg("points2"),
          py::arg("cameraMatrix1"), py::arg("distCoeffs1"), py::arg("cameraMatrix2"),
          py::arg("distCoeffs2"), py::arg("E") = py::none(), py::arg("R") = py::none(),
          py::arg("t") = py::none(), py::arg("method") = ransac, py::arg("prob") = 0.999,
          py::arg("threshold") = 1.0, py::arg("mask") = py::none(),
          "recoverPose(points1, points2, cameraMatrix1, distCoeffs1, cameraMatrix2, distCoeffs2[, "
          "E[, R[, t[, method[, prob[, threshold[, mask]]]]]]]) -> retval, E, R, t, mask");
    m.def("recoverPose", &poseFromCamera, py::arg("E"), py::arg("points1"), py::arg("points2"),
          py::arg("cameraMatrix"), py::arg("R") = py::none(), py::arg("t") = py::none(),
          py::arg("mask") = py::none(),
          "recoverPose(E, points1, points2, cameraMatrix[, R[, t[, mask]]]) -> retval, R, t, mask");
    m.def("recoverPose", &poseWithDistance, py::arg("E"), py::arg("points1"), py::arg("points2"),
          py::arg("cameraMatrix"), py::arg("distanceThresh"), py::arg("R") = py::none(),
          py::arg("t") = py::none(), py::arg("mask") = py::none(),
          py::arg("triangulatedPoints") = py::none(),
          "recoverPose(E, points1, points2, cameraMatrix, distanceThresh[, R[, t[, mask[, "
          "triangulatedPoints]]]]) -> retval, R, t, mask, triangulatedPoints");
    m.def(
        "recoverPose", &poseFromFocal, py::arg("E"), py::arg("points1"), py::arg("points2"),
        py::arg("R") = py::none(), py::arg("t") = py::none(), py::arg("focal") = 1.0,
        py::arg("pp") = std::make_pair(0.0, 0.0), py::arg("mask") = py::none(),
        "recoverPose(E, points1, points2[, R[, t[, focal[, pp[, mask]]]]]) -> retval, R, t, mask");

    // EssentialParams: keyword construction, every field read/write, a readable repr.
    py::class_<cv::essential::EssentialParams> params(m, "EssentialParams",
                                                      "Settings of one estimate (the module's "
                                                      "own overload); see essential/params.hpp.");
    params.def(py::init([](const py::kwargs& kwargs) {
        py::object self = py::cast(cv::essential::EssentialParams());
        for (const auto& item : kwargs) {
            const std::string key = item.first.cast<std::string>();
            if (!py::hasattr(self, key.c_str()) || key.rfind("_", 0) == 0)
                throw py::type_error("EssentialParams has no field '" + key + "'");
            self.attr(key.c_str()) = item.second;
        }
        return self.cast<cv::essential::EssentialParams>();
    }));
    using P = cv::essential::EssentialParams;
    params.def_readwrite("solver", &P::solver)
        .def_readwrite("method", &P::method)
        .def_readwrite("engine", &P::engine)
        .def_readwrite("timeBudgetMs", &P::timeBudgetMs)
        .def_readwrite("preemptiveHypotheses", &P::preemptiveHypotheses)
        .def_readwrite("preemptiveBlockSize", &P::preemptiveBlockSize)
        .def_readwrite("confidence", &P::confidence)
        .def_readwrite("threshold", &P::threshold)
        .def_property(
            "distance", [](const P& p) { return static_cast<int>(p.distance); },
            [](P& p, int d) { p.distance = static_cast<cv::essential::EssentialDistance>(d); })
        .def_readwrite("maxIters", &P::maxIters)
        .def_readwrite("sampleBudget", &P::sampleBudget)
        .def_readwrite("budgetLocalSamples", &P::budgetLocalSamples)
        .def_readwrite("planeParallax", &P::planeParallax)
        .def_readwrite("loIterations", &P::loIterations)
        .def_readwrite("loSampleSize", &P::loSampleSize)
        .def_readwrite("sampler", &P::sampler)
        .def_readwrite("sprt", &P::sprt)
        .def_readwrite("seed", &P::seed)
        .def_readwrite("refine", &P::refine)
        .def_readwrite("recoverPose", &P::recoverPose)
        .def("__repr__", [](const P& p) {
            return cv::format("EssentialParams(solver='%s', method=%d, engine=%d, "
                              "timeBudgetMs=%g, confidence=%g, threshold=%g, maxIters=%d, "
                              "sampleBudget=%d, budgetLocalSamples=%s, planeParallax=%s, "
                              "loIterations=%d, sampler=%d, sprt=%s, refine=%s)",
                              p.solver.c_str(), p.method, p.engine, p.timeBudgetMs, p.confidence,
                              p.threshold, p.maxIters, p.sampleBudget,
                              p.budgetLocalSamples ? "True" : "False",
                              p.planeParallax ? "True" : "False", p.loIterations, p.sampler,
                              p.sprt ? "True" : "False", p.refine ? "True" : "False");
        });

    using Rep = cv::essential::EssentialReport;
    py::class_<Rep>(m, "EssentialReport", "What one estimate did: the pose, counts and times.")
        .def_readonly("success", &Rep::success)
        .def_property_readonly("E", [](const Rep& r) { return matxArray(r.E); })
        .def_property_readonly("R", [](const Rep& r) { return matxArray(r.R); })
        .def_property_readonly("t", [](const Rep& r) { return toArray(cv::Mat(r.t)); })
        .def_readonly("poseRecovered", &Rep::poseRecovered)
        .def_readonly("pointsInFront", &Rep::pointsInFront)
        .def_readonly("degenerate", &Rep::degenerate)
        .def_readonly("numPoints", &Rep::numPoints)
        .def_readonly("inliers", &Rep::inliers)
        .def_readonly("iterations", &Rep::iterations)
        .def_readonly("hypothesesGenerated", &Rep::hypothesesGenerated)
        .def_readonly("planeParallaxKept", &Rep::planeParallaxKept)
        .def_readonly("timeTotalMs", &Rep::timeTotalMs)
        .def("__repr__", [](const Rep& r) {
            return cv::format("EssentialReport(success=%s, inliers=%d of %d, iterations=%d, "
                              "timeTotalMs=%.3f)",
                              r.success ? "True" : "False", r.inliers, r.numPoints, r.iterations,
                              r.timeTotalMs);
        });

    m.def("findEssentialMatIter", &findWithParams, py::arg("points1"), py::arg("points2"),
          py::arg("cameraMatrix"), py::arg("params"), py::arg("mask") = py::none(),
          "findEssentialMatIter(points1, points2, cameraMatrix, params[, mask]) -> retval, mask, "
          "report\n\nThe module's own form: EssentialParams in, an EssentialReport out.");
    m.def("listSolvers", &cv::essential::listSolvers, "listSolvers() -> list of solver names");
    m.def("registerSolver", &registerPythonSolver, py::arg("name"), py::arg("solver"),
          py::arg("sampleSize") = 5, py::arg("maxSolutions") = 10, py::arg("successRate") = 1.0,
          "registerSolver(name, solver[, sampleSize[, maxSolutions[, successRate]]]) -> None\n\n"
          "Registers a Python solver: solver(x1, x2) takes two (sampleSize, 2) arrays of "
          "normalised points and returns a list of 3 x 3 essential matrices. Slow (a Python call "
          "per sample) but usable in every form with EssentialParams(solver=name).");
    using BR = cv::essential::EssentialPairResult;
    py::class_<BR>(m, "EssentialPairResult", "The estimate of one pair of a batch.")
        .def_property_readonly("E", [](const BR& r) { return toArray(r.E); })
        .def_property_readonly("mask", [](const BR& r) { return toArray(r.mask); })
        .def_readonly("report", &BR::report)
        .def_readonly("error", &BR::error)
        .def("__repr__", [](const BR& r) {
            return r.error.empty() ? cv::format("EssentialPairResult(inliers=%d of %d)",
                                                r.report.inliers, r.report.numPoints)
                                   : "EssentialPairResult(error=" + r.error + ")";
        });
    m.def("findEssentialMatBatch", &findBatch, py::arg("pairs"), py::arg("params") = py::none(),
          py::arg("threads") = 0, py::arg("progress") = py::none(),
          "findEssentialMatBatch(pairs[, params[, threads[, progress]]]) -> list of "
          "EssentialPairResult\n\npairs: (points1, points2, cameraMatrix) tuples, estimated in "
          "parallel without the GIL; pair i uses the seed batchPairSeed(params.seed, i), so the "
          "results do not depend on the thread count. progress: a callable(done, total), or True "
          "for a tqdm bar on a terminal.");
    m.def("batchPairSeed", &cv::essential::batchPairSeed, py::arg("seed"), py::arg("index"));
}
