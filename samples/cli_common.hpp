// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// Helpers the command-line sample programs (essential_pair, essential_sequence) share: the error
// they report and exit with (and main()'s handling of it), "--name value" / "--name=value" options,
// strict parsing of numbers in options and text files, timing, and the angles between rotations and
// directions. Header-only; nothing here is part of the opencv_essential library.

#ifndef ESSENTIAL_SAMPLES_CLI_COMMON_HPP
#define ESSENTIAL_SAMPLES_CLI_COMMON_HPP

#include <opencv2/core.hpp>
#include <opencv2/essential.hpp>

#include "named_values.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

namespace essential_samples {

/** A usage or input error: main() prints its message as one line and exits with `code`. */
struct Failure
{
    std::string message;
    int code;
};

/** Throws Failure{message, code}. */
[[noreturn]] inline void fail(const std::string& message, int code = 1)
{
    throw Failure{message, code};
}

/** Runs `run` (the program's main) and turns what it throws into one line on stderr, prefixed by
"<program>: ", and the exit status: Failure, its message and code; cv::Exception, its err and
function, 1; std::exception, its what(), 1. */
inline int runCli(const char* program, int (*run)(int, char**), int argc, char** argv)
{
    try {
        return run(argc, argv);
    } catch (const Failure& failure) {
        std::string message = failure.message; // one line, whatever a file's name holds
        std::replace(message.begin(), message.end(), '\n', ' ');
        std::cerr << program << ": " << message << "\n";
        return failure.code;
    } catch (const cv::Exception& e) {
        std::cerr << program << ": " << e.err << " (in " << e.func << ")\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << program << ": " << e.what() << "\n";
        return 1;
    }
}

/** Whether the command-line argument `arg` is an option "--name...": "--" alone and anything not
starting with "--" are positional arguments. */
inline bool isOption(const std::string& arg)
{
    return arg.rfind("--", 0) == 0 && arg.size() != 2;
}

/** The value of the option arg = argv[i]: "--name=value" (arg becomes "--name"), or "--name" and
the value as the next argument (i then moves to it); fail(..., 2) when there is no next argument. */
inline std::string optionValue(std::string& arg, int& i, int argc, char** argv)
{
    const size_t equals = arg.find('=');
    if (equals != std::string::npos) {
        std::string value = arg.substr(equals + 1);
        arg = arg.substr(0, equals);
        return value;
    }
    if (i + 1 < argc) return argv[++i];
    fail("option " + arg + " needs a value (see --help)", 2);
}

/** Milliseconds since `start`. */
inline double elapsedMs(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

/** The whole of `text` as a finite number; false (value unspecified) otherwise. */
inline bool parseDouble(const std::string& text, double& value)
{
    if (text.empty()) return false;
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    value = std::strtod(begin, &end);
    return errno == 0 && end != begin && *end == '\0' && std::isfinite(value);
}

/** The whole of `text` as a decimal integer in range; false (value unspecified) otherwise. */
inline bool parseInt(const std::string& text, long long& value)
{
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    value = std::strtoll(text.c_str(), &end, 10);
    return errno == 0 && *end == '\0';
}

/** A seed: the whole of `text` as a non-negative integer, decimal or 0x hex (base 0 of strtoull);
false (value unchanged) otherwise. */
inline bool parseSeed(const std::string& text, std::uint64_t& value)
{
    char* end = nullptr;
    errno = 0;
    const unsigned long long seed = std::strtoull(text.c_str(), &end, 0);
    if (text.empty() || text[0] == '-' || errno != 0 || *end != '\0') return false;
    value = static_cast<std::uint64_t>(seed);
    return true;
}

/** "a,b,,c" -> {"a", "b", "", "c"}; a trailing separator gives a trailing empty part. */
inline std::vector<std::string> split(const std::string& text, char separator)
{
    std::vector<std::string> parts;
    std::string part;
    std::istringstream stream(text);
    while (std::getline(stream, part, separator))
        parts.push_back(part);
    if (!text.empty() && text.back() == separator) parts.emplace_back();
    return parts;
}

/** The value of an option listing solvers ("gn,nister,gn+nister"): each name must be one
createSolver() accepts; fail(option + ": " + reason, 2) otherwise. */
inline std::vector<std::string> parseSolverList(const std::string& option, const std::string& value)
{
    const std::vector<std::string> solvers = split(value, ',');
    for (const std::string& solver : solvers) {
        try {
            cv::essential::createSolver(solver);
        } catch (const cv::Exception& e) {
            fail(option + ": " + e.err, 2);
        }
    }
    return solvers;
}

/** The numbers of a text file, one row per line. Blank lines and lines starting with '#' are
skipped; every other whitespace-separated token must be a finite number, else
fail(malformed + ": '" + token + "' is not a number"). */
inline std::vector<std::vector<double>> readNumberRows(std::istream& in,
                                                       const std::string& malformed)
{
    std::vector<std::vector<double>> rows;
    std::string line;
    while (std::getline(in, line)) {
        const size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        std::istringstream stream(line);
        std::vector<double> row;
        std::string token;
        while (stream >> token) {
            double value;
            if (!parseDouble(token, value)) fail(malformed + ": '" + token + "' is not a number");
            row.push_back(value);
        }
        rows.push_back(row);
    }
    return rows;
}

/** The samplers of EssentialParams::sampler by their command-line names. */
inline constexpr NamedValue<cv::SamplingMethod> kSamplerNames[] = {
    {"uniform", cv::SAMPLING_UNIFORM},
    {"prosac", cv::SAMPLING_PROSAC},
    {"napsac", cv::SAMPLING_NAPSAC},
    {"pnapsac", cv::SAMPLING_PROGRESSIVE_NAPSAC}};

/** "uniform", "prosac", "napsac" or "pnapsac" as the cv::SamplingMethod the module takes in
EssentialParams::sampler; false (value unchanged) for anything else. */
inline bool parseSampler(const std::string& name, cv::SamplingMethod& sampler)
{
    return parseNamedValue(kSamplerNames, name, sampler);
}

/** The name parseSampler() reads for a sampler. */
inline const char* samplerName(cv::SamplingMethod sampler)
{
    return nameOfValue(kSamplerNames, sampler, "uniform");
}

/** Indices of the matches sorted by descriptor distance, best (smallest) first, ties in input
order: the order PROSAC needs. */
inline std::vector<int> orderByDistance(const std::vector<float>& distances)
{
    std::vector<int> order(distances.size());
    for (size_t i = 0; i < order.size(); ++i)
        order[i] = static_cast<int>(i);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return distances[a] < distances[b]; });
    return order;
}

/** `values` taken in `order`. */
template <typename T>
std::vector<T> permuted(const std::vector<T>& values, const std::vector<int>& order)
{
    std::vector<T> out;
    out.reserve(order.size());
    for (int i : order)
        out.push_back(values[static_cast<size_t>(i)]);
    return out;
}

/** Angle in degrees of the rotation Ra^T Rb. */
inline double rotationAngleDeg(const cv::Matx33d& Ra, const cv::Matx33d& Rb)
{
    const cv::Matx33d D = Ra.t() * Rb;
    const double c = std::max(-1.0, std::min(1.0, (cv::trace(D) - 1.0) / 2.0));
    return std::acos(c) * 180.0 / CV_PI;
}

/** Angle in degrees between the directions a and b; `zeroAngle` when either is the zero vector. */
inline double directionAngleDeg(const cv::Vec3d& a, const cv::Vec3d& b, double zeroAngle)
{
    const double na = cv::norm(a), nb = cv::norm(b);
    if (na == 0.0 || nb == 0.0) return zeroAngle;
    const double c = std::max(-1.0, std::min(1.0, a.dot(b) / (na * nb)));
    return std::acos(c) * 180.0 / CV_PI;
}

} // namespace essential_samples

#endif
