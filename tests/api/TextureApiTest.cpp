// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// QD3DShader.h's colour routines, the texture shader and the pixmap and
// mipmap textures: every call, every error of the data rules in their
// order, references taken and given, and failed setters that leave the
// object and its edit index as they were.

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"
#include "TextureTestSupport.h"

#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <vector>

namespace {

using namespace q3test;

// ---- Colours ------------------------------------------------------------------

class ColorApiTest : public OwningApiTest {};

bool sameRGB(const TQ3ColorRGB& c, float r, float g, float b)
{
    return c.r == r && c.g == g && c.b == b;
}

bool sameARGB(const TQ3ColorARGB& c, float a, float r, float g, float b)
{
    return c.a == a && sameRGB({c.r, c.g, c.b}, r, g, b);
}

TEST_F(ColorApiTest, SetFillsEveryChannelAndReturnsTheColour)
{
    TQ3ColorRGB rgb{};
    EXPECT_EQ(Q3ColorRGB_Set(&rgb, 0.25f, -1.0f, 7.0f), &rgb);
    EXPECT_TRUE(sameRGB(rgb, 0.25f, -1.0f, 7.0f));
    TQ3ColorARGB argb{};
    EXPECT_EQ(Q3ColorARGB_Set(&argb, 0.5f, 0.25f, 0.125f, 1.0f), &argb);
    EXPECT_TRUE(sameARGB(argb, 0.5f, 0.25f, 0.125f, 1.0f));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ColorRGB_Set(nullptr, 0, 0, 0), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ColorARGB_Set(nullptr, 0, 0, 0, 0), nullptr), kQ3ErrorNULLParameter);
}

TEST_F(ColorApiTest, ArithmeticWorksChannelByChannelAndMayAlias)
{
    const TQ3ColorRGB a{0.5f, 0.25f, 2.0f}, b{0.25f, 1.0f, -1.0f};
    TQ3ColorRGB r{};
    EXPECT_EQ(Q3ColorRGB_Add(&a, &b, &r), &r);
    EXPECT_TRUE(sameRGB(r, 0.75f, 1.25f, 1.0f));
    EXPECT_EQ(Q3ColorRGB_Subtract(&a, &b, &r), &r);
    EXPECT_TRUE(sameRGB(r, 0.25f, -0.75f, 3.0f));
    EXPECT_EQ(Q3ColorRGB_Scale(&a, 4.0f, &r), &r);
    EXPECT_TRUE(sameRGB(r, 2.0f, 1.0f, 8.0f));
    EXPECT_EQ(Q3ColorRGB_Lerp(&a, &b, 0.0f, &r), &r);
    EXPECT_TRUE(sameRGB(r, a.r, a.g, a.b));
    EXPECT_EQ(Q3ColorRGB_Lerp(&a, &b, 1.0f, &r), &r);
    EXPECT_TRUE(sameRGB(r, b.r, b.g, b.b));
    EXPECT_EQ(Q3ColorRGB_Lerp(&a, &b, 0.5f, &r), &r);
    EXPECT_TRUE(sameRGB(r, 0.375f, 0.625f, 0.5f));
    EXPECT_EQ(Q3ColorRGB_Lerp(&a, &b, 2.0f, &r), &r); // beyond last
    EXPECT_TRUE(sameRGB(r, 0.0f, 1.75f, -4.0f));
    r = TQ3ColorRGB{1.0f, 1.0f, 1.0f};
    EXPECT_EQ(Q3ColorRGB_Accumulate(&a, &r), &r);
    EXPECT_TRUE(sameRGB(r, 1.5f, 1.25f, 3.0f));
    // The result may be an input.
    TQ3ColorRGB x = a;
    EXPECT_EQ(Q3ColorRGB_Add(&x, &x, &x), &x);
    EXPECT_TRUE(sameRGB(x, 1.0f, 0.5f, 4.0f));
    x = a;
    EXPECT_EQ(Q3ColorRGB_Accumulate(&x, &x), &x);
    EXPECT_TRUE(sameRGB(x, 1.0f, 0.5f, 4.0f));
    x = a;
    EXPECT_EQ(Q3ColorRGB_Lerp(&x, &b, 0.5f, &x), &x);
    EXPECT_TRUE(sameRGB(x, 0.375f, 0.625f, 0.5f));
}

TEST_F(ColorApiTest, ClampBringsChannelsIntoZeroToOne)
{
    const float inf = std::numeric_limits<float>::infinity();
    const TQ3ColorRGB c{-0.5f, 0.5f, 1.5f};
    TQ3ColorRGB r{};
    EXPECT_EQ(Q3ColorRGB_Clamp(&c, &r), &r);
    EXPECT_TRUE(sameRGB(r, 0.0f, 0.5f, 1.0f));
    const TQ3ColorRGB extremes{-inf, inf, kNaN};
    EXPECT_EQ(Q3ColorRGB_Clamp(&extremes, &r), &r);
    EXPECT_EQ(r.r, 0.0f);
    EXPECT_EQ(r.g, 1.0f);
    EXPECT_TRUE(std::isnan(r.b));
    TQ3ColorRGB self = c;
    EXPECT_EQ(Q3ColorRGB_Clamp(&self, &self), &self);
    EXPECT_TRUE(sameRGB(self, 0.0f, 0.5f, 1.0f));
}

TEST_F(ColorApiTest, NonFiniteValuesAreComputedWithAsTheyAre)
{
    for (float bad : kNonFinite) {
        const TQ3ColorRGB c{bad, 0.5f, 0.25f};
        TQ3ColorRGB r{};
        ASSERT_EQ(Q3ColorRGB_Scale(&c, 2.0f, &r), &r);
        EXPECT_TRUE(std::isnan(bad) ? std::isnan(r.r) : r.r == bad);
        EXPECT_EQ(r.g, 1.0f);
        ASSERT_EQ(Q3ColorRGB_Scale(&c, bad, &r), &r);
        EXPECT_FALSE(std::isfinite(r.g));
        float luminance = 0.0f;
        ASSERT_EQ(Q3ColorRGB_Luminance(&c, &luminance), &luminance);
        EXPECT_FALSE(std::isfinite(luminance));
    }
}

TEST_F(ColorApiTest, LuminanceWeighsTheChannels)
{
    // QD3DShader.h's weights: 77, 151 and 28 parts in 256.
    const TQ3ColorRGB colors[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {0.5f, 0.25f, 0.75f}};
    for (const TQ3ColorRGB& c : colors) {
        float luminance = -1.0f;
        ASSERT_EQ(Q3ColorRGB_Luminance(&c, &luminance), &luminance);
        const double want = (77.0 * c.r + 151.0 * c.g + 28.0 * c.b) / 256.0;
        EXPECT_NEAR(luminance, want, 1e-6);
    }
}

TEST_F(ColorApiTest, EveryNullPointerIsRefusedAndNothingIsWritten)
{
    const TQ3ColorRGB c{0.1f, 0.2f, 0.3f};
    const TQ3ColorRGB sentinel{9, 9, 9};
    TQ3ColorRGB r = sentinel;
    float luminance = 9.0f;
    const std::vector<std::function<const void*()>> calls = {
        [&] { return Q3ColorRGB_Add(nullptr, &c, &r); },     [&] { return Q3ColorRGB_Add(&c, nullptr, &r); },
        [&] { return Q3ColorRGB_Add(&c, &c, nullptr); },     [&] { return Q3ColorRGB_Subtract(nullptr, &c, &r); },
        [&] { return Q3ColorRGB_Subtract(&c, nullptr, &r); }, [&] { return Q3ColorRGB_Subtract(&c, &c, nullptr); },
        [&] { return Q3ColorRGB_Scale(nullptr, 1, &r); },    [&] { return Q3ColorRGB_Scale(&c, 1, nullptr); },
        [&] { return Q3ColorRGB_Clamp(nullptr, &r); },       [&] { return Q3ColorRGB_Clamp(&c, nullptr); },
        [&] { return Q3ColorRGB_Lerp(nullptr, &c, 0, &r); }, [&] { return Q3ColorRGB_Lerp(&c, nullptr, 0, &r); },
        [&] { return Q3ColorRGB_Lerp(&c, &c, 0, nullptr); }, [&] { return Q3ColorRGB_Accumulate(nullptr, &r); },
        [&] { return Q3ColorRGB_Accumulate(&c, nullptr); },  [&] { return Q3ColorRGB_Luminance(nullptr, &luminance); },
        [&] { return Q3ColorRGB_Luminance(&c, nullptr); },
    };
    for (std::size_t i = 0; i < calls.size(); ++i) {
        EXPECT_Q3_ERROR(EXPECT_EQ(calls[i](), nullptr) << "call " << i, kQ3ErrorNULLParameter);
        EXPECT_TRUE(sameRGB(r, 9, 9, 9)) << "call " << i;
        EXPECT_EQ(luminance, 9.0f) << "call " << i;
    }
}

// ---- Textures -----------------------------------------------------------------

class TextureApiTest : public OwningApiTest {
protected:
    void SetUp() override
    {
        OwningApiTest::SetUp();
        m_bytes.assign(4096, 0x40);
        m_storage = own(Q3MemoryStorage_New(m_bytes.data(), static_cast<unsigned long>(m_bytes.size())));
    }

    // 4 x 2 ARGB32 pixels, 4 spare bytes a row.
    TQ3StoragePixmap goodPixmap() const
    {
        return TQ3StoragePixmap{m_storage, 4, 2, 20, 32, kQ3PixelTypeARGB32, kQ3EndianBig, kQ3EndianLittle};
    }

    // An 8 x 2 RGB16 chain: 8x2, 4x1, 2x1, 1x1, packed one after another.
    TQ3Mipmap goodMipmap() const
    {
        TQ3Mipmap m = bigEndianMipmap(m_storage, kQ3PixelTypeRGB16, true,
                                      {{8, 2, 16, 0}, {4, 1, 8, 32}, {2, 1, 4, 40}, {1, 1, 2, 44}});
        // Not read: one past the chain's end.
        m.mipmaps[4] = TQ3MipmapImage{ULONG_MAX, 0, 0, ULONG_MAX};
        return m;
    }

    static bool samePixmap(const TQ3StoragePixmap& a, const TQ3StoragePixmap& b)
    {
        return std::memcmp(&a, &b, sizeof a) == 0;
    }
    static bool sameMipmap(const TQ3Mipmap& a, const TQ3Mipmap& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

    std::vector<std::pair<TQ3Object, TQ3Error>> badTextures(TQ3Object otherTexture)
    {
        return {{nullptr, kQ3ErrorNULLParameter},
                {strayHandle(), kQ3ErrorInvalidObject},
                {own(Q3AttributeSet_New()), kQ3ErrorInvalidObjectType},
                {m_storage, kQ3ErrorInvalidObjectType},
                {otherTexture, kQ3ErrorInvalidObjectType},
                {deadObject(), kQ3ErrorInvalidObject}};
    }

    std::vector<unsigned char> m_bytes;
    TQ3StorageObject m_storage = nullptr;
};

// Stores a value a C caller may put in an enum field, without reading it as
// the enum (which UBSan would refuse for a value outside the enumeration).
template <class E>
void setRaw(E& field, std::int32_t value)
{
    static_assert(sizeof(E) == sizeof value, "an enum field is 32 bits");
    std::memcpy(&field, &value, sizeof value);
}

TEST_F(TextureApiTest, PixmapTextureHasItsTypeSizeAndPixmap)
{
    const TQ3StoragePixmap pixmap = goodPixmap();
    const unsigned long before = referenceCount(m_storage);
    TQ3TextureObject texture = Q3PixmapTexture_New(&pixmap);
    ASSERT_NE(texture, nullptr);
    EXPECT_EQ(referenceCount(m_storage), before + 1);
    EXPECT_EQ(Q3Object_GetType(texture), kQ3ObjectTypeShared);
    EXPECT_EQ(Q3Shared_GetType(texture), kQ3SharedTypeTexture);
    EXPECT_EQ(Q3Texture_GetType(texture), kQ3TextureTypePixmap);
    EXPECT_EQ(Q3Object_GetLeafType(texture), kQ3TextureTypePixmap);
    unsigned long width = 0, height = 0;
    EXPECT_EQ(Q3Texture_GetWidth(texture, &width), kQ3Success);
    EXPECT_EQ(Q3Texture_GetHeight(texture, &height), kQ3Success);
    EXPECT_EQ(width, 4u);
    EXPECT_EQ(height, 2u);
    TQ3StoragePixmap got{};
    ASSERT_EQ(Q3PixmapTexture_GetPixmap(texture, &got), kQ3Success);
    EXPECT_TRUE(samePixmap(got, pixmap));
    EXPECT_EQ(referenceCount(m_storage), before + 2); // the caller's new reference
    Q3Object_Dispose(got.image);
    // Disposing of the texture releases its storage reference.
    Q3Object_Dispose(texture);
    EXPECT_EQ(referenceCount(m_storage), before);
    EXPECT_Q3_ERROR(Q3Object_Dispose(texture), kQ3ErrorInvalidObject);
}

TEST_F(TextureApiTest, MipmapTextureHasItsTypeSizeAndMipmap)
{
    const TQ3Mipmap mipmap = goodMipmap();
    TQ3TextureObject texture = own(Q3MipmapTexture_New(&mipmap));
    ASSERT_NE(texture, nullptr);
    EXPECT_EQ(Q3Texture_GetType(texture), kQ3TextureTypeMipmap);
    unsigned long width = 0, height = 0;
    EXPECT_EQ(Q3Texture_GetWidth(texture, &width), kQ3Success);
    EXPECT_EQ(Q3Texture_GetHeight(texture, &height), kQ3Success);
    EXPECT_EQ(width, 8u);
    EXPECT_EQ(height, 2u);
    TQ3Mipmap got{};
    ASSERT_EQ(Q3MipmapTexture_GetMipmap(texture, &got), kQ3Success);
    EXPECT_TRUE(sameMipmap(got, mipmap)); // the unread entries too
    Q3Object_Dispose(got.image);
}

TEST_F(TextureApiTest, TextureCallsRefuseBadHandlesAndNullOutputs)
{
    const TQ3StoragePixmap pixmap = goodPixmap();
    const TQ3Mipmap mipmap = goodMipmap();
    TQ3TextureObject pixmapTexture = own(Q3PixmapTexture_New(&pixmap));
    TQ3TextureObject mipmapTexture = own(Q3MipmapTexture_New(&mipmap));
    for (const auto& [bad, error] : badTextures(nullptr)) {
        if (bad == nullptr && error != kQ3ErrorNULLParameter)
            continue;
        unsigned long size = 7;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Texture_GetType(bad), kQ3ObjectTypeInvalid), error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Texture_GetWidth(bad, &size), kQ3Failure), error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Texture_GetHeight(bad, &size), kQ3Failure), error);
        EXPECT_EQ(size, 7u);
    }
    for (const auto& [bad, error] : badTextures(mipmapTexture)) {
        TQ3StoragePixmap out{};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapTexture_GetPixmap(bad, &out), kQ3Failure), error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapTexture_SetPixmap(bad, &pixmap), kQ3Failure), error);
        EXPECT_EQ(out.image, nullptr);
    }
    for (const auto& [bad, error] : badTextures(pixmapTexture)) {
        TQ3Mipmap out{};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3MipmapTexture_GetMipmap(bad, &out), kQ3Failure), error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3MipmapTexture_SetMipmap(bad, &mipmap), kQ3Failure), error);
        EXPECT_EQ(out.image, nullptr);
    }
    EXPECT_Q3_ERROR(Q3Texture_GetWidth(pixmapTexture, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Texture_GetHeight(mipmapTexture, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3PixmapTexture_GetPixmap(pixmapTexture, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3PixmapTexture_SetPixmap(pixmapTexture, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3MipmapTexture_GetMipmap(mipmapTexture, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3MipmapTexture_SetMipmap(mipmapTexture, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapTexture_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MipmapTexture_New(nullptr), nullptr), kQ3ErrorNULLParameter);
}

// Each pixmap rule broken alone, in the header's order of checks.
std::vector<std::pair<std::function<void(TQ3StoragePixmap&)>, TQ3Error>> brokenPixmaps(TQ3Object notStorage)
{
    return {
        {[](TQ3StoragePixmap& p) { p.image = nullptr; }, kQ3ErrorNULLParameter},
        {[](TQ3StoragePixmap& p) { p.image = strayHandle(); }, kQ3ErrorInvalidObject},
        {[=](TQ3StoragePixmap& p) { p.image = notStorage; }, kQ3ErrorInvalidObjectType},
        {[](TQ3StoragePixmap& p) { setRaw(p.pixelType, 6); }, kQ3ErrorInvalidData},
        {[](TQ3StoragePixmap& p) { setRaw(p.pixelType, -1); }, kQ3ErrorInvalidData},
        {[](TQ3StoragePixmap& p) { setRaw(p.byteOrder, 2); }, kQ3ErrorInvalidData},
        {[](TQ3StoragePixmap& p) { setRaw(p.bitOrder, -3); }, kQ3ErrorInvalidData},
        {[](TQ3StoragePixmap& p) { p.pixelSize = 16; }, kQ3ErrorUnsupportedPixelDepth},
        {[](TQ3StoragePixmap& p) { p.pixelSize = ULONG_MAX; }, kQ3ErrorUnsupportedPixelDepth},
        {[](TQ3StoragePixmap& p) { p.width = 0; }, kQ3ErrorInvalidData},
        {[](TQ3StoragePixmap& p) { p.height = 0; }, kQ3ErrorInvalidData},
        {[](TQ3StoragePixmap& p) { p.width = 4097; p.rowBytes = 4 * 4097; }, kQ3ErrorInvalidData},
        {[](TQ3StoragePixmap& p) { p.height = ULONG_MAX; }, kQ3ErrorInvalidData},
        {[](TQ3StoragePixmap& p) { p.width = UINT32_MAX; }, kQ3ErrorInvalidData},
        {[](TQ3StoragePixmap& p) { p.rowBytes = 15; }, kQ3ErrorInvalidData},
        {[](TQ3StoragePixmap& p) { p.rowBytes = 2049; }, kQ3ErrorInvalidData}, // 2 rows > 4096 bytes
        {[](TQ3StoragePixmap& p) { p.rowBytes = ULONG_MAX; }, kQ3ErrorInvalidData},
    };
}

TEST_F(TextureApiTest, EachPixmapRuleIsCheckedAndASetLeavesTheTextureUnchanged)
{
    const TQ3StoragePixmap good = goodPixmap();
    TQ3TextureObject texture = own(Q3PixmapTexture_New(&good));
    const TQ3Uns32 edit = Q3Shared_GetEditIndex(texture);
    int i = 0;
    for (const auto& [breakIt, error] : brokenPixmaps(own(Q3AttributeSet_New()))) {
        TQ3StoragePixmap bad = good;
        breakIt(bad);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapTexture_New(&bad), nullptr) << "rule " << i, error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapTexture_SetPixmap(texture, &bad), kQ3Failure) << "rule " << i, error);
        TQ3StoragePixmap got{};
        ASSERT_EQ(Q3PixmapTexture_GetPixmap(texture, &got), kQ3Success);
        EXPECT_TRUE(samePixmap(got, good)) << "rule " << i;
        Q3Object_Dispose(got.image);
        EXPECT_EQ(Q3Shared_GetEditIndex(texture), edit) << "rule " << i;
        ++i;
    }
    // Exactly the storage's size is enough; the widest image is 4096.
    TQ3StoragePixmap exact = good;
    exact.rowBytes = 2048;
    EXPECT_EQ(Q3PixmapTexture_SetPixmap(texture, &exact), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(texture), edit);
    std::vector<unsigned char> wide(4096 * 3);
    TQ3StorageObject wideStorage = own(Q3MemoryStorage_New(wide.data(), static_cast<unsigned long>(wide.size())));
    const TQ3StoragePixmap widest{wideStorage, 4096, 1, 4096 * 3, 24, kQ3PixelTypeRGB24, kQ3EndianBig, kQ3EndianBig};
    EXPECT_NE(own(Q3PixmapTexture_New(&widest)), nullptr);
}

TEST_F(TextureApiTest, SetPixmapMovesTheStorageReference)
{
    const TQ3StoragePixmap good = goodPixmap();
    TQ3TextureObject texture = own(Q3PixmapTexture_New(&good));
    std::vector<unsigned char> other(64, 1);
    TQ3StorageObject storage = own(Q3MemoryStorage_New(other.data(), 64));
    const unsigned long oldCount = referenceCount(m_storage), newCount = referenceCount(storage);
    TQ3StoragePixmap next{storage, 2, 2, 8, 16, kQ3PixelTypeRGB16_565, kQ3EndianLittle, kQ3EndianBig};
    ASSERT_EQ(Q3PixmapTexture_SetPixmap(texture, &next), kQ3Success);
    EXPECT_EQ(referenceCount(m_storage), oldCount - 1);
    EXPECT_EQ(referenceCount(storage), newCount + 1);
    unsigned long width = 0;
    EXPECT_EQ(Q3Texture_GetWidth(texture, &width), kQ3Success);
    EXPECT_EQ(width, 2u);
    // A duplicate is a new texture sharing the storage.
    TQ3TextureObject copy = own(Q3Object_Duplicate(texture));
    ASSERT_NE(copy, nullptr);
    EXPECT_NE(copy, texture);
    TQ3StoragePixmap got{};
    ASSERT_EQ(Q3PixmapTexture_GetPixmap(copy, &got), kQ3Success);
    EXPECT_TRUE(samePixmap(got, next));
    Q3Object_Dispose(got.image);
}

TEST_F(TextureApiTest, EachMipmapRuleIsCheckedAndASetLeavesTheTextureUnchanged)
{
    const TQ3Mipmap good = goodMipmap();
    TQ3TextureObject texture = own(Q3MipmapTexture_New(&good));
    const TQ3Uns32 edit = Q3Shared_GetEditIndex(texture);
    TQ3Object notStorage = own(Q3AttributeSet_New());
    const std::vector<std::pair<std::function<void(TQ3Mipmap&)>, TQ3Error>> rules = {
        {[](TQ3Mipmap& m) { m.image = nullptr; }, kQ3ErrorNULLParameter},
        {[](TQ3Mipmap& m) { m.image = strayHandle(); }, kQ3ErrorInvalidObject},
        {[=](TQ3Mipmap& m) { m.image = notStorage; }, kQ3ErrorInvalidObjectType},
        {[](TQ3Mipmap& m) { setRaw(m.useMipmapping, 2); }, kQ3ErrorInvalidData},
        {[](TQ3Mipmap& m) { setRaw(m.pixelType, 7); }, kQ3ErrorInvalidData},
        {[](TQ3Mipmap& m) { setRaw(m.byteOrder, 5); }, kQ3ErrorInvalidData},
        {[](TQ3Mipmap& m) { setRaw(m.bitOrder, 5); }, kQ3ErrorInvalidData},
        {[](TQ3Mipmap& m) { m.reserved = 1; }, kQ3ErrorInvalidData},
        {[](TQ3Mipmap& m) { m.mipmaps[0].width = 0; }, kQ3ErrorInvalidData},
        {[](TQ3Mipmap& m) { m.mipmaps[0].height = UINT32_MAX; }, kQ3ErrorInvalidData},
        {[](TQ3Mipmap& m) { m.mipmaps[0].rowBytes = 15; }, kQ3ErrorInvalidData},
        {[](TQ3Mipmap& m) { m.mipmaps[0].offset = 4096 - 31; }, kQ3ErrorInvalidData},
        {[](TQ3Mipmap& m) { m.mipmaps[0].offset = ULONG_MAX; }, kQ3ErrorInvalidData},
        // Sides that are not powers of 2, with mipmapping.
        {[](TQ3Mipmap& m) { m.mipmaps[0].width = 6; }, kQ3ErrorInvalidData},
        {[](TQ3Mipmap& m) { m.mipmaps[0].height = 3; }, kQ3ErrorInvalidData},
        // The chain: the first image after the first, the last, each in size
        // and in place.
        {[](TQ3Mipmap& m) { m.mipmaps[1].width = 8; }, kQ3ErrorInvalidData},
        {[](TQ3Mipmap& m) { m.mipmaps[1].height = 2; }, kQ3ErrorInvalidData},
        {[](TQ3Mipmap& m) { m.mipmaps[3].width = 0; }, kQ3ErrorInvalidData},
        {[](TQ3Mipmap& m) { m.mipmaps[3].rowBytes = 1; }, kQ3ErrorInvalidData},
        {[](TQ3Mipmap& m) { m.mipmaps[3].offset = 4095; }, kQ3ErrorInvalidData},
        {[](TQ3Mipmap& m) { m.mipmaps[2].offset = UINT32_MAX; }, kQ3ErrorInvalidData},
    };
    int i = 0;
    for (const auto& [breakIt, error] : rules) {
        TQ3Mipmap bad = good;
        breakIt(bad);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3MipmapTexture_New(&bad), nullptr) << "rule " << i, error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3MipmapTexture_SetMipmap(texture, &bad), kQ3Failure) << "rule " << i, error);
        TQ3Mipmap got{};
        ASSERT_EQ(Q3MipmapTexture_GetMipmap(texture, &got), kQ3Success);
        EXPECT_TRUE(sameMipmap(got, good)) << "rule " << i;
        Q3Object_Dispose(got.image);
        EXPECT_EQ(Q3Shared_GetEditIndex(texture), edit) << "rule " << i;
        ++i;
    }
    // Without mipmapping only the first image is read: any size, any later
    // entries.
    TQ3Mipmap single = good;
    single.useMipmapping = kQ3False;
    single.mipmaps[0] = TQ3MipmapImage{6, 3, 12, 100};
    single.mipmaps[1] = TQ3MipmapImage{0, 0, 0, ULONG_MAX};
    single.mipmaps[31] = TQ3MipmapImage{ULONG_MAX, ULONG_MAX, ULONG_MAX, ULONG_MAX};
    ASSERT_EQ(Q3MipmapTexture_SetMipmap(texture, &single), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(texture), edit);
    unsigned long width = 0;
    EXPECT_EQ(Q3Texture_GetWidth(texture, &width), kQ3Success);
    EXPECT_EQ(width, 6u);
    // A 1 x 1 first image with mipmapping is the whole chain; a 4096-wide
    // one needs 13 images.
    TQ3Mipmap dot = good;
    dot.mipmaps[0] = TQ3MipmapImage{1, 1, 2, 0};
    dot.mipmaps[1] = TQ3MipmapImage{0, 0, 0, 0};
    EXPECT_NE(own(Q3MipmapTexture_New(&dot)), nullptr);
    std::vector<unsigned char> wide(3 * 8192);
    TQ3StorageObject wideStorage = own(Q3MemoryStorage_New(wide.data(), static_cast<unsigned long>(wide.size())));
    TQ3Mipmap widest = good;
    widest.image = wideStorage;
    widest.pixelType = kQ3PixelTypeRGB24;
    unsigned long offset = 0;
    for (unsigned level = 0; level < 13; ++level) {
        const unsigned long w = 4096ul >> level;
        widest.mipmaps[level] = TQ3MipmapImage{w, 1, 3 * w, offset};
        offset += 3 * w;
    }
    widest.mipmaps[13] = TQ3MipmapImage{0, 0, 0, 0};
    EXPECT_NE(own(Q3MipmapTexture_New(&widest)), nullptr);
    widest.mipmaps[12].width = 2; // the last level wrong
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MipmapTexture_New(&widest), nullptr), kQ3ErrorInvalidData);
}

// ---- The texture shader -------------------------------------------------------

TEST_F(TextureApiTest, TextureShaderHasItsTypeChainAndHoldsItsTexture)
{
    const TQ3StoragePixmap pixmap = goodPixmap();
    TQ3TextureObject texture = own(Q3PixmapTexture_New(&pixmap));
    const unsigned long before = referenceCount(texture);
    TQ3ShaderObject shader = own(Q3TextureShader_New(texture));
    ASSERT_NE(shader, nullptr);
    EXPECT_EQ(referenceCount(texture), before + 1);
    EXPECT_EQ(Q3Shared_GetType(shader), kQ3SharedTypeShape);
    EXPECT_EQ(Q3Shape_GetType(shader), kQ3ShapeTypeShader);
    EXPECT_EQ(Q3Shader_GetType(shader), kQ3ShaderTypeSurface);
    EXPECT_EQ(Q3SurfaceShader_GetType(shader), kQ3SurfaceShaderTypeTexture);
    EXPECT_EQ(Q3Object_GetLeafType(shader), kQ3SurfaceShaderTypeTexture);
    TQ3TextureObject got = nullptr;
    ASSERT_EQ(Q3TextureShader_GetTexture(shader, &got), kQ3Success);
    EXPECT_EQ(got, texture);
    EXPECT_EQ(referenceCount(texture), before + 2);
    Q3Object_Dispose(got);

    // SetTexture moves the reference; a failed one changes nothing.
    const TQ3Mipmap mipmap = goodMipmap();
    TQ3TextureObject other = own(Q3MipmapTexture_New(&mipmap));
    const TQ3Uns32 edit = Q3Shared_GetEditIndex(shader);
    for (const auto& [bad, error] : badTextures(own(Q3PhongIllumination_New()))) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TextureShader_SetTexture(shader, bad), kQ3Failure), error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TextureShader_New(bad), nullptr), error);
    }
    EXPECT_EQ(Q3Shared_GetEditIndex(shader), edit);
    ASSERT_EQ(Q3TextureShader_SetTexture(shader, other), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(shader), edit);
    EXPECT_EQ(referenceCount(texture), before);
    ASSERT_EQ(Q3TextureShader_GetTexture(shader, &got), kQ3Success);
    EXPECT_EQ(got, other);
    Q3Object_Dispose(got);

    // A duplicate has its own copy of the texture and the uv settings.
    ASSERT_EQ(Q3Shader_SetUBoundary(shader, kQ3ShaderUVBoundaryClamp), kQ3Success);
    TQ3ShaderObject copy = own(Q3Object_Duplicate(shader));
    ASSERT_NE(copy, nullptr);
    TQ3TextureObject copied = nullptr;
    ASSERT_EQ(Q3TextureShader_GetTexture(copy, &copied), kQ3Success);
    EXPECT_NE(copied, other);
    EXPECT_EQ(Q3Texture_GetType(copied), kQ3TextureTypeMipmap);
    Q3Object_Dispose(copied);
    TQ3ShaderUVBoundary boundary = kQ3ShaderUVBoundaryWrap;
    EXPECT_EQ(Q3Shader_GetUBoundary(copy, &boundary), kQ3Success);
    EXPECT_EQ(boundary, kQ3ShaderUVBoundaryClamp);
}

TEST_F(TextureApiTest, TextureShaderCallsRefuseBadHandles)
{
    const TQ3StoragePixmap pixmap = goodPixmap();
    TQ3TextureObject texture = own(Q3PixmapTexture_New(&pixmap));
    TQ3ShaderObject shader = own(Q3TextureShader_New(texture));
    TQ3ShaderObject phong = own(Q3PhongIllumination_New());
    const std::vector<std::pair<TQ3Object, TQ3Error>> badShaders = {
        {nullptr, kQ3ErrorNULLParameter},      {strayHandle(), kQ3ErrorInvalidObject},
        {texture, kQ3ErrorInvalidObjectType},  {phong, kQ3ErrorInvalidObjectType},
        {deadObject(), kQ3ErrorInvalidObject}};
    for (const auto& [bad, error] : badShaders) {
        TQ3TextureObject out = nullptr;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TextureShader_GetTexture(bad, &out), kQ3Failure), error);
        EXPECT_EQ(out, nullptr);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TextureShader_SetTexture(bad, texture), kQ3Failure), error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3SurfaceShader_GetType(bad), kQ3ObjectTypeInvalid), error);
    }
    EXPECT_Q3_ERROR(Q3TextureShader_GetTexture(shader, nullptr), kQ3ErrorNULLParameter);
}

} // namespace
