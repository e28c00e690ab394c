// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The Python module cv_essential (pybind11): a drop-in for cv2.findEssentialMat and
// cv2.recoverPose with cv2's conventions, the module's own parameters and report, solvers
// written in Python, and batches of pairs in parallel. See python/README.md.

#include "bindings.hpp"

PYBIND11_MODULE(cv_essential, m)
{
    namespace cep = cv_essential_py;
    namespace py = pybind11;
    m.doc() = "opencv_essential: essential-matrix estimation with iterative minimal-set solvers "
              "(Rosten, Reitmayr, Drummond), a drop-in for cv2.findEssentialMat and "
              "cv2.recoverPose";
    // The docstrings give the forms in cv2's notation; pybind11's generated "(*args, **kwargs)"
    // signatures of the dispatching functions would only hide them.
    py::options options;
    options.disable_function_signatures();
    py::module_ forms = m.def_submodule("_forms", "the overloads behind the public functions");
    cep::defineParamsAndReport(m);
    cep::defineDropIn(m, forms);
    cep::defineSolvers(m, forms);
    cep::defineBatch(m, forms);
    cep::defineOverheadProbe(forms);
}
