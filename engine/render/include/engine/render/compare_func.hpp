// SPDX-License-Identifier: MIT
#pragma once
// The eight comparison functions shared by the depth test and the alpha test.
// Read as "incoming <func> stored/reference": Less passes when incoming < stored.
#include <cstdint>

namespace engine::render {

enum class CompareFunc : std::uint8_t { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };

inline constexpr CompareFunc kAllCompareFuncs[] = {
    CompareFunc::Never,   CompareFunc::Less,     CompareFunc::Equal,        CompareFunc::LessEqual,
    CompareFunc::Greater, CompareFunc::NotEqual, CompareFunc::GreaterEqual, CompareFunc::Always};

// NaN compares false with everything, so only Never/NotEqual/Always have a defined answer
// for it: exactly IEEE's, as GPUs do.
constexpr bool compare(CompareFunc func, float incoming, float reference) {
    switch (func) {
        case CompareFunc::Never: return false;
        case CompareFunc::Less: return incoming < reference;
        case CompareFunc::Equal: return incoming == reference;
        case CompareFunc::LessEqual: return incoming <= reference;
        case CompareFunc::Greater: return incoming > reference;
        case CompareFunc::NotEqual: return incoming != reference;
        case CompareFunc::GreaterEqual: return incoming >= reference;
        case CompareFunc::Always: return true;
    }
    return false;
}

const char* compareFuncName(CompareFunc func);

// The GL enum of a function: CompareFunc lists them in GL's order, GL_NEVER (0x0200) to
// GL_ALWAYS (0x0207), so the GL backend and a GL host (ssam::gl) need no table; the GL backend
// checks the correspondence at compile time (gl_enums.cpp).
constexpr unsigned glCompareFunc(CompareFunc func) { return 0x0200u + static_cast<unsigned>(func); }

}  // namespace engine::render
