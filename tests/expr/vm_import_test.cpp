// import_vm: the real models load and evaluate; malformed input reports the
// right line and column.
#include "zeroset/expr/vm_import.hpp"

#include <gtest/gtest.h>
#include "support/models.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "zeroset/expr/batch_evaluator.hpp"
#include "zeroset/expr/evaluator.hpp"

namespace zeroset {
namespace {

Expr load(const std::string& name) {
    std::ifstream in(std::string(ZEROSET_MODELS_DIR) + "/" + name);
    EXPECT_TRUE(in.good()) << "cannot open " << name;
    return import_vm(in);
}

Expr parse(const std::string& text) {
    std::istringstream in(text);
    return import_vm(in);
}

TEST(VmImport, RealModelsLoadAndEvaluate) {
    ZEROSET_SKIP_WITHOUT_MODEL("bear.vm");
    ZEROSET_SKIP_WITHOUT_MODEL("prospero.vm");

    for (const char* name : {"bear.vm", "prospero.vm"}) {
        SCOPED_TRACE(name);
        const Expr model = load(name);
        const Tape tape(model);
        EXPECT_GT(tape.clauses().size(), 300u);
        Evaluator<double> eval(tape);
        Evaluator<Interval> eval_i(tape);
        for (const Vec3d p : {Vec3d{0, 0, 0}, Vec3d{0.1, -0.2, 0.3}, Vec3d{-0.9, 0.8, 0.05}, Vec3d{0.5, 0.5, -0.5}}) {
            const double v = eval(p.x, p.y, p.z);
            EXPECT_TRUE(std::isfinite(v)) << "at " << p.x << ", " << p.y << ", " << p.z;
            // And the interval evaluation over a small box around p contains it.
            const Interval box =
                evaluate_box(eval_i, {p.x - 0.01, p.y - 0.01, p.z - 0.01}, {p.x + 0.01, p.y + 0.01, p.z + 0.01});
            EXPECT_LE(box.lo, v);
            EXPECT_GE(box.hi, v);
        }
        // The batch evaluators agree on a grid (slots are heavily reused here).
        std::vector<double> x, y, z;
        for (int i = 0; i < 300; ++i) {
            x.push_back(-1.0 + 2.0 * (i % 17) / 16.0);
            y.push_back(-1.0 + 2.0 * (i % 13) / 12.0);
            z.push_back(-0.5 + (i % 7) / 6.0);
        }
        std::vector<double> out(x.size());
        std::vector<float> xf(x.begin(), x.end()), yf(y.begin(), y.end()), zf(z.begin(), z.end()), out_f(x.size());
        BatchEvaluator<double>(tape).evaluate(x, y, z, out);
        BatchEvaluator<float>(tape).evaluate(xf, yf, zf, out_f);
        Evaluator<float> eval_f(tape);
        // Not bit for bit: the batch's exp and log are vector functions a few
        // ulps from glibc's (expr/batch_lanes.hpp).
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double expected = eval(x[i], y[i], z[i]);
            ASSERT_NEAR(out[i], expected, 1e-12 * (1.0 + std::abs(expected))) << "point " << i;
            const float expected_f = eval_f(xf[i], yf[i], zf[i]);
            ASSERT_NEAR(out_f[i], expected_f, 1e-5f * (1.0f + std::abs(expected_f))) << "point " << i;
        }
    }
}

TEST(VmImport, ProsperoHasInkAndPaper) {
    ZEROSET_SKIP_WITHOUT_MODEL("prospero.vm");

    // The text model is negative on the letters and positive between them.
    const Tape tape(load("prospero.vm"));
    Evaluator<double> eval(tape);
    int inside = 0, outside = 0;
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j) {
            const double v = eval(-1.0 + 2.0 * i / 63.0, -1.0 + 2.0 * j / 63.0, 0.0);
            ASSERT_TRUE(std::isfinite(v));
            (v < 0 ? inside : outside) += 1;
        }
    EXPECT_GT(inside, 64);
    EXPECT_GT(outside, 64);
}

TEST(VmImport, SyntaxAndOps) {
    const Expr f = parse(
        "# a comment line\n"
        "\n"
        "_x var-x   # trailing comment\n"
        "_y\tvar-y\r\n"
        "_c const -2.5e-1\n"
        "_a add _x _c\n"
        "_r recip _a\n"
        "_k copy _r\n"
        "_m mul _k _y\n");
    const Tape tape_f(f);
    Evaluator<double> eval(tape_f);
    EXPECT_DOUBLE_EQ(eval(2.25, 3.0, 0.0), 1.5);  // y / (x − 0.25)
    // Every op of the table with a .vm name and operands can be read.
    const Expr g = parse(
        "x var-x\ny var-y\nz var-z\n"
        "a sub x y\nb div a z\nc neg b\nd square c\ne sqrt d\nf abs e\ng exp f\nh ln g\n"
        "i sin h\nj cos i\nk min j x\nl max k y\nm pow l z\n");
    Tape tape(g);
    Evaluator<double> e(tape);
    const double x = 0.3, y = 0.2, z = 2.0;
    const double b = (x - y) / z;
    const double h = std::log(std::exp(std::abs(std::sqrt(b * b))));
    const double expected = std::pow(std::max(std::min(std::cos(std::sin(h)), x), y), z);
    EXPECT_DOUBLE_EQ(e(x, y, z), expected);
}

/// The error import_vm reports for `text`.
VmImportError error_for(const std::string& text) {
    try {
        parse(text);
    } catch (const VmImportError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return {0, 0, ""};
}

TEST(VmImport, UnknownOpcode) {
    const VmImportError e = error_for("_0 var-x\n_1 frobnicate _0\n");
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 4);
    EXPECT_NE(std::string(e.what()).find("frobnicate"), std::string::npos) << e.what();
    // powi has no operand for its exponent in .vm: not an opcode there.
    EXPECT_EQ(error_for("_0 var-x\n\n_1 powi _0\n").line(), 3);
}

TEST(VmImport, UnknownOperand) {
    const VmImportError e = error_for("_0 var-x\n# note\n_1 add _0 _9\n");
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.column(), 11);
    EXPECT_NE(std::string(e.what()).find("_9"), std::string::npos) << e.what();
    // With two unknown operands, the first one is reported.
    const VmImportError both = error_for("_0 var-x\n_1 max _8 _9\n");
    EXPECT_EQ(both.column(), 8);
    EXPECT_NE(std::string(both.what()).find("_8"), std::string::npos) << both.what();
    // A value used before it is defined is unknown at that point.
    const VmImportError later = error_for("_0 var-x\n_1 neg _2\n_2 var-y\n");
    EXPECT_EQ(later.line(), 2);
    EXPECT_EQ(later.column(), 8);
}

TEST(VmImport, WrongOperandCount) {
    const VmImportError too_many = error_for("_0 var-x\n  _1 neg _0 _0\n");
    EXPECT_EQ(too_many.line(), 2);
    EXPECT_EQ(too_many.column(), 6);
    const VmImportError too_few = error_for("_0 var-x\n_1 mul _0\n");
    EXPECT_EQ(too_few.line(), 2);
    EXPECT_EQ(too_few.column(), 4);
    EXPECT_EQ(error_for("_0 var-x 3\n").line(), 1);
    EXPECT_EQ(error_for("_0 const\n").line(), 1);
    const VmImportError lonely = error_for("_0 var-x\n   _1\n");
    EXPECT_EQ(lonely.line(), 2);
    EXPECT_EQ(lonely.column(), 4);
}

TEST(VmImport, MalformedConst) {
    for (const char* bad : {"1.2.3", "abc", "1e", "0x1p3q", "--1"}) {
        const VmImportError e = error_for(std::string("_x var-x\n\n\t_c const ") + bad + "\n_y add _x _c\n");
        EXPECT_EQ(e.line(), 3) << bad;
        EXPECT_EQ(e.column(), 11) << bad;
        EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
}

TEST(VmImport, EmptyModel) {
    EXPECT_THROW(parse(""), VmImportError);
    EXPECT_THROW(parse("# only a comment\n\n"), VmImportError);
}

TEST(VmImport, LastClauseIsTheOutput) {
    const Expr f = parse("a var-x\nb var-y\nc add a b\nd mul a b\n");
    const Tape tape(f);
    Evaluator<double> eval(tape);
    EXPECT_EQ(eval(3, 4, 0), 12.0);
}

// fidget's trigonometry, rounding and remainder opcodes: those of the op
// table by name, the others built from ops with fidget's meaning (round half
// away from 0, mod as Rust's rem_euclid, in [0, |b|)).
TEST(VmImport, FidgetRoundingAndTrigonometry) {
    const auto at = [&](const std::string& name, double x, double y) {
        const Expr g = parse("x var-x\ny var-y\n" + std::string("o ") + name + "\n");
        const Tape tape(g);
        Evaluator<double> eval(tape);
        return eval(x, y, 0.0);
    };
    for (const double x : {-2.5, -1.5, -0.5, -0.3, 0.0, 0.49, 0.5, 1.5, 2.7}) {
        for (const double y : {-0.75, 0.4, 3.0}) {
            EXPECT_DOUBLE_EQ(at("tan x", x, y), std::tan(x));
            EXPECT_DOUBLE_EQ(at("atan y", x, y), std::atan(y));
            EXPECT_DOUBLE_EQ(at("atan2 y x", x, y), std::atan2(y, x));
            EXPECT_EQ(at("floor x", x, y), std::floor(x));
            EXPECT_EQ(at("ceil x", x, y), std::ceil(x));
            EXPECT_EQ(at("round x", x, y), std::round(x)) << x;  // C's round: half away from 0, as Rust's
            const double rem = std::fmod(x, y) < 0 ? std::fmod(x, y) + std::abs(y) : std::fmod(x, y);
            EXPECT_NEAR(at("mod x y", x, y), rem, 1e-15) << x << " mod " << y;
            if (std::abs(y) <= 1) {
                EXPECT_NEAR(at("asin y", x, y), std::asin(y), 1e-15);
                EXPECT_NEAR(at("acos y", x, y), std::acos(y), 1e-15);
            } else {
                EXPECT_TRUE(std::isnan(at("asin y", x, y)));
            }
        }
    }
    // fidget's other opcodes have no meaning here: still unknown.
    for (const char* opcode : {"compare x y", "and x y", "or x y", "not x", "mix x y", "rand x"}) {
        const std::string message = error_for("x var-x\ny var-y\no " + std::string(opcode) + "\n").what();
        EXPECT_NE(message.find("unknown opcode"), std::string::npos) << opcode;
    }
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

TEST(VmImport, ConstantsMustBeFiniteAndNamesDefinedOnce) {
    for (const char* bad : {"nan", "inf", "-inf", "1e999"}) {
        const VmImportError e = error_for(std::string("_0 var-x\n_1 const ") + bad + "\n_2 add _0 _1\n");
        EXPECT_EQ(e.line(), 2) << bad;
        EXPECT_EQ(e.column(), 10) << bad;
    }
    const VmImportError twice = error_for("_0 var-x\n_1 const 2\n_0 mul _0 _1\n");
    EXPECT_EQ(twice.line(), 3);
    EXPECT_EQ(twice.column(), 1);
    EXPECT_NE(std::string(twice.what()).find("already defined (line 1)"), std::string::npos) << twice.what();
}

TEST(VmImport, AnyLineEndingWorks) {
    for (const char* end : {"\n", "\r\n", "\r"}) {
        const std::string text = std::string("_0 var-x") + end + "_1 const 2" + end + "_2 mul _0 _1" + end;
        const Tape tape(parse(text));
        Evaluator<double> f(tape);
        EXPECT_EQ(f(3.0, 0.0, 0.0), 6.0);
    }
    // A file whose last line has no ending at all.
    const Tape tape(parse("_0 var-x\r_1 neg _0"));
    Evaluator<double> f(tape);
    EXPECT_EQ(f(3.0, 0.0, 0.0), -3.0);
}

}  // namespace
}  // namespace zeroset
