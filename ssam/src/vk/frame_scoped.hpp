// SPDX-License-Identifier: MIT
#pragma once
// What SSAM makes over the host's objects (the render-pass path's framebuffers over its image
// views) lives for one frame: made for the frame that uses it, destroyed once
// FrameDesc::framesCompleted passes that frame, and never found again by the host's handle
// values. A host that destroys its views and makes new ones can get the same values back
// (lavapipe did in 4 of 6 recreations), and a framebuffer kept by those values would then name
// destroyed views: beginning a render pass with it uses them after their destruction (Vulkan
// spec, "Object Lifetime"). Free of Vulkan, so its bookkeeping is tested with fake handles.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace ssam::vk::detail {

template <class Object>
class FrameScoped {
public:
    // Room for one more, so that add() cannot throw once the object exists.
    void reserveOne() {
        if (entries_.size() == entries_.capacity()) entries_.reserve(entries_.size() * 2 + 4);
    }
    // `object`, made for frame `frame` (after reserveOne(): does not throw).
    void add(std::uint64_t frame, Object object) noexcept { entries_.push_back({frame, std::move(object)}); }
    // destroy(object) for each made for a frame below `framesCompleted` (finished on the device);
    // the others are kept, in order.
    template <class Destroy>
    void collect(std::uint64_t framesCompleted, Destroy&& destroy) noexcept {
        std::size_t kept = 0;
        for (std::size_t i = 0; i < entries_.size(); ++i) {
            if (entries_[i].frame < framesCompleted) destroy(entries_[i].object);
            else entries_[kept++] = std::move(entries_[i]);
        }
        entries_.erase(entries_.begin() + static_cast<std::ptrdiff_t>(kept), entries_.end());
    }
    // The device is idle: every one goes.
    template <class Destroy>
    void destroyAll(Destroy&& destroy) noexcept {
        for (Entry& e : entries_) destroy(e.object);
        entries_.clear();
    }
    std::size_t size() const noexcept { return entries_.size(); }

private:
    struct Entry {
        std::uint64_t frame;
        Object object;
    };
    std::vector<Entry> entries_;
};

}  // namespace ssam::vk::detail
