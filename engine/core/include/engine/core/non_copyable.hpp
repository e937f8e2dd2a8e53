// SPDX-License-Identifier: MIT
#pragma once
// engine::NonCopyable: a private base for a class whose copy would share what it owns (GPU
// objects, systems registered by its address, its Impl); one base says so where each class
// otherwise deleted its own two copy members. It declares no move, so a class deriving from it
// moves only if it declares its own moves, as with the deleted members it replaces.

namespace engine {

class NonCopyable {
public:
    NonCopyable(const NonCopyable&) = delete;
    NonCopyable& operator=(const NonCopyable&) = delete;

protected:
    NonCopyable() = default;
    ~NonCopyable() = default;
};

}  // namespace engine
