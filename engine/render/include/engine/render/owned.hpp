// SPDX-License-Identifier: MIT
#pragma once
// A backend resource destroyed with its owner (RAII over a handle): a module that creates
// programs and pipelines in its constructor leaks none when a later create throws.
#include <utility>

#include "engine/render/backend.hpp"

namespace engine::render {

template <typename Handle>
class Owned {
public:
    Owned() = default;
    Owned(Backend& backend, Handle handle) : backend_(&backend), handle_(handle) {}
    Owned(Owned&& other) noexcept : backend_(other.backend_), handle_(std::exchange(other.handle_, Handle{})) {}
    Owned& operator=(Owned&& other) noexcept {
        if (this != &other) {
            reset();
            backend_ = other.backend_;
            handle_ = std::exchange(other.handle_, Handle{});
        }
        return *this;
    }
    Owned(const Owned&) = delete;
    Owned& operator=(const Owned&) = delete;
    ~Owned() { reset(); }

    Handle get() const { return handle_; }
    operator Handle() const { return handle_; }  // NOLINT: used where the handle is
    void reset() {
        if (handle_) backend_->destroy(std::exchange(handle_, Handle{}));
    }

private:
    Backend* backend_ = nullptr;
    Handle handle_;
};

}  // namespace engine::render
