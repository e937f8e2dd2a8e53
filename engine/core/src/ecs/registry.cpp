// SPDX-License-Identifier: MIT
#include "engine/core/ecs/registry.hpp"

#include <sstream>

#include "engine/core/error.hpp"

namespace engine::ecs {

Registry::~Registry() = default;

Entity Registry::create() {
    if (live_.locked())
        throw Error(
            "ecs: cannot create an entity while a view over all entities is iterating; "
            "use CommandBuffer::create()");
    const Entity e = allocateSlot();
    try {
        live_.insert(e);
    } catch (...) {
        freeSlot(e);
        throw;
    }
    slots_[e.index()].state = Slot::State::Live;
    return e;
}

void Registry::destroy(Entity e) {
    requireAlive(e, "destroy", {});
    // Check every set first so that a refused destroy changes nothing.
    refuseIfLocked(live_, e, "destroy");
    for (const auto& pool : pools_)
        if (pool && pool->contains(e)) refuseIfLocked(*pool, e, "destroy");
    for (const auto& pool : pools_)
        if (pool) pool->erase(e);
    live_.erase(e);
    freeSlot(e);
}

Entity Registry::reserve() { return allocateSlot(); }

void Registry::commitReserved(Entity e) {
    if (!reserved(e)) throwFor(e, "commit", {}, "it is not a pending CommandBuffer entity");
    if (live_.locked())
        throw Error("ecs: cannot flush a CommandBuffer create while a view over all entities is iterating");
    live_.insert(e);
    slots_[e.index()].state = Slot::State::Live;
}

void Registry::releaseReserved(Entity e) {
    if (reserved(e)) freeSlot(e);
}

bool Registry::reserved(Entity e) const noexcept {
    return e.index() < slots_.size() && slots_[e.index()].state == Slot::State::Reserved &&
           slots_[e.index()].generation == e.generation();
}

// Hands out a slot in the Reserved state; create() and commitReserved() make it Live.
Entity Registry::allocateSlot() {
    if (!freeSlots_.empty()) {
        const std::uint32_t index = freeSlots_.back();
        freeSlots_.pop_back();
        slots_[index].state = Slot::State::Reserved;
        return Entity::fromParts(index, slots_[index].generation);
    }
    if (slots_.size() > Entity::kMaxIndex) {
        std::ostringstream msg;
        msg << "ecs: out of entity slots (" << Entity::kMaxIndex + 1 << " slots, " << live_.size() << " alive, "
            << retiredSlots_ << " retired after " << Entity::kMaxGeneration + 1 << " generations each)";
        throw Error(msg.str());
    }
    slots_.push_back(Slot{0, Slot::State::Reserved});
    return Entity::fromParts(static_cast<std::uint32_t>(slots_.size() - 1), 0);
}

void Registry::freeSlot(Entity e) {
    Slot& slot = slots_[e.index()];
    if (slot.generation == Entity::kMaxGeneration) {
        // The next generation would wrap to 0 and let the oldest handles alias a new
        // occupant: take the slot out of service instead.
        slot.state = Slot::State::Retired;
        ++retiredSlots_;
        return;
    }
    ++slot.generation;
    slot.state = Slot::State::Free;
    freeSlots_.push_back(e.index());
}

void Registry::requireAlive(Entity e, std::string_view action, std::string_view component) const {
    if (alive(e)) return;
    std::ostringstream why;
    const Slot* slot = e.index() < slots_.size() ? &slots_[e.index()] : nullptr;
    if (e.isNull()) {
        why << "the handle is null";
    } else if (!slot) {
        why << "this registry never created it";
    } else if (slot->state == Slot::State::Retired) {
        why << "the handle is stale (slot " << e.index() << " was destroyed and retired)";
    } else if (slot->state == Slot::State::Reserved && slot->generation == e.generation()) {
        why << "it was created by a CommandBuffer that has not been flushed yet";
    } else if (e.generation() < slot->generation) {
        why << "the handle is stale (destroyed; slot " << e.index() << " has moved on to generation "
            << slot->generation << ')';
    } else {
        why << "this registry never created it (slot " << e.index() << " is at generation " << slot->generation << ')';
    }
    throwFor(e, action, component, why.str());
}

void Registry::refuseIfLocked(const SparseSet& set, Entity e, std::string_view action) const {
    if (!set.locked()) return;
    const bool allEntities = &set == &live_;
    std::ostringstream msg;
    msg << "ecs: cannot " << action << ' ';
    if (!allEntities) msg << "component '" << set.name() << "' " << (action == "add" ? "to " : "of ");
    msg << e << " while a view over " << (allEntities ? std::string_view("all entities") : set.name())
        << " is iterating; record it in a CommandBuffer and flush after the loop";
    throw Error(msg.str());
}

void Registry::throwFor(Entity e, std::string_view action, std::string_view component, std::string_view why) {
    std::ostringstream msg;
    msg << "ecs: cannot " << action << ' ';
    if (!component.empty()) msg << "component '" << component << "' " << (action == "add" ? "to " : "of ");
    msg << e << ": " << why;
    throw Error(msg.str());
}

}  // namespace engine::ecs
