// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// The front-end options both command-line programs take, with the same names, values and help:
// --descriptor, --matcher, --keep-fraction; and the detector options essential_pair takes on top:
// --detector, --sift-features, --ratio. Header-only; nothing here is part of the library.

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
        // SIFT's descriptor is not one of these: it comes with SIFT's keypoints (--detector sift).
        if (!parseDescriptor(value, options.descriptor) || options.descriptor == Descriptor::Sift)
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

/** The detector options (essential_pair): --detector, --sift-features, --ratio. */
inline std::vector<OptionSpec> detectorOptionSpecs()
{
    return {{"detector", true, ""}, {"sift-features", true, ""}, {"ratio", true, ""}};
}

/** Applies the option to `options` and returns true; false when it is not a detector option.
Fails (exit status 2) on a bad value; finishDetectorOptions() checks the combinations. */
inline bool applyDetectorOption(const GivenOption& option, FrontEndOptions& options)
{
    const std::string& value = option.value;
    if (option.name == "detector") {
        if (!parseDetector(value, options.detector))
            fail("--detector must be fast or sift, not '" + value + "'", 2);
    } else if (option.name == "sift-features") {
        long long count = 0;
        if (!parseInt(value, count) || count < 0 || count > 10000000)
            fail("--sift-features must be an integer in [0, 10000000] (0: all), not '" + value +
                     "'",
                 2);
        options.siftFeatures = static_cast<int>(count);
    } else if (option.name == "ratio") {
        if (!parseDouble(value, options.ratio) || !(options.ratio > 0.0 && options.ratio <= 1.0))
            fail("--ratio must be in (0, 1], not '" + value + "'", 2);
    } else {
        return false;
    }
    return true;
}

/** After all the options (`given`, as parsed) are applied: fails (exit status 2) on --sift-features
or --ratio without --detector sift, and on --descriptor with it (SIFT has its own descriptor). With
--detector sift the descriptor is SIFT's, and the keep fraction 1 (every match that passes the ratio
test) unless --keep-fraction was given. */
inline void finishDetectorOptions(const std::vector<GivenOption>& given, FrontEndOptions& options)
{
    const auto wasGiven = [&](const char* name) {
        for (const GivenOption& option : given)
            if (option.name == name) return true;
        return false;
    };
    if (options.detector == Detector::Sift) {
        if (wasGiven("descriptor"))
            fail("--descriptor goes with --detector fast (the FAST corners' descriptor); "
                 "--detector sift computes SIFT's own",
                 2);
        options.descriptor = Descriptor::Sift;
        if (!wasGiven("keep-fraction")) options.keepFraction = 1.0;
    } else {
        for (const char* name : {"sift-features", "ratio"})
            if (wasGiven(name)) fail(std::string("--") + name + " needs --detector sift", 2);
    }
}

/** Help lines of the detector options. */
inline std::string detectorHelp()
{
    return "  --detector D           fast (default: FAST-9 corners on an image pyramid, described\n"
           "                         by --descriptor) or sift (OpenCV's SIFT with its own\n"
           "                         descriptor, matched with Lowe's ratio test; --keep-fraction\n"
           "                         then defaults to 1, every match that passes the test)\n"
           "  --sift-features N      with sift: the N strongest keypoints per image, 0 for all\n"
           "                         (default 4000)\n"
           "  --ratio R              with sift: a match is kept when its distance is below R\n"
           "                         times the second nearest's, R in (0, 1] (default 0.8)\n";
}

} // namespace essential_samples

#endif
