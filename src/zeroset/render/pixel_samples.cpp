// Jittered Latin-hypercube pixel samples from a counter-based hash.
#include "zeroset/render/pixel_samples.hpp"

namespace zeroset {

namespace {

/// A well-mixed 64-bit hash (SplitMix64's finaliser).
std::uint64_t mix(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

double unit(std::uint64_t h) { return static_cast<double>(h >> 11) * 0x1.0p-53; }

}  // namespace

SubPixel pixel_sample(int px, int py, int index, int count) {
    if (count == 1) return {0.5, 0.5};
    const std::uint64_t pixel = mix((static_cast<std::uint64_t>(static_cast<std::uint32_t>(py)) << 32) |
                                    static_cast<std::uint32_t>(px));
    // Column strata are a per-pixel random permutation of the row strata: the
    // rank of this sample's hashed key among all keys of the pixel. That is
    // O(count) per sample, cheap next to tracing for the counts allowed.
    const std::uint64_t key = mix(pixel ^ static_cast<std::uint64_t>(index));
    int column = 0;
    for (int j = 0; j < count; ++j)
        if (mix(pixel ^ static_cast<std::uint64_t>(j)) < key) ++column;
    const double jx = unit(mix(key + 1)), jy = unit(mix(key + 2));
    return {(column + jx) / count, (index + jy) / count};
}

}  // namespace zeroset
