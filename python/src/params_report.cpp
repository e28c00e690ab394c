// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// EssentialParams (keyword construction, every field, repr, pickling) and EssentialReport (every
// field, read-only), and the constants their fields take beyond cv2's own.

#include "bindings.hpp"
#include "cv2_arrays.hpp"

#include <opencv2/essential.hpp>

#include <pybind11/stl.h>

#include <string>
#include <type_traits>
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

/** Calls f(name, member pointer) for each number of EssentialReport besides success, E, R and t,
in the header's order: the one list the Python attributes and the pickled state are made from. */
template <class F> void forEachReportNumber(F&& f)
{
    f("poseRecovered", &Report::poseRecovered);
    f("pointsInFront", &Report::pointsInFront);
    f("rotationOnlyFraction", &Report::rotationOnlyFraction);
    f("homographyFraction", &Report::homographyFraction);
    f("degenerate", &Report::degenerate);
    f("numPoints", &Report::numPoints);
    f("inliers", &Report::inliers);
    f("iterations", &Report::iterations);
    f("hypothesesGenerated", &Report::hypothesesGenerated);
    f("hypothesesConverged", &Report::hypothesesConverged);
    f("hypothesesScored", &Report::hypothesesScored);
    f("refineIterations", &Report::refineIterations);
    f("pointsScored", &Report::pointsScored);
    f("localOptimisations", &Report::localOptimisations);
    f("localOptimisationsKept", &Report::localOptimisationsKept);
    f("sprtRejections", &Report::sprtRejections);
    f("planeParallaxKept", &Report::planeParallaxKept);
    f("timeSetupMs", &Report::timeSetupMs);
    f("timeSearchMs", &Report::timeSearchMs);
    f("timeRefineMs", &Report::timeRefineMs);
    f("timePoseMs", &Report::timePoseMs);
    f("timeTotalMs", &Report::timeTotalMs);
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
    forEachReportNumber([&](const char*, auto member) { s.append(r.*member); });
    return py::tuple(s);
}

Report reportFromState(const py::tuple& s)
{
    size_t numbers = 0;
    forEachReportNumber([&](const char*, auto) { ++numbers; });
    if (s.size() != 1 + 9 + 9 + 3 + numbers)
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
    forEachReportNumber([&](const char*, auto member) {
        r.*member = s[i++].cast<std::decay_t<decltype(r.*member)>>();
    });
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

    py::class_<Report> report(
        m, "EssentialReport",
        "What one estimate did: the pose, the counts and the time of each stage "
        "(opencv2/essential/params.hpp documents every field).");
    report.def_readonly("success", &Report::success)
        .def_property_readonly("E", [](const Report& r) { return toNumpy(cv::Mat(r.E)); })
        .def_property_readonly("R", [](const Report& r) { return toNumpy(cv::Mat(r.R)); })
        .def_property_readonly("t", [](const Report& r) { return toNumpy(cv::Mat(r.t)); });
    forEachReportNumber([&](const char* name, auto member) { report.def_readonly(name, member); });
    report
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
