// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#ifndef OPENCV_ESSENTIAL_RANSAC_DEADLINE_HPP
#define OPENCV_ESSENTIAL_RANSAC_DEADLINE_HPP

#include <chrono>
#include <cmath>

namespace cv {
namespace essential {
namespace ransac {

/** A point in time after which a search returns what it has; inactive (never passed) by default.
Reading the steady clock costs about 20 ns, so loops check it every few iterations, not per point.
*/
struct Deadline
{
    typedef std::chrono::steady_clock Clock;
    bool active = false;
    Clock::time_point end;

    /** Active, ending `ms` from now (already passed when ms <= 0). */
    static Deadline after(double ms)
    {
        Deadline d;
        d.active = true;
        d.end = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double, std::milli>(ms));
        return d;
    }
    bool passed() const { return active && Clock::now() >= end; }
    /** Milliseconds left (negative once passed; +inf when inactive). */
    double remainingMs() const
    {
        if (!active) return HUGE_VAL;
        return std::chrono::duration<double, std::milli>(end - Clock::now()).count();
    }
};

} // namespace ransac
} // namespace essential
} // namespace cv

#endif
