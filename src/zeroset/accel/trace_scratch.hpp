// TraceScratch: what one render thread writes while it traces — per-leaf
// evaluators and root finders (made on a leaf's first use, so a scene of
// 100 000 objects costs only what a thread actually touches), reusable span
// buffers for CSG, the evaluation counters, and the first NaN met. The
// primitives themselves stay shared and read-only.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "zeroset/accel/camera_frustum.hpp"
#include "zeroset/accel/surface_ref.hpp"
#include "zeroset/trace/trace_counters.hpp"

namespace zeroset {

class LeafPrimitive;
struct LeafScratch;
struct BlobScratch;

class TraceScratch {
public:
    /// For a tree of `leaf_count` implicit leaves (ids 0 … leaf_count − 1).
    explicit TraceScratch(std::size_t leaf_count);
    ~TraceScratch();
    TraceScratch(const TraceScratch&) = delete;
    TraceScratch& operator=(const TraceScratch&) = delete;

    TraceCounters counters;

    /// Where a leaf's function first evaluated to NaN.
    struct NanRecord {
        const LeafPrimitive* leaf;
        Vec3d point;  // in the leaf's own space
    };
    std::optional<NanRecord> first_nan;

    /// While a camera ray's first hit is traced: the rays of its image
    /// tile, in the space of the primitive being asked (an instance carries
    /// them into its child's, CameraFrustumScope), and the ray's pixel in
    /// the tile; null for every other ray. Leaves that cull a tile's
    /// frustum (accel/frustum_cull.hpp) read it.
    const CameraFrustum* camera_frustum = nullptr;
    int camera_pixel = 0;
    /// While the renderer asks whether a camera tile shows nothing
    /// (Primitive::misses_tile): whether rows of the tile have been traced
    /// and all missed. A leaf then tries its tile proof, though its misses
    /// were cheap (a thin object most rays pass).
    bool tile_rows_missed = false;

    /// The scratch slot of leaf `id` (empty until the leaf fills it).
    std::unique_ptr<LeafScratch>& leaf(std::size_t id) { return leaves_.at(id); }

    /// The blobs' scratch (empty until a blob fills it): one for all of
    /// them, as a blob's query never runs another's.
    std::unique_ptr<BlobScratch>& blob() { return blob_; }

    /// A cleared span list for the caller's use until the lease ends; leases
    /// end in the reverse order of their start (queries nest).
    class SpanLease {
    public:
        explicit SpanLease(TraceScratch& scratch);
        ~SpanLease() { --scratch_.spans_in_use_; }
        SpanLease(const SpanLease&) = delete;
        SpanLease& operator=(const SpanLease&) = delete;
        SpanList& operator*() const { return *list_; }
        SpanList* operator->() const { return list_; }

    private:
        TraceScratch& scratch_;
        SpanList* list_;
    };

    /// The child of a group that last blocked a shadow ray, which blocks the
    /// next one from a neighbouring pixel often (POV-Ray's shadow cache): a
    /// small table indexed by the group's address, so a collision only costs
    /// a test that fails.
    struct Occluder {
        const void* group = nullptr;
        std::uint32_t child = 0;
    };
    Occluder& last_occluder(const void* group) {
        return occluders_[(reinterpret_cast<std::uintptr_t>(group) >> 6) % occluders_.size()];
    }

    /// A camera tile carried into an instance's space (CameraFrustum::
    /// in_child_space), kept for the tile's next rays: a small table of
    /// two-way sets indexed by the instance's address, checked by the
    /// tile's serial. Two ways, so that instances whose addresses share a
    /// set (nested ones, one ray after another) do not evict each other:
    /// each eviction made a new frustum with a new serial, which the
    /// leaves' tile proofs then took for a new tile — whether that happened
    /// hung on where the allocator put the instances, and cost steiner.pov
    /// a third more work in some runs than in others.
    struct ChildTile {
        const void* instance = nullptr;
        std::uint64_t parent = 0;  // the serial of the tile it was made from
        CameraFrustum frustum;
    };
    /// The instance's slot, or the one of its set used less recently for
    /// the caller to fill.
    ChildTile& child_tile(const void* instance) {
        const std::uintptr_t a = reinterpret_cast<std::uintptr_t>(instance);
        const std::size_t set = ((a >> 4) ^ (a >> 10)) % child_tile_sets;
        std::uint8_t& recent = child_tile_recent_[set];
        for (std::uint8_t way = 0; way < 2; ++way) {
            if (child_tiles_[2 * set + way].instance == instance) {
                recent = way;
                return child_tiles_[2 * set + way];
            }
        }
        recent = static_cast<std::uint8_t>(1 - recent);
        return child_tiles_[2 * set + recent];
    }

private:
    std::vector<std::unique_ptr<LeafScratch>> leaves_;
    std::unique_ptr<BlobScratch> blob_;
    std::array<Occluder, 64> occluders_{};
    static constexpr std::size_t child_tile_sets = 16;
    std::array<ChildTile, 2 * child_tile_sets> child_tiles_{};
    std::array<std::uint8_t, child_tile_sets> child_tile_recent_{};  // the way used last in each set
    std::vector<std::unique_ptr<SpanList>> span_pool_;
    std::size_t spans_in_use_ = 0;
};

/// Sets the scratch's camera frustum for a scope, and puts the one before back.
class CameraFrustumScope {
public:
    CameraFrustumScope(TraceScratch& scratch, const CameraFrustum* frustum)
        : scratch_(scratch), before_(scratch.camera_frustum) {
        scratch.camera_frustum = frustum;
    }
    ~CameraFrustumScope() { scratch_.camera_frustum = before_; }
    CameraFrustumScope(const CameraFrustumScope&) = delete;
    CameraFrustumScope& operator=(const CameraFrustumScope&) = delete;

private:
    TraceScratch& scratch_;
    const CameraFrustum* before_;
};

}  // namespace zeroset
