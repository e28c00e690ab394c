// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// Shared by the essential_colmap tests: the COLMAP database the ctest fixture colmap_make_database
// creates (skip when it is missing, with the reason), private copies of it, a file's bytes, and
// running a program.

#ifndef ESSENTIAL_TEST_COLMAP_TEST_SUPPORT_HPP
#define ESSENTIAL_TEST_COLMAP_TEST_SUPPORT_HPP

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace colmap_test {

/** Whether the colmap program is on the PATH. */
inline bool colmapInstalled()
{
    return std::system("command -v colmap > /dev/null 2>&1") == 0;
}

/** The bytes of a file (empty when it cannot be read). */
inline std::vector<char> fileBytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline bool fileExists(const std::string& path)
{
    return std::ifstream(path).good();
}

/** A private copy of the fixture's COLMAP database under the test's own name, or "" when the
fixture did not make it (the caller then GTEST_SKIPs). */
inline std::string copyOfColmapDatabase(const std::string& name)
{
    const std::string source = COLMAP_TEST_DATABASE;
    if (!fileExists(source)) return "";
    const std::string copy = std::string(COLMAP_TEST_WORK) + "/" + name + ".db";
    std::ofstream(copy, std::ios::binary) << std::ifstream(source, std::ios::binary).rdbuf();
    return copy;
}

/** The reason to give GTEST_SKIP when copyOfColmapDatabase() returned "". */
inline std::string missingDatabaseReason()
{
    return std::string("no COLMAP database at ") + COLMAP_TEST_DATABASE +
           (colmapInstalled() ? " (run the ctest entry colmap_make_database first)"
                              : " (colmap is not installed: scripts/bootstrap.sh installs it)");
}

/** Runs a shell command; its exit status, and its stdout and stderr in `output` (through the file
WORK/<name>.log: `name` must be unique among tests that may run at the same time). */
inline int runCommand(const std::string& name, const std::string& command, std::string& output)
{
    const std::string log = std::string(COLMAP_TEST_WORK) + "/" + name + ".log";
    const int status = std::system((command + " > " + log + " 2>&1").c_str());
    const std::vector<char> bytes = fileBytes(log);
    output.assign(bytes.begin(), bytes.end());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace colmap_test

#endif
