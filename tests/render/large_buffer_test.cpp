// LargeBuffer (render/large_buffer.hpp): a vector whose big allocations sit
// on 2 MiB boundaries (offered to the kernel as huge pages) and whose small
// ones are plain; both keep what is stored in them.
#include <gtest/gtest.h>

#include <cstdint>

#include "zeroset/render/image.hpp"
#include "zeroset/render/large_buffer.hpp"

namespace zeroset {
namespace {

TEST(LargeBuffer, BigBuffersSitOnHugePageBoundariesAndKeepTheirValues) {
    LargeBuffer<Vec3f> big(1024 * 1024);  // 12 MiB
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(big.data()) % LargeBufferAllocator<Vec3f>::huge_page, 0u);
    EXPECT_EQ(big[12345].x, 0.0f);  // value-initialised, as a std::vector's
    for (std::size_t i = 0; i < big.size(); i += 4099) big[i] = {static_cast<float>(i), 1.0f, 2.0f};
    const LargeBuffer<Vec3f> copy = big;
    for (std::size_t i = 0; i < big.size(); i += 4099) EXPECT_EQ(copy[i].x, static_cast<float>(i));
    big.resize(10);  // shrinking keeps the front
    EXPECT_EQ(big[0].y, 1.0f);
}

TEST(LargeBuffer, SmallAndEmptyBuffersWork) {
    LargeBuffer<float> small(3, 1.5f);
    small.push_back(2.5f);
    EXPECT_EQ(small.size(), 4u);
    EXPECT_EQ(small[3], 2.5f);
    LargeBuffer<float> none;
    none.reserve(0);
    EXPECT_TRUE(none.empty());
    const Image image(640, 480);
    EXPECT_EQ(image.pixels.size(), 640u * 480u);
    EXPECT_EQ(image.at(639, 479).z, 0.0f);
}

TEST(LargeBuffer, AnImpossibleSizeIsRefused) {
    LargeBufferAllocator<Vec3f> allocator;
    EXPECT_THROW((void)allocator.allocate(std::size_t{1} << 62), std::bad_array_new_length);
}

}  // namespace
}  // namespace zeroset
