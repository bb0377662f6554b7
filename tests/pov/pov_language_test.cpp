// The POV-Ray importer's language: tokens and comments, expressions,
// colours, directives (#declare, #local, #if, #while, #for, #switch,
// #macro, #include), and errors located at file:line:column.
#include <fstream>

#include "pov/pov_test_support.hpp"
#include "support/temp_dir.hpp"
#include "zeroset/pov/pov_lexer.hpp"

namespace zeroset::pov::test {
namespace {

/// The radius of the scene's first object, a sphere written `sphere { 0, R }`
/// with R the expression under test: f(R, 0, 0) = 0.
double radius_of(const std::string& declarations, const std::string& r) {
    const PovImport imported = import(declarations + "\nsphere { 0, " + r + " }");
    const SceneNode& s = first_node(imported);
    // f = x² + y² + z² − R²: R² = −f(0, 0, 0).
    return std::sqrt(-value_at(s, 0, 0, 0));
}

TEST(PovLexer, CutsTokensAndSkipsNestedComments) {
    const auto tokens = tokenize_pov("#declare A = <1, .5, 2e1>; // rest\n/* a /* nested */ comment */ \"s\\\"q\" <= !=", "t.pov");
    ASSERT_EQ(tokens.size(), 15U);
    EXPECT_EQ(tokens[0].kind, PovTokenKind::Directive);
    EXPECT_EQ(tokens[0].text, "declare");
    EXPECT_EQ(tokens[6].number, 0.5);
    EXPECT_EQ(tokens[8].number, 20.0);
    EXPECT_EQ(tokens[11].kind, PovTokenKind::String);
    EXPECT_EQ(tokens[11].text, "s\"q");
    EXPECT_EQ(tokens[11].where.line, 2);
    EXPECT_EQ(tokens[12].text, "<=");
    EXPECT_EQ(tokens[13].text, "!=");
    EXPECT_EQ(tokens[14].kind, PovTokenKind::End);
    EXPECT_THROW(tokenize_pov("/* never closed", "t.pov"), SceneError);
    try {
        tokenize_pov("sphere {\n  0, 1 ` }", "t.pov");
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "t.pov:2:8: unexpected character '`'");
    }
}

TEST(PovExpressions, NumbersVectorsAndBuiltIns) {
    EXPECT_DOUBLE_EQ(radius_of("", "1 + 2 * 3 - 4 / 2"), 5.0);
    EXPECT_DOUBLE_EQ(radius_of("#declare V = <3, 4, 0>;", "vlength(V)"), 5.0);
    EXPECT_DOUBLE_EQ(radius_of("#declare V = <1, 2, 3> * 2;", "V.z + V.x"), 8.0);
    EXPECT_DOUBLE_EQ(radius_of("", "(2 > 1) ? 3 : 4"), 3.0);
    EXPECT_DOUBLE_EQ(radius_of("", "select(-1, 2, 3)"), 2.0);
    EXPECT_DOUBLE_EQ(radius_of("", "max(1, 7, 3) - min(4, 2)"), 5.0);
    EXPECT_DOUBLE_EQ(radius_of("", "log(100) + ln(exp(1))"), 3.0);  // log is base 10
    EXPECT_DOUBLE_EQ(radius_of("", "int(-2.7) + 5"), 3.0);          // int truncates
    EXPECT_NEAR(radius_of("", "degrees(pi / 2)"), 90.0, 1e-12);
    EXPECT_DOUBLE_EQ(radius_of("", "image_width / image_height * 3"), 4.0);
    EXPECT_DOUBLE_EQ(radius_of("", "strlen(concat(\"ab\", str(12, 0, 0)))"), 4.0);
    EXPECT_NEAR(radius_of("", "vrotate(x, <0, 0, 90>).y"), 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(radius_of("", "(1 = 1) + (1 != 1) + (true & !false) + (0 | off)"), 2.0);
    // '<' compares, unless a vector follows with its comma left out before it.
    EXPECT_DOUBLE_EQ(radius_of("#declare A = (1 < 2) + select(1 < 2, 0, 1) + (2 < 1);", "A + 1"), 3.0);
    // A colour's components: rgb, then overrides.
    EXPECT_DOUBLE_EQ(radius_of("#declare C = color rgb <0.25, 0.5, 1> blue 0.75 transmit 0.5;", "C.blue + C.transmit"), 1.25);
    EXPECT_DOUBLE_EQ(radius_of("#declare C = color red 1 green 0.5;", "C.red + C.green + C.blue"), 1.5);
    EXPECT_DOUBLE_EQ(radius_of("#declare C = rgbf 0.5;", "C.filter * 4"), 2.0);
}

TEST(PovDirectives, DeclareLocalIfWhileFor) {
    EXPECT_DOUBLE_EQ(radius_of("#declare A = 1;\n#if (A > 0) #declare A = 2; #else #declare A = 3; #end", "A"), 2.0);
    EXPECT_DOUBLE_EQ(radius_of("#declare A = 0;\n#if (A) #declare B = 1; #elseif (A = 0) #declare B = 5; #else #declare B = 9; #end", "B"), 5.0);
    EXPECT_DOUBLE_EQ(radius_of("#ifdef(Nothing) #declare B = 1; #else #declare B = 2; #end #ifndef(B) #declare B = 7; #end", "B"), 2.0);
    EXPECT_DOUBLE_EQ(radius_of("#declare S = 0; #declare I = 1;\n#while (I <= 4) #declare S = S + I; #declare I = I + 1; #end", "S"), 10.0);
    EXPECT_DOUBLE_EQ(radius_of("#declare S = 0;\n#for (I, 1, 9, 2) #declare S = S + I; #end", "S"), 25.0);
    EXPECT_DOUBLE_EQ(radius_of("#declare S = 0;\n#for (I, 3, 1, -1) #if (I = 2) #break #end #declare S = S + I; #end", "S"), 3.0);
    EXPECT_DOUBLE_EQ(radius_of("#switch (3) #case (1) #declare R = 1; #break #range (2, 4) #declare R = 6; #break #else #declare R = 9; #end", "R"), 6.0);
    EXPECT_DOUBLE_EQ(radius_of("#switch (8) #case (1) #declare R = 1; #break #else #declare R = 9; #end", "R"), 9.0);
    // #local inside a macro stays there; #declare reaches the globals.
    EXPECT_DOUBLE_EQ(radius_of("#declare G = 1;\n#macro M(P) #local G = 100; #declare H = P + G; #end\nM(2)", "H + G"), 103.0);
    // A macro's body is spliced in where it is called: one that leaves a value returns it.
    EXPECT_DOUBLE_EQ(radius_of("#macro Twice(V) (2 * (V)) #end", "Twice(1 + 1) + 1"), 5.0);
    // #undef forgets a name.
    EXPECT_EQ(error_of("#declare A = 1; #undef A\nsphere { 0, A }"),
              "scene.pov:2:13: unknown name 'A' (not declared, and not a built-in value or function)");
}

TEST(PovDirectives, IncludesAreSearchedBesideTheSceneThenOnTheIncludePath) {
    const zeroset::test::TempDir dir;
    std::filesystem::create_directories(dir.path() / "more");
    std::ofstream(dir.path() / "near.inc") << "#declare Near = 2;\n";
    std::ofstream(dir.path() / "more" / "far.inc") << "#declare Far = 3;\n";
    std::ofstream(dir.path() / "scene.pov") << "#include \"near.inc\"\n#include \"far.inc\"\nsphere { 0, Near + Far }\n";
    PovOptions options;
    options.include_paths = {dir.path() / "more"};
    const PovImport imported = read_pov_scene(dir.path() / "scene.pov", options);
    EXPECT_DOUBLE_EQ(value_at(first_node(imported), 5, 0, 0), 0.0);
    std::ofstream(dir.path() / "bad.pov") << "#include \"nowhere.inc\"\n";
    try {
        read_pov_scene(dir.path() / "bad.pov", options);
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.pov:1:1: cannot find the include file \"nowhere.inc\""), std::string::npos)
            << e.what();
    }
}

TEST(PovDirectives, ErrorsAreLocated) {
    EXPECT_EQ(error_of("#if (1)\nsphere { 0, 1 }\n"), "scene.pov:3:1: a #if is not closed by an #end");
    EXPECT_EQ(error_of("#end"), "scene.pov:1:1: #end without an open block");
    EXPECT_EQ(error_of("#error \"stop here\""), "scene.pov:1:1: #error: stop here");
    EXPECT_EQ(error_of("#declare A = ;"), "scene.pov:1:14: expected a value but found ';'");
    EXPECT_EQ(error_of("#fopen F \"x\" read"), "scene.pov:1:1: #fopen is not supported (file input and output, arrays of directives, …)");
    EXPECT_EQ(error_of("#declare S = 0; #while (1) #declare S = S + 1; #end"),
              "scene.pov:1:48: the scene's loops ran more than 1000 times");
    EXPECT_EQ(error_of("#macro M(A) M(A) #end M(1)"), "scene.pov:1:13: macros call each other more than 200 deep");
    EXPECT_EQ(error_of("sphere { <0, 0, 0>, 1 } frobnicate"), "scene.pov:1:25: unknown statement 'frobnicate'");
    EXPECT_EQ(error_of("sphere { 0, 1 glow 1 }"), "scene.pov:1:15: unknown object modifier 'glow' in sphere");
    // Nesting is bounded: the parser recurses.
    EXPECT_EQ(error_of("#declare A = " + std::string(300, '(') + "1" + std::string(300, ')') + ";"),
              "scene.pov:1:214: expressions or objects nested more than 200 deep");
    std::string unions;
    for (int i = 0; i < 300; ++i) unions += "union { ";
    EXPECT_NE(error_of(unions).find("nested more than 200 deep"), std::string::npos);
    // A call in a call's arguments, however it is reached (found by the fuzzer: a stack overflow).
    std::string calls = "#macro B(P) sphere { P, 1 } #end\nobject { ";
    for (int i = 0; i < 3000; ++i) calls += "B(";
    EXPECT_EQ(error_of(calls), "scene.pov:2:408: macro calls nested in their arguments more than 200 deep");
    // A #declare whose value begins with another #declare (found by the fuzzer: a stack overflow).
    std::string declares;
    for (int i = 0; i < 3000; ++i) declares += "#declare a ";
    EXPECT_NE(error_of(declares).find("directives nested more than 200 deep"), std::string::npos);
    // Directives count apart from expressions: a macro recursing 90 deep
    // through #local values still reads (POV-Ray allows about 100).
    const std::string recursion =
        "#macro T(N) #if (N > 0) #local O = union { sphere { 0, 1 } object { T(N - 1) translate y } } #else "
        "#local O = sphere { 0, 1 } #end O #end\nobject { T(90) }";
    EXPECT_EQ(error_of(recursion), "");
}

TEST(PovDirectives, UnusedDeclarationsSayNothingUsedOnesWarn) {
    const std::string texture = "#declare T = texture { pigment { checker color rgb 1 color rgb 0 } finish { metallic } }\n";
    const PovImport unused = import(texture + "light_source { <1, 2, 3> color rgb 1 } sphere { 0, 1 } global_settings { assumed_gamma 1 }");
    EXPECT_TRUE(unused.scene.warnings.empty()) << unused.scene.warnings.front();
    const PovImport used = import(texture + "light_source { <1, 2, 3> color rgb 1 } sphere { 0, 1 texture { T } }");
    EXPECT_TRUE(warned(used, "scene.pov:1:34: the pigment pattern 'checker' is not supported; rendered as its first colour, rgb <1, 1, 1>"));
    EXPECT_TRUE(warned(used, "the finish's metallic is not supported; left out"));
    // No assumed_gamma: POV-Ray leaves gamma alone, zeroset cannot.
    EXPECT_TRUE(warned(used, "scene.pov:1:1: no assumed_gamma"));
}

TEST(PovDirectives, SwitchCasesRunOnUntilABreak) {
    EXPECT_DOUBLE_EQ(radius_of("#declare R = 0; #switch (1) #case (1) #declare R = R + 1; #case (2) #declare R = R + 10; "
                               "#break #case (3) #declare R = R + 100; #end",
                               "R"),
                     11.0);
    EXPECT_DOUBLE_EQ(radius_of("#declare R = 0; #switch (5) #case (1) #declare R = 1; #else #declare R = R + 2; #end", "R"), 2.0);
}

TEST(PovDirectives, FunctionsKeepTheValuesOfWhereTheyAreDefined) {
    EXPECT_DOUBLE_EQ(radius_of("#declare R = 0.8; #declare F = function { R + x } #declare R = 0.3;", "F(0, 0, 0)"), 0.8);
    // A macro's parameter, gone when the function is called.
    EXPECT_DOUBLE_EQ(radius_of("#macro Shifted(S) function { x + S } #end #declare G = Shifted(2);", "G(1, 0, 0)"), 3.0);
    // Commas may be left out in vectors.
    EXPECT_DOUBLE_EQ(radius_of("#declare V = <3 4 0>;", "vlength(V)"), 5.0);
}

}  // namespace
}  // namespace zeroset::pov::test
