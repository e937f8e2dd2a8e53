// SPDX-License-Identifier: MIT
#pragma once
// Shared by the fuzz targets (libFuzzer, tests/README.md "Fuzzing"): what a target may accept as
// the outcome of hostile input, and a scratch directory for the loaders that take paths.
//
// The contract every target checks: bad input ends in engine::Error whose message names what
// was wrong and where; accepted input yields data that keeps the loader's promises (no NaN,
// no index out of range). Anything else (another exception type, a crash, a sanitizer
// report, a hang) is a bug.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ssam::fuzz {

// Thrown when a loader broke its contract. Not an engine::Error, so the target lets it escape
// and both libFuzzer (as a crash) and replay_main (as a failed file) report it.
class ContractViolation : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

inline void require(bool ok, const std::string& what) {
    if (!ok) throw ContractViolation(what);
}

// A refusal must say where: its message starts with `prefix` (the file or flag named) and
// goes on to say what was wrong. With SSAM_FUZZ_VERBOSE=1 in the environment the message is
// printed, to see what each seed exercises.
void requireMessageNames(const std::exception& error, std::string_view prefix);

// A directory of its own for this process under the system temp dir (fuzzers and replays run
// side by side), created on first use and removed at exit.
const std::filesystem::path& scratchDir(std::string_view target);

// Replaces `path`'s contents with the input; a target reuses one path per process.
void writeInput(const std::filesystem::path& path, const std::uint8_t* data, std::size_t size);

// Loaders log warnings for every odd file; at fuzzing rates that is most of the run time.
void silenceWarnings();

}  // namespace ssam::fuzz
