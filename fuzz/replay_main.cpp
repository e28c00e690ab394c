// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// A main() for the fuzz target without libFuzzer: runs LLVMFuzzerTestOneInput once on each file
// given (or each file in each directory given), so that the kept inputs in fuzz/regression/ are
// replayed by ctest with any compiler. The target aborts on a broken contract.

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

bool runFile(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "essential_fuzz_replay: cannot open %s\n", path.string().c_str());
        return false;
    }
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    int files = 0;
    for (int a = 1; a < argc; ++a) {
        const std::filesystem::path arg(argv[a]);
        if (std::filesystem::is_directory(arg)) {
            for (const auto& entry : std::filesystem::directory_iterator(arg)) {
                if (!entry.is_regular_file()) continue;
                if (!runFile(entry.path())) return 1;
                ++files;
            }
        } else {
            if (!runFile(arg)) return 1;
            ++files;
        }
    }
    if (files == 0) {
        std::fprintf(stderr, "essential_fuzz_replay: no input files\n");
        return 1;
    }
    std::printf("essential_fuzz_replay: %d inputs replayed, contract kept\n", files);
    return 0;
}
