// SPDX-License-Identifier: MIT
#pragma once
// The checks every module's options run on their float fields, with one wording:
// "<Struct>.<field> is not finite", "<Struct>.<field> = 2.5 is negative", "... must be > 0".
// A caller names its struct once: engine::FieldChecks check{"Wind"}; check.nonNegative(w.strength, "strength").
#include <cmath>
#include <string>

#include "engine/core/error.hpp"

namespace engine {

struct FieldChecks {
    const char* owner;  // the options struct's name, as its user spells it

    void finite(float v, const char* field) const {
        if (!std::isfinite(v)) throw Error(name(field) + " is not finite");
    }
    void nonNegative(float v, const char* field) const {
        finite(v, field);
        if (v < 0.0f) throw Error(name(field) + " = " + std::to_string(v) + " is negative");
    }
    void positive(float v, const char* field) const {
        finite(v, field);
        if (!(v > 0.0f)) throw Error(name(field) + " = " + std::to_string(v) + " must be > 0");
    }

private:
    std::string name(const char* field) const { return std::string(owner) + "." + field; }
};

}  // namespace engine
