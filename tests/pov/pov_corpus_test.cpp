// POV-Ray's own sample scenes (Debian's povray-examples: objects/quartic/,
// objects/blob*.pov, objects/isosurfaces.pov), where the package is
// installed: every one imports — a SceneError would be a scene zeroset
// cannot draw — and every warning is located. bench/compare_povray_corpus.py
// compares the images with POV-Ray's.
#include <filesystem>
#include <regex>

#include "pov/pov_test_support.hpp"
#include "zeroset/render/renderer.hpp"
#include "zeroset/scene/load_scene.hpp"
#include "zeroset/scene/scene_writer.hpp"

namespace zeroset::pov::test {
namespace {

std::vector<std::filesystem::path> corpus() {
    const std::filesystem::path objects = "/usr/share/doc/povray/examples/objects";
    std::vector<std::filesystem::path> scenes;
    std::error_code error;
    if (!std::filesystem::is_directory(objects / "quartic", error)) return scenes;
    for (const auto& e : std::filesystem::directory_iterator(objects / "quartic"))
        if (e.path().extension() == ".pov") scenes.push_back(e.path());
    for (const auto& e : std::filesystem::directory_iterator(objects)) {
        const std::string name = e.path().filename().string();
        if ((name.starts_with("blob") || name == "isosurfaces.pov") && e.path().extension() == ".pov") scenes.push_back(e.path());
    }
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

TEST(PovCorpus, EverySampleSceneImportsWithLocatedMessages) {
    const auto scenes = corpus();
    if (scenes.empty()) GTEST_SKIP() << "povray-examples is not installed";
    EXPECT_EQ(scenes.size(), 23U);  // 18 quartics, 4 blobs, the isosurfaces
    const std::regex located(R"(^[^:]+:\d+:\d+: .+)");
    for (const auto& scene : scenes) {
        try {
            const PovImport imported = read_pov_scene(scene);
            EXPECT_FALSE(imported.scene.nodes.empty()) << scene;
            EXPECT_FALSE(imported.scene.lights.empty()) << scene;
            for (const std::string& w : imported.scene.warnings) EXPECT_TRUE(std::regex_match(w, located)) << w;
            for (const std::string& n : imported.notes) EXPECT_TRUE(std::regex_match(n, located)) << n;
        } catch (const SceneError& e) {
            ADD_FAILURE() << e.what();
        }
    }
}

TEST(PovCorpus, ImportedScenesWrittenAsZerosetScenesRenderTheSame) {
    // What `zeroset import` writes reads back as the scene it imported.
    const auto scenes = corpus();
    if (scenes.empty()) GTEST_SKIP() << "povray-examples is not installed";
    RenderSettings settings;
    settings.width = 32;
    settings.height = 24;
    for (const auto& scene : scenes) {
        const PovImport imported = read_pov_scene(scene);
        const std::string text = write_scene(imported.scene);
        const Scene again = parse_scene(text, "written.zs", ".");
        EXPECT_EQ(render(imported.scene, settings).image.pixels, render(again, settings).image.pixels) << scene;
    }
}

}  // namespace
}  // namespace zeroset::pov::test
