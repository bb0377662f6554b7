// Pictures of a slice (render/slice.hpp): the sign of f in black and white
// (inside black), or its value as a colour map with the zero contour drawn.
#pragma once

#include "zeroset/render/image.hpp"
#include "zeroset/render/slice.hpp"

namespace zeroset {

enum class SliceShading {
    Sign,   // f < 0 black, f ≥ 0 white
    Value,  // inside blue, outside orange, banded every `band` units of f; the zero contour black
};

/// The picture of `field`; pixels where f is NaN are magenta. For Value the
/// field must have every pixel evaluated (SliceSettings::every_pixel).
Image slice_image(const SliceField& field, SliceShading shading, double band);

}  // namespace zeroset
