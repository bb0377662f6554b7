// Every limit of the scene language (scene/scene_limits.hpp, and the live
// expression nodes of expr/expr.hpp) at its value and one past it: at the
// limit the scene parses, past it the error names the limit and the place.
// Small limits stand in for the defaults where reaching those would take
// seconds; the defaults themselves are tested where it is cheap.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_test_support.hpp"

namespace zeroset::test {
namespace {

std::string objects(int n) {
    std::string text;
    for (int i = 0; i < n; ++i) text += "object { surface x - " + std::to_string(i) + " }\n";
    return text;
}

TEST(SceneLimits, Objects) {
    SceneLimits limits;
    limits.objects = 5;
    EXPECT_EQ(error_of(objects(5), ".", limits), "");
    EXPECT_EQ(error_of(objects(6), ".", limits), "scene.zs:6:1: the scene makes more than 5 objects");
    // Loops and shapes count every object they make.
    EXPECT_EQ(error_of("for i from 1 to 5 { object { surface x - i } }", ".", limits), "");
    EXPECT_EQ(error_of("for i from 1 to 6 { object { surface x - i } }", ".", limits),
              "scene.zs:1:21: the scene makes more than 5 objects (in the loop at scene.zs:1:1 with i = 6)");
    // A shape placed again with the same arguments shares its objects; new
    // arguments make new ones.
    const std::string two = "shape two(a) { object { surface x - a } object { surface y - a } }\n";
    EXPECT_EQ(error_of(two + "instance two(1)  instance two(1)  instance two(1)  instance two(1)", ".", limits), "");
    EXPECT_EQ(error_of(two + "instance two(1)  instance two(2)  instance two(3)", ".", limits),
              "scene.zs:1:41: the scene makes more than 5 objects (in shape 'two' placed at scene.zs:2:44)");
    EXPECT_EQ(SceneLimits{}.objects, 1'000'000);
}

TEST(SceneLimits, LoopIterations) {
    SceneLimits limits;
    limits.loop_iterations = 12;
    EXPECT_EQ(error_of("for i from 1 to 12 { }", ".", limits), "");
    EXPECT_EQ(error_of("for i from 1 to 13 { }", ".", limits),
              "scene.zs:1:1: the scene's loops would run more than 12 times in all");
    EXPECT_EQ(error_of("for i from 1 to 1e9 { }", ".", limits), "scene.zs:1:1: the loop would run more than 12 times");
    EXPECT_EQ(error_of("for i from 1 to 3 { for j from 1 to 3 { } }", ".", limits), "");  // 3 + 3 × 3
    EXPECT_NE(error_of("for i from 1 to 4 { for j from 1 to 3 { } }", ".", limits).find("more than 12 times"),
              std::string::npos);
    // Past the default (reaching it takes seconds).
    EXPECT_EQ(error_of("for i from 0 to 10000000 { }"),
              "scene.zs:1:1: the scene's loops would run more than 10000000 times in all");
}

TEST(SceneLimits, BlockNesting) {
    const auto groups = [](int n) {
        std::string text;
        for (int i = 0; i < n; ++i) text += "group { ";
        text += "object { surface x }";
        for (int i = 0; i < n; ++i) text += " }";
        return text;
    };
    // The object's block is one level too.
    EXPECT_EQ(error_of(groups(199)), "");
    EXPECT_EQ(error_of(groups(200)), "scene.zs:1:1601: blocks nested too deeply (more than 200 levels)");
}

TEST(SceneLimits, ExpressionNesting) {
    const auto nested = [](int n) {
        return "object { surface " + std::string(static_cast<std::size_t>(n), '(') + "x" +
               std::string(static_cast<std::size_t>(n), ')') + " }";
    };
    EXPECT_EQ(error_of(nested(1000)), "");
    EXPECT_EQ(error_of(nested(1001)), "scene.zs:1:1018: expression nested too deeply (more than 1000 levels)");
    SceneLimits limits;
    limits.expression_nesting = 10;
    EXPECT_EQ(error_of(nested(10), ".", limits), "");
    EXPECT_EQ(error_of(nested(11), ".", limits), "scene.zs:1:28: expression nested too deeply (more than 10 levels)");
}

TEST(SceneLimits, IncludeDepth) {
    const TempDir dir;
    const auto chain = [&](const std::string& name, int files) {  // name0 includes name1 … up to name<files-1>
        for (int i = 0; i + 1 < files; ++i)
            dir.write(name + std::to_string(i) + ".zs", "include \"" + name + std::to_string(i + 1) + ".zs\"\n");
        dir.write(name + std::to_string(files - 1) + ".zs", "object { surface x }\n");
        return dir.path() / (name + "0.zs");
    };
    const auto error = [](const std::filesystem::path& file) {
        try {
            load_scene(file);
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(error(chain("a", 64)), "");
    EXPECT_NE(error(chain("b", 65)).find("b63.zs:1:1: includes nested too deeply (more than 64 files"),
              std::string::npos);
}

TEST(SceneLimits, LiveExpressionNodes) {
    // Each term of x + x·1 + x·2 + … is a new product and a new sum.
    const auto sum = [](int terms) {
        std::string text = "object { surface x";
        for (int i = 1; i < terms; ++i) text += " + x*" + std::to_string(i + 1);
        return text + " }";
    };
    const std::size_t live = live_expression_nodes();
    const std::size_t old = set_max_expression_nodes(live + 200);
    const std::string within = error_of(sum(40));  // about 120 new nodes, constants included
    const std::string past = error_of(sum(200));
    set_max_expression_nodes(old);
    EXPECT_EQ(within, "");
    EXPECT_NE(past.find("scene.zs:1:18: this expression is too large: the expressions have more than"),
              std::string::npos)
        << past;
    EXPECT_EQ(max_expression_nodes(), 4'000'000u);
}

}  // namespace
}  // namespace zeroset::test
