// SPDX-License-Identifier: MIT
#pragma once
// The programs every backend brings (ProgramRef::standard). Each is described like a
// module's program (program_desc.hpp); this is the backend-neutral half of the description
// (name, vertex input, parameter struct, GL uniform and texture layout, checks), which each
// backend completes with its own part (its GLSL, its CPU kernel).
#include <array>
#include <cstddef>
#include <memory>
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/program.hpp"
#include "engine/render/program_desc.hpp"

namespace engine::render {

ProgramDesc standardProgramDesc(ProgramKind kind);

inline constexpr int kStandardProgramCount = 4;

// A backend's standard programs, each made the first time a pipeline names it: `Slot` is what
// the backend keeps per program (its description with a CPU kernel, a compiled GL program).
template <typename Slot>
class StandardProgramSlots {
public:
    // The program of `kind`; make(standardProgramDesc(kind)) completes and builds it the first time.
    template <typename Make>
    std::shared_ptr<const Slot> get(ProgramKind kind, Make&& make) {
        const auto index = std::size_t(kind);
        if (index >= slots_.size()) throw Error("unknown standard program " + std::to_string(index));
        std::shared_ptr<const Slot>& slot = slots_[index];
        if (!slot) slot = make(standardProgramDesc(kind));
        return slot;
    }

    void clear() {
        for (auto& slot : slots_) slot.reset();
    }

private:
    std::array<std::shared_ptr<const Slot>, kStandardProgramCount> slots_;
};

}  // namespace engine::render
