// Newton basins (survey Fig. 5): Newton's method per pixel in complex
// arithmetic, then the real limits clustered into distinct roots and coloured.
#include "zeroset/render/newton_basins.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <thread>

#include "zeroset/render/render_settings.hpp"

namespace zeroset {

namespace {

constexpr double converged_step = 1e-10;    // relative to max(1, |t|)
constexpr double real_tolerance = 1e-8;     // |Im t| of a real root, relative
constexpr double cluster_tolerance = 1e-6;  // real limits closer than this are one root, relative
constexpr double escape_radius = 1e10;
constexpr int max_iteration_limit = 100000;

double scale(Complex t) { return std::max(1.0, modulus(t)); }

void check_settings(const Ray& ray, const BasinSettings& s) {
    require_in_range(s.width, 1, max_image_side, "width");
    require_in_range(s.height, 1, max_image_side, "height");
    require_image_fits(s.width, s.height);
    require_in_range(s.max_iterations, 1, max_iteration_limit, "iterations");
    require_in_range(s.threads, 0, 4096, "threads");
    const ComplexRect& r = s.region;
    if (!(std::isfinite(r.re_min) && std::isfinite(r.re_max) && std::isfinite(r.im_min) && std::isfinite(r.im_max)))
        throw RenderError("the rectangle of the t-plane must have finite corners");
    if (!(r.re_min < r.re_max && r.im_min < r.im_max))
        throw RenderError("the rectangle of the t-plane is empty (need re min < re max and im min < im max)");
    const double length_squared = dot(ray.dir, ray.dir);
    if (!(length_squared > 0.0 && std::isfinite(length_squared) && std::isfinite(dot(ray.origin, ray.origin))))
        throw RenderError("the ray needs a finite origin and a finite, non-zero direction");
}

/// Where one pixel's start value went: a real limit is labelled later.
struct PixelOutcome {
    NewtonOutcome::Kind kind = NewtonOutcome::Kind::Diverged;
    double root = 0.0;  // Re of the limit, for a real root
    int iterations = 0;
};

/// The distinct real limits: sorted, then split wherever two neighbours lie
/// further apart than the tolerance; each cluster's median is its root.
std::vector<double> distinct_roots(std::vector<double> limits) {
    std::sort(limits.begin(), limits.end());
    std::vector<double> roots;
    std::size_t begin = 0;
    for (std::size_t i = 1; i <= limits.size(); ++i) {
        const bool cluster_ends = i == limits.size() ||
                                  limits[i] - limits[i - 1] > cluster_tolerance * std::max(1.0, std::abs(limits[i]));
        if (!cluster_ends) continue;
        roots.push_back(limits[begin + (i - begin) / 2]);
        begin = i;
    }
    return roots;
}

/// The index of the root nearest to `t` in the ascending list.
int root_index(const std::vector<double>& roots, double t) {
    const auto above = std::lower_bound(roots.begin(), roots.end(), t);
    if (above == roots.begin()) return 0;
    if (above == roots.end() || t - *(above - 1) < *above - t) return static_cast<int>(above - roots.begin()) - 1;
    return static_cast<int>(above - roots.begin());
}

/// Fast convergence is bright, slow is dark — the classic basin shading,
/// which shows the fractal boundaries inside each basin.
float brightness(int iterations) {
    return static_cast<float>(0.2 + 0.8 * std::pow(0.85, static_cast<double>(std::max(0, iterations - 3))));
}

}  // namespace

NewtonOutcome newton_from(Evaluator<Jet<Complex>>& eval, const Ray& ray, Complex t0, int max_iterations) {
    Complex t = t0;
    for (int i = 1; i <= max_iterations; ++i) {
        const Jet<Complex> h = evaluate_along_ray(eval, ray.origin, ray.dir, t);
        const Complex step = h.v / h.d1;  // eq. 22
        t = t - step;
        if (!is_finite(t) || modulus(t) > escape_radius) return {NewtonOutcome::Kind::Diverged, t, i};
        if (modulus(step) <= converged_step * scale(t)) {
            const bool real = std::abs(t.im) <= real_tolerance * scale(t);
            return {real ? NewtonOutcome::Kind::RealRoot : NewtonOutcome::Kind::ComplexRoot, t, i};
        }
    }
    return {NewtonOutcome::Kind::Diverged, t, max_iterations};
}

Complex basin_start(const BasinSettings& settings, int x, int y) {
    const ComplexRect& r = settings.region;
    const double u = (static_cast<double>(x) + 0.5) / static_cast<double>(settings.width);
    const double v = (static_cast<double>(y) + 0.5) / static_cast<double>(settings.height);
    return {r.re_min + u * (r.re_max - r.re_min), r.im_max - v * (r.im_max - r.im_min)};
}

Vec3f basin_colour(int index) {
    // Tableau 10 in linear RGB (brown and grey swapped for two light tints).
    static constexpr std::array<Vec3f, 10> palette{{
        {0.0137f, 0.1845f, 0.4564f},  // blue
        {1.0000f, 0.2122f, 0.0044f},  // orange
        {0.0252f, 0.3515f, 0.0252f},  // green
        {0.6724f, 0.0203f, 0.0212f},  // red
        {0.2961f, 0.1356f, 0.5089f},  // purple
        {0.7682f, 0.1845f, 0.5395f},  // pink
        {0.5029f, 0.5089f, 0.0160f},  // olive
        {0.0086f, 0.5149f, 0.6240f},  // cyan
        {0.4233f, 0.5711f, 0.8070f},  // light blue
        {1.0000f, 0.4969f, 0.1878f},  // light orange
    }};
    return palette[static_cast<std::size_t>(index) % palette.size()];
}

BasinMap newton_basins(const Tape& tape, const Ray& ray, const BasinSettings& settings) {
    check_settings(ray, settings);
    const int width = settings.width, height = settings.height;
    std::vector<PixelOutcome> outcomes(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));

    std::atomic<int> next_row{0};
    const auto worker = [&] {
        Evaluator<Jet<Complex>> eval(tape);
        for (int y = next_row++; y < height; y = next_row++) {
            for (int x = 0; x < width; ++x) {
                const NewtonOutcome o = newton_from(eval, ray, basin_start(settings, x, y), settings.max_iterations);
                outcomes[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] =
                    {o.kind, o.limit.re, o.iterations};
            }
        }
    };
    {
        const int thread_count = settings.threads > 0
                                     ? settings.threads
                                     : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
        std::vector<std::jthread> pool;
        for (int t = 1; t < std::min(thread_count, height); ++t) pool.emplace_back(worker);
        worker();
    }

    std::vector<double> limits;
    for (const PixelOutcome& o : outcomes)
        if (o.kind == NewtonOutcome::Kind::RealRoot) limits.push_back(o.root);

    BasinMap map;
    map.real_roots = distinct_roots(std::move(limits));
    map.image = Image(width, height);
    map.labels.resize(outcomes.size());
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
        const PixelOutcome& o = outcomes[i];
        switch (o.kind) {
            case NewtonOutcome::Kind::RealRoot: {
                const int index = root_index(map.real_roots, o.root);
                map.labels[i] = index;
                map.image.pixels[i] = basin_colour(index) * brightness(o.iterations);
                break;
            }
            case NewtonOutcome::Kind::ComplexRoot:
                map.labels[i] = BasinMap::complex_root;
                map.image.pixels[i] = {0.0f, 0.0f, 0.0f};
                break;
            case NewtonOutcome::Kind::Diverged:
                map.labels[i] = BasinMap::diverged;
                map.image.pixels[i] = {1.0f, 1.0f, 1.0f};
                break;
        }
    }
    return map;
}

}  // namespace zeroset
