// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// The names by which the sample programs spell enum values on the command line and in their
// output (--sampler pnapsac, --matcher grid, ...): one table per enum serves both directions, so
// that what a program prints is what it reads back. Header-only; not part of the library.

#ifndef ESSENTIAL_SAMPLES_NAMED_VALUES_HPP
#define ESSENTIAL_SAMPLES_NAMED_VALUES_HPP

#include <cstddef>
#include <string>

namespace essential_samples {

template <typename Value> struct NamedValue
{
    const char* name;
    Value value;
};

/** The value `name` stands for in `table`; false (value unchanged) when it names none. */
template <typename Value, std::size_t N>
bool parseNamedValue(const NamedValue<Value> (&table)[N], const std::string& name, Value& value)
{
    for (const NamedValue<Value>& entry : table)
        if (name == entry.name) {
            value = entry.value;
            return true;
        }
    return false;
}

/** The name of `value` in `table`, or `unknown` for a value the table does not list. */
template <typename Value, std::size_t N>
const char* nameOfValue(const NamedValue<Value> (&table)[N], Value value, const char* unknown)
{
    for (const NamedValue<Value>& entry : table)
        if (entry.value == value) return entry.name;
    return unknown;
}

} // namespace essential_samples

#endif
