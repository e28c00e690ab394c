// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#ifndef OPENCV_ESSENTIAL_HPP
#define OPENCV_ESSENTIAL_HPP

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include "opencv2/essential/batch.hpp"
#include "opencv2/essential/params.hpp"
#include "opencv2/essential/solver.hpp"

/** @defgroup essential Essential matrix estimation with iterative minimal-set solvers

Fast, robust estimation of the essential matrix between two calibrated views, after Rosten,
Reitmayr and Drummond, "Improved RANSAC performance using simple, iterative minimal-set solvers"
@cite Rosten2010:
hypotheses come from a tiny Gauss-Newton or Levenberg-Marquardt optimiser on a minimal set of five
correspondences in a 5-DOF parameterisation (rotation by the SO(3) exponential map, translation as a
rotated unit vector), or from a speed-tuned Nister five-point solver (the default draws from both
in turn), are verified by Wald's SPRT and scored by MSAC on the Sampson distance, each
new best model is polished by a few iterations of iteratively reweighted least squares (IRLS) on the
points near it (local optimisation), and the winner is refined by IRLS with Tukey's biweight at a
scale that follows the estimated noise, on the points near it and in front of both cameras
(docs/ACCURACY.md).

findEssentialMatIter() has every overload of `cv::findEssentialMat` of the OpenCV it is built
against (six in 4.x; four in 5.x, which removed the two forms without maxIters) with the same
arguments, defaults, return value and mask, and recoverPoseIter() every overload of
`cv::recoverPose`, so renaming a call site is enough to switch. The `Iter` suffix keeps the names
apart from OpenCV's under `using namespace cv; using namespace cv::essential;` and under
argument-dependent lookup (every argument is a cv:: type, so an unqualified call also finds the cv::
function). The same functions are also declared as `cv::essential::recoverPose`, the module's
original spelling: call that one qualified, since unqualified it is ambiguous with cv::recoverPose.

Input and output arrays are taken exactly as OpenCV 4.6 takes them (checked against OpenCV itself
for every overload, method flag, 21 point layouts and 7 mask forms by test/test_drop_in_layouts.cpp
and test/test_drop_in_recover_pose.cpp; the table: docs/ROBUSTNESS.md, "Point layouts"). OpenCV
reads points in one of three ways, depending on the overload and the method:

- RANSAC and LMEDS (camera-matrix and focal forms), and recoverPoseIter() from E: any depth,
converted to double; `std::vector<Point2f|Point2d|Point>`, an N x 2 one-channel or N x 1 / 1 x N
  two-channel matrix, views included; both arrays with the same number of channels (so not a
  vector of points with an N x 2 matrix);
- the USAC flags (camera-matrix and focal forms) and the UsacParams form without distortion: any
  depth; one point per row of an N x k matrix (k >= 2; the first two coordinates are x and y, so
  homogeneous N x 3 points must have w = 1) or per element of a k-channel array, a matrix with fewer
  rows than columns transposed first (2 x N, 3 x N);
- the forms with distortion coefficients (which call cv::undistortPoints first) and
recoverPoseIter()'s two-camera form: CV_32F or CV_64F only; the shapes above or their transposes (2
x N), continuous in memory (a view such as `pts.colRange(0, 2)` is rejected, except by the
UsacParams form, which copies it first).

A mask is written as by the same path: RANSAC and LMEDS keep a caller's preallocated 1 x N CV_8U
mask as 1 x N (OpenCV creates the mask allowing the transposed shape) and reject a preallocated
mask view that is not continuous in memory; the USAC flags and the UsacParams form copy an N x 1
CV_8U mask into the caller's array (a 1 x N mask becomes N x 1, a view of the right size is written
in place, a `std::vector<int>` receives the values converted); any other preallocated mask is
replaced by an N x 1 CV_8U one.

Differences from `cv::findEssentialMat` and `cv::recoverPose` that a caller may notice:
- invalid input (fewer than 5 points, non-finite coordinates, points more than 1e8 focal lengths
  from the principal point, a singular camera matrix or one with a negative focal length, prob
  outside (0, 1), ...) raises cv::Exception naming the argument, where OpenCV may assert, crash or
  return garbage (the full table: docs/ROBUSTNESS.md);
- data with no geometry (independent points, all points identical, fewer than six distinct
  correspondences among the inliers) gives an empty E and an all-zero mask;
- a scene that does not determine the pose (no parallax, or a plane) still gives E, and the
  EssentialReport of the module's own overload says so (EssentialReport::degenerate);
- `maxIters` is a budget, not a count of samples: an iterative solver that solves a fraction s of
  outlier-free samples may draw maxIters / s samples (EssentialParams::maxIterations), and when that
cap does not buy one expected good sample at the best model's inlier ratio (hard data: few inliers,
  or a wrong best model), the search goes on, every other sample spatially local, up to the samples
  that fit in three quarters of the time OpenCV's RANSAC spends on `maxIters` iterations with as
  many points (about 20 maxIters at N = 500; EssentialParams::sampleBudget, budgetLocalSamples).
  Data on which the confidence is reached stop as before; hard data get the time OpenCV would have
  spent and are right more often (docs/HARD_PAIRS.md);
- when the winner's inliers are dominated by one plane, models fixed by the points off the plane
  are tried and kept when clearly better supported (EssentialParams::planeParallax): planar
  scenes are where a search stops on the plane's twin pose;
- the returned E is refined by IRLS on the points near the search winner (set
  EssentialParams::refine = false in the module's own overload to skip this), and the mask is that
  of the refined E;
- LMEDS derives its threshold from the median error as OpenCV does, with OpenCV's floor of 0.001
  normalised units; a solver whose sample is as large as the point set (robust on 10 points) uses
  the finite-sample correction of one spare point instead of dividing by zero;
- recoverPoseIter() from E (without distanceThresh) counts every point in front of both cameras:
  OpenCV's overloads ignore points farther than 50 baselines, so that in a deep scene seen from a
  short baseline the sign of t is arbitrary there; the distanceThresh overload honours the caller's
  threshold as OpenCV does (DLT triangulation, OpenCV's cheirality test), so passing 50 reproduces
  OpenCV; its distanceThresh must be positive (+inf: no cut), where OpenCV counts no point;
- recoverPoseIter() reads a CV_32F E (OpenCV 4.6 fails on one with a type mismatch inside its
  triangulation); R, t and E may be noArray() (OpenCV asserts);
- recoverPoseIter()'s two-camera form has no 50-baseline cut either; when no essential matrix is
found it returns 0 with E empty, R = I and t = 0, and with exactly five points it keeps, of the
several solutions, the one with the most points in front (OpenCV asserts in both cases);
- a failed estimate always leaves an all-zero N x 1 mask (OpenCV's RANSAC leaves the mask it
  allocated as it was, its UsacParams form leaves the caller's mask untouched);
- the USAC method flags and the UsacParams overload map onto the module's own engine (adaptive
  MSAC with IRLS local optimisation, PROSAC, SPRT) as in the tables below, in the spirit of
  OpenCV's usac::setParameters; OpenCV's graph-cut and sigma-consensus LO, MAGSAC++ scoring and
  parallel RANSAC are not implemented; the NAPSAC samplers are the module's own (local samples on a
  grid over both images). Unlike OpenCV 4.6, whose USAC flags ignore
  `maxIters` (always 1000), the flags honour it.

The `method` flags of the drop-in overloads. Every flag keeps `prob`, `threshold` and `maxIters`;
"LO k" is EssentialParams::loIterations = k (IRLS on all the inliers of each new best model); SPRT
verification (EssentialParams::sprt) is on for RANSAC and every USAC flag, as OpenCV's USAC
verifies with SPRT too:

| flag            | engine settings            | OpenCV 4.6 (usac::setParameters)             |
|-----------------|----------------------------|----------------------------------------------|
| `RANSAC`        | MSAC, uniform, LO 5, SPRT  | plain RANSAC                                 |
| `LMEDS`         | LMedS (no LO, no SPRT)     | LMedS                                        |
| `USAC_DEFAULT`  | MSAC, uniform, LO 5        | MSAC, inner + iterative LO                   |
| `USAC_PARALLEL` | as USAC_DEFAULT (1 thread) | MSAC, inner LO, parallel                     |
| `USAC_FAST`     | MSAC, uniform, LO 2        | MSAC, fewer LO iterations                    |
| `USAC_ACCURATE` | MSAC, uniform, LO 10       | MSAC, graph-cut LO                           |
| `USAC_PROSAC`   | MSAC, PROSAC, LO 5         | PROSAC (points sorted best first), inner LO  |
| `USAC_MAGSAC`   | MSAC, uniform, LO 5        | MAGSAC++ score, sigma-consensus LO           |
| `USAC_FM_8PTS`  | as USAC_DEFAULT            | 8-point fundamental-matrix solver            |

Inlier distance: RANSAC and LMEDS compare the Sampson distance with the threshold, as OpenCV
does; every USAC flag and the UsacParams form compare the symmetric epipolar distance
sqrt(d1^2 + d2^2) (each point's distance to its epipolar line), as OpenCV 4.6's USAC does for
essential matrices (EssentialParams::distance = DISTANCE_SYMMETRIC_EPIPOLAR). The latter is at least
twice the former, so at the same threshold the USAC flags mark fewer inliers, in both libraries.
The returned E has unit Frobenius norm (singular values 1/sqrt(2), 1/sqrt(2), 0), as OpenCV's.

Notes: USAC_PARALLEL runs on one thread and gives the same result as USAC_DEFAULT. USAC_MAGSAC
scores by MSAC with the given threshold (MAGSAC++'s marginalisation over noise scales is not
implemented). USAC_FM_8PTS makes OpenCV fit an unconstrained 3 x 3 matrix with its 8-point
fundamental-matrix solver to the calibrated points; an essential matrix is asked for, so the module
estimates one with its own solvers.

The UsacParams overload reads every field of OpenCV 4.6's UsacParams:

| field                  | meaning here                                                      |
|------------------------|-------------------------------------------------------------------|
| `confidence`           | as `prob`                                                         |
| `threshold`            | as `threshold` (unused by SCORE_METHOD_LMEDS)                     |
| `maxIterations`        | as `maxIters`                                                     |
| `randomGeneratorState` | the seed, read as an unsigned 32-bit value                        |
| `score`                | RANSAC, MSAC, MAGSAC: MSAC; LMEDS: the LMedS engine (1)           |
| `sampler`              | UNIFORM; PROSAC (sorted points); NAPSAC; PROGRESSIVE_NAPSAC (2)   |
| `loMethod`             | LOCAL_OPTIM_NULL: no LO; every other method: IRLS LO (3)          |
| `loIterations`         | IRLS iterations of each LO (0: no LO)                             |
| `loSampleSize`         | LO on a random subset of this many inliers (0: all) (4)           |
| `isParallel`           | ignored (5)                                                       |
| `neighborsSearch`      | ignored (6)                                                       |

(1) LMedS derives its threshold from the data and has no LO; SCORE_METHOD_MAGSAC scores by MSAC
with `threshold` (MAGSAC++ is not implemented). (2) NAPSAC draws every sample among
neighbours (a cell of a 16 x 16 to 2 x 2 grid over both images), PROGRESSIVE_NAPSAC every other
one; with SCORE_METHOD_LMEDS the samples are uniform (the module's LMedS search has no local
sampler). (3)
LOCAL_OPTIM_INNER_LO, LOCAL_OPTIM_INNER_AND_ITER_LO, LOCAL_OPTIM_GC and LOCAL_OPTIM_SIGMA all run
the module's IRLS local optimisation with `loIterations` and `loSampleSize`. (4) 1 to 4 raise
StsBadArg; OpenCV 4.6's default of 14 is used as given. (5) The search runs on one thread; the
result is the same either way. (6) OpenCV uses the neighbourhood graph in its NAPSAC samplers (the
module's use their own grid) and in graph-cut LO (replaced here by IRLS LO), so it cannot change the
result. Invalid values of score, sampler, loMethod, loIterations or loSampleSize raise StsBadArg
naming the field.

One policy for what the module does not implement: the drop-in forms (method flags, UsacParams)
accept every value OpenCV 4.6 accepts and run the nearest equivalent the tables above name
(MAGSAC++ as MSAC, graph-cut and sigma LO as IRLS LO, parallel as one thread, NAPSAC with LMedS as
uniform sampling), so that switching a call site never turns a working call into an exception; the
module's own EssentialParams form raises StsNotImplemented for the same settings, naming the field,
because a caller who spells them out there asked for exactly that.

OpenCV 4.7 added `final_polisher` and `final_polisher_iterations` to UsacParams; 4.6 has neither,
and the module always ends with its IRLS refinement (EssentialParams::refine).
*/

namespace cv {
namespace essential {

//! @addtogroup essential
//! @{

/** @brief Drop-in replacement for `cv::findEssentialMat(points1, points2, cameraMatrix, method,
prob, threshold, maxIters, mask)`.

@param points1 N >= 5 points of the first image, in any layout `cv::findEssentialMat` takes with
this method (the table in the module description): with RANSAC and LMEDS
`std::vector<Point2f|Point2d>`, an N x 2 one-channel or N x 1 / 1 x N two-channel Mat of any depth;
with the USAC flags also 2 x N, N x 3 and 3 x N (first two coordinates) arrays.
@param points2 the N corresponding points of the second image (with RANSAC and LMEDS, with as many
channels as points1).
@param cameraMatrix 3 x 3 intrinsic matrix of both cameras (fx, fy non-zero).
@param method `RANSAC`, `LMEDS` or a USAC flag (`USAC_DEFAULT`, ..., `USAC_MAGSAC`: the settings
each stands for are in the module description's table).
@param prob confidence in (0, 1).
@param threshold maximum distance, in pixels, of an inlier: Sampson distance for RANSAC, symmetric
epipolar distance for the USAC flags (as OpenCV); unused by LMEDS; > 0.
@param maxIters maximum number of RANSAC iterations in OpenCV's units (see
EssentialParams::maxIterations); > 0.
@param mask output N x 1 CV_8U (a preallocated 1 x N CV_8U mask stays 1 x N with RANSAC and LMEDS,
as in OpenCV): 1 for the inliers of the returned E, 0 otherwise.
@return E as a 3 x 3 CV_64F Mat of unit Frobenius norm; with exactly five points, all the distinct
solutions found, stacked as a 3n x 3 Mat; an empty Mat (and an all-zero mask) when no essential
matrix is found.
@throws cv::Exception for invalid arguments, with a message that names the argument.
@sa cv::findEssentialMat
*/
CV_EXPORTS_W Mat findEssentialMatIter(InputArray points1, InputArray points2,
                                      InputArray cameraMatrix, int method = RANSAC,
                                      double prob = 0.999, double threshold = 1.0,
                                      int maxIters = 1000, OutputArray mask = noArray());

#if CV_VERSION_MAJOR <                                                                             \
    5 // OpenCV 5 removed the two forms without maxIters; so does the module there.
/** @overload Same as above with maxIters = 1000 (OpenCV's older form). @sa cv::findEssentialMat */
CV_EXPORTS Mat findEssentialMatIter(InputArray points1, InputArray points2, InputArray cameraMatrix,
                                    int method, double prob, double threshold, OutputArray mask);
#endif

/** @overload The camera matrix is [focal 0 pp.x; 0 focal pp.y; 0 0 1]. @sa cv::findEssentialMat */
CV_EXPORTS_W Mat findEssentialMatIter(InputArray points1, InputArray points2, double focal = 1.0,
                                      Point2d pp = Point2d(0, 0), int method = RANSAC,
                                      double prob = 0.999, double threshold = 1.0,
                                      int maxIters = 1000, OutputArray mask = noArray());

#if CV_VERSION_MAJOR < 5
/** @overload Focal/principal-point form with maxIters = 1000 (OpenCV's older form). @sa
 * cv::findEssentialMat */
CV_EXPORTS Mat findEssentialMatIter(InputArray points1, InputArray points2, double focal,
                                    Point2d pp, int method, double prob, double threshold,
                                    OutputArray mask);
#endif

/** @overload Two cameras, each with its own distortion.

As in OpenCV, the points are undistorted with their own camera, then mapped through the mean of the
two camera matrices, whose focal lengths also convert the pixel threshold. As cv::undistortPoints,
this form takes CV_32F or CV_64F points only, N x 2, 2 x N, N x 1 or 1 x N, continuous in memory.
@sa cv::findEssentialMat
*/
CV_EXPORTS_W Mat findEssentialMatIter(InputArray points1, InputArray points2,
                                      InputArray cameraMatrix1, InputArray distCoeffs1,
                                      InputArray cameraMatrix2, InputArray distCoeffs2,
                                      int method = RANSAC, double prob = 0.999,
                                      double threshold = 1.0, OutputArray mask = noArray());

/** @overload UsacParams form.

Every field of OpenCV 4.6's UsacParams is read, as the module description's table says: confidence,
threshold, maxIterations, randomGeneratorState, score (MSAC or LMedS), sampler (uniform, PROSAC,
NAPSAC or progressive NAPSAC), loMethod / loIterations / loSampleSize (IRLS local optimisation);
isParallel and neighborsSearch cannot change the result and are ignored. OpenCV 4.7 and later
add final_polisher and final_polisher_iterations: NONE_POLISHER, or 0 iterations, switch the
module's final IRLS refinement off (EssentialParams::refine); LSQ_POLISHER, MAGSAC and COV_POLISHER
(the default) run it to its own convergence test. Invalid values raise StsBadArg naming the
field. As in OpenCV, the points are undistorted with each camera's own
coefficients when there are any (then read as the two-camera form reads them, a view copied first),
and read as with the USAC flags otherwise; the mask is N x 1.
@sa cv::findEssentialMat
*/
CV_EXPORTS_W Mat findEssentialMatIter(InputArray points1, InputArray points2,
                                      InputArray cameraMatrix1, InputArray cameraMatrix2,
                                      InputArray dist_coeff1, InputArray dist_coeff2,
                                      OutputArray mask, const UsacParams& params);

/** @brief The module's own overload: every setting, and an optional report.

@param points1 points of the first image, in any layout a drop-in overload takes (read as with the
USAC flags, which take them all).
@param points2 points of the second image.
@param cameraMatrix 3 x 3 intrinsic matrix of both cameras.
@param params solver, scoring, confidence, threshold, iteration cap, seed, refinement.
@param mask output N x 1 CV_8U inlier mask (copied into the caller's array, as with the USAC
flags).
@param report if not null, filled with R, t, counts and timings.
@return E (3 x 3 CV_64F; 3n x 3 for exactly five points), or an empty Mat on failure.
@sa cv::findEssentialMat
*/
CV_EXPORTS Mat findEssentialMatIter(InputArray points1, InputArray points2, InputArray cameraMatrix,
                                    const EssentialParams& params, OutputArray mask = noArray(),
                                    EssentialReport* report = nullptr);

/** @overload The report by reference, the form OpenCV's Python generator wraps: in Python,
`E, mask, report = cv2.essential.findEssentialMatIter(points1, points2, cameraMatrix, params)`.
@sa cv::findEssentialMat
*/
CV_EXPORTS_W Mat findEssentialMatIter(InputArray points1, InputArray points2,
                                      InputArray cameraMatrix, const EssentialParams& params,
                                      OutputArray mask, CV_OUT EssentialReport& report);

/** @brief Drop-in replacement for `cv::recoverPose(E, points1, points2, cameraMatrix, R, t, mask)`.

Decomposes E by SVD into its two rotations and the translation direction, and chooses among the four
(R, +-t) candidates the one that puts the most correspondences in front of both cameras. Unlike
OpenCV 4.6, which ignores points farther than 50 baselines (so that in a deep scene seen from a
short baseline no point counts and the sign of t is arbitrary), every point with positive depth in
both views counts. To get OpenCV's cut, call the distanceThresh overload with 50.

@param E essential matrix: 3 x 3, or its nine entries in one continuous array (1 x 9, 9 x 1), as
OpenCV reads it; CV_32F or CV_64F (OpenCV 4.6 fails on CV_32F).
@param points1 points of the first image, as cv::recoverPose reads them: a vector of 2D points, an
N x 2 one-channel or N x 1 / 1 x N two-channel matrix of any depth, views included, both arrays
with the same number of channels.
@param points2 points of the second image.
@param cameraMatrix 3 x 3 intrinsic matrix.
@param R output 3 x 3 CV_64F rotation from view 1 to view 2 (may be noArray()).
@param t output 3 x 1 CV_64F unit translation (may be noArray()).
@param mask in/out: if given (a continuous CV_8U vector, one entry per point), only its non-zero
points are used; on return it is N x 1 CV_8U and keeps its value at the points used that lie in
front of both cameras for the chosen pose, 0 elsewhere; if empty, it is created with 255 at those
points.
@return the number of (masked) points in front of both cameras.
@sa cv::recoverPose
*/
CV_EXPORTS_W int recoverPoseIter(InputArray E, InputArray points1, InputArray points2,
                                 InputArray cameraMatrix, OutputArray R, OutputArray t,
                                 InputOutputArray mask = noArray());

/** @overload The camera matrix is [focal 0 pp.x; 0 focal pp.y; 0 0 1]. @sa cv::recoverPose */
CV_EXPORTS_W int recoverPoseIter(InputArray E, InputArray points1, InputArray points2,
                                 OutputArray R, OutputArray t, double focal = 1.0,
                                 Point2d pp = Point2d(0, 0), InputOutputArray mask = noArray());

/** @overload With OpenCV's distance cut and the triangulated points.

The caller's distanceThresh is honoured: as `cv::recoverPose`, a point counts for a pose when its
linear (DLT) triangulation, the method of `cv::triangulatePoints`, has positive depth below
distanceThresh (in units of the baseline, |t| = 1) in both views. OpenCV's other overloads use
distanceThresh = 50; the module's do not cut at all. This form costs a 4 x 4 SVD per point and
candidate pose, as OpenCV's does.

@param distanceThresh > 0; +inf keeps OpenCV's DLT test without a cut. NaN or <= 0 raise
StsBadArg (OpenCV then counts no point).
@param triangulatedPoints output 4 x N CV_64F homogeneous points of the chosen pose, in the first
camera's frame (X2 = R X1 + t): each column the DLT solution of unit norm, with W >= 0 (OpenCV's
columns are also of unit norm, with the sign its SVD gives). When E cannot be decomposed (the zero
matrix) the call returns 0 with R = I, t = 0 and triangulatedPoints empty.
@sa cv::recoverPose
*/
CV_EXPORTS_W int recoverPoseIter(InputArray E, InputArray points1, InputArray points2,
                                 InputArray cameraMatrix, OutputArray R, OutputArray t,
                                 double distanceThresh, InputOutputArray mask = noArray(),
                                 OutputArray triangulatedPoints = noArray());

/** @overload Estimates E from two cameras with distortion, then recovers the pose.

As `cv::recoverPose`: the points are undistorted with their own camera (and read as
cv::undistortPoints reads them: CV_32F or CV_64F, N x 2, 2 x N, N x 1 or 1 x N, continuous), E is
estimated as by the two-camera findEssentialMatIter() with the same method, prob and threshold,
its inlier mask written into `mask` (if given), and the pose recovered from the points that mask
marks (all points when no mask is given). Unlike OpenCV, there is no 50-baseline cut; when no
essential matrix is found the call returns 0 with E empty, R = I and t = 0 (OpenCV asserts); with
exactly five points, of the several solutions the one with the most points in front is kept
(OpenCV asserts).

@param points1 points of the first image.
@param points2 points of the second image.
@param cameraMatrix1 camera matrix of the first view.
@param distCoeffs1 its distortion coefficients (4, 5, 8, 12 or 14, or empty).
@param cameraMatrix2 camera matrix of the second view.
@param distCoeffs2 its distortion coefficients.
@param E output 3 x 3 CV_64F essential matrix.
@param R output rotation, as above.
@param t output unit translation, as above.
@param method RANSAC, LMEDS or a USAC flag, as findEssentialMatIter().
@param prob confidence in (0, 1).
@param threshold inlier threshold in pixels (converted with the mean focal length of the cameras).
@param mask output N x 1 CV_8U: 1 at the inliers of E in front of both cameras, 0 elsewhere.
@return the number of (masked) points in front of both cameras.
@sa cv::recoverPose
*/
CV_EXPORTS_W int recoverPoseIter(InputArray points1, InputArray points2, InputArray cameraMatrix1,
                                 InputArray distCoeffs1, InputArray cameraMatrix2,
                                 InputArray distCoeffs2, OutputArray E, OutputArray R,
                                 OutputArray t, int method = cv::RANSAC, double prob = 0.999,
                                 double threshold = 1.0, InputOutputArray mask = noArray());

/** @overload The module's original name for recoverPoseIter(E, points1, points2, cameraMatrix, R,
t, mask). Call it qualified (`cv::essential::recoverPose(...)`): an unqualified call under `using
namespace cv::essential` is ambiguous with cv::recoverPose. */
CV_EXPORTS_W int recoverPose(InputArray E, InputArray points1, InputArray points2,
                             InputArray cameraMatrix, OutputArray R, OutputArray t,
                             InputOutputArray mask = noArray());

/** @overload The original name for the focal form of recoverPoseIter(). */
CV_EXPORTS_W int recoverPose(InputArray E, InputArray points1, InputArray points2, OutputArray R,
                             OutputArray t, double focal = 1.0, Point2d pp = Point2d(0, 0),
                             InputOutputArray mask = noArray());

/** @overload The original name for the distanceThresh form of recoverPoseIter(). */
CV_EXPORTS_W int recoverPose(InputArray E, InputArray points1, InputArray points2,
                             InputArray cameraMatrix, OutputArray R, OutputArray t,
                             double distanceThresh, InputOutputArray mask = noArray(),
                             OutputArray triangulatedPoints = noArray());

/** @overload The original name for the two-camera form of recoverPoseIter(). */
CV_EXPORTS_W int recoverPose(InputArray points1, InputArray points2, InputArray cameraMatrix1,
                             InputArray distCoeffs1, InputArray cameraMatrix2,
                             InputArray distCoeffs2, OutputArray E, OutputArray R, OutputArray t,
                             int method = cv::RANSAC, double prob = 0.999, double threshold = 1.0,
                             InputOutputArray mask = noArray());

//! @}

} // namespace essential
} // namespace cv

#endif // OPENCV_ESSENTIAL_HPP
