// `mpirun -n 2 zeroset render …` against one process: the same files, byte
// for byte, for every method, supersampling, cone antialiasing, EXR layers,
// included files and animations; and failures of a rank — a scene error, a
// NaN, a killed process — end the job with a message and no image.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>

#include "support/cli_test.hpp"

namespace {

namespace fs = std::filesystem;
using zeroset::test::Outcome;
using zeroset::test::read_text;

class DistributedCli : public zeroset::test::CliTest {
protected:
    void SetUp() override {
#ifndef ZEROSET_MPIRUN
        if (!std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()).starts_with("WithoutMpi"))
            GTEST_SKIP() << "built without MPI";
#endif
    }

    /// `mpirun -n RANKS zeroset ARGS`; oversubscribed, as CI has 2 cores.
    Outcome mpirun(const std::string& args, int ranks = 2) const {
#ifdef ZEROSET_MPIRUN
        return run_shell(launcher(ranks) + "'" ZEROSET_BINARY "' " + args);
#else
        (void)args, (void)ranks;
        return {};
#endif
    }

    static std::string launcher(int ranks) {
#ifdef ZEROSET_MPIRUN
        // Root is allowed (CI runs as root); no binding, so that ranks and threads share the cores.
        return "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 '" ZEROSET_MPIRUN "' -n " +
               std::to_string(ranks) + " --oversubscribe --bind-to none ";
#else
        (void)ranks;
        return {};
#endif
    }

    /// Renders with one process and with `ranks` ranks; expects the same file.
    void expect_same_file(const std::string& args, const std::string& out, int ranks = 2) const {
        const Outcome one = run(args + " -q -o one_" + out);
        ASSERT_EQ(one.status, 0) << one.err;
        const Outcome many = mpirun(args + " -q -o many_" + out, ranks);
        ASSERT_EQ(many.status, 0) << many.err;
        const std::string a = read_text(dir_.path() / ("one_" + out)), b = read_text(dir_.path() / ("many_" + out));
        EXPECT_FALSE(a.empty());
        EXPECT_TRUE(a == b) << args << ": the " << ranks << "-rank file differs from the one process's";
    }

    static std::string scene(const std::string& name) { return "'" ZEROSET_SOURCE_DIR "/scenes/" + name + "'"; }
};

TEST_F(DistributedCli, EveryMethodGivesTheSameImageAsOneProcess) {
    for (const char* method : {"auto", "sphere", "interval", "lg", "newton", "regula_falsi", "bisection"})
        expect_same_file(std::string("render --width 64 --height 48 --method ") + method, std::string(method) + ".png");
    expect_same_file("render " + scene("algebraic/tangle_cube.zs") + " --width 64 --height 48 --method polynomial",
                     "polynomial.png");
}

TEST_F(DistributedCli, SamplesLayersIncludesAndPrimitivesAreTheSame) {
    expect_same_file("render --width 48 --height 36 --spp 4", "spp4.png");
    expect_same_file("render --width 48 --height 36 --antialias cone", "cone.png");
    expect_same_file("render --width 40 --height 30", "layers.exr");
    expect_same_file("render " + scene("csg/machined_part_roth.zs") + " --width 64 --height 48", "csg.png");
    expect_same_file("render " + scene("blobs/ball_and_stick.zs") + " --width 64 --height 48", "blobs.png");
    expect_same_file("render " + scene("sweeps/coil.zs") + " --width 64 --height 48", "sweep.png", 3);
}

TEST_F(DistributedCli, OtherRanksNeedNoneOfRankZerosFiles) {
    // Rank 1 runs in an empty folder: the scene, its include and the output
    // folder exist for rank 0 only, as on a cluster without a shared file system.
    dir_.write("inc/ball.zs", "let ball = x^2 + y^2 + z^2 - 1\n");
    dir_.write("scene.zs", "include \"inc/ball.zs\"\ncamera { from (0, 1, -5) }\nlight { from (-5, 8, -6) }\n"
                           "object { surface ball  bounds box((-2, -2, -2), (2, 2, 2)) }\n");
    fs::create_directories(dir_.path() / "out");
    fs::create_directories(dir_.path() / "elsewhere");
    const std::string args = "render scene.zs --width 48 --height 32 -q --tile-log out/tiles.csv -o out/";
    ASSERT_EQ(run(args + "one.png").status, 0);
    dir_.write("run.sh", "if [ \"$OMPI_COMM_WORLD_RANK\" = 1 ]; then cd elsewhere; fi\nexec '" ZEROSET_BINARY "' " + args +
                             "many.png\n");
    const Outcome r = run_shell(launcher(2) + "sh run.sh");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(read_text(dir_.path() / "out/one.png") == read_text(dir_.path() / "out/many.png"));
    std::istringstream log(read_text(dir_.path() / "out/tiles.csv"));
    int rank_1_tiles = 0;
    for (std::string row; std::getline(log, row);) {
        std::istringstream cells(row);
        std::string cell;
        for (int column = 0; column < 6; ++column) std::getline(cells, cell, ',');  // the sixth is the rank
        rank_1_tiles += cell == "1";
    }
    EXPECT_GT(rank_1_tiles, 0) << "rank 1 traced no tile";
    EXPECT_TRUE(fs::is_empty(dir_.path() / "elsewhere"));
}

TEST_F(DistributedCli, AnimationsSpreadFramesAndTilesAndMatch) {
    dir_.write("orbit.zs",
               "camera { from (0, 1, -6) }\n"
               "light { from (-5, 8, -6) }\n"
               "object \"ball\" { surface (x - 2 * clock + 1)^2 + y^2 + z^2 - 1  bounds box((-3, -2, -2), (3, 2, 2)) }\n");
    const Outcome one = run("render orbit.zs --frames 4 --width 32 --height 24 -q -o one.png");
    ASSERT_EQ(one.status, 0) << one.err;
    const Outcome many = mpirun("render orbit.zs --frames 4 --width 32 --height 24 -o many.png --tile-log tiles.csv");
    ASSERT_EQ(many.status, 0) << many.err;
    for (int frame = 0; frame < 4; ++frame) {
        const std::string n = "_000" + std::to_string(frame) + ".png";
        EXPECT_TRUE(read_text(dir_.path() / ("one" + n)) == read_text(dir_.path() / ("many" + n))) << "frame " << frame;
    }
    // The summary: a line per frame, a line per rank, and the imbalance.
    EXPECT_NE(many.err.find("zeroset: wrote many_0003.png"), std::string::npos) << many.err;
    EXPECT_NE(many.err.find("zeroset: rank 1: "), std::string::npos) << many.err;
    EXPECT_NE(many.err.find("2 ranks, load imbalance"), std::string::npos) << many.err;
    // The tile log: every tile of every frame once: 4 frames of 2 × 2 tiles.
    const std::string log = read_text(dir_.path() / "tiles.csv");
    EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 1 + 4 * 4) << log;
}

TEST_F(DistributedCli, ASceneErrorIsReportedOnceAndWritesNothing) {
    dir_.write("bad.zs", "camera { from (0, 0, -5) }\nobject \"x\" { surface x^2 + bogus }\n");
    const Outcome r = mpirun("render bad.zs -o out.png");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("bad.zs:2:"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("bad.zs:2:"), r.err.rfind("bad.zs:2:")) << "reported by every rank: " << r.err;
    EXPECT_FALSE(fs::exists(dir_.path() / "out.png"));
}

TEST_F(DistributedCli, ANanOnAnyRankEndsTheJobWithItsMessage) {
    dir_.write("nan.zs",
               "camera { from (0, 0, -5) }\n"
               "object \"root\" { surface sqrt(x) + y^2 + z^2 - 1  bounds box((-2, -2, -2), (2, 2, 2)) }\n");
    const Outcome r = mpirun("render nan.zs -o out.png --width 64 --height 64");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("NaN"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_.path() / "out.png"));
}

TEST_F(DistributedCli, AFailureInARanksLastTilesOrAnEarlierFrameIsNeverLost) {
    // 8×8 is one tile: a NaN found while tracing it must fail the job, not
    // be sent as a tile that completes the frame (several runs, as it is a race).
    dir_.write("nan.zs",
               "camera { from (0, 0, -5) }\n"
               "object \"root\" { surface sqrt(x) + y^2 + z^2 - 1  bounds box((-2, -2, -2), (2, 2, 2)) }\n");
    for (int run = 0; run < 3; ++run) {
        const Outcome r = mpirun("render nan.zs -o one.png --width 8 --height 8 --threads 1");
        EXPECT_EQ(r.status, 1) << r.err;
        EXPECT_NE(r.err.find("NaN"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir_.path() / "one.png"));
    }
    // NaN in frame 0 only: its failure must survive the frame being freed
    // while the ranks go on to later frames, and frame 0 is never written.
    dir_.write("nan0.zs",
               "image { width 16 height 16 }\ncamera { from (0, 0, -5) }\n"
               "object \"root\" { surface sqrt(x + 10 * clock) + y^2 + z^2 - 1  bounds box((-2, -2, -2), (2, 2, 2)) }\n");
    const Outcome frames = mpirun("render nan0.zs --frames 4 -o frame.png --threads 1");
    EXPECT_EQ(frames.status, 1) << frames.err;
    EXPECT_NE(frames.err.find("NaN"), std::string::npos) << frames.err;
    EXPECT_FALSE(fs::exists(dir_.path() / "frame_0000.png"));
}

TEST_F(DistributedCli, StandardOutputIsRefusedUnderMpirun) {
    const Outcome r = mpirun("render -q -o - --width 16 --height 16");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("under mpirun, write the image to a file"), std::string::npos) << r.err;
}

TEST_F(DistributedCli, AKilledRankEndsTheJobWithNoImage) {
    // Rank 1 kills itself with SIGKILL shortly after starting a long render.
    dir_.write("run.sh",
               "if [ \"$OMPI_COMM_WORLD_RANK\" = 1 ]; then (sleep 1; kill -9 $$) & fi\n"
               "exec '" ZEROSET_BINARY "' render --width 1600 --height 1200 --spp 16 -o out.png\n");
    const Outcome r = run_shell(launcher(2) + "sh run.sh");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("rank 1"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_.path() / "out.png"));
    for (const auto& entry : fs::directory_iterator(dir_.path()))
        EXPECT_EQ(entry.path().extension(), ".sh") << "left behind: " << entry.path();
}

#ifndef ZEROSET_MPIRUN
TEST_F(DistributedCli, WithoutMpiBuiltInAnMpiLaunchIsRefused) {
    const Outcome r = run_shell("OMPI_COMM_WORLD_SIZE=2 '" ZEROSET_BINARY "' render -o out.png");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("built without MPI"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_.path() / "out.png"));
}
#endif

}  // namespace
