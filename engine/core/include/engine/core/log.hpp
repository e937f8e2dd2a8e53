// SPDX-License-Identifier: MIT
#pragma once
// Minimal levelled logging to stderr. Messages are built with operator<< so any
// streamable value can be logged without a formatting library.
#include <sstream>
#include <string_view>

namespace engine::log {

enum class Level { Debug, Info, Warn, Error, Off };

void setLevel(Level level);
Level level();
void write(Level level, std::string_view message);

template <typename... Args>
void print(Level lvl, const Args&... args) {
    if (lvl < level()) return;
    std::ostringstream out;
    (out << ... << args);
    write(lvl, out.str());
}

template <typename... Args>
void debug(const Args&... args) {
    print(Level::Debug, args...);
}
template <typename... Args>
void info(const Args&... args) {
    print(Level::Info, args...);
}
template <typename... Args>
void warn(const Args&... args) {
    print(Level::Warn, args...);
}
template <typename... Args>
void error(const Args&... args) {
    print(Level::Error, args...);
}

}  // namespace engine::log
