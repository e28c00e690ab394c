// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// COLMAP's camera models as stored in its database (model id, float64 parameters in the model's
// order), and the mapping between pixels and normalised image coordinates by each model's own
// formula. Supported: SIMPLE_PINHOLE (0), PINHOLE (1), SIMPLE_RADIAL (2), RADIAL (3), OPENCV (4);
// the other COLMAP 3.8 models are named in the refusal. Pixel coordinates are COLMAP's: those of
// its keypoints, with the same origin as the principal point stored with the camera.

#ifndef ESSENTIAL_SAMPLES_COLMAP_CAMERA_MODELS_HPP
#define ESSENTIAL_SAMPLES_COLMAP_CAMERA_MODELS_HPP

#include <opencv2/core.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace essential_colmap {

/** A row of COLMAP's cameras table. */
struct ColmapCamera
{
    std::int64_t id = 0;
    int modelId = -1;
    std::int64_t width = 0, height = 0;
    std::vector<double> params;
    /** COLMAP's prior_focal_length: the focal length is known (given by the user or read from
    EXIF), not a guess. COLMAP verifies a pair as calibrated only when both cameras have it. */
    bool priorFocalLength = false;
};

/** COLMAP's name of a camera model id ("OPENCV_FISHEYE"), or "unknown model id N". */
std::string cameraModelName(int modelId);

/** The number of parameters of a COLMAP model id, or -1 for an id COLMAP 3.8 does not define. */
int cameraModelParamCount(int modelId);

/** Every supported model as the general form fx, fy, cx, cy, k1, k2, p1, p2 (zeros where the model
has no such term). With (u, v) normalised and r2 = u^2 + v^2, the distorted normalised point is
  u' = u (1 + k1 r2 + k2 r2^2) + 2 p1 u v + p2 (r2 + 2 u^2)
  v' = v (1 + k1 r2 + k2 r2^2) + 2 p2 u v + p1 (r2 + 2 v^2)
and the pixel (fx u' + cx, fy v' + cy): COLMAP's OPENCV model, of which SIMPLE_RADIAL (k1 only,
fx = fy = f) and RADIAL (k1, k2, fx = fy = f) are special cases, and the pinhole models without
distortion. */
struct CameraIntrinsics
{
    double fx = 1, fy = 1, cx = 0, cy = 0;
    double k1 = 0, k2 = 0, p1 = 0, p2 = 0;

    cv::Matx33d K() const { return cv::Matx33d(fx, 0, cx, 0, fy, cy, 0, 0, 1); }
    bool distorted() const { return k1 != 0 || k2 != 0 || p1 != 0 || p2 != 0; }
};

/** The camera's intrinsics; a DatabaseError naming the camera and its model for a model that is
not supported, a wrong number of parameters, a non-finite parameter, or a focal length outside
[1e-100, 1e100] pixels (zero, negative, or so far from any camera that the module would find the
camera matrix singular). */
CameraIntrinsics cameraIntrinsics(const ColmapCamera& camera);

/** The pixel of a normalised point (the model's forward formula). */
cv::Point2d projectNormalised(const CameraIntrinsics& camera, const cv::Point2d& normalised);

/** The normalised point whose pixel is `pixel`: the inverse of projectNormalised() by Newton's
method on the 2 x 2 distortion Jacobian, from the distorted point as the start. False when it does
not converge (for example beyond the fold of a strong barrel distortion, where no normalised point
maps to the pixel); `normalised` is then unspecified. */
bool undistortPixel(const CameraIntrinsics& camera, const cv::Point2d& pixel,
                    cv::Point2d& normalised);

} // namespace essential_colmap

#endif
