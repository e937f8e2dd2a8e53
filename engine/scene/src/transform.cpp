// SPDX-License-Identifier: MIT
#include "engine/scene/transform.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace engine::scene {

glm::mat4 Transform::matrix() const {
    return glm::translate(glm::mat4(1.0f), position) * glm::mat4_cast(rotation) * glm::scale(glm::mat4(1.0f), scale);
}

}  // namespace engine::scene
