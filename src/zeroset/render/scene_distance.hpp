// SceneDistance: a lower bound of the distance from a point to the scene's
// solids, for cone tracing (render/cone_tracer.hpp). It is sphere tracing's
// unbounding sphere (survey §5.2, eq. 30) taken from one surface to the
// whole scene tree:
//   - a leaf gives f(c)/G, where c is the point of its (convex) bounds
//     nearest p and G bounds |∇f| (interval gradient, as expr/lipschitz.hpp)
//     over the part in the bounds of the box around a ball of radius
//     `reach` around p: the way from c to the nearest surface stays in the
//     bounds and the ball, so no surface lies nearer than the hypotenuse
//     of p's distance to the bounds and f(c)/G, nor beyond reach;
//   - CSG combines the bounds of the distance to each solid and to its
//     complement: a union takes the smallest, an intersection the largest,
//     a difference A − B the largest of A's and B's complement's;
//   - a transform turns a length in the object's space into one in the
//     scene's by dividing by how much its inverse may stretch.
// The leaf that gives the bound is returned with it, and the direction
// from p towards its surface, which is where a cone trace aims its ray.
//
// The estimate is shared by the render threads read-only; each thread
// owns a DistanceProbe with its evaluators.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/tape.hpp"
#include "zeroset/math/box3.hpp"
#include "zeroset/math/mat4.hpp"
#include "zeroset/scene/scene.hpp"

namespace zeroset {

class SceneDistance {
public:
    /// The largest function (in tape clauses) an object may have: each
    /// bound walks it whole, a point and an interval gradient, at every step.
    static constexpr std::size_t max_clauses = 4096;
    /// A blob's field has several clauses a component: past this many, it
    /// is refused before its field is built.
    static constexpr std::size_t max_blob_components = 512;

    /// Throws RenderError for an object past max_clauses or max_blob_components.
    explicit SceneDistance(const Scene& scene);

    /// A box holding every bounded object, in the scene's space: cone
    /// tracing marches only inside it (unbounded ones, such as planes,
    /// count where it reaches).
    [[nodiscard]] const Box3& reach() const { return reach_; }
    /// A box holding each top-level node's solid, in the scene's space
    /// (infinite where it is unbounded), in the order of the scene's nodes.
    [[nodiscard]] const std::vector<Box3>& root_boxes() const { return root_boxes_; }

private:
    friend class DistanceProbe;

    /// A node of the scene's tree, flattened, with its placement.
    struct Node {
        SceneNode::Kind kind;
        Mat4 to_local;          // the scene's space → the node's own
        Mat4 to_scene;          // and back
        double stretch;         // a bound of how much to_local stretches a length
        Bounds bounds;          // a leaf's bounds, in its own space
        int tape = -1;          // a leaf's tape, in tapes_
        std::vector<int> children;
    };

    /// The object's tape, or a RenderError naming it when it is too large.
    static std::unique_ptr<Tape> bounded_tape(const SceneNode& node);
    /// Appends the node and those below it; returns its index.
    int add(const SceneNode& node, const Mat4& to_scene, std::unordered_map<const SceneNode*, int>& tape_of);
    /// A box holding the node's solid, in the scene's space.
    [[nodiscard]] Box3 box_of(int node) const;

    std::vector<Node> nodes_;
    std::vector<int> roots_;
    std::vector<Box3> root_boxes_;
    std::vector<int> all_roots_;  // 0, 1, … : every top-level node
    std::vector<std::unique_ptr<Tape>> tapes_;  // one for each distinct object
    Box3 reach_;
};

/// What the distance bound says at a point.
struct DistanceBound {
    double distance = 0.0;  // no solid is nearer than this (in the scene's units)
    int leaf = -1;          // the node whose surface gives it; -1 when none is within reach
    bool complement = false;  // the bound is to the outside of that leaf's solid (p is inside it)
    bool by_bounds = false;   // the leaf's bounds give it, not its function
};

class DistanceProbe {
public:
    explicit DistanceProbe(const SceneDistance& scene);

    /// A lower bound of the distance from p to the scene's solids — and
    /// `reach` when none is within reach; 0 inside one.
    DistanceBound outside_at(const Vec3d& p, double reach);
    /// The same over some of the top-level nodes only (indices into the
    /// scene's nodes): those whose boxes may hold what is near p.
    DistanceBound outside_at(const Vec3d& p, double reach, std::span<const int> roots);
    /// A lower bound of the distance from p to the space outside every
    /// solid (capped at `reach`); 0 outside them all.
    DistanceBound inside_at(const Vec3d& p, double reach);
    DistanceBound inside_at(const Vec3d& p, double reach, std::span<const int> roots);
    /// Whether the box (in the scene's space) holds no point of the solids
    /// of those top-level nodes, by interval analysis: false when unsure.
    bool holds_no_solid(const Box3& box, std::span<const int> roots);
    /// The unit direction, in the scene's space, in which the bound's leaf
    /// surface is nearest to first order: down its gradient, or up it for a
    /// complement — or towards the nearest point or face of its bounds, when
    /// they give the bound; zero where the gradient vanishes.
    Vec3d toward_surface(const Vec3d& p, const DistanceBound& bound);

    /// Evaluations of f and of its gradient enclosure so far.
    [[nodiscard]] std::uint64_t evaluations() const { return evaluations_; }

private:
    /// The bounds of the distance to the node's solid (`outside`) and to
    /// its complement (`inside`).
    struct Pair {
        DistanceBound outside, inside;
    };
    /// Both, within reach; `only_outside` when the caller needs only the
    /// first, which lets unions look no further than their nearest child.
    Pair node_at(int node, const Vec3d& p, double reach, bool only_outside);
    /// holds_no_solid for one node and a box in the scene's space.
    bool node_holds_none(int node, const Box3& box);
    Pair leaf_at(int node, const Vec3d& p, double reach);

    const SceneDistance* scene_;
    std::vector<Evaluator<double>> values_;
    std::vector<Evaluator<Interval>> enclosures_;
    std::vector<Evaluator<Dual<Interval>>> slopes_;
    std::vector<Evaluator<Dual<double>>> gradients_;
    std::uint64_t evaluations_ = 0;
};

}  // namespace zeroset
