// SPDX-License-Identifier: MIT
#pragma once
// A driver's storage for what it makes, addressed by the NativeId it hands the Device
// (driver.hpp). No checks: the Device has already refused stale and null handles, so a driver
// is only ever given an index it returned and has not been told to destroy.
#include <cstdint>
#include <utility>
#include <vector>

#include "engine/render/driver.hpp"

namespace engine::render {

template <typename T>
class NativeSlots {
public:
    NativeId add(T value) {
        if (!free_.empty()) {
            const NativeId id = free_.back();
            free_.pop_back();
            slots_[id] = std::move(value);
            live_[id] = true;
            return id;
        }
        slots_.push_back(std::move(value));
        live_.push_back(true);
        return NativeId(slots_.size() - 1);
    }
    T& operator[](NativeId id) { return slots_[id]; }
    const T& operator[](NativeId id) const { return slots_[id]; }
    void remove(NativeId id) {
        slots_[id] = T{};
        live_[id] = false;
        free_.push_back(id);
    }
    // Calls f on every live value (a driver's tear-down releases what they own).
    template <typename F>
    void forEach(F&& f) {
        for (std::size_t i = 0; i < slots_.size(); ++i)
            if (live_[i]) f(slots_[i]);
    }

private:
    std::vector<T> slots_;
    std::vector<bool> live_;
    std::vector<NativeId> free_;
};

}  // namespace engine::render
