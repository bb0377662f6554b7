// Nanoseconds per solve of the polynomial solvers (survey §3.4 and Yuksel,
// HPG 2022) at degrees 2, 3, 4, 6 and 8: all real roots in [0, 1] of random
// polynomials whose roots all lie in [0, 1] (fixed seed), and the first root
// alone. The inputs are built before the timed loop, which cycles through
// 256 of them.
#include <benchmark/benchmark.h>

#include <array>
#include <random>
#include <span>
#include <vector>

#include "zeroset/roots/descartes.hpp"
#include "zeroset/roots/fast_polynomial.hpp"
#include "zeroset/roots/laguerre.hpp"
#include "zeroset/roots/sturm.hpp"

namespace {

using zeroset::PolynomialRoots;
using Solve = PolynomialRoots (*)(std::span<const double>, double, double, std::span<double>);

/// 256 polynomials of the degree, each the product of (t − rᵢ), rᵢ ∈ [0, 1].
std::vector<std::vector<double>> inputs(int degree) {
    std::mt19937_64 rng(1984);
    std::uniform_real_distribution<double> root(0.0, 1.0);
    std::vector<std::vector<double>> polynomials(256);
    for (auto& c : polynomials) {
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

template <Solve solve, bool first_only>
void bm_solve(benchmark::State& state) {
    const auto polynomials = inputs(static_cast<int>(state.range(0)));
    std::array<double, zeroset::max_polynomial_degree> out{};
    const std::span<double> wanted = first_only ? std::span<double>(out).first(1) : std::span<double>(out);
    std::size_t i = 0;
    long evaluations = 0;
    for (auto _ : state) {
        const PolynomialRoots r = solve(polynomials[i], 0.0, 1.0, wanted);
        evaluations += r.evaluations;
        benchmark::DoNotOptimize(out.data());
        benchmark::DoNotOptimize(r);
        i = (i + 1) % polynomials.size();
    }
    state.counters["evaluations"] =
        benchmark::Counter(static_cast<double>(evaluations), benchmark::Counter::kAvgIterations);
}

void degrees(benchmark::internal::Benchmark* b) {
    for (const int degree : {2, 3, 4, 6, 8}) b->Arg(degree);
}

BENCHMARK(bm_solve<zeroset::sturm_roots, false>)->Name("sturm/all")->Apply(degrees);
BENCHMARK(bm_solve<zeroset::descartes_roots, false>)->Name("descartes/all")->Apply(degrees);
BENCHMARK(bm_solve<zeroset::laguerre_roots, false>)->Name("laguerre/all")->Apply(degrees);
BENCHMARK(bm_solve<zeroset::fast_polynomial_roots, false>)->Name("fast/all")->Apply(degrees);
BENCHMARK(bm_solve<zeroset::sturm_roots, true>)->Name("sturm/first")->Apply(degrees);
BENCHMARK(bm_solve<zeroset::descartes_roots, true>)->Name("descartes/first")->Apply(degrees);
BENCHMARK(bm_solve<zeroset::fast_polynomial_roots, true>)->Name("fast/first")->Apply(degrees);

}  // namespace

BENCHMARK_MAIN();
