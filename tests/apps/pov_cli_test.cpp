// The program with POV-Ray scenes: `render` takes a .pov file (its image
// size before the scene is read, --include-path for #include), `import`
// writes the zeroset scene it becomes, and errors are located with nothing
// written.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/cli_test.hpp"
#include "zeroset/io/image_reader.hpp"

namespace {

using zeroset::test::Outcome;

class PovCli : public zeroset::test::CliTest {};

const std::string scene =
    "#include \"sizes.inc\"\n"
    "camera { location <0, 1, -5> look_at 0 right x*image_width/image_height angle 50 }\n"
    "light_source { <-5, 8, -6> color rgb 1 }\n"
    "sphere { 0, Radius pigment { color rgb <1, 0.2, 0.1> } finish { phong 0.5 } }\n"
    "isosurface { function { x*x + y*y + z*z - 1 } max_gradient 3 translate <1.5, 0, 0> }\n";

TEST_F(PovCli, RendersAndImportsAPovRayScene) {
    std::filesystem::create_directories(dir_.path() / "inc");
    dir_.write("inc/sizes.inc", "#declare Radius = 0.8;\n");
    dir_.write("scene.pov", scene);
    const Outcome r = run("render scene.pov -o shot.png --width 64 --height 48 --include-path inc");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("zeroset: note: scene.pov:5:47: max_gradient is not needed"), std::string::npos) << r.err;
    const zeroset::Image image = zeroset::read_png(dir_.path() / "shot.png");
    EXPECT_EQ(image.width, 64);
    // import: the scene as zeroset text, which renders the same image.
    const Outcome i = run("import scene.pov -o scene.zs --width 64 --height 48 --include-path inc");
    ASSERT_EQ(i.status, 0) << i.err;
    const Outcome again = run("render scene.zs -o again.png -q");
    ASSERT_EQ(again.status, 0) << again.err;
    EXPECT_EQ(zeroset::read_png(dir_.path() / "again.png").pixels, image.pixels);
    EXPECT_EQ(run("import scene.zs").status, 2);  // import reads .pov scenes only
}

TEST_F(PovCli, ErrorsAreLocatedAndWriteNothing) {
    dir_.write("bad.pov", "sphere { 0, 1 }\nlathe { linear_spline 2, <0, 0>, <1, 1> }\n");
    const Outcome r = run("render bad.pov -o shot.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("bad.pov:2:1: lathe is not supported"), std::string::npos) << r.err;
    const Outcome i = run("import bad.pov -o bad.zs");
    EXPECT_EQ(i.status, 1);
    EXPECT_FALSE(std::filesystem::exists(dir_.path() / "shot.png"));
    EXPECT_FALSE(std::filesystem::exists(dir_.path() / "bad.zs"));
}

}  // namespace
