// ImplicitLeaf: one implicit surface f = 0 within its bounds — the survey's
// object: a tape, a ray-intersection method chosen for it (trace/), and its
// bounds (§6.1). Its solid is {f ≤ 0} ∩ bounds: where the bounds cut through
// the solid, the cut is a face of the solid, with the bounds' normal.
//
// The first hit comes from the method's first_hit; the spans (for CSG) from
// its all_hits, with the inside and outside told apart by the sign of f
// between consecutive roots, so a tangent root neither opens nor closes a
// span by itself (it becomes a span of length 0).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "zeroset/accel/frustum_cull.hpp"
#include "zeroset/accel/octree.hpp"
#include "zeroset/accel/polynomial_tile_proof.hpp"
#include "zeroset/accel/primitive.hpp"
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/trace/bounds.hpp"
#include "zeroset/trace/root_finder.hpp"
#include "zeroset/trace/search_region.hpp"

namespace zeroset {

class TraceScratch;
class ImplicitLeaf;

/// What an implicit leaf is made of.
struct LeafDescription {
    std::string name;  // for messages
    Expr surface;
    Bounds bounds;
    Method method = Method::Auto;  // Auto is resolved by choose_method
    PolynomialSolver solver = PolynomialSolver::Fast;
    NormalMode normals = NormalMode::Analytic;
    /// The difference normals' step relative to the object's size (the
    /// diagonal of its SearchRegion's box); 0:
    /// the default of the mode (normal_step()).
    double normal_step = 0.0;
    MaterialId material = no_material;
    /// Spatial partitioning of the bounds (accel/octree.hpp); Auto is
    /// resolved by resolve_partition.
    Partition partition = Partition::Auto;
    /// The largest size of the object's bounds on screen, in pixels, that
    /// the octree's depth is chosen for (0: 512).
    int footprint_pixels = 0;
    /// Told how the octree's build goes (OctreeSettings::on_progress).
    std::function<void(int, int)> on_octree_progress;
    /// The object is its surface alone, a sheet (POV-Ray's open isosurfaces
    /// and clipped surfaces): a ray's first hit is the first root of f in
    /// the bounds, never where the bounds cut the solid or where the ray
    /// starts inside it. Its spans (for CSG) are still those of its solid.
    bool open = false;
    /// An open object's clipping (POV-Ray's clipped_by): where this
    /// expression of the object's own coordinates is positive, the surface
    /// is not drawn.
    std::optional<Expr> clip;
    /// POV-Ray's bounded_by on its unbounded surfaces: a ray that does not
    /// pass through these bounds (from its start on, without end) does not
    /// see the object; one that does sees every hit in the object's bounds,
    /// before the gate or beyond it.
    std::optional<Bounds> gate;
};

/// Auto → Lipschitz for the methods that bound f over cells (interval, LG,
/// sphere) on tapes of at least `partition_min_clauses` clauses; else None.
/// An explicit choice on another method is an error (std::invalid_argument).
inline constexpr std::size_t partition_min_clauses = 64;
Partition resolve_partition(Partition asked, Method method, const Tape& tape);
/// Cells about 8 pixels across at the given footprint: depth ⌈log₂(footprint/8)⌉, within [2, 6]
/// (deeper trees cost more than they save: bear.vm at 1024² took 174 s at depth 8, 85 s at 6).
int octree_depth_for(int footprint_pixels);

/// A thread's evaluators and root finder for one leaf.
struct LeafScratch {
    explicit LeafScratch(const ImplicitLeaf& leaf);

    RayFunction h;
    std::unique_ptr<RootFinder> finder;
    Evaluator<Dual<double>> gradient;
    Evaluator<double> value;
    std::optional<Evaluator<double>> clip;  // the clip's, when the leaf has one
    std::vector<double> roots;
    std::unique_ptr<CulledTiles> culled;  // made for the first camera tile the leaf meets
    std::unique_ptr<ProvenTiles> proven;  // made at the first costly miss of a camera ray, for a polynomial leaf
};

class ImplicitLeaf final : public LeafPrimitive {
public:
    /// `id` numbers the leaf among all leaves of its tree (TraceScratch
    /// slots). Throws std::invalid_argument when the method cannot trace the
    /// surface (the polynomial method on a non-polynomial f).
    ImplicitLeaf(std::size_t id, LeafDescription description);
    // The octree and the scratch's evaluators point at the tape inside.
    ImplicitLeaf(const ImplicitLeaf&) = delete;
    ImplicitLeaf& operator=(const ImplicitLeaf&) = delete;

    [[nodiscard]] Box3 bounds() const override { return region_.box(); }
    std::optional<Hit> first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const override;
    void spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const override;
    /// When the tile misses the search region or the gate (their boxes, or
    /// a sphere's own), or the leaf's tile proof has proven it (ProvenTiles).
    bool misses_tile(const CameraFrustum& tile, TraceScratch& scratch) const override;

    /// The unit outward normal at a boundary point, in the leaf's own space:
    /// ∇f (eq. 33) or its difference estimate (eq. 34), or the bounds'
    /// normal on a cut; the zero vector where it is undefined.
    Vec3d local_normal(const SurfaceRef& surface, TraceScratch& scratch) const override;

    [[nodiscard]] std::size_t id() const { return id_; }
    [[nodiscard]] const std::string& name() const override { return description_.name; }
    [[nodiscard]] Method method() const { return method_; }
    [[nodiscard]] const Tape& tape() const { return tape_; }
    /// The clip's tape (LeafDescription::clip), if there is one.
    [[nodiscard]] const std::optional<Tape>& clip_tape() const { return clip_tape_; }
    [[nodiscard]] const RootFinderSettings& settings() const { return settings_; }
    [[nodiscard]] const LeafDescription& description() const { return description_; }
    [[nodiscard]] Partition partition() const { return partition_; }
    /// The octree of the bounds, when partitioned.
    [[nodiscard]] const Octree* octree() const { return octree_ ? &*octree_ : nullptr; }
    /// Whether camera tiles are proven free of the surface before their rays
    /// are traced (the polynomial method: accel/polynomial_tile_proof.hpp).
    [[nodiscard]] bool proves_camera_tiles() const { return method_ == Method::Polynomial; }
    /// The step of the difference normals, a length in the leaf's space:
    /// 3e-9 × scale for forward and 1e-6 × scale for central differences
    /// unless the description gives one — where the normal study
    /// (tests/accel/normals_test.cpp, docs/rendering.md#normals) finds the
    /// least error.
    [[nodiscard]] double normal_step() const;

private:
    LeafScratch& scratch_for(TraceScratch& scratch) const;
    /// The part of [t_min, t_max] to search — the ray within the search
    /// region, nothing when it misses the gate — and where along it the
    /// surface most likely is (NaN: anywhere; RayFunction::set_focus).
    struct SearchedSpan {
        Span span;
        double focus;
    };
    [[nodiscard]] std::optional<SearchedSpan> searched_span(const Ray& ray, double t_min, double t_max) const;
    /// first_hit on the span found, without the camera tiles' proofs.
    std::optional<Hit> traced_first_hit(LeafScratch& leaf, const Ray& ray, const SearchedSpan& found, double t_min,
                                        TraceScratch& scratch) const;
    /// Counts the cell and makes its tape the ray function's base.
    void enter_cell(LeafScratch& leaf, const OctreeCell& cell, TraceScratch& scratch) const;
    /// Where a camera ray can start to look for the solid: the depth its
    /// pixel's voxels are proven empty to, culled once for the ray's whole
    /// tile (accel/frustum_cull.hpp), as the ray's t; +∞ when the pixel's
    /// rays all miss the solid.
    double camera_ray_start(LeafScratch& leaf, const Ray& ray, TraceScratch& scratch) const;
    /// The method run cell by cell along the ray, front to back.
    HitResult first_hit_in_cells(LeafScratch& leaf, Span span, TraceScratch& scratch) const;
    /// The roots in the span into leaf.roots, over the cells when partitioned.
    HitStatus all_hits(LeafScratch& leaf, Span span, TraceScratch& scratch) const;
    /// Records a NaN the last query met (if it met one and it is the first).
    void note_nan(const LeafScratch& leaf, std::uint64_t nans_before, TraceScratch& scratch) const;
    [[nodiscard]] SurfaceRef surface_at(const Ray& ray, double t, BoundaryKind kind) const;

    std::size_t id_;
    LeafDescription description_;
    Tape tape_;
    SearchRegion region_;  // the bounds, shrunk to the surface
    double scale_;  // the size its tolerances and offsets follow (gated_scale)
    Method method_;
    RootFinderSettings settings_;
    Partition partition_;
    std::optional<Octree> octree_;
    std::optional<Tape> clip_tape_;
};

}  // namespace zeroset
