// An implicit leaf's queries over its method, and its normals (§8).
#include "zeroset/accel/implicit_leaf.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "zeroset/accel/spans_from_roots.hpp"
#include "zeroset/accel/trace_scratch.hpp"
#include "zeroset/trace/choose_method.hpp"

namespace zeroset {

namespace {

Vec3d unit_or_zero(const Vec3d& g) {
    const double len = length(g);
    if (!(len > 0.0) || !std::isfinite(len)) return {};
    return g / len;
}

}  // namespace

LeafScratch::LeafScratch(const ImplicitLeaf& leaf)
    : h(leaf.tape()),
      finder(make_root_finder(leaf.method(), leaf.tape(), leaf.settings())),
      gradient(leaf.tape()),
      value(leaf.tape()) {
    if (leaf.clip_tape()) clip.emplace(*leaf.clip_tape());
}

Partition resolve_partition(Partition asked, Method method, const Tape& tape) {
    const bool bounds_cells = method == Method::Interval || method == Method::Lg || method == Method::Sphere;
    if (asked == Partition::Auto)
        return bounds_cells && tape.clauses().size() >= partition_min_clauses ? Partition::Lipschitz : Partition::None;
    if (asked != Partition::None && !bounds_cells)
        throw std::invalid_argument("partition " + std::string(partition_name(asked)) +
                                    " needs the interval, lg or sphere method, not " +
                                    std::string(method_name(method)));
    return asked;
}

int octree_depth_for(int footprint_pixels) {
    const int footprint = footprint_pixels > 0 ? footprint_pixels : 512;
    const int depth = static_cast<int>(std::ceil(std::log2(std::max(1.0, footprint / 8.0))));
    return std::clamp(depth, 2, 6);
}

namespace {

/// An open object's bounds narrowed to its clip's solid (narrowed_to_clip).
LeafDescription narrowed(LeafDescription d) {
    d.bounds = narrowed_to_clip(d.bounds, d.clip, d.open);
    return d;
}

}  // namespace

ImplicitLeaf::ImplicitLeaf(std::size_t id, LeafDescription description)
    : id_(id),
      description_(narrowed(std::move(description))),
      tape_(description_.surface),
      region_(tape_, description_.bounds),
      scale_(gated_scale(region_.scale(), description_.gate)),
      method_(resolve_method(description_.method, tape_)),
      settings_(settings_for_scale(scale_)),
      partition_(resolve_partition(description_.partition, method_, tape_)) {
    settings_.polynomial_solver = description_.solver;
    if (description_.clip) {
        if (!description_.open) throw std::invalid_argument("a clip needs an open object (open on)");
        clip_tape_.emplace(*description_.clip);
    }
    (void)make_root_finder(method_, tape_, settings_);  // throws here, not in a render thread
    if (partition_ != Partition::None) {
        OctreeSettings octree;
        octree.rule = partition_;
        octree.max_depth = octree_depth_for(description_.footprint_pixels);
        octree.on_progress = description_.on_octree_progress;
        octree_.emplace(tape_, region_.box(), octree);
    }
}

LeafScratch& ImplicitLeaf::scratch_for(TraceScratch& scratch) const {
    std::unique_ptr<LeafScratch>& slot = scratch.leaf(id_);
    if (!slot) slot = std::make_unique<LeafScratch>(*this);
    return *slot;
}

void ImplicitLeaf::note_nan(const LeafScratch& leaf, std::uint64_t nans_before, TraceScratch& scratch) const {
    if (scratch.counters.nan_evaluations != nans_before && !scratch.first_nan)
        scratch.first_nan = TraceScratch::NanRecord{this, leaf.h.last_nan_point()};
}

SurfaceRef ImplicitLeaf::surface_at(const Ray& ray, double t, BoundaryKind kind) const {
    return leaf_surface(*this, kind, description_.material, ray.at(t), scale_);
}

void ImplicitLeaf::enter_cell(LeafScratch& leaf, const OctreeCell& cell, TraceScratch& scratch) const {
    ++scratch.counters.cell_visits;
    leaf.h.set_base_tape(octree_->tape_of(cell), cell.can_prune);
}

double ImplicitLeaf::camera_ray_start(LeafScratch& leaf, const Ray& ray, TraceScratch& scratch) const {
    const CameraFrustum& tile = *scratch.camera_frustum;
    const int pixel = scratch.camera_pixel;
    // Not one of the tile's rays: never expected, but nothing is culled then.
    if (!(ray.origin == tile.origin) || pixel < 0 || pixel >= tile.pixels()) return 0.0;
    if (!leaf.culled) leaf.culled = std::make_unique<CulledTiles>(tape_);
    const std::vector<double>* depths = leaf.culled->first_depths(tile, region_.box(), scratch.counters);
    if (!depths) return 0.0;
    const double depth = (*depths)[static_cast<std::size_t>(pixel)];
    if (depth == std::numeric_limits<double>::infinity()) return depth;
    const double rate = tile.depth_rate(ray.dir);
    if (!(rate > 0.0)) return 0.0;
    // A hair short of the depth: the voxel in front, proven empty, was
    // widened by far more than that (frustum_cull.cpp, box_pad).
    return depth / rate * (1.0 - 1e-12);
}

HitResult ImplicitLeaf::first_hit_in_cells(LeafScratch& leaf, Span span, TraceScratch& scratch) const {
    // A ray that starts in the solid hits at once — also where that part of
    // the solid holds no surface, so no cell. NaN there fails, as unpartitioned.
    const double start = leaf.h.value(span.t0, scratch.counters);
    if (start != start) return {std::nullopt, HitStatus::Failed};
    if (start <= 0.0) return {span.t0, HitStatus::Ok};
    // Outside at the start, so outside at every cell's start: no root lies
    // in the cells before it (their methods found none) nor in the discarded
    // cells between (the Lipschitz rule's proof), and f keeps its sign where
    // it has no root. So no cell evaluates its start again. Bloomenthal's
    // rules may discard surface: there each cell checks its start, as the
    // method does alone.
    const bool outside_at_cells = partition_ == Partition::Lipschitz;
    HitResult hit;
    octree_->walk(leaf.h.ray(), span, [&](Span cell_span, const OctreeCell& cell) {
        enter_cell(leaf, cell, scratch);
        hit = outside_at_cells ? leaf.finder->first_hit_from_outside(leaf.h, cell_span, scratch.counters)
                               : leaf.finder->first_hit(leaf.h, cell_span, scratch.counters);
        // A failure in one cell (NaN, a budget spent) fails the query, as it
        // fails a method over the whole span: a later hit is not trusted.
        if (hit.status == HitStatus::Failed) hit.t.reset();
        return hit.t.has_value() || hit.status == HitStatus::Failed;
    });
    leaf.h.reset_base_tape();
    return hit;
}

HitStatus ImplicitLeaf::all_hits(LeafScratch& leaf, Span span, TraceScratch& scratch) const {
    if (!octree_) return leaf.finder->all_hits(leaf.h, span, leaf.roots, scratch.counters);
    HitStatus status = HitStatus::Ok;
    octree_->walk(leaf.h.ray(), span, [&](Span cell_span, const OctreeCell& cell) {
        enter_cell(leaf, cell, scratch);
        if (leaf.finder->all_hits(leaf.h, cell_span, leaf.roots, scratch.counters) == HitStatus::Failed)
            status = HitStatus::Failed;
        return false;
    });
    leaf.h.reset_base_tape();
    return status;
}

std::optional<ImplicitLeaf::SearchedSpan> ImplicitLeaf::searched_span(const Ray& ray, double t_min,
                                                                      double t_max) const {
    constexpr double nowhere = std::numeric_limits<double>::quiet_NaN();
    if (!description_.gate) {
        const auto span = region_.clip(ray, t_min, t_max);
        return span ? std::optional<SearchedSpan>({*span, nowhere}) : std::nullopt;
    }
    // The span reaches far beyond the gate, where the surface mostly is:
    // about the focus, the polynomial method's rounding bound is least where it matters.
    const std::optional<double> focus = gate_focus(*description_.gate, ray, t_min);
    if (!focus) return std::nullopt;
    const auto span = region_.clip(ray, t_min, t_max);
    if (!span) return std::nullopt;
    return SearchedSpan{*span, *focus};
}

bool ImplicitLeaf::misses_tile(const CameraFrustum& tile, TraceScratch& scratch) const {
    // Camera rays start at the eye, t = 0, where the gate's test starts too.
    // A sphere is passed when its box is, or when no ray of the tile comes
    // within its radius of its centre (POV-Ray's bounded_by spheres: the
    // tiles beside a sphere but across its box's corners).
    if (const auto basis = tile.dual_basis()) {
        const CameraFrustum::Planes planes = tile.planes(*basis);
        const auto passes = [&](const Bounds& b, const Box3& box) {
            return tile.misses(box, planes) ||
                   (b.kind == Bounds::Kind::Sphere && tile.distance_outside(b.center, b.center, planes) > b.radius);
        };
        if (passes(region_.bounds(), region_.box()) ||
            (description_.gate && passes(*description_.gate, description_.gate->enclosing_box())))
            return true;
    }
    if (!proves_camera_tiles()) return false;
    LeafScratch& leaf = scratch_for(scratch);
    // Tried once rows of the tile have all missed — at the same ask for
    // every leaf, so that a group's leaves (POV-Ray's three axes) prove a
    // tile together rather than one row apart. A gated surface's cheap
    // misses pass beside its gate, and the proof, over the whole region its
    // other rays search, would seldom hold: it is tried for its costly
    // misses only.
    const bool try_proof = !description_.gate && scratch.tile_rows_missed;
    if (!leaf.proven && try_proof) leaf.proven = std::make_unique<ProvenTiles>(tape_);
    return leaf.proven && leaf.proven->proves_tile(tile, region_.box(), try_proof, scratch.counters);
}

std::optional<Hit> ImplicitLeaf::first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const {
    // A camera ray of a tile proven free of the surface misses at once.
    const bool camera = scratch.camera_frustum && proves_camera_tiles();
    LeafScratch* leaf = nullptr;
    ProvenTiles::Entry* tile = nullptr;
    if (camera) {
        leaf = &scratch_for(scratch);
        if (leaf->proven) tile = leaf->proven->entry(*scratch.camera_frustum);
        if (tile && tile->state == ProvenTiles::State::Proven && leaf->proven->proven_miss(*tile, ray)) {
            ++scratch.counters.proven_tile_rays;
            return std::nullopt;
        }
    }
    const auto found = searched_span(ray, t_min, t_max);
    if (!found) return std::nullopt;
    if (!leaf) leaf = &scratch_for(scratch);
    if (!camera || (tile && tile->state != ProvenTiles::State::Untried))
        return traced_first_hit(*leaf, ray, *found, t_min, scratch);
    // Costly misses in a tile not yet tried ask for its proof; the first
    // makes the leaf's proofs.
    const std::uint64_t before = scratch.counters.evaluations();
    std::optional<Hit> hit = traced_first_hit(*leaf, ray, *found, t_min, scratch);
    const std::uint64_t spent = scratch.counters.evaluations() - before;
    if (!leaf->proven) {
        if (hit || spent < ProvenTiles::costly_miss) return hit;
        leaf->proven = std::make_unique<ProvenTiles>(tape_);
    }
    if (!tile) tile = leaf->proven->entry(*scratch.camera_frustum);
    if (tile) leaf->proven->traced(*tile, region_.box(), hit.has_value(), spent, scratch.counters);
    return hit;
}

// Inlined into first_hit: a call, and the copy of its result, cost rays
// that never meet a tile ~2 %.
[[gnu::always_inline]] inline std::optional<Hit> ImplicitLeaf::traced_first_hit(LeafScratch& leaf, const Ray& ray,
                                                                                const SearchedSpan& found, double t_min,
                                                                                TraceScratch& scratch) const {
    const Span span = found.span;
    const std::uint64_t nans = scratch.counters.nan_evaluations;
    leaf.h.set_ray(ray);
    leaf.h.set_focus(found.focus);
    if (description_.open) {  // a sheet: the first root, wherever the ray starts
        // Most rays start outside the solid: then the first hit is the first
        // root, as for a closed object, unless the clip removes it there.
        if (!octree_) {
            const HitResult first = leaf.finder->first_hit(leaf.h, span, scratch.counters);
            if (first.status != HitStatus::Failed && !first.t) {
                note_nan(leaf, nans, scratch);
                return std::nullopt;  // no root at all in the span
            }
            if (first.t && (*first.t > span.t0 || leaf.h.value(span.t0, scratch.counters) >= 0.0)) {
                const Vec3d p = ray.at(*first.t);
                bool clipped = false;
                if (leaf.clip) {
                    ++scratch.counters.point_evaluations;
                    clipped = (*leaf.clip)(p.x, p.y, p.z) > 0.0;
                }
                if (!clipped) {
                    note_nan(leaf, nans, scratch);
                    return Hit{*first.t, surface_at(ray, *first.t, BoundaryKind::Surface)};
                }
            }
        }
        leaf.roots.clear();
        if (all_hits(leaf, span, scratch) == HitStatus::Failed) ++scratch.counters.failed_queries;
        note_nan(leaf, nans, scratch);
        std::sort(leaf.roots.begin(), leaf.roots.end());
        for (const double t : leaf.roots) {
            if (t < span.t0 || t > span.t1) continue;
            if (leaf.clip) {  // clipped away here?
                const Vec3d p = ray.at(t);
                ++scratch.counters.point_evaluations;
                if ((*leaf.clip)(p.x, p.y, p.z) > 0.0) continue;
            }
            return Hit{t, surface_at(ray, t, BoundaryKind::Surface)};
        }
        return std::nullopt;
    }
    // A camera ray of a partitioned leaf starts where its tile's culling
    // says the solid may begin: nothing of it lies in front of that.
    Span searched = span;
    if (octree_ && scratch.camera_frustum) {
        searched.t0 = std::max(searched.t0, camera_ray_start(leaf, ray, scratch));
        if (!(searched.t0 <= searched.t1)) return std::nullopt;
    }
    const HitResult hit = octree_ ? first_hit_in_cells(leaf, searched, scratch)
                                  : leaf.finder->first_hit(leaf.h, searched, scratch.counters);
    note_nan(leaf, nans, scratch);
    if (hit.status == HitStatus::Failed) ++scratch.counters.failed_queries;
    if (!hit.t) return std::nullopt;
    // A hit at the span's start with the ray already inside: on the bounds'
    // cut when the ray came in through them, else the ray starts inside.
    BoundaryKind kind = BoundaryKind::Surface;
    if (*hit.t == span.t0 && leaf.h.value(span.t0, scratch.counters) < 0.0)
        kind = span.t0 > t_min ? BoundaryKind::Bounds : BoundaryKind::Open;
    return Hit{*hit.t, surface_at(ray, *hit.t, kind)};
}

void ImplicitLeaf::spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const {
    const auto found = searched_span(ray, t_min, t_max);
    if (!found) return;
    const Span span = found->span;
    LeafScratch& leaf = scratch_for(scratch);
    const std::uint64_t nans = scratch.counters.nan_evaluations;
    leaf.h.set_ray(ray);
    leaf.h.set_focus(found->focus);
    std::vector<double>& roots = leaf.roots;
    roots.clear();
    if (all_hits(leaf, span, scratch) == HitStatus::Failed)
        ++scratch.counters.failed_queries;  // the spans below are those of the roots found so far
    // The events: t0, the roots strictly inside the span, t1.
    std::sort(roots.begin(), roots.end());
    std::erase_if(roots, [&](double t) { return !(t > span.t0 && t < span.t1); });
    // Cells overlap by their pad, so a root near a face may come from both:
    // roots closer than the methods' own merge width are one.
    const double merge_width = 4.0 * leaf.h.to_t(settings_.tangent_width);
    const auto same_root = [merge_width](double a, double b) { return b - a <= merge_width; };
    roots.erase(std::unique(roots.begin(), roots.end(), same_root), roots.end());
    spans_from_roots(
        roots, span.t0, span.t1, span.t0 > t_min ? BoundaryKind::Bounds : BoundaryKind::Open,
        span.t1 < t_max ? BoundaryKind::Bounds : BoundaryKind::Open,
        [&](double t) { return leaf.h.value(t, scratch.counters) <= 0.0; },
        [&](double t, BoundaryKind kind) { return Hit{t, surface_at(ray, t, kind)}; }, out);
    note_nan(leaf, nans, scratch);
}

double ImplicitLeaf::normal_step() const {
    const double relative = description_.normal_step > 0.0                               ? description_.normal_step
                            : description_.normals == NormalMode::CentralDifference ? 1e-6
                                                                                    : 3e-9;
    return relative * scale_;
}

Vec3d ImplicitLeaf::local_normal(const SurfaceRef& surface, TraceScratch& scratch) const {
    const Vec3d& p = surface.local_point;
    if (surface.kind == BoundaryKind::Bounds) return description_.bounds.normal_at(p);
    LeafScratch& leaf = scratch_for(scratch);
    const auto f = [&](double x, double y, double z) { return leaf.value(x, y, z); };
    const auto central = [&](double h) {
        return unit_or_zero({f(p.x + h, p.y, p.z) - f(p.x - h, p.y, p.z), f(p.x, p.y + h, p.z) - f(p.x, p.y - h, p.z),
                             f(p.x, p.y, p.z + h) - f(p.x, p.y, p.z - h)});
    };
    switch (description_.normals) {
        case NormalMode::Analytic: {  // eq. 33
            const Vec3d n = unit_or_zero(evaluate_gradient(leaf.gradient, p).g);
            // Where ∇f vanishes (or overflows) exactly — at a kink of a
            // distance function — central differences over their default step.
            return n != Vec3d{} ? n : central(1e-6 * scale_);
        }
        case NormalMode::ForwardDifference: {  // eq. 34
            const double h = normal_step(), f0 = f(p.x, p.y, p.z);
            return unit_or_zero({f(p.x + h, p.y, p.z) - f0, f(p.x, p.y + h, p.z) - f0, f(p.x, p.y, p.z + h) - f0});
        }
        case NormalMode::CentralDifference: return central(normal_step());
    }
    return {};
}

}  // namespace zeroset
