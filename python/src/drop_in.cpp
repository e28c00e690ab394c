// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// findEssentialMatIter and recoverPose with cv2 4.6's forms, keyword names, defaults, dispatch
// order and return tuples, plus the module's own form (EssentialParams in, a report out).

#include "bindings.hpp"
#include "cv2_arrays.hpp"
#include "cv2_errors.hpp"

#include <opencv2/essential.hpp>

#include <pybind11/stl.h>

#include <utility>

namespace cv_essential_py {

namespace {

using Point = std::pair<double, double>;

/** The mask argument as the estimators take it: a private copy, so that the caller's array is
never written (cv2 returns a new mask array). */
cv::Mat maskCopy(const InputMat& mask)
{
    return mask.mat.clone();
}

py::tuple findCamera(const InputMat& points1, const InputMat& points2, const InputMat& cameraMatrix,
                     int method, double prob, double threshold, int maxIters,
                     const InputMat& maskIn)
{
    cv::Mat E, mask = maskCopy(maskIn);
    withoutGil([&] {
        E = cv::essential::findEssentialMatIter(points1.mat, points2.mat, cameraMatrix.mat, method,
                                                prob, threshold, maxIters, mask);
    });
    return py::make_tuple(toNumpy(E), toNumpy(mask));
}

py::tuple findFocal(const InputMat& points1, const InputMat& points2, double focal, Point pp,
                    int method, double prob, double threshold, int maxIters, const InputMat& maskIn)
{
    cv::Mat E, mask = maskCopy(maskIn);
    withoutGil([&] {
        E = cv::essential::findEssentialMatIter(points1.mat, points2.mat, focal,
                                                cv::Point2d(pp.first, pp.second), method, prob,
                                                threshold, maxIters, mask);
    });
    return py::make_tuple(toNumpy(E), toNumpy(mask));
}

py::tuple findTwoCameras(const InputMat& points1, const InputMat& points2,
                         const InputMat& cameraMatrix1, const InputMat& distCoeffs1,
                         const InputMat& cameraMatrix2, const InputMat& distCoeffs2, int method,
                         double prob, double threshold, const InputMat& maskIn)
{
    cv::Mat E, mask = maskCopy(maskIn);
    withoutGil([&] {
        E = cv::essential::findEssentialMatIter(points1.mat, points2.mat, cameraMatrix1.mat,
                                                distCoeffs1.mat, cameraMatrix2.mat, distCoeffs2.mat,
                                                method, prob, threshold, mask);
    });
    return py::make_tuple(toNumpy(E), toNumpy(mask));
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

py::tuple findUsac(const InputMat& points1, const InputMat& points2, const InputMat& cameraMatrix1,
                   const InputMat& cameraMatrix2, const InputMat& distCoeffs1,
                   const InputMat& distCoeffs2, const py::object& params, const InputMat& maskIn)
{
    if (!py::isinstance(params, py::module_::import("cv2").attr("UsacParams")))
        throw py::type_error("params: expected a cv2.UsacParams");
    const cv::UsacParams usac = usacParamsOf(params);
    cv::Mat E, mask = maskCopy(maskIn);
    withoutGil([&] {
        E = cv::essential::findEssentialMatIter(points1.mat, points2.mat, cameraMatrix1.mat,
                                                cameraMatrix2.mat, distCoeffs1.mat, distCoeffs2.mat,
                                                mask, usac);
    });
    return py::make_tuple(toNumpy(E), toNumpy(mask));
}

py::tuple findWithParams(const InputMat& points1, const InputMat& points2,
                         const InputMat& cameraMatrix, const cv::essential::EssentialParams& params,
                         const InputMat& maskIn)
{
    cv::Mat E, mask = maskCopy(maskIn);
    cv::essential::EssentialReport report;
    withoutGil([&] {
        E = cv::essential::findEssentialMatIter(points1.mat, points2.mat, cameraMatrix.mat, params,
                                                mask, &report);
    });
    return py::make_tuple(toNumpy(E), toNumpy(mask), report);
}

// recoverPose. cv2 returns R and t (and E, the triangulated points) as new arrays; the output
// arguments it accepts (R, t, E, triangulatedPoints) are converted as cv2 converts them and
// otherwise ignored, as their values are.

py::tuple poseFromCamera(const InputMat& E, const InputMat& points1, const InputMat& points2,
                         const InputMat& cameraMatrix, const InputMat&, const InputMat&,
                         const InputMat& maskIn)
{
    cv::Mat R, t, mask = maskCopy(maskIn);
    int inFront = 0;
    withoutGil([&] {
        inFront = cv::essential::recoverPoseIter(E.mat, points1.mat, points2.mat, cameraMatrix.mat,
                                                 R, t, mask);
    });
    return py::make_tuple(inFront, toNumpy(R), toNumpy(t), toNumpy(mask));
}

py::tuple poseFromFocal(const InputMat& E, const InputMat& points1, const InputMat& points2,
                        const InputMat&, const InputMat&, double focal, Point pp,
                        const InputMat& maskIn)
{
    cv::Mat R, t, mask = maskCopy(maskIn);
    int inFront = 0;
    withoutGil([&] {
        inFront = cv::essential::recoverPoseIter(E.mat, points1.mat, points2.mat, R, t, focal,
                                                 cv::Point2d(pp.first, pp.second), mask);
    });
    return py::make_tuple(inFront, toNumpy(R), toNumpy(t), toNumpy(mask));
}

py::tuple poseWithDistance(const InputMat& E, const InputMat& points1, const InputMat& points2,
                           const InputMat& cameraMatrix, double distanceThresh, const InputMat&,
                           const InputMat&, const InputMat& maskIn, const InputMat&)
{
    cv::Mat R, t, points, mask = maskCopy(maskIn);
    int inFront = 0;
    withoutGil([&] {
        inFront = cv::essential::recoverPoseIter(E.mat, points1.mat, points2.mat, cameraMatrix.mat,
                                                 R, t, distanceThresh, mask, points);
    });
    return py::make_tuple(inFront, toNumpy(R), toNumpy(t), toNumpy(mask), toNumpy(points));
}

py::tuple poseFromTwoCameras(const InputMat& points1, const InputMat& points2,
                             const InputMat& cameraMatrix1, const InputMat& distCoeffs1,
                             const InputMat& cameraMatrix2, const InputMat& distCoeffs2,
                             const InputMat&, const InputMat&, const InputMat&, int method,
                             double prob, double threshold, const InputMat& maskIn)
{
    cv::Mat E, R, t, mask = maskCopy(maskIn);
    int inFront = 0;
    withoutGil([&] {
        inFront = cv::essential::recoverPoseIter(
            points1.mat, points2.mat, cameraMatrix1.mat, distCoeffs1.mat, cameraMatrix2.mat,
            distCoeffs2.mat, E, R, t, method, prob, threshold, mask);
    });
    return py::make_tuple(inFront, toNumpy(E), toNumpy(R), toNumpy(t), toNumpy(mask));
}

const char* const kFindDoc =
    "findEssentialMatIter(points1, points2, cameraMatrix[, method[, prob[, threshold[, maxIters[, "
    "mask]]]]]) -> retval, mask\n"
    "findEssentialMatIter(points1, points2[, focal[, pp[, method[, prob[, threshold[, maxIters[, "
    "mask]]]]]]]) -> retval, mask\n"
    "findEssentialMatIter(points1, points2, cameraMatrix1, distCoeffs1, cameraMatrix2, "
    "distCoeffs2[, method[, prob[, threshold[, mask]]]]) -> retval, mask\n"
    "findEssentialMatIter(points1, points2, cameraMatrix1, cameraMatrix2, dist_coeff1, "
    "dist_coeff2, params[, mask]) -> retval, mask\n"
    "findEssentialMatIter(points1, points2, cameraMatrix, params[, mask]) -> retval, mask, "
    "report\n"
    ".   @brief Calculates an essential matrix from the corresponding points in two images, as\n"
    ".   cv2.findEssentialMat does (the same forms, arguments, defaults and results), with the\n"
    ".   iterative minimal-set solvers of Rosten, Reitmayr and Drummond.\n"
    ".\n"
    ".   The first four forms are cv2.findEssentialMat's (params: a cv2.UsacParams). The last one\n"
    ".   takes an EssentialParams and returns an EssentialReport as well. retval is the 3 x 3\n"
    ".   essential matrix (None if none was found), mask an N x 1 uint8 array of the inliers.\n"
    ".   Bad input raises cv2.error.";

const char* const kPoseDoc =
    "recoverPose(points1, points2, cameraMatrix1, distCoeffs1, cameraMatrix2, distCoeffs2[, E[, "
    "R[, t[, method[, prob[, threshold[, mask]]]]]]]) -> retval, E, R, t, mask\n"
    "recoverPose(E, points1, points2, cameraMatrix[, R[, t[, mask]]]) -> retval, R, t, mask\n"
    "recoverPose(E, points1, points2, cameraMatrix, distanceThresh[, R[, t[, mask[, "
    "triangulatedPoints]]]]) -> retval, R, t, mask, triangulatedPoints\n"
    "recoverPose(E, points1, points2[, R[, t[, focal[, pp[, mask]]]]]) -> retval, R, t, mask\n"
    ".   @brief Recovers the rotation and the translation from an essential matrix and the\n"
    ".   corresponding points, as cv2.recoverPose does (the same forms and results). The first\n"
    ".   form estimates E with findEssentialMatIter. As in cv2, a positional fifth argument after\n"
    ".   the camera matrix is the (ignored) output R: give distanceThresh by keyword.";

const char* const kPoseIterDoc =
    "recoverPoseIter(...) -> the same forms and results as recoverPose\n"
    ".   @brief The C++ API's name for recoverPose (cv::essential::recoverPoseIter); both names "
    "are\n"
    ".   the same function here.";

} // namespace

void defineDropIn(py::module_& m, py::module_& forms)
{
    const int ransac = static_cast<int>(cv::RANSAC);
    const py::none none;
    // The forms in cv2's order; pybind11 tries them in turn, as cv2's dispatcher does, and then
    // the module's own form.
    forms.def("findEssentialMatIter", &findCamera, py::arg("points1"), py::arg("points2"),
              py::arg("cameraMatrix"), py::arg("method") = ransac, py::arg("prob") = 0.999,
              py::arg("threshold") = 1.0, py::arg("maxIters") = 1000, py::arg("mask") = none);
    forms.def("findEssentialMatIter", &findFocal, py::arg("points1"), py::arg("points2"),
              py::arg("focal") = 1.0, py::arg("pp") = Point(0.0, 0.0), py::arg("method") = ransac,
              py::arg("prob") = 0.999, py::arg("threshold") = 1.0, py::arg("maxIters") = 1000,
              py::arg("mask") = none);
    forms.def("findEssentialMatIter", &findTwoCameras, py::arg("points1"), py::arg("points2"),
              py::arg("cameraMatrix1"), py::arg("distCoeffs1"), py::arg("cameraMatrix2"),
              py::arg("distCoeffs2"), py::arg("method") = ransac, py::arg("prob") = 0.999,
              py::arg("threshold") = 1.0, py::arg("mask") = none);
    forms.def("findEssentialMatIter", &findUsac, py::arg("points1"), py::arg("points2"),
              py::arg("cameraMatrix1"), py::arg("cameraMatrix2"), py::arg("dist_coeff1"),
              py::arg("dist_coeff2"), py::arg("params"), py::arg("mask") = none);
    forms.def("findEssentialMatIter", &findWithParams, py::arg("points1"), py::arg("points2"),
              py::arg("cameraMatrix"), py::arg("params"), py::arg("mask") = none);
    defineWithCv2Errors(m, forms, "findEssentialMatIter", {"points1", "points2", "cameraMatrix"},
                        kFindDoc);

    // recoverPose in cv2 4.6's dispatch order.
    forms.def("recoverPose", &poseFromTwoCameras, py::arg("points1"), py::arg("points2"),
              py::arg("cameraMatrix1"), py::arg("distCoeffs1"), py::arg("cameraMatrix2"),
              py::arg("distCoeffs2"), py::arg("E") = none, py::arg("R") = none, py::arg("t") = none,
              py::arg("method") = ransac, py::arg("prob") = 0.999, py::arg("threshold") = 1.0,
              py::arg("mask") = none);
    forms.def("recoverPose", &poseFromCamera, py::arg("E"), py::arg("points1"), py::arg("points2"),
              py::arg("cameraMatrix"), py::arg("R") = none, py::arg("t") = none,
              py::arg("mask") = none);
    forms.def("recoverPose", &poseWithDistance, py::arg("E"), py::arg("points1"),
              py::arg("points2"), py::arg("cameraMatrix"), py::arg("distanceThresh"),
              py::arg("R") = none, py::arg("t") = none, py::arg("mask") = none,
              py::arg("triangulatedPoints") = none);
    forms.def("recoverPose", &poseFromFocal, py::arg("E"), py::arg("points1"), py::arg("points2"),
              py::arg("R") = none, py::arg("t") = none, py::arg("focal") = 1.0,
              py::arg("pp") = Point(0.0, 0.0), py::arg("mask") = none);
    defineWithCv2Errors(m, forms, "recoverPose", {"E", "points1", "points2", "cameraMatrix"},
                        kPoseDoc);
    // The C++ API's name (the Iter suffix cannot collide with cv::recoverPose under
    // using-directives); in Python both names are the same forms.
    forms.attr("recoverPoseIter") = forms.attr("recoverPose");
    defineWithCv2Errors(m, forms, "recoverPoseIter", {"E", "points1", "points2", "cameraMatrix"},
                        kPoseIterDoc);
}

} // namespace cv_essential_py
