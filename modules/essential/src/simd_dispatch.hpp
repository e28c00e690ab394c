// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Runtime dispatch of the hot loops to an AVX2 build of themselves. The default build targets any
// x86-64 (SSE2: two doubles per vector); on a CPU of the x86-64-v3 level (AVX2 with FMA, every
// x86-64 CPU since 2013-2015) the loader picks the clone of each marked function once, through an
// ifunc. The clone contracts a * b + c into one fused multiply-add, which rounds once instead of
// twice: the loops are written so that vector width does not change the order of any sum, so the
// two builds differ only where a multiply-add was fused, in the last bits (test_sampson and
// test_solvers bound the difference), and on one machine every result is the same run after run.
// Fusing took a tenth off the drop-in's instructions and 6-11% off its time (docs/PERFORMANCE.md
// section 11). A build with -march=native (ESSENTIAL_NATIVE) or without GCC's ifunc support on
// x86-64 Linux compiles the functions once, as they are.

#ifndef OPENCV_ESSENTIAL_SIMD_DISPATCH_HPP
#define OPENCV_ESSENTIAL_SIMD_DISPATCH_HPP

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) &&       \
    !defined(__AVX2__) && !defined(ESSENTIAL_NO_CLONES)
/** The clone's target: AVX2 and FMA (and the level's other extensions), not AVX-512. */
#define ESSENTIAL_CLONE_TARGET "arch=x86-64-v3"
#define ESSENTIAL_SIMD_CLONES __attribute__((target_clones(ESSENTIAL_CLONE_TARGET, "default")))
#define ESSENTIAL_HAS_CLONES 1
#else
#define ESSENTIAL_SIMD_CLONES
#define ESSENTIAL_HAS_CLONES 0
#endif

/** For a loop in a header that a marked function calls: GCC does not inline a function into a
caller with a different target unless told to, and the loop would then run its default build from
both clones. ESSENTIAL_LAMBDA_INLINE_INTO_CLONES is the same for a lambda, after its parameters. */
#if defined(__GNUC__)
#define ESSENTIAL_INLINE_INTO_CLONES inline __attribute__((always_inline))
#define ESSENTIAL_LAMBDA_INLINE_INTO_CLONES __attribute__((always_inline))
#else
#define ESSENTIAL_INLINE_INTO_CLONES inline
#define ESSENTIAL_LAMBDA_INLINE_INTO_CLONES
#endif

/** For a marked function that calls much header code not marked for inlining (Eigen's small
fixed-size expressions): every call in it is inlined where the callee's body is visible. Without it
GCC left dozens of Eigen's 3-vector and comma-initialiser calls in the clone of the iterative
solvers (solvers/iterative_minimal_solver.cpp), which then ran their default build. */
#if defined(__GNUC__)
#define ESSENTIAL_FLATTEN __attribute__((flatten))
#else
#define ESSENTIAL_FLATTEN
#endif

#endif
