// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// The front-end options both command-line programs take, with the same names, values and help:
// --descriptor, --matcher, --keep-fraction. Header-only; nothing here is part of the library.

#ifndef ESSENTIAL_SAMPLES_CLI_FRONTEND_OPTIONS_HPP
#define ESSENTIAL_SAMPLES_CLI_FRONTEND_OPTIONS_HPP

#include "cli_common.hpp"
#include "cli_parser.hpp"
#include "frontend/frontend.hpp"

#include <string>
#include <vector>

namespace essential_samples {

/** The front end's settings from the command line. */
typedef FrontEndParams FrontEndOptions;

/** The front-end options and the old spelling they replace (deprecated, still accepted). */
inline std::vector<OptionSpec> frontEndOptionSpecs()
{
    return {{"descriptor", true, ""},
            {"matcher", true, ""},
            {"keep-fraction", true, ""},
            {"keep", true, "keep-fraction"}};
}

/** Applies the option to `options` and returns true; false when it is not a front-end option.
Fails (exit status 2) on a bad value. */
inline bool applyFrontEndOption(const GivenOption& option, FrontEndOptions& options)
{
    const std::string& value = option.value;
    if (option.name == "descriptor") {
        if (!parseDescriptor(value, options.descriptor))
            fail("--descriptor must be brief, orb or patch, not '" + value + "'", 2);
    } else if (option.name == "matcher") {
        if (!parseMatcher(value, options.matcher))
            fail("--matcher must be brute-force, grid or flann, not '" + value + "'", 2);
    } else if (option.name == "keep-fraction") {
        if (!parseDouble(value, options.keepFraction) ||
            !(options.keepFraction > 0.0 && options.keepFraction <= 1.0))
            fail("--keep-fraction must be a fraction in (0, 1], not '" + value + "'", 2);
    } else {
        return false;
    }
    return true;
}

/** Help lines of the front-end options. */
inline std::string frontEndHelp()
{
    return "  --descriptor D         brief (upright BRIEF, default), orb (rBRIEF) or patch\n"
           "                         (normalised 8 x 8 grey patch)\n"
           "  --matcher M            brute-force (default: every corner against every corner,\n"
           "                         exact), grid (only the strongest corners of each cell of an\n"
           "                         8 x 8 grid, at most 2048 per image, then brute force: the\n"
           "                         fast mode) or flann (approximate: LSH / k-d trees);\n"
           "                         docs/FRONTEND.md measures them\n"
           "  --keep-fraction F      fraction of the matches kept, the best by descriptor\n"
           "                         distance, in (0, 1] (default 0.2)\n";
}

} // namespace essential_samples

#endif
