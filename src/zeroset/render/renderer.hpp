// The renderer: camera rays → nearest hit → shading → image (with depth and
// normal layers on request), in tiles spread over all cores. Each thread owns its tracer, so tiles share nothing mutable.
#pragma once

#include "zeroset/render/image.hpp"
#include "zeroset/render/render_settings.hpp"
#include "zeroset/render/render_stats.hpp"
#include "zeroset/scene/scene.hpp"

namespace zeroset {

struct RenderResult {
    Image image;
    RenderStats stats;
};

/// Renders the scene; throws RenderError for bad settings or when a surface
/// function evaluates to NaN (the message names the object and the point).
RenderResult render(const Scene& scene, const RenderSettings& settings);

}  // namespace zeroset
