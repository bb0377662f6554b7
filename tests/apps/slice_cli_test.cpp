// `zeroset slice` as a user meets it: the Prospero challenge's command draws
// the text, inside black; a scene object is sliced over its bounds; value
// shading draws a colour map; every bad argument fails with a message and
// leaves no file behind.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/cli_test.hpp"
#include "support/models.hpp"
#include "zeroset/io/image_reader.hpp"

namespace fs = std::filesystem;

namespace {

using zeroset::test::Outcome;

class SliceCli : public zeroset::test::CliTest {};

int black_pixels(const zeroset::Image& image) {
    int black = 0;
    for (const zeroset::Vec3f& p : image.pixels) black += p.x == 0.0f && p.y == 0.0f && p.z == 0.0f;
    return black;
}

TEST_F(SliceCli, ProsperoIsBlackTextOnWhite) {
    ZEROSET_SKIP_WITHOUT_MODEL("prospero.vm");

    const Outcome r = run("slice '" ZEROSET_MODELS_DIR "/prospero.vm' --size 128 -o p.png");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("wrote p.png (128x128)"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("full tape 5728 clauses"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(" lanes)"), std::string::npos) << "names the SIMD level: " << r.err;
    const zeroset::Image image = zeroset::read_png(dir_ / "p.png");
    ASSERT_EQ(image.width, 128);
    const int black = black_pixels(image);
    // The text covers a fifth of the square or so; the margins are white.
    EXPECT_GT(black, 128 * 128 / 10);
    EXPECT_LT(black, 128 * 128 / 2);
    EXPECT_EQ(image.at(2, 2).x, 1.0f);
    EXPECT_EQ(image.at(125, 125).x, 1.0f);
}

TEST_F(SliceCli, SceneObjectIsSlicedOverItsBounds) {
    dir_.write("ball.zs", "object \"ball\" { surface x^2 + y^2 + z^2 - 4  bounds box((-2,-2,-2), (2,2,2)) }\n");
    const Outcome r = run("slice ball.zs --size 64 --axis y -q");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    const zeroset::Image image = zeroset::read_png(dir_ / "slice.png");
    // The bounds fill the square, so the disc of radius 2 touches its edges: π/4 of it is inside.
    EXPECT_NEAR(black_pixels(image) / (64.0 * 64.0), 3.14159 / 4, 0.02);
    const Outcome off = run("slice ball.zs --size 64 --at 1.9 --region -2,2 -o off.png");
    ASSERT_EQ(off.status, 0) << off.err;
    EXPECT_LT(black_pixels(zeroset::read_png(dir_ / "off.png")), 64 * 64 / 10);
}

TEST_F(SliceCli, ValueShadingIsAColourMap) {
    dir_.write("ball.zs", "object \"ball\" { surface x^2 + y^2 + z^2 - 1 }\n");
    const Outcome r = run("slice ball.zs --size 48 --region -2,2 --shading value -o v.pfm");
    ASSERT_EQ(r.status, 0) << r.err;
    const zeroset::Image image = zeroset::read_pfm(dir_ / "v.pfm");
    const zeroset::Vec3f centre = image.at(24, 24), corner = image.at(1, 1);
    EXPECT_GT(centre.z, centre.x) << "inside is blue";
    EXPECT_GT(corner.x, corner.z) << "outside is orange";
    EXPECT_EQ(run("slice --help").status, 0);
}

TEST_F(SliceCli, BadArgumentsFailWithAMessageAndNoFile) {
    dir_.write("ball.zs", "object \"ball\" { surface x^2 + y^2 + z^2 - 1 }\n");
    dir_.write("bad.vm", "_0 var-x\n_1 frobnicate _0\n");
    const std::pair<const char*, const char*> cases[] = {
        {"ball.zs --size 0", "size"},
        {"ball.zs --size 100000", "size"},
        {"ball.zs --axis w", "axis 'w'"},
        {"ball.zs --region 1,-1", "--region"},
        {"ball.zs --at nan", "--at"},
        {"ball.zs --shading rainbow", "rainbow"},
        {"ball.zs --object nosuch", "nosuch"},
        {"ball.zs --threads -1", "threads"},
        {"bad.vm", "bad.vm:2"},
        {"bad.vm --object ball", "--object"},
        {"missing.vm", "missing.vm"},
        {"", "one .vm model or scene file"},
        {"ball.zs ball.zs", "one .vm model or scene file"},
        {"ball.zs -o out.jpg", "out.jpg"},
    };
    for (const auto& [args, mentions] : cases) {
        const bool names_output = std::string(args).find("-o ") != std::string::npos;
        const Outcome r = run(std::string("slice ") + args + (names_output ? "" : " -o out.png"));
        EXPECT_NE(r.status, 0) << args;
        EXPECT_NE(r.err.find(mentions), std::string::npos) << args << ": " << r.err;
        EXPECT_EQ(dir_.entries(), (std::vector<std::string>{"bad.vm", "ball.zs"})) << args;
    }
}

}  // namespace

namespace {

class MeshCli : public zeroset::test::CliTest {};

TEST_F(MeshCli, WritesAClosedMeshOfASceneObjectAndChecksFirst) {
    const Outcome r = run("mesh '" ZEROSET_SOURCE_DIR "/scenes/examples/torus.zs' -o torus.stl --resolution 32");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("zeroset: wrote torus.stl — "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("dual contouring"), std::string::npos) << r.err;  // the default
    const Outcome tetra = run("mesh '" ZEROSET_SOURCE_DIR "/scenes/examples/torus.zs' -o torus.ply --method tetrahedra");
    ASSERT_EQ(tetra.status, 0) << tetra.err;
    EXPECT_NE(tetra.err.find("marching tetrahedra, vertices within"), std::string::npos) << tetra.err;
    const Outcome unknown = run("mesh '" ZEROSET_SOURCE_DIR "/scenes/examples/torus.zs' -o t.stl --method duel");
    EXPECT_EQ(unknown.status, 2);
    EXPECT_NE(unknown.err.find("did you mean 'dual'"), std::string::npos) << unknown.err;
    const auto size = std::filesystem::file_size(dir_ / "torus.stl");
    EXPECT_GT(size, 84u + 50u * 1000u);
    EXPECT_EQ((size - 84) % 50, 0u);
    for (const char* bad : {"'" ZEROSET_SOURCE_DIR "/scenes/examples/torus.zs'",          // no output
                            "'" ZEROSET_SOURCE_DIR "/scenes/examples/torus.zs' -o t.fbx",  // no such format
                            "'" ZEROSET_SOURCE_DIR "/scenes/examples/torus.zs' -o t.obj --resolution 100"}) {
        const Outcome e = run(std::string("mesh ") + bad);
        EXPECT_EQ(e.status, 2) << bad << ": " << e.err;
    }
    const Outcome nowhere = run("mesh '" ZEROSET_SOURCE_DIR "/scenes/examples/torus.zs' -o no/dir/t.obj");
    EXPECT_EQ(nowhere.status, 1);
    EXPECT_EQ(dir_.entries().size(), 2u);  // only torus.stl and torus.ply
}

}  // namespace
