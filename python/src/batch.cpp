// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// findEssentialMatBatch from Python: many pairs on a pool of threads without the GIL, with a
// progress callable or bar, and batchPairSeed.

#include "bindings.hpp"
#include "cv2_arrays.hpp"
#include "cv2_errors.hpp"

#include <opencv2/essential.hpp>

#include <pybind11/stl.h>

#include <string>
#include <vector>

namespace cv_essential_py {

namespace {

using PairResult = cv::essential::EssentialPairResult;

/** One array of a pair, copied: the workers read it without the GIL, whatever Python does with
the array meanwhile. */
cv::Mat pairArray(py::handle o, size_t index, const char* name)
{
    InputMat m;
    std::string why;
    if (!toInputMat(o, m, &why))
        raiseCv2Error("findEssentialMatBatch: pair " + std::to_string(index) + ", " + name + ": " +
                      why);
    return m.mat.clone();
}

/** `pairs` a sequence of (points1, points2, cameraMatrix); runs without the GIL. `progress`:
None, a callable(done, total) (called with the GIL), or True for a tqdm bar when python3-tqdm is
installed and stderr is a terminal (nothing otherwise). */
std::vector<PairResult> findBatch(const py::sequence& pairs, const py::object& paramsIn,
                                  int threads, const py::object& progress, int firstIndex)
{
    std::vector<cv::essential::EssentialPair> input;
    input.reserve(pairs.size());
    for (const py::handle& item : pairs) {
        const size_t index = input.size();
        if (!py::isinstance<py::sequence>(item) || py::len(item) != 3)
            raiseCv2Error("findEssentialMatBatch: pair " + std::to_string(index) +
                          " is not a (points1, points2, cameraMatrix) sequence");
        const py::sequence t = py::reinterpret_borrow<py::sequence>(item);
        cv::essential::EssentialPair p;
        p.points1 = pairArray(t[0], index, "points1");
        p.points2 = pairArray(t[1], index, "points2");
        p.cameraMatrix = pairArray(t[2], index, "cameraMatrix");
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
    std::vector<PairResult> results;
    try {
        withoutGil([&] {
            results =
                cv::essential::findEssentialMatBatch(input, params, threads, report, firstIndex);
        });
    } catch (...) {
        if (!bar.is_none()) bar.attr("close")();
        throw;
    }
    if (!bar.is_none()) bar.attr("close")();
    return results;
}

} // namespace

void defineBatch(py::module_& m, py::module_& forms)
{
    py::class_<PairResult>(m, "EssentialPairResult",
                           "The estimate of one pair of a batch: E (None when none was found), "
                           "mask, report, and error (empty, or the message of the pair's bad "
                           "input).")
        .def_property_readonly("E", [](const PairResult& r) { return toNumpy(r.E); })
        .def_property_readonly("mask", [](const PairResult& r) { return toNumpy(r.mask); })
        .def_readonly("report", &PairResult::report)
        .def_readonly("error", &PairResult::error)
        .def("__repr__",
             [](const PairResult& r) {
                 return r.error.empty() ? cv::format("EssentialPairResult(inliers=%d of %d)",
                                                     r.report.inliers, r.report.numPoints)
                                        : "EssentialPairResult(error=" + r.error + ")";
             })
        .def(py::pickle(
            [](const PairResult& r) {
                return py::make_tuple(toNumpy(r.E), toNumpy(r.mask), reportState(r.report),
                                      r.error);
            },
            [](const py::tuple& state) {
                PairResult r;
                InputMat E, mask;
                if (state.size() != 4 || !toInputMat(state[0], E, nullptr) ||
                    !toInputMat(state[1], mask, nullptr))
                    throw py::value_error("EssentialPairResult: not a pickle of one");
                r.E = E.mat.clone();
                r.mask = mask.mat.clone();
                r.report = reportFromState(state[2].cast<py::tuple>());
                r.error = state[3].cast<std::string>();
                return r;
            }));
    forms.def("findEssentialMatBatch", &findBatch, py::arg("pairs"), py::arg("params") = py::none(),
              py::arg("threads") = 0, py::arg("progress") = py::none(), py::arg("firstIndex") = 0);
    defineWithCv2Errors(
        m, forms, "findEssentialMatBatch", {},
        "findEssentialMatBatch(pairs[, params[, threads[, progress[, firstIndex]]]]) -> retval\n"
        ".   Estimates many pairs in parallel: pairs is a sequence of (points1, points2,\n"
        ".   cameraMatrix); retval a list of EssentialPairResult in the same order. Runs on\n"
        ".   `threads` threads (0: cv2.getNumThreads()) without the GIL. Pair i uses the seed\n"
        ".   batchPairSeed(params.seed, firstIndex + i), so the results do not depend on the\n"
        ".   thread count, and parts of a long list estimated with their first index (on other\n"
        ".   processes or machines) give the results of one batch. A bad pair gets an error\n"
        ".   message and does not stop the others. progress: a callable(done, total), or True\n"
        ".   for a tqdm bar when stderr is a terminal.");
    m.def("batchPairSeed", &cv::essential::batchPairSeed, py::arg("seed"), py::arg("index"),
          "batchPairSeed(seed, index) -> retval\n"
          ".   The seed findEssentialMatBatch gives pair `index` of a batch with seed `seed`.");
}

} // namespace cv_essential_py
