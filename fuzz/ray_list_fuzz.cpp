// Fuzz target: the ray list of `zeroset ray --rays`. Any text is either a
// list of rays with finite components and nonzero directions or a
// RayListError naming its line.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fuzz_support.hpp"
#include "ray_list.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace zeroset;
    try {
        for (const Ray& ray : cli::parse_ray_list(fuzz::as_text(data, size), "fuzz.rays")) {
            const bool finite = std::isfinite(ray.origin.x) && std::isfinite(ray.origin.y) &&
                                std::isfinite(ray.origin.z) && std::isfinite(ray.dir.x) && std::isfinite(ray.dir.y) &&
                                std::isfinite(ray.dir.z);
            if (!finite || ray.dir == Vec3d{}) std::abort();  // the reader promised otherwise
        }
    } catch (const cli::RayListError&) {
    }
    return 0;
}
