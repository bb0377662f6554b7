// libpng glue. libpng reports errors by calling an error callback that must
// not return; we longjmp back to a setjmp. A longjmp that skips a C++
// destructor is undefined behaviour, so every setjmp sits in a small "phase"
// function whose locals are all trivially destructible, and every buffer
// and libpng handle is owned by its caller, which frees them normally —
// on success, on a libpng error, or on an exception.
#include "zeroset/io/png.hpp"

#include <png.h>
#include <zlib.h>

#include <array>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "zeroset/io/image_shape.hpp"
#include "zeroset/io/srgb.hpp"

namespace zeroset {

namespace {

// Decoding refuses images larger than this many pixels (8192 × 8192), so a
// tiny malicious file cannot demand gigabytes.
constexpr std::size_t max_decoded_pixels = std::size_t{1} << 26;

struct PngErrorState {
    char message[256] = "unknown libpng error";
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
    auto* state = static_cast<PngErrorState*>(png_get_error_ptr(png));
    std::snprintf(state->message, sizeof state->message, "%s", message != nullptr ? message : "unknown libpng error");
    png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}  // warnings are not errors; stay quiet

// Write callback: append to a std::vector. The allocation may throw, and an
// exception must not cross libpng's C frames: convert it to png_error once
// the try block (and everything it owns) is gone.
void write_to_vector(png_structp png, png_bytep data, std::size_t length) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
    bool stored = true;
    try {
        out->insert(out->end(), data, data + length);
    } catch (...) {
        stored = false;
    }
    if (!stored) png_error(png, "out of memory");
}

void flush_nothing(png_structp) {}

struct MemorySource {
    const std::uint8_t* data;
    std::size_t size;
    std::size_t offset;
};

void read_from_memory(png_structp png, png_bytep out, std::size_t length) {
    auto* source = static_cast<MemorySource*>(png_get_io_ptr(png));
    if (length > source->size - source->offset) png_error(png, "truncated PNG data");
    std::memcpy(out, source->data + source->offset, length);
    source->offset += length;
}

// Owns a libpng write or read struct pair; frees it however we leave.
class PngHandles {
public:
    PngHandles(bool writing, PngErrorState* error) : writing_(writing) {
        png_ = writing ? png_create_write_struct(PNG_LIBPNG_VER_STRING, error, on_png_error, on_png_warning)
                       : png_create_read_struct(PNG_LIBPNG_VER_STRING, error, on_png_error, on_png_warning);
        if (png_ != nullptr) info_ = png_create_info_struct(png_);
        if (png_ == nullptr || info_ == nullptr) {
            destroy();
            throw std::runtime_error("cannot initialise libpng");
        }
    }
    ~PngHandles() { destroy(); }
    PngHandles(const PngHandles&) = delete;
    PngHandles& operator=(const PngHandles&) = delete;

    [[nodiscard]] png_structp png() const { return png_; }
    [[nodiscard]] png_infop info() const { return info_; }

private:
    void destroy() {
        if (writing_)
            png_destroy_write_struct(&png_, &info_);
        else
            png_destroy_read_struct(&png_, &info_, nullptr);
    }

    bool writing_;
    png_structp png_ = nullptr;
    png_infop info_ = nullptr;
};

// ---- phase functions: setjmp targets, trivially destructible locals only ----

bool write_png_phase(png_structp png, png_infop info, std::vector<std::uint8_t>* out, png_uint_32 width,
                     png_uint_32 height, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;  // NOLINT(cert-err52-cpp): libpng reports errors by longjmp
    png_set_write_fn(png, out, write_to_vector, flush_nothing);
    png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    // Written for speed: libpng's defaults (zlib level 6, the best of five
    // filters per row) took 19–27 ms for a 640×480 or 800×600 render, 10–15 %
    // of the whole run; Paeth rows run-length coded at level 2 take 4.5–6.5
    // ms for files about 30 % larger (docs/rendering.md).
    png_set_compression_level(png, 2);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_PAETH);
    png_set_compression_strategy(png, Z_RLE);
    // sRGB chunk, plus the matching gAMA and cHRM for decoders that ignore sRGB.
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, info);
    return true;
}

// Reads the header and sets up conversion of any PNG to 8-bit RGB.
bool read_png_header_phase(png_structp png, png_infop info, MemorySource* source, png_uint_32* width,
                           png_uint_32* height) {
    if (setjmp(png_jmpbuf(png))) return false;  // NOLINT(cert-err52-cpp): libpng reports errors by longjmp
    png_set_read_fn(png, source, read_from_memory);
    png_read_info(png, info);
    png_set_expand(png);        // palette → RGB, grey < 8 bits → 8 bits, tRNS → alpha
    png_set_scale_16(png);      // 16 → 8 bits, rounded
    png_set_strip_alpha(png);
    png_set_gray_to_rgb(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_bit_depth(png, info) != 8 || png_get_channels(png, info) != 3)
        png_error(png, "unexpected pixel layout after conversion to RGB");
    *width = png_get_image_width(png, info);
    *height = png_get_image_height(png, info);
    return true;
}

bool read_png_rows_phase(png_structp png, png_infop info, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;  // NOLINT(cert-err52-cpp): libpng reports errors by longjmp
    png_read_image(png, rows);
    png_read_end(png, info);
    return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
    require_valid_image(image);
    const auto width = static_cast<std::size_t>(image.width);
    const auto height = static_cast<std::size_t>(image.height);
    const std::size_t row_bytes = 3 * width;

    std::vector<std::uint8_t> rgb(row_bytes * height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        rgb[3 * i + 0] = encode_srgb8(image.pixels[i].x);
        rgb[3 * i + 1] = encode_srgb8(image.pixels[i].y);
        rgb[3 * i + 2] = encode_srgb8(image.pixels[i].z);
    }
    std::vector<png_bytep> rows(height);
    for (std::size_t y = 0; y < height; ++y) rows[y] = rgb.data() + y * row_bytes;

    std::vector<std::uint8_t> out;
    out.reserve(rgb.size() / 4 + 1024);
    PngErrorState error;
    const PngHandles handles(/*writing=*/true, &error);
    if (!write_png_phase(handles.png(), handles.info(), &out, static_cast<png_uint_32>(width),
                         static_cast<png_uint_32>(height), rows.data()))
        throw std::runtime_error(std::string("libpng: ") + error.message);
    return out;
}

Image decode_png(std::span<const std::uint8_t> bytes) {
    if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0) throw std::runtime_error("not a PNG file");

    PngErrorState error;
    const PngHandles handles(/*writing=*/false, &error);
    MemorySource source{bytes.data(), bytes.size(), 0};
    png_uint_32 width = 0;
    png_uint_32 height = 0;
    if (!read_png_header_phase(handles.png(), handles.info(), &source, &width, &height))
        throw std::runtime_error(std::string("invalid PNG: ") + error.message);
    if (width == 0 || height == 0 || static_cast<std::size_t>(width) * height > max_decoded_pixels)
        throw std::runtime_error("PNG too large: " + std::to_string(width) + "x" + std::to_string(height));

    const std::size_t row_bytes = 3 * static_cast<std::size_t>(width);
    std::vector<std::uint8_t> rgb(row_bytes * height);
    std::vector<png_bytep> rows(height);
    for (std::size_t y = 0; y < height; ++y) rows[y] = rgb.data() + y * row_bytes;
    if (!read_png_rows_phase(handles.png(), handles.info(), rows.data()))
        throw std::runtime_error(std::string("invalid PNG: ") + error.message);

    std::array<float, 256> linear{};
    for (std::size_t code = 0; code < linear.size(); ++code)
        linear[code] = decode_srgb8(static_cast<std::uint8_t>(code));
    Image image(static_cast<int>(width), static_cast<int>(height));
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = {linear[rgb[3 * i + 0]], linear[rgb[3 * i + 1]], linear[rgb[3 * i + 2]]};
    return image;
}

}  // namespace zeroset
