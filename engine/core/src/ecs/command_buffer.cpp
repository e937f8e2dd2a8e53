// SPDX-License-Identifier: MIT
#include "engine/core/ecs/command_buffer.hpp"

#include <sstream>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"

namespace engine::ecs {

struct CommandBuffer::Create final : Command {
    using Command::Command;
    bool apply(Registry& registry) override {
        registry.commitReserved(target);
        committed = true;
        return true;
    }
    void discard(Registry& registry) noexcept override {
        if (!committed) registry.releaseReserved(target);
    }
    bool committed = false;
};

struct CommandBuffer::Destroy final : Command {
    using Command::Command;
    bool apply(Registry& registry) override {
        if (!registry.alive(target)) return false;
        registry.destroy(target);
        return true;
    }
};

Entity CommandBuffer::create() {
    const Entity e = registry_->reserve();
    try {
        record(std::make_unique<Create>(e));
    } catch (...) {
        registry_->releaseReserved(e);
        throw;
    }
    return e;
}

void CommandBuffer::destroy(Entity e) {
    requireRecordable(e, "destroy");
    record(std::make_unique<Destroy>(e));
}

FlushStats CommandBuffer::flush() {
    // Take the commands first: the buffer is empty again whatever happens below.
    std::vector<std::unique_ptr<Command>> commands = std::move(commands_);
    commands_.clear();
    FlushStats stats;
    std::size_t next = 0;
    try {
        for (; next < commands.size(); ++next) {
            if (commands[next]->apply(*registry_)) ++stats.applied;
            else ++stats.dropped;
        }
    } catch (...) {
        for (std::size_t i = next; i < commands.size(); ++i) commands[i]->discard(*registry_);
        throw;
    }
    if (stats.dropped != 0)
        log::debug("ecs: CommandBuffer flush dropped ", stats.dropped, " of ", commands.size(),
                   " commands whose entity was no longer alive");
    return stats;
}

void CommandBuffer::clear() noexcept {
    for (auto& command : commands_) command->discard(*registry_);
    commands_.clear();
}

void CommandBuffer::requireRecordable(Entity e, const char* action) const {
    if (registry_->alive(e) || registry_->reserved(e)) return;
    // Let the registry explain why the handle is unusable.
    registry_->requireAlive(e, std::string("record a CommandBuffer ") + action + " for", {});
}

}  // namespace engine::ecs
