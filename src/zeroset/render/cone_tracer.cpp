// The cone's march to the ray's hit, its edge samples and their blend (see
// cone_tracer.hpp).
#include "zeroset/render/cone_tracer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "zeroset/accel/primitive.hpp"

namespace zeroset {

namespace {
constexpr double infinity = std::numeric_limits<double>::infinity();
}  // namespace

double disk_coverage(double u) {
    if (u >= 1.0) return 0.0;
    if (u <= -1.0) return 1.0;
    return (std::acos(u) - u * std::sqrt(1.0 - u * u)) / std::numbers::pi;
}

ConeTracer::ConeTracer(const SceneDistance& distance, double footprint)
    : distance_(&distance), probe_(distance), footprint_(footprint) {
    const Box3& reach = distance.reach();
    least_step_ = 1e-6 * (reach.valid() ? std::max(reach.diagonal(), 1e-300) : 1.0);
}

void ConeTracer::grow_boxes(const Vec3d& eye) {
    grown_for_ = eye;
    grown_.clear();
    bounded_.clear();
    unbounded_.clear();
    std::vector<Box3> bounded_boxes;
    const std::vector<Box3>& boxes = distance_->root_boxes();
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const Box3& box = boxes[i];
        grown_.push_back(box);
        if (!box.valid()) continue;
        if (!is_bounded(box)) {
            unbounded_.push_back(static_cast<int>(i));
            continue;
        }
        // Grown by the cone's widest radius over the box: the distance from
        // the eye to its farthest corner bounds t in it.
        double farthest = 0.0;
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3d c{corner & 1 ? box.hi.x : box.lo.x, corner & 2 ? box.hi.y : box.lo.y,
                          corner & 4 ? box.hi.z : box.lo.z};
            farthest = std::max(farthest, length(c - eye));
        }
        // A point of the box within r(t) = κt of the ray's point has
        // t ≤ farthest / (1 − κ).
        if (footprint_ >= 0.5) {  // pixels wider than half their distance: no useful box
            grown_.back() = {{-infinity, -infinity, -infinity}, {infinity, infinity, infinity}};
            unbounded_.push_back(static_cast<int>(i));
            continue;
        }
        const double margin = footprint_ * farthest / (1.0 - footprint_) * 1.01 + least_step_;
        grown_.back() = {box.lo - Vec3d{margin, margin, margin}, box.hi + Vec3d{margin, margin, margin}};
        bounded_.push_back(static_cast<int>(i));
        bounded_boxes.push_back(grown_.back());
    }
    bvh_.emplace(bounded_boxes, 1);
}

void ConeTracer::find_windows(const Ray& ray, const Span& span) {
    if (!bvh_ || !(grown_for_ == ray.origin)) grow_boxes(ray.origin);
    windows_.clear();
    const auto add = [&](int root) {
        if (const std::optional<Span> in = grown_[static_cast<std::size_t>(root)].clip(ray, span.t0, span.t1))
            windows_.push_back({*in, root});
    };
    for (const int root : unbounded_) add(root);
    if (!bvh_->empty())
        bvh_->traverse(ray, span.t0, span.t1, [&](std::uint32_t i, double t_max) {
            add(bounded_[i]);
            return t_max;
        });
    std::sort(windows_.begin(), windows_.end(), [](const Window& a, const Window& b) { return a.span.t0 < b.span.t0; });
}

void ConeTracer::candidates_at(double t) {
    candidates_.clear();
    for (const Window& w : windows_)
        if (w.span.t0 <= t && t <= w.span.t1) candidates_.push_back(w.root);
}

int ConeTracer::find_edges(const Ray& ray, double t_end, bool ends_on_hit, ConeCounters& counters) {
    const std::uint64_t evaluations_before = probe_.evaluations();
    const Box3& reach = distance_->reach();
    const std::optional<Span> span = reach.valid() ? reach.clip(ray, 0.0, t_end) : std::nullopt;
    int found = 0;
    if (!span) return found;
    find_windows(ray, *span);

    Edge nearest;  // of the stretch the cone is in, while ratio < 1
    bool in_stretch = false;
    const auto close_stretch = [&] {
        if (in_stretch) edges_[static_cast<std::size_t>(found++)] = nearest;
        in_stretch = false;
    };
    double t = span->t0, window = span->t1 - span->t0;
    double jump = 0.0;          // the stretch of t an interval test tries next; 0: none
    double reach_factor = 4.0;  // how many point steps long it is
    int steps = 0;
    std::size_t next_window = 0;  // windows_ before it have begun
    open_.clear();
    for (; t < span->t1 && steps < max_steps && found < max_edges - 1; ++steps) {
        // Only the top-level nodes whose grown boxes the ray is in can come
        // within the cone; with none, the march jumps to the next one's box.
        for (; next_window < windows_.size() && windows_[next_window].span.t0 <= t; ++next_window)
            open_.push_back(next_window);
        std::erase_if(open_, [&](std::size_t w) { return windows_[w].span.t1 < t; });
        active_.clear();
        for (const std::size_t w : open_) active_.push_back(windows_[w].root);
        const double next_start = next_window < windows_.size() ? windows_[next_window].span.t0 : span->t1;
        if (active_.empty()) {
            close_stretch();
            t = next_start;
            window = span->t1 - t;
            continue;
        }
        if (!in_stretch && jump > 0.0) {
            // Interval analysis over the cone (survey Fig. 9, step 2): a
            // stretch of it that holds no solid is passed whole, and the next
            // try is twice as long — sphere tracing's slow approach to a
            // surface met at a grazing angle becomes a few such jumps.
            const double t1 = std::min({t + jump, next_start, span->t1});
            const double r1 = footprint_ * t1;
            const Vec3d a = ray.at(t), b = ray.at(t1), grow{r1, r1, r1};
            if (t1 > t && probe_.holds_no_solid({min(a, b) - grow, max(a, b) + grow}, active_)) {
                t = t1;
                jump *= 2.0;
                continue;
            }
            reach_factor = std::max(0.5 * reach_factor, 1.5);  // the jumps fail here: try shorter ones
        }
        const double radius = footprint_ * t;
        const DistanceBound bound = probe_.outside_at(ray.at(t), std::max(window, 2.0 * radius), active_);
        const double ratio = radius > 0.0 ? bound.distance / radius : 1.0;
        if (ratio < 1.0) {
            // Another surface taking over the bound ends the stretch of the
            // one before (an edge just in front of the surface hit, say).
            if (in_stretch && bound.leaf != nearest.bound.leaf && bound.leaf >= 0 && nearest.bound.leaf >= 0)
                close_stretch();
            if (!in_stretch || ratio < nearest.ratio) nearest = {t, ratio, radius, 0.5 * (t + t_end), bound};
            in_stretch = true;
        } else {
            close_stretch();
        }
        const double step = std::max({bound.distance, 0.5 * radius, least_step_});
        window = 2.0 * step;
        jump = bound.distance > 2.0 * radius ? reach_factor * step : 0.0;  // far from every surface: try intervals next
        t = std::min(t + step, std::max(next_start, t + least_step_));
    }
    // A stretch still open where the ray hits is the hit surface coming
    // into the cone: the ray's own colour covers it.
    if (!ends_on_hit) close_stretch();
    counters.steps += static_cast<std::uint64_t>(steps);
    if (steps == max_steps) ++counters.gave_up;
    counters.evaluations += probe_.evaluations() - evaluations_before;
    return found;
}

std::optional<ConeTracer::Edge> ConeTracer::find_inner_edge(const Ray& ray, double t_hit, const Vec3d& normal,
                                                           ConeCounters& counters) {
    const std::uint64_t evaluations_before = probe_.evaluations();
    Edge deepest{t_hit, 0.0, footprint_ * t_hit, t_hit, {}};
    const Box3& reach = distance_->reach();
    const std::optional<Span> rest = reach.clip(ray, t_hit, std::numeric_limits<double>::infinity());
    find_windows(ray, rest.value_or(Span{t_hit, t_hit}));
    candidates_.clear();
    for (const Window& w : windows_) candidates_.push_back(w.root);
    int steps = 1;
    // Most hits are far from a silhouette: a first look as deep as the cone
    // is wide, past the hit across the surface's tangent plane, settles them.
    const double across = std::max(std::abs(dot(normal, ray.dir)), 0.1);
    const double t_look = t_hit + 1.5 * footprint_ * t_hit / across, radius_there = footprint_ * t_look;
    if (probe_.inside_at(ray.at(t_look), 2.0 * radius_there, candidates_).distance >= radius_there) {
        counters.steps += 1;
        counters.evaluations += probe_.evaluations() - evaluations_before;
        return std::nullopt;
    }
    double t = t_hit, depth = 0.0;
    bool covered = false;
    for (; steps < max_steps; ++steps) {
        t += std::max({depth, 0.5 * footprint_ * t, least_step_});
        const double radius = footprint_ * t;
        const Vec3d p = ray.at(t);
        const DistanceBound inside = probe_.inside_at(p, 2.0 * radius, candidates_);
        depth = inside.distance;
        if (depth >= radius) {
            covered = true;  // the solid fills the cone here: no silhouette is near
            break;
        }
        if (depth == 0.0 && probe_.outside_at(p, radius, candidates_).distance > 0.0) break;  // out of the solid again
        if (depth / radius > deepest.ratio) deepest = {t, depth / radius, radius, t, inside};
    }
    counters.steps += static_cast<std::uint64_t>(steps);
    counters.evaluations += probe_.evaluations() - evaluations_before;
    if (steps == max_steps) ++counters.gave_up;
    if (covered || steps == max_steps || deepest.bound.leaf < 0) return std::nullopt;
    // A chord through the solid far longer than it is deep passes near a
    // silhouette; a short one crosses a sheet thinner than the cone, which
    // still covers the whole pixel when seen face on.
    if (t - t_hit < 4.0 * deepest.ratio * deepest.radius) return std::nullopt;
    deepest.t_far = t;  // where the ray leaves the solid: an aimed ray meeting it sooner meets it
    return deepest;
}

std::optional<Vec3d> ConeTracer::across_edge(const Ray& ray, const Edge& edge) {
    // Two directions spanning the disk, perpendicular to the ray.
    const Vec3d& d = ray.dir;
    const Vec3d helper = std::abs(d.x) < 0.6 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
    const Vec3d e1 = normalize(cross(d, helper)), e2 = cross(d, e1);
    const Vec3d p = ray.at(edge.t);
    const double h = 0.5 * edge.radius;
    const bool inner = edge.bound.complement;
    const auto bound = [&](const Vec3d& q) {
        return inner ? probe_.inside_at(q, 2.0 * edge.radius, candidates_).distance
                     : probe_.outside_at(q, 2.0 * edge.radius, candidates_).distance;
    };
    // Down the bound across the disk — the distance to the solid (outer
    // edges) or the depth in it (inner ones) — whatever the surface's shape — a crease or a
    // CSG edge has no one gradient that says it.
    Vec3d way = e1 * (bound(p - e1 * h) - bound(p + e1 * h)) + e2 * (bound(p - e2 * h) - bound(p + e2 * h));
    if (!(length(way) > 0.0)) {  // flat across the disk: the surface's own gradient
        way = probe_.toward_surface(p, edge.bound);
        way = way - d * dot(way, d);
    }
    const double len = length(way);
    if (!(len > 0.0) || !std::isfinite(len)) return std::nullopt;
    return way / len;
}

std::optional<ConeTracer::EdgeSample> ConeTracer::resolve(SceneTracer& tracer, const Ray& ray, const Edge& edge,
                                                         ShadingCounters& shading, int bounces, ConeCounters& counters) {
    const Vec3d p = ray.at(edge.t);
    const std::optional<Vec3d> across = across_edge(ray, edge);
    if (!across) return std::nullopt;
    const Vec3d toward = *across;

    // A ray aimed at p + s·toward is past the edge when it meets the edge's
    // own surface (an outer edge) or misses the ray's own solid (an inner
    // one); either shows before t_far. At s = d the bound says it is not.
    const bool inner = edge.bound.complement;
    std::optional<SurfaceHit> seen;
    Ray seen_ray = ray;
    const auto past = [&](double s) {
        const Ray aimed{ray.origin, normalize(p + toward * s - ray.origin)};
        ++counters.aimed_rays;
        const std::optional<SurfaceHit> hit = tracer.closest_hit(aimed, std::numeric_limits<double>::infinity());
        const bool meets = hit && hit->t < edge.t_far;
        if (meets == inner) return false;
        seen = hit;
        seen_ray = aimed;
        return true;
    };
    double near = edge.ratio * edge.radius, far = 0.5 * (near + edge.radius);
    if (!past(far)) {
        near = far;
        far = edge.radius;
        if (!past(far)) return std::nullopt;  // the surface does not reach into the cone after all
    }
    for (int i = 0; i < edge_refinements; ++i) {
        const double middle = 0.5 * (near + far);
        if (past(middle)) far = middle;
        else near = middle;
    }
    // What lies past the edge covers the disk beyond it: the edge's
    // surface, for an outer edge, and what is behind, for an inner one.
    const double beyond = disk_coverage(0.5 * (near + far) / edge.radius);
    const Vec3d color = seen ? shade(tracer, seen_ray, *seen, shading, bounces) : tracer.prepared().scene().background;
    return EdgeSample{color, beyond};
}

Vec3d ConeTracer::pixel(SceneTracer& tracer, const Ray& ray, const std::optional<SurfaceHit>& hit,
                        const Vec3d& ray_color, ShadingCounters& shading, int bounces, ConeCounters& counters) {
    const auto resolved = [&](const Edge& edge) {
        std::optional<EdgeSample> sample = resolve(tracer, ray, edge, shading, bounces, counters);
        ++(sample ? counters.edges : counters.missed_edges);
        return sample;
    };
    Vec3d own = ray_color;
    if (hit) {
        // The ray's own surface, near its silhouette, leaves part of the cone to what lies behind.
        if (const std::optional<Edge> inner = find_inner_edge(ray, hit->t, hit->normal, counters))
            if (const auto behind = resolved(*inner)) own = ray_color * (1.0 - behind->coverage) + behind->color * behind->coverage;
    }
    const double t_end = hit ? hit->t : std::numeric_limits<double>::infinity();
    const int found = find_edges(ray, t_end, hit.has_value(), counters);
    Vec3d color{};
    double covered = 0.0;
    for (int i = 0; i < found; ++i) {
        candidates_at(edges_[static_cast<std::size_t>(i)].t);
        const auto sample = resolved(edges_[static_cast<std::size_t>(i)]);
        if (!sample) continue;
        const double alpha = (1.0 - covered) * sample->coverage;
        color += sample->color * alpha;
        covered += alpha;
    }
    return color + own * (1.0 - covered);
}

}  // namespace zeroset
