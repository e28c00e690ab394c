// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// EssentialParams (keyword construction, every field, repr, pickling) and EssentialReport (every
// field, read-only), and the constants their fields take beyond cv2's own.

#include "bindings.hpp"
#include "cv2_arrays.hpp"

#include <opencv2/essential.hpp>

#include <pybind11/stl.h>

#include <string>
#include <vector>

namespace cv_essential_py {

namespace {

using Params = cv::essential::EssentialParams;
using Report = cv::essential::EssentialReport;

/** The fields of EssentialParams in the header's order (repr and pickling walk them;
python/tests/test_params_report.py checks the list against the header). */
const std::vector<std::string>& paramFields()
{
    static const std::vector<std::string> fields = {"solver",
                                                    "method",
                                                    "engine",
                                                    "timeBudgetMs",
                                                    "preemptiveHypotheses",
                                                    "preemptiveBlockSize",
                                                    "confidence",
                                                    "threshold",
                                                    "distance",
                                                    "maxIters",
                                                    "sampleBudget",
                                                    "budgetLocalSamples",
                                                    "planeParallax",
                                                    "loIterations",
                                                    "loSampleSize",
                                                    "sampler",
                                                    "sprt",
                                                    "seed",
                                                    "refine",
                                                    "recoverPose"};
    return fields;
}

/** "name=repr(value), ..." over `fields` of `self`. */
std::string fieldsRepr(const py::object& self, const std::vector<std::string>& fields)
{
    std::string out;
    for (const std::string& f : fields) {
        if (!out.empty()) out += ", ";
        out += f + "=" + py::repr(self.attr(f.c_str())).cast<std::string>();
    }
    return out;
}

Params paramsFromKeywords(const py::dict& kwargs)
{
    py::object self = py::cast(Params());
    for (const auto& item : kwargs) {
        const std::string key = py::str(item.first);
        bool known = false;
        for (const std::string& f : paramFields())
            known = known || f == key;
        if (!known) throw py::type_error("EssentialParams has no field '" + key + "'");
        self.attr(key.c_str()) = item.second;
    }
    return self.cast<Params>();
}

} // namespace

/** The report's numbers in a fixed order: E, R, t (row by row), then the other fields in the
header's order. EssentialReport's pickled state. */
py::tuple reportState(const Report& r)
{
    py::list s;
    s.append(r.success);
    for (int k = 0; k < 9; ++k)
        s.append(r.E.val[k]);
    for (int k = 0; k < 9; ++k)
        s.append(r.R.val[k]);
    for (int k = 0; k < 3; ++k)
        s.append(r.t[k]);
    s.append(r.poseRecovered);
    s.append(r.pointsInFront);
    s.append(r.rotationOnlyFraction);
    s.append(r.homographyFraction);
    s.append(r.degenerate);
    s.append(r.numPoints);
    s.append(r.inliers);
    s.append(r.iterations);
    s.append(r.hypothesesGenerated);
    s.append(r.hypothesesConverged);
    s.append(r.hypothesesScored);
    s.append(r.refineIterations);
    s.append(r.pointsScored);
    s.append(r.localOptimisations);
    s.append(r.localOptimisationsKept);
    s.append(r.sprtRejections);
    s.append(r.planeParallaxKept);
    s.append(r.timeSetupMs);
    s.append(r.timeSearchMs);
    s.append(r.timeRefineMs);
    s.append(r.timePoseMs);
    s.append(r.timeTotalMs);
    return py::tuple(s);
}

Report reportFromState(const py::tuple& s)
{
    if (s.size() != 44)
        throw py::value_error("EssentialReport: not the pickle of one from this module version");
    Report r;
    size_t i = 0;
    r.success = s[i++].cast<bool>();
    for (int k = 0; k < 9; ++k)
        r.E.val[k] = s[i++].cast<double>();
    for (int k = 0; k < 9; ++k)
        r.R.val[k] = s[i++].cast<double>();
    for (int k = 0; k < 3; ++k)
        r.t[k] = s[i++].cast<double>();
    r.poseRecovered = s[i++].cast<decltype(r.poseRecovered)>();
    r.pointsInFront = s[i++].cast<decltype(r.pointsInFront)>();
    r.rotationOnlyFraction = s[i++].cast<decltype(r.rotationOnlyFraction)>();
    r.homographyFraction = s[i++].cast<decltype(r.homographyFraction)>();
    r.degenerate = s[i++].cast<decltype(r.degenerate)>();
    r.numPoints = s[i++].cast<decltype(r.numPoints)>();
    r.inliers = s[i++].cast<decltype(r.inliers)>();
    r.iterations = s[i++].cast<decltype(r.iterations)>();
    r.hypothesesGenerated = s[i++].cast<decltype(r.hypothesesGenerated)>();
    r.hypothesesConverged = s[i++].cast<decltype(r.hypothesesConverged)>();
    r.hypothesesScored = s[i++].cast<decltype(r.hypothesesScored)>();
    r.refineIterations = s[i++].cast<decltype(r.refineIterations)>();
    r.pointsScored = s[i++].cast<decltype(r.pointsScored)>();
    r.localOptimisations = s[i++].cast<decltype(r.localOptimisations)>();
    r.localOptimisationsKept = s[i++].cast<decltype(r.localOptimisationsKept)>();
    r.sprtRejections = s[i++].cast<decltype(r.sprtRejections)>();
    r.planeParallaxKept = s[i++].cast<decltype(r.planeParallaxKept)>();
    r.timeSetupMs = s[i++].cast<decltype(r.timeSetupMs)>();
    r.timeSearchMs = s[i++].cast<decltype(r.timeSearchMs)>();
    r.timeRefineMs = s[i++].cast<decltype(r.timeRefineMs)>();
    r.timePoseMs = s[i++].cast<decltype(r.timePoseMs)>();
    r.timeTotalMs = s[i++].cast<decltype(r.timeTotalMs)>();
    return r;
}

void defineParamsAndReport(py::module_& m)
{
    m.attr("ENGINE_ADAPTIVE") = static_cast<int>(cv::essential::ENGINE_ADAPTIVE);
    m.attr("ENGINE_OPENCV") = static_cast<int>(cv::essential::ENGINE_OPENCV);
    m.attr("ENGINE_PREEMPTIVE") = static_cast<int>(cv::essential::ENGINE_PREEMPTIVE);
    m.attr("DISTANCE_SAMPSON") = static_cast<int>(cv::essential::DISTANCE_SAMPSON);
    m.attr("DISTANCE_SYMMETRIC_EPIPOLAR") =
        static_cast<int>(cv::essential::DISTANCE_SYMMETRIC_EPIPOLAR);
    m.attr("BUDGET_CONFIDENCE") = static_cast<int>(cv::essential::BUDGET_CONFIDENCE);
    m.attr("BUDGET_OPENCV_TIME") = static_cast<int>(cv::essential::BUDGET_OPENCV_TIME);

    py::class_<Params> params(m, "EssentialParams",
                              "EssentialParams(**fields)\n"
                              ".   Settings of one estimate (the module's own form of "
                              "findEssentialMatIter), every field by keyword, e.g.\n"
                              ".   EssentialParams(solver='gn+nister', timeBudgetMs=10). The "
                              "fields and their defaults are\n"
                              ".   documented in opencv2/essential/params.hpp. method and "
                              "sampler take cv2's constants\n"
                              ".   (cv2.RANSAC, cv2.LMEDS, cv2.SAMPLING_UNIFORM, ...); engine, "
                              "distance and sampleBudget this\n"
                              ".   module's (ENGINE_*, DISTANCE_*, BUDGET_*).");
    params.def(py::init([](const py::kwargs& kwargs) { return paramsFromKeywords(kwargs); }));
    params.def_readwrite("solver", &Params::solver)
        .def_readwrite("method", &Params::method)
        .def_readwrite("engine", &Params::engine)
        .def_readwrite("timeBudgetMs", &Params::timeBudgetMs)
        .def_readwrite("preemptiveHypotheses", &Params::preemptiveHypotheses)
        .def_readwrite("preemptiveBlockSize", &Params::preemptiveBlockSize)
        .def_readwrite("confidence", &Params::confidence)
        .def_readwrite("threshold", &Params::threshold)
        .def_property(
            "distance", [](const Params& p) { return static_cast<int>(p.distance); },
            [](Params& p, int d) {
                if (d != cv::essential::DISTANCE_SAMPSON &&
                    d != cv::essential::DISTANCE_SYMMETRIC_EPIPOLAR)
                    throw py::value_error("distance: DISTANCE_SAMPSON or "
                                          "DISTANCE_SYMMETRIC_EPIPOLAR");
                p.distance = static_cast<cv::essential::EssentialDistance>(d);
            })
        .def_readwrite("maxIters", &Params::maxIters)
        .def_readwrite("sampleBudget", &Params::sampleBudget)
        .def_readwrite("budgetLocalSamples", &Params::budgetLocalSamples)
        .def_readwrite("planeParallax", &Params::planeParallax)
        .def_readwrite("loIterations", &Params::loIterations)
        .def_readwrite("loSampleSize", &Params::loSampleSize)
        .def_readwrite("sampler", &Params::sampler)
        .def_readwrite("sprt", &Params::sprt)
        .def_readwrite("seed", &Params::seed)
        .def_readwrite("refine", &Params::refine)
        .def_readwrite("recoverPose", &Params::recoverPose)
        .def("__repr__",
             [](const py::object& self) {
                 return "EssentialParams(" + fieldsRepr(self, paramFields()) + ")";
             })
        // Picklable, so that multiprocessing and Dask can send it to other processes.
        .def(py::pickle(
            [](const py::object& self) {
                py::dict state;
                for (const std::string& f : paramFields())
                    state[f.c_str()] = self.attr(f.c_str());
                return state;
            },
            [](const py::dict& state) { return paramsFromKeywords(state); }));

    py::class_<Report>(m, "EssentialReport",
                       "What one estimate did: the pose, the counts and the time of each stage "
                       "(opencv2/essential/params.hpp documents every field).")
        .def_readonly("success", &Report::success)
        .def_property_readonly("E", [](const Report& r) { return toNumpy(cv::Mat(r.E)); })
        .def_property_readonly("R", [](const Report& r) { return toNumpy(cv::Mat(r.R)); })
        .def_property_readonly("t", [](const Report& r) { return toNumpy(cv::Mat(r.t)); })
        .def_readonly("poseRecovered", &Report::poseRecovered)
        .def_readonly("pointsInFront", &Report::pointsInFront)
        .def_readonly("rotationOnlyFraction", &Report::rotationOnlyFraction)
        .def_readonly("homographyFraction", &Report::homographyFraction)
        .def_readonly("degenerate", &Report::degenerate)
        .def_readonly("numPoints", &Report::numPoints)
        .def_readonly("inliers", &Report::inliers)
        .def_readonly("iterations", &Report::iterations)
        .def_readonly("hypothesesGenerated", &Report::hypothesesGenerated)
        .def_readonly("hypothesesConverged", &Report::hypothesesConverged)
        .def_readonly("hypothesesScored", &Report::hypothesesScored)
        .def_readonly("refineIterations", &Report::refineIterations)
        .def_readonly("pointsScored", &Report::pointsScored)
        .def_readonly("localOptimisations", &Report::localOptimisations)
        .def_readonly("localOptimisationsKept", &Report::localOptimisationsKept)
        .def_readonly("sprtRejections", &Report::sprtRejections)
        .def_readonly("planeParallaxKept", &Report::planeParallaxKept)
        .def_readonly("timeSetupMs", &Report::timeSetupMs)
        .def_readonly("timeSearchMs", &Report::timeSearchMs)
        .def_readonly("timeRefineMs", &Report::timeRefineMs)
        .def_readonly("timePoseMs", &Report::timePoseMs)
        .def_readonly("timeTotalMs", &Report::timeTotalMs)
        .def("__repr__",
             [](const Report& r) {
                 return cv::format("EssentialReport(success=%s, inliers=%d of %d, iterations=%d, "
                                   "poseRecovered=%s, degenerate=%s, timeTotalMs=%.3f)",
                                   r.success ? "True" : "False", r.inliers, r.numPoints,
                                   r.iterations, r.poseRecovered ? "True" : "False",
                                   r.degenerate ? "True" : "False", r.timeTotalMs);
             })
        // Picklable, so that results can come back
        // from other processes.
        .def(py::pickle([](const Report& r) { return reportState(r); },
                        [](const py::tuple& s) { return reportFromState(s); }));
}

} // namespace cv_essential_py
