// Roth's span arithmetic (accel/span_ops.hpp) against sets of sample points:
// a t is inside a ∪ b, a ∩ b or a − b exactly when it is inside the result.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "zeroset/accel/span_ops.hpp"

namespace zeroset {
namespace {

Hit at(double t, int tag) {
    Hit h{t, {}};
    h.surface.material = tag;  // which input a boundary came from
    return h;
}

/// Sorted, disjoint random spans in [0, 10], boundaries tagged.
SpanList random_spans(std::mt19937& random, int tag) {
    std::uniform_real_distribution<double> gap(0.0, 1.5);
    SpanList spans;
    double t = gap(random);
    while (true) {
        const double enter = t, exit = t + gap(random);
        if (exit > 10.0) break;
        spans.push_back({at(enter, tag), at(exit, tag)});
        t = exit + gap(random) + 1e-3;
    }
    return spans;
}

bool inside(const SpanList& spans, double t) {
    for (const InsideSpan& s : spans)
        if (s.enter.t <= t && t <= s.exit.t) return true;
    return false;
}

void expect_sorted_and_disjoint(const SpanList& spans) {
    for (std::size_t i = 0; i < spans.size(); ++i) {
        EXPECT_LE(spans[i].enter.t, spans[i].exit.t);
        if (i > 0) {
            EXPECT_LT(spans[i - 1].exit.t, spans[i].enter.t);
        }
    }
}

TEST(SpanOps, AgreeWithPointwiseSetOperations) {
    std::mt19937 random(3);
    for (int trial = 0; trial < 200; ++trial) {
        const SpanList a = random_spans(random, 1), b = random_spans(random, 2);
        SpanList u = a, i, d;
        u.insert(u.end(), b.begin(), b.end());
        merge_overlapping(u);
        intersect(a, b, i);
        subtract(a, b, d);
        expect_sorted_and_disjoint(u);
        expect_sorted_and_disjoint(i);
        expect_sorted_and_disjoint(d);
        for (int k = 0; k <= 2000; ++k) {
            const double t = 0.005 * k + 1e-7;  // off the boundaries
            EXPECT_EQ(inside(u, t), inside(a, t) || inside(b, t)) << t;
            EXPECT_EQ(inside(i, t), inside(a, t) && inside(b, t)) << t;
            EXPECT_EQ(inside(d, t), inside(a, t) && !inside(b, t)) << t;
        }
    }
}

TEST(SpanOps, ADifferenceFlipsTheSubtractedBoundaries) {
    const SpanList a{{at(0, 1), at(10, 1)}}, b{{at(2, 2), at(3, 2)}};
    SpanList d;
    subtract(a, b, d);
    ASSERT_EQ(d.size(), 2u);
    EXPECT_EQ(d[0].exit.t, 2.0);
    EXPECT_EQ(d[0].exit.surface.material, 2);  // the hole's wall is b's surface …
    EXPECT_TRUE(d[0].exit.surface.flipped);    // … seen from outside b
    EXPECT_EQ(d[1].enter.t, 3.0);
    EXPECT_TRUE(d[1].enter.surface.flipped);
    EXPECT_FALSE(d[0].enter.surface.flipped);
}

TEST(SpanOps, SpansRunningToInfinityAreKept) {
    // A plane's solid beyond its crossing runs on to t = ∞.
    const SpanList floor{{at(2, 1), at(INFINITY, 0)}}, pit{{at(3, 2), at(4, 2)}};
    SpanList out;
    subtract(floor, pit, out);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[1].enter.t, 4.0);
    EXPECT_EQ(out[1].exit.t, INFINITY);
    intersect(floor, floor, out);
    EXPECT_EQ(out.size(), 1u);
}

TEST(SpanOps, IntersectionAndDifferenceAreRegularised) {
    // Two solids that only touch share no volume; a solid minus itself is empty.
    const SpanList a{{at(0, 1), at(1, 1)}}, b{{at(1, 2), at(2, 2)}};
    SpanList out;
    intersect(a, b, out);
    EXPECT_TRUE(out.empty());
    subtract(a, a, out);
    EXPECT_TRUE(out.empty());
    // A union keeps a tangent touch (a span of length 0).
    out = a;
    out.push_back({at(5, 3), at(5, 3)});
    merge_overlapping(out);
    EXPECT_EQ(out.size(), 2u);
}

TEST(SpanOps, MergeOverlappingKeepsTheOutermostBoundaries) {
    SpanList s{{at(3, 1), at(6, 1)}, {at(0, 2), at(4, 2)}, {at(5, 3), at(9, 3)}, {at(10, 4), at(11, 4)}};
    merge_overlapping(s);
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[0].enter.surface.material, 2);
    EXPECT_EQ(s[0].exit.surface.material, 3);
    EXPECT_EQ(s[0].exit.t, 9.0);
}

}  // namespace
}  // namespace zeroset
