// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "cv2_errors.hpp"

#include "cv2_arrays.hpp"

#include <set>

namespace cv_essential_py {

py::object cv2Error()
{
    static py::object error = py::module_::import("cv2").attr("error");
    return error;
}

void raiseCv2Error(const std::string& message)
{
    PyErr_SetString(cv2Error().ptr(), message.c_str());
    throw py::error_already_set();
}

namespace {

/** The array arguments of the module's cv2-style forms. */
bool isArrayArgument(const std::string& name)
{
    static const std::set<std::string> names = {"points1",
                                                "points2",
                                                "cameraMatrix",
                                                "cameraMatrix1",
                                                "cameraMatrix2",
                                                "distCoeffs1",
                                                "distCoeffs2",
                                                "dist_coeff1",
                                                "dist_coeff2",
                                                "mask",
                                                "E",
                                                "R",
                                                "t",
                                                "triangulatedPoints"};
    return names.count(name) > 0;
}

/** The first array argument that cv2 would not convert, and why; empty when there is none. */
std::string firstBadArray(const py::args& args, const py::kwargs& kwargs,
                          const std::vector<std::string>& positional)
{
    InputMat ignored;
    std::string why;
    for (size_t i = 0; i < args.size() && i < positional.size(); ++i)
        if (isArrayArgument(positional[i]) && !toInputMat(args[i], ignored, &why))
            return "'" + positional[i] + "' (argument " + std::to_string(i + 1) + "): " + why;
    for (const auto& item : kwargs) {
        const std::string key = py::str(item.first);
        if (isArrayArgument(key) && !toInputMat(item.second, ignored, &why))
            return "'" + key + "': " + why;
    }
    return std::string();
}

} // namespace

void defineWithCv2Errors(py::module_& m, const py::module_& forms, const char* name,
                         const std::vector<std::string>& positional, const char* doc)
{
    const py::object impl = forms.attr(name);
    const std::string function = name;
    m.def(
        name,
        [impl, function, positional](const py::args& args, const py::kwargs& kwargs) {
            try {
                return impl(*args, **kwargs);
            } catch (py::error_already_set& e) {
                if (!e.matches(PyExc_TypeError)) throw;
                const std::string bad = firstBadArray(args, kwargs, positional);
                // pybind11's message lists the forms; it is kept when no array is to blame
                // (a wrong count, an unknown keyword, a non-integer method...).
                raiseCv2Error(
                    function + ": " +
                    (bad.empty() ? std::string(e.what()) : "cannot convert argument " + bad));
            }
        },
        doc);
}

} // namespace cv_essential_py
