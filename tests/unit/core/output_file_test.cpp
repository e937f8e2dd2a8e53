// SPDX-License-Identifier: MIT
// engine/core/output_file.hpp: outputs proven writable before work, and written whole or not
// at all -- a failure leaves neither a partial target nor a temporary file, and a set of files
// is put in place together or not at all.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "engine/core/output_file.hpp"
#include "expect_error.hpp"
#include "temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
using ssam::testing::expectError;
using ssam::testing::TempDir;

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

std::vector<std::string> entries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

TEST(OutputFile, WrittenWholeUnderItsNameWithNothingElseLeft) {
    TempDir dir("ssam_unit_core");
    write(dir / "report.csv", "old");
    engine::writeFileAtomically(dir / "report.csv", std::string_view("a,b\n1,2\n"));
    EXPECT_EQ(read(dir / "report.csv"), "a,b\n1,2\n");
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"report.csv"});
}

TEST(OutputFile, PendingFileKeepsTheExtensionAndIsRemovedUncommitted) {
    TempDir dir("ssam_unit_core");
    write(dir / "frame.png", "old frame");
    {
        engine::PendingFile file(dir / "frame.png");
        EXPECT_EQ(file.path().parent_path(), dir.path());
        EXPECT_EQ(file.path().extension(), ".png");  // writers that pick a format by it still can
        EXPECT_TRUE(fs::exists(file.path()));
        write(file.path(), "half a fr");
    }  // an exception on the way out: never committed
    EXPECT_EQ(read(dir / "frame.png"), "old frame");
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"frame.png"});
}

TEST(OutputFile, SetIsCommittedTogether) {
    TempDir dir("ssam_unit_core");
    engine::PendingFiles files;
    write(files.add(dir / "x.png"), "png");
    write(files.add(dir / "x.exr"), "exr");
    EXPECT_EQ(entries(dir.path()).size(), 2u);
    EXPECT_FALSE(fs::exists(dir / "x.png"));  // nothing in place before commit()
    files.commit();
    EXPECT_EQ(read(dir / "x.png"), "png");
    EXPECT_EQ(read(dir / "x.exr"), "exr");
    EXPECT_EQ(entries(dir.path()), (std::vector<std::string>{"x.exr", "x.png"}));
}

// The second file cannot be renamed into place (a non-empty directory holds its name): the
// first, already in place, is removed again, so neither is left, and no temporary either.
TEST(OutputFile, SetWithOneFailureLeavesNeither) {
    TempDir dir("ssam_unit_core");
    fs::create_directories(dir / "x.exr" / "occupied");
    engine::PendingFiles files;
    write(files.add(dir / "x.png"), "png");
    write(files.add(dir / "x.exr"), "exr");
    expectError([&] { files.commit(); }, "removed '" + (dir / "x.png").string() + "' written with it");
    EXPECT_FALSE(fs::exists(dir / "x.png"));
    EXPECT_TRUE(fs::is_directory(dir / "x.exr"));
    files = engine::PendingFiles();  // destroyed: its temporaries go
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"x.exr"});
}

TEST(OutputFile, WritableDirectoryIsProvenByCreatingAFile) {
    TempDir dir("ssam_unit_core");
    engine::requireWritableDirectory(dir.path(), false);
    EXPECT_TRUE(entries(dir.path()).empty());  // the probe is removed
    engine::requireWritableDirectory(dir / "made" / "deep", true);
    EXPECT_TRUE(fs::is_directory(dir / "made" / "deep"));
    expectError([&] { engine::requireWritableDirectory(dir / "absent", false); }, "does not exist");
    write(dir / "plain", "");
    expectError([&] { engine::requireWritableDirectory(dir / "plain", true); }, "is not a directory");
    expectError([&] { engine::requireWritableFile(dir / "made", false); }, "is a directory, not a file name");
    // access() answers yes to root here; creating a file does not.
    expectError([&] { engine::requireWritableDirectory("/proc", false); }, "cannot create files in '/proc'");
}

}  // namespace
