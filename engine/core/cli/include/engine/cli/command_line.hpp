// SPDX-License-Identifier: MIT
#pragma once
// The command-line contract every tool of the project keeps (racer, ssam-bench,
// content-generator, ssam-idiff; game/README.md "Command-line contract"), after the GNU and
// BSD conventions:
//   exit 0  the work was done;
//   exit 1  the work failed (an input that cannot be read, an output that cannot be written,
//           a backend that cannot start);
//   exit 2  a usage error: an unknown flag, a malformed or out-of-range value, a combination
//           that means nothing -- caught by CLI11 while parsing or thrown by the tool as an
//           engine::UsageError;
// and every message is one line "<tool>: error: ..." on stderr. CLI11's own exit codes (104,
// 105, ...) never reach the shell.
//
// Kept apart from engine_core (its own target, engine::cli, not installed with ssam) so the
// installed engine does not carry a CLI11 dependency.
#include <functional>
#include <string>
#include <string_view>

namespace CLI {
class App;
}

namespace engine::cli {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

// "<tool>: error: <message>" on stderr; a message of several lines gets the prefix on each.
void printError(std::string_view tool, std::string_view message);

// The line each tool's --help ends with.
std::string contractHelpFooter();

// Parses argv into `app`, then runs `work`, keeping the contract: --help prints and exits 0;
// a CLI11 parse error exits 2; from `work`, an engine::UsageError exits 2 and any other
// exception 1, each printed with printError(). `work` returns the exit status (0, or a tool's
// own documented code).
int runTool(std::string_view tool, CLI::App& app, int argc, char** argv, const std::function<int()>& work);

}  // namespace engine::cli
