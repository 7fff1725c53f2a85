// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The interactive renderer's texture filters (Q3InteractiveRenderer_
// SetRAVETextureFilter: Fast nearest, Mid bilinear, Best trilinear over a
// mipmap chain), pixel by pixel against the filters' formulas evaluated here.
//
// The quad spans world x 0..2 and y -0.5..1.5, which the orthographic camera
// maps onto pixels 8..39 across and down of a 64 x 48 image (16 pixels a
// world unit), so pixel (px, py) of the quad sees
//   s = (px - 8 + 1/2) / 32,  t = (py - 8 + 1/2) / 32
// (t down the image from its top row) times the uv transform's scale k.
//   bilinear: a = s W - 1/2, b = t H - 1/2; the texels (floor a, floor b) and
//             their right and lower neighbours (wrapped), weighted by
//             (1 - fa)(1 - fb), fa (1 - fb), (1 - fa) fb, fa fb;
//   trilinear: lambda = log2(W k / 32) for a W-texel-wide square texture
//             (texels per pixel), bilinear in images floor(lambda) and the
//             next, mixed by lambda's fraction (OpenGL 2.1, 3.8.8).
// llvmpipe keeps 8 bits of each weight's fraction, so a channel may differ by
// a unit or two from the exact value; the tolerances say how many.

#include "OwningApiTest.h"
#include "QuadMesh.h"
#include "RenderTestSupport.h"
#include "TextureTestSupport.h"

#include "QD3DRenderer.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace {

using namespace q3test;

constexpr int kWidth = 64, kHeight = 48;
constexpr int kQuad0 = 8, kQuadSide = 32;

// RAVE's kQATextureFilter_Fast, _Mid, _Best (RAVE.h).
constexpr unsigned long kFast = 0, kMid = 1, kBest = 2;

struct Colour {
    double r = 0, g = 0, b = 0;
};

Colour mix(const Colour& a, const Colour& b, double f)
{
    return Colour{a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f};
}

// An RGB24 image of w x h texels, row 0 the top row.
struct Image {
    int w = 0, h = 0;
    std::vector<Colour> texels;
    Colour at(int column, int row) const { return texels[std::size_t(row) * w + column]; }
};

// A 4 x 4 image of distinct texels.
Image distinctTexels()
{
    Image image{4, 4, {}};
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column)
            image.texels.push_back(Colour{double(20 + 70 * column), double(230 - 60 * row),
                                          double((37 * (row * 4 + column)) % 256)});
    return image;
}

Image solid(int side, const Colour& colour)
{
    return Image{side, side, std::vector<Colour>(std::size_t(side) * side, colour)};
}

// Bilinear sample at (s, t), wrapped or clamped to the edge.
Colour bilinear(const Image& image, double s, double t, bool clamp)
{
    const double a = s * image.w - 0.5, b = t * image.h - 0.5;
    const double fa = a - std::floor(a), fb = b - std::floor(b);
    const int i0 = int(std::floor(a)), j0 = int(std::floor(b));
    const auto column = [&](int i) { return clamp ? std::min(std::max(i, 0), image.w - 1) : ((i % image.w) + image.w) % image.w; };
    const auto row = [&](int j) { return clamp ? std::min(std::max(j, 0), image.h - 1) : ((j % image.h) + image.h) % image.h; };
    const Colour top = mix(image.at(column(i0), row(j0)), image.at(column(i0 + 1), row(j0)), fa);
    const Colour bottom = mix(image.at(column(i0), row(j0 + 1)), image.at(column(i0 + 1), row(j0 + 1)), fa);
    return mix(top, bottom, fb);
}

Colour nearest(const Image& image, double s, double t)
{
    const int i = ((int(std::floor(s * image.w)) % image.w) + image.w) % image.w;
    const int j = ((int(std::floor(t * image.h)) % image.h) + image.h) % image.h;
    return image.at(i, j);
}

class TextureFilterRenderTest : public OwningApiTest {
protected:
    // A texture of `images` (one: a pixmap texture; more: a mipmap chain
    // with useMipmapping) stored as RGB24 one after another.
    TQ3ShaderObject shaderOf(const std::vector<Image>& images, double scale = 1.0, bool clamp = false)
    {
        std::vector<unsigned char>& bytes = m_bytes.emplace_back();
        std::vector<unsigned long> offsets;
        for (const Image& image : images) {
            offsets.push_back(bytes.size());
            for (const Colour& c : image.texels)
                bytes.insert(bytes.end(), {(unsigned char)c.r, (unsigned char)c.g, (unsigned char)c.b});
        }
        TQ3StorageObject storage = own(Q3MemoryStorage_New(bytes.data(), static_cast<unsigned long>(bytes.size())));
        TQ3TextureObject texture = nullptr;
        if (images.size() == 1) {
            const TQ3StoragePixmap pixmap{storage,      (unsigned long)images[0].w, (unsigned long)images[0].h,
                                          3ul * images[0].w, 24, kQ3PixelTypeRGB24, kQ3EndianBig, kQ3EndianBig};
            texture = own(Q3PixmapTexture_New(&pixmap));
        } else {
            TQ3Mipmap mipmap = q3test::bigEndianMipmap(storage, kQ3PixelTypeRGB24, true, {});
            for (std::size_t i = 0; i < images.size(); ++i)
                mipmap.mipmaps[i] = TQ3MipmapImage{(unsigned long)images[i].w, (unsigned long)images[i].h,
                                                   3ul * images[i].w, offsets[i]};
            texture = own(Q3MipmapTexture_New(&mipmap));
        }
        EXPECT_NE(texture, nullptr);
        TQ3ShaderObject shader = own(Q3TextureShader_New(texture));
        TQ3Matrix3x3 m{{{float(scale), 0, 0}, {0, float(scale), 0}, {0, 0, 1}}};
        EXPECT_EQ(Q3Shader_SetUVTransform(shader, &m), kQ3Success);
        if (clamp) {
            EXPECT_EQ(Q3Shader_SetUBoundary(shader, kQ3ShaderUVBoundaryClamp), kQ3Success);
            EXPECT_EQ(Q3Shader_SetVBoundary(shader, kQ3ShaderUVBoundaryClamp), kQ3Success);
        }
        return shader;
    }

    // The quad, unlit, with uv (0, 0) at world (0, -0.5) and (1, 1) at (2, 1.5).
    TQ3GeometryObject quad()
    {
        const q3test::QuadMesh quad({{0, -0.5f, 0}, {2, -0.5f, 0}, {2, 1.5f, 0}, {0, 1.5f, 0}},
                                    {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
        TQ3GeometryObject mesh = own(quad.create());
        EXPECT_NE(mesh, nullptr);
        return mesh;
    }

    // The quad drawn with `shader` by an interactive renderer whose RAVE
    // filter is `filter` (or left as a new renderer has it).
    Pixmap render(TQ3ShaderObject shader, const unsigned long* filter)
    {
        Pixmap image(kWidth, kHeight);
        TQ3GeometryObject mesh = quad();
        TestView view(image.pixmap(), kQ3RendererTypeInteractive);
        if (filter != nullptr) {
            TQ3RendererObject renderer = nullptr;
            EXPECT_EQ(Q3View_GetRenderer(view.view(), &renderer), kQ3Success);
            EXPECT_EQ(Q3InteractiveRenderer_SetRAVETextureFilter(renderer, *filter), kQ3Success);
            Q3Object_Dispose(renderer);
        }
        EXPECT_EQ(view.render([&](TQ3ViewObject v) {
            Q3Shader_Submit(shader, v);
            Q3Geometry_Submit(mesh, v);
        }),
                  kQ3ViewStatusDone);
        return image;
    }

    // Every pixel of the quad against expected(s, t) (s, t before the uv
    // transform's scale), within `tolerance` per channel; returns the
    // largest difference seen.
    int expectPixels(const Pixmap& image, const std::function<Colour(double, double)>& expected, int tolerance,
                     const std::string& what)
    {
        int worst = 0;
        for (int py = kQuad0; py < kQuad0 + kQuadSide; ++py)
            for (int px = kQuad0; px < kQuad0 + kQuadSide; ++px) {
                const double s = (px - kQuad0 + 0.5) / kQuadSide, t = (py - kQuad0 + 0.5) / kQuadSide;
                const Colour want = expected(s, t);
                const Rgba got = image.at(px, py);
                const int d = std::max({std::abs(got.r - int(std::lround(want.r))),
                                        std::abs(got.g - int(std::lround(want.g))),
                                        std::abs(got.b - int(std::lround(want.b)))});
                worst = std::max(worst, d);
                EXPECT_LE(d, tolerance) << what << ": pixel (" << px << ", " << py << ") is " << got.r << " "
                                        << got.g << " " << got.b << ", expected " << want.r << " " << want.g << " "
                                        << want.b;
            }
        return worst;
    }

    std::vector<std::vector<unsigned char>> m_bytes;
};

// The level colours of a 64 x 64 mipmap chain: far apart in every channel,
// so that a wrong level or weight shows.
const Colour kLevelColours[7] = {{250, 10, 10},  {10, 250, 10}, {10, 10, 250}, {250, 250, 10},
                                 {10, 250, 250}, {250, 10, 250}, {128, 128, 128}};

std::vector<Image> solidChain()
{
    std::vector<Image> chain;
    for (int level = 0, side = 64; side >= 1; ++level, side /= 2)
        chain.push_back(solid(side, kLevelColours[level]));
    return chain;
}

TEST_F(TextureFilterRenderTest, ANewRendererSamplesTheNearestTexelAsRAVEsFastFilter)
{
    unsigned long filter = 99;
    TQ3RendererObject renderer = own(Q3Renderer_NewFromType(kQ3RendererTypeInteractive));
    ASSERT_EQ(Q3InteractiveRenderer_GetRAVETextureFilter(renderer, &filter), kQ3Success);
    EXPECT_EQ(filter, kFast);
    // Magnified 8 times: each pixel shows the texel its centre falls in.
    const Image image = distinctTexels();
    TQ3ShaderObject shader = shaderOf({image});
    const auto expected = [&](double s, double t) { return nearest(image, s, t); };
    EXPECT_EQ(expectPixels(render(shader, nullptr), expected, 0, "default"), 0);
    EXPECT_EQ(expectPixels(render(shader, &kFast), expected, 0, "fast"), 0);
    // A value RAVE does not define draws as the default.
    const unsigned long unknown = 7;
    EXPECT_EQ(expectPixels(render(shader, &unknown), expected, 0, "7"), 0);
}

TEST_F(TextureFilterRenderTest, MidFiltersBilinearlyBetweenTheFourNearestTexels)
{
    const Image image = distinctTexels();
    const Pixmap wrapped = render(shaderOf({image}), &kMid);
    const int worst = expectPixels(wrapped, [&](double s, double t) { return bilinear(image, s, t, false); }, 2,
                                   "wrapped");
    // Between two texels: the formula, not the nearest texel.
    EXPECT_LE(worst, 2);
    const Pixmap clamped = render(shaderOf({image}, 1.0, true), &kMid);
    expectPixels(clamped, [&](double s, double t) { return bilinear(image, s, t, true); }, 2, "clamped");
    // Scaled by the uv transform (1.5): the filter sees the transformed uv,
    // v scaled from the image's bottom (t = 1 - v).
    const Pixmap scaled = render(shaderOf({image}, 1.5), &kMid);
    expectPixels(scaled, [&](double s, double t) { return bilinear(image, 1.5 * s, 1.0 - 1.5 * (1.0 - t), false); },
                 2, "scaled by 1.5");
}

TEST_F(TextureFilterRenderTest, MidReadsOnlyTheFirstImageOfAMipmap)
{
    // 64 texels over 32 pixels: minified twice, but Mid has no levels.
    const Pixmap image = render(shaderOf(solidChain()), &kMid);
    expectPixels(image, [](double, double) { return kLevelColours[0]; }, 0, "mid, minified");
}

TEST_F(TextureFilterRenderTest, BestMixesTheTwoMipmapLevelsAroundTheLevelOfDetail)
{
    // lambda = log2(64 k / 32) = 1 + log2(k). Every pixel must lie on the
    // segment between the colours of images floor(lambda) and the next
    // (within 3 per channel), at a fraction within 0.05 of lambda's: OpenGL
    // lets an implementation approximate the scale factor and its log2
    // (OpenGL 2.1, 3.8.8), and llvmpipe's approximation is off by up to 0.042
    // between powers of two (exact at them and half-way).
    const double exponents[] = {-1.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0};
    for (double e : exponents) {
        const double k = std::pow(2.0, e);
        const double lambda = 1.0 + e;
        const int level = lambda <= 0.0 ? 0 : int(std::floor(lambda));
        const double f = lambda <= 0.0 ? 0.0 : lambda - level;
        const Colour a = kLevelColours[level], b = kLevelColours[level + 1];
        const Pixmap image = render(shaderOf(solidChain(), k), &kBest);
        int wrong = 0;
        for (int py = kQuad0; py < kQuad0 + kQuadSide; ++py)
            for (int px = kQuad0; px < kQuad0 + kQuadSide; ++px) {
                const Rgba c = image.at(px, py);
                const double d[3] = {b.r - a.r, b.g - a.g, b.b - a.b};
                const double g[3] = {c.r - a.r, c.g - a.g, c.b - a.b};
                const double got = (g[0] * d[0] + g[1] * d[1] + g[2] * d[2]) / (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                double off = 0.0;
                for (int i = 0; i < 3; ++i)
                    off = std::max(off, std::abs(g[i] - got * d[i]));
                if ((std::abs(got - f) <= 0.05 && off <= 3.0) || wrong++ > 0)
                    continue;
                ADD_FAILURE() << "lambda " << lambda << ": pixel (" << px << ", " << py << ") is " << c.r << " "
                              << c.g << " " << c.b << ": " << got << " of the way from image " << level
                              << " to the next (" << off << " off that line), expected " << f;
            }
    }
}

TEST_F(TextureFilterRenderTest, BestFiltersBilinearlyWithinEachLevel)
{
    // A 8 x 8 level 0 of distinct texels (its 4 x 4 quarter repeated) over a
    // chain of solid images; k = 2: 16 texels over 32 pixels, lambda -1, so
    // the first image is magnified and filtered bilinearly.
    Image first{8, 8, {}};
    const Image quarter = distinctTexels();
    for (int row = 0; row < 8; ++row)
        for (int column = 0; column < 8; ++column)
            first.texels.push_back(quarter.at(column % 4, row % 4));
    std::vector<Image> chain = {first, solid(4, kLevelColours[1]), solid(2, kLevelColours[2]),
                                solid(1, kLevelColours[3])};
    const Pixmap image = render(shaderOf(chain, 2.0), &kBest);
    expectPixels(image, [&](double s, double t) { return bilinear(first, 2.0 * s, 1.0 - 2.0 * (1.0 - t), false); }, 2,
                 "best, magnified");
}

TEST_F(TextureFilterRenderTest, BestOnATextureOfOneImageFiltersBilinearly)
{
    const Image image = distinctTexels();
    const Pixmap drawn = render(shaderOf({image}), &kBest);
    expectPixels(drawn, [&](double s, double t) { return bilinear(image, s, t, false); }, 2, "best, one image");
}

TEST_F(TextureFilterRenderTest, AMipmapWithoutUseMipmappingIsOneImageUnderBest)
{
    std::vector<Image> chain = solidChain();
    std::vector<unsigned char>& bytes = m_bytes.emplace_back();
    for (const Colour& c : chain[0].texels)
        bytes.insert(bytes.end(), {(unsigned char)c.r, (unsigned char)c.g, (unsigned char)c.b});
    TQ3StorageObject storage = own(Q3MemoryStorage_New(bytes.data(), static_cast<unsigned long>(bytes.size())));
    const TQ3Mipmap mipmap = q3test::bigEndianMipmap(storage, kQ3PixelTypeRGB24, false, {{64, 64, 192, 0}});
    TQ3TextureObject texture = own(Q3MipmapTexture_New(&mipmap));
    ASSERT_NE(texture, nullptr);
    TQ3ShaderObject shader = own(Q3TextureShader_New(texture));
    expectPixels(render(shader, &kBest), [](double, double) { return kLevelColours[0]; }, 0, "one image");
}

// The texture's alpha is the level's the filter reads, also where the first
// image is opaque and a later one is not (the renderer stores a texture
// without alpha only when every image it can read is opaque): drawn under
// Best at level 1 exactly (k = 1: 64 texels over 32 pixels), the image's
// alpha is that level's, as the draw writes it (a texture whose first image
// is opaque draws opaque, unblended).
TEST_F(TextureFilterRenderTest, BestReadsTheAlphaOfTheLevelItDraws)
{
    constexpr int kLevelAlpha = 96;
    std::vector<unsigned char>& bytes = m_bytes.emplace_back();
    std::vector<TQ3MipmapImage> images;
    for (int level = 0, side = 64; side >= 1; ++level, side /= 2) {
        images.push_back(TQ3MipmapImage{(unsigned long)side, (unsigned long)side, 4ul * side, bytes.size()});
        const Colour c = kLevelColours[level];
        const unsigned char alpha = level == 0 ? 255 : kLevelAlpha;
        for (int i = 0; i < side * side; ++i)
            bytes.insert(bytes.end(), {alpha, (unsigned char)c.r, (unsigned char)c.g, (unsigned char)c.b});
    }
    TQ3StorageObject storage = own(Q3MemoryStorage_New(bytes.data(), static_cast<unsigned long>(bytes.size())));
    TQ3Mipmap mipmap = q3test::bigEndianMipmap(storage, kQ3PixelTypeARGB32, true, {});
    for (std::size_t i = 0; i < images.size(); ++i)
        mipmap.mipmaps[i] = images[i];
    TQ3TextureObject texture = own(Q3MipmapTexture_New(&mipmap));
    ASSERT_NE(texture, nullptr);
    TQ3ShaderObject shader = own(Q3TextureShader_New(texture));
    const Pixmap image = render(shader, &kBest);
    expectPixels(image, [](double, double) { return kLevelColours[1]; }, 3, "level 1");
    int wrong = 0;
    for (int py = kQuad0; py < kQuad0 + kQuadSide; ++py)
        for (int px = kQuad0; px < kQuad0 + kQuadSide; ++px)
            wrong += std::abs(image.at(px, py).a - kLevelAlpha) > 3;
    EXPECT_EQ(wrong, 0) << "pixels whose alpha is not level 1's";
    // Under Mid the first image alone is read: opaque.
    const Pixmap first = render(shader, &kMid);
    EXPECT_EQ(first.at(kQuad0 + 5, kQuad0 + 5).a, 255);
}

} // namespace
