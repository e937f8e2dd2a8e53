// SPDX-License-Identifier: MIT
#pragma once
// CommandBuffer: structural changes recorded now, applied to the registry at flush(),
// in recording order. This is how systems create, destroy, add and remove while a
// view is iterating; the Scheduler flushes after every phase.
//
// Contracts
// - create() returns the final handle at once (its slot is reserved), so later
//   commands in the same buffer can target it; it becomes alive at flush().
// - Recording for a handle that is neither alive nor a pending create throws
//   engine::Error immediately, where the bug is.
// - At flush, a command whose entity is no longer alive (destroyed by an earlier
//   command or directly since recording) is dropped and counted in FlushStats:
//   two systems destroying the same entity in one phase is not an error.
// - add<T> at flush adds, or replaces the value if the entity already has a T.
// - Component values are built when recorded (args are moved/copied in).
// - clear() or destruction discards what was not flushed; pending creates are
//   released and their handles are stale. If a command throws during flush, the
//   commands after it are discarded the same way and the exception propagates.
// - The buffer must not outlive its registry. Not thread-safe.
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "engine/core/ecs/entity.hpp"
#include "engine/core/ecs/registry.hpp"

namespace engine::ecs {

struct FlushStats {
    std::size_t applied = 0;
    std::size_t dropped = 0;  // their entity was no longer alive
};

class CommandBuffer {
public:
    explicit CommandBuffer(Registry& registry) noexcept : registry_(&registry) {}
    ~CommandBuffer() { clear(); }
    CommandBuffer(const CommandBuffer&) = delete;
    CommandBuffer& operator=(const CommandBuffer&) = delete;

    Entity create();
    void destroy(Entity e);
    template <class T, class... Args>
    void add(Entity e, Args&&... args) {
        requireRecordable(e, "add");
        record(std::make_unique<Add<T>>(e, T(std::forward<Args>(args)...)));
    }
    template <class T>
    void remove(Entity e) {
        requireRecordable(e, "remove");
        record(std::make_unique<Remove<T>>(e));
    }

    FlushStats flush();
    void clear() noexcept;
    std::size_t size() const noexcept { return commands_.size(); }
    bool empty() const noexcept { return commands_.empty(); }
    Registry& registry() const noexcept { return *registry_; }

private:
    struct Command {
        explicit Command(Entity e) noexcept : target(e) {}
        virtual ~Command() = default;
        // Returns false when the command was dropped (its entity is not alive).
        virtual bool apply(Registry& registry) = 0;
        // Called instead of apply() when the command will never run.
        virtual void discard(Registry&) noexcept {}
        Entity target;
    };
    struct Create;
    struct Destroy;
    template <class T>
    struct Add final : Command {
        Add(Entity e, T&& v) : Command(e), value(std::move(v)) {}
        bool apply(Registry& registry) override {
            if (!registry.alive(target)) return false;
            registry.addOrReplace<T>(target, std::move(value));
            return true;
        }
        T value;
    };
    template <class T>
    struct Remove final : Command {
        using Command::Command;
        bool apply(Registry& registry) override {
            if (!registry.alive(target)) return false;
            registry.remove<T>(target);
            return true;
        }
    };

    void requireRecordable(Entity e, const char* action) const;
    void record(std::unique_ptr<Command> command) { commands_.push_back(std::move(command)); }

    Registry* registry_;
    std::vector<std::unique_ptr<Command>> commands_;
};

}  // namespace engine::ecs
