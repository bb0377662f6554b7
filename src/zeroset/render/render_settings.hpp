// What to render and how: image size, samples, threads, progress reporting.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "zeroset/accel/octree.hpp"
#include "zeroset/render/tile_work.hpp"
#include "zeroset/trace/method.hpp"

namespace zeroset {

struct RenderSettings {
    int width = 640;
    int height = 480;
    int samples_per_pixel = 1;
    /// Antialias edges with one ray per pixel by cone tracing its footprint
    /// (render/cone_tracer.hpp) instead of with more samples; needs
    /// samples_per_pixel = 1.
    bool cone_antialiasing = false;
    int threads = 0;  // 0: all hardware threads
    /// Also fill the image's depth and normal layers (render/image.hpp).
    bool layers = false;
    /// When given, every object is intersected with this method instead of its own.
    std::optional<Method> method;
    /// When given, the `polynomial` method's solver for every object.
    std::optional<PolynomialSolver> solver;
    /// When given, how every object's normals are computed.
    std::optional<NormalMode> normals;
    /// When given, every object's spatial partitioning (accel/octree.hpp).
    std::optional<Partition> partition;
    /// Cull each image tile's frustum against the partitioned objects before
    /// their camera rays are traced (accel/frustum_cull.hpp), prove tiles
    /// free of polynomial surfaces (accel/polynomial_tile_proof.hpp), list
    /// blobs' components by tile, and leave tiles proven to show no object
    /// to the background, untraced (Primitive::misses_tile); off only to
    /// compare.
    bool frustum_culling = true;
    /// Evaluations of f (point, interval and gradient) the whole render may
    /// spend before it stops with a RenderError; default_evaluation_budget
    /// when absent.
    std::optional<std::uint64_t> max_evaluations;
    /// Called after every finished tile with (tiles done, tiles in all), from
    /// one thread at a time.
    std::function<void(int, int)> on_progress;
    /// Called after every finished tile with its place and what it cost,
    /// from one thread at a time (`zeroset render --tile-log`).
    std::function<void(const TileRect&, const TileWork&)> on_tile;
    /// Called as an object's octree is built, before tracing, with (parts
    /// done, parts in all), from one thread at a time.
    std::function<void(int, int)> on_prepare_progress;
};

/// A render that cannot be done (bad settings, a scene that evaluates to NaN…).
class RenderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The largest image side, in pixels, any renderer here accepts.
inline constexpr int max_image_side = 65536;
/// The most pixels an image may have: 2^28, whose linear float image takes
/// 3 GiB (plus the 8-bit copy a PNG is encoded from).
inline constexpr long long max_image_pixels = 1LL << 28;

/// The evaluations a render may spend by default: 2^14 per camera ray on
/// average (more than a hundred times what the project's scenes take,
/// shadow rays included), and at least 2^22, so that a tiny image still
/// affords the worst single ray. It stops a render that would otherwise
/// take hours — a surface with detail finer than a pixel everywhere, or
/// bounds far larger than the surface — with a message, not a hang.
inline constexpr std::uint64_t evaluations_per_camera_ray = 1U << 14;
inline constexpr std::uint64_t least_evaluation_budget = 1U << 22;
[[nodiscard]] std::uint64_t default_evaluation_budget(const RenderSettings& settings);

/// Throws RenderError unless width × height ≤ max_image_pixels, saying how
/// much memory the image would take.
void require_image_fits(int width, int height);

/// Checks sizes and counts; throws RenderError with a message naming the option.
void validate(const RenderSettings& settings);

/// Throws RenderError("WHAT must be between LOW and HIGH, got VALUE") unless
/// low ≤ value ≤ high.
void require_in_range(int value, int low, int high, const char* what);

}  // namespace zeroset
