// SPDX-License-Identifier: MIT
#pragma once
// The whole ECS: entities, registry and views, command buffers, phased scheduler.
#include "engine/core/ecs/command_buffer.hpp"
#include "engine/core/ecs/entity.hpp"
#include "engine/core/ecs/registry.hpp"
#include "engine/core/ecs/scheduler.hpp"
#include "engine/core/ecs/view.hpp"
