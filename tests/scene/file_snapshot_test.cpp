// File snapshots: a scene loaded while recording loads again, the same, from
// the snapshot alone once its files are gone (how the ranks of a distributed
// render read what rank 0 sent); a file the snapshot lacks cannot be read;
// damaged bytes are refused.
#include <gtest/gtest.h>

#include <filesystem>

#include "scene_test_support.hpp"
#include "zeroset/pov/pov_import.hpp"
#include "zeroset/scene/file_snapshot.hpp"
#include "zeroset/scene/file_text.hpp"
#include "zeroset/scene/scene_writer.hpp"

namespace zeroset {
namespace {

using test::TempDir;

/// The scene written back as text: equal texts, equal scenes.
std::string scene_text(const Scene& scene) { return write_scene(scene); }

TEST(FileSnapshot, AZerosetSceneLoadsFromTheSnapshotAloneOnceItsFilesAreGone) {
    std::string expected;
    std::string bytes;
    std::filesystem::path main;
    {
        const TempDir dir;
        dir.write("lib/shapes.zs", "let ball = x^2 + y^2 + z^2 - 1\nlight { from (0, 5, 0) }\n");
        dir.write("models/ring.vm", "_0 var-x\n_1 var-y\n_2 mul _0 _0\n_3 mul _1 _1\n_4 add _2 _3\n_5 const 1\n_6 sub _4 _5\n");
        main = dir.write("main.zs",
                         "include \"lib/shapes.zs\"\n"
                         "object { surface min(ball, model(\"models/ring.vm\"))  bounds box((-2,-2,-2), (2,2,2)) }\n");
        FileSnapshot recorded;
        {
            const FileRecording recording(recorded);
            expected = scene_text(load_scene(main));
        }
        EXPECT_EQ(recorded.texts.size(), 3U);
        bytes = recorded.pack();
    }  // the directory and its files are gone
    ASSERT_FALSE(std::filesystem::exists(main));
    const FileSnapshot sent = FileSnapshot::unpack(bytes);
    const FileReplay replay(sent);
    EXPECT_EQ(scene_text(load_scene(main)), expected);
}

TEST(FileSnapshot, APovRaySceneFindsItsIncludesInTheSnapshot) {
    std::string expected;
    FileSnapshot recorded;
    std::filesystem::path main;
    {
        const TempDir dir;
        dir.write("inc/size.inc", "#declare R = 0.75;\n");
        main = dir.write("scene.pov",
                         "#include \"size.inc\"\n"
                         "#if (file_exists(\"inc/size.inc\")) sphere { 0, R } #else sphere { 0, 2 } #end\n");
        pov::PovOptions options;
        options.include_paths = {(dir.path() / "inc").string()};
        const FileRecording recording(recorded);
        expected = scene_text(pov::read_pov_scene(main, options).scene);
    }
    const FileReplay replay(recorded);
    pov::PovOptions options;
    options.include_paths = {(main.parent_path() / "inc").string()};
    EXPECT_EQ(scene_text(pov::read_pov_scene(main, options).scene), expected);
    EXPECT_NE(expected.find("- 0.5625"), std::string::npos) << expected;  // R² from the include
}

TEST(FileSnapshot, AFileTheSnapshotLacksCannotBeRead) {
    const FileSnapshot empty;
    const FileReplay replay(empty);
    try {
        (void)read_text_file("/etc/hostname");
        ADD_FAILURE() << "read a file that was not sent";
    } catch (const FileReadError& e) {
        EXPECT_STREQ(e.what(), "it is not among the files rank 0 sent");
    }
    EXPECT_FALSE(regular_file_exists("/etc/hostname"));
}

TEST(FileSnapshot, DamagedBytesAreRefused) {
    FileSnapshot s;
    s.texts["a.zs"] = "camera { fov 30 }\n";
    s.regular["b.inc"] = true;
    s.canonical["./a.zs"] = "a.zs";
    const std::string bytes = s.pack();
    const FileSnapshot back = FileSnapshot::unpack(bytes);
    EXPECT_EQ(back.texts, s.texts);
    EXPECT_EQ(back.regular, s.regular);
    EXPECT_EQ(back.canonical, s.canonical);
    EXPECT_THROW((void)FileSnapshot::unpack(bytes.substr(0, bytes.size() - 1)), std::runtime_error);
    EXPECT_THROW((void)FileSnapshot::unpack(bytes + "x"), std::runtime_error);
}

}  // namespace
}  // namespace zeroset
