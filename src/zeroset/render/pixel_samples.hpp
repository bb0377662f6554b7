// Stratified supersampling: N samples in a pixel, one per row stratum and one
// per column stratum (a jittered Latin hypercube), so any N stratifies well.
// The jitter comes from a hash of the pixel, so an image does not depend on
// the number of threads. A single sample sits at the pixel centre.
#pragma once

#include <cstdint>

namespace zeroset {

struct SubPixel {
    double x;
    double y;
};

/// Sample `index` of `count` in pixel (px, py), in [0, 1)².
SubPixel pixel_sample(int px, int py, int index, int count);

}  // namespace zeroset
