// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Stands in for the cv_cpu_config.h that OpenCV's build generates and does not install; the
// installed opencv2/core/cv_cpu_dispatch.h includes it when __OPENCV_BUILD is defined, as it is
// for OpenCV's test framework. No CPU feature is declared, so the framework is compiled for the
// compiler's baseline, as everything else in this project.
