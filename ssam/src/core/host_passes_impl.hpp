// SPDX-License-Identifier: MIT
#pragma once
// HostPasses' calls (ssam/core/host_passes.hpp), written once over the API's Impl, which has:
// channel (HostChannel), settings, run(body) and fail(status, text) (a Failure or any exception
// to its Status and message, the open frame abandoned), beginFrame(frame) -> FrameReport,
// render(frame, draw, user) -> FrameReport, beginFoliagePass(pass) -> PassInfo,
// endFoliagePass(pass) and compositeFrame(). Each API's .cpp includes this and instantiates
// HostPasses for its types. Every call on a moved-from object (no Impl) returns InvalidCall.
#include "ssam/core/host_passes.hpp"

namespace ssam {

template <class Host, class FrameDesc, class FoliageProgram, class PassInfo>
void HostPasses<Host, FrameDesc, FoliageProgram, PassInfo>::setMessageCallback(MessageCallback callback,
                                                                               void* user) noexcept {
    if (auto* s = impl()) s->channel.setCallback(callback, user);
}

template <class Host, class FrameDesc, class FoliageProgram, class PassInfo>
const char* HostPasses<Host, FrameDesc, FoliageProgram, PassInfo>::lastMessage() const noexcept {
    const auto* s = impl();
    return s ? s->channel.lastMessage() : Host::kMovedFrom;
}

template <class Host, class FrameDesc, class FoliageProgram, class PassInfo>
const Settings& HostPasses<Host, FrameDesc, FoliageProgram, PassInfo>::settings() const noexcept {
    static const Settings defaults;
    const auto* s = impl();
    return s ? s->settings : defaults;
}

template <class Host, class FrameDesc, class FoliageProgram, class PassInfo>
Status HostPasses<Host, FrameDesc, FoliageProgram, PassInfo>::render(const FrameDesc& frame, DrawFoliage draw,
                                                                     void* user, FrameReport* report) noexcept {
    auto* s = impl();
    if (!s) return Status::InvalidCall;
    if (report) *report = {};
    if (!draw) return s->fail(Status::InvalidArgument, Host::kRenderWithoutCallback);
    return s->run([&] {
        const FrameReport done = s->render(frame, draw, user);
        if (report) *report = done;
    });
}

template <class Host, class FrameDesc, class FoliageProgram, class PassInfo>
Status HostPasses<Host, FrameDesc, FoliageProgram, PassInfo>::beginFrame(const FrameDesc& frame,
                                                                         FrameReport* report) noexcept {
    auto* s = impl();
    if (!s) return Status::InvalidCall;
    if (report) *report = {};
    return s->run([&] {
        const FrameReport begun = s->beginFrame(frame);
        if (report) *report = begun;
    });
}

namespace core {

// begin...Pass: the pass's PassInfo into `info` (where given).
template <class Impl, class PassInfo>
Status beginFoliagePass(Impl* s, FoliagePass pass, PassInfo* info) noexcept {
    if (!s) return Status::InvalidCall;
    return s->run([&] {
        const PassInfo begun = s->beginFoliagePass(pass);
        if (info) *info = begun;
    });
}

template <class Impl>
Status endFoliagePass(Impl* s, FoliagePass pass) noexcept {
    if (!s) return Status::InvalidCall;
    return s->run([&] { s->endFoliagePass(pass); });
}

}  // namespace core

template <class Host, class FrameDesc, class FoliageProgram, class PassInfo>
Status HostPasses<Host, FrameDesc, FoliageProgram, PassInfo>::beginMaskPass(PassInfo* info) noexcept {
    return core::beginFoliagePass(impl(), FoliagePass::Mask, info);
}

template <class Host, class FrameDesc, class FoliageProgram, class PassInfo>
Status HostPasses<Host, FrameDesc, FoliageProgram, PassInfo>::endMaskPass() noexcept {
    return core::endFoliagePass(impl(), FoliagePass::Mask);
}

template <class Host, class FrameDesc, class FoliageProgram, class PassInfo>
Status HostPasses<Host, FrameDesc, FoliageProgram, PassInfo>::beginColorPass(PassInfo* info) noexcept {
    return core::beginFoliagePass(impl(), FoliagePass::Color, info);
}

template <class Host, class FrameDesc, class FoliageProgram, class PassInfo>
Status HostPasses<Host, FrameDesc, FoliageProgram, PassInfo>::endColorPass() noexcept {
    return core::endFoliagePass(impl(), FoliagePass::Color);
}

template <class Host, class FrameDesc, class FoliageProgram, class PassInfo>
Status HostPasses<Host, FrameDesc, FoliageProgram, PassInfo>::composite() noexcept {
    auto* s = impl();
    if (!s) return Status::InvalidCall;
    return s->run([&] { s->compositeFrame(); });
}

}  // namespace ssam
