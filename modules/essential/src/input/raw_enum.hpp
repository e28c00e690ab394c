// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#ifndef OPENCV_ESSENTIAL_INPUT_RAW_ENUM_HPP
#define OPENCV_ESSENTIAL_INPUT_RAW_ENUM_HPP

#include <cstring>

namespace cv {
namespace essential {

/** An enum field (of UsacParams or EssentialParams) as the int it holds. A value outside the
enumeration (which a caller can make only by a cast) must be rejected with a message, but loading it
as the enum type is undefined behaviour (UBSan's -fsanitize=enum reports it), so the bytes are read
as an int. */
template <typename Enum> inline int rawEnum(const Enum& field)
{
    static_assert(sizeof(Enum) == sizeof(int), "the enums read here are int-sized");
    int value;
    std::memcpy(&value, &field, sizeof value);
    return value;
}

} // namespace essential
} // namespace cv

#endif
