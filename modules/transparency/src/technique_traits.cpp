// SPDX-License-Identifier: MIT
// What the traits a technique was made with ask of the caller's frame.
#include "transparency/technique.hpp"
#include "transparency/temporal.hpp"

namespace transparency {

glm::vec2 Technique::projectionJitter(std::uint64_t frameIndex) const {
    return traits_.temporal ? haltonJitter(frameIndex, traits_.jitterPhases) : glm::vec2(0.0f);
}

}  // namespace transparency
