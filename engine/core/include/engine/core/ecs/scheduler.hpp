// SPDX-License-Identifier: MIT
#pragma once
// Scheduler: runs named systems in named phases, in a fixed order.
//
// A frame (run()) walks the phases in the order given at construction, and within a
// phase the systems in registration order. Systems share one CommandBuffer, flushed
// after every phase (the last included), so what a phase records is visible to the
// next phase and a frame leaves nothing pending.
//
//   Scheduler scheduler;                           // input, simulation, deformation, camera, extraction
//   scheduler.add(phase::simulation, "integrate", [](Registry& r, CommandBuffer& cmd) {...});
//   scheduler.run(registry);
//
// Registering into an unknown phase, an empty system or a name already in use throws
// engine::Error. An engine::Error thrown by a system is rethrown with the system's
// name and phase prepended; unflushed commands of that frame are discarded.
#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/ecs/command_buffer.hpp"
#include "engine/core/ecs/registry.hpp"

namespace engine::ecs {

namespace phase {
inline constexpr std::string_view input = "input";
inline constexpr std::string_view simulation = "simulation";
inline constexpr std::string_view deformation = "deformation";
inline constexpr std::string_view camera = "camera";
inline constexpr std::string_view extraction = "extraction";
}  // namespace phase

using System = std::function<void(Registry&, CommandBuffer&)>;

class Scheduler {
public:
    static constexpr std::array<std::string_view, 5> kDefaultPhases{phase::input, phase::simulation, phase::deformation,
                                                                    phase::camera, phase::extraction};

    Scheduler();  // the default phases
    // Custom phases, run in this order; throws on an empty list, empty or duplicate names.
    explicit Scheduler(std::vector<std::string> phases);

    void add(std::string_view phase, std::string name, System system);
    // One frame: every phase, every system, a flush after each phase.
    void run(Registry& registry);

    std::vector<std::string> phases() const;
    // Registered system names of `phase`, in run order; throws for an unknown phase.
    std::vector<std::string> systems(std::string_view phase) const;

private:
    struct NamedSystem {
        std::string name;
        System run;
    };
    struct Phase {
        std::string name;
        std::vector<NamedSystem> systems;
    };

    std::size_t phaseIndex(std::string_view name) const;  // throws for an unknown phase

    std::vector<Phase> phases_;
};

}  // namespace engine::ecs
