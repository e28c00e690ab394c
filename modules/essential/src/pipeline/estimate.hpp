// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The pipeline every overload runs once its arguments are normalised correspondences and a
// normalised threshold (input/): search -> in-front and plane checks -> refinement -> support test
// -> mask -> report and pose. docs/ARCHITECTURE.md draws it.

#ifndef OPENCV_ESSENTIAL_PIPELINE_ESTIMATE_HPP
#define OPENCV_ESSENTIAL_PIPELINE_ESTIMATE_HPP

#include "input/mask_output.hpp"
#include "input/problem.hpp"

#include "opencv2/essential/params.hpp"

#include <opencv2/core.hpp>

namespace cv {
namespace essential {

/** E of unit Frobenius norm (empty when there is none) for `problem` under `params`, `test` being
the call's inlier test (params.threshold in normalised units, on the distance params choose); the
mask goes into the caller's array as `maskWriting` says; `report`, if not null, receives what the
call did; `start` is the call's tick count (its time budget and report times count from it). */
Mat estimate(const Problem& problem, InlierTest test, const EssentialParams& params,
             OutputArray mask, MaskWriting maskWriting, EssentialReport* report, int64 start);

} // namespace essential
} // namespace cv

#endif
