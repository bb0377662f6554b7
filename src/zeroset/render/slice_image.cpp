// Colouring a slice. The zero contour is where a pixel's sign differs from a
// neighbour's, which needs no gradient and never misses a sign change between
// pixel centres.
#include "zeroset/render/slice_image.hpp"

#include <cmath>
#include <numbers>

namespace zeroset {

namespace {

const Vec3f undefined_colour{1.0f, 0.0f, 1.0f};
const Vec3f inside_colour{0.10f, 0.30f, 0.80f};
const Vec3f outside_colour{0.90f, 0.45f, 0.10f};

bool on_contour(const SliceField& field, int x, int y) {
    const bool inside = field.at(x, y) < 0.0f;
    const auto differs = [&](int nx, int ny) {
        if (nx < 0 || ny < 0 || nx >= field.size || ny >= field.size) return false;
        const float v = field.at(nx, ny);
        return v == v && (v < 0.0f) != inside;
    };
    return differs(x + 1, y) || differs(x - 1, y) || differs(x, y + 1) || differs(x, y - 1);
}

Vec3f value_colour(float f, double band) {
    const Vec3f base = f < 0.0f ? inside_colour : outside_colour;
    // Bands: brightness waves once per `band` of f, fading out far from 0.
    const double phase = std::abs(f) / band;
    const auto wave = static_cast<float>(0.5 + 0.5 * std::cos(2.0 * std::numbers::pi * phase));
    const auto fade = static_cast<float>(std::exp(-0.15 * phase));
    const float light = 0.65f + 0.35f * wave * fade;
    return base * light;
}

}  // namespace

Image slice_image(const SliceField& field, SliceShading shading, double band) {
    Image image(field.size, field.size);
    for (int y = 0; y < field.size; ++y) {
        for (int x = 0; x < field.size; ++x) {
            const float f = field.at(x, y);
            Vec3f& pixel = image.at(x, y);
            if (f != f) {
                pixel = undefined_colour;
            } else if (shading == SliceShading::Sign) {
                pixel = f < 0.0f ? Vec3f{0.0f, 0.0f, 0.0f} : Vec3f{1.0f, 1.0f, 1.0f};
            } else {
                pixel = on_contour(field, x, y) ? Vec3f{0.0f, 0.0f, 0.0f} : value_colour(f, band);
            }
        }
    }
    return image;
}

}  // namespace zeroset
