// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Errors as cv2 raises them: cv2.error for a cv::Exception and for arguments no form accepts.

#ifndef CV_ESSENTIAL_PY_CV2_ERRORS_HPP
#define CV_ESSENTIAL_PY_CV2_ERRORS_HPP

#include <opencv2/core.hpp>

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace cv_essential_py {

namespace py = pybind11;

/** cv2.error, the exception cv2 raises; the module raises the same. */
py::object cv2Error();

/** Raises cv2.error with `message` (as a C++ exception pybind11 passes on to Python). */
[[noreturn]] void raiseCv2Error(const std::string& message);

/** Runs `call` without the GIL and turns a cv::Exception into cv2.error. */
template <class Call> void withoutGil(Call call)
{
    try {
        py::gil_scoped_release release;
        call();
    } catch (const cv::Exception& e) {
        raiseCv2Error(e.what());
    }
}

/** Defines the public function `name` of `m` over the overloads registered under the same name
in `forms` (pybind11 tries them in turn, as cv2's dispatcher tries cv2's forms). When no form
accepts the arguments, pybind11's TypeError becomes cv2.error, as in cv2, naming the first array
argument that could not be converted and why (`positional` names the positional arguments of
the first form). */
void defineWithCv2Errors(py::module_& m, const py::module_& forms, const char* name,
                         const std::vector<std::string>& positional, const char* doc);

} // namespace cv_essential_py

#endif // CV_ESSENTIAL_PY_CV2_ERRORS_HPP
