// Evaluator throughput on a real model (bear.vm), in clause·points per second,
// next to a straight-line SIMD multiply-add loop over the same number of values
// in the same binary — the machine's own ceiling for this kind of work; and
// the tape pruner's two steps on prospero.vm, as slicing uses them.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "fma_ceiling.hpp"
#include "zeroset/expr/batch_evaluator.hpp"
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/tape_pruner.hpp"
#include "zeroset/expr/vm_import.hpp"

namespace {

using zeroset::Tape;

Tape model_tape(const char* name) {
    std::ifstream in(std::string(ZEROSET_MODELS_DIR) + "/" + name);
    return Tape(zeroset::import_vm(in));
}

const Tape& bear_tape() {
    static const Tape tape = model_tape("bear.vm");
    return tape;
}

template <class F>
struct Points {
    std::vector<F> x, y, z, out;
    explicit Points(std::size_t n) : x(n), y(n), z(n), out(n) {
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        for (std::size_t i = 0; i < n; ++i) {
            x[i] = static_cast<F>(u(rng));
            y[i] = static_cast<F>(u(rng));
            z[i] = static_cast<F>(u(rng));
        }
    }
};

void set_rate(benchmark::State& state, std::size_t clauses, std::size_t points) {
    state.counters["clause_points/s"] = benchmark::Counter(static_cast<double>(clauses * points),
                                                           benchmark::Counter::kIsIterationInvariantRate);
    state.counters["clauses"] = static_cast<double>(clauses);
}

template <class F>
void BM_BatchEvaluator_Bear(benchmark::State& state) {
    const Tape& tape = bear_tape();
    const auto n = static_cast<std::size_t>(state.range(0));
    Points<F> p(n);
    zeroset::BatchEvaluator<F> eval(tape);
    for (auto _ : state) {
        eval.evaluate(p.x, p.y, p.z, p.out);
        benchmark::DoNotOptimize(p.out.data());
        benchmark::ClobberMemory();
    }
    set_rate(state, tape.clauses().size(), n);
}
BENCHMARK(BM_BatchEvaluator_Bear<float>)->Arg(4096);
BENCHMARK(BM_BatchEvaluator_Bear<double>)->Arg(4096);

template <class T>
void BM_PointEvaluator_Bear(benchmark::State& state) {
    const Tape& tape = bear_tape();
    const auto n = static_cast<std::size_t>(state.range(0));
    Points<double> p(n);
    zeroset::Evaluator<T> eval(tape);
    for (auto _ : state) {
        for (std::size_t i = 0; i < n; ++i) benchmark::DoNotOptimize(eval(T(p.x[i]), T(p.y[i]), T(p.z[i])));
    }
    set_rate(state, tape.clauses().size(), n);
}
BENCHMARK(BM_PointEvaluator_Bear<double>)->Arg(256);
BENCHMARK(BM_PointEvaluator_Bear<zeroset::Interval>)->Arg(256);

/// Interval and gradient enclosures over boxes of side 0.05, as an octree
/// cell or a segment's box sees them (point intervals skip the sign cases).
template <class T>
void BM_BoxEvaluator_Bear(benchmark::State& state) {
    using zeroset::Interval;
    const Tape& tape = bear_tape();
    const auto n = static_cast<std::size_t>(state.range(0));
    Points<double> p(n);
    zeroset::Evaluator<T> eval(tape);
    const auto box = [](double v) { return Interval(v, v + 0.05); };
    for (auto _ : state) {
        for (std::size_t i = 0; i < n; ++i) {
            if constexpr (std::is_same_v<T, Interval>)
                benchmark::DoNotOptimize(eval(box(p.x[i]), box(p.y[i]), box(p.z[i])));
            else
                benchmark::DoNotOptimize(eval(T::variable(box(p.x[i]), 0), T::variable(box(p.y[i]), 1), T::variable(box(p.z[i]), 2)));
        }
    }
    set_rate(state, tape.clauses().size(), n);
}
BENCHMARK(BM_BoxEvaluator_Bear<zeroset::Interval>)->Arg(256);

/// The four quarters of a square tile of side 2^-range(0) of prospero's ±1
/// square, at a place its outline crosses, and the tape to evaluate them
/// with: the full one for the root (range 0), else the one pruned to the tile.
struct ProsperoTile {
    Tape tape;
    std::array<zeroset::Box3, zeroset::TapePruner::lanes> quarters;

    explicit ProsperoTile(int level) {
        static const Tape full = model_tape("prospero.vm");
        const double side = std::ldexp(2.0, -level), x0 = -0.11, y0 = 0.23;  // on the outline
        const zeroset::Box3 tile{{x0, y0, 0.0}, {x0 + side, y0 + side, 0.0}};
        zeroset::TapePruner pruner(full);
        if (level == 0) tape = full;
        else pruner.prune(full, tile, tape);
        for (int k = 0; k < 4; ++k) {
            const double qx = x0 + (k % 2) * side / 2, qy = y0 + (k / 2) * side / 2;
            quarters[static_cast<std::size_t>(k)] = {{qx, qy, 0.0}, {qx + side / 2, qy + side / 2, 0.0}};
        }
    }
};

/// The pruner's interval walk over the four quarters: four one-box walks,
/// or one walk of four lanes (range(1) = 1).
void BM_PrunerEvaluate_Prospero(benchmark::State& state) {
    const ProsperoTile tile(static_cast<int>(state.range(0)));
    zeroset::TapePruner pruner(tile.tape);
    for (auto _ : state) {
        if (state.range(1) == 1) {
            benchmark::DoNotOptimize(pruner.evaluate(tile.tape, tile.quarters));
        } else {
            for (const zeroset::Box3& box : tile.quarters) benchmark::DoNotOptimize(pruner.evaluate(tile.tape, box));
        }
    }
    state.counters["clauses"] = static_cast<double>(tile.tape.clauses().size());
    state.counters["tile_clauses/s"] = benchmark::Counter(static_cast<double>(4 * tile.tape.clauses().size()),
                                                          benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PrunerEvaluate_Prospero)->ArgsProduct({{0, 3, 6}, {0, 1}});

/// The pruned tapes of the four quarters, after one walk of four lanes.
void BM_PrunerSimplify_Prospero(benchmark::State& state) {
    const ProsperoTile tile(static_cast<int>(state.range(0)));
    zeroset::TapePruner pruner(tile.tape);
    (void)pruner.evaluate(tile.tape, tile.quarters);
    std::array<Tape, 4> pruned;
    std::size_t kept = 0;
    for (auto _ : state) {
        kept = 0;
        for (int k = 0; k < 4; ++k) kept += pruner.simplified(pruned[static_cast<std::size_t>(k)], k).clauses().size();
        benchmark::DoNotOptimize(pruned.data());
    }
    state.counters["clauses"] = static_cast<double>(tile.tape.clauses().size());
    state.counters["kept"] = static_cast<double>(kept) / 4.0;
    state.counters["source_clauses/s"] = benchmark::Counter(static_cast<double>(4 * tile.tape.clauses().size()),
                                                            benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PrunerSimplify_Prospero)->DenseRange(0, 6, 3);
BENCHMARK(BM_BoxEvaluator_Bear<zeroset::Dual<zeroset::Interval>>)->Arg(256);

/// The ceiling (bench/fma_ceiling.hpp): for each clause of the tape, one
/// multiply-add over a batch of lanes held in cache — what the batch
/// evaluator would reach with zero dispatch cost and the cheapest op everywhere.
template <class F>
void BM_StraightLineFma(benchmark::State& state) {
    constexpr std::size_t lanes = zeroset::BatchEvaluator<F>::lanes;
    const std::size_t clauses = bear_tape().clauses().size();
    const auto n = static_cast<std::size_t>(state.range(0));
    std::vector<F> slots(8 * lanes);
    for (std::size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<F>(0.5 + 1e-3 * static_cast<double>(i % 97));
    for (auto _ : state) {
        for (std::size_t batch = 0; batch < n; batch += lanes) {
            zeroset::bench::straight_line_fma(slots.data(), clauses);
            benchmark::ClobberMemory();
        }
        benchmark::DoNotOptimize(slots.data());
    }
    set_rate(state, clauses, n);
    state.SetLabel(zeroset::batch_simd_target());
}
BENCHMARK(BM_StraightLineFma<float>)->Arg(4096);
BENCHMARK(BM_StraightLineFma<double>)->Arg(4096);

}  // namespace

BENCHMARK_MAIN();
