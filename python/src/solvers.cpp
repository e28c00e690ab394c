// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Solvers from Python: listSolvers, registerSolver with a Python function as a minimal solver,
// and isOpenCvLoopAvailable.

#include "bindings.hpp"
#include "cv2_errors.hpp"

#include <opencv2/essential.hpp>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <string>

namespace cv_essential_py {

namespace {

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
        raiseCv2Error("registerSolver: sampleSize must be >= 5, maxSolutions >= 1 and "
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
        raiseCv2Error(e.what());
    }
}

} // namespace

void defineSolvers(py::module_& m, py::module_& forms)
{
    m.def("listSolvers", &cv::essential::listSolvers,
          "listSolvers() -> retval\n"
          ".   The names of the registered solvers (built in: gn, lm, robust, nister, and the\n"
          ".   composites such as gn+nister), for EssentialParams(solver=...).");
    m.def("isOpenCvLoopAvailable", &cv::essential::isOpenCvLoopAvailable,
          "isOpenCvLoopAvailable() -> retval\n"
          ".   True when this build can run solvers inside OpenCV's own RANSAC loop\n"
          ".   (EssentialParams(engine=ENGINE_OPENCV)).");
    forms.def("registerSolver", &registerPythonSolver, py::arg("name"), py::arg("solver"),
              py::arg("sampleSize") = 5, py::arg("maxSolutions") = 10,
              py::arg("successRate") = 1.0);
    defineWithCv2Errors(
        m, forms, "registerSolver", {},
        "registerSolver(name, solver[, sampleSize[, maxSolutions[, successRate]]]) -> None\n"
        ".   Registers a minimal solver written in Python: solver(x1, x2) takes two\n"
        ".   (sampleSize, 2) float64 arrays of normalised points (K^-1 applied) and returns a\n"
        ".   list of 3 x 3 essential matrices (at most maxSolutions are read). successRate is\n"
        ".   the chance that it solves an outlier-free sample (1 for a closed-form solver). Slow\n"
        ".   (one Python call per sample, with the GIL) but usable in every form with\n"
        ".   EssentialParams(solver=name). Its exceptions become cv2.error naming it.");
}

} // namespace cv_essential_py
