// What a blob keeps per thread between rays (BlobScratch): a camera tile's
// components nearest the eye first, which its rays walk instead of the
// BVH, and the components that blocked the last shadow ray, which often
// block the next. Also a tile's question before its rays: whether its
// field can reach the threshold anywhere along them.
#include "zeroset/accel/blob.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace zeroset {

namespace {

// A camera tile that sees more components than this walks the BVH: a ray
// that meets nothing walks its tile's whole list.
constexpr std::size_t max_tile_list = 128;

}  // namespace

Box3 Blob::reach_box(std::uint32_t i) const {
    const Component& c = components_[i];
    if (!c.sphere) return model().reach_box(c.index, c.reach);
    // The centre ± R·√reach, and a few units for the rounding of both.
    const double half = c.reach_length * (1.0 + 1e-12) + u4 * (c.center_largest + c.reach_length);
    return {c.center - Vec3d{half, half, half}, c.center + Vec3d{half, half, half}};
}

double Blob::beside_bound(const Vec3d& eye, const Component& c, const Vec3d& from_center) {
    // passes_beside's keep for any ray from the eye: its term |nearest|·
    // max|d_i| is at most |e|·|d|/|d|²·|d| = |e|.
    const double e2 = dot(from_center, from_center);
    const double keep =
        c.reach_length + 1e-9 * (c.reach_length + max_abs(eye) + c.center_largest + std::sqrt(e2));
    // The ray's squared distance from the centre is |e|² − (e·d)²/|d|². The
    // rounding of (e·d)², of beside·|d|² and of beside itself is within 20
    // units of (|e|² + keep²)·|d|²; with 64 units off beside, a ray the test
    // puts beside is farther than keep from the centre.
    return e2 - keep * keep - 16.0 * u4 * (e2 + keep * keep);
}

const BlobScratch::TileList* Blob::tile_list(const Ray& ray, const CameraFrustum& tile, BlobScratch& s) const {
    ++s.tile_list_uses;
    BlobScratch::TileList* list = &s.tile_lists[s.last_tile_list];  // a tile's rays come in a row
    if (list->blob != id_ || !list->tile.same_as(tile)) {
        list = nullptr;
        for (BlobScratch::TileList& l : s.tile_lists)
            if (l.blob == id_ && l.tile.same_as(tile)) list = &l;
    }
    if (!list) {
        // More tiles and blobs in turn than the cache holds (instances of a
        // blob each see the tile in their own space): a list is made for at
        // most one ray in 16, the others walk the BVH.
        if (s.tile_list_fills >= 64 && 16 * s.tile_list_fills > s.tile_list_uses) return nullptr;
        ++s.tile_list_fills;
        list = &*std::min_element(s.tile_lists.begin(), s.tile_lists.end(),
                                  [](const auto& a, const auto& b) { return a.last_use < b.last_use; });
        list->blob = id_;
        list->tile = tile;
        fill_tile_list(*list);
    }
    list->last_use = s.tile_list_uses;
    s.last_tile_list = static_cast<std::size_t>(list - s.tile_lists.data());
    return list->usable && tile.holds(ray, list->check) ? list : nullptr;
}

void Blob::fill_tile_list(BlobScratch::TileList& list) const {
    const CameraFrustum& tile = list.tile;
    list.entries.clear();
    const auto check = tile.ray_check();
    list.usable = check.has_value();
    if (!list.usable) return;
    list.check = *check;
    const CameraFrustum::Planes planes = tile.planes(check->basis);
    bvh_->select([&](const Box3& box) { return !tile.misses(box, planes); },
                 [&](std::uint32_t i) {
                     const Box3 box = reach_box(i);
                     if (tile.misses(box, planes)) return true;
                     if (list.entries.size() == max_tile_list) {
                         list.usable = false;
                         return false;
                     }
                     // The distance from the eye to the box, a little short for its rounding.
                     Vec3d out;
                     for (int axis = 0; axis < 3; ++axis)
                         out[axis] = std::max({box.lo[axis] - tile.origin[axis], 0.0, tile.origin[axis] - box.hi[axis]});
                     const Component& c = components_[i];
                     const Vec3d from_center = tile.origin - c.center;
                     list.entries.push_back({length(out) * (1.0 - 8.0 * u4), i, from_center,
                                             c.sphere ? beside_bound(tile.origin, c, from_center) : -1.0});
                     return true;
                 });
    if (list.usable)
        std::sort(list.entries.begin(), list.entries.end(),
                  [](const BlobScratch::TileList::Entry& a, const BlobScratch::TileList::Entry& b) { return a.nearest < b.nearest; });
}

bool Blob::misses_tile(const CameraFrustum& tile, TraceScratch&) const {
    const auto basis = tile.dual_basis();
    if (!basis) return false;
    const CameraFrustum::Planes planes = tile.planes(*basis);
    if (tile.misses(bounds(), planes)) return true;
    // Each component the tile's rays come within reach of adds at most its
    // kernel at its least distance from them: when the sum stays below T,
    // f > 0 at every point of every ray — with room for the rounding of the
    // field as the rays compute it, a few units of each term. (Not for the
    // quadratic pieces, which may pass their kernel a little.)
    double field = 0.0;
    std::size_t met = 0;
    bool missed = true;
    bvh_->select([&](const Box3& box) { return !tile.misses(box, planes); },
                 [&](std::uint32_t i) {
                     if (tile.misses(reach_box(i), planes)) return true;
                     if (settings_.metaball_quadratics || ++met > max_components_bounded_by_tile) return missed = false;
                     field += field_above(i, tile, planes);
                     return missed = field * (1.0 + 1e-9) < settings_.threshold;
                 });
    return missed;
}

double Blob::field_above(std::uint32_t i, const CameraFrustum& tile, const CameraFrustum::Planes& planes) const {
    const Component& c = components_[i];
    if (c.strength <= 0.0) return 0.0;
    // |q| is at least least_scale times the distance from the center, or
    // from a cylinder's axis segment.
    const double distance = tile.distance_outside(c.center, c.end, planes);
    const double scaled = distance * c.least_scale;
    const double u = scaled * scaled * (1.0 - 8.0 * unit_roundoff);
    return c.strength * kernel_value_above(settings_.kernel, u, c.blobbiness) * (1.0 + 2.0 * unit_roundoff);
}

void Blob::remember_blocker(const Ray& ray, double t, BlobScratch& s) const {
    s.blocker_blob = 0;
    if (!positive_) return;
    s.blocker_components.clear();
    if (s.active.empty() || s.active.size() > 8) return;
    for (const std::uint32_t k : s.active) {
        const std::uint32_t i = s.kernels[k].component;
        if (!components_[i].sphere) return;  // only round ones: their bound below is simple
        s.blocker_components.push_back(i);
    }
    s.blocker_blob = id_;
    s.blocker_point = ray.at(t);
}

bool Blob::blocked_as_before(const Ray& ray, Span span, const BlobScratch& s) const {
    if (s.blocker_blob != id_) return false;
    // The ray's point nearest the last inside point, within the span.
    const double t = std::clamp(dot(s.blocker_point - ray.origin, ray.dir) / dot(ray.dir, ray.dir), span.t0, span.t1);
    if (!(t >= span.t0 && t <= span.t1)) return false;  // NaN
    const Vec3d p = ray.at(t);
    // p is off the ray's true point by rounding: a few units of its size.
    const double off = 4.0 * u4 * (max_abs(ray.origin) + std::abs(t) * max_abs(ray.dir));
    double field = 0.0, error = 0.0;
    for (const std::uint32_t i : s.blocker_components) {
        const Component& c = components_[i];
        const Vec3d q = (p - c.center) * c.inverse_radius;
        const double u = dot(q, q);
        if (!(u <= c.reach)) continue;
        const KernelValue k = kernel_at(settings_.kernel, u, c.blobbiness);
        field += c.strength * k.value;
        // What p's offset and q's rounding (each coordinate off by (off + |p|
        // + |c|)·u4/R) and the dot product's do to u, and so to K, to first
        // order with room to spare; then Horner's absolute rounding of K.
        const double q_off = (off + 2.0 * u4 * (max_abs(p) + c.center_largest)) * c.inverse_radius;
        const double u_off = 4.0 * (std::sqrt(u) + q_off) * q_off + 4.0 * u4 * u;
        error += c.strength * (std::abs(k.slope) * u_off + kernel_rounding_);
    }
    // Inside when the field provably reaches T there (the others only add to it).
    return field - 2.0 * error >= settings_.threshold * (1.0 + 1e-12);
}

}  // namespace zeroset
