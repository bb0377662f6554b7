// The octrees of accel/octree.hpp: the Lipschitz octree keeps every surface
// point (sound), the vertex-sign octree loses thin features (the survey's
// "main flaw" of §6.2), and rays walking cells find the same hits as rays
// over the whole bounds.
#include <gtest/gtest.h>
#include "support/models.hpp"

#include <cmath>
#include <fstream>
#include <memory>
#include <random>

#include "zeroset/accel/implicit_leaf.hpp"
#include "zeroset/accel/octree.hpp"
#include "zeroset/accel/trace_scratch.hpp"
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/vm_import.hpp"

namespace zeroset {
namespace {

const Expr x = var_x(), y = var_y(), z = var_z();

Expr bear() {
    std::ifstream in(ZEROSET_MODELS_DIR "/bear.vm");
    return import_vm(in);
}
const Box3 bear_box{{-0.7, -0.65, -0.75}, {1.05, 0.9, 0.7}};

bool in_some_cell(const Octree& octree, const Vec3d& p, double pad) {
    for (const Box3& b : octree.cell_boxes())
        if (Box3{b.lo - Vec3d{pad, pad, pad}, b.hi + Vec3d{pad, pad, pad}}.contains(p)) return true;
    return false;
}

/// Points on the surface: sign changes along random segments, bisected.
std::vector<Vec3d> surface_points(const Tape& tape, const Box3& box, int wanted) {
    Evaluator<double> f(tape);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const auto random_point = [&] {
        return Vec3d{box.lo.x + u(rng) * (box.hi.x - box.lo.x), box.lo.y + u(rng) * (box.hi.y - box.lo.y),
                     box.lo.z + u(rng) * (box.hi.z - box.lo.z)};
    };
    std::vector<Vec3d> points;
    for (int attempt = 0; attempt < 100 * wanted && static_cast<int>(points.size()) < wanted; ++attempt) {
        Vec3d a = random_point(), b = random_point();
        double fa = f(a.x, a.y, a.z);
        if (fa * f(b.x, b.y, b.z) >= 0.0) continue;
        for (int i = 0; i < 60; ++i) {
            const Vec3d m = (a + b) * 0.5;
            const double fm = f(m.x, m.y, m.z);
            if ((fm < 0.0) == (fa < 0.0)) a = m, fa = fm;
            else b = m;
        }
        points.push_back(a);
    }
    return points;
}

TEST(Octree, EverySurfacePointOfTheBearIsInACell) {
    ZEROSET_SKIP_WITHOUT_MODEL("bear.vm");

    const Tape tape(bear());
    OctreeSettings settings;
    settings.max_depth = 4;
    const Octree octree(tape, bear_box, settings);
    const OctreeStats& s = octree.stats();
    EXPECT_GT(s.cells, 100u);
    EXPECT_LT(s.cells, 4096u / 2);  // most of the 16³ cells are discarded
    EXPECT_LE(s.mean_cell_clauses, static_cast<double>(s.full_clauses));
    EXPECT_GT(s.median_lipschitz, 0.0);
    const std::vector<Vec3d> points = surface_points(tape, bear_box, 300);
    ASSERT_EQ(points.size(), 300u);
    for (const Vec3d& p : points) EXPECT_TRUE(in_some_cell(octree, p, 1e-9)) << p.x << " " << p.y << " " << p.z;
    // Each cell's tape agrees with the full tape inside the cell.
    Evaluator<double> full(tape);
    for (std::size_t i = 0; i < octree.cells().size(); i += 37) {
        Evaluator<double> cell(octree.tape_of(octree.cells()[i]));
        const Vec3d c = octree.cell_boxes()[i].center();
        EXPECT_EQ(cell(c.x, c.y, c.z), full(c.x, c.y, c.z));
    }
}

TEST(Octree, CellCapStopsSubdivision) {
    ZEROSET_SKIP_WITHOUT_MODEL("bear.vm");

    const Tape tape(bear());
    OctreeSettings settings;
    settings.max_depth = 6;
    settings.max_cells = 200;
    const Octree octree(tape, bear_box, settings);
    EXPECT_LT(octree.stats().cells, 200u + 8 * 64);  // subtrees in flight may each finish one set of children
    const std::vector<Vec3d> points = surface_points(tape, bear_box, 100);
    for (const Vec3d& p : points) EXPECT_TRUE(in_some_cell(octree, p, 1e-9));
}

// A sheet 0.002 thick at z = 0.3: the corners of 0.125-wide cells sit at
// z = 0.25 and 0.375, all outside it, so Bloomenthal's vertex-sign rule
// sees no surface at all; Kalra and Barr's interval and Lipschitz tests
// keep the cells it passes through.
TEST(Octree, VertexSignMissesAThinSheetTheLipschitzOctreeKeeps) {
    const Tape sheet(abs(z - 0.3) - 0.001);
    const Box3 box{{-1, -1, -1}, {1, 1, 1}};
    OctreeSettings settings;
    settings.max_depth = 4;
    settings.rule = Partition::Lipschitz;
    const Octree lipschitz(sheet, box, settings);
    settings.rule = Partition::VertexSign;
    const Octree vertex_sign(sheet, box, settings);
    EXPECT_EQ(lipschitz.stats().cells, 16u * 16u);  // the one layer of cells around z = 0.3
    EXPECT_EQ(vertex_sign.stats().cells, 0u);

    // And so rendering misses the sheet. A ball beside it keeps the leaf's
    // bounds (shrunk to the surface) from closing around the sheet alone.
    const auto leaf = [&](Partition partition) {
        LeafDescription d;
        d.name = "sheet and ball";
        d.surface = min(abs(z - 0.3) - 0.001, hypot(hypot(x - 0.5, y), z + 0.4) - 0.3);
        d.bounds = Bounds::make_box(box);
        d.method = Method::Interval;
        d.partition = partition;
        d.footprint_pixels = 256;  // depth 4
        return std::make_unique<const ImplicitLeaf>(0, d);
    };
    const auto whole = leaf(Partition::None), kept = leaf(Partition::Lipschitz), lost = leaf(Partition::VertexSign);
    TraceScratch scratch(1);
    int sheet_hits = 0, sheet_hits_kept = 0, sheet_hits_lost = 0;
    for (int i = 0; i < 20; ++i) {
        const Ray ray{{-0.95 + 0.1 * i, 0.05 * i - 0.5, -2.0}, {0.0, 0.0, 1.0}};
        const auto a = whole->first_hit(ray, 0.0, 10.0, scratch);
        const auto b = kept->first_hit(ray, 0.0, 10.0, scratch);
        const auto c = lost->first_hit(ray, 0.0, 10.0, scratch);
        ASSERT_TRUE(a && b);
        EXPECT_NEAR(a->t, b->t, 1e-9);
        const bool on_sheet = std::abs(a->t - 2.299) < 1e-9;
        sheet_hits += on_sheet;
        sheet_hits_kept += std::abs(b->t - 2.299) < 1e-9;
        sheet_hits_lost += c && std::abs(c->t - 2.299) < 1e-9;
    }
    EXPECT_GT(sheet_hits, 10);
    EXPECT_EQ(sheet_hits_kept, sheet_hits);
    EXPECT_EQ(sheet_hits_lost, 0);
}

/// Surface tracking (§6.2) keeps exactly the straddling cells of the finest
/// grid that are connected to its seed: all of them on one sphere, none of
/// a second sphere apart from the first — tracking's own flaw.
TEST(Octree, SeedFillTracksTheSeedsComponentOnly) {
    const Box3 box{{-1, -1, -1}, {1, 1, 1}};
    OctreeSettings settings;
    settings.rule = Partition::SeedFill;
    settings.max_depth = 4;
    const Expr centre = hypot(hypot(x, y), z) - 0.5;
    const Expr corner = hypot(hypot(x - 0.7, y - 0.7), z - 0.7) - 0.2;
    // Brute force: the straddling cells of the 16³ grid.
    const auto straddling = [&](const Expr& f) {
        const Tape tape(f);
        Evaluator<double> e(tape);
        std::size_t count = 0;
        const double h = 2.0 / 16;
        for (int i = 0; i < 16; ++i)
            for (int j = 0; j < 16; ++j)
                for (int k = 0; k < 16; ++k) {
                    bool negative = false, positive = false;
                    for (int c = 0; c < 8; ++c) {
                        const double v = e(-1 + h * (i + (c & 1)), -1 + h * (j + ((c >> 1) & 1)), -1 + h * (k + (c >> 2)));
                        negative |= v <= 0;  // on the surface counts as inside, as in the seed fill
                        positive |= v > 0;
                    }
                    count += negative && positive;
                }
        return count;
    };
    const Tape one(centre);
    const Octree tracked(one, box, settings);
    EXPECT_GT(tracked.stats().cells, 50u);
    EXPECT_EQ(tracked.stats().cells, straddling(centre));

    const Tape two(min(centre, corner));
    const Octree tracked_two(two, box, settings);
    EXPECT_EQ(tracked_two.stats().cells, tracked.stats().cells);  // the corner ball is not reached
    EXPECT_GT(straddling(min(centre, corner)), straddling(centre));
    settings.rule = Partition::Lipschitz;
    const Octree lipschitz(two, box, settings);
    for (const Vec3d& p : {Vec3d{0.9, 0.7, 0.7}, Vec3d{0.5, 0.0, 0.0}})
        EXPECT_TRUE(in_some_cell(lipschitz, p, 0.0)) << p.x;
    EXPECT_FALSE(in_some_cell(tracked_two, {0.9, 0.7, 0.7}, 0.0));
    EXPECT_TRUE(in_some_cell(tracked_two, {0.5, 0.0, 0.0}, 0.0));
}

/// First hits with and without the octree agree on rays through the bear.
TEST(Octree, RaysOverCellsFindTheSameFirstHits) {
    ZEROSET_SKIP_WITHOUT_MODEL("bear.vm");

    for (const Method method : {Method::Interval, Method::Sphere, Method::Lg}) {
        SCOPED_TRACE(method_name(method));
        const auto leaf = [&](Partition partition) {
            LeafDescription d;
            d.name = "bear";
            d.surface = bear();
            d.bounds = Bounds::make_box(bear_box);
            d.method = method;
            d.partition = partition;
            d.footprint_pixels = 128;
            return ImplicitLeaf(0, d);
        };
        const ImplicitLeaf whole = leaf(Partition::None), cells = leaf(Partition::Lipschitz);
        ASSERT_NE(cells.octree(), nullptr);
        TraceScratch scratch_whole(1), scratch_cells(1);
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> u(-0.5, 0.5);
        int hits = 0;
        for (int i = 0; i < 150; ++i) {
            const Ray ray{{-2.6, 0.7 + u(rng), 2.0 + u(rng)}, {2.75 + u(rng), -0.6 + u(rng), -2.05 + u(rng)}};
            const auto a = whole.first_hit(ray, 0.0, 10.0, scratch_whole);
            const auto b = cells.first_hit(ray, 0.0, 10.0, scratch_cells);
            ASSERT_EQ(a.has_value(), b.has_value()) << i;
            if (!a) continue;
            ++hits;
            EXPECT_NEAR(a->t, b->t, 1e-6) << i;
        }
        EXPECT_GT(hits, 50);
        EXPECT_GT(scratch_cells.counters.cell_visits, 0u);
    }
}

}  // namespace
}  // namespace zeroset
