// RenderStats: what a render cost, and its one-line summary (like POV-Ray's).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "zeroset/trace/trace_counters.hpp"

namespace zeroset {

/// Cone antialiasing's work (render/cone_tracer.hpp).
struct ConeCounters {
    std::uint64_t steps = 0;         // distance bounds taken along cones
    std::uint64_t edges = 0;         // edge samples shaded
    std::uint64_t missed_edges = 0;  // edges whose aimed rays found no surface in the cone (not blended)
    std::uint64_t aimed_rays = 0;    // rays aimed across edges
    std::uint64_t gave_up = 0;       // cones stopped at max_steps
    std::uint64_t evaluations = 0;   // of the distance bounds

    ConeCounters& operator+=(const ConeCounters& o) {
        steps += o.steps, edges += o.edges, missed_edges += o.missed_edges;
        aimed_rays += o.aimed_rays, gave_up += o.gave_up, evaluations += o.evaluations;
        return *this;
    }
};

struct RenderStats {
    int width = 0;
    int height = 0;
    int samples_per_pixel = 0;
    int threads = 0;
    double seconds = 0.0;          // the whole render
    double prepare_seconds = 0.0;  // of which preparing the scene (tapes, methods, BVHs)
    std::uint64_t camera_rays = 0;
    std::uint64_t untraced_camera_rays = 0;  // of those, in tiles proven to see no surface: the background, untraced
    std::uint64_t shadow_rays = 0;
    std::uint64_t reflection_rays = 0;
    [[nodiscard]] std::uint64_t rays() const { return camera_rays + shadow_rays + reflection_rays; }
    std::uint64_t hits = 0;
    bool cone_antialiasing = false;
    ConeCounters cone;  // all zero without cone antialiasing
    TraceCounters counters;
    /// The distinct objects (leaves) by the method that traces them;
    /// planes count as "plane".
    std::vector<std::pair<std::string, int>> methods;
    /// PreparedScene::partition_summary().
    std::string partitions;
    /// PreparedScene::blob_summary().
    std::string blobs;
    /// PreparedScene::warnings().
    std::vector<std::string> warnings;
};

/// "800x600, 1 spp, 2 threads: 1.23 s (prepare 0.01 s, trace 1.22 s); 790000 rays (480000 camera, 310000 shadow), 150000 hits; 10.2M evaluations (9.1M point, 0.8M interval, 0.3M gradient); objects: polynomial 2, sphere 1"
std::string summary_line(const RenderStats& stats);

}  // namespace zeroset
