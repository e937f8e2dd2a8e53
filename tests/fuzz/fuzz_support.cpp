// SPDX-License-Identifier: MIT
#include "fuzz_support.hpp"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <system_error>

#include "engine/core/log.hpp"
#include "scratch_dir.hpp"

namespace ssam::fuzz {

// Sanitizer defaults, read at start-up by ASan/LSan (make fuzz, the asan preset); unused in
// other builds. OpenImageIO 2.4's PNG reader leaks its error text when a file ends early: the
// read callback stores it in a std::string, then libpng longjmps past the destructor (the
// same leak tests/unit/assets suppresses). It is inside the library and cannot be prevented
// from outside, so it is suppressed by name; names match only with full stacks, hence the
// slow unwinder (its cost is not measurable at these execution rates).
extern "C" const char* __asan_default_options() { return "fast_unwind_on_malloc=0"; }
extern "C" const char* __lsan_default_suppressions() {
    return "leak:OpenImageIO_v2_4::PNGInput::PngReadCallback\n"
           "leak:OpenImageIO_v2_4::ImageInput::geterror\n";
}

void requireMessageNames(const std::exception& error, std::string_view prefix) {
    const std::string_view message = error.what();
    static const bool verbose = [] {
        const char* flag = std::getenv("SSAM_FUZZ_VERBOSE");
        return flag && std::string_view(flag) == "1";
    }();
    if (verbose) std::cerr << "refused: " << message << "\n";
    require(message.substr(0, prefix.size()) == prefix && message.size() > prefix.size() + 2,
            "engine::Error does not name where (expected it to start with '" + std::string(prefix) +
                "' and say what was wrong): '" + std::string(message) + "'");
}

const std::filesystem::path& scratchDir(std::string_view target) {
    // One target per process.
    static const ssam::testing::ScratchDir dir("ssam_fuzz_" + std::string(target) + "_" + std::to_string(::getpid()));
    return dir.path();
}

void writeInput(const std::filesystem::path& path, const std::uint8_t* data, std::size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (size > 0) out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) throw std::runtime_error("fuzz: cannot write the input to '" + path.string() + "'");
}

void silenceWarnings() { engine::log::setLevel(engine::log::Level::Error); }

}  // namespace ssam::fuzz
