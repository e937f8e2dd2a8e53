// SPDX-License-Identifier: MIT
#pragma once
// The engine's one parallel loop (the soft backend's tiles, set-up and resolves, the image
// metrics, the wind): oneTBB's parallel_for, with its fork and join stated to ThreadSanitizer.
//
// Why: Debian's libtbb is not built with -fsanitize=thread, so TSan cannot see that a task
// starts after the caller's writes, nor that parallel_for returns after every task's writes:
// those hand-offs happen in the library's own atomics. It then reports each of them as a race
// (a tile written by a worker, read back by the caller). The annotations state exactly these
// two edges, on one token per loop: the caller releases before the loop and each chunk
// acquires when it starts (fork); each chunk releases when it ends and the caller acquires
// after the loop (join). A real race inside the loop body is still reported. Without TSan
// they compile to nothing.
//
// Header-only and oneTBB's: include it only from code that links TBB::tbb. Where there is no
// oneTBB (the web page's WebAssembly build: CMake option SSAM_WITH_TBB off defines
// ENGINE_SERIAL_LOOPS), the same loops run in order on the calling thread.
#include <algorithm>
#include <cstddef>
#if !defined(ENGINE_SERIAL_LOOPS)
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#if defined(__SANITIZE_THREAD__)
#define ENGINE_THREAD_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define ENGINE_THREAD_SANITIZER 1
#endif
#endif
#if defined(ENGINE_THREAD_SANITIZER)
#include <sanitizer/tsan_interface.h>
#endif

namespace engine {

namespace parallel_detail {
// One loop's fork and join, as TSan's happens-before edges (see the top of this file).
class HandOff {
public:
    void release() noexcept {
#if defined(ENGINE_THREAD_SANITIZER)
        __tsan_release(&token_);
#endif
    }
    void acquire() noexcept {
#if defined(ENGINE_THREAD_SANITIZER)
        __tsan_acquire(&token_);
#endif
    }

private:
    [[maybe_unused]] char token_ = 0;
};
}  // namespace parallel_detail

#if defined(ENGINE_SERIAL_LOOPS)
// No oneTBB: body(i) for every i in [begin, end), in order, on this thread.
template <typename Index, typename Body>
void parallelFor(Index begin, Index end, const Body& body) {
    for (Index i = begin; i < end; ++i) body(i);
}

// No oneTBB: body(first, last) over consecutive chunks of `grain` indices (the last may be
// shorter), in order, on this thread.
template <typename Index, typename Body>
void parallelForChunks(Index begin, Index end, Index grain, const Body& body) {
    const Index step = std::max(grain, Index(1));
    for (Index first = begin; first < end;) {
        const Index last = end - first > step ? first + step : end;
        body(first, last);
        first = last;
    }
}
#else
// body(i) for every i in [begin, end), in parallel (oneTBB's auto partitioner).
template <typename Index, typename Body>
void parallelFor(Index begin, Index end, const Body& body) {
    parallel_detail::HandOff handOff;
    handOff.release();
    tbb::parallel_for(begin, end, [&](Index i) {
        handOff.acquire();
        body(i);
        handOff.release();
    });
    handOff.acquire();
}

// body(first, last) over chunks of [begin, end) of at least `grain` indices, in parallel.
template <typename Index, typename Body>
void parallelForChunks(Index begin, Index end, Index grain, const Body& body) {
    parallel_detail::HandOff handOff;
    handOff.release();
    tbb::parallel_for(tbb::blocked_range<Index>(begin, end, grain), [&](const tbb::blocked_range<Index>& chunk) {
        handOff.acquire();
        body(chunk.begin(), chunk.end());
        handOff.release();
    });
    handOff.acquire();
}
#endif

}  // namespace engine
