// TraceCounters: the work a ray query spends, so methods can be compared on
// the same ray (DESIGN.md) and the renderer can report totals.
#pragma once

#include <cstdint>
#include <limits>

namespace zeroset {

struct TraceCounters {
    std::uint64_t point_evaluations = 0;     // f at a point
    std::uint64_t interval_evaluations = 0;  // f over a box
    std::uint64_t gradient_evaluations = 0;  // f and ∇f over a box (for a Lipschitz bound)
    std::uint64_t nan_evaluations = 0;       // point evaluations that gave NaN
    std::uint64_t failed_queries = 0;        // ray queries a method gave up on (a budget spent), answered "no hit"
    std::uint64_t cell_visits = 0;           // octree cells a method ran in (accel/octree.hpp)
    std::uint64_t blob_kernels = 0;          // blob components a ray came within reach of (accel/blob.hpp)
    std::uint64_t blob_list_rays = 0;        // camera rays that met a blob's components by their tile's list
    std::uint64_t blob_cached_shadows = 0;   // shadow rays a blob's last blocker settled
    std::uint64_t proven_tile_rays = 0;      // camera rays a polynomial leaf's tile proof answered (accel/polynomial_tile_proof.hpp)
    /// Not a count: once evaluations() passes it, the subdividing methods
    /// give up (Failed) at their next segment. The renderer sets its budget
    /// here, so that one query cannot run far past it.
    std::uint64_t evaluation_limit = std::numeric_limits<std::uint64_t>::max();

    [[nodiscard]] std::uint64_t evaluations() const {
        return point_evaluations + interval_evaluations + gradient_evaluations;
    }
    [[nodiscard]] bool over_limit() const { return evaluations() > evaluation_limit; }

    TraceCounters& operator+=(const TraceCounters& o) {
        point_evaluations += o.point_evaluations;
        interval_evaluations += o.interval_evaluations;
        gradient_evaluations += o.gradient_evaluations;
        nan_evaluations += o.nan_evaluations;
        failed_queries += o.failed_queries;
        cell_visits += o.cell_visits;
        blob_kernels += o.blob_kernels;
        blob_list_rays += o.blob_list_rays;
        blob_cached_shadows += o.blob_cached_shadows;
        proven_tile_rays += o.proven_tile_rays;
        return *this;
    }

    /// The counts made since `before` (a snapshot of the same counters),
    /// with no evaluation_limit: what one piece of work cost.
    [[nodiscard]] TraceCounters since(const TraceCounters& before) const {
        TraceCounters d;
        d.point_evaluations = point_evaluations - before.point_evaluations;
        d.interval_evaluations = interval_evaluations - before.interval_evaluations;
        d.gradient_evaluations = gradient_evaluations - before.gradient_evaluations;
        d.nan_evaluations = nan_evaluations - before.nan_evaluations;
        d.failed_queries = failed_queries - before.failed_queries;
        d.cell_visits = cell_visits - before.cell_visits;
        d.blob_kernels = blob_kernels - before.blob_kernels;
        d.blob_list_rays = blob_list_rays - before.blob_list_rays;
        d.blob_cached_shadows = blob_cached_shadows - before.blob_cached_shadows;
        d.proven_tile_rays = proven_tile_rays - before.proven_tile_rays;
        return d;
    }
};

}  // namespace zeroset
