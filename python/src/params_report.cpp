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

/** Calls f(name, member pointer) for each field of EssentialParams in the header's order: the list
the Python attributes, keywords, repr and pickled state are made from. Its body is written by
scripts/params_table.py from the header's struct. */
template <class F> void forEachParamField(F&& f)
{
    f("confidence", &Params::confidence);
    f("threshold", &Params::threshold);
    f("maxIterations", &Params::maxIterations);
    f("distance", &Params::distance);
    f("seed", &Params::seed);
    f("solver", &Params::solver);
    f("engine", &Params::engine);
    f("score", &Params::score);
    f("sampler", &Params::sampler);
    f("sprt", &Params::sprt);
    f("sampleBudget", &Params::sampleBudget);
    f("timeBudgetMs", &Params::timeBudgetMs);
    f("preemptiveHypotheses", &Params::preemptiveHypotheses);
    f("preemptiveBlockSize", &Params::preemptiveBlockSize);
    f("loIterations", &Params::loIterations);
    f("loSampleSize", &Params::loSampleSize);
    f("budgetLocalSamples", &Params::budgetLocalSamples);
    f("planeParallax", &Params::planeParallax);
    f("inFrontCheck", &Params::inFrontCheck);
    f("refine", &Params::refine);
    f("recoverPose", &Params::recoverPose);
}

const std::vector<std::string>& paramFields()
{
    static const std::vector<std::string> fields = [] {
        std::vector<std::string> names;
        forEachParamField([&](const char* name, auto) { names.push_back(name); });
        return names;
    }();
    return fields;
}

/** The values of each enum that EssentialParams holds, with the names Python spells them by: as in
cv2, an enum field is an int in Python; assigning a value outside its enumeration raises ValueError
naming the field and the constants it takes. */
struct EnumValue
{
    int value;
    const char* name;
};
const std::vector<EnumValue>& enumValues(cv::ScoreMethod*)
{
    static const std::vector<EnumValue> v = {{cv::SCORE_METHOD_RANSAC, "cv2.SCORE_METHOD_RANSAC"},
                                             {cv::SCORE_METHOD_MSAC, "cv2.SCORE_METHOD_MSAC"},
                                             {cv::SCORE_METHOD_MAGSAC, "cv2.SCORE_METHOD_MAGSAC"},
                                             {cv::SCORE_METHOD_LMEDS, "cv2.SCORE_METHOD_LMEDS"}};
    return v;
}
const std::vector<EnumValue>& enumValues(cv::SamplingMethod*)
{
    static const std::vector<EnumValue> v = {
        {cv::SAMPLING_UNIFORM, "cv2.SAMPLING_UNIFORM"},
        {cv::SAMPLING_PROGRESSIVE_NAPSAC, "cv2.SAMPLING_PROGRESSIVE_NAPSAC"},
        {cv::SAMPLING_NAPSAC, "cv2.SAMPLING_NAPSAC"},
        {cv::SAMPLING_PROSAC, "cv2.SAMPLING_PROSAC"}};
    return v;
}
const std::vector<EnumValue>& enumValues(cv::essential::EssentialEngine*)
{
    static const std::vector<EnumValue> v = {
        {cv::essential::ENGINE_ADAPTIVE, "ENGINE_ADAPTIVE"},
        {cv::essential::ENGINE_OPENCV, "ENGINE_OPENCV"},
        {cv::essential::ENGINE_PREEMPTIVE, "ENGINE_PREEMPTIVE"}};
    return v;
}
const std::vector<EnumValue>& enumValues(cv::essential::EssentialDistance*)
{
    static const std::vector<EnumValue> v = {
        {cv::essential::DISTANCE_SAMPSON, "DISTANCE_SAMPSON"},
        {cv::essential::DISTANCE_SYMMETRIC_EPIPOLAR, "DISTANCE_SYMMETRIC_EPIPOLAR"}};
    return v;
}
const std::vector<EnumValue>& enumValues(cv::essential::EssentialSampleBudget*)
{
    static const std::vector<EnumValue> v = {
        {cv::essential::BUDGET_CONFIDENCE, "BUDGET_CONFIDENCE"},
        {cv::essential::BUDGET_OPENCV_TIME, "BUDGET_OPENCV_TIME"}};
    return v;
}

/** Defines one EssentialParams field as a Python attribute: plain fields as they are, enum fields
as ints checked against their enumeration. */
template <class T>
void defineParamField(py::class_<Params>& cls, const char* name, T Params::*member)
{
    if constexpr (std::is_enum_v<T>) {
        const std::string field = name;
        cls.def_property(
            name, [member](const Params& p) { return static_cast<int>(p.*member); },
            [member, field](Params& p, int value) {
                std::string names;
                for (const EnumValue& e : enumValues(static_cast<T*>(nullptr))) {
                    if (e.value == value) {
                        p.*member = static_cast<T>(value);
                        return;
                    }
                    names += std::string(names.empty() ? "" : ", ") + e.name;
                }
                throw py::value_error("EssentialParams." + field + " must be one of " + names +
                                      ", got " + std::to_string(value));
            });
    } else {
        cls.def_readwrite(name, member);
    }
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
in the header's order: the list the Python attributes and the pickled state are made from. Its
body is written by scripts/params_table.py from the header's struct. */
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
    f("inFrontSearch", &Report::inFrontSearch);
    f("inFrontSearchKept", &Report::inFrontSearchKept);
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
                              ".   documented in opencv2/essential/params.hpp. score and "
                              "sampler take cv2's constants\n"
                              ".   (cv2.SCORE_METHOD_MSAC, cv2.SCORE_METHOD_LMEDS, "
                              "cv2.SAMPLING_UNIFORM, ...); engine,\n"
                              ".   distance and sampleBudget this module's (ENGINE_*, "
                              "DISTANCE_*, BUDGET_*).");
    params.def(py::init([](const py::kwargs& kwargs) { return paramsFromKeywords(kwargs); }));
    forEachParamField(
        [&](const char* name, auto member) { defineParamField(params, name, member); });
    params
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
