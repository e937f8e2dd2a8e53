// SPDX-License-Identifier: MIT
#pragma once
// Slots addressed by generation-checked handles, shared by the backends. A destroyed
// slot's generation moves on, so an old handle to it is reported, never aliased.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/render/handles.hpp"

namespace engine::render {

template <typename Tag, typename T>
class ResourcePool {
public:
    explicit ResourcePool(std::string kind) : kind_(std::move(kind)) {}

    Handle<Tag> add(T value) {
        std::uint32_t index;
        if (!free_.empty()) {
            index = free_.back();
            free_.pop_back();
        } else {
            index = static_cast<std::uint32_t>(slots_.size());
            slots_.push_back({});
        }
        Slot& slot = slots_[index];
        slot.value = std::move(value);
        slot.alive = true;
        return {index, slot.generation};
    }

    T& get(Handle<Tag> h) { return slots_[check(h)].value; }
    const T& get(Handle<Tag> h) const { return slots_[check(h)].value; }
    bool alive(Handle<Tag> h) const {
        return h.valid() && h.index < slots_.size() && slots_[h.index].alive &&
               slots_[h.index].generation == h.generation;
    }

    // Calls f on every live value (a backend's tear-down releases what they own).
    template <typename F>
    void forEach(F&& f) const {
        for (const Slot& slot : slots_)
            if (slot.alive) f(slot.value);
    }

    void remove(Handle<Tag> h) {
        Slot& slot = slots_[check(h)];
        slot.value = T{};
        slot.alive = false;
        if (++slot.generation == 0) return;  // generation space used up: retire the slot for good
        free_.push_back(h.index);
    }

private:
    struct Slot {
        T value{};
        std::uint32_t generation = 1;
        bool alive = false;
    };

    std::uint32_t check(Handle<Tag> h) const {
        if (!h.valid()) throw Error(kind_ + " handle is null");
        if (!alive(h))
            throw Error(kind_ + " handle " + std::to_string(h.index) + ":" + std::to_string(h.generation) +
                        " is stale or was never created");
        return h.index;
    }

    std::string kind_;
    std::vector<Slot> slots_;
    std::vector<std::uint32_t> free_;
};

}  // namespace engine::render
