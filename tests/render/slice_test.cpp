// Slices: every pixel of a sliced image has the sign of f at its centre —
// certainly where an interval decided its tile, and up to float rounding
// where it was evaluated on a pruned tape — and the tile quadtree shrinks a
// real CSG model's tape by orders of magnitude.
#include <gtest/gtest.h>
#include "support/models.hpp"

#include <cmath>
#include <fstream>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/vm_import.hpp"
#include "zeroset/render/render_settings.hpp"
#include "zeroset/render/slice.hpp"
#include "zeroset/render/slice_image.hpp"

namespace zeroset {
namespace {

/// The centre of pixel i along an axis of `size` pixels over [min, max], as slice() computes it.
float centre(const SlicePlane& p, int size, int i) {
    return static_cast<float>(p.min + (i + 0.5) * ((p.max - p.min) / size));
}
float centre_from_top(const SlicePlane& p, int size, int j) {
    return static_cast<float>(p.max - (j + 0.5) * ((p.max - p.min) / size));
}

/// Compares every pixel with the full tape at the pixel's centre in double:
/// the signs agree wherever |f| is clear of float rounding; the evaluated
/// values agree to float precision. Returns the number of pixels compared
/// (every `stride`-th pixel in both directions).
int expect_agrees_with_full_tape(const Tape& tape, const SliceSettings& settings, const SliceField& field,
                                 double rounding, int stride = 1) {
    Evaluator<double> f(tape);
    int compared = 0;
    for (int j = 0; j < field.size; j += stride) {
        for (int i = 0; i < field.size; i += stride) {
            const double u = centre(settings.plane, settings.size, i);
            const double v = centre_from_top(settings.plane, settings.size, j);
            const double w = static_cast<float>(settings.plane.at);
            const double exact = settings.plane.axis == 2 ? f(u, v, w) : settings.plane.axis == 1 ? f(u, w, v) : f(w, u, v);
            const float got = field.at(i, j);
            if (std::isnan(exact)) {
                EXPECT_TRUE(std::isnan(got)) << i << "," << j;
                continue;
            }
            if (std::abs(exact) <= rounding) continue;
            ++compared;
            EXPECT_EQ(got < 0.0f, exact < 0.0) << "pixel " << i << "," << j << ": " << got << " vs " << exact;
            if (settings.every_pixel) {
                EXPECT_NEAR(got, exact, rounding) << i << "," << j;
            }
        }
    }
    return compared;
}

Expr disc(double cx, double cy, double r) { return sqrt(square(var_x() - cx) + square(var_y() - cy)) - r; }

TEST(Slice, UnionOfDiscsHasTheSignOfEveryPixelCentre) {
    const Tape tape(min(min(disc(-0.5, 0.2, 0.3), disc(0.4, -0.3, 0.25)), disc(0.6, 0.6, 0.01)));
    SliceSettings settings;
    settings.size = 200;  // not a power of two: partial tiles at the edges
    const SliceField field = slice(tape, settings);
    EXPECT_GT(expect_agrees_with_full_tape(tape, settings, field, 1e-5), 39000);
    EXPECT_GT(field.stats.pixels_decided, 30000u) << "most of the square is far from the discs";
    EXPECT_LT(field.stats.pixels_evaluated, 10000u);
    EXPECT_EQ(field.stats.pixels_decided + field.stats.pixels_evaluated, 200u * 200u);
}

TEST(Slice, EveryPixelModeGivesTheValues) {
    const Tape tape(min(disc(-0.5, 0.2, 0.3), disc(0.4, -0.3, 0.25)));
    SliceSettings settings;
    settings.size = 96;
    settings.every_pixel = true;
    const SliceField field = slice(tape, settings);
    EXPECT_EQ(field.stats.pixels_decided, 0u);
    EXPECT_EQ(expect_agrees_with_full_tape(tape, settings, field, 1e-5), 96 * 96);
}

TEST(Slice, ImageAxesFollowThePlane) {
    // f = u − 0.5 for the plane's horizontal axis u, and v for the vertical:
    // column 0 is u = min, row 0 is v = max.
    for (int axis = 0; axis < 3; ++axis) {
        const Expr u = axis == 0 ? var_y() : var_x();
        const Expr v = axis == 2 ? var_y() : var_z();
        SliceSettings settings;
        settings.size = 40;
        settings.plane.axis = axis;
        settings.plane.at = 0.25;
        const SliceField across = slice(Tape(u - 0.5), settings);
        EXPECT_LT(across.at(0, 20), 0.0f) << axis;
        EXPECT_GT(across.at(39, 20), 0.0f) << axis;
        const SliceField up = slice(Tape(v - 0.5), settings);
        EXPECT_GT(up.at(20, 0), 0.0f) << axis;
        EXPECT_LT(up.at(20, 39), 0.0f) << axis;
        const Expr w = axis == 0 ? var_x() : axis == 1 ? var_y() : var_z();
        const SliceField at = slice(Tape(w - 0.2), settings);  // 0.25 − 0.2 > 0 everywhere
        EXPECT_EQ(at.stats.pixels_decided, 40u * 40u) << axis;
    }
}

TEST(Slice, ProsperoMatchesTheFullTapeWithTapesShrunkAHundredfold) {
    ZEROSET_SKIP_WITHOUT_MODEL("prospero.vm");

    std::ifstream in(ZEROSET_MODELS_DIR "/prospero.vm");
    const Tape tape(import_vm(in));
    SliceSettings settings;
    settings.size = 512;
    const SliceField field = slice(tape, settings);
    // Every fourth pixel both ways keeps the full-tape oracle to a second.
    EXPECT_GT(expect_agrees_with_full_tape(tape, settings, field, 1e-4, 4), 125 * 125);
    const SliceStats& s = field.stats;
    ASSERT_GT(s.leaf_batches, 0u);
    EXPECT_LT(s.leaf_clauses / s.leaf_batches, s.full_clauses / 20);
    EXPECT_LT(s.max_leaf_slots, s.full_slots / 5);
    EXPECT_GT(s.pixels_decided, 512u * 512u / 4);
}

TEST(Slice, UndefinedRegionsAreNaNAndMagenta) {
    const Tape tape(sqrt(var_x()) - 0.5);  // undefined for x < 0
    SliceSettings settings;
    settings.size = 64;
    const SliceField field = slice(tape, settings);
    EXPECT_EQ(expect_agrees_with_full_tape(tape, settings, field, 1e-6) > 0, true);
    EXPECT_TRUE(std::isnan(field.at(5, 30)));
    const Image image = slice_image(field, SliceShading::Sign, 0.1);
    EXPECT_EQ(image.at(5, 30).y, 0.0f);
    EXPECT_EQ(image.at(5, 30).x, 1.0f);
    EXPECT_EQ(image.at(60, 30).x, 1.0f) << "outside is white";
    EXPECT_EQ(image.at(36, 30).x, 0.0f) << "inside (0 < x < 0.25) is black";
}

TEST(Slice, ValueImageDrawsTheZeroContour) {
    const Tape tape(disc(0.0, 0.0, 0.5));
    SliceSettings settings;
    settings.size = 100;
    settings.every_pixel = true;
    const Image image = slice_image(slice(tape, settings), SliceShading::Value, 0.125);
    // Along the middle row the circle crosses at x = ±0.5: pixels 24/25 and 74/75.
    int black = 0;
    for (int i = 0; i < 100; ++i) {
        const Vec3f p = image.at(i, 50);
        if (p.x == 0.0f && p.y == 0.0f && p.z == 0.0f) {
            ++black;
            EXPECT_TRUE(i == 24 || i == 25 || i == 74 || i == 75) << i;
        }
    }
    EXPECT_EQ(black, 4);
    EXPECT_GT(image.at(50, 50).z, image.at(50, 50).x) << "inside is blue";
    EXPECT_GT(image.at(2, 50).x, image.at(2, 50).z) << "outside is orange";
}

TEST(Slice, ImpossibleSettingsAreErrors) {
    const Tape tape(var_x());
    SliceSettings settings;
    settings.size = 0;
    EXPECT_THROW(slice(tape, settings), RenderError);
    settings.size = 16;
    settings.plane.min = 1.0;
    settings.plane.max = -1.0;
    EXPECT_THROW(slice(tape, settings), RenderError);
    settings.plane = {};
    settings.plane.at = INFINITY;
    EXPECT_THROW(slice(tape, settings), RenderError);
    settings.plane = {};
    settings.plane.axis = 3;
    EXPECT_THROW(slice(tape, settings), RenderError);
    settings.plane = {};
    settings.plane.max = 1e30;  // the edge of what float samples well
    EXPECT_NO_THROW(slice(tape, settings));
    settings.plane.max = 2e30;
    EXPECT_THROW(slice(tape, settings), RenderError);
}

}  // namespace
}  // namespace zeroset
