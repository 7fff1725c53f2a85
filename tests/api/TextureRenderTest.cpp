// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Texture shaders drawn by the interactive renderer: a TriMesh quad whose
// corners carry uv (0, 0) .. (1, 1) shows a texture of distinct texels, each
// pixel checked against the texel this file computes from the pixel
// centre's uv (QD3DShader.h: (0, 0) the image's bottom left, nearest
// sampling, wrap or clamp, the uv transform as a row-vector affine map).
// Pixels whose uv lies within a tenth of a texel of a texel edge are skipped:
// there the rasterizer's rounding, not the rule, decides.

#include "GeometryTestSupport.h"
#include "InteractiveRender.h"
#include "OwningApiTest.h"
#include "QuadMesh.h"
#include "RenderTestSupport.h"
#include "TextureTestSupport.h"

#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"
#include "QD3DStyle.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace {

using namespace q3test;

// 40 x 30 pixels under listing1OrthographicCamera: world x -0.5..3.5 and y
// 2..-1 across them. The quad spans x 0..3 and y -0.5..1.5: pixels 5..34
// across and 5..24 down.
constexpr int kWidth = 40, kHeight = 30;
constexpr float kX0 = 0.0f, kX1 = 3.0f, kY0 = -0.5f, kY1 = 1.5f;

double worldX(int px)
{
    return -0.5 + (px + 0.5) / kWidth * 4.0;
}
double worldY(int py)
{
    return 2.0 - (py + 0.5) / kHeight * 3.0;
}

// A 4 x 2 texture of distinct RGB24 texels, row 0 the top row.
constexpr int kTexW = 4, kTexH = 2;
Rgba texel(int column, int row)
{
    return Rgba{30 + 50 * column, 200 - 90 * row, 60 + 40 * column + 20 * row, 255};
}

std::vector<unsigned char> textureBytes()
{
    std::vector<unsigned char> bytes;
    for (int row = 0; row < kTexH; ++row)
        for (int column = 0; column < kTexW; ++column) {
            const Rgba c = texel(column, row);
            bytes.insert(bytes.end(), {(unsigned char)c.r, (unsigned char)c.g, (unsigned char)c.b});
        }
    return bytes;
}

struct UVMap {
    float m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    bool clampU = false, clampV = false;
};

// The texel a pixel should show, or false where the pixel is outside the
// quad or too near a texel edge to say.
bool expectedTexel(int px, int py, const UVMap& map, Rgba& out)
{
    const double x = worldX(px), y = worldY(py);
    const double u = (x - kX0) / (kX1 - kX0), v = (y - kY0) / (kY1 - kY0);
    if (u < 0.02 || u > 0.98 || v < 0.02 || v > 0.98)
        return false;
    const double tu = u * map.m[0][0] + v * map.m[1][0] + map.m[2][0];
    const double tv = u * map.m[0][1] + v * map.m[1][1] + map.m[2][1];
    // Texel coordinates: column from the left, row from the top.
    double cs = tu * kTexW, rs = (1.0 - tv) * kTexH;
    const auto nearEdge = [](double t) { return std::fabs(t - std::round(t)) < 0.1; };
    if (map.clampU)
        cs = std::min(std::max(cs, 0.5), kTexW - 0.5);
    if (map.clampV)
        rs = std::min(std::max(rs, 0.5), kTexH - 0.5);
    if (nearEdge(cs) || nearEdge(rs))
        return false;
    const int column = int(((int(std::floor(cs)) % kTexW) + kTexW) % kTexW);
    const int row = int(((int(std::floor(rs)) % kTexH) + kTexH) % kTexH);
    out = texel(column, row);
    return true;
}

class TextureRenderTest : public OwningApiTest, protected InteractiveRendering<kWidth, kHeight> {
protected:
    void SetUp() override
    {
        OwningApiTest::SetUp();
        m_bytes = textureBytes();
        m_storage = own(Q3MemoryStorage_New(m_bytes.data(), static_cast<unsigned long>(m_bytes.size())));
        const TQ3StoragePixmap pixmap{m_storage, kTexW, kTexH, 3 * kTexW, 24, kQ3PixelTypeRGB24, kQ3EndianBig,
                                      kQ3EndianBig};
        m_texture = own(Q3PixmapTexture_New(&pixmap));
        ASSERT_NE(m_texture, nullptr);
        m_shader = own(Q3TextureShader_New(m_texture));
        ASSERT_NE(m_shader, nullptr);
    }

    // The quad as a TriMesh with a uv per corner (kQ3AttributeTypeSurfaceUV
    // or another uv type) and a red diffuse colour the texture replaces.
    TQ3GeometryObject quad(TQ3AttributeType uvType = kQ3AttributeTypeSurfaceUV)
    {
        q3test::QuadMesh quad({{kX0, kY0, 0}, {kX1, kY0, 0}, {kX1, kY1, 0}, {kX0, kY1, 0}},
                              {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, false, uvType);
        quad.data.triMeshAttributeSet = own(colorSet(1, 0, 0));
        TQ3GeometryObject mesh = own(quad.create());
        EXPECT_NE(mesh, nullptr);
        return mesh;
    }

    // Every pixel the rule decides (identity uv map) shows its texel, or its
    // inverse (255 minus each channel).
    void expectFrame(const Pixmap& image, bool inverted, const std::string& what)
    {
        int checked = 0;
        for (int py = 0; py < kHeight; ++py)
            for (int px = 0; px < kWidth; ++px) {
                Rgba want{};
                if (!expectedTexel(px, py, UVMap{}, want))
                    continue;
                ++checked;
                if (inverted)
                    want = Rgba{255 - want.r, 255 - want.g, 255 - want.b, 255};
                const Rgba got = image.at(px, py);
                EXPECT_TRUE(got.r == want.r && got.g == want.g && got.b == want.b)
                    << what << ": pixel (" << px << ", " << py << ") is " << got.r << " " << got.g << " " << got.b
                    << ", expected " << want.r << " " << want.g << " " << want.b;
            }
        EXPECT_GT(checked, 300) << what;
    }

    // Frames of one view, which keeps what its renderer cached from frame
    // to frame (a new view's renderer would start afresh).
    struct Frames {
        Pixmap image{kWidth, kHeight};
        TestView view{image.pixmap(), kQ3RendererTypeInteractive};

        // A frame of `mesh` drawn with `shader`.
        Pixmap draw(TQ3GeometryObject mesh, TQ3ShaderObject shader)
        {
            EXPECT_EQ(view.render([&](TQ3ViewObject v) {
                EXPECT_EQ(Q3Shader_Submit(shader, v), kQ3Success);
                EXPECT_EQ(Q3Geometry_Submit(mesh, v), kQ3Success);
            }),
                      kQ3ViewStatusDone);
            return image;
        }
    };

    // Every pixel the rule decides shows its texel scaled by `scale` (within
    // `tolerance` per channel); returns how many were checked.
    int expectTexels(const Pixmap& image, const UVMap& map, const std::string& what, double scale = 1.0,
                     int tolerance = 0)
    {
        int checked = 0;
        for (int py = 0; py < kHeight; ++py)
            for (int px = 0; px < kWidth; ++px) {
                Rgba want{};
                if (!expectedTexel(px, py, map, want))
                    continue;
                ++checked;
                const Rgba got = image.at(px, py);
                const auto near = [&](int g, int w) { return std::abs(g - int(std::lround(w * scale))) <= tolerance; };
                EXPECT_TRUE(near(got.r, want.r) && near(got.g, want.g) && near(got.b, want.b))
                    << what << ": pixel (" << px << ", " << py << ") is " << got.r << " " << got.g << " " << got.b
                    << ", expected " << want.r * scale << " " << want.g * scale << " " << want.b * scale;
            }
        return checked;
    }

    std::vector<unsigned char> m_bytes;
    TQ3StorageObject m_storage = nullptr;
    TQ3TextureObject m_texture = nullptr;
    TQ3ShaderObject m_shader = nullptr;
};

TEST_F(TextureRenderTest, UnlitQuadShowsEachTexelWhereItsUVFalls)
{
    TQ3GeometryObject mesh = quad();
    const Pixmap image = render([&](TQ3ViewObject v) {
        EXPECT_EQ(Q3Shader_Submit(m_shader, v), kQ3Success);
        EXPECT_EQ(Q3Geometry_Submit(mesh, v), kQ3Success);
    });
    EXPECT_GT(expectTexels(image, UVMap{}, "identity"), 300);
}

TEST_F(TextureRenderTest, ASurfaceShaderAttributeTexturesAsTheShaderDoes)
{
    TQ3GeometryObject mesh = quad();
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    ASSERT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceShader, &m_shader), kQ3Success);
    const Pixmap fromSet = render([&](TQ3ViewObject v) {
        EXPECT_EQ(Q3AttributeSet_Submit(set, v), kQ3Success);
        EXPECT_EQ(Q3Geometry_Submit(mesh, v), kQ3Success);
    });
    EXPECT_GT(expectTexels(fromSet, UVMap{}, "Q3AttributeSet_Submit"), 300);
    const Pixmap fromAttribute = render([&](TQ3ViewObject v) {
        EXPECT_EQ(Q3Attribute_Submit(kQ3AttributeTypeSurfaceShader, &m_shader, v), kQ3Success);
        EXPECT_EQ(Q3Geometry_Submit(mesh, v), kQ3Success);
    });
    EXPECT_GT(expectTexels(fromAttribute, UVMap{}, "Q3Attribute_Submit"), 300);
}

TEST_F(TextureRenderTest, WithoutTheShaderTheQuadKeepsItsDiffuseColour)
{
    TQ3GeometryObject mesh = quad();
    const Pixmap image = render([&](TQ3ViewObject v) { Q3Geometry_Submit(mesh, v); });
    const Rgba c = image.at(20, 15);
    EXPECT_EQ(c.r, 255);
    EXPECT_EQ(c.g, 0);
    EXPECT_EQ(c.b, 0);
}

TEST_F(TextureRenderTest, UVTransformScalesAndTranslatesTheTexture)
{
    TQ3GeometryObject mesh = quad();
    UVMap map;
    map.m[0][0] = 2.0f;  // u' = 2u + 0.25
    map.m[1][1] = 1.5f;  // v' = 1.5v - 0.25
    map.m[2][0] = 0.25f;
    map.m[2][1] = -0.25f;
    TQ3Matrix3x3 matrix;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            matrix.value[i][j] = map.m[i][j];
    ASSERT_EQ(Q3Shader_SetUVTransform(m_shader, &matrix), kQ3Success);
    const Pixmap image = renderUnder(m_shader, mesh);
    EXPECT_GT(expectTexels(image, map, "wrapped"), 200);

    // Clamped in u: right of u' = 1 the last column repeats; v still wraps.
    map.clampU = true;
    ASSERT_EQ(Q3Shader_SetUBoundary(m_shader, kQ3ShaderUVBoundaryClamp), kQ3Success);
    const Pixmap clampedU = renderUnder(m_shader, mesh);
    EXPECT_GT(expectTexels(clampedU, map, "clamped in u"), 200);

    map.clampV = true;
    ASSERT_EQ(Q3Shader_SetVBoundary(m_shader, kQ3ShaderUVBoundaryClamp), kQ3Success);
    const Pixmap clamped = renderUnder(m_shader, mesh);
    EXPECT_GT(expectTexels(clamped, map, "clamped in u and v"), 200);
}

TEST_F(TextureRenderTest, ShadingUVServesWhereThereIsNoSurfaceUV)
{
    TQ3GeometryObject mesh = quad(kQ3AttributeTypeShadingUV);
    const Pixmap image = renderUnder(m_shader, mesh);
    EXPECT_GT(expectTexels(image, UVMap{}, "shading uv"), 300);
}

TEST_F(TextureRenderTest, AGroupAndPushPopScopeTheShader)
{
    TQ3GeometryObject mesh = quad();
    // In a group: the shader applies to the group's mesh.
    TQ3GroupObject group = own(Q3DisplayGroup_New());
    Q3Group_AddObject(group, m_shader);
    Q3Group_AddObject(group, mesh);
    EXPECT_GT(expectTexels(render([&](TQ3ViewObject v) { Q3Object_Submit(group, v); }), UVMap{}, "group"), 300);
    // Popped: the mesh after the pop is untextured (red).
    const Pixmap popped = render([&](TQ3ViewObject v) {
        Q3Push_Submit(v);
        Q3Shader_Submit(m_shader, v);
        Q3Pop_Submit(v);
        Q3Geometry_Submit(mesh, v);
    });
    EXPECT_EQ(popped.at(20, 15).r, 255);
    EXPECT_EQ(popped.at(20, 15).g, 0);
}

TEST_F(TextureRenderTest, LambertUnderAmbientLightScalesTheTexel)
{
    TQ3GeometryObject mesh = quad();
    TQ3LightData light{kQ3True, 0.5f, {1, 1, 1}};
    TQ3LightObject ambient = own(Q3AmbientLight_New(&light));
    TQ3GroupObject lights = own(Q3LightGroup_New());
    Q3Group_AddObject(lights, ambient);
    TQ3ShaderObject lambert = own(Q3LambertIllumination_New());
    Pixmap image(kWidth, kHeight);
    {
        TestView view(image.pixmap(), kQ3RendererTypeInteractive);
        ASSERT_EQ(Q3View_SetLightGroup(view.view(), lights), kQ3Success);
        EXPECT_EQ(view.render([&](TQ3ViewObject v) {
            Q3Shader_Submit(lambert, v);
            Q3Shader_Submit(m_shader, v);
            Q3Geometry_Submit(mesh, v);
        }),
                  kQ3ViewStatusDone);
    }
    // ka Ia Od with Od the texel: half of each texel, give or take the
    // 8-bit rounding of the lit colour and of the product.
    EXPECT_GT(expectTexels(image, UVMap{}, "lambert", 0.5, 2), 300);
}

TEST_F(TextureRenderTest, AMipmapTextureShowsItsFirstImage)
{
    // The first image after 5 bytes of something else, then a 2 x 1 second
    // image and a 1 x 1 third one, which are not drawn.
    std::vector<unsigned char> bytes(5, 0x11);
    const std::vector<unsigned char> first = textureBytes();
    bytes.insert(bytes.end(), first.begin(), first.end());
    bytes.insert(bytes.end(), 9, 0x77);
    TQ3StorageObject storage = own(Q3MemoryStorage_New(bytes.data(), static_cast<unsigned long>(bytes.size())));
    const TQ3Mipmap mipmap = q3test::bigEndianMipmap(storage, kQ3PixelTypeRGB24, true,
                                                     {{kTexW, kTexH, 3 * kTexW, 5}, {2, 1, 6, 5 + 24}, {1, 1, 3, 5 + 30}});
    TQ3TextureObject texture = own(Q3MipmapTexture_New(&mipmap));
    ASSERT_NE(texture, nullptr);
    TQ3ShaderObject shader = own(Q3TextureShader_New(texture));
    TQ3GeometryObject mesh = quad();
    EXPECT_GT(expectTexels(render([&](TQ3ViewObject v) {
                               Q3Shader_Submit(shader, v);
                               Q3Geometry_Submit(mesh, v);
                           }),
                           UVMap{}, "mipmap"),
              300);
}

TEST_F(TextureRenderTest, AVertexWithoutAUVTexturesTheMeshUnlessAFaceUsesIt)
{
    // A Mesh: the quad's four corners with their uvs, and a fifth vertex
    // with no uv. While no face uses it, the quad shows its texels under a
    // uv transform; once a face does, the mesh is untextured (its red).
    const TQ3Point3D corners[4] = {{kX0, kY0, 0}, {kX1, kY0, 0}, {kX1, kY1, 0}, {kX0, kY1, 0}};
    const TQ3Param2D uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const auto meshWithFifthVertex = [&](bool fifthInAFace) {
        TQ3GeometryObject mesh = own(Q3Mesh_New());
        TQ3MeshVertex vertices[5];
        for (int i = 0; i < 4; ++i) {
            TQ3AttributeSet set = own(Q3AttributeSet_New());
            EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceUV, &uvs[i]), kQ3Success);
            const TQ3Vertex3D vertex{corners[i], set};
            vertices[i] = Q3Mesh_VertexNew(mesh, &vertex);
        }
        const TQ3Vertex3D fifth{{kX1 + 0.2f, kY1, 0}, nullptr};
        vertices[4] = Q3Mesh_VertexNew(mesh, &fifth);
        EXPECT_NE(Q3Mesh_FaceNew(mesh, 4, vertices, own(colorSet(1, 0, 0))), nullptr);
        if (fifthInAFace) {
            TQ3MeshVertex sliver[3] = {vertices[1], vertices[4], vertices[2]};
            EXPECT_NE(Q3Mesh_FaceNew(mesh, 3, sliver, own(colorSet(1, 0, 0))), nullptr);
        }
        return mesh;
    };
    UVMap map;
    map.m[0][0] = 2.0f;
    map.m[2][1] = 0.25f;
    TQ3Matrix3x3 matrix;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            matrix.value[i][j] = map.m[i][j];
    ASSERT_EQ(Q3Shader_SetUVTransform(m_shader, &matrix), kQ3Success);
    EXPECT_GT(expectTexels(renderUnder(m_shader, meshWithFifthVertex(false)), map, "fifth vertex unused"), 200);
    const Pixmap untextured = renderUnder(m_shader, meshWithFifthVertex(true));
    const Rgba centre = untextured.at(kWidth / 2, kHeight / 2);
    EXPECT_TRUE(centre.r == 255 && centre.g == 0 && centre.b == 0)
        << "a face uses the vertex without a uv: " << centre.r << " " << centre.g << " " << centre.b;
}

TEST_F(TextureRenderTest, TexelsChangedInTheCallersBufferOrThroughTheStorageAreDrawnInTheNextFrame)
{
    // A texture in the caller's buffer (Q3MemoryStorage_NewBuffer: used in
    // place), drawn; its bytes then changed in the buffer itself, with no
    // call; then replaced through the storage. Each frame shows the texels
    // the storage holds then.
    TQ3GeometryObject mesh = quad();
    std::vector<unsigned char> buffer = textureBytes();
    const unsigned long size = static_cast<unsigned long>(buffer.size());
    TQ3StorageObject storage = own(Q3MemoryStorage_NewBuffer(buffer.data(), size, size));
    const TQ3StoragePixmap pixmap{storage, kTexW, kTexH, 3 * kTexW, 24, kQ3PixelTypeRGB24, kQ3EndianBig, kQ3EndianBig};
    TQ3ShaderObject shader = own(Q3TextureShader_New(own(Q3PixmapTexture_New(&pixmap))));
    ASSERT_NE(shader, nullptr);
    Frames frames;
    const auto draw = [&] { return frames.draw(mesh, shader); };
    expectFrame(draw(), false, "first frame");
    expectFrame(draw(), false, "second frame, unchanged");
    for (unsigned char& byte : buffer)
        byte = static_cast<unsigned char>(255 - byte);
    expectFrame(draw(), true, "after the caller's buffer changed");
    const std::vector<unsigned char> original = textureBytes();
    ASSERT_EQ(Q3MemoryStorage_Set(storage, original.data(), size), kQ3Success);
    expectFrame(draw(), false, "after Q3MemoryStorage_Set");
}

TEST_F(TextureRenderTest, TexelsOfAStorageQ3OwnsAreDrawnAsTheyAreAfterEveryWayOfChangingThem)
{
    // A storage Q3 owns (Q3MemoryStorage_New): the renderer may know its
    // bytes by the storage's version instead of comparing them; every way
    // the bytes can change must still show in the next frame: through the
    // storage (Q3Storage_SetData), and through the pointer
    // Q3MemoryStorage_GetBuffer hands out, with no call after it.
    TQ3GeometryObject mesh = quad();
    const std::vector<unsigned char> bytes = textureBytes();
    std::vector<unsigned char> inverse = bytes;
    for (unsigned char& byte : inverse)
        byte = static_cast<unsigned char>(255 - byte);
    const unsigned long size = static_cast<unsigned long>(bytes.size());
    TQ3StorageObject storage = own(Q3MemoryStorage_New(bytes.data(), size));
    const TQ3StoragePixmap pixmap{storage, kTexW, kTexH, 3 * kTexW, 24, kQ3PixelTypeRGB24, kQ3EndianBig, kQ3EndianBig};
    TQ3ShaderObject shader = own(Q3TextureShader_New(own(Q3PixmapTexture_New(&pixmap))));
    ASSERT_NE(shader, nullptr);
    Frames frames;
    expectFrame(frames.draw(mesh, shader), false, "first frame");
    expectFrame(frames.draw(mesh, shader), false, "second frame, unchanged");
    unsigned long written = 0;
    ASSERT_EQ(Q3Storage_SetData(storage, 0, size, inverse.data(), &written), kQ3Success);
    ASSERT_EQ(written, size);
    expectFrame(frames.draw(mesh, shader), true, "after Q3Storage_SetData");
    unsigned char* buffer = nullptr;
    ASSERT_EQ(Q3MemoryStorage_GetBuffer(storage, &buffer, nullptr, nullptr), kQ3Success);
    ASSERT_NE(buffer, nullptr);
    expectFrame(frames.draw(mesh, shader), true, "after Q3MemoryStorage_GetBuffer");
    std::copy(bytes.begin(), bytes.end(), buffer);
    expectFrame(frames.draw(mesh, shader), false, "after a write through Q3MemoryStorage_GetBuffer's pointer");
}

TEST_F(TextureRenderTest, MipmapsOverOneStorageAtDifferentOffsetsDrawTheirOwnTexels)
{
    // One storage Q3 owns holding the texture and then its inverse; two
    // mipmap textures of the same size and layout, the first at offset 0,
    // the second at the inverse's offset: each is drawn with its own texels,
    // in one frame after the other and both in the same frame's cache.
    TQ3GeometryObject mesh = quad();
    std::vector<unsigned char> bytes = textureBytes();
    const std::size_t half = bytes.size();
    for (std::size_t i = 0; i < half; ++i)
        bytes.push_back(static_cast<unsigned char>(255 - bytes[i]));
    TQ3StorageObject storage = own(Q3MemoryStorage_New(bytes.data(), static_cast<unsigned long>(bytes.size())));
    const auto mipmapAt = [&](unsigned long offset) {
        TQ3Mipmap mipmap{};
        mipmap.image = storage;
        mipmap.useMipmapping = kQ3False;
        mipmap.pixelType = kQ3PixelTypeRGB24;
        mipmap.bitOrder = kQ3EndianBig;
        mipmap.byteOrder = kQ3EndianBig;
        mipmap.mipmaps[0] = TQ3MipmapImage{kTexW, kTexH, 3 * kTexW, offset};
        TQ3ShaderObject shader = own(Q3TextureShader_New(own(Q3MipmapTexture_New(&mipmap))));
        EXPECT_NE(shader, nullptr);
        return shader;
    };
    TQ3ShaderObject plain = mipmapAt(0);
    TQ3ShaderObject inverted = mipmapAt(static_cast<unsigned long>(half));
    Frames frames;
    expectFrame(frames.draw(mesh, plain), false, "the texture at offset 0");
    expectFrame(frames.draw(mesh, inverted), true, "the texture at the inverse's offset");
    expectFrame(frames.draw(mesh, plain), false, "the texture at offset 0 again");
}

TEST_F(TextureRenderTest, AStorageThatNoLongerHoldsTheImageFailsTheRendering)
{
    TQ3GeometryObject mesh = quad();
    std::vector<unsigned char> bytes = textureBytes();
    TQ3StorageObject storage = own(Q3MemoryStorage_New(bytes.data(), static_cast<unsigned long>(bytes.size())));
    const TQ3StoragePixmap pixmap{storage, kTexW, kTexH, 3 * kTexW, 24, kQ3PixelTypeRGB24, kQ3EndianBig, kQ3EndianBig};
    TQ3TextureObject texture = own(Q3PixmapTexture_New(&pixmap));
    TQ3ShaderObject shader = own(Q3TextureShader_New(texture));
    ASSERT_EQ(Q3MemoryStorage_Set(storage, bytes.data(), 3), kQ3Success);
    Pixmap image(kWidth, kHeight);
    TestView view(image.pixmap(), kQ3RendererTypeInteractive);
    ASSERT_EQ(Q3View_StartRendering(view.view()), kQ3Success);
    Q3Shader_Submit(shader, view.view());
    EXPECT_Q3_ERROR(Q3Geometry_Submit(mesh, view.view()), kQ3ErrorInvalidData);
    Q3View_Cancel(view.view());
}

} // namespace
