// SPDX-License-Identifier: MIT
#pragma once
// How much the process's peak resident memory grew over a scope (Linux): the peak is reset
// to the current RSS (/proc/self/clear_refs, "5") at construction and read back from
// VmHWM. Unlike the counted backend resources this sees CPU-side memory too (the exact
// reference's fragment lists, llvmpipe's own allocations), but it is noisy: memory the
// allocator kept from earlier work is reused without growing the RSS. NaN where /proc is
// unavailable.
namespace bench {

class RssPeak {
public:
    RssPeak();
    double growthMb() const;  // MiB above the RSS at construction

private:
    double startKb_;
};

}  // namespace bench
