// Tape pruning: inside the box the pruned tape computes exactly what the full
// tape computes, with fewer clauses wherever a min/max side wins outright.
#include <gtest/gtest.h>
#include "support/models.hpp"

#include <array>
#include <bit>
#include <fstream>
#include <random>
#include <string>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/tape_pruner.hpp"
#include "zeroset/expr/vm_import.hpp"

namespace zeroset {
namespace {

Expr ball(double cx, double r) {
    return sqrt(square(var_x() - cx) + square(var_y()) + square(var_z())) - r;
}

/// Checks that `pruned` agrees bit for bit with `full` at random points in the box.
void expect_same_inside(const Tape& full, const Tape& pruned, const Box3& box, int samples = 200) {
    Evaluator<double> f(full), g(full);
    g.rebind(pruned);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < samples; ++i) {
        const Vec3d p{box.lo.x + u(rng) * (box.hi.x - box.lo.x), box.lo.y + u(rng) * (box.hi.y - box.lo.y),
                      box.lo.z + u(rng) * (box.hi.z - box.lo.z)};
        ASSERT_EQ(f(p.x, p.y, p.z), g(p.x, p.y, p.z)) << p.x << " " << p.y << " " << p.z;
    }
}

TEST(TapePruner, UnionOfDistantBallsKeepsOnlyTheNearOne) {
    const Tape full(min(ball(-5, 1), ball(5, 1)));
    TapePruner pruner(full);
    Tape pruned;
    const Box3 near_left{{-6, -1, -1}, {-4, 1, 1}};
    const Interval value = pruner.prune(full, near_left, pruned);
    EXPECT_LE(value.lo, 0.0);
    // Each ball is 4 clauses (x − c, two hypots, − r), plus the min: 9 → 4.
    EXPECT_EQ(full.clauses().size(), 9u);
    EXPECT_EQ(pruned.clauses().size(), 4u);
    for (const Clause& c : pruned.clauses()) EXPECT_NE(c.op, Op::Min);
    // Renumbered: x, y, z, the live constants (-5 and 1), and reused working slots.
    EXPECT_EQ(pruned.constants().size(), 2u);
    EXPECT_LT(pruned.slot_count(), full.slot_count());
    expect_same_inside(full, pruned, near_left);
}

TEST(TapePruner, ATapeCanPruneToAVariableOrAConstant) {
    const Tape full(max(min(var_x(), var_y() + 10.0), Expr(-3.0)));
    TapePruner pruner(full);
    Tape pruned;
    const Box3 box{{0, 0, 0}, {1, 1, 1}};  // x < y + 10, and x > -3
    pruner.prune(full, box, pruned);
    EXPECT_TRUE(pruned.clauses().empty());
    EXPECT_EQ(pruned.result_slot(), Tape::slot_x);
    expect_same_inside(full, pruned, box);
    const Box3 far{{-9, 0, 0}, {-8, 1, 1}};  // x < -3 everywhere
    pruner.prune(full, far, pruned);
    EXPECT_TRUE(pruned.clauses().empty());
    Evaluator<double> f(full);
    f.rebind(pruned);
    EXPECT_EQ(f(-8.5, 0.5, 0.5), -3.0);
}

TEST(TapePruner, AValueUsedAfterItsMinIsResolvedKeepsItsSlot) {
    // a = x², m = min(a, 100) resolves to a over the box, and a is used again
    // after m: the slot of a must survive until the last use of either.
    const Expr a = square(var_x());
    const Expr m = min(a, Expr(100.0));
    const Tape full(m * var_y() + a * var_z() + m);
    TapePruner pruner(full);
    Tape pruned;
    const Box3 box{{-2, -1, -1}, {2, 1, 1}};
    pruner.prune(full, box, pruned);
    EXPECT_LT(pruned.clauses().size(), full.clauses().size());
    expect_same_inside(full, pruned, box);
}

TEST(TapePruner, AmbiguousBoxKeepsBothSides) {
    const Tape full(min(ball(-1, 1), ball(1, 1)));
    TapePruner pruner(full);
    Tape pruned;
    const Box3 middle{{-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}};
    pruner.prune(full, middle, pruned);
    EXPECT_EQ(pruned.clauses().size(), full.clauses().size());
    expect_same_inside(full, pruned, middle);
}

TEST(TapePruner, PruningAPrunedTapeNarrowsFurther) {
    const Expr three = min(min(ball(-4, 1), ball(0, 1)), ball(4, 1));
    const Tape full(three);
    TapePruner pruner(full);
    Tape wide, narrow;
    // Over `wide` the right ball loses to the other two; over `narrow` the
    // middle ball also beats the left one.
    const Box3 wide_box{{-2.5, -0.3, -0.3}, {0.5, 0.3, 0.3}};
    const Box3 narrow_box{{-0.5, -0.3, -0.3}, {0.5, 0.3, 0.3}};
    pruner.prune(full, wide_box, wide);
    pruner.prune(wide, narrow_box, narrow);
    EXPECT_LT(wide.clauses().size(), full.clauses().size());
    EXPECT_LT(narrow.clauses().size(), wide.clauses().size());
    expect_same_inside(full, wide, wide_box);
    expect_same_inside(full, narrow, narrow_box);
}

TEST(TapePruner, BearStaysExactAndShrinksInSmallBoxes) {
    ZEROSET_SKIP_WITHOUT_MODEL("bear.vm");

    std::ifstream in(ZEROSET_MODELS_DIR "/bear.vm");
    const Tape full(import_vm(in));
    TapePruner pruner(full);
    Tape pruned;
    std::size_t total = 0;
    int boxes = 0;
    for (double x = -0.6; x < 0.9; x += 0.3) {
        for (double y = -0.5; y < 0.8; y += 0.3) {
            const Box3 box{{x, y, 0.0}, {x + 0.05, y + 0.05, 0.05}};
            pruner.prune(full, box, pruned);
            total += pruned.clauses().size();
            ++boxes;
            expect_same_inside(full, pruned, box, 20);
        }
    }
    // bear is mostly smooth blends (27 of 543 clauses are min/max), so small
    // boxes drop only part of it.
    EXPECT_LT(total / static_cast<std::size_t>(boxes), full.clauses().size() * 9 / 10);
}

TEST(TapePruner, ProsperoShrinksByOrdersOfMagnitudeInSmallBoxes) {
    ZEROSET_SKIP_WITHOUT_MODEL("prospero.vm");

    std::ifstream in(ZEROSET_MODELS_DIR "/prospero.vm");
    const Tape full(import_vm(in));
    TapePruner pruner(full);
    Tape wide, narrow;
    std::size_t most_clauses = 0;
    std::uint32_t most_slots = 0;
    for (double x = -0.9; x < 0.9; x += 0.35) {
        for (double y = -0.9; y < 0.9; y += 0.35) {
            const Box3 box{{x, y, 0.0}, {x + 0.1, y + 0.1, 0.0}};
            const Box3 small{{x, y, 0.0}, {x + 0.02, y + 0.02, 0.0}};
            pruner.prune(full, box, wide);
            pruner.prune(wide, small, narrow);
            most_clauses = std::max(most_clauses, wide.clauses().size());
            most_slots = std::max(most_slots, narrow.slot_count());
            expect_same_inside(full, wide, box, 10);
            expect_same_inside(full, narrow, small, 10);
        }
    }
    EXPECT_LT(most_clauses, full.clauses().size() / 10);
    EXPECT_LT(most_slots, full.slot_count() / 10);
}

/// Two tapes are the same: clauses, constants, slots.
void expect_same_tape(const Tape& a, const Tape& b) {
    ASSERT_EQ(a.clauses().size(), b.clauses().size());
    for (std::size_t i = 0; i < a.clauses().size(); ++i) {
        const Clause &p = a.clauses()[i], &q = b.clauses()[i];
        ASSERT_TRUE(p.op == q.op && p.out == q.out && p.a == q.a && p.b == q.b) << "clause " << i;
    }
    EXPECT_EQ(a.constants(), b.constants());
    EXPECT_EQ(a.slot_count(), b.slot_count());
    EXPECT_EQ(a.result_slot(), b.result_slot());
}

/// The four-lane evaluate() against four one-box ones over random boxes:
/// the same bounds, bit for bit, and the same pruned tapes — walking the
/// full tape, and (odd rounds) a tape pruned to a box around all four, as
/// slicing does; no pruned tape needs more slots than its source.
void expect_lanes_like_single_boxes(const Tape& full, double reach, double largest_side, int rounds) {
    TapePruner lanes(full), single(full);
    std::mt19937 random(17);
    std::uniform_real_distribution<double> place(-reach, reach), side(0.0, largest_side);
    Tape around;
    for (int round = 0; round < rounds; ++round) {
        std::array<Box3, TapePruner::lanes> boxes;
        Box3 all = empty_box();
        for (Box3& box : boxes) {
            const Vec3d lo{place(random), place(random), place(random)};
            box = {lo, lo + Vec3d{side(random), side(random), side(random)}};
            all = united(all, box);
        }
        const Tape* source = &full;
        if (round % 2 == 1) {
            (void)single.prune(full, all, around);
            EXPECT_LE(around.slot_count(), full.slot_count());
            source = &around;
        }
        const IntervalLanes f = lanes.evaluate(*source, boxes);
        for (int k = 0; k < TapePruner::lanes; ++k) {
            const Interval expected = single.evaluate(*source, boxes[static_cast<std::size_t>(k)]);
            const Interval got = f.lane(k);
            ASSERT_TRUE((got.is_empty() && expected.is_empty()) ||
                        (std::bit_cast<std::uint64_t>(got.lo) == std::bit_cast<std::uint64_t>(expected.lo) &&
                         std::bit_cast<std::uint64_t>(got.hi) == std::bit_cast<std::uint64_t>(expected.hi)))
                << "round " << round << " lane " << k << ": [" << got.lo << ", " << got.hi << "] against ["
                << expected.lo << ", " << expected.hi << "]";
            Tape from_lanes, from_single;
            const Tape& a = lanes.simplified(from_lanes, k);
            const Tape& b = single.simplified(from_single);
            expect_same_tape(a, b);
            EXPECT_LE(a.slot_count(), source->slot_count());
            expect_same_inside(full, a, boxes[static_cast<std::size_t>(k)], 4);
        }
    }
}

TEST(TapePruner, FourLanesEvaluateAndPruneAsFourSingleBoxes) {
    // Every op, and min/max whose sides win in some boxes and not in others.
    const Expr x = var_x(), y = var_y(), z = var_z();
    const Expr shape = min(max(ball(-1, 1), -z + 0.25 * sin(3.0 * x)), ball(1.5, 0.75) * exp(-square(y)) / (1.0 + abs(x))) +
                       min(sqrt(square(x) + square(y)), max(hypot(x, z) - 2.0, powi(y, 3) - atan(z)));
    expect_lanes_like_single_boxes(Tape(shape), 3.0, 2.0, 500);
}

TEST(TapePruner, FourLanesMatchSingleBoxesOnTheModels) {
    ZEROSET_SKIP_WITHOUT_MODEL("prospero.vm");
    ZEROSET_SKIP_WITHOUT_MODEL("bear.vm");
    for (const char* name : {"prospero.vm", "bear.vm"}) {
        std::ifstream in(std::string(ZEROSET_MODELS_DIR) + "/" + name);
        expect_lanes_like_single_boxes(Tape(import_vm(in)), 1.0, 0.3, 40);
    }
}

TEST(TapePruner, APrunedTapePrunesAgainAsTheFullTapeDoes) {
    // Its values are followed through its own slots, which reuse the
    // full tape's differently: pruning it again over a smaller box gives
    // the tape that pruning the full tape there gives.
    const Expr x = var_x(), y = var_y(), z = var_z();
    const Tape full(min(min(ball(-5, 1), ball(5, 1)), max(hypot(x, y) - 2.0, z - 3.0)) + 0.5 * z);
    TapePruner pruner(full);
    const Box3 near_left{{-7, -1.5, -1.5}, {-3, 1.5, 1.5}}, nearer{{-6, -1, -1}, {-4, 1, 1}};
    Tape wide, narrow, direct;
    (void)pruner.prune(full, near_left, wide);
    (void)pruner.prune(wide, nearer, narrow);
    (void)pruner.prune(full, nearer, direct);
    expect_same_tape(narrow, direct);
    expect_same_inside(full, narrow, nearer);
    // Pruned to nothing but a constant, it prunes again to that constant.
    const Tape constant_min(min(var_x(), Expr(5.0)));
    TapePruner constant_pruner(constant_min);
    Tape just_five, again;
    (void)constant_pruner.prune(constant_min, Box3{{6, 0, 0}, {7, 1, 1}}, just_five);
    EXPECT_TRUE(just_five.clauses().empty());
    const Interval five = constant_pruner.prune(just_five, Box3{{6.5, 0, 0}, {7, 1, 1}}, again);
    EXPECT_EQ(five.lo, 5.0);
    EXPECT_EQ(five.hi, 5.0);
    EXPECT_TRUE(again.clauses().empty());
    EXPECT_EQ(again.result_slot(), just_five.result_slot());
}

}  // namespace
}  // namespace zeroset
