// Scene → scene-language text: statement by statement, the tree depth
// first, each node with its keys, material and transform. A node the tree
// reaches more than once (a shape placed as instances) is written once, as a
// shape, and placed by `instance` wherever it occurs. Expressions name their
// large shared and deep parts as lets (expression_writer.hpp), written
// before the shapes and objects.
#include "zeroset/scene/scene_writer.hpp"

#include <cmath>
#include <functional>
#include <sstream>
#include <unordered_map>

#include "zeroset/scene/expression_writer.hpp"

namespace zeroset {

namespace {

std::string vector(const Vec3d& v) {
    return "(" + number_text(v.x) + ", " + number_text(v.y) + ", " + number_text(v.z) + ")";
}

std::string quoted(const std::string& name) { return name.empty() ? "" : " \"" + name + "\""; }

class Writer {
public:
    explicit Writer(std::ostringstream& out) : out_(out) {}

    /// The lets the expressions written so far need.
    [[nodiscard]] const std::string& lets() const { return expressions_.lets(); }

    void line(const std::string& text) { out_ << std::string(static_cast<std::size_t>(2 * depth_), ' ') << text << "\n"; }

    void open(const std::string& head) {
        line(head + " {");
        ++depth_;
    }
    void close() {
        --depth_;
        line("}");
    }

    void material(const Material& m) {
        const std::string color = m.color_pattern
                                      ? "(" + expressions_.text((*m.color_pattern)[0]) + ", " +
                                            expressions_.text((*m.color_pattern)[1]) + ", " +
                                            expressions_.text((*m.color_pattern)[2]) + ")"
                                      : vector(m.color);
        line("material { color " + color + "  ambient " + number_text(m.ambient) + "  diffuse " +
             number_text(m.diffuse) + "  specular " + number_text(m.specular) + "  shininess " +
             number_text(m.shininess) + "  reflection " + number_text(m.reflection) + " }");
    }

    void transform(const Mat4& t) {
        if (t.is_identity()) return;
        std::string text = "matrix (";
        for (std::size_t r = 0; r < 3; ++r)
            for (std::size_t c = 0; c < 4; ++c) text += number_text(t.m[r][c]) + (r == 2 && c == 3 ? ")" : ", ");
        line(text);
    }

    /// `key` (bounds or gate) and the shape.
    void bounds(const Bounds& b, const std::string& key = "bounds") {
        switch (b.kind) {
            case Bounds::Kind::None: line(key + " none"); break;
            case Bounds::Kind::Box: line(key + " box(" + vector(b.box.lo) + ", " + vector(b.box.hi) + ")"); break;
            case Bounds::Kind::Sphere:
                line(key + " sphere(" + vector(b.center) + ", " + number_text(b.radius) + ")");
                break;
        }
    }

    void modifiers(const SceneNode& node) {
        if (node.material) material(*node.material);
        transform(node.transform);
    }

    /// Counts how often the tree reaches each node, and names the shared
    /// ones as shapes, written here children first.
    void shapes(const std::vector<SceneNodePtr>& top) {
        std::vector<const SceneNode*> order;  // shared nodes, children before parents
        const std::function<void(const SceneNode&)> visit = [&](const SceneNode& n) {
            if (++uses_[&n] > 1) return;
            for (const SceneNodePtr& c : n.children) visit(*c);
            order.push_back(&n);
        };
        for (const SceneNodePtr& n : top) visit(*n);
        for (const SceneNode* n : order) {
            if (uses_[n] < 2) continue;
            const std::string name = "shape_" + std::to_string(shape_names_.size() + 1);
            open("shape " + name);
            if (n->kind == SceneNode::Kind::Group) {  // its body is the group's contents
                for (const SceneNodePtr& c : n->children) node(*c);
                modifiers(*n);
            } else {
                node(*n);
            }
            close();
            out_ << "\n";
            shape_names_[n] = name;
        }
    }

    void node(const SceneNode& n) {
        // An instance: a group around one shared node, or the shared node itself.
        if (n.kind == SceneNode::Kind::Group && n.children.size() == 1)
            if (const auto s = shape_names_.find(n.children.front().get()); s != shape_names_.end()) {
                if (!n.material && n.transform.is_identity()) return line("instance " + s->second);
                open("instance " + s->second);
                modifiers(n);
                return close();
            }
        if (const auto s = shape_names_.find(&n); s != shape_names_.end()) return line("instance " + s->second);
        switch (n.kind) {
            case SceneNode::Kind::Object: object(n); return;
            case SceneNode::Kind::Group: open("group" + quoted(n.name)); break;
            case SceneNode::Kind::Intersection: open("intersection" + quoted(n.name)); break;
            case SceneNode::Kind::Difference: open("difference" + quoted(n.name)); break;
        }
        for (const SceneNodePtr& child : n.children) node(*child);
        modifiers(n);
        close();
    }

    void object(const SceneNode& n) {
        const Object& o = n.object;
        if (o.blob) return blob(n);
        if (o.sweep) return sweep(n);
        if (o.fractal) return fractal(n);
        open("object" + quoted(n.name));
        line("surface " + expressions_.text(o.surface));
        bounds(o.bounds);
        if (o.method != Method::Auto) line("method " + std::string(method_name(o.method)));
        if (o.solver != PolynomialSolver::Fast) line("solver " + std::string(polynomial_solver_name(o.solver)));
        if (o.normals != NormalMode::Analytic) line("normals " + std::string(normal_mode_name(o.normals)));
        if (o.partition != Partition::Auto) line("partition " + std::string(partition_name(o.partition)));
        if (o.cut_by_bounds) line("cut on");
        if (o.open) line("open on");
        if (o.clip) line("clip " + expressions_.text(*o.clip));
        if (o.gate) bounds(*o.gate, "gate");
        modifiers(n);
        close();
    }

    void blob(const SceneNode& n) {
        const Object& o = n.object;
        const BlobModel& m = *o.blob;
        open("blob" + quoted(n.name));
        line("kernel " + std::string(blob_kernel_info(m.kernel()).name) + "  threshold " + number_text(m.threshold()));
        if (o.blob_tolerance != default_blinn_tolerance) line("tolerance " + number_text(o.blob_tolerance));
        if (o.blob_quadratics) line("quadratics on");
        if (o.method != Method::Auto) line("method " + std::string(method_name(o.method)));
        for (const BlobComponent& c : m.components()) {
            std::string text = "component { ";
            if (c.end) text += "from " + vector(c.center) + "  to " + vector(*c.end);
            else text += "center " + vector(c.center);
            text += "  radius " + number_text(c.radius) + "  strength " + number_text(c.strength);
            if (m.kernel() == BlobKernel::Blinn) text += "  blobbiness " + number_text(c.blobbiness);
            if (!c.end && !c.shape.is_identity()) {
                text += "  matrix (";
                for (std::size_t r = 0; r < 3; ++r)
                    for (std::size_t k = 0; k < 4; ++k) text += number_text(k == 3 ? 0.0 : c.shape.m[r][k]) + (r == 2 && k == 3 ? ")" : ", ");
            }
            line(text + " }");
        }
        modifiers(n);
        close();
    }

    void sweep(const SceneNode& n) {
        // One sweep statement per piece (a sweep's pieces may mix degrees);
        // a linear piece as `linear`, the others as cubic Béziers.
        const bool several = n.object.sweep->size() > 1;
        if (several) open("group" + quoted(n.name));
        for (const SweptSegment& s : *n.object.sweep) {
            open("sweep" + (several ? std::string() : quoted(n.name)));
            std::array<Vec3d, 4> b = s.control();
            if (s.degree() == 2) b = {b[0], b[0] + 2.0 / 3.0 * (b[1] - b[0]), b[2] + 2.0 / 3.0 * (b[1] - b[2]), b[2]};
            if (s.degree() == 1) {
                line("curve linear");
                line("point " + vector(b[0]) + " radius " + number_text(s.radius_from()));
                line("point " + vector(b[1]) + " radius " + number_text(s.radius_to()));
            } else {
                line("curve bezier  radius " + number_text(s.radius_from()));  // the control points' (not used)
                line("point " + vector(b[0]) + " radius " + number_text(s.radius_from()));
                line("point " + vector(b[1]));
                line("point " + vector(b[2]));
                line("point " + vector(b[3]) + " radius " + number_text(s.radius_to()));
            }
            if (!several) modifiers(n);
            close();
        }
        if (several) {
            modifiers(n);
            close();
        }
    }

    void fractal(const SceneNode& n) {
        const FractalParameters& p = n.object.fractal->parameters();
        open("fractal" + quoted(n.name));
        line("kind " + std::string(fractal_kind_info(p.kind).name) + "  iterations " + std::to_string(p.iterations) +
             "  detail " + number_text(n.object.fractal_detail));
        if (p.kind == FractalKind::QuaternionJulia)
            line("c " + vector({p.c.r, p.c.i, p.c.j}) + "  ck " + number_text(p.c.k) + "  slice " +
                 number_text(p.slice));
        else
            line("power " + number_text(p.power));
        modifiers(n);
        close();
    }

private:
    std::ostringstream& out_;
    ExpressionWriter expressions_;
    int depth_ = 0;
    std::unordered_map<const SceneNode*, int> uses_;
    std::unordered_map<const SceneNode*, std::string> shape_names_;
};

}  // namespace

std::string write_scene(const Scene& scene, const std::string& header) {
    std::ostringstream out;
    std::istringstream lines(header);
    for (std::string l; std::getline(lines, l);) out << "# " << l << "\n";
    for (const std::string& w : scene.warnings) out << "# warning: " << w << "\n";
    if (!header.empty() || !scene.warnings.empty()) out << "\n";
    Writer w(out);
    const ImageSettings& i = scene.image;
    w.line("image { width " + std::to_string(i.width) + "  height " + std::to_string(i.height) + "  spp " +
           std::to_string(i.samples_per_pixel) + (i.cone_antialiasing ? "  antialias cone" : "") + "  reflection_depth " +
           std::to_string(i.reflection_depth) + " }");
    const Camera& c = scene.camera;
    w.line("camera { from " + vector(c.from) + "  at " + vector(c.at) + "  up " + vector(c.up) + "  fov " +
           number_text(c.fov_degrees) + (c.shift_right != 0.0 ? "  shift_right " + number_text(c.shift_right) : "") +
           (c.shift_up != 0.0 ? "  shift_up " + number_text(c.shift_up) : "") + " }");
    for (const Light& l : scene.lights)
        w.line("light { " + (l.kind == Light::Kind::Point ? "from " + vector(l.position) : "direction " + vector(l.direction)) +
               "  color " + vector(l.color) + "  shadows " + (l.casts_shadows ? "on" : "off") + " }");
    w.line("background " + vector(scene.background));
    w.line("ambient " + vector(scene.ambient));
    out << "\n";
    // The shapes and objects, after the lets their expressions need.
    std::ostringstream body;
    Writer b(body);
    b.shapes(scene.nodes);
    for (const SceneNodePtr& n : scene.nodes) {
        body << "\n";
        b.node(*n);
    }
    if (!b.lets().empty()) out << b.lets();
    out << body.str();
    return out.str();
}

}  // namespace zeroset
