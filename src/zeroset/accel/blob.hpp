// Blob: a blobby object as a primitive that knows its kernels (survey §2,
// §3.1, §3.2, §6.1). Each component's sphere (or ellipsoid) of influence —
// where its kernel is not 0, or for Blinn's Gaussian, where it is above a
// tolerance — sits in a BVH, so a ray meets only the components it passes
// near. Their entry and exit events split the ray into segments with a fixed
// set of components in reach; on each, the field is solved exactly
// (trace/blob_segment.hpp): as a guarded polynomial in t for soft objects and
// POV-Ray's kernel, by interval isolation for Gaussians and metaballs.
// Segments whose field provably stays below the threshold are skipped by a
// bound from each component's nearest approach. Normals are the exact
// gradient of the components in reach. Cost per ray grows with the
// components the ray meets, not with their total.
#pragma once

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "zeroset/accel/bvh.hpp"
#include "zeroset/accel/camera_frustum.hpp"
#include "zeroset/accel/primitive.hpp"
#include "zeroset/expr/blob_model.hpp"
#include "zeroset/trace/blob_segment.hpp"
#include "zeroset/trace/bounds.hpp"

namespace zeroset {

struct BlobDescription {
    std::string name;  // for messages
    std::shared_ptr<const BlobModel> model;
    MaterialId material = no_material;
    /// Blinn only: the cut-off, relative to the threshold.
    double tolerance = default_blinn_tolerance;
    /// Threads for building the BVH (0: all cores).
    int threads = 0;
    /// Metaballs only: solve the survey's approximation (§3.1) — each
    /// component's contribution along the ray as quadratic pieces in t —
    /// instead of the exact kernel.
    bool metaball_quadratics = false;
    /// Written as an expression and recognised (expr/gaussian_sum.hpp): said in the summary.
    bool from_expression = false;
    /// Bounds that clip the blob as an object's bounds clip its surface (a
    /// hit on them where they cut the solid): a recognised sum of Gaussians
    /// keeps its object's. None for a blob, whose reach bounds it.
    std::optional<Bounds> clip = std::nullopt;
};

/// What a thread writes while it traces a blob (one at a time: a blob's
/// query never runs another's).
struct BlobScratch {
    std::vector<KernelOnRay> kernels;  // the components the ray meets
    struct Event {
        enum class Kind : std::uint8_t { Enter, Piece, Exit };  // Piece: a metaball's quadratic piece ends
        double t;
        std::uint32_t kernel;  // into kernels
        Kind kind;
    };
    std::vector<Event> events;
    std::vector<std::uint32_t> active;    // kernels in reach on the current segment
    std::vector<std::uint32_t> position;  // each kernel's place in active
    std::vector<double> roots;
    Bvh::Queue queue;  // first_hit's traversal
    /// The last hit found and the components in reach there, which give its
    /// normal when it is shaded next (as it usually is) without a search.
    const void* hit_blob = nullptr;
    Vec3d hit_point{};
    std::vector<std::uint32_t> hit_components;
    /// Where a shadow ray last found the blob's inside, and the round
    /// components in reach there (for a blob whose components are all
    /// positive, Blob::positive_): their field alone is a lower bound on the
    /// blob's, so a neighbouring shadow ray that passes near that point is
    /// often proven blocked by them alone — POV-Ray's shadow cache, within
    /// one blob. Blobs are told apart by their serial number (Blob::id_),
    /// never reused.
    std::uint64_t blocker_blob = 0;
    Vec3d blocker_point{};
    std::vector<std::uint32_t> blocker_components;
    /// The components a camera tile's rays can meet, nearest the eye first
    /// (Blob::tile_list), for the last few tiles and blobs.
    struct TileList {
        std::uint64_t blob = 0;  // Blob::id_
        CameraFrustum tile;
        CameraFrustum::RayCheck check;
        struct Entry {
            double nearest;  // no point of the component's reach is nearer the eye
            std::uint32_t component;
            // A round component's centre as seen from the eye, e = eye − centre,
            // and the test that a ray of the tile passes beside its reach with
            // room for all rounding: (e·d)² < beside·|d|² (never, for other
            // components, whose `beside` is negative) — Blob::passes_beside
            // without its per-ray sizes.
            Vec3d from_center;
            double beside;
        };
        std::vector<Entry> entries;
        bool usable = false;  // false: too long to walk; the BVH serves the tile's rays
        std::uint64_t last_use = 0;
    };
    std::array<TileList, 4> tile_lists;
    std::size_t last_tile_list = 0;     // the one the last camera ray used, tried first
    std::uint64_t tile_list_uses = 0;   // camera rays that asked
    std::uint64_t tile_list_fills = 0;  // lists made
};

/// What the render summary says about a blob.
struct BlobStats {
    std::size_t components = 0;
    std::size_t bvh_nodes = 0;
    std::size_t bytes = 0;      // the components, their boxes and the BVH
    double reach_radius = 1.0;  // the largest cut-off radius over R (Blinn; 1 for the others)
};

class Blob final : public LeafPrimitive {
public:
    /// Throws std::invalid_argument for a tolerance outside (0, 1).
    explicit Blob(BlobDescription description);

    /// Its reach within its clip; a point when they do not meet (as CsgNode's empty intersection).
    [[nodiscard]] Box3 bounds() const override { return bounds_.valid() ? bounds_ : Box3{{0, 0, 0}, {0, 0, 0}}; }
    std::optional<Hit> first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const override;
    /// Stops at the first point found inside, not necessarily the first hit.
    bool occluded(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const override;
    void spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const override;
    /// When the field stays below the threshold on every ray of the tile:
    /// the components whose reach boxes the tile may meet (with none, the
    /// field is at the threshold, outside), each at its least distance from
    /// the rays. Not proven past max_components_bounded_by_tile of them.
    bool misses_tile(const CameraFrustum& tile, TraceScratch& scratch) const override;
    static constexpr std::size_t max_components_bounded_by_tile = 64;
    /// ∇f of the components in reach of the point, normalised.
    Vec3d local_normal(const SurfaceRef& surface, TraceScratch& scratch) const override;
    [[nodiscard]] const std::string& name() const override { return description_.name; }

    [[nodiscard]] const BlobModel& model() const { return *description_.model; }
    [[nodiscard]] const BlobStats& stats() const { return stats_; }
    [[nodiscard]] double tolerance() const { return description_.tolerance; }
    [[nodiscard]] bool quadratics() const { return description_.metaball_quadratics; }
    [[nodiscard]] bool from_expression() const { return description_.from_expression; }
    /// f and ∇f at a point, over the components in reach (for tests and normals).
    [[nodiscard]] double value_at(const Vec3d& p) const;
    [[nodiscard]] Vec3d gradient_at(const Vec3d& p) const;

    // Public for their tests: the pieces of a component's mapping that a
    // wrong rounding bound would break without any image showing it.
    /// The ray in a kernel's space, q(t) = q0 + t·qd, with bounds on the
    /// rounding of each coordinate.
    struct MappedRay {
        Vec3d q0, qd;
        double q0_error, qd_error;
    };
    /// Where the ray, mapped about a cylinder's axis line, is within its
    /// reach of the line, widened past any rounding (the whole ray when
    /// that is not decided); nothing when it never is.
    [[nodiscard]] static std::optional<Span> tube_on_ray(const MappedRay& across, double reach) {
        return tube_on_ray(across, reach, nearest_approach(across.q0, across.qd));
    }
    /// The same from the mapped ray's nearest approach to the axis, found already.
    [[nodiscard]] static std::optional<Span> tube_on_ray(const MappedRay& across, double reach,
                                                         const NearestApproach& approach);
    /// A cylinder's axis line in the blob's space, with the sizes the
    /// rounding of passes_beside_axis is measured in.
    struct AxisLine {
        Vec3d point, direction;
        double point_length, direction_length;
    };
    /// Whether the ray passes farther than `radius` from the line by a margin
    /// far wider than the rounding of this test and of the exact one: a
    /// cylinder it holds meets none of its parts (the round ends lie within
    /// that distance of the line too). Division-free, in the blob's own
    /// space, before the component is mapped; rays within 10⁻⁶ radians of
    /// the line's direction are never rejected.
    [[nodiscard]] static bool passes_beside_axis(const Ray& ray, double origin_length, double dir_length,
                                                 const AxisLine& axis, double radius);

private:
    static constexpr double u4 = 2.0 * std::numeric_limits<double>::epsilon();  // 4 units of rounding
    /// Whether a square (|d|², or a beside test's bound) is a normal double
    /// far from underflow and overflow, where the beside tests' rounding
    /// arguments hold.
    static bool well_scaled(double square) { return square >= 0x1p-900 && square <= 0x1p900; }

    /// One component, prepared.
    struct Component {
        std::uint32_t index;  // in the model (its to_kernel map)
        bool sphere;          // its map is (p − center)/R: applied without the matrix
        bool cylinder;        // from center to end: a body and two round ends
        double reach;         // u up to which it counts
        double strength;
        double blobbiness;
        Vec3d center;
        double inverse_radius;
        double radius_square;  // R² (0 where not a normal number): a sphere's 1/|q_d|² is R²/|d|²
        Vec3d end;            // a cylinder's
        // Fixed for every ray: a cylinder's axis and the sizes its mapping error is made of.
        Vec3d axis;           // end − center
        double axis_square;   // |axis|²
        double inverse_axis_square;  // 1/|axis|² (∞ for a sphere's zero axis)
        double axis_length;
        double center_length;
        double center_largest;  // the largest |coordinate| of center, and of end
        double end_largest;
        double reach_length;    // R·√reach: how far from its center (or axis) it counts
        double least_scale;     // at most the least factor its map scales lengths by: 1/R unless stretched (0: not known)
    };
    /// The ray with the sizes every component's mapping error is made of,
    /// worked out once a query.
    struct RaySizes {
        const Ray& ray;
        double origin_length, dir_length;
        double origin_largest, dir_largest;  // largest |coordinate|
        double dir_square;                   // |dir|²
        double inverse_dir_square;           // 1/|dir|² (NaN where |dir|² is outside 2^±900)
        explicit RaySizes(const Ray& r);
    };
    [[nodiscard]] const Mat4& to_kernel(const Component& c) const { return model().to_kernel(c.index); }
    /// Calls add(KernelOnRay) for the component as the ray sees it where the
    /// ray comes within its reach: once, or for a cylinder once for each of
    /// its parts the ray meets (an end, the body, the other end — the
    /// kernel of the distance to the segment is, piece by piece along the
    /// ray, the kernel of a distance to a point or to the axis line).
    /// (`beside_checked`: the caller has already found that the ray does not
    /// pass a round component beside its reach.)
    /// (Inline, defined in blob.cpp, its only user.)
    template <class Add>
    inline void on_ray(const RaySizes& ray, std::uint32_t i, Add&& add, bool beside_checked = false) const;
    /// Whether the ray passes farther than `radius` from `point` (whose
    /// largest |coordinate| is given) by a margin far wider than the
    /// rounding of the exact test: a cheap rejection in the blob's own space
    /// before a component is mapped into its kernel's.
    [[nodiscard]] static bool passes_beside(const RaySizes& ray, const Vec3d& point, double point_largest, double radius);
    /// The ray about a point (a component's centre or end, whose largest
    /// |coordinate| is given): q = (p − point)/R.
    [[nodiscard]] static MappedRay about_point(const RaySizes& ray, const Component& c, const Vec3d& point,
                                               double point_largest);
    /// The component's kernel along the mapped ray, within reach and the span
    /// `part`, from the mapped ray's nearest approach (to its centre or axis).
    [[nodiscard]] std::optional<KernelOnRay> part_on_ray(const Component& c, const MappedRay& q, Span part,
                                                         const NearestApproach& approach) const;
    [[nodiscard]] std::optional<KernelOnRay> part_on_ray(const Component& c, const MappedRay& q, Span part) const {
        return part_on_ray(c, q, part, nearest_approach(q.q0, q.qd));
    }

    BlobScratch& scratch_for(TraceScratch& scratch) const;
    /// For a camera ray of `tile`: the tile's components nearest first,
    /// made at the tile's first ray — camera rays share the eye, so a walk
    /// down this list meets the components in the order the BVH's would,
    /// without its heap. Nothing when the ray is not certainly one of the
    /// tile's, or when the tile sees too many components for a walk to pay.
    const BlobScratch::TileList* tile_list(const Ray& ray, const CameraFrustum& tile, BlobScratch& s) const;
    /// The list of its tile's components: those whose reach box the tile's
    /// rays may meet, by their boxes' distance from the eye.
    void fill_tile_list(BlobScratch::TileList& list) const;
    /// A list entry's `beside` for round component c, e = eye − centre.
    [[nodiscard]] static double beside_bound(const Vec3d& eye, const Component& c, const Vec3d& from_center);
    /// An upper bound on component i's s·K at any point of the tile's rays
    /// (0 for a negative one), with its rounding.
    [[nodiscard]] double field_above(std::uint32_t i, const CameraFrustum& tile,
                                     const CameraFrustum::Planes& planes) const;
    /// A box about component i's reach (rounded outward).
    [[nodiscard]] Box3 reach_box(std::uint32_t i) const;
    /// Whether the ray is proven blocked by the components of the last
    /// shadow ray's inside point (BlobScratch::blocker_point) within `span`.
    [[nodiscard]] bool blocked_as_before(const Ray& ray, Span span, const BlobScratch& s) const;
    /// Keeps the inside point a shadow ray found at t and the components in reach there.
    void remember_blocker(const Ray& ray, double t, BlobScratch& s) const;
    /// What a search looks for: the first hit, or any t on or in the solid.
    enum class Query { First, Any };
    /// The query's t in `span` (a part of the blob's clip), or nothing;
    /// s.active holds the components in reach there.
    std::optional<double> search(const Ray& ray, Span span, Query query, BlobScratch& s, TraceScratch& scratch) const;
    /// A t in [ta, tb] where f ≤ 0 over s.active, if the one point tried —
    /// the strongest component's nearest approach — is one.
    [[nodiscard]] std::optional<double> probe_inside(const BlobScratch& s, double ta, double tb) const;
    /// The part of [t_min, t_max] within the blob's reach and its clip.
    [[nodiscard]] std::optional<Span> clip(const Ray& ray, double t_min, double t_max) const;
    /// Adds a component the ray meets to s.kernels and its events, clipped to [t_min, t_max], to s.events.
    void add_events(const KernelOnRay& k, double t_min, double t_max, BlobScratch& s) const;
    /// An event's change to the components in reach (s.active).
    void apply(const BlobScratch::Event& e, BlobScratch& s) const;
    /// The components the ray meets within [t_min, t_max], into s.kernels,
    /// and their events, sorted latest first (the earliest at the back).
    void gather(const RaySizes& sizes, double t_min, double t_max, BlobScratch& s) const;
    /// Calls on_segment(ta, tb) for each segment with components in reach
    /// whose field may reach the threshold, front to back, with s.active
    /// holding them; it returns false to stop.
    template <class OnSegment>
    void sweep(BlobScratch& s, OnSegment&& on_segment) const;
    /// Whether the field may reach the threshold on [ta, tb] over s.active (false: skip the segment).
    [[nodiscard]] bool may_reach_threshold(const BlobScratch& s, double ta, double tb) const;
    /// Whether f ≤ 0 at t over s.active for a cut-off kernel: the components
    /// entering there took the field past T without a root in between.
    [[nodiscard]] bool jumps_inside(const BlobScratch& s, double t) const;
    /// The solver's settings for a ray (its tangent width in t).
    [[nodiscard]] BlobSegmentSettings settings_for(const Ray& ray) const;
    /// f at t over every gathered kernel in reach there, as the solver sees it.
    [[nodiscard]] double value_on_ray(const BlobScratch& s, double t) const;
    [[nodiscard]] SurfaceRef surface_at(const Ray& ray, double t, BoundaryKind kind) const;
    /// One component's part of ∇f at p (0 beyond its reach).
    [[nodiscard]] Vec3d gradient_from(const Vec3d& p, const Component& c) const;
    /// Calls visit(i) for the components whose reach holds p.
    template <class Visit>
    void components_at(const Vec3d& p, Visit&& visit) const;

    BlobDescription description_;
    BlobSegmentSettings settings_;
    std::vector<Component> components_;
    Box3 bounds_;
    double scale_ = 1.0;   // the bounds' diagonal
    std::unique_ptr<Bvh> bvh_;
    BlobStats stats_;
    /// Every component is positive and the kernel a polynomial: the field
    /// of any few components is a lower bound on the blob's, and
    /// kernel_rounding_ bounds the rounding of one K (shadow cache).
    bool positive_ = false;
    double kernel_rounding_ = 0.0;
    /// A serial number, never reused: what the per-thread caches are keyed on.
    std::uint64_t id_;
};

}  // namespace zeroset
