// PFM encoder and decoder. Byte order is handled explicitly (bit_cast and
// shifts), so the files are the same on any host.
#include "zeroset/io/pfm.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include "zeroset/io/image_shape.hpp"

namespace zeroset {

namespace {

void append_float_le(std::vector<std::uint8_t>& out, float value) {
    const auto bits = std::bit_cast<std::uint32_t>(value);
    for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<std::uint8_t>(bits >> shift));
}

float load_float(const std::uint8_t* p, bool little_endian) {
    std::uint32_t bits = 0;
    for (int i = 0; i < 4; ++i) {
        const int shift = little_endian ? 8 * i : 8 * (3 - i);
        bits |= static_cast<std::uint32_t>(p[i]) << shift;
    }
    return std::bit_cast<float>(bits);
}

bool is_space(std::uint8_t c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

// Reads the header's whitespace-separated tokens in order.
class HeaderReader {
public:
    explicit HeaderReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

    std::string_view token(const char* what) {
        while (pos_ < bytes_.size() && is_space(bytes_[pos_])) ++pos_;
        const std::size_t start = pos_;
        while (pos_ < bytes_.size() && !is_space(bytes_[pos_])) ++pos_;
        if (start == pos_) throw std::runtime_error(std::string("invalid PFM: missing ") + what);
        return {reinterpret_cast<const char*>(bytes_.data()) + start, pos_ - start};
    }

    template <class T>
    T number(const char* what) {
        const std::string_view text = token(what);
        T value{};
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc{} || end != text.data() + text.size())
            throw std::runtime_error(std::string("invalid PFM: bad ") + what + " '" + std::string(text) + "'");
        return value;
    }

    /// The offset of the pixel data: exactly one whitespace byte ends the header.
    std::size_t data_offset() {
        if (pos_ >= bytes_.size() || !is_space(bytes_[pos_]))
            throw std::runtime_error("invalid PFM: no whitespace after the scale");
        return pos_ + 1;
    }

private:
    std::span<const std::uint8_t> bytes_;
    std::size_t pos_ = 0;
};

}  // namespace

std::vector<std::uint8_t> encode_pfm(const Image& image) {
    require_valid_image(image);
    const std::string header = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    std::vector<std::uint8_t> out;
    out.reserve(header.size() + 12 * image.pixels.size());
    out.insert(out.end(), header.begin(), header.end());
    for (int y = image.height - 1; y >= 0; --y) {
        for (int x = 0; x < image.width; ++x) {
            const Vec3f& p = image.at(x, y);
            append_float_le(out, p.x);
            append_float_le(out, p.y);
            append_float_le(out, p.z);
        }
    }
    return out;
}

Image decode_pfm(std::span<const std::uint8_t> bytes) {
    HeaderReader header(bytes);
    const std::string_view magic = header.token("magic number");
    if (magic != "PF" && magic != "Pf") throw std::runtime_error("not a PFM file (expected 'PF' or 'Pf')");
    const std::size_t channels = magic == "PF" ? 3 : 1;
    const int width = header.number<int>("width");
    const int height = header.number<int>("height");
    const double scale = header.number<double>("scale");
    if (width <= 0 || height <= 0)
        throw std::runtime_error("invalid PFM: size " + std::to_string(width) + "x" + std::to_string(height));
    if (scale == 0.0 || !std::isfinite(scale))
        throw std::runtime_error("invalid PFM: scale must be finite and non-zero");
    const bool little_endian = scale < 0.0;

    const std::size_t offset = header.data_offset();
    const std::size_t available = bytes.size() - offset;
    const std::size_t bytes_per_pixel = 4 * channels;
    const std::size_t pixel_count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (pixel_count > available / bytes_per_pixel) throw std::runtime_error("invalid PFM: truncated pixel data");
    if (pixel_count * bytes_per_pixel != available)
        throw std::runtime_error("invalid PFM: unexpected data after the pixels");

    Image image(width, height);
    const std::uint8_t* p = bytes.data() + offset;
    for (int y = height - 1; y >= 0; --y) {
        for (int x = 0; x < width; ++x) {
            Vec3f& pixel = image.at(x, y);
            if (channels == 3) {
                pixel = {load_float(p, little_endian), load_float(p + 4, little_endian),
                         load_float(p + 8, little_endian)};
            } else {
                const float v = load_float(p, little_endian);
                pixel = {v, v, v};
            }
            p += bytes_per_pixel;
        }
    }
    return image;
}

}  // namespace zeroset
