// SPDX-License-Identifier: MIT
#include "engine/core/ecs/scheduler.hpp"

#include <sstream>

#include "engine/core/error.hpp"

namespace engine::ecs {

Scheduler::Scheduler() : Scheduler(std::vector<std::string>(kDefaultPhases.begin(), kDefaultPhases.end())) {}

Scheduler::Scheduler(std::vector<std::string> phases) {
    if (phases.empty()) throw Error("ecs: a Scheduler needs at least one phase");
    for (std::string& name : phases) {
        if (name.empty()) throw Error("ecs: Scheduler phase names must not be empty");
        for (const Phase& existing : phases_)
            if (existing.name == name) throw Error("ecs: Scheduler phase '" + name + "' is listed twice");
        phases_.push_back(Phase{std::move(name), {}});
    }
}

std::size_t Scheduler::phaseIndex(std::string_view name) const {
    for (std::size_t i = 0; i < phases_.size(); ++i)
        if (phases_[i].name == name) return i;
    std::ostringstream msg;
    msg << "ecs: unknown Scheduler phase '" << name << "' (phases:";
    for (const Phase& phase : phases_) msg << ' ' << phase.name;
    msg << ')';
    throw Error(msg.str());
}

void Scheduler::add(std::string_view phaseName, std::string name, System system) {
    Phase& phase = phases_[phaseIndex(phaseName)];
    if (name.empty()) throw Error("ecs: a system in phase '" + phase.name + "' needs a name");
    if (!system) throw Error("ecs: system '" + name + "' has no function");
    for (const Phase& other : phases_)
        for (const NamedSystem& existing : other.systems)
            if (existing.name == name)
                throw Error("ecs: system name '" + name + "' is already used in phase '" + other.name + "'");
    phase.systems.push_back(NamedSystem{std::move(name), std::move(system)});
}

void Scheduler::run(Registry& registry) {
    CommandBuffer commands(registry);
    for (Phase& phase : phases_) {
        for (NamedSystem& system : phase.systems) {
            try {
                system.run(registry, commands);
            } catch (const Error& error) {
                throw Error("system '" + system.name + "' (phase '" + phase.name + "'): " + error.what());
            }
        }
        try {
            commands.flush();
        } catch (const Error& error) {
            throw Error("flushing commands after phase '" + phase.name + "': " + error.what());
        }
    }
}

std::vector<std::string> Scheduler::phases() const {
    std::vector<std::string> names;
    for (const Phase& phase : phases_) names.push_back(phase.name);
    return names;
}

std::vector<std::string> Scheduler::systems(std::string_view phaseName) const {
    std::vector<std::string> names;
    for (const NamedSystem& system : phases_[phaseIndex(phaseName)].systems) names.push_back(system.name);
    return names;
}

}  // namespace engine::ecs
