// The zeroset program as a user meets it: exit codes, messages with
// file:line:column, no output file on any error, and every shipped scene
// rendered at a small size with a sensible share of the frame covered.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_test.hpp"
#include "zeroset/io/image_reader.hpp"

namespace fs = std::filesystem;

namespace {

using zeroset::test::Outcome;

class Cli : public zeroset::test::CliTest {
protected:
    fs::path write(const std::string& name, const std::string& text) const { return dir_.write(name, text); }

    /// Files in the temp directory (nothing may be left behind by a failure).
    [[nodiscard]] std::size_t file_count() const { return dir_.entries().size(); }

};

double coverage(const zeroset::Image& image) {
    // The background is uniform: count pixels that differ from the corner's.
    const zeroset::Vec3f bg = image.at(0, 0);
    int covered = 0;
    for (const auto& p : image.pixels)
        if (std::abs(p.x - bg.x) + std::abs(p.y - bg.y) + std::abs(p.z - bg.z) > 1e-3f) ++covered;
    return static_cast<double>(covered) / static_cast<double>(image.pixels.size());
}

TEST_F(Cli, HelpListsCommandsAndOptions) {
    EXPECT_EQ(run("--help").status, 0);
    const Outcome no_args = run("");
    EXPECT_EQ(no_args.status, 2);
    EXPECT_NE(no_args.err.find("render"), std::string::npos);
    EXPECT_EQ(run("render --help").status, 0);
    const Outcome bad = run("frobnicate");
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.err.find("unknown command"), std::string::npos) << bad.err;
    EXPECT_NE(run("rendr").err.find("did you mean 'render'?"), std::string::npos);
    const Outcome option = run("render --widht 10");
    EXPECT_EQ(option.status, 2);
    EXPECT_NE(option.err.find("unknown option --widht; did you mean '--width'?"), std::string::npos) << option.err;
    const Outcome method = run("render --method intervall");
    EXPECT_EQ(method.status, 2);
    EXPECT_NE(method.err.find("did you mean 'interval'?"), std::string::npos) << method.err;
}

TEST_F(Cli, RendersTheDefaultScene) {
    const Outcome r = run("render -o out.png --width 96 --height 72");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("96x72"), std::string::npos) << r.err;  // the summary line
    EXPECT_NE(r.err.find("hits"), std::string::npos) << r.err;
    const zeroset::Image image = zeroset::read_png(dir_ / "out.png");
    EXPECT_EQ(image.width, 96);
    EXPECT_EQ(image.height, 72);
    const double c = coverage(image);
    EXPECT_GT(c, 0.08);
    EXPECT_LT(c, 0.9);
}

TEST_F(Cli, WritesPpmAndPfmByExtension) {
    ASSERT_EQ(run("render -q -o out.ppm --width 32 --height 24").status, 0);
    ASSERT_EQ(run("render -q -o out.pfm --width 32 --height 24").status, 0);
    EXPECT_EQ(zeroset::read_pfm(dir_ / "out.pfm").width, 32);
    std::ifstream ppm(dir_ / "out.ppm", std::ios::binary);
    std::string magic;
    ppm >> magic;
    EXPECT_EQ(magic, "P6");
}

TEST_F(Cli, WritesExrWithDepthAndNormalsThatExrheaderReads) {
    ASSERT_EQ(run("render -q -o out.exr --width 32 --height 24").status, 0);
    const zeroset::Image image = zeroset::read_exr(dir_ / "out.exr");
    EXPECT_EQ(image.width, 32);
    ASSERT_TRUE(image.has_layers());
    // OpenEXR's own tool, as an independent reader (Debian's openexr package).
    if (std::system("command -v exrheader > /dev/null 2>&1") != 0) GTEST_SKIP() << "exrheader is not installed";
    const Outcome header = run_shell("exrheader out.exr");
    ASSERT_EQ(header.status, 0) << header.err;
    for (const char* channel : {"R,", "G,", "B,", "Z,", "N.x,", "N.y,", "N.z,"})
        EXPECT_NE(header.out.find(std::string("    ") + channel), std::string::npos) << channel << "\n" << header.out;
    EXPECT_NE(header.out.find("(0 0) - (31 23)"), std::string::npos) << header.out;
}

TEST_F(Cli, WritesToStandardOutputInTheNamedFormat) {
    const Outcome png = run_shell("'" ZEROSET_BINARY "' render -q -o - --width 16 --height 12 | od -An -c -N4");
    ASSERT_EQ(png.status, 0) << png.err;
    EXPECT_NE(png.out.find("P   N   G"), std::string::npos) << png.out;
    const Outcome ppm = run_shell("'" ZEROSET_BINARY "' slice '" ZEROSET_SOURCE_DIR
                                  "/scenes/hart1993/blinn_blobs.zs' -q --size 8 -o - --format ppm | head -c 2");
    ASSERT_EQ(ppm.status, 0) << ppm.err;
    EXPECT_EQ(ppm.out, "P6");
    EXPECT_EQ(file_count(), 0u);
    const Outcome bad = run("render -o - --format jpg");
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.err.find("jpg"), std::string::npos) << bad.err;
    const Outcome mismatch = run("render -o out.png --format exr");
    EXPECT_EQ(mismatch.status, 2);
    EXPECT_NE(mismatch.err.find("--format"), std::string::npos) << mismatch.err;
}

TEST_F(Cli, AnUnwritableOutputIsReportedBeforeRendering) {
    // A scene far too costly to render in a test: the error must come first.
    write("slow.zs", "image { width 4000 height 4000 spp 64 }\n"
                     "object \"a\" { surface x^2 + y^2 + z^2 - 1 bounds box((-1,-1,-1),(1,1,1)) }\n");
    for (const char* output : {"no/such/dir/out.png", "."}) {
        const Outcome r = run(std::string("render slow.zs -o ") + output);
        EXPECT_NE(r.status, 0) << output;
        EXPECT_EQ(r.err.find("wrote"), std::string::npos) << r.err;
    }
    fs::create_directory(dir_ / "taken.png");
    const Outcome taken = run("render slow.zs -o taken.png");
    EXPECT_EQ(taken.status, 1);
    EXPECT_NE(taken.err.find("taken.png: is a directory"), std::string::npos) << taken.err;
}

TEST_F(Cli, FramesAreNumberedFilesWithTheClockRunningFromZeroToOne) {
    write("roll.zs", "camera { from (0, 0, -6) }\n"
                     "object \"b\" { surface (x - 2 * clock + 1)^2 + y^2 + z^2 - 0.25  bounds box((-2,-1,-1),(2,1,1)) }\n");
    const Outcome r = run("render roll.zs -q --frames 3 -o roll.pfm --width 40 --height 30");
    ASSERT_EQ(r.status, 0) << r.err;
    const zeroset::Image first = zeroset::read_pfm(dir_ / "roll_0000.pfm");
    const zeroset::Image middle = zeroset::read_pfm(dir_ / "roll_0001.pfm");
    const zeroset::Image last = zeroset::read_pfm(dir_ / "roll_0002.pfm");
    EXPECT_EQ(file_count(), 4u);  // the scene and three frames
    // The ball runs from x = -1 to x = 1: left of centre, centred, right of centre.
    const auto lit = [](const zeroset::Image& image, int x) { return image.at(x, 15).x > image.at(0, 0).x + 0.01f; };
    EXPECT_TRUE(lit(first, 13) && !lit(first, 27));
    EXPECT_TRUE(lit(middle, 20) && !lit(middle, 13) && !lit(middle, 27));
    EXPECT_TRUE(lit(last, 27) && !lit(last, 13));
    const Outcome at = run("render roll.zs -q --clock 1 -o at.pfm --width 40 --height 30");
    ASSERT_EQ(at.status, 0) << at.err;
    EXPECT_EQ(zeroset::read_pfm(dir_ / "at.pfm").pixels, last.pixels);
    for (const char* bad : {"roll.zs --frames 0", "roll.zs --frames 2 -o -", "roll.zs --frames 2 --clock 0.5",
                            "roll.zs --clock abc", "--frames 2"}) {
        const Outcome e = run(std::string("render ") + bad);
        EXPECT_EQ(e.status, 2) << bad << ": " << e.err;
    }
    // Each frame's file is checked before that frame is rendered.
    fs::create_directory(dir_ / "stuck_0001.png");
    const Outcome stuck = run("render roll.zs -q --frames 3 -o stuck.png --width 8 --height 6");
    EXPECT_EQ(stuck.status, 1);
    EXPECT_NE(stuck.err.find("stuck_0001.png: is a directory"), std::string::npos) << stuck.err;
    EXPECT_TRUE(fs::exists(dir_ / "stuck_0000.png"));
    EXPECT_FALSE(fs::exists(dir_ / "stuck_0002.png"));
}

TEST_F(Cli, BoundsThatCutTheSolidAreAWarningUnlessTheSceneSaysSo) {
    write("cut.zs", "camera { from (0, 0, -5) }\n"
                    "object \"ball\" {\n  surface x^2 + y^2 + z^2 - 1\n  bounds box((-1.1, -1.1, -1.1), (1.1, 1.1, 0.5))\n}\n");
    const Outcome r = run("render cut.zs -q -o cut.png --width 16 --height 12");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("zeroset: warning: cut.zs:2:1: object 'ball': its bounds cut through its solid: f < 0 at "),
              std::string::npos) << r.err;
    EXPECT_NE(r.err.find("on the face z = 0.5"), std::string::npos) << r.err;
    write("meant.zs", "camera { from (0, 0, -5) }\n"
                      "object \"ball\" { surface x^2 + y^2 + z^2 - 1  bounds box((-1.1, -1.1, -1.1), (1.1, 1.1, 0.5))  cut on }\n");
    const Outcome meant = run("render meant.zs -q -o meant.png --width 16 --height 12");
    ASSERT_EQ(meant.status, 0) << meant.err;
    EXPECT_EQ(meant.err, "");
}

TEST_F(Cli, SyntaxErrorNamesFileLineColumnAndWritesNothing) {
    write("bad.zs", "camera { from (0, 0, -5) }\nobject { surface x^2 + * y }\n");
    const std::size_t before = file_count();
    const Outcome r = run("render bad.zs -o out.png --width 16 --height 16");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("bad.zs:2:"), std::string::npos) << r.err;
    EXPECT_EQ(file_count(), before);
}

TEST_F(Cli, UnknownIdentifierNamesFileLineColumn) {
    write("unknown.zs", "object {\n  surface x^2 + y^2 + q - 1\n}\n");
    const Outcome r = run("render unknown.zs -o out.png --width 16 --height 16");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("unknown.zs:2:23:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("'q'"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
}

TEST_F(Cli, NonPositiveImageSizeInSceneNamesFileLineColumn) {
    write("size.zs", "image { width 0 height 10 }\nobject { surface x^2 + y^2 + z^2 - 1 }\n");
    const Outcome r = run("render size.zs -o out.png");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("size.zs:1:15:"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
}

TEST_F(Cli, NonPositiveImageSizeOnCommandLineIsAnError) {
    for (const char* args : {"--width 0", "--height -3", "--width abc", "--spp 0"}) {
        const Outcome r = run(std::string("render -o out.png ") + args);
        EXPECT_NE(r.status, 0) << args;
        EXPECT_FALSE(r.err.empty()) << args;
        EXPECT_FALSE(fs::exists(dir_ / "out.png")) << args;
    }
}

TEST_F(Cli, ConeAntialiasingOptionIsCheckedBeforeRendering) {
    const Outcome unknown = run("render -o out.png --width 8 --height 8 --antialias cones");
    EXPECT_NE(unknown.status, 0);
    EXPECT_NE(unknown.err.find("unknown antialiasing 'cones' (known: samples, cone)"), std::string::npos) << unknown.err;
    const Outcome both = run("render -o out.png --width 8 --height 8 --antialias cone --spp 4");
    EXPECT_NE(both.status, 0);
    EXPECT_NE(both.err.find("cone antialiasing traces one ray per pixel"), std::string::npos) << both.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
    const Outcome blob = run("render '" ZEROSET_SOURCE_DIR "/scenes/blobs/molecule_1000.zs' -o out.png --width 8 "
                             "--height 8 --antialias cone");
    EXPECT_NE(blob.status, 0);
    EXPECT_NE(blob.err.find("object 'molecule' has 1000 blob components: cone antialiasing"), std::string::npos)
        << blob.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
    const Outcome fine = run("render -o out.png --width 32 --height 24 --antialias cone");
    EXPECT_EQ(fine.status, 0) << fine.err;
    EXPECT_NE(fine.err.find("cone antialiasing:"), std::string::npos) << fine.err;
    EXPECT_TRUE(fs::exists(dir_ / "out.png"));
}

TEST_F(Cli, BadOutputAndMissingSceneAreErrors) {
    const Outcome jpg = run("render -o out.jpg --width 8 --height 8");
    EXPECT_NE(jpg.status, 0);
    EXPECT_NE(jpg.err.find("out.jpg"), std::string::npos) << jpg.err;
    const Outcome missing = run("render nowhere.zs -o out.png");
    EXPECT_NE(missing.status, 0);
    EXPECT_NE(missing.err.find("nowhere.zs"), std::string::npos) << missing.err;
    const Outcome no_dir = run("render -o no/such/dir/out.png --width 8 --height 8");
    EXPECT_NE(no_dir.status, 0);
    EXPECT_EQ(file_count(), 0u);
}

TEST_F(Cli, NanProducingFunctionIsAnErrorAndWritesNothing) {
    write("nan.zs",
          "camera { from (0, 0, -5) }\n"
          "object \"root\" { surface sqrt(x) + y^2 + z^2 - 1  bounds box((-2, -2, -2), (2, 2, 2)) }\n");
    const Outcome r = run("render nan.zs -o out.png --width 16 --height 16");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("NaN"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
}

TEST_F(Cli, ARenderPastItsEvaluationBudgetIsAnErrorAndWritesNothing) {
    const Outcome spent = run("render -o out.png --width 16 --height 12 --max-evaluations 100");
    EXPECT_EQ(spent.status, 1);
    EXPECT_NE(spent.err.find("its budget of 100 evaluations"), std::string::npos) << spent.err;
    const Outcome malformed = run("render -o out.png --width 16 --height 12 --max-evaluations lots");
    EXPECT_EQ(malformed.status, 2);
    EXPECT_NE(malformed.err.find("--max-evaluations"), std::string::npos) << malformed.err;
    EXPECT_EQ(file_count(), 0u);
    const Outcome enough = run("render -o out.png --width 16 --height 12 --max-evaluations 100000000");
    EXPECT_EQ(enough.status, 0) << enough.err;
}

/// Every scene shipped in scenes/ renders at a small size and covers a
/// sensible part of the frame (something is visible, not everything).
TEST_F(Cli, EveryShippedSceneRendersWithSensibleCoverage) {
    int scenes = 0;
    for (const auto& entry : fs::recursive_directory_iterator(ZEROSET_SOURCE_DIR "/scenes")) {
        if (entry.path().extension() != ".zs") continue;
        ++scenes;
        const Outcome r = run("render -q '" + entry.path().string() + "' -o shot.png --width 64 --height 48");
        ASSERT_EQ(r.status, 0) << entry.path() << "\n" << r.err;
        const double c = coverage(zeroset::read_png(dir_ / "shot.png"));
        EXPECT_GT(c, 0.03) << entry.path();
        EXPECT_LT(c, 0.97) << entry.path();
    }
    EXPECT_GE(scenes, 5);
}

}  // namespace

namespace {

// Ctrl-C (SIGINT) or SIGTERM during a long render stops it at once, says so,
// and leaves no file — neither the image nor a hidden temporary.
TEST_F(Cli, AnInterruptedRenderStopsPromptlyAndWritesNothing) {
    for (const char* signal : {"INT", "TERM"}) {
        // The built-in scene at 4000×3000 with 16 samples a pixel: many seconds of work.
        const std::string command = std::string("'" ZEROSET_BINARY "' render") +
                                    " -o slow.png --width 4000 --height 3000 --spp 16 & pid=$!; "
                                    "sleep 0.5; kill -" + signal + " $pid; wait $pid; echo status=$?";
        const Outcome r = run_shell(command);
        EXPECT_NE(r.out.find(std::string("status=") + (std::string(signal) == "INT" ? "130" : "143")),
                  std::string::npos)
            << r.out << r.err;
        EXPECT_NE(r.err.find("nothing was written"), std::string::npos) << r.err;
        EXPECT_EQ(file_count(), 0u) << signal;
    }
}

}  // namespace

namespace {

TEST_F(Cli, TheTileLogHasARowPerTileAndABadPlaceIsRefusedBeforeRendering) {
    const Outcome r = run("render -q -o out.png --width 40 --height 20 --threads 2 --tile-log tiles.csv");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string log = zeroset::test::read_text(dir_ / "tiles.csv");
    EXPECT_EQ(log.substr(0, log.find('\n')), "frame,x0,y0,width,height,rank,seconds,evaluations,camera_rays,hits");
    // 40×20 is 3 × 2 tiles, the last column and row narrower; every ray counted once.
    EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 1 + 6) << log;
    EXPECT_NE(log.find("\n0,32,16,8,4,0,"), std::string::npos) << log;
    std::istringstream rows(log.substr(log.find('\n') + 1));
    long long rays = 0;
    for (std::string row; std::getline(rows, row);) {
        std::vector<std::string> cells;
        std::istringstream fields(row);
        for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
        ASSERT_EQ(cells.size(), 10U) << row;
        rays += std::stoll(cells[8]);
    }
    EXPECT_EQ(rays, 40 * 20);
    // A log that cannot be written stops the render before it starts.
    const Outcome bad = run("render -o late.png --width 16 --height 16 --tile-log no/such/dir/tiles.csv");
    EXPECT_NE(bad.status, 0);
    EXPECT_NE(bad.err.find("no/such/dir/tiles.csv"), std::string::npos) << bad.err;
    EXPECT_FALSE(fs::exists(dir_ / "late.png"));
}

}  // namespace
