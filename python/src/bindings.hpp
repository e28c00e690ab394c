// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The parts of the Python module cv_essential, each defined in its own file and put together in
// module.cpp. `forms` is the private submodule that holds the overloads behind the public
// functions (cv2_errors.hpp).

#ifndef CV_ESSENTIAL_PY_BINDINGS_HPP
#define CV_ESSENTIAL_PY_BINDINGS_HPP

#include <opencv2/essential.hpp>

#include <pybind11/pybind11.h>

namespace cv_essential_py {

namespace py = pybind11;

/** EssentialParams, EssentialReport and the constants of their fields (params_report.cpp). */
void defineParamsAndReport(py::module_& m);
/** An EssentialReport's pickled state and back (batch.cpp pickles pair results with it). */
py::tuple reportState(const cv::essential::EssentialReport& r);
cv::essential::EssentialReport reportFromState(const py::tuple& s);
/** findEssentialMatIter and recoverPose with cv2's forms, and the module's own (drop_in.cpp). */
void defineDropIn(py::module_& m, py::module_& forms);
/** listSolvers, registerSolver with Python solvers, isOpenCvLoopAvailable (solvers.cpp). */
void defineSolvers(py::module_& m, py::module_& forms);
/** findEssentialMatBatch and batchPairSeed (batch.cpp). */
void defineBatch(py::module_& m, py::module_& forms);
/** The private timing hook of the binding-overhead benchmark (overhead_probe.cpp). */
void defineOverheadProbe(py::module_& forms);

} // namespace cv_essential_py

#endif // CV_ESSENTIAL_PY_BINDINGS_HPP
