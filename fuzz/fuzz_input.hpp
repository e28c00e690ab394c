// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Reads a fuzzer's bytes as choices and numbers. Every read succeeds: past the end it returns
// zeros, so that any byte string, including an empty one, is a valid input.

#ifndef OPENCV_ESSENTIAL_FUZZ_INPUT_HPP
#define OPENCV_ESSENTIAL_FUZZ_INPUT_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

namespace essential_fuzz {

class FuzzInput
{
public:
    FuzzInput(const uint8_t* data, size_t size) : data_(data), size_(size) {}

    /** A choice in [0, k) from the next byte or two (k >= 1). */
    int pick(int k)
    {
        if (k <= 1) return 0;
        const uint32_t raw = k <= 256 ? byte()
                                      : (uint32_t(byte()) << 24 | uint32_t(byte()) << 16 |
                                         uint32_t(byte()) << 8 | byte());
        return static_cast<int>(raw % static_cast<uint32_t>(k));
    }

    /** A number in [0, 1) from two bytes. */
    double unit() { return (uint32_t(byte()) << 8 | byte()) / 65536.0; }

    /** Any double, specials included: NaN, +-infinity, zero, denormals, 1e8, 1e300, or raw bits. */
    double anyDouble()
    {
        static const double specials[] = {std::numeric_limits<double>::quiet_NaN(),
                                          std::numeric_limits<double>::infinity(),
                                          -std::numeric_limits<double>::infinity(),
                                          0.0,
                                          -0.0,
                                          std::numeric_limits<double>::denorm_min(),
                                          1e8,
                                          -1e8,
                                          1e300,
                                          1e-300,
                                          -1.0,
                                          1.0};
        const int kind = pick(16);
        if (kind < 12) return specials[kind];
        uint64_t bits = 0;
        for (int i = 0; i < 8; ++i)
            bits = bits << 8 | byte();
        double d;
        std::memcpy(&d, &bits, sizeof d);
        return d;
    }

    /** A pixel coordinate: mostly in [0, 1024), rarely any double (1 in 256: an input has dozens of
    coordinates, and one bad one rejects it), sometimes the previous value again. */
    double coordinate()
    {
        const int kind = pick(256);
        if (kind == 0) return anyDouble();
        if (kind <= 8) return last_;
        last_ = 1024.0 * unit();
        return last_;
    }

private:
    uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }

    const uint8_t* data_;
    size_t size_;
    size_t pos_ = 0;
    double last_ = 0.0;
};

} // namespace essential_fuzz

#endif
