// include and model(): paths relative to the including file, shared names,
// each file read once, cycles, missing files, and .vm import errors located
// inside the .vm file. Files are written to a fresh temporary directory.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include "support/models.hpp"
#include <sys/stat.h>

#include <fstream>

#include "scene_test_support.hpp"
#include "zeroset/scene/file_text.hpp"

namespace zeroset {
namespace {

using test::TempDir;

std::string load_error(const std::filesystem::path& file) {
    try {
        load_scene(file);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

TEST(Include, IncludedFileSharesNamesAndAddsItsStatements) {
    const TempDir dir;
    dir.write("lib/shapes.zs", "let ball = x^2 + y^2 + z^2 - r^2\nlight { from (0, 5, 0) }\n");
    const auto main = dir.write("main.zs", "let r = 2\ninclude \"lib/shapes.zs\"\nobject { surface ball }\n");
    const Scene s = load_scene(main);
    ASSERT_EQ(s.lights.size(), 1U);
    ASSERT_EQ(placed_objects(s).size(), 1U);
    const Tape tape(placed_objects(s).at(0).object().surface);
    Evaluator<double> eval(tape);
    EXPECT_DOUBLE_EQ(eval(1, 1, 1), 3.0 - 4.0);  // r from the includer, ball from the included file
}

TEST(Include, PathsAreRelativeToTheIncludingFile) {
    const TempDir dir;
    dir.write("a/b/inner.zs", "let k = 7\n");
    dir.write("a/outer.zs", "include \"b/inner.zs\"\n");
    const auto main = dir.write("main.zs", "include \"a/outer.zs\"\ncamera { fov k }\n");
    EXPECT_EQ(load_scene(main).camera.fov_degrees, 7.0);
    // parse_scene takes the base directory explicitly.
    EXPECT_EQ(parse_scene("include \"outer.zs\"\ncamera { fov k }", "text", dir.path() / "a").camera.fov_degrees, 7.0);
}

TEST(Include, EachFileIsReadOncePerScene) {
    const TempDir dir;
    dir.write("common.zs", "let unit = 1\nlight { from (0, 9, 0) }\n");
    dir.write("left.zs", "include \"common.zs\"\n");
    dir.write("right.zs", "include \"./common.zs\"\n");
    const auto main = dir.write("main.zs", "include \"left.zs\"\ninclude \"right.zs\"\ninclude \"common.zs\"\n");
    EXPECT_EQ(load_scene(main).lights.size(), 1U);
}

TEST(Include, ErrorsInsideAnIncludedFileNameThatFile) {
    const TempDir dir;
    dir.write("sub/bad.zs", "let a = 1\nlet b = a + q\n");
    const auto main = dir.write("main.zs", "include \"sub/bad.zs\"\n");
    EXPECT_EQ(load_error(main), (dir.path() / "sub/bad.zs").string() + ":2:13: unknown identifier 'q'");
}

TEST(Include, MissingFileIsReportedAtTheIncludeStatement) {
    const TempDir dir;
    const auto main = dir.write("main.zs", "let a = 1\n  include \"nope.zs\"\n");
    EXPECT_EQ(load_error(main), main.string() + ":2:3: cannot open included file '" +
                                    (dir.path() / "nope.zs").string() + "': no such file or directory");
    EXPECT_EQ(test::error_of("include 42"), "scene.zs:1:9: expected a string in quotes but found '42'");
}

TEST(Include, CyclesAreErrors) {
    const TempDir dir;
    const auto a = dir.write("a.zs", "include \"b.zs\"\n");
    const auto b = dir.write("b.zs", "\ninclude \"a.zs\"\n");
    EXPECT_EQ(load_error(a), b.string() + ":2:1: include cycle: " + a.string() + " -> " + b.string() + " -> " +
                                 a.string());
    const auto self = dir.write("self.zs", "include \"self.zs\"\n");
    EXPECT_EQ(load_error(self), self.string() + ":1:1: include cycle: " + self.string() + " -> " + self.string());
}

TEST(LoadScene, MissingOrUnreadableFile) {
    const TempDir dir;
    try {
        load_scene(dir.path() / "missing.zs");
        FAIL() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  (dir.path() / "missing.zs").string() + ": cannot open the scene file: no such file or directory");
        EXPECT_EQ(e.line(), 0);
        EXPECT_EQ(e.file(), (dir.path() / "missing.zs").string());
    }
    EXPECT_EQ(load_error(dir.path()), dir.path().string() + ": cannot open the scene file: it is a directory");
}

TEST(LoadScene, ErrorCarriesItsParts) {
    const TempDir dir;
    const auto file = dir.write("s.zs", "\n\ncamera { fov 500 }");
    try {
        load_scene(file);
        FAIL() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.file(), file.string());
        EXPECT_EQ(e.line(), 3);
        EXPECT_EQ(e.column(), 14);
        EXPECT_EQ(e.message(), "fov must be between 0 and 180 degrees, but it is 500");
    }
}

TEST(Model, ImportsTheBear) {
    ZEROSET_SKIP_WITHOUT_MODEL("bear.vm");

    const Scene s = parse_scene("object { surface model(\"" ZEROSET_MODELS_DIR "/bear.vm\") }", "scene.zs", ".");
    const Expr bear = placed_objects(s).at(0).object().surface;
    EXPECT_GT(bear.node_count(), 100U);
    const Tape tape(bear);
    Evaluator<double> eval(tape);
    EXPECT_LT(eval(0.1, 0.1, 0), 0.0);  // inside the head
    EXPECT_GT(eval(3, 3, 3), 0.0);      // far outside
}

TEST(Model, PathIsRelativeToTheSceneAndModelsComposeWithExpressions) {
    const TempDir dir;
    dir.write("models/ball.vm", "# a unit ball\nx var-x\ny var-y\nz var-z\nx2 square x\ny2 square y\nz2 square z\n"
                                "s add x2 y2\nt add s z2\none const 1\nout sub t one\n");
    const auto main = dir.write("scenes/main.zs", "let m = model(\"../models/ball.vm\")\nobject { surface min(m, model(\"../models/ball.vm\") + 1) }\n");
    const Scene s = load_scene(main);
    const Tape tape(placed_objects(s).at(0).object().surface);
    Evaluator<double> eval(tape);
    EXPECT_DOUBLE_EQ(eval(2, 0, 0), 3.0);
}

TEST(Model, MalformedModelReportsItsOwnLineAndColumn) {
    const TempDir dir;
    const auto vm = dir.write("bad.vm", "x var-x\ny var-y\nz frobnicate x y\n");
    const auto main = dir.write("main.zs", "object { surface model(\"bad.vm\") }\n");
    EXPECT_EQ(load_error(main), vm.string() + ":3:3: unknown opcode `frobnicate`");
}

TEST(Model, MissingModelIsReportedAtTheCall) {
    const TempDir dir;
    const auto main = dir.write("main.zs", "object {\n  surface 1 + model(\"gone.vm\") }\n");
    EXPECT_EQ(load_error(main), main.string() + ":2:15: cannot open model '" + (dir.path() / "gone.vm").string() +
                                    "': no such file or directory");
    EXPECT_EQ(test::error_of("object { surface model(bear) }"),
              "scene.zs:1:24: expected a file name in quotes, as in model(\"bear.vm\"), but found 'bear'");
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

TEST(Include, OnlyRegularFilesOfBoundedSizeAreRead) {
    const TempDir dir;
    const auto fifo = dir.path() / "pipe.zs";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto main = dir.write("main.zs", "include \"pipe.zs\"\n");
    EXPECT_EQ(load_error(main), main.string() + ":1:1: cannot open included file '" + fifo.string() +
                                    "': it is a FIFO (a named pipe), not a regular file");
    const auto zero = dir.write("zero.zs", "object { surface model(\"/dev/zero\") }\n");
    EXPECT_EQ(load_error(zero), zero.string() + ":1:18: cannot open model '/dev/zero': it is a device, not a regular file");
    const auto huge = dir.path() / "huge.zs";
    { std::ofstream touch(huge); }
    std::filesystem::resize_file(huge, max_text_file_bytes + 1);  // sparse: costs no disk
    EXPECT_EQ(load_error(huge), huge.string() + ": cannot open the scene file: it is larger than 256 MiB, the most a "
                                                "scene, include, model or ray list may be");
}

TEST(Include, NestingIsBounded) {
    const TempDir dir;
    for (int i = 0; i < 70; ++i)
        dir.write("f" + std::to_string(i) + ".zs", "include \"f" + std::to_string(i + 1) + ".zs\"\n");
    dir.write("f70.zs", "object { surface x }\n");
    const std::string error = load_error(dir.path() / "f0.zs");
    EXPECT_NE(error.find("f63.zs:1:1: includes nested too deeply (more than 64 files"), std::string::npos) << error;
    // A long chain read one after another is no nesting at all.
    std::string flat;
    for (int i = 0; i < 200; ++i) flat += "include \"g" + std::to_string(i) + ".zs\"\n";
    for (int i = 0; i < 200; ++i) dir.write("g" + std::to_string(i) + ".zs", "let g" + std::to_string(i) + " = 1\n");
    EXPECT_EQ(load_error(dir.write("flat.zs", flat)), "");
}

}  // namespace
}  // namespace zeroset
