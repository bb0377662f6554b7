// `zeroset ray` as a user meets it: the survey's ray on the default scene
// gives the blend's four roots from every guaranteed method, as a table and
// as JSON that a real JSON parser (Python's) accepts, one line per ray with
// --rays; --plot writes an SVG; bad input fails with a clear message, a
// non-zero exit and no file.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_test.hpp"
#include "zeroset/io/image_reader.hpp"

namespace fs = std::filesystem;

namespace {

using zeroset::test::Outcome;
using zeroset::test::read_text;

/// One method's entry of a JSON report, as Python read it.
struct MethodEntry {
    std::string resolved, status, first_hit;
    std::vector<double> hits;
};

/// One ray's JSON report, as Python read it.
struct RayEntry {
    std::string t0, t1;
    std::map<std::string, MethodEntry> methods;
    std::vector<std::string> order;
};

// Reads JSON Lines with Python's json module, checks every report's fields,
// and prints them as plain words for the test to read.
constexpr const char* json_reader = R"(import json, sys
ray_keys = {"scene", "object", "origin", "dir", "t0", "t1", "newton_from", "methods"}
method_keys = {"method", "resolved", "first_hit", "status", "evaluations", "hits", "all_hits_status",
               "all_hits_evaluations", "message"}
statuses = {"ok", "no hit", "failed", "diverged"}
for line in sys.stdin:
    d = json.loads(line)
    assert set(d) == ray_keys, sorted(d)
    assert len(d["origin"]) == 3 and len(d["dir"]) == 3
    print("ray", d["t0"], d["t1"])
    for m in d["methods"]:
        assert set(m) == method_keys, sorted(m)
        assert m["status"] in statuses and m["all_hits_status"] in statuses
        assert isinstance(m["evaluations"], int) and isinstance(m["all_hits_evaluations"], int)
        assert m["message"] is None or "failed" in (m["status"], m["all_hits_status"])
        assert all(isinstance(t, (int, float)) for t in m["hits"]) and m["hits"] == sorted(m["hits"])
        print("method", m["method"], m["resolved"], m["status"].replace(" ", "_"), m["first_hit"], *m["hits"])
)";

class RayCli : public zeroset::test::CliTest {
protected:
    /// The JSON Lines text as Python reads it; fails the test if Python rejects it.
    std::vector<RayEntry> parse_json_lines(const std::string& text) const {
        const fs::path script = logs_.write("read.py", json_reader);
        const fs::path input = logs_.write("input.jsonl", text), parsed = logs_ / "parsed.txt";
        const std::string command = "python3 '" + script.string() + "' < '" + input.string() + "' > '" +
                                    parsed.string() + "' 2> '" + (logs_ / "python.txt").string() + "'";
        const int raw = std::system(command.c_str());
        EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << read_text(logs_ / "python.txt") << "\n" << text;
        std::vector<RayEntry> rays;
        std::istringstream lines(read_text(parsed));
        for (std::string line; std::getline(lines, line);) {
            std::istringstream words(line);
            std::string kind;
            words >> kind;
            if (kind == "ray") {
                words >> rays.emplace_back().t0 >> rays.back().t1;
            } else if (!rays.empty()) {
                std::string name;
                MethodEntry m;
                words >> name >> m.resolved >> m.status >> m.first_hit;
                for (double t; words >> t;) m.hits.push_back(t);
                rays.back().methods[name] = m;
                rays.back().order.push_back(name);
            }
        }
        return rays;
    }
};

// The Blinn blend of the survey's Figure 3 along the survey's ray has four
// roots; these are from 40-digit arithmetic (mpmath) on the same H(t).
constexpr double survey_roots[] = {2.9957298760415094, 4.5020852795518956, 5.8530189382692446, 6.2540237055958461};

TEST_F(RayCli, SurveyRayGivesTheFourRootsFromEveryGuaranteedMethod) {
    const Outcome r = run("ray --json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << "one JSON object on one line";
    const std::vector<RayEntry> rays = parse_json_lines(r.out);
    ASSERT_EQ(rays.size(), 1u);
    const RayEntry& ray = rays[0];
    // The ray clipped to box((-2.4, -1.2, -1.2), (2.4, 1.2, 1.2)), where x
    // enters at -2.4 and leaves at 2.4 — and to the box the surface can be
    // in, inside that and around the roots.
    EXPECT_GT(std::stod(ray.t0), (-2.4 + 4.905) / 0.981);
    EXPECT_LT(std::stod(ray.t0), survey_roots[0]);
    EXPECT_LT(std::stod(ray.t1), (2.4 + 4.905) / 0.981);
    EXPECT_GT(std::stod(ray.t1), survey_roots[3]);
    EXPECT_EQ(ray.order, (std::vector<std::string>{"auto", "sphere", "interval", "lg", "polynomial", "newton",
                                                   "regula_falsi", "bisection"}));
    // Blinn's blend is not a polynomial: that method cannot run, and says why.
    EXPECT_EQ(ray.methods.at("polynomial").status, "failed");
    EXPECT_NE(ray.methods.at("auto").resolved, "auto");
    for (const char* name : {"interval", "lg", "sphere"}) {
        const MethodEntry& m = ray.methods.at(name);
        EXPECT_EQ(m.status, "ok") << name;
        ASSERT_EQ(m.hits.size(), 4u) << name;
        for (std::size_t i = 0; i < 4; ++i) {
            EXPECT_NEAR(m.hits[i], survey_roots[i], 1e-9) << name << " root " << i;
            EXPECT_NEAR(m.hits[i], ray.methods.at("interval").hits[i], 1e-9) << name << " root " << i;
        }
        EXPECT_NEAR(std::stod(m.first_hit), survey_roots[0], 1e-9) << name;
    }
}

TEST_F(RayCli, TextTableListsEveryMethod) {
    const Outcome r = run("ray");
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* part : {"scene    <default>", "object   blobs", "used as given", "shrunk to its surface", "first hit",
                             "all hits", "auto (", "interval ", "lg ", "sphere ", "newton ", "regula_falsi ",
                             "bisection ", "2.995729876, 4.50208528, 5.853018938, 6.254023706"})
        EXPECT_NE(r.out.find(part), std::string::npos) << part << "\n" << r.out;
}

TEST_F(RayCli, OneMethodAndNewtonsStart) {
    const Outcome r = run("ray --method interval --newton-from 3.6 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rays = parse_json_lines(r.out);
    ASSERT_EQ(rays.size(), 1u);
    EXPECT_EQ(rays[0].order, std::vector<std::string>{"interval"});
    EXPECT_NE(r.out.find("\"newton_from\":3.6000000000000001"), std::string::npos) << r.out;
    EXPECT_EQ(run("ray --method nope").status, 2);
    EXPECT_EQ(run("ray --newton-from soon").status, 2);
}

TEST_F(RayCli, RaysFileGivesOneJsonLinePerRay) {
    dir_.write("rays.txt",
               "# the survey's ray, then one along the x axis\n"
               "-4.905 -0.67 0.364   0.981 0.174 0.0872\n"
               "\n"
               "  -5 0 0 1 0 0   # through both centres\n");
    const Outcome r = run("ray --rays rays.txt --json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 2);
    const auto rays = parse_json_lines(r.out);
    ASSERT_EQ(rays.size(), 2u);
    EXPECT_EQ(rays[0].methods.at("interval").hits.size(), 4u);
    // Along the x axis the blend is one solid: it enters and leaves it once.
    EXPECT_EQ(rays[1].methods.at("interval").hits.size(), 2u);
    EXPECT_GT(std::stod(rays[1].t0), 5.0 - 2.4);  // inside the bounds, before the hit
    EXPECT_LT(std::stod(rays[1].t0), rays[1].methods.at("interval").hits[0]);

    const Outcome text = run("ray --rays rays.txt");
    ASSERT_EQ(text.status, 0) << text.err;
    std::size_t reports = 0;
    for (std::size_t i = text.out.find("scene    "); i != std::string::npos; i = text.out.find("scene    ", i + 1)) ++reports;
    EXPECT_EQ(reports, 2u);
}

TEST_F(RayCli, MalformedRaysLineNamesFileAndLine) {
    dir_.write("rays.txt", "# ok\n0 0 -5 0 0 1\n1 2 3 4 5\n");
    const Outcome few = run("ray --rays rays.txt --json");
    EXPECT_NE(few.status, 0);
    EXPECT_NE(few.err.find("rays.txt:3: "), std::string::npos) << few.err;
    EXPECT_TRUE(few.out.empty()) << "nothing printed before the error";

    dir_.write("rays.txt", "0 0 -5 0 0 1\n0 0 -5 0 0 x1\n");
    const Outcome word = run("ray --rays rays.txt");
    EXPECT_NE(word.status, 0);
    EXPECT_NE(word.err.find("rays.txt:2: 'x1' is not a number"), std::string::npos) << word.err;

    dir_.write("rays.txt", "0 0 -5 0 0 0\n");
    EXPECT_NE(run("ray --rays rays.txt").err.find("rays.txt:1: the direction is zero"), std::string::npos);
    dir_.write("rays.txt", "0 0 -5 0 0 inf\n");
    EXPECT_NE(run("ray --rays rays.txt").err.find("rays.txt:1: 'inf' is not a finite number"), std::string::npos);
    dir_.write("rays.txt", "# nothing\n\n");
    EXPECT_NE(run("ray --rays rays.txt").status, 0);
    EXPECT_NE(run("ray --rays missing.txt").err.find("missing.txt"), std::string::npos);
    EXPECT_NE(run("ray --rays /dev/zero").err.find("/dev/zero: cannot open the ray list: it is a device"),
              std::string::npos);
}

TEST_F(RayCli, UnknownObjectListsTheNames) {
    const Outcome r = run("ray --object teapot");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("'teapot'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("'blobs', 'floor'"), std::string::npos) << r.err;
}

TEST_F(RayCli, RayMissingTheBoundsHasNoSpanAndNoHits) {
    const Outcome r = run("ray --object blobs --origin 0,5,0 --dir 1,0,0 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rays = parse_json_lines(r.out);
    ASSERT_EQ(rays.size(), 1u);
    EXPECT_EQ(rays[0].t0, "None");
    EXPECT_EQ(rays[0].t1, "None");
    EXPECT_EQ(rays[0].methods.size(), 8u);
    for (const auto& [name, m] : rays[0].methods) {
        if (name == "polynomial") continue;  // Blinn's blend is not a polynomial: that method fails
        EXPECT_EQ(m.status, "no_hit") << name;
        EXPECT_EQ(m.first_hit, "None") << name;
        EXPECT_TRUE(m.hits.empty()) << name;
    }
    EXPECT_NE(run("ray --origin 0,5,0 --dir 1,0,0").out.find("misses the object's bounds"), std::string::npos);
    const Outcome plot = run("ray --origin 0,5,0 --dir 1,0,0 --plot miss.svg");
    EXPECT_NE(plot.status, 0);
    EXPECT_NE(plot.err.find("misses"), std::string::npos) << plot.err;
    EXPECT_TRUE(dir_.entries().empty());
}

TEST_F(RayCli, PlotWritesAnSvg) {
    const Outcome r = run("ray --newton-from 3.6 --plot ray.svg");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = read_text(dir_ / "ray.svg");
    EXPECT_TRUE(svg.starts_with("<?xml")) << svg.substr(0, 100);
    EXPECT_TRUE(svg.ends_with("</svg>\n"));
    EXPECT_NE(svg.find("<polyline"), std::string::npos);  // H(t)
    EXPECT_NE(svg.find("<circle"), std::string::npos);    // the hits
    EXPECT_NE(svg.find("interval boxes"), std::string::npos);
    EXPECT_NE(svg.find("blobs"), std::string::npos);
    EXPECT_EQ(dir_.entries(), std::vector<std::string>{"ray.svg"});
}

TEST_F(RayCli, CompareDrawsASecondSceneDashedLikeFigureEight) {
    const std::string soft = std::string(ZEROSET_SOURCE_DIR) + "/scenes/hart1993/soft_objects.zs";
    const std::string blinn = std::string(ZEROSET_SOURCE_DIR) + "/scenes/hart1993/blinn_blobs.zs";
    const Outcome r = run("ray '" + soft + "' --origin -4.905,-0.67,0.364 --dir 0.981,0.174,0.0872 --plot fig8.svg" +
                          " --compare '" + blinn + "' --compare-object blobs");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = read_text(dir_ / "fig8.svg");
    EXPECT_NE(svg.find("H of blobs (blinn_blobs.zs)"), std::string::npos);
    EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);  // the compared curve
    const Outcome without_plot = run("ray --compare '" + blinn + "'");
    EXPECT_EQ(without_plot.status, 2);
    EXPECT_NE(without_plot.err.find("--plot"), std::string::npos) << without_plot.err;
}

TEST_F(RayCli, UsageErrorsWriteNothing) {
    dir_.write("sphere.zs", "object \"ball\" { surface x^2 + y^2 + z^2 - 1 }\n");
    const Outcome no_ray = run("ray sphere.zs");
    EXPECT_EQ(no_ray.status, 2);
    EXPECT_NE(no_ray.err.find("--origin"), std::string::npos) << no_ray.err;
    const Outcome ok = run("ray sphere.zs --origin 0,0,-5 --dir 0,0,1 --method interval --json");
    ASSERT_EQ(ok.status, 0) << ok.err;
    const auto rays = parse_json_lines(ok.out);
    ASSERT_EQ(rays.size(), 1u);
    ASSERT_EQ(rays[0].methods.at("interval").hits.size(), 2u);
    EXPECT_NEAR(rays[0].methods.at("interval").hits[0], 4.0, 1e-12);
    EXPECT_NEAR(rays[0].methods.at("interval").hits[1], 6.0, 1e-12);

    for (const char* args : {"--plot ray.png", "--dir 0,0,0", "--origin 1,2", "--rays x.txt --origin 0,0,0",
                             "--rays x.txt --plot a.svg", "a.zs b.zs", "--frobnicate"}) {
        const Outcome r = run(std::string("ray ") + args);
        EXPECT_EQ(r.status, 2) << args << ": " << r.err;
        EXPECT_FALSE(r.err.empty()) << args;
    }
    EXPECT_EQ(dir_.entries(), std::vector<std::string>{"sphere.zs"});
}

TEST_F(RayCli, HelpExplainsTheCommand) {
    const Outcome r = run("ray --help");
    EXPECT_EQ(r.status, 0);
    for (const char* part : {"--origin", "--dir", "--object", "--method", "--newton-from", "--json", "--rays", "--plot",
                             "used as given"})
        EXPECT_NE(r.out.find(part), std::string::npos) << part;
    EXPECT_NE(run("--help").out.find("zeroset ray"), std::string::npos);
}

}  // namespace

namespace {

// An object placed by transforms (inside a shape and an instance) is probed
// in its own space: the ray from the scene is moved, the t values stay.
TEST_F(RayCli, TransformedObjectIsProbedInItsOwnSpace) {
    dir_.write("moved.zs",
          "shape ball { object \"ball\" { surface x^2 + y^2 + z^2 - 1  bounds box((-1, -1, -1), (1, 1, 1))  scale 0.5 } }\n"
          "group { instance ball { translate (3, 0, 0) } }\n");
    const Outcome r = run("ray moved.zs --object ball --origin 0,0,0 --dir 1,0,0 --method interval --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rays = parse_json_lines(r.out);
    ASSERT_EQ(rays.size(), 1u);
    const MethodEntry& m = rays[0].methods.at("interval");
    ASSERT_EQ(m.hits.size(), 2u);
    EXPECT_NEAR(m.hits[0], 2.5, 1e-12);  // the ball of radius 0.5 at x = 3, in the scene's t
    EXPECT_NEAR(m.hits[1], 3.5, 1e-12);
}

}  // namespace

namespace {

class RayPixel : public zeroset::test::CliTest {};

/// The number after "first_hit": in one line of `zeroset ray --json`.
double first_hit_of(const std::string& json) {
    const auto at = json.find("\"first_hit\":");
    if (at == std::string::npos) return NAN;
    return std::strtod(json.c_str() + at + 12, nullptr);
}

TEST_F(RayPixel, IsTheRayTheRendererTracesThere) {
    // The EXR's depth at a pixel is the distance along that pixel's camera
    // ray; --pixel must cast the same ray, so its first hit is that depth.
    ASSERT_EQ(run("render -q -o out.exr").status, 0);
    const zeroset::Image image = zeroset::read_exr(dir_ / "out.exr");
    for (const auto& [px, py] : {std::pair{400, 300}, std::pair{300, 280}, std::pair{520, 330}}) {
        const Outcome r = run("ray --pixel " + std::to_string(px) + "," + std::to_string(py) + " --method interval --json");
        ASSERT_EQ(r.status, 0) << r.err;
        const double depth = image.depth[static_cast<std::size_t>(py * image.width + px)];
        EXPECT_NEAR(first_hit_of(r.out), depth, 1e-5 * depth) << px << "," << py << ": " << r.out;
    }
    const Outcome outside = run("ray --pixel 800,0");
    EXPECT_EQ(outside.status, 2);
    EXPECT_NE(outside.err.find("X must be a whole number from 0 to 799"), std::string::npos) << outside.err;
    EXPECT_EQ(run("ray --pixel 1,2 --origin 0,0,0").status, 2);
}

}  // namespace
