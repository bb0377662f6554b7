// write_image: format by extension, clear errors, and atomicity — the
// directory is listed after every success and failure: exactly the target,
// or nothing, and never a temporary file.
#include "zeroset/io/image_writer.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "zeroset/io/image_reader.hpp"
#include "support/temp_dir.hpp"

namespace zeroset {
namespace {

using Names = std::vector<std::string>;

Image grey_image(int width, int height, float value) {
    Image image(width, height);
    for (Vec3f& p : image.pixels) p = {value, value, value};
    return image;
}

// Runs write_image, expects ImageWriteError, returns its message.
std::string write_error(const Image& image, const std::filesystem::path& path) {
    try {
        write_image(image, path);
    } catch (const ImageWriteError& e) {
        EXPECT_EQ(e.path(), path);
        EXPECT_EQ(std::string(e.what()), path.string() + ": " + e.reason());
        return e.what();
    }
    ADD_FAILURE() << "write_image(" << path << ") did not throw";
    return {};
}

bool is_png(const std::vector<std::uint8_t>& bytes) {
    return bytes.size() > 8 && std::memcmp(bytes.data(), "\x89PNG\r\n\x1a\n", 8) == 0;
}

TEST(ImageFormat, ByExtensionIgnoringCase) {
    EXPECT_EQ(image_format_for("out.png"), ImageFormat::Png);
    EXPECT_EQ(image_format_for("dir/out.PNG"), ImageFormat::Png);
    EXPECT_EQ(image_format_for("a.b/out.Png"), ImageFormat::Png);
    EXPECT_EQ(image_format_for("out.ppm"), ImageFormat::Ppm);
    EXPECT_EQ(image_format_for("out.PPM"), ImageFormat::Ppm);
    EXPECT_EQ(image_format_for("/tmp/out.pfm"), ImageFormat::Pfm);
    EXPECT_EQ(image_format_for("out.pFm"), ImageFormat::Pfm);
    EXPECT_EQ(image_format_for("out.jpg"), std::nullopt);
    EXPECT_EQ(image_format_for("out.png.gz"), std::nullopt);
    EXPECT_EQ(image_format_for("png"), std::nullopt);
    EXPECT_EQ(image_format_for("out"), std::nullopt);
    EXPECT_EQ(image_format_for("out."), std::nullopt);
    EXPECT_EQ(image_format_for(""), std::nullopt);
}

TEST(ImageFormat, ProblemExplainsTheChoice) {
    EXPECT_EQ(image_format_problem("out.png"), std::nullopt);
    EXPECT_EQ(image_format_problem("out.jpg"), "unsupported image format '.jpg' (use .png, .ppm, .pfm or .exr)");
    EXPECT_EQ(image_format_problem("out"), "no file extension to choose the image format (use .png, .ppm, .pfm or .exr)");
}

TEST(WriteImage, UnsupportedExtensionThrowsAndCreatesNothing) {
    const test::TempDir dir;
    const std::string message = write_error(grey_image(2, 2, 0.5f), dir / "out.jpg");
    EXPECT_EQ(message, (dir / "out.jpg").string() + ": unsupported image format '.jpg' (use .png, .ppm, .pfm or .exr)");
    EXPECT_EQ(dir.entries(), Names{});
}

TEST(WriteImage, MalformedImagesThrowAndCreateNothing) {
    const test::TempDir dir;
    for (const char* name : {"a.png", "a.ppm", "a.pfm"}) {
        EXPECT_NE(write_error(Image(), dir / name).find("invalid image size 0x0"), std::string::npos);
        EXPECT_NE(write_error(Image(0, 4), dir / name).find("invalid image size 0x4"), std::string::npos);
        Image negative;
        negative.width = -3;
        negative.height = 2;
        EXPECT_NE(write_error(negative, dir / name).find("invalid image size -3x2"), std::string::npos);
        Image short_of_pixels(3, 2);
        short_of_pixels.pixels.resize(5);
        EXPECT_NE(write_error(short_of_pixels, dir / name).find("image has 5 pixels, expected 3x2 = 6"),
                  std::string::npos);
    }
    EXPECT_EQ(dir.entries(), Names{});
}

TEST(WriteImage, MissingDirectoryThrowsAndCreatesNothing) {
    const test::TempDir dir;
    const std::filesystem::path target = dir / "no/such/dir/out.png";
    EXPECT_EQ(write_error(grey_image(2, 2, 0.5f), target),
              target.string() + ": cannot create file: No such file or directory");
    EXPECT_EQ(dir.entries(), Names{});
}

TEST(WriteImage, SuccessLeavesExactlyTheTarget) {
    const test::TempDir dir;
    write_image(grey_image(3, 2, 0.25f), dir / "out.png");
    EXPECT_EQ(dir.entries(), Names{"out.png"});
    write_image(grey_image(3, 2, 0.25f), dir / "out.ppm");
    write_image(grey_image(3, 2, 0.25f), dir / "out.pfm");
    EXPECT_EQ(dir.entries(), (Names{"out.pfm", "out.png", "out.ppm"}));
}

TEST(WriteImage, ReplacesAnExistingFile) {
    const test::TempDir dir;
    test::write_text(dir / "out.png", "an older file that is not a PNG");
    write_image(grey_image(4, 4, 1.0f), dir / "out.png");
    EXPECT_TRUE(is_png(test::read_bytes(dir / "out.png")));
    EXPECT_EQ(read_png(dir / "out.png").at(3, 3), Vec3f(1.0f, 1.0f, 1.0f));

    write_image(grey_image(2, 1, 0.0f), dir / "out.png");
    const Image second = read_png(dir / "out.png");
    EXPECT_EQ(second.width, 2);
    EXPECT_EQ(second.at(1, 0), Vec3f(0.0f, 0.0f, 0.0f));
    EXPECT_EQ(dir.entries(), Names{"out.png"});
}

TEST(WriteImage, FailedRenameRemovesTheTemporaryFile) {
    // The target is a directory: the temporary file is written, then rename()
    // fails; the temporary must go and the directory must survive.
    const test::TempDir dir;
    std::filesystem::create_directory(dir / "out.png");
    test::write_text(dir / "out.png" / "keep", "x");
    const std::string message = write_error(grey_image(2, 2, 0.5f), dir / "out.png");
    EXPECT_NE(message.find(": cannot replace file: "), std::string::npos) << message;
    EXPECT_EQ(dir.entries(), Names{"out.png"});
    EXPECT_TRUE(std::filesystem::is_directory(dir / "out.png"));
    EXPECT_TRUE(std::filesystem::exists(dir / "out.png" / "keep"));
}

TEST(WriteImage, EncoderFailureLeavesTheOldFile) {
    const test::TempDir dir;
    test::write_text(dir / "out.png", "previous");
    const std::string message = write_error(Image(1'000'001, 1), dir / "out.png");
    EXPECT_NE(message.find("cannot encode image: libpng"), std::string::npos) << message;
    EXPECT_EQ(dir.entries(), Names{"out.png"});
    const std::vector<std::uint8_t> kept = test::read_bytes(dir / "out.png");
    EXPECT_EQ(std::string(kept.begin(), kept.end()), "previous");
}

}  // namespace
}  // namespace zeroset
