// The POV-Ray importer's objects, camera, lights and materials: each object
// kind's surface and solid, POV-Ray's coefficient order and transforms, CSG
// with inverse, clipping, and the finish mapping.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "pov/pov_test_support.hpp"

namespace zeroset::pov::test {
namespace {

const std::string lit = "light_source { <10, 20, -30> color rgb 1 }\n";

TEST(PovObjects, PolynomialsFollowPovRaysTermOrder) {
    // piriform.pov's quartic: 4x⁴ − 4x³ + y² + z² (terms 0, 3, 25, 32 of 35).
    const PovImport q = import(lit + "quartic { <4, 0, 0, -4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,"
                                     " 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0> }");
    const SceneNode& n = first_node(q);
    for (const auto& [x, y, z] : std::vector<std::array<double, 3>>{{0.5, 0.3, -0.2}, {-1, 2, 0.5}, {0.1, 0, 3}})
        EXPECT_DOUBLE_EQ(value_at(n, x, y, z), 4 * std::pow(x, 4) - 4 * std::pow(x, 3) + y * y + z * z);
    EXPECT_TRUE(n.object.open);  // a polynomial is a sheet, as POV-Ray draws it
    // quadric <A, B, C>, <D, E, F>, <G, H, I>, J.
    const SceneNode& quadric = first_node(import(lit + "quadric { <1, 2, 3>, <4, 5, 6>, <7, 8, 9>, 10 }"));
    const double x = 0.3, y = -0.7, z = 1.1;
    EXPECT_NEAR(value_at(quadric, x, y, z),
                x * x + 2 * y * y + 3 * z * z + 4 * x * y + 5 * x * z + 6 * y * z + 7 * x + 8 * y + 9 * z + 10, 1e-12);
    // poly and polynomial give the same surface.
    const SceneNode& poly = first_node(import(lit + "poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -1> }"));
    const SceneNode& polynomial = first_node(import(lit + "polynomial { 2, xyz(2, 0, 0): 1, xyz(0, 2, 0): 1, xyz(0, 0, 2): 1, xyz(0, 0, 0): -1 }"));
    EXPECT_DOUBLE_EQ(value_at(poly, x, y, z), x * x + y * y + z * z - 1);
    EXPECT_DOUBLE_EQ(value_at(polynomial, x, y, z), x * x + y * y + z * z - 1);
    // Commas may be left out between coefficients (hyptorus.pov does).
    EXPECT_DOUBLE_EQ(value_at(first_node(import(lit + "poly { 2, <1, 0, 0, 0 1, 0, 0, 1, 0, -1> }")), x, y, z), x * x + y * y + z * z - 1);
}

// Polynomials are written in a sparse Horner form (pov_solids.cpp): the
// same polynomial, with fewer products than the sum of its terms — which
// makes its ray polynomial cheaper to form.
TEST(PovObjects, PolynomialsAreTheirTermsWithFewerProducts) {
    std::mt19937 random(3);
    std::uniform_real_distribution<double> coefficient(-3.0, 3.0), point(-1.5, 1.5);
    for (int order = 2; order <= 6; ++order) {
        const std::size_t count = static_cast<std::size_t>((order + 1) * (order + 2) * (order + 3) / 6);
        for (int trial = 0; trial < 5; ++trial) {
            std::vector<double> c(count);
            std::string text = lit + "poly { " + std::to_string(order) + ", <";
            for (std::size_t k = 0; k < count; ++k) {
                c[k] = random() % 3 == 0 ? std::round(coefficient(random) * 8.0) / 8.0 : 0.0;  // sparse, as POV-Ray's are
                text += (k ? ", " : "") + std::to_string(c[k]);
            }
            const SceneNode& n = first_node(import(text + "> }"));
            for (int p = 0; p < 10; ++p) {
                const double x = point(random), y = point(random), z = point(random);
                // Term by term in POV-Ray's order, and a bound on either sum's rounding.
                double sum = 0.0, magnitude = 0.0;
                std::size_t k = 0;
                for (int i = order; i >= 0; --i)
                    for (int j = order - i; j >= 0; --j)
                        for (int l = order - i - j; l >= 0; --l, ++k) {
                            const double term = c[k] * std::pow(x, i) * std::pow(y, j) * std::pow(z, l);
                            sum += term;
                            magnitude += std::abs(term);
                        }
                EXPECT_NEAR(value_at(n, x, y, z), sum, 1e-13 * magnitude) << "order " << order << ", trial " << trial;
            }
        }
    }
    // torus.pov's quartic: ten terms, six products of two squares when summed
    // term by term; three in the Horner form.
    const SceneNode& torus = first_node(import(lit + "quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -104, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,"
                                                     " 1, 0, 0, 2, 0, 56, 0, 0, 0, 0, 1, 0, -104, 0, 784> }"));
    const Tape tape(torus.object.surface);
    const auto products = std::count_if(tape.clauses().begin(), tape.clauses().end(), [](const Clause& c) {
        return c.op == Op::Mul || c.op == Op::Powi;
    });
    EXPECT_LE(products, 7) << torus.object.surface.to_string();
    EXPECT_NEAR(value_at(torus, std::sqrt(40.0) + std::sqrt(12.0), 0, 0), 0.0, 1e-9);
}

TEST(PovObjects, SolidsAndTheirTransforms) {
    // A torus lies around y, radii 2 and 0.5: its tube crosses the x axis at 1.5 and 2.5.
    const SceneNode& torus = first_node(import(lit + "torus { 2, 0.5 }"));
    EXPECT_NEAR(value_at(torus, 1.5, 0, 0), 0.0, 1e-12);
    EXPECT_NEAR(value_at(torus, 0, 0, 2.5), 0.0, 1e-12);
    EXPECT_LT(value_at(torus, 2, 0, 0), 0.0);
    EXPECT_GT(value_at(torus, 2, 0.6, 0), 0.0);
    // `inverse` in a transform block inverts the whole block, wherever it is written.
    const SceneNode& inv = first_node(import(lit + "sphere { 0, 1 transform { inverse translate x scale 2 } }"));
    EXPECT_NEAR(length(inv.transform.transform_point({2, 0, 0}) - Vec3d{0, 0, 0}), 0.0, 1e-12);
    // POV-Ray's rotate: about x, then y, then z; translate after.
    const SceneNode& s = first_node(import(lit + "sphere { <1, 0, 0>, 0.5 rotate <0, 0, 90> translate <0, 0, 3> }"));
    EXPECT_NEAR(length(s.transform.transform_point({1, 0, 0}) - Vec3d{0, 1, 3}), 0.0, 1e-12);
    // A box's solid; a plane's half-space below it.
    const SceneNode& b = first_node(import(lit + "box { <1, 2, 3>, <-1, -2, -3> }"));
    EXPECT_LT(value_at(b, 0.9, 1.9, 2.9), 0.0);
    EXPECT_GT(value_at(b, 1.1, 0, 0), 0.0);
    const SceneNode& p = first_node(import(lit + "plane { <0, 2, 0>, 1 }"));
    EXPECT_EQ(p.object.bounds.kind, Bounds::Kind::None);
    EXPECT_DOUBLE_EQ(value_at(p, 5, 1, 7), 0.0);
    // A cylinder along its axis: a quadric in its own frame, capped by its bounds.
    const SceneNode& c = first_node(import(lit + "cylinder { <0, 0, 0>, <0, 2, 0>, 0.5 }"));
    EXPECT_NEAR(length(c.transform.transform_point({0, 0, 2}) - Vec3d{0, 2, 0}), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(value_at(c, 0.5, 0, 1), 0.0);
    EXPECT_TRUE(c.object.cut_by_bounds);
    EXPECT_FALSE(c.object.open);
    EXPECT_TRUE(first_node(import(lit + "cone { 0, 1, y, 0.5 open }")).object.open);
}

TEST(PovObjects, BlobsIsosurfacesAndCsg) {
    const SceneNode& blob = first_node(import(lit + "blob { threshold 0.6 sphere { <1, 0, 0>, 1, 1 scale <2, 1, 1> } "
                                                    "cylinder { 0, y, 0.5, strength 2 } component 1, 0.5, <0, 0, 3> }"));
    ASSERT_TRUE(blob.object.blob);
    const BlobModel& m = *blob.object.blob;
    EXPECT_EQ(m.kernel(), BlobKernel::PovRay);
    EXPECT_DOUBLE_EQ(m.threshold(), 0.6);
    ASSERT_EQ(m.components().size(), 3U);
    EXPECT_EQ(m.components()[0].center, (Vec3d{2, 0, 0}));  // moved about the origin, shaped about its center
    EXPECT_DOUBLE_EQ(m.components()[0].shape.m[0][0], 2.0);
    EXPECT_TRUE(m.components()[1].is_cylinder());
    EXPECT_DOUBLE_EQ(m.components()[1].strength, 2.0);
    // An isosurface: f − threshold in its container; max_gradient is noted as unneeded.
    const PovImport iso = import(lit + "isosurface { function { x*x + y*y + z*z } threshold 1 max_gradient 4 "
                                       "contained_by { sphere { 0, 2 } } open }");
    const SceneNode& i = first_node(iso);
    EXPECT_DOUBLE_EQ(value_at(i, 1, 0, 0), 0.0);
    EXPECT_EQ(i.object.bounds.kind, Bounds::Kind::Sphere);
    EXPECT_TRUE(i.object.open);
    ASSERT_EQ(iso.notes.size(), 1U);
    EXPECT_NE(iso.notes[0].find("scene.pov:2:55: max_gradient is not needed"), std::string::npos) << iso.notes[0];
    // Functions of functions, and functions.inc's closed forms.
    const SceneNode& f = first_node(import(lit + "#declare F = function(a, b) { a * a - b }\n"
                                                 "isosurface { function { F(x, 2) + y*y + z*z + 1 } }"));
    EXPECT_DOUBLE_EQ(value_at(f, 1, 0, 0), 0.0);
    // difference { A B } and intersection { A inverse B } are both A − B.
    for (const char* text : {"difference { sphere { 0, 1 } sphere { x, 1 } }", "intersection { sphere { 0, 1 } sphere { x, 1 inverse } }"}) {
        const SceneNode& d = first_node(import(lit + text));
        EXPECT_EQ(d.kind, SceneNode::Kind::Difference) << text;
        EXPECT_EQ(d.children.size(), 2U);
    }
    EXPECT_EQ(first_node(import(lit + "merge { sphere { 0, 1 } sphere { x, 1 } }")).kind, SceneNode::Kind::Group);
}

TEST(PovObjects, SphereSweepsAreSweeps) {
    const SceneNode linear = first_node(import(lit + "sphere_sweep { linear_spline 3, <0, 0, 0>, 0.5, <1, 0, 0>, 0.2, <1, 1, 0>, 0.2 }"));
    ASSERT_TRUE(linear.object.sweep);
    ASSERT_EQ(linear.object.sweep->size(), 2U);
    EXPECT_DOUBLE_EQ((*linear.object.sweep)[0].radius_from(), 0.5);
    EXPECT_EQ((*linear.object.sweep)[1].control()[1], (Vec3d{1, 1, 0}));
    // cubic_spline is Catmull–Rom through the inner points; its radius goes linearly, with a warning.
    const PovImport cubic = import(lit + "sphere_sweep { cubic_spline 4, <0, 0, 0>, 0.1 <1, 0, 0>, 0.1 <1, 1, 0>, 0.2 <0, 1, 0>, 0.1 tolerance 1e-4 }");
    const auto& pieces = *first_node(cubic).object.sweep;
    ASSERT_EQ(pieces.size(), 1U);
    EXPECT_EQ(pieces[0].control()[0], (Vec3d{1, 0, 0}));
    EXPECT_EQ(pieces[0].control()[3], (Vec3d{1, 1, 0}));
    EXPECT_TRUE(warned(cubic, "radius goes linearly along each piece"));
    EXPECT_EQ(cubic.notes.size(), 1U);  // tolerance: not needed
    EXPECT_EQ(error_of("sphere_sweep { cubic_spline 3, <0, 0, 0>, 0.1 <1, 0, 0>, 0.1 <1, 1, 0>, 0.1 }"),
              "scene.pov:1:1: sphere_sweep: an open spline sweep needs at least 4 points");
}

TEST(PovObjects, BoundedByIsASheetsGate) {
    // POV-Ray's bounded_by on an unbounded polynomial tests each ray: the
    // sheet keeps its ±10⁴ bounds, the bound becomes its gate (in its own
    // space, through the object's transform).
    const SceneNode& sheet = first_node(import(lit + "quadric { <1, 1, 0>, <0, 0, 0>, <0, 0, 0>, -1 "
                                                     "bounded_by { sphere { <0, 0, 1>, 2 } } translate <5, 0, 0> }"));
    ASSERT_TRUE(sheet.object.gate);
    EXPECT_EQ(sheet.object.gate->kind, Bounds::Kind::Sphere);
    EXPECT_EQ(sheet.object.gate->center, (Vec3d{0, 0, 1}));
    EXPECT_EQ(sheet.object.gate->radius, 2.0);
    EXPECT_EQ(sheet.object.bounds.enclosing_box().hi.x, 1e4);
    EXPECT_TRUE(sheet.object.open);
    // A turned box gates by the box around it, and says so.
    const PovImport turned = import(lit + "quadric { <1, 1, 0>, <0, 0, 0>, <0, 0, 0>, -1 "
                                          "bounded_by { box { -1, 1 rotate 30 * z } } }");
    ASSERT_TRUE(first_node(turned).object.gate);
    EXPECT_EQ(first_node(turned).object.gate->kind, Bounds::Kind::Box);
    EXPECT_NEAR(first_node(turned).object.gate->box.hi.x, std::cos(0.5236) + std::sin(0.5236), 1e-3);
    EXPECT_EQ(std::ranges::count_if(turned.scene.warnings,
                                    [](const std::string& w) { return w.find("bounded_by a turned box") != std::string::npos; }),
              1);
    // On a bounded solid it is not needed: a note, no gate.
    const PovImport ball = import(lit + "sphere { 0, 1 bounded_by { box { -2, 2 } } }");
    EXPECT_FALSE(first_node(ball).object.gate);
    EXPECT_EQ(ball.notes.size(), 1U);
}

TEST(PovObjects, ClippingLeavesASurfaceOpen) {
    // clipped_by planes: the sphere is open, drawn where both planes say inside.
    const SceneNode& s = first_node(import(lit + "sphere { 0, 1 clipped_by { plane { x, 0.5 } plane { -x, 0.5 } } }"));
    ASSERT_TRUE(s.object.clip);
    EXPECT_TRUE(s.object.open);
    const Tape clip(*s.object.clip);
    Evaluator<double> g(clip);
    EXPECT_LT(g(0.2, 0.9, 0), 0.0);
    EXPECT_GT(g(0.7, 0, 0), 0.0);
    EXPECT_GT(g(-0.7, 0, 0), 0.0);
    // A clear sphere in an intersection clips the other member: folium.pov's idiom.
    const PovImport folium = import(lit + "intersection { quartic { <0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, -3, 0, 0, 0, 0, -3, 0, 0, "
                                          "0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0> pigment { color rgb <1, 0, 0> } } "
                                          "sphere { 0, 10 pigment { color rgbf <1, 1, 1, 1> } } }");
    const SceneNode& q = first_node(folium);
    EXPECT_EQ(q.kind, SceneNode::Kind::Object);
    EXPECT_TRUE(q.object.open);
    EXPECT_EQ(q.object.bounds.kind, Bounds::Kind::Sphere);
    EXPECT_DOUBLE_EQ(q.object.bounds.radius, 10.0);
    EXPECT_FALSE(warned(folium, "transparency"));
    // A partly clear object is drawn opaque, with a warning.
    EXPECT_TRUE(warned(import(lit + "sphere { 0, 1 pigment { color rgbt <1, 0, 0, 0.5> } }"),
                       "scene.pov:2:1: transparency (filter, transmit) is not supported; rendered opaque"));
}

TEST(PovScene, CameraLightsAndSettings) {
    const PovImport s = import("camera { location <0, 2, -5> look_at <0, 0, 0> right x*image_width/image_height angle 60 }\n"
                               "light_source { <1, 2, 3> color rgb <1, 0.5, 0.25> shadowless }\n"
                               "light_source { <0, 10, 0> color rgb 1 parallel point_at <0, 0, 0> }\n"
                               "background { color rgb <0.1, 0.2, 0.3> }\n"
                               "global_settings { assumed_gamma 1.0 ambient_light rgb 0.5 max_trace_level 3 }\n"
                               "sphere { 0, 1 }");
    const Camera& c = s.scene.camera;
    EXPECT_EQ(c.from, (Vec3d{0, 2, -5}));
    EXPECT_NEAR(length(normalize(c.at - c.from) - normalize(Vec3d{0, -2, 5})), 0.0, 1e-12);
    // The horizontal angle 60° at 4:3 is a vertical field of view of 2·atan(tan 30° · 3/4).
    EXPECT_NEAR(c.fov_degrees, 2 * std::atan(std::tan(std::numbers::pi / 6) * 0.75) * 180 / std::numbers::pi, 1e-9);
    ASSERT_EQ(s.scene.lights.size(), 2U);
    EXPECT_FALSE(s.scene.lights[0].casts_shadows);
    EXPECT_EQ(s.scene.lights[0].color, (Vec3d{1, 0.5, 0.25}));
    EXPECT_EQ(s.scene.lights[1].kind, Light::Kind::Directional);
    EXPECT_NEAR(length(s.scene.lights[1].direction - Vec3d{0, -1, 0}), 0.0, 1e-12);
    EXPECT_EQ(s.scene.background, (Vec3d{0.1, 0.2, 0.3}));
    EXPECT_EQ(s.scene.ambient, (Vec3d{0.5, 0.5, 0.5}));
    EXPECT_EQ(s.scene.image.reflection_depth, 3);
    EXPECT_EQ(s.scene.image.width, 320);
    // A direction leaning towards up (trough.pov's camera): a shifted lens,
    // looking along the part of the direction off the image plane.
    const PovImport shifted = import(lit + "camera { location -4*z right x*4/3 up y direction <0, 0.1, 1.5> } sphere { 0, 1 }");
    const Camera& sc = shifted.scene.camera;
    EXPECT_NEAR(length(sc.at - sc.from - Vec3d{0, 0, 1.5}), 0.0, 1e-12);
    EXPECT_NEAR(sc.fov_degrees, 2 * std::atan(0.5 / 1.5) * 180 / std::numbers::pi, 1e-9);
    EXPECT_NEAR(sc.shift_up, 0.1, 1e-12);
    EXPECT_EQ(sc.shift_right, 0.0);
    EXPECT_FALSE(warned(shifted, "skewed"));
    // Measured after the camera's transforms: a stretch along y doubles the
    // up vector and the lean.
    const Camera& stretched =
        import(lit + "camera { location -4*z right x*4/3 up y direction <0, 0.1, 1.5> scale <1, 2, 1> } sphere { 0, 1 }")
            .scene.camera;
    EXPECT_NEAR(stretched.fov_degrees, 2 * std::atan(1.0 / 1.5) * 180 / std::numbers::pi, 1e-9);
    EXPECT_NEAR(stretched.shift_up, 0.1, 1e-12);
    EXPECT_THROW(import(lit + "camera { location -4*z right x*4/3 up y direction <0, 1500, 1> } sphere { 0, 1 }"),
                 SceneError);
    // Up and right not at right angles: a skewed plane, not supported.
    EXPECT_TRUE(warned(import(lit + "camera { location -4*z right <1.2, 0.5, 0> up y direction z } sphere { 0, 1 }"),
                       "skewed image plane"));
    // A camera whose right/up ratio is not the image's: a warning.
    EXPECT_TRUE(warned(import(lit + "camera { location -5*z right x up y } sphere { 0, 1 }"), "right/up ratio"));
}

TEST(PovScene, FinishesMapToMaterials) {
    const SceneNode& n = first_node(import(lit + "sphere { 0, 1 texture { pigment { color rgb <0.5, 0.25, 1> } "
                                                 "finish { ambient 0.2 diffuse 0.7 phong 0.8 phong_size 30 reflection 0.3 } } }"));
    ASSERT_TRUE(n.material);
    const Material& m = *n.material;
    EXPECT_EQ(m.color, (Vec3d{0.5, 0.25, 1}));
    EXPECT_DOUBLE_EQ(m.ambient, 0.2);
    EXPECT_DOUBLE_EQ(m.diffuse, 0.7);
    EXPECT_DOUBLE_EQ(m.specular, 0.8);
    EXPECT_DOUBLE_EQ(m.shininess, 120.0);  // Phong's exponent 30 as Blinn's 4·30
    EXPECT_DOUBLE_EQ(m.reflection, 0.3);
    // specular with roughness: Blinn's exponent 1/roughness.
    const SceneNode& sp = first_node(import(lit + "sphere { 0, 1 finish { specular 0.5 roughness 0.01 } }"));
    EXPECT_DOUBLE_EQ(sp.material->shininess, 100.0);
    // No texture: POV-Ray's default, black with ambient 0.1 and diffuse 0.6; #default changes the finish.
    const SceneNode& plain = first_node(import(lit + "sphere { 0, 1 }"));
    EXPECT_EQ(plain.material->color, (Vec3d{0, 0, 0}));
    EXPECT_DOUBLE_EQ(plain.material->diffuse, 0.6);
    EXPECT_DOUBLE_EQ(first_node(import(lit + "#default { finish { ambient 0 diffuse 0.9 } } sphere { 0, 1 }")).material->diffuse, 0.9);
    // A texture given again goes over the object's own: here its colour, keeping its finish.
    const SceneNode& again = first_node(import(lit + "#declare S = sphere { 0, 1 pigment { color rgb 1 } finish { diffuse 0.3 } }\n"
                                                     "object { S pigment { color rgb <0, 1, 0> } }"));
    EXPECT_EQ(again.material->color, (Vec3d{0, 1, 0}));
    EXPECT_DOUBLE_EQ(again.material->diffuse, 0.3);
    // A union's texture reaches the members that give none.
    const SceneNode& u = first_node(import(lit + "union { sphere { 0, 1 } sphere { x, 1 pigment { color rgb 1 } } pigment { color rgb <1, 0, 0> } }"));
    EXPECT_EQ(u.material->color, (Vec3d{1, 0, 0}));
    EXPECT_EQ(u.children[1]->material->color, (Vec3d{1, 1, 1}));
}

TEST(PovScene, WhatCannotBeDrawnIsAnErrorOrAWarning) {
    EXPECT_EQ(error_of("lathe { linear_spline 2, <0, 0>, <1, 1> }"),
              "scene.pov:1:1: lathe is not supported: zeroset cannot reproduce its geometry (docs/povray.md lists what it reads)");
    EXPECT_EQ(error_of("isosurface { function { x > 0 } }"),
              "scene.pov:1:27: a comparison on x, y or z is not supported in a function (zeroset's functions are continuous)");
    // functions.inc's Perlin noise: rendered as its mean, with a warning.
    const PovImport noisy = import(lit + "#declare f_noise3d = function { internal(76) }\n"
                                         "isosurface { function { y - f_noise3d(x, y, z) } }");
    EXPECT_DOUBLE_EQ(value_at(first_node(noisy), 0, 0.5, 0), 0.0);
    EXPECT_TRUE(warned(noisy, "f_noise3d (POV-Ray's Perlin noise) is not supported; rendered as its mean, 0.5"));
    EXPECT_TRUE(warned(import(lit + "sky_sphere { pigment { color rgb 1 } } sphere { 0, 1 }"), "sky_sphere is not supported"));
    EXPECT_TRUE(warned(import(lit + "sphere { 0, 1 no_shadow }"), "scene.pov:2:15: no_shadow is not supported"));
    EXPECT_TRUE(warned(import("sphere { 0, 1 }"), "the scene has no light_source"));
}

}  // namespace
}  // namespace zeroset::pov::test
