// SPDX-License-Identifier: MIT
#pragma once
// The one exception type the engine throws for bad input and invalid state.
// Messages say what was wrong and where ("image 'x.png': truncated at row 12"),
// so a caller can print what() and a user knows what to fix.
#include <stdexcept>
#include <string>
#include <string_view>

namespace engine {

class Error : public std::runtime_error {
public:
    explicit Error(std::string_view message) : std::runtime_error(printable(message)) {}
    explicit Error(const char* message) : Error(std::string_view(message)) {}
    explicit Error(const std::string& message) : Error(std::string_view(message)) {}

private:
    // A message quotes names from the input (a glTF string may hold "\u0000"): a NUL in it
    // would end what() early and hide the rest, so it is spelled out.
    static std::string printable(std::string_view message) {
        std::string out;
        out.reserve(message.size());
        for (char c : message) {
            if (c == '\0') out += "\\0";
            else out += c;
        }
        return out;
    }
};

}  // namespace engine
