// Nanoseconds per solve of the polynomial solvers (survey §3.4 and Yuksel,
// HPG 2022) at degrees 2, 3, 4, 6 and 8, all real roots in the span and the
// first root alone, on two kinds of input:
// - random polynomials whose roots all lie in [0, 1] (fixed seed), solved on
//   [0, 1] — 256 of them;
// - real ray polynomials ("ray/…"): F(t) = f∘r(t) of the primary rays of a
//   64×64 image of an algebraic scene (sphere, Clebsch cubic, Kummer quartic,
//   Barth sextic, Chmutov octic), each solved on its ray's span inside the
//   object's bounds. Every ray that meets the bounds is kept, hit or miss, as
//   a renderer sees them; the counter with_root is the fraction with a root.
// The ray polynomials are formed as the polynomial method forms them, about
// the span's midpoint; "ray/form/…" times that forming, compiled and by the
// reference walk. The closed form joins the solvers at degrees ≤ 4. The
// inputs are built before the timed loop, which cycles through them.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <exception>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/ray_polynomial.hpp"
#include "zeroset/expr/ray_polynomial_program.hpp"
#include "zeroset/expr/tape.hpp"
#include "zeroset/render/camera_rays.hpp"
#include "zeroset/roots/closed_form.hpp"
#include "zeroset/roots/descartes.hpp"
#include "zeroset/roots/fast_polynomial.hpp"
#include "zeroset/roots/laguerre.hpp"
#include "zeroset/roots/sturm.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace {

using zeroset::PolynomialRoots;
using Solve = PolynomialRoots (*)(std::span<const double>, double, double, std::span<double>);

/// A polynomial to solve on [t0, t1].
struct Input {
    std::vector<double> c;
    double t0 = 0.0;
    double t1 = 1.0;
};

/// 256 polynomials of the degree, each the product of (t − rᵢ), rᵢ ∈ [0, 1].
std::vector<Input> random_inputs(int degree) {
    std::mt19937_64 rng(1984);
    std::uniform_real_distribution<double> root(0.0, 1.0);
    std::vector<Input> polynomials(256);
    for (Input& p : polynomials) {
        std::vector<double>& c = p.c;
        c = {1.0};
        for (int k = 0; k < degree; ++k) {
            const double r = root(rng);
            std::vector<double> next(c.size() + 1, 0.0);
            for (std::size_t i = 0; i < c.size(); ++i) {
                next[i + 1] += c[i];
                next[i] -= r * c[i];
            }
            c = next;
        }
    }
    return polynomials;
}

/// A ray and the centre its polynomial was formed about.
struct CentredRay {
    zeroset::Ray ray;
    double t_c;
};

/// The ray polynomials of one scene, their rays, and the fraction with a root.
struct RayInputs {
    std::unique_ptr<zeroset::Tape> tape;
    std::vector<Input> polynomials;
    std::vector<CentredRay> rays;
    double with_root = 0.0;
};

const char* scene_of_degree(int degree) {
    switch (degree) {
        case 2: return "sphere.zs";
        case 3: return "clebsch.zs";
        case 4: return "kummer.zs";
        case 6: return "barth_sextic.zs";
        default: return "chmutov_octic.zs";
    }
}

/// F(t) along the primary rays of a 64×64 image of the scene's first object,
/// clipped to its bounds; throws unless the surface has the given degree.
RayInputs make_ray_inputs(int degree) {
    constexpr int side = 64;
    RayInputs inputs;
    const zeroset::Scene scene =
        zeroset::load_scene(std::string(ZEROSET_SOURCE_DIR) + "/scenes/algebraic/" + scene_of_degree(degree));
    const zeroset::Object& object = placed_objects(scene).at(0).object();
    inputs.tape = std::make_unique<zeroset::Tape>(object.surface);
    const zeroset::Tape& tape = *inputs.tape;
    auto compiled = zeroset::RayPolynomialProgram::compile(tape);
    if (!compiled.program || compiled.program->degree() != degree)
        throw std::runtime_error(std::string(scene_of_degree(degree)) + " is not of degree " + std::to_string(degree));
    zeroset::RayPolynomialProgram& program = *compiled.program;
    const zeroset::CameraRays camera(scene.camera, side, side);
    int with_root = 0;
    for (int py = 0; py < side; ++py) {
        for (int px = 0; px < side; ++px) {
            const zeroset::Ray ray = camera.ray(px, py, 0.5, 0.5);
            const auto span = object.bounds.clip(ray, 0.0, std::numeric_limits<double>::max());
            if (!span) continue;
            // As the polynomial method forms it: centred on the span's midpoint.
            const double t_c = 0.5 * span->t0 + 0.5 * span->t1;
            program.evaluate(ray, t_c);
            const auto c = program.value();
            const Input input{{c.begin(), c.end()}, span->t0 - t_c, span->t1 - t_c};
            inputs.polynomials.push_back(input);
            inputs.rays.push_back({ray, t_c});
            std::array<double, 1> first{};
            if (zeroset::sturm_roots(c, input.t0, input.t1, first).count > 0) ++with_root;
        }
    }
    inputs.with_root = static_cast<double>(with_root) / static_cast<double>(inputs.polynomials.size());
    return inputs;
}

/// Built once per degree: every repetition of every solver sees the same rays.
const RayInputs& ray_inputs(int degree) {
    static std::map<int, RayInputs> cache;
    const auto it = cache.find(degree);
    return it != cache.end() ? it->second : cache.emplace(degree, make_ray_inputs(degree)).first->second;
}

/// The closed form with the solvers' signature. Its work is not counted in
/// evaluations (reported as 0).
PolynomialRoots closed_form(std::span<const double> c, double t0, double t1, std::span<double> out) {
    std::array<double, zeroset::max_closed_form_degree> roots{};
    const int found = zeroset::closed_form_roots_in(c, t0, t1, roots);
    const int kept = std::min(found, static_cast<int>(out.size()));
    std::copy_n(roots.begin(), kept, out.begin());
    return {kept, 0};
}

template <Solve solve, bool first_only>
void run(benchmark::State& state, const std::vector<Input>& polynomials) {
    std::array<double, zeroset::max_polynomial_degree> out{};
    const std::span<double> wanted = first_only ? std::span<double>(out).first(1) : std::span<double>(out);
    std::size_t i = 0;
    long evaluations = 0;
    for (auto _ : state) {
        const Input& p = polynomials[i];
        const PolynomialRoots r = solve(p.c, p.t0, p.t1, wanted);
        evaluations += r.evaluations;
        benchmark::DoNotOptimize(out.data());
        benchmark::DoNotOptimize(r);
        i = (i + 1) % polynomials.size();
    }
    state.counters["evaluations"] =
        benchmark::Counter(static_cast<double>(evaluations), benchmark::Counter::kAvgIterations);
}

template <Solve solve, bool first_only>
void bm_solve(benchmark::State& state) {
    run<solve, first_only>(state, random_inputs(static_cast<int>(state.range(0))));
}

template <Solve solve, bool first_only>
void bm_ray_solve(benchmark::State& state) {
    try {
        const RayInputs& inputs = ray_inputs(static_cast<int>(state.range(0)));
        run<solve, first_only>(state, inputs.polynomials);
        state.counters["with_root"] = inputs.with_root;
        state.counters["rays"] = static_cast<double>(inputs.polynomials.size());
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
    }
}

/// Forming F along the same rays: the compiled program (centred, with its
/// rounding bound) against the reference walk in Polynomial arithmetic.
void bm_form_compiled(benchmark::State& state) {
    const RayInputs& inputs = ray_inputs(static_cast<int>(state.range(0)));
    auto program = *zeroset::RayPolynomialProgram::compile(*inputs.tape).program;
    std::size_t i = 0;
    for (auto _ : state) {
        program.evaluate(inputs.rays[i].ray, inputs.rays[i].t_c);
        benchmark::DoNotOptimize(program.value().data());
        i = (i + 1) % inputs.rays.size();
    }
}

void bm_form_reference(benchmark::State& state) {
    const RayInputs& inputs = ray_inputs(static_cast<int>(state.range(0)));
    zeroset::Evaluator<zeroset::Polynomial> eval(*inputs.tape);
    std::size_t i = 0;
    for (auto _ : state) {
        const auto f = zeroset::ray_polynomial(eval, inputs.rays[i].ray);
        benchmark::DoNotOptimize(f);
        i = (i + 1) % inputs.rays.size();
    }
}

void degrees(benchmark::internal::Benchmark* b) {
    for (const int degree : {2, 3, 4, 6, 8}) b->Arg(degree);
}

void closed_form_degrees(benchmark::internal::Benchmark* b) {
    for (const int degree : {2, 3, 4}) b->Arg(degree);
}

BENCHMARK(bm_solve<zeroset::sturm_roots, false>)->Name("sturm/all")->Apply(degrees);
BENCHMARK(bm_solve<zeroset::descartes_roots, false>)->Name("descartes/all")->Apply(degrees);
BENCHMARK(bm_solve<zeroset::laguerre_roots, false>)->Name("laguerre/all")->Apply(degrees);
BENCHMARK(bm_solve<zeroset::fast_polynomial_roots, false>)->Name("fast/all")->Apply(degrees);
BENCHMARK(bm_solve<closed_form, false>)->Name("closed_form/all")->Apply(closed_form_degrees);
BENCHMARK(bm_solve<zeroset::sturm_roots, true>)->Name("sturm/first")->Apply(degrees);
BENCHMARK(bm_solve<zeroset::descartes_roots, true>)->Name("descartes/first")->Apply(degrees);
BENCHMARK(bm_solve<zeroset::fast_polynomial_roots, true>)->Name("fast/first")->Apply(degrees);
BENCHMARK(bm_solve<closed_form, true>)->Name("closed_form/first")->Apply(closed_form_degrees);

BENCHMARK(bm_form_compiled)->Name("ray/form/compiled")->Apply(degrees);
BENCHMARK(bm_form_reference)->Name("ray/form/reference")->Apply(degrees);
BENCHMARK(bm_ray_solve<zeroset::sturm_roots, false>)->Name("ray/sturm/all")->Apply(degrees);
BENCHMARK(bm_ray_solve<zeroset::descartes_roots, false>)->Name("ray/descartes/all")->Apply(degrees);
BENCHMARK(bm_ray_solve<zeroset::laguerre_roots, false>)->Name("ray/laguerre/all")->Apply(degrees);
BENCHMARK(bm_ray_solve<zeroset::fast_polynomial_roots, false>)->Name("ray/fast/all")->Apply(degrees);
BENCHMARK(bm_ray_solve<closed_form, false>)->Name("ray/closed_form/all")->Apply(closed_form_degrees);
BENCHMARK(bm_ray_solve<zeroset::sturm_roots, true>)->Name("ray/sturm/first")->Apply(degrees);
BENCHMARK(bm_ray_solve<zeroset::descartes_roots, true>)->Name("ray/descartes/first")->Apply(degrees);
BENCHMARK(bm_ray_solve<zeroset::laguerre_roots, true>)->Name("ray/laguerre/first")->Apply(degrees);
BENCHMARK(bm_ray_solve<zeroset::fast_polynomial_roots, true>)->Name("ray/fast/first")->Apply(degrees);
BENCHMARK(bm_ray_solve<closed_form, true>)->Name("ray/closed_form/first")->Apply(closed_form_degrees);

}  // namespace

BENCHMARK_MAIN();
