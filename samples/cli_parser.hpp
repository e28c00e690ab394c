// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// The command line of the sample programs, read by POSIX/GNU getopt_long: "--name value" and
// "--name=value", options and positional arguments in any order, "--" ends the options. On top of
// getopt_long: names must be spelled out (getopt_long would take any unique prefix, so that a typo
// such as --budget for --budget-ms passed silently), every error is one line (Failure, exit status
// 2), and deprecated spellings are accepted with a warning. cv::CommandLineParser was the other
// candidate: it reads only "--name=value" (so "--camera-file F" would make F a positional
// argument) and ignores unknown options. Header-only; nothing here is part of the library.

#ifndef ESSENTIAL_SAMPLES_CLI_PARSER_HPP
#define ESSENTIAL_SAMPLES_CLI_PARSER_HPP

#include "cli_common.hpp"

#include <getopt.h>

#include <iostream>
#include <string>
#include <vector>

namespace essential_samples {

/** A long option: its name without "--", whether it takes a value, and for a deprecated spelling
the name that replaces it. */
struct OptionSpec
{
    std::string name;
    bool hasValue;
    std::string replacedBy;
};

/** One option as given, under its current name (a deprecated spelling is renamed). */
struct GivenOption
{
    std::string name;
    std::string value;
};

/** The command line: options in the order given, positional arguments, and whether -h or --help
was given (then nothing else is checked). */
struct CommandLine
{
    std::vector<GivenOption> options;
    std::vector<std::string> positional;
    bool help = false;
};

/** The option name of a command-line token: "--name=value" -> "name", "--name" -> "name". */
inline std::string tokenName(const std::string& token)
{
    const std::string name = token.rfind("--", 0) == 0 ? token.substr(2) : token;
    return name.substr(0, name.find('='));
}

/** Parses argv against `specs` (plus -h and --help). Fails with exit status 2 and one line on an
unknown, abbreviated or ambiguous option, a missing value, or a value given to an option that takes
none. A deprecated spelling prints "<program>: warning: --old is deprecated; use --new" on stderr.
*/
inline CommandLine parseCommandLine(const char* program, int argc, char** argv,
                                    const std::vector<OptionSpec>& specs)
{
    const int helpIndex = static_cast<int>(specs.size());
    std::vector<option> table;
    for (size_t i = 0; i < specs.size(); ++i)
        table.push_back(option{specs[i].name.c_str(),
                               specs[i].hasValue ? required_argument : no_argument, nullptr,
                               1000 + static_cast<int>(i)});
    table.push_back(option{"help", no_argument, nullptr, 1000 + helpIndex});
    table.push_back(option{nullptr, 0, nullptr, 0});

    const auto findSpec = [&](const std::string& name) -> const OptionSpec* {
        for (const OptionSpec& spec : specs)
            if (spec.name == name) return &spec;
        return nullptr;
    };

    CommandLine line;
    opterr = 0; // the messages below, one line each, instead of getopt's own
    optind = 1;
    for (;;) {
        const int c = getopt_long(argc, argv, ":h", table.data(), nullptr);
        if (c == -1) break;
        if (c == 'h') {
            line.help = true;
            return line;
        }
        if (c == '?') {
            // glibc sets optopt to the option's value for a long option given a value it does not
            // take, to the character for an unknown short option, to 0 for an unknown long one.
            if (optopt >= 1000 && optopt - 1000 < helpIndex)
                fail("option --" + specs[static_cast<size_t>(optopt - 1000)].name +
                         " takes no value",
                     2);
            if (optopt == 1000 + helpIndex) fail("option --help takes no value", 2);
            if (optopt > 0 && optopt < 256)
                fail(std::string("unknown option '-") + char(optopt) + "' (see --help)", 2);
            const std::string name = tokenName(argv[optind - 1]);
            const OptionSpec* spec = findSpec(name);
            if (spec && !spec->hasValue) fail("option --" + name + " takes no value", 2);
            fail("unknown option '--" + name + "' (see --help)", 2);
        }
        if (c == ':')
            fail("option --" + tokenName(argv[optind - 1]) + " needs a value (see --help)", 2);

        const int index = c - 1000;
        if (index == helpIndex) {
            line.help = true;
            return line;
        }
        const OptionSpec& spec = specs[static_cast<size_t>(index)];
        // The token as typed: the value, when separate, is the argument before optind.
        const bool separateValue = spec.hasValue && optind >= 2 && argv[optind - 1] == optarg;
        const std::string typed = tokenName(argv[optind - (separateValue ? 2 : 1)]);
        if (typed != spec.name)
            fail("unknown option '--" + typed + "' (did you mean --" + spec.name + "?)", 2);
        GivenOption given{spec.name, spec.hasValue ? std::string(optarg) : std::string()};
        if (!spec.replacedBy.empty()) {
            std::cerr << program << ": warning: --" << spec.name << " is deprecated; use --"
                      << spec.replacedBy << "\n";
            given.name = spec.replacedBy;
        }
        line.options.push_back(given);
    }
    for (int i = optind; i < argc; ++i)
        line.positional.push_back(argv[i]);
    return line;
}

} // namespace essential_samples

#endif
