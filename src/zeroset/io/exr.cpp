// EXR through OpenEXR's C++ API, with memory streams in place of files.
#include "zeroset/io/exr.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>

#include "zeroset/io/image_shape.hpp"

namespace zeroset {

namespace {

/// Collects what OpenEXR writes, with the seeks it makes to patch its
/// line-offset table.
class MemoryOutput final : public Imf::OStream {
public:
    MemoryOutput() : Imf::OStream("memory") {}
    void write(const char c[], int n) override {
        const auto end = position_ + static_cast<std::size_t>(n);
        if (end > bytes_.size()) bytes_.resize(end);
        std::memcpy(bytes_.data() + position_, c, static_cast<std::size_t>(n));
        position_ = end;
    }
    uint64_t tellp() override { return position_; }
    void seekp(uint64_t pos) override { position_ = static_cast<std::size_t>(pos); }
    std::vector<std::uint8_t> take() { return std::move(bytes_); }

private:
    std::vector<std::uint8_t> bytes_;
    std::size_t position_ = 0;
};

class MemoryInput final : public Imf::IStream {
public:
    explicit MemoryInput(std::span<const std::uint8_t> bytes) : Imf::IStream("memory"), bytes_(bytes) {}
    bool read(char c[], int n) override {
        if (position_ + static_cast<std::size_t>(n) > bytes_.size()) throw std::runtime_error("truncated EXR data");
        std::memcpy(c, bytes_.data() + position_, static_cast<std::size_t>(n));
        position_ += static_cast<std::size_t>(n);
        return position_ < bytes_.size();
    }
    uint64_t tellg() override { return position_; }
    void seekg(uint64_t pos) override { position_ = static_cast<std::size_t>(pos); }

private:
    std::span<const std::uint8_t> bytes_;
    std::size_t position_ = 0;
};

/// One float channel of `base`, an array of records `stride` bytes apart.
Imf::Slice float_slice(const void* base, std::size_t stride, int width) {
    return Imf::Slice(Imf::FLOAT, static_cast<char*>(const_cast<void*>(base)), stride,
                      stride * static_cast<std::size_t>(width));
}

constexpr const char* normal_channels[3] = {"N.x", "N.y", "N.z"};

}  // namespace

std::vector<std::uint8_t> encode_exr(const Image& image) {
    require_valid_image(image);
    const bool layers = image.has_layers();
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer frame;
    const char* rgb[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        header.channels().insert(rgb[c], Imf::Channel(Imf::FLOAT));
        frame.insert(rgb[c], float_slice(&image.pixels[0][c], sizeof(Vec3f), image.width));
    }
    if (layers) {
        header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
        frame.insert("Z", float_slice(image.depth.data(), sizeof(float), image.width));
        for (int c = 0; c < 3; ++c) {
            header.channels().insert(normal_channels[c], Imf::Channel(Imf::FLOAT));
            frame.insert(normal_channels[c], float_slice(&image.normals[0][c], sizeof(Vec3f), image.width));
        }
    }
    MemoryOutput out;
    try {
        Imf::OutputFile file(out, header, 1);
        file.setFrameBuffer(frame);
        file.writePixels(image.height);
    } catch (const std::exception& e) {
        throw std::runtime_error(std::string("OpenEXR: ") + e.what());
    }
    return out.take();
}

Image decode_exr(std::span<const std::uint8_t> bytes) {
    try {
        MemoryInput in(bytes);
        Imf::InputFile file(in, 1);
        const Imath::Box2i window = file.header().dataWindow();
        const int width = window.max.x - window.min.x + 1;
        const int height = window.max.y - window.min.y + 1;
        if (width <= 0 || height <= 0 || static_cast<long long>(width) * height > (1LL << 28))
            throw std::runtime_error("EXR data window of " + std::to_string(width) + "x" + std::to_string(height));
        Image image(width, height);
        const Imf::ChannelList& channels = file.header().channels();
        const bool layers = channels.findChannel("Z") && std::all_of(std::begin(normal_channels), std::end(normal_channels),
                                                                     [&](const char* n) { return channels.findChannel(n); });
        if (layers) image.add_layers();
        // The data window's corner lands on element 0 (Slice::Make shifts the
        // base for it); a missing channel reads as 0.
        const auto at = [&](auto* first, int c, std::size_t stride) {
            return Imf::Slice::Make(Imf::FLOAT, reinterpret_cast<char*>(first) + c * sizeof(float), window, stride,
                                    stride * static_cast<std::size_t>(width));
        };
        Imf::FrameBuffer frame;
        const char* rgb[3] = {"R", "G", "B"};
        for (int c = 0; c < 3; ++c) frame.insert(rgb[c], at(image.pixels.data(), c, sizeof(Vec3f)));
        if (layers) {
            frame.insert("Z", at(image.depth.data(), 0, sizeof(float)));
            for (int c = 0; c < 3; ++c) frame.insert(normal_channels[c], at(image.normals.data(), c, sizeof(Vec3f)));
        }
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        return image;
    } catch (const std::runtime_error&) {
        throw;
    } catch (const std::exception& e) {
        throw std::runtime_error(std::string("OpenEXR: ") + e.what());
    }
}

}  // namespace zeroset
