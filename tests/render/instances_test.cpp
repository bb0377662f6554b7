// Instancing: a shape placed a thousand times is one prepared primitive —
// one tape, one set of evaluators per thread — with a transform per
// placement (DESIGN.md, "Primitives").
#include <gtest/gtest.h>
#include "support/models.hpp"

#include <string>

#include "zeroset/render/prepared_scene.hpp"
#include "zeroset/render/renderer.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset {
namespace {

TEST(Instances, AThousandBearsAreOneTape) {
    ZEROSET_SKIP_WITHOUT_MODEL("bear.vm");

    const std::string text =
        "camera { from (15, 40, -60)  at (15, 0, 15)  fov 40 }\n"
        "shape bear { object { surface model(\"" ZEROSET_MODELS_DIR
        "/bear.vm\")  bounds box((-0.7, -0.65, -0.75), (1.05, 0.9, 0.7)) } }\n"
        "for i from 0 to 31 { for j from 0 to 31 {\n"
        "  instance bear { rotate (0, 11 * i + 7 * j, 0)  translate (i, 0, j) }\n"
        "} }\n";
    const Scene scene = parse_scene(text, "bears.zs", ".");
    EXPECT_EQ(placed_objects(scene).size(), 1024u);
    const PreparedScene prepared(scene);
    ASSERT_EQ(prepared.leaves().size(), 1u);  // one tape for all 1024
    const Tape bear(placed_objects(scene).front().object().surface);
    EXPECT_EQ(prepared.leaves().front()->tape().clauses().size(), bear.clauses().size());

    RenderSettings settings;
    settings.width = 48;
    settings.height = 32;
    settings.threads = 2;
    const RenderResult r = render(scene, settings);
    EXPECT_GT(r.stats.hits, 100u);  // the field of bears is there
}

}  // namespace
}  // namespace zeroset
