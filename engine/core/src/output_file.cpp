// SPDX-License-Identifier: MIT
#include "engine/core/output_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <system_error>

#include "engine/core/error.hpp"

namespace engine {

namespace fs = std::filesystem;

namespace {

fs::path directoryOf(const fs::path& target) { return target.has_parent_path() ? target.parent_path() : fs::path("."); }

std::string randomSuffix() {
    static const char kLetters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    thread_local std::mt19937_64 random(
        std::random_device{}() ^
        static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) ^
        static_cast<std::uint64_t>(::getpid()));
    std::string suffix(6, ' ');
    for (char& c : suffix) c = kLetters[random() % (sizeof kLetters - 1)];
    return suffix;
}

// Creates an empty file under a fresh name beside `target`. O_EXCL makes the name ours alone;
// mode 0666 lets the umask decide the final permissions, as for any file the tool creates.
fs::path createTemporaryBeside(const fs::path& target) {
    const fs::path directory = directoryOf(target);
    const std::string stem = target.stem().string(), extension = target.extension().string();
    for (int attempt = 0; attempt < 100; ++attempt) {
        fs::path candidate = target.parent_path() / ("." + stem + ".tmp-" + randomSuffix() + extension);
        const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            return candidate;
        }
        if (errno != EEXIST)
            throw Error("cannot create files in '" + directory.string() + "': " + std::strerror(errno));
    }
    throw Error("cannot create files in '" + directory.string() + "': no free temporary name after 100 tries");
}

}  // namespace

void requireWritableDirectory(const fs::path& directory, bool create) {
    const fs::path dir = directory.empty() ? fs::path(".") : directory;
    std::error_code ec;
    const fs::file_status status = fs::status(dir, ec);
    if (fs::exists(status) && !fs::is_directory(status)) throw Error("'" + dir.string() + "' is not a directory");
    if (!fs::exists(status)) {
        if (!create) throw Error("directory '" + dir.string() + "' does not exist");
        fs::create_directories(dir, ec);
        if (ec) throw Error("cannot create the directory '" + dir.string() + "': " + ec.message());
    }
    fs::remove(createTemporaryBeside(dir / "write-test"), ec);
}

void requireWritableFile(const fs::path& target, bool createDirectory) {
    std::error_code ec;
    if (fs::is_directory(target, ec)) throw Error("'" + target.string() + "' is a directory, not a file name");
    requireWritableDirectory(directoryOf(target), createDirectory);
}

PendingFile::PendingFile(fs::path target) : target_(std::move(target)), temporary_(createTemporaryBeside(target_)) {}

PendingFile::PendingFile(PendingFile&& other) noexcept
    : target_(std::move(other.target_)), temporary_(std::move(other.temporary_)) {
    other.temporary_.clear();
}

PendingFile::~PendingFile() {
    if (temporary_.empty()) return;
    std::error_code ec;
    fs::remove(temporary_, ec);  // best effort: a destructor must not throw
}

void PendingFile::commit() {
    std::error_code ec;
    fs::rename(temporary_, target_, ec);
    if (ec) throw Error("cannot put '" + target_.string() + "' in place: " + ec.message());
    temporary_.clear();
}

fs::path PendingFiles::add(const fs::path& target) {
    files_.emplace_back(target);
    return files_.back().path();
}

void PendingFiles::commit() {
    std::vector<fs::path> placed;
    for (PendingFile& file : files_) {
        try {
            file.commit();
        } catch (const Error& e) {
            std::string removed;
            std::error_code ec;
            for (const fs::path& path : placed) {
                fs::remove(path, ec);
                removed += (removed.empty() ? "" : ", ") + ("'" + path.string() + "'");
            }
            if (removed.empty()) throw;
            throw Error(std::string(e.what()) + "; removed " + removed + " written with it");
        }
        placed.push_back(file.target());
    }
    files_.clear();
}

void writeFileAtomically(const fs::path& path, std::span<const std::uint8_t> bytes) {
    PendingFile file(path);
    std::ofstream out(file.path(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw Error("cannot write '" + path.string() + "'");
    file.commit();
}

void writeFileAtomically(const fs::path& path, std::string_view text) {
    writeFileAtomically(path, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

}  // namespace engine
