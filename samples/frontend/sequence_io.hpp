// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// Image sequences with ground-truth camera poses, as ../shared/data/rail-a: a folder of frames
// NNN.jpg, camera.txt (the 3 x 3 camera matrix) and poses.txt (one line per frame
// `k r00 r01 .. r22 Cx Cy Cz`, world-to-camera rotation and camera centre). Reading such a folder
// and the true relative pose, essential and fundamental matrices of two of its frames, for the
// sample programs and the experiments. It uses OpenCV only; nothing here is part of the
// opencv_essential library.

#ifndef ESSENTIAL_SAMPLES_SEQUENCE_IO_HPP
#define ESSENTIAL_SAMPLES_SEQUENCE_IO_HPP

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace essential_samples {

/** The pose of one frame. */
struct Pose
{
    cv::Matx33d R; ///< world to camera
    cv::Vec3d C;   ///< camera centre in the world
};

/** Reads DIR/camera.txt into K (nine numbers, row by row) and appends the poses of DIR/poses.txt
to `poses`, one per line that starts with a frame number, in file order (the frame number itself is
not used; a line with missing numbers leaves the rest of its pose unspecified). Returns false when
either file cannot be opened or camera.txt does not hold nine numbers; with acceptShortCamera, a
camera.txt that ends before the ninth number is accepted too (K's remaining entries are then
unspecified), only a token that is not a number makes it fail. */
bool readSequence(const std::string& dir, cv::Matx33d& K, std::vector<Pose>& poses,
                  bool acceptShortCamera = false);

/** DIR/NNN.jpg: the path of frame k (at least three digits). */
std::string framePath(const std::string& dir, int k);

/** The rotation from frame a's camera to frame b's: R_b R_a^T. */
cv::Matx33d relativeRotation(const Pose& a, const Pose& b);

/** The translation of frame b's camera relative to frame a's, in b's coordinates:
-R_b (C_b - C_a), so that x_b = relativeRotation(a, b) x_a + relativeTranslation(a, b). */
cv::Vec3d relativeTranslation(const Pose& a, const Pose& b);

/** [t]x, the matrix of the cross product t x (.). */
cv::Matx33d crossMatrix(const cv::Vec3d& t);

/** The true essential matrix of frames (a, b): E = [t]x R of their relative pose, so that
x_b^T E x_a = 0 for normalised image points. */
cv::Matx33d trueEssential(const Pose& a, const Pose& b);

/** The true fundamental matrix of frames (a, b) with camera K: K^-T E K^-1, so that
x_b^T F x_a = 0 for pixel coordinates. */
cv::Matx33d trueFundamental(const cv::Matx33d& K, const Pose& a, const Pose& b);

/** The Sampson distance in pixels of the match (p1, p2) to the fundamental matrix F (p2 in the
second image); HUGE_VAL when undefined. */
double sampsonPx(const cv::Matx33d& F, const cv::Point2f& p1, const cv::Point2f& p2);

} // namespace essential_samples

#endif
