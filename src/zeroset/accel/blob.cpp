// The blob primitive: components' reach in a BVH, events along the ray,
// segments solved front to back.
#include "zeroset/accel/blob.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "zeroset/accel/spans_from_roots.hpp"
#include "zeroset/accel/trace_scratch.hpp"

namespace zeroset {

namespace {

/// x where it is a normal number (full precision), else 0: a product with
/// it is then 0, which the one user takes for "not known" (Blob::on_ray).
double normal_or_zero(double x) { return std::isnormal(x) ? x : 0.0; }

// A blob of this many components or fewer (one BVH leaf) meets them all
// without the tree's walk.
constexpr std::size_t few_components = 4;
// A shadow ray through a blob of this many components or fewer gathers
// every one it meets before it looks for the inside: in a bigger one, a
// blocked ray would map everything behind its blocker (a side-lit cloud
// of 100 000 took 0.046 → 0.072 s so).
constexpr std::size_t small_for_shadows = 16;

/// Whether a component the ray meets counts within [t_min, t_max].
bool meets(const KernelOnRay& k, double t_min, double t_max) { return k.t_out >= t_min && k.t_in <= t_max; }

/// The events' order: the events wait sorted by it, latest first, so that
/// the next is at the back; at equal t entries come first (an object, not
/// a function, so that std::sort inlines it).
constexpr auto later = [](const BlobScratch::Event& a, const BlobScratch::Event& b) {
    return a.t > b.t || (a.t == b.t && a.kind > b.kind);
};

// Blob::id_'s source: the per-thread caches tell blobs apart by it.
std::atomic<std::uint64_t> next_blob_id{1};

/// At most the least factor by which a component's map into its kernel's
/// space, q = L⁻¹(p − center)/R, scales distances from its center (or
/// axis): 1/R, or 1/(R·‖L‖) with ‖L‖ ≤ √3 times its longest column
/// (rounded a little low); 0 for a shape that moves the kernel off the
/// center.
double least_scale(const BlobComponent& c) {
    if (c.shape == Mat4::identity()) return 1.0 / c.radius;
    if (!(c.shape.transform_point({0, 0, 0}) == Vec3d{0, 0, 0})) return 0.0;
    return (1.0 - 1e-12) / (c.radius * std::sqrt(3.0) * c.shape.max_stretch());
}

}  // namespace

Blob::Blob(BlobDescription description) : description_(std::move(description)), id_(next_blob_id++) {
    const BlobModel& m = model();
    if (!(description_.tolerance > 0.0 && description_.tolerance < 1.0))
        throw std::invalid_argument("a blob's tolerance must lie strictly between 0 and 1");
    const std::optional<Box3> solid = m.solid_bounds(description_.tolerance);
    if (!solid)
        throw std::invalid_argument("a blob needs a component of positive strength (its field never reaches the threshold)");
    bounds_ = *solid;
    if (description_.clip) bounds_ = overlap(bounds_, description_.clip->enclosing_box());  // not valid() where they miss
    if (!std::isfinite(bounds_.diagonal()))
        throw std::invalid_argument("the blob's reach is wider than a double can measure");
    std::vector<Box3> boxes;
    for (std::size_t i = 0; i < m.components().size(); ++i) {
        const BlobComponent& c = m.components()[i];
        const double reach = m.reach(i, description_.tolerance);
        if (!(reach > 0.0)) continue;  // a Gaussian too weak to count anywhere
        const bool sphere = c.shape == Mat4::identity() && !c.is_cylinder();
        if (c.is_cylinder() && description_.metaball_quadratics)
            throw std::invalid_argument("component " + std::to_string(i + 1) +
                                        ": the quadratic pieces are for round components, not cylinders");
        const Vec3d end = c.end.value_or(c.center), axis = end - c.center;
        components_.push_back({static_cast<std::uint32_t>(i), sphere, c.is_cylinder(), reach, c.strength, c.blobbiness,
                               c.center, 1.0 / c.radius, normal_or_zero(c.radius * c.radius), end, axis, dot(axis, axis),
                               1.0 / dot(axis, axis), length(axis), length(c.center),
                               max_abs(c.center), max_abs(end), c.radius * std::sqrt(reach),
                               least_scale(c)});
        boxes.push_back(m.reach_box(i, reach));
        if (!is_bounded(boxes.back()) || !std::isfinite(boxes.back().diagonal()))
            throw std::invalid_argument("component " + std::to_string(i + 1) + ": its reach is wider than a double can measure");
        stats_.reach_radius = std::max(stats_.reach_radius, std::sqrt(reach));
    }
    bvh_ = std::make_unique<Bvh>(boxes, description_.threads);
    // The shadow cache's proof: all strengths positive, a polynomial kernel
    // (0 at its reach's end, and its rounding bounded by its coefficients).
    const std::span<const double> kernel = blob_kernel_info(m.kernel()).polynomial;
    positive_ = !kernel.empty() &&
                std::all_of(m.components().begin(), m.components().end(), [](const BlobComponent& c) { return c.strength > 0.0; });
    for (const double c : kernel) kernel_rounding_ += 8.0 * u4 * std::abs(c);
    scale_ = std::max(bounds_.diagonal(), 1e-300);
    const RootFinderSettings tolerances = settings_for_scale(scale_);
    if (description_.metaball_quadratics && m.kernel() != BlobKernel::Metaball)
        throw std::invalid_argument("the quadratic approximation is for metaballs only");
    settings_ = {m.kernel(), m.threshold(), tolerances.tangent_width, tolerances.max_segments,
                 description_.metaball_quadratics};
    stats_.components = components_.size();
    stats_.bvh_nodes = bvh_->node_count();
    // The model's components and maps, the prepared ones, the BVH's nodes and leaf order.
    stats_.bytes = m.components().size() * (sizeof(BlobComponent) + sizeof(Mat4)) + components_.size() * sizeof(Component) +
                   bvh_->node_count() * 128 + components_.size() * sizeof(std::uint32_t);
}

std::optional<Span> Blob::clip(const Ray& ray, double t_min, double t_max) const {
    if (!bounds_.valid()) return std::nullopt;
    const auto span = bounds_.clip(ray, t_min, t_max);
    if (!span || !description_.clip || description_.clip->kind == Bounds::Kind::Box) return span;
    return description_.clip->clip(ray, span->t0, span->t1);
}

BlobScratch& Blob::scratch_for(TraceScratch& scratch) const {
    std::unique_ptr<BlobScratch>& slot = scratch.blob();
    if (!slot) slot = std::make_unique<BlobScratch>();
    return *slot;
}

Blob::RaySizes::RaySizes(const Ray& r)
    : ray(r), origin_length(length(r.origin)), dir_length(length(r.dir)), origin_largest(max_abs(r.origin)),
      dir_largest(max_abs(r.dir)), dir_square(dot(r.dir, r.dir)),
      // Where |d|² is near underflow or overflow (1/|d|² = 0 would measure the
      // origin's distance, not the ray's), NaN: passes_beside then never rejects.
      inverse_dir_square(well_scaled(dir_square) ? 1.0 / dir_square : std::numeric_limits<double>::quiet_NaN()) {}

// Inlined into its few callers: called, it cost the 1 000-blob cloud 1.5 % more.
template <class Add>
[[gnu::always_inline]] inline void Blob::on_ray(const RaySizes& sizes, std::uint32_t i, Add&& add, bool beside_checked) const {
    const Ray& ray = sizes.ray;
    constexpr double infinity = std::numeric_limits<double>::infinity();
    const Component& c = components_[i];
    const Span everywhere{-infinity, infinity};
    if (c.sphere) {
        if (!beside_checked && passes_beside(sizes, c.center, c.center_largest, c.reach_length)) return;
        const MappedRay q = about_point(sizes, c, c.center, c.center_largest);
        // 1/|d|² is NaN where |d|² is badly scaled, and R² is 0 where it is not
        // a normal number: there the division.
        const double inverse_a2 = sizes.inverse_dir_square * c.radius_square;
        const NearestApproach approach =
            std::isnormal(inverse_a2) ? nearest_approach(q.q0, q.qd, inverse_a2) : nearest_approach(q.q0, q.qd);
        if (const auto k = part_on_ray(c, q, everywhere, approach)) add(*k);
        return;
    }
    if (!c.cylinder) {
        const MappedRay q{to_kernel(c).transform_point(ray.origin), to_kernel(c).transform_vector(ray.dir),
                          mapping_error(to_kernel(c), ray.origin, true), mapping_error(to_kernel(c), ray.dir, false)};
        if (const auto k = part_on_ray(c, q, everywhere)) add(*k);
        return;
    }
    if (passes_beside_axis(ray, sizes.origin_length, sizes.dir_length,
                           {c.center, c.axis, c.center_length, c.axis_length}, c.reach_length))
        return;
    // The ray's place along the axis, s(t) = s0 + t·sd: the body for s in
    // [0, 1], the round ends beyond. Where they meet, the two kernels agree
    // to first order (distance to the end = distance to the axis), so the
    // rounding of these bounds changes f by its square: far below the
    // segment solver's rounding radius.
    const Vec3d& w = c.axis;
    const Vec3d offset = ray.origin - c.center;
    // Multiplied by 1/|w|², not divided: a unit more of rounding, within the
    // margins below, and two divisions fewer on every ray that meets it.
    const double s0 = times_inverse(dot(offset, w), c.axis_square, c.inverse_axis_square);
    const double sd = times_inverse(dot(ray.dir, w), c.axis_square, c.inverse_axis_square);
    Span start = everywhere, body = everywhere, finish = everywhere;  // where s ≤ 0, 0 ≤ s ≤ 1, s ≥ 1
    if (sd != 0.0) {
        // One division for both ends.
        const double inverse_sd = 1.0 / sd;
        const double at_start = times_inverse(-s0, sd, inverse_sd), at_end = times_inverse(1.0 - s0, sd, inverse_sd);
        body = {std::min(at_start, at_end), std::max(at_start, at_end)};
        start = sd > 0.0 ? Span{-infinity, at_start} : Span{at_start, infinity};
        finish = sd > 0.0 ? Span{at_end, infinity} : Span{-infinity, at_end};
    } else {
        // One part only: a ray in an end plane is the body's (both agree there).
        const Span none{infinity, -infinity};
        if (!(s0 < 0.0)) start = none;
        if (!(s0 >= 0.0 && s0 <= 1.0)) body = none;
        if (!(s0 > 1.0)) finish = none;
    }
    // The body: q = ((p − a) − s·w)/R, the offset from the axis line. Its
    // rounding: p − a, then s (a dot product over w·w: off by a few units
    // times |p − a|/|w|), s·w and the difference, within 8 units of
    // (|o| + |a| + |s0|·|w|)/R — and the same for the direction.
    const MappedRay across{(offset - s0 * w) * c.inverse_radius, (ray.dir - sd * w) * c.inverse_radius,
                           2.0 * u4 * (sizes.origin_length + c.center_length + std::abs(s0) * c.axis_length) * c.inverse_radius,
                           2.0 * u4 * (sizes.dir_length + std::abs(sd) * c.axis_length) * c.inverse_radius};
    // Each round end lies in the tube of reach about the axis line: a ray
    // that misses the tube meets no part, and an end whose part of the ray
    // lies outside the tube need not be mapped.
    const NearestApproach to_axis = nearest_approach(across.q0, across.qd);
    const std::optional<Span> tube = tube_on_ray(across, c.reach, to_axis);
    if (!tube) return;
    const auto within = [&](const Span& part) { return part.t0 <= tube->t1 && part.t1 >= tube->t0; };
    // In the order the ray meets them, so that the events come sorted when they can.
    const bool forwards = sd >= 0.0;
    const Span& first = forwards ? start : finish;
    const Span& last = forwards ? finish : start;
    const auto about_start = [&] { return about_point(sizes, c, c.center, c.center_largest); };
    const auto about_end = [&] { return about_point(sizes, c, c.end, c.end_largest); };
    if (within(first))
        if (const auto k = part_on_ray(c, forwards ? about_start() : about_end(), first)) add(*k);
    if (const auto k = part_on_ray(c, across, body, to_axis)) add(*k);
    if (within(last))
        if (const auto k = part_on_ray(c, forwards ? about_end() : about_start(), last)) add(*k);
}

void Blob::gather(const RaySizes& sizes, double t_min, double t_max, BlobScratch& s) const {
    s.kernels.clear();
    s.events.clear();
    const auto meet = [&](std::uint32_t i) __attribute__((always_inline)) {  // (left a call, the walk cost 1 % more)
        on_ray(sizes, i, [&](const KernelOnRay& k) {
            if (meets(k, t_min, t_max)) add_events(k, t_min, t_max, s);
        });
    };
    if (components_.size() <= few_components) {
        for (std::uint32_t i = 0; i < components_.size(); ++i) meet(i);
    } else {
        bvh_->traverse(sizes.ray, t_min, t_max, [&](std::uint32_t i, double limit) {
            meet(i);
            return limit;  // every component along the ray: the events need them all
        });
    }
    // Latest first, so that the earliest is taken from the back; at equal t
    // entries last, so that a component's own entry precedes its exit.
    std::sort(s.events.begin(), s.events.end(), later);
}

template <class OnSegment>
void Blob::sweep(BlobScratch& s, OnSegment&& on_segment) const {
    s.active.clear();
    const std::vector<BlobScratch::Event>& events = s.events;  // latest first
    for (std::size_t i = events.size(); i > 0;) {
        const double ta = events[i - 1].t;
        for (; i > 0 && events[i - 1].t == ta; --i) apply(events[i - 1], s);
        if (i == 0 || s.active.empty()) continue;
        const double tb = events[i - 1].t;
        if (may_reach_threshold(s, ta, tb) && !on_segment(ta, tb)) return;
    }
}

bool Blob::may_reach_threshold(const BlobScratch& s, double ta, double tb) const {
    // The quadratic pieces may pass their kernel a little: they are solved, cheaply, wherever they are.
    return settings_.metaball_quadratics ||
           blob_field_upper_bound(settings_, s.kernels, s.active, ta, tb) >= settings_.threshold;
}

bool Blob::jumps_inside(const BlobScratch& s, double t) const {
    // Only a cut-off Gaussian jumps where it enters (by less than tolerance·T).
    if (blob_kernel_info(settings_.kernel).finite_support) return false;
    return blob_field_at(settings_, s.kernels, s.active, t).value <= 0.0;
}

BlobSegmentSettings Blob::settings_for(const Ray& ray) const {
    BlobSegmentSettings s = settings_;
    s.tangent_width /= length(ray.dir);  // a length in the blob's space, as a span of t
    return s;
}

double Blob::value_on_ray(const BlobScratch& s, double t) const {
    double field = 0.0;
    const KernelOnRay* previous = nullptr;  // a cylinder's parts come one after another and meet at their ends: count one
    for (const KernelOnRay& k : s.kernels) {
        if (!(t >= k.t_in && t <= k.t_out)) continue;
        if (previous && previous->component == k.component && t >= previous->t_in && t <= previous->t_out) continue;
        field += k.strength * kernel_value_on_ray(settings_, k, t);
        previous = &k;
    }
    return settings_.threshold - field;
}

SurfaceRef Blob::surface_at(const Ray& ray, double t, BoundaryKind kind) const {
    return leaf_surface(*this, kind, description_.material, ray.at(t), scale_);
}

void Blob::add_events(const KernelOnRay& k, double t_min, double t_max, BlobScratch& s) const {
    using Kind = BlobScratch::Event::Kind;
    const auto index = static_cast<std::uint32_t>(s.kernels.size());
    s.kernels.push_back(k);
    s.events.push_back({std::max(k.t_in, t_min), index, Kind::Enter});
    s.events.push_back({std::min(k.t_out, t_max), index, Kind::Exit});
    if (settings_.metaball_quadratics) {
        const MetaballPieces pieces = metaball_pieces(k);
        for (int j = 1; j + 1 < pieces.count; ++j) {
            const double t = pieces.ends[static_cast<std::size_t>(j)];
            if (t > t_min && t < t_max) s.events.push_back({t, index, Kind::Piece});
        }
    }
}

void Blob::apply(const BlobScratch::Event& e, BlobScratch& s) const {
    if (e.kind == BlobScratch::Event::Kind::Enter) {
        s.position.resize(std::max<std::size_t>(s.position.size(), e.kernel + 1));
        s.position[e.kernel] = static_cast<std::uint32_t>(s.active.size());
        s.active.push_back(e.kernel);
    } else if (e.kind == BlobScratch::Event::Kind::Exit) {  // swap with the last and drop it
        const std::uint32_t at = s.position[e.kernel], last = s.active.back();
        s.active[at] = last;
        s.position[last] = at;
        s.active.pop_back();
    }
}

std::optional<Hit> Blob::first_hit(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const {
    const auto span = clip(ray, t_min, t_max);
    if (!span) return std::nullopt;
    BlobScratch& s = scratch_for(scratch);
    const std::optional<double> hit = search(ray, *span, Query::First, s, scratch);
    if (!hit) return std::nullopt;
    // Inside already at the span's start: on the clip's cut when the ray came in through it.
    BoundaryKind kind = BoundaryKind::Surface;
    if (*hit == span->t0 && value_on_ray(s, span->t0) < 0.0)
        kind = span->t0 > t_min ? BoundaryKind::Bounds : BoundaryKind::Open;
    const Hit h{*hit, surface_at(ray, *hit, kind)};
    s.hit_blob = this;
    s.hit_point = h.surface.local_point;
    s.hit_components.clear();
    for (const std::uint32_t k : s.active)  // a cylinder's parts meet at their ends: its component once
        if (std::find(s.hit_components.begin(), s.hit_components.end(), s.kernels[k].component) == s.hit_components.end())
            s.hit_components.push_back(s.kernels[k].component);
    return h;
}

bool Blob::occluded(const Ray& ray, double t_min, double t_max, TraceScratch& scratch) const {
    const auto span = clip(ray, t_min, t_max);
    if (!span) return false;
    BlobScratch& s = scratch_for(scratch);
    if (blocked_as_before(ray, *span, s)) {
        ++scratch.counters.blob_cached_shadows;
        return true;
    }
    const std::optional<double> inside = search(ray, *span, Query::Any, s, scratch);
    if (inside) remember_blocker(ray, *inside, s);
    return inside.has_value();
}

std::optional<double> Blob::probe_inside(const BlobScratch& s, double ta, double tb) const {
    // Where the strongest component comes nearest the ray, within the segment.
    const KernelOnRay* strongest = nullptr;
    for (const std::uint32_t i : s.active)
        if (!strongest || s.kernels[i].peak > strongest->peak) strongest = &s.kernels[i];
    const double t = std::clamp(strongest->nearest, ta, tb);
    if (!(t >= ta && t <= tb)) return std::nullopt;  // NaN
    return blob_field_at(settings_, s.kernels, s.active, t).value <= 0.0 ? std::optional<double>(t) : std::nullopt;
}

std::optional<double> Blob::search(const Ray& ray, Span span, Query query, BlobScratch& s, TraceScratch& scratch) const {
    s.kernels.clear();
    s.events.clear();
    s.active.clear();
    const BlobSegmentSolver solver(settings_for(ray));
    // The BVH hands over the components front to back, with a frontier
    // before which every component has been seen: the segments before it
    // are complete and are solved at once, so the search stops at the first
    // hit without gathering what lies behind it.
    double done = span.t0;  // the segments before it are solved
    bool started = false;   // whether the start was checked
    std::optional<double> hit;
    bool failed = false;
    // The events wait sorted latest first: the next is at the back.
    const auto advance = [&](double frontier) {
        while (!s.events.empty() && s.events.back().t < frontier) {
            const BlobScratch::Event e = s.events.back();
            if (e.t > done) {
                // Every component at t0 is in: is the ray inside already? (Not
                // asked of the quadratic pieces, which are the ray's own: see
                // BlobSegmentSolver's quadratic roots; nor where none is in
                // reach, as from a camera outside: there f = T.)
                if (!started && !settings_.metaball_quadratics) {
                    started = true;
                    if (!s.active.empty() && value_on_ray(s, span.t0) <= 0.0) {
                        hit = span.t0;
                        return false;
                    }
                }
                if (!s.active.empty() && may_reach_threshold(s, done, e.t)) {
                    if (jumps_inside(s, done)) {  // a Gaussian entered at its cut-off and took f below 0
                        hit = done;
                        return false;
                    }
                    // Any point inside will do: one evaluation often finds
                    // it where the solver would isolate the first.
                    if (query == Query::Any && !settings_.metaball_quadratics) {
                        ++scratch.counters.point_evaluations;
                        if (const auto inside = probe_inside(s, done, e.t)) {
                            hit = inside;
                            return false;
                        }
                    }
                    s.roots.clear();
                    if (solver.roots(s.kernels, s.active, done, e.t, true, s.roots, scratch.counters) == HitStatus::Failed) {
                        failed = true;
                        return false;
                    }
                    if (!s.roots.empty()) {
                        hit = s.roots.front();
                        return false;
                    }
                }
                done = e.t;
            }
            s.events.pop_back();
            apply(e, s);
        }
        return true;
    };
    const RaySizes sizes(ray);
    const auto meet = [&](std::uint32_t i, bool beside_checked = false) {
        on_ray(
            sizes, i,
            [&](const KernelOnRay& k) {
                if (!meets(k, span.t0, span.t1)) return;
                const std::size_t before = s.events.size();
                add_events(k, span.t0, span.t1, s);
                // Each into its place: few moves, as the pending events are few
                // and a new entry is mostly among the earliest of them.
                for (std::size_t j = before; j < s.events.size(); ++j) {
                    const BlobScratch::Event e = s.events[j];
                    std::size_t at = j;
                    for (; at > 0 && later(e, s.events[at - 1]); --at) s.events[at] = s.events[at - 1];
                    s.events[at] = e;
                }
            },
            beside_checked);
    };
    // Most shadow rays are not blocked and meet every component on their
    // way: through a small blob they gather them all and skip the ordered
    // walk's queue, as every ray through a blob of a few does.
    const bool gathered = components_.size() <= few_components ||
                          (query == Query::Any && components_.size() <= small_for_shadows);
    const BlobScratch::TileList* list =
        !gathered && scratch.camera_frustum ? tile_list(ray, *scratch.camera_frustum, s) : nullptr;
    if (gathered) {
        gather(sizes, span.t0, span.t1, s);
        advance(std::numeric_limits<double>::infinity());
    } else if (list) {
        ++scratch.counters.blob_list_rays;
        // The ray leaves the eye: a component no nearer it than `nearest`
        // enters at t ≥ nearest/|dir|, and so does every one after it.
        const double per_length = (1.0 - 8.0 * u4) / length(ray.dir);
        const bool beside_tested = well_scaled(sizes.dir_square);
        bool going = true;
        for (const BlobScratch::TileList::Entry& e : list->entries) {
            const double enters = e.nearest * per_length;
            if (enters > span.t1) break;
            const double along = dot(e.from_center, ray.dir), bound = e.beside * sizes.dir_square;
            if (beside_tested && along * along < bound && well_scaled(bound)) continue;  // passes beside its reach
            if (!s.events.empty() && s.events.back().t < enters && !(going = advance(enters))) break;
            meet(e.component, true);
        }
        if (going) advance(std::numeric_limits<double>::infinity());
    } else {
        bvh_->traverse_in_order(ray, span.t0, span.t1, s.queue, [&](std::uint32_t i, double limit) {
            if (i == Bvh::frontier) return advance(limit) ? span.t1 : -std::numeric_limits<double>::infinity();
            meet(i);
            return limit;
        });
    }
    scratch.counters.blob_kernels += s.kernels.size();
    if (failed) {
        ++scratch.counters.failed_queries;
        return std::nullopt;
    }
    return hit;
}

void Blob::spans(const Ray& ray, double t_min, double t_max, TraceScratch& scratch, SpanList& out) const {
    const auto span = clip(ray, t_min, t_max);
    if (!span) return;
    BlobScratch& s = scratch_for(scratch);
    gather(RaySizes(ray), span->t0, span->t1, s);
    scratch.counters.blob_kernels += s.kernels.size();
    if (s.kernels.empty()) return;
    const BlobSegmentSolver solver(settings_for(ray));
    s.roots.clear();
    sweep(s, [&](double ta, double tb) {
        if (jumps_inside(s, ta)) s.roots.push_back(ta);  // a boundary without a root of f on either side
        if (solver.roots(s.kernels, s.active, ta, tb, false, s.roots, scratch.counters) == HitStatus::Failed)
            ++scratch.counters.failed_queries;  // the spans are those of the roots found so far
        return true;
    });
    std::sort(s.roots.begin(), s.roots.end());
    std::erase_if(s.roots, [&](double t) { return !(t > span->t0 && t < span->t1); });
    // A root on a segment's end may come from both segments.
    const double merge_width = 4.0 * settings_for(ray).tangent_width;
    s.roots.erase(std::unique(s.roots.begin(), s.roots.end(), [&](double a, double b) { return b - a <= merge_width; }),
                  s.roots.end());
    spans_from_roots(
        s.roots, span->t0, span->t1, span->t0 > t_min ? BoundaryKind::Bounds : BoundaryKind::Open,
        span->t1 < t_max ? BoundaryKind::Bounds : BoundaryKind::Open,
        [&](double t) { return value_on_ray(s, t) <= 0.0; },
        [&](double t, BoundaryKind kind) { return Hit{t, surface_at(ray, t, kind)}; }, out);
}

template <class Visit>
void Blob::components_at(const Vec3d& p, Visit&& visit) const {
    // A ray of no length at p meets the boxes that hold p.
    bvh_->traverse(Ray{p, {0.5773, 0.5774, 0.5775}}, 0.0, 0.0, [&](std::uint32_t i, double limit) {
        visit(components_[i]);
        return limit;
    });
}

double Blob::value_at(const Vec3d& p) const {
    double field = 0.0;
    components_at(p, [&](const Component& c) {
        const double u = model().u_at(c.index, p);
        if (u <= c.reach) field += c.strength * kernel_value_at(settings_.kernel, u, c.blobbiness);
    });
    return settings_.threshold - field;
}

Vec3d Blob::gradient_at(const Vec3d& p) const {
    Vec3d gradient{};
    components_at(p, [&](const Component& c) { gradient = gradient + gradient_from(p, c); });
    return gradient;
}

Vec3d Blob::gradient_from(const Vec3d& p, const Component& c) const {
    if (c.cylinder) {  // q = (p − nearest)/R, so ∇u = 2q/R
        const Vec3d q =
            (p - (c.center + std::clamp(dot(p - c.center, c.axis) / c.axis_square, 0.0, 1.0) * c.axis)) * c.inverse_radius;
        const double u = dot(q, q);
        if (u > c.reach) return {};
        return -(c.strength * kernel_at(settings_.kernel, u, c.blobbiness).slope * 2.0 * c.inverse_radius) * q;
    }
    const Vec3d q = to_kernel(c).transform_point(p);
    const double u = dot(q, q);
    if (u > c.reach) return {};
    // ∇u = 2·Mᵀq; f = T − Σ s·K(u)
    return -(c.strength * kernel_at(settings_.kernel, u, c.blobbiness).slope * 2.0) * to_kernel(c).transpose_transform_vector(q);
}

Vec3d Blob::local_normal(const SurfaceRef& surface, TraceScratch& scratch) const {
    if (surface.kind == BoundaryKind::Bounds)
        return description_.clip.value_or(Bounds::make_box(bounds_)).normal_at(surface.local_point);
    Vec3d g{};
    const BlobScratch& s = scratch_for(scratch);
    if (s.hit_blob == this && s.hit_point == surface.local_point) {
        for (const std::uint32_t i : s.hit_components) g = g + gradient_from(surface.local_point, components_[i]);
    } else {
        g = gradient_at(surface.local_point);
    }
    const double n = length(g);
    return n > 0.0 && std::isfinite(n) ? g / n : Vec3d{};
}

}  // namespace zeroset
