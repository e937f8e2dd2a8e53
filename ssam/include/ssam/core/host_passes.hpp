// SPDX-License-Identifier: MIT
#pragma once
// The calls every host API of SSAM answers alike (ssam::gl's ScreenSpaceAlphaMaskGl and
// ssam::vk's ScreenSpaceAlphaMaskVk derive from it): the message callback, the settings in use,
// and one frame's passes, either (a) render() with SSAM's built-in programs or (b) the host's own
// shaders between beginFrame() and composite(). What a frame and a pass mean for the host (its GL
// state, its command buffer) is said in that API's header. Host-neutral core: standard C++17 only.
//
// `Host` is the API's class, which derives from HostPasses and befriends it: it keeps the state
// (`impl_`) and the messages kMovedFrom and kRenderWithoutCallback. The other three are the
// API's frame, built-in program and pass descriptions.
#include <memory>
#include <type_traits>

#include "ssam/core/frame.hpp"
#include "ssam/core/settings.hpp"
#include "ssam/core/status.hpp"

#pragma push_macro("Status")
#undef Status

namespace ssam {

template <class Host, class FrameDesc, class FoliageProgram, class PassInfo>
class HostPasses {
public:
    void setMessageCallback(MessageCallback callback, void* user) noexcept;
    // The message of the last call that did not return Ok ("" before any).
    const char* lastMessage() const noexcept;
    const Settings& settings() const noexcept;

    // Way (a): the three passes with SSAM's built-in programs. `draw(user, program)` runs twice,
    // mask pass then colour pass, and draws the same foliage in the same order each time
    // ([Hathaway 2010] §3.8). A throwing `draw` is reported (CallbackFailed), never rethrown.
    using DrawFoliage = void (*)(void* user, const FoliageProgram& program);
    Status render(const FrameDesc& frame, DrawFoliage draw, void* user, FrameReport* report = nullptr) noexcept;
    // The same with any callable, e.g. a lambda: render(frame, [&](const FoliageProgram& p) {...}).
    template <class Draw>
    Status render(const FrameDesc& frame, Draw&& draw, FrameReport* report = nullptr) noexcept {
        using Callable = std::remove_reference_t<Draw>;
        return render(
            frame, [](void* user, const FoliageProgram& p) { (*static_cast<Callable*>(user))(p); },
            const_cast<void*>(static_cast<const void*>(std::addressof(draw))), report);
    }

    // Way (b): the host's own shaders, one pass at a time. beginFrame checks the frame and
    // (re)creates SSAM's targets; when FrameReport::foliageInView is false the frame is over.
    // Out of order: InvalidCall, and the open frame is abandoned.
    Status beginFrame(const FrameDesc& frame, FrameReport* report = nullptr) noexcept;
    Status beginMaskPass(PassInfo* info = nullptr) noexcept;
    Status endMaskPass() noexcept;
    Status beginColorPass(PassInfo* info = nullptr) noexcept;
    Status endColorPass() noexcept;
    Status composite() noexcept;

protected:
    HostPasses() = default;
    ~HostPasses() = default;
    HostPasses(HostPasses&&) noexcept = default;
    HostPasses& operator=(HostPasses&&) noexcept = default;
    HostPasses(const HostPasses&) = delete;
    HostPasses& operator=(const HostPasses&) = delete;

private:
    auto* impl() const noexcept { return static_cast<const Host*>(this)->impl_.get(); }
};

}  // namespace ssam

#pragma pop_macro("Status")
