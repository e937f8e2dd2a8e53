// SPDX-License-Identifier: MIT
// The main() of a fuzz target in the default build (GCC, CI): runs LLVMFuzzerTestOneInput once
// on every file named on the command line, and on every file inside each directory named (not
// recursive, in name order, so a run is repeatable). Prints one line per file. The target
// decides what a failure is: it returns normally for input it handled and lets anything else
// escape; an escaping exception is reported here and the replay exits 1 after the rest have
// run. A crash or a sanitizer report ends the process, which ctest reports as a failure too.
// With -DSSAM_FUZZ=ON libFuzzer provides main() instead (tests/fuzz/CMakeLists.txt).
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

std::vector<std::filesystem::path> inputsOf(const std::vector<std::filesystem::path>& arguments) {
    std::vector<std::filesystem::path> files;
    for (const auto& argument : arguments) {
        if (!std::filesystem::is_directory(argument)) {
            files.push_back(argument);
            continue;
        }
        std::vector<std::filesystem::path> inside;
        for (const auto& entry : std::filesystem::directory_iterator(argument))
            if (entry.is_regular_file()) inside.push_back(entry.path());
        std::sort(inside.begin(), inside.end());
        files.insert(files.end(), inside.begin(), inside.end());
    }
    return files;
}

bool readFile(const std::filesystem::path& path, std::vector<std::uint8_t>& bytes) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return !in.bad();
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: " << argv[0] << " FILE_OR_DIRECTORY...\n"
                  << "Runs the fuzz target once on every file (the seed corpus replay of tests/fuzz).\n";
        return 2;
    }
    const std::vector<std::filesystem::path> files = inputsOf({argv + 1, argv + argc});
    if (files.empty()) {
        std::cerr << "no input files in the arguments given\n";
        return 2;
    }
    int failed = 0;
    for (const auto& file : files) {
        std::vector<std::uint8_t> bytes;
        if (!readFile(file, bytes)) {
            std::cout << "FAIL " << file.string() << ": cannot read the file\n";
            ++failed;
            continue;
        }
        const auto start = std::chrono::steady_clock::now();
        try {
            LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
            const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
            std::cout << "ok   " << file.string() << " (" << bytes.size() << " bytes, " << took.count() << " ms)\n";
        } catch (const std::exception& e) {
            std::cout << "FAIL " << file.string() << ": escaped the target: " << e.what() << "\n";
            ++failed;
        } catch (...) {
            std::cout << "FAIL " << file.string() << ": escaped the target: an exception of unknown type\n";
            ++failed;
        }
    }
    std::cout << files.size() - static_cast<std::size_t>(failed) << " of " << files.size() << " inputs passed\n";
    return failed == 0 ? 0 : 1;
}
