// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The command line of the experiment programs: each option is declared with the variable it sets,
// and samples/cli_parser.hpp reads argv ("--name value" or "--name=value", names spelled out). A
// value that does not parse, an unknown option or a missing value fails with one line and exit
// status 2; --help prints the usage (by default the options with their defaults) and exits 0.

#ifndef OPENCV_ESSENTIAL_BENCH_OPTIONS_HPP
#define OPENCV_ESSENTIAL_BENCH_OPTIONS_HPP

#include "cli_parser.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace essential_bench {

class Options
{
public:
    /** `usage`, when not empty, is what --help prints; otherwise the declared options with their
    values before parsing (the defaults). */
    explicit Options(std::string program, std::string usage = std::string())
        : program_(std::move(program)), usage_(std::move(usage))
    {
    }

    void add(const std::string& name, int& target)
    {
        declare(name, std::to_string(target), [&target, name](const std::string& v) {
            long long x = 0;
            if (!essential_samples::parseInt(v, x) || x < -2147483647LL || x > 2147483647LL)
                essential_samples::fail("--" + name + " must be an integer, got '" + v + "'", 2);
            target = static_cast<int>(x);
        });
    }
    void add(const std::string& name, std::uint64_t& target)
    {
        declare(name, std::to_string(target), [&target, name](const std::string& v) {
            if (!essential_samples::parseSeed(v, target))
                essential_samples::fail(
                    "--" + name + " must be an unsigned integer, got '" + v + "'", 2);
        });
    }
    void add(const std::string& name, double& target)
    {
        declare(name, number(target), [&target, name](const std::string& v) {
            if (!essential_samples::parseDouble(v, target))
                essential_samples::fail("--" + name + " must be a number, got '" + v + "'", 2);
        });
    }
    void add(const std::string& name, std::string& target)
    {
        declare(name, target, [&target](const std::string& v) { target = v; });
    }
    /** A comma-separated list of numbers. */
    void add(const std::string& name, std::vector<double>& target)
    {
        std::string shown;
        for (size_t i = 0; i < target.size(); ++i)
            shown += (i ? "," : "") + number(target[i]);
        declare(name, shown, [&target, name](const std::string& v) {
            target.clear();
            for (const std::string& part : essential_samples::split(v, ',')) {
                double x = 0;
                if (!essential_samples::parseDouble(part, x))
                    essential_samples::fail("--" + name + ": '" + part + "' is not a number", 2);
                target.push_back(x);
            }
        });
    }
    /** A comma-separated list of integers. */
    void add(const std::string& name, std::vector<int>& target)
    {
        std::string shown;
        for (size_t i = 0; i < target.size(); ++i)
            shown += (i ? "," : "") + std::to_string(target[i]);
        declare(name, shown, [&target, name](const std::string& v) {
            target.clear();
            for (const std::string& part : essential_samples::split(v, ',')) {
                long long x = 0;
                if (!essential_samples::parseInt(part, x) || x < -2147483647LL || x > 2147483647LL)
                    essential_samples::fail("--" + name + ": '" + part + "' is not an integer", 2);
                target.push_back(static_cast<int>(x));
            }
        });
    }
    /** A list separated by `separator` (',' unless the items hold commas). */
    void add(const std::string& name, std::vector<std::string>& target, char separator = ',')
    {
        std::string shown;
        for (size_t i = 0; i < target.size(); ++i)
            shown += (i ? std::string(1, separator) : std::string()) + target[i];
        declare(name, shown, [&target, separator](const std::string& v) {
            target = essential_samples::split(v, separator);
        });
    }
    /** An option without a value. */
    void flag(const std::string& name, bool& target)
    {
        specs_.push_back({name, false, ""});
        shown_.push_back("");
        setters_.push_back([&target](const std::string&) { target = true; });
    }
    /** An option whose value `handler` reads (and checks). */
    void custom(const std::string& name, const std::string& shown,
                std::function<void(const std::string&)> handler)
    {
        declare(name, shown, std::move(handler));
    }

    /** Reads argv; exits after --help (0) or on an error (2, one line "<program>: message" on
    stderr). Positional arguments are refused. */
    void parse(int argc, char** argv)
    {
        try {
            const essential_samples::CommandLine line =
                essential_samples::parseCommandLine(program_.c_str(), argc, argv, specs_);
            if (line.help) {
                std::fputs(usage().c_str(), stdout);
                std::exit(0);
            }
            if (!line.positional.empty())
                essential_samples::fail(
                    "unexpected argument '" + line.positional.front() + "' (see --help)", 2);
            for (const essential_samples::GivenOption& given : line.options)
                for (size_t i = 0; i < specs_.size(); ++i)
                    if (specs_[i].name == given.name) setters_[i](given.value);
        } catch (const essential_samples::Failure& failure) {
            std::fprintf(stderr, "%s: %s\n", program_.c_str(), failure.message.c_str());
            std::exit(failure.code);
        }
    }

    std::string usage() const
    {
        if (!usage_.empty()) return usage_;
        std::string text = "usage: " + program_ + " [options]; each option with its default:\n";
        for (size_t i = 0; i < specs_.size(); ++i)
            text += "  --" + specs_[i].name + (specs_[i].hasValue ? " " + shown_[i] : "") + "\n";
        return text;
    }

private:
    static std::string number(double x)
    {
        std::ostringstream s;
        s << x;
        return s.str();
    }
    void declare(const std::string& name, const std::string& shown,
                 std::function<void(const std::string&)> setter)
    {
        specs_.push_back({name, true, ""});
        shown_.push_back(shown);
        setters_.push_back(std::move(setter));
    }

    std::string program_, usage_;
    std::vector<essential_samples::OptionSpec> specs_;
    std::vector<std::string> shown_;
    std::vector<std::function<void(const std::string&)>> setters_;
};

} // namespace essential_bench

#endif
