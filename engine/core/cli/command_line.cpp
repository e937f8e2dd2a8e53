// SPDX-License-Identifier: MIT
#include "engine/cli/command_line.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>

#include "engine/core/usage_error.hpp"

namespace engine::cli {

void printError(std::string_view tool, std::string_view message) {
    while (!message.empty() && (message.back() == '\n' || message.back() == '\r')) message.remove_suffix(1);
    std::string out;
    std::size_t start = 0;
    do {
        const std::size_t end = std::min(message.find('\n', start), message.size());
        out += std::string(tool) + ": error: " + std::string(message.substr(start, end - start)) + "\n";
        start = end + 1;
    } while (start < message.size());
    std::fputs(out.c_str(), stderr);  // one write: whole lines even beside other output
}

std::string contractHelpFooter() {
    return "Exit status: 0 done, 1 the work failed, 2 usage error (unknown flag, bad value, a combination "
           "that means nothing); messages are '<tool>: error: ...' on stderr. Every output is checked "
           "before the work starts and written whole or not at all (game/README.md, \"Command-line contract\").";
}

int runTool(std::string_view tool, CLI::App& app, int argc, char** argv, const std::function<int()>& work) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help and --help-all are "errors" with exit code 0: CLI11 prints the help.
        if (e.get_exit_code() == 0) return app.exit(e) == 0 ? kExitSuccess : kExitFailure;
        printError(tool, std::string(e.what()) + " (see --help)");
        return kExitUsage;
    }
    try {
        return work();
    } catch (const UsageError& e) {
        printError(tool, e.what());
        return kExitUsage;
    } catch (const std::exception& e) {
        printError(tool, e.what());
        return kExitFailure;
    }
}

}  // namespace engine::cli
