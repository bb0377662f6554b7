// LargeBuffer: a vector for the renderer's big per-frame buffers (an
// image's pixels and layers). Fresh memory from the system is mapped one
// 4 KiB page at a time when first touched, and in a virtual machine each of
// those page faults costs about 10 µs: the 900 of a 640×480 image took
// 10 ms, half the render of a nearly empty scene and a tenth of most. A
// buffer of 2 MiB or more is aligned to 2 MiB and offered to the kernel as
// transparent huge pages (madvise), so that it faults in a few large pages.
// Where the kernel declines (THP off), nothing changes but the alignment.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <limits>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace zeroset {

template <class T>
struct LargeBufferAllocator {
    static_assert(alignof(T) <= alignof(std::max_align_t), "small buffers come from malloc, aligned for max_align_t only");
    using value_type = T;
    static constexpr std::size_t huge_page = std::size_t{2} << 20;

    LargeBufferAllocator() = default;
    template <class U>
    LargeBufferAllocator(const LargeBufferAllocator<U>&) noexcept {}  // NOLINT: converting, as allocators are

    T* allocate(std::size_t n) {
        constexpr auto largest = static_cast<std::size_t>(std::numeric_limits<std::ptrdiff_t>::max()) - huge_page;
        if (n > largest / sizeof(T)) throw std::bad_array_new_length();
        const std::size_t bytes = n * sizeof(T);
        void* p = nullptr;
        if (bytes < huge_page) {
            p = std::malloc(bytes == 0 ? 1 : bytes);
        } else {
            const std::size_t rounded = (bytes + huge_page - 1) / huge_page * huge_page;
            p = std::aligned_alloc(huge_page, rounded);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
            if (p) madvise(p, rounded, MADV_HUGEPAGE);  // advice only: its failure changes nothing
#endif
        }
        if (!p) throw std::bad_alloc();
        return static_cast<T*>(p);
    }

    void deallocate(T* p, std::size_t) noexcept { std::free(p); }

    template <class U>
    bool operator==(const LargeBufferAllocator<U>&) const noexcept {
        return true;
    }
};

template <class T>
using LargeBuffer = std::vector<T, LargeBufferAllocator<T>>;

}  // namespace zeroset
