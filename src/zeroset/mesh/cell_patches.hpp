// The patches of surface in one grid cell, from the signs of f at its
// corners — marching cubes' pieces, one vertex each in dual contouring.
//
// A cell's crossing edges (where the corners' signs differ) are joined in
// pairs on each face: the two there are, or, on an ambiguous face (four
// crossings: its inside corners diagonal), the two around each inside
// corner — or, where the face is "flipped", the two around each outside
// corner. A patch is a class of that joining (a cycle of edges around the
// cell). Both cells of a face join its edges alike, so their patches fit.
#pragma once

#include <array>
#include <cstdint>

#include "zeroset/mesh/octree_walk.hpp"

namespace zeroset::cell {

// The 12 edges: edge e runs along axis e / 4, at offsets (e & 1) and
// (e >> 1 & 1) on the next two axes, (axis + 1) % 3 and (axis + 2) % 3.
constexpr int edge_axis(int e) { return e / 4; }
constexpr int edge_low_corner(int e) {
    const int axis = edge_axis(e);
    return ((e & 1) << ((axis + 1) % 3)) | (((e >> 1) & 1) << ((axis + 2) % 3));
}
constexpr int edge_high_corner(int e) { return edge_low_corner(e) | (1 << edge_axis(e)); }
/// Signs: bit c set where corner c is inside (f < 0).
constexpr bool inside(int signs, int corner) { return ((signs >> corner) & 1) != 0; }
constexpr bool crosses(int signs, int e) { return inside(signs, edge_low_corner(e)) != inside(signs, edge_high_corner(e)); }

/// The 6 faces: face 2·axis + side is the one at offset `side` on `axis`.
constexpr bool on_face(int e, int face) {
    return edge_axis(e) != face / 2 && corner_offset(edge_low_corner(e), face / 2) == face % 2;
}
/// The same face seen from the cell beyond it.
constexpr int opposite_face(int face) { return face ^ 1; }

struct Patches {
    std::array<std::int8_t, 12> of_edge{};  // the patch (0 to 3) of each crossing edge; −1 elsewhere
    std::int8_t count = 0;
};

/// The patches for corner signs `signs`, with the faces whose bit is set in
/// `flipped` joined around their outside corners.
constexpr Patches patches_of(int signs, int flipped) {
    std::array<int, 12> parent{};
    for (int e = 0; e < 12; ++e) parent[static_cast<std::size_t>(e)] = e;
    const auto root = [&](int e) {
        while (parent[static_cast<std::size_t>(e)] != e) e = parent[static_cast<std::size_t>(e)];
        return e;
    };
    const auto join = [&](int a, int b) { parent[static_cast<std::size_t>(root(a))] = root(b); };
    for (int face = 0; face < 6; ++face) {
        std::array<int, 4> crossing{};
        int n = 0;
        for (int e = 0; e < 12; ++e)
            if (on_face(e, face) && crosses(signs, e)) crossing[static_cast<std::size_t>(n++)] = e;
        if (n == 2) join(crossing[0], crossing[1]);
        if (n != 4) continue;
        const bool around_inside = ((flipped >> face) & 1) == 0;
        const auto pivot = [&](int e) {  // the edge's inside (or outside) corner
            return inside(signs, edge_low_corner(e)) == around_inside ? edge_low_corner(e) : edge_high_corner(e);
        };
        for (int p = 0; p < 4; ++p)
            for (int q = p + 1; q < 4; ++q)
                if (pivot(crossing[static_cast<std::size_t>(p)]) == pivot(crossing[static_cast<std::size_t>(q)]))
                    join(crossing[static_cast<std::size_t>(p)], crossing[static_cast<std::size_t>(q)]);
    }
    Patches patches;
    std::array<int, 12> patch_of_root{};
    patch_of_root.fill(-1);
    for (int e = 0; e < 12; ++e) {
        patches.of_edge[static_cast<std::size_t>(e)] = -1;
        if (!crosses(signs, e)) continue;
        int& patch = patch_of_root[static_cast<std::size_t>(root(e))];
        if (patch < 0) patch = patches.count++;
        patches.of_edge[static_cast<std::size_t>(e)] = static_cast<std::int8_t>(patch);
    }
    return patches;
}

/// patches_of(signs, 0) for all 256 sign patterns.
inline constexpr std::array<Patches, 256> unflipped = [] {
    std::array<Patches, 256> table{};
    for (int signs = 0; signs < 256; ++signs) table[static_cast<std::size_t>(signs)] = patches_of(signs, 0);
    return table;
}();

inline Patches patches_of_cell(int signs, int flipped) {
    return flipped == 0 ? unflipped[static_cast<std::size_t>(signs)] : patches_of(signs, flipped);
}

/// Whether one patch holds all four crossings of an ambiguous face: the
/// surface goes round the face through the cell. When the cell beyond does
/// the same, the two cells' vertices would be joined by four triangles;
/// flipping the face splits both patches and keeps the mesh manifold.
constexpr bool wraps_round(const Patches& patches, int signs, int face) {
    int patch = -1, n = 0;
    for (int e = 0; e < 12; ++e) {
        if (!on_face(e, face) || !crosses(signs, e)) continue;
        const int p = patches.of_edge[static_cast<std::size_t>(e)];
        if (n++ > 0 && p != patch) return false;
        patch = p;
    }
    return n == 4;
}

}  // namespace zeroset::cell
