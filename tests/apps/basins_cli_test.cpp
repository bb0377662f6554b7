// `zeroset basins` as a user meets it: the default invocation draws the
// survey's Figure 5 with the four real roots of the blobs in four colours (plus
// black and white regions) and names the roots on stderr; every bad argument
// fails with a message and leaves no file behind.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/cli_test.hpp"
#include "zeroset/io/image_reader.hpp"
#include "zeroset/render/newton_basins.hpp"

namespace fs = std::filesystem;

namespace {

using zeroset::test::Outcome;

class BasinsCli : public zeroset::test::CliTest {};

/// Pixel counts per class: [0] black, [1] white, [2 + i] shades of basin colour i.
std::array<int, 12> classify(const zeroset::Image& image) {
    std::array<int, 12> counts{};
    for (const zeroset::Vec3f& p : image.pixels) {
        if (p.x < 1e-4f && p.y < 1e-4f && p.z < 1e-4f) {
            ++counts[0];
        } else if (p.x > 0.999f && p.y > 0.999f && p.z > 0.999f) {
            ++counts[1];
        } else {
            // The palette colour in the same direction (shading only scales it).
            int best = 0;
            float best_cosine = -1.0f;
            for (int i = 0; i < 10; ++i) {
                const zeroset::Vec3f c = zeroset::basin_colour(i);
                const float cosine = dot(p, c) / (length(p) * length(c));
                if (cosine > best_cosine) best_cosine = cosine, best = i;
            }
            ++counts[static_cast<std::size_t>(2 + best)];
        }
    }
    return counts;
}

TEST_F(BasinsCli, DefaultInvocationDrawsFigure5OfTheSurveyBlobs) {
    const Outcome r = run("basins -o out.png --width 160 --height 90");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("real roots along the ray: 2.99573, 4.50209, 5.85302, 6.25402"), std::string::npos) << r.err;
    const zeroset::Image image = zeroset::read_png(dir_ / "out.png");
    ASSERT_EQ(image.width, 160);
    ASSERT_EQ(image.height, 90);
    const std::array<int, 12> counts = classify(image);
    EXPECT_GT(counts[0], 100) << "complex-root (black) regions";
    EXPECT_GT(counts[1], 100) << "diverging (white) regions";
    int root_colours = 0;
    for (std::size_t i = 2; i < counts.size(); ++i) root_colours += counts[i] > 100 ? 1 : 0;
    EXPECT_GE(root_colours, 4);
}

TEST_F(BasinsCli, WritesBasinsPngByDefaultAndHasHelp) {
    ASSERT_EQ(run("basins --width 32 --height 18").status, 0);
    EXPECT_TRUE(fs::exists(dir_ / "basins.png"));
    EXPECT_EQ(run("basins --help").status, 0);
}

TEST_F(BasinsCli, OptionsChooseTheSceneObjectRayAndRectangle) {
    dir_.write("sphere.zs", "object \"ball\" { surface x^2 + y^2 + z^2 - 1 }\n");
    const Outcome r = run("basins sphere.zs --object ball --origin -3,0,0 --dir 2,0,0 --re 0,3 --im -1,1 "
                          "--width 24 --height 16 --iterations 50 -o ball.pfm");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("real roots along the ray: 1, 2\n"), std::string::npos) << r.err;
    EXPECT_EQ(zeroset::read_pfm(dir_ / "ball.pfm").width, 24);
}

TEST_F(BasinsCli, BadArgumentsFailWithAMessageAndNoFile) {
    dir_.write("sphere.zs", "object \"ball\" { surface x^2 + y^2 + z^2 - 1 }\n");
    const std::pair<const char*, const char*> cases[] = {
        {"--width 0", "width"},
        {"--height -5", "height"},
        {"--iterations 0", "iterations"},
        {"--width abc", "--width"},
        {"--re 5,1", "--re"},
        {"--im 1,1", "--im"},
        {"--re 1,x", "--re"},
        {"--origin 1,2", "--origin"},
        {"--dir 1,2,3,4", "--dir"},
        {"--dir 0,0,0", "direction"},
        {"--origin nan,0,0", "--origin"},
        {"--object nosuch", "nosuch"},
        {"sphere.zs --object blobs", "'ball'"},
        {"missing.zs", "missing.zs"},
        {"--frobnicate 3", "--frobnicate"},
        {"-o out.jpg", "out.jpg"},
    };
    for (const auto& [args, mentions] : cases) {
        const bool names_output = std::string(args).starts_with("-o ");
        const Outcome r = run(std::string("basins ") + args + (names_output ? "" : " -o out.png"));
        EXPECT_NE(r.status, 0) << args;
        EXPECT_NE(r.err.find(mentions), std::string::npos) << args << ": " << r.err;
        EXPECT_EQ(dir_.entries(), std::vector<std::string>{"sphere.zs"}) << args;
    }
}

}  // namespace
