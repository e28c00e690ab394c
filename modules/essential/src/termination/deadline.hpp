// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#ifndef OPENCV_ESSENTIAL_TERMINATION_DEADLINE_HPP
#define OPENCV_ESSENTIAL_TERMINATION_DEADLINE_HPP

#include <chrono>
#include <cmath>

namespace cv {
namespace essential {
namespace termination {

/** A point in time after which a search returns what it has; inactive (never passed) by default.
Reading the clock costs more than checking a point, so loops read it every few iterations, not
per point (docs/TUNING.md, "Deadline checks"). */
struct Deadline
{
    typedef std::chrono::steady_clock Clock;
    bool active = false;
    Clock::time_point end;

    /** Active, ending `ms` from now (already passed when ms <= 0 or NaN). A deadline beyond the
    clock's range (about 292 years of nanoseconds from the clock's epoch; any `ms` from about
    9e12, including +inf) saturates at the largest time point, which is never passed: converting
    such a duration to the clock's 64-bit count would be undefined behaviour. */
    static Deadline after(double ms)
    {
        Deadline d;
        d.active = true;
        const Clock::time_point now = Clock::now();
        if (!(ms > 0)) {
            d.end = now;
            return d;
        }
        typedef std::chrono::duration<double, std::milli> Millis;
        const double left =
            std::chrono::duration_cast<Millis>(Clock::time_point::max() - now).count();
        // Compare in double before converting: ms < left guarantees the cast below fits (the
        // double nearest to `left` may round up, hence the margin of one part in 1e9).
        if (ms < left * (1.0 - 1e-9))
            d.end = now + std::chrono::duration_cast<Clock::duration>(Millis(ms));
        else
            d.end = Clock::time_point::max();
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

} // namespace termination
} // namespace essential
} // namespace cv

#endif
