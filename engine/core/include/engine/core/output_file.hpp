// SPDX-License-Identifier: MIT
#pragma once
// Output files written whole or not at all, the way git replaces a ref or an index: each file
// is written under a temporary name in its own directory and renamed over its target only once
// complete (rename within one directory is atomic on POSIX), so a failure never leaves a
// half-written target, and a set of files that belong together (a PNG and the EXR of its
// layers) appears together or not at all. This guards against the program failing, not
// against power loss: nothing is fsynced.
//
// And checked before any work: a tool proves it can create files where it will write before
// it renders its first frame, by creating one there, since access() answers "writable" to root
// even where nothing can be created (/proc).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

namespace engine {

// Proves that files can be created in `directory` by creating and removing a temporary file
// there; with `create`, makes the directory (and its parents) first. Throws engine::Error
// naming the directory and the system's reason.
void requireWritableDirectory(const std::filesystem::path& directory, bool create);

// requireWritableDirectory() on `target`'s directory ("." when it has none), and `target`
// itself must not be a directory, since no file can be renamed over one.
void requireWritableFile(const std::filesystem::path& target, bool createDirectory);

// A file being written. The constructor creates it empty under a unique temporary name beside
// `target` (".<stem>.tmp-XXXXXX<extension>": the extension is kept, so a writer that picks the
// format by it still picks the right one); write to path(), then commit() renames it over
// the target. Destroyed uncommitted (an exception on the way), it removes the temporary file.
class PendingFile {
public:
    explicit PendingFile(std::filesystem::path target);
    ~PendingFile();
    PendingFile(PendingFile&& other) noexcept;
    PendingFile& operator=(PendingFile&&) = delete;
    PendingFile(const PendingFile&) = delete;
    PendingFile& operator=(const PendingFile&) = delete;

    const std::filesystem::path& path() const { return temporary_; }
    const std::filesystem::path& target() const { return target_; }
    void commit();

private:
    std::filesystem::path target_;
    std::filesystem::path temporary_;  // empty once committed or moved from
};

// Files that appear together or not at all. add() returns the temporary path to write the
// file to; commit() renames them all, and if one rename fails it removes the targets it has
// already renamed (so neither the new set nor a mixed set is left) and throws.
class PendingFiles {
public:
    std::filesystem::path add(const std::filesystem::path& target);
    void commit();
    bool empty() const { return files_.empty(); }

private:
    std::vector<PendingFile> files_;
};

// Writes `bytes` (or `text`) to `path` whole or not at all; throws engine::Error naming it.
void writeFileAtomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);
void writeFileAtomically(const std::filesystem::path& path, std::string_view text);

}  // namespace engine
