// SPDX-License-Identifier: MIT
// engine/cli/command_line.hpp: the exit codes and messages every tool shares -- 0 done, 1 the
// work failed, 2 a usage error (CLI11's own codes, 104, 105, ..., never escape) -- each message
// "<tool>: error: ..." on stderr.
#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "engine/cli/command_line.hpp"
#include "engine/core/usage_error.hpp"

namespace {

struct Outcome {
    int exit = -1;
    std::string stderrText;
};

// Runs a small tool with one --count option (1..10) on `args`; `work` is its body.
Outcome runWith(
    std::vector<std::string> args, const std::function<int()>& work = [] { return 0; }) {
    CLI::App app{"tool"};
    int count = 1;
    app.add_option("--count", count)->check(CLI::Range(1, 10));
    args.insert(args.begin(), "tool");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    ::testing::internal::CaptureStderr();
    Outcome o;
    o.exit = engine::cli::runTool("tool", app, static_cast<int>(argv.size()), argv.data(), work);
    o.stderrText = ::testing::internal::GetCapturedStderr();
    return o;
}

TEST(CommandLine, ParseErrorsAreUsageErrors) {
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"--bogus"}, {"--count", "0"}, {"--count", "abc"}, {"--count"}, {"extra"}}) {
        const Outcome o = runWith(args);
        EXPECT_EQ(o.exit, engine::cli::kExitUsage) << args.front();
        EXPECT_EQ(o.stderrText.rfind("tool: error: ", 0), 0u) << o.stderrText;
    }
}

TEST(CommandLine, WorkDecidesTheRest) {
    EXPECT_EQ(runWith({"--count", "3"}).exit, 0);
    EXPECT_EQ(runWith({}, [] { return 4; }).exit, 4);  // a tool's own documented code
    const Outcome usage = runWith({}, []() -> int { throw engine::UsageError("--a means nothing without --b"); });
    EXPECT_EQ(usage.exit, engine::cli::kExitUsage);
    EXPECT_EQ(usage.stderrText, "tool: error: --a means nothing without --b\n");
    const Outcome failed = runWith({}, []() -> int { throw engine::Error("cannot write 'x.png'"); });
    EXPECT_EQ(failed.exit, engine::cli::kExitFailure);
    EXPECT_EQ(failed.stderrText, "tool: error: cannot write 'x.png'\n");
}

TEST(CommandLine, EveryLineOfAMessageIsPrefixed) {
    ::testing::internal::CaptureStderr();
    engine::cli::printError("tool", "first\nsecond\n");
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "tool: error: first\ntool: error: second\n");
}

TEST(CommandLine, HelpExitsZero) {
    ::testing::internal::CaptureStdout();
    EXPECT_EQ(runWith({"--help"}).exit, 0);
    ::testing::internal::GetCapturedStdout();
}

}  // namespace
