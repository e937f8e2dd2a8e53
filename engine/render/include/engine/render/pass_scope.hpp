// SPDX-License-Identifier: MIT
#pragma once
// One render pass as a scope (RAII): begun on construction, ended by end(). When an error
// unwinds through the scope before end() (a draw refused, a module's callback throwing), the
// pass is aborted instead (Backend::abortPass: what was recorded is dropped), so the backend
// is never left inside a pass and the next beginPass works.
#include "engine/render/backend.hpp"

namespace engine::render {

class PassScope {
public:
    PassScope(Backend& backend, const PassDesc& pass) : backend_(backend) { backend_.beginPass(pass); }
    ~PassScope() {
        if (open_) backend_.abortPass();
    }
    PassScope(const PassScope&) = delete;
    PassScope& operator=(const PassScope&) = delete;

    // Runs the pass (Backend::endPass). The pass is over even when this throws.
    void end() {
        open_ = false;
        backend_.endPass();
    }

private:
    Backend& backend_;
    bool open_ = true;
};

}  // namespace engine::render
