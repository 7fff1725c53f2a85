// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Texture shaders kept in attribute sets (kQ3AttributeTypeSurfaceShader), as
// Apple-era models keep them, drawn by the interactive renderer: in a
// geometry's own set, in a TriMesh's triangle attribute array, in a box's
// face set, in a polygon's vertex sets, and submitted to the view in a set.
// Every geometry is the quad of TextureRenderTest (x 0..3, y -0.5..1.5 under
// listing1OrthographicCamera, uv (0, 0) at its bottom left and (1, 1) at its
// top right), so each decidable pixel is checked against the texel this file
// computes from the pixel centre's uv, for whichever of two textures of
// distinct texels should cover it. Pixels within a tenth of a texel of a
// texel edge, or near the diagonal between two faces, are skipped: there the
// rasterizer's rounding, not the rule, decides.

#include "GeometryTestSupport.h"
#include "InteractiveRender.h"
#include "OwningApiTest.h"
#include "QuadMesh.h"
#include "RenderTestSupport.h"

#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"
#include "QD3DStyle.h"
#include "QD3DView.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace {

using namespace q3test;

constexpr int kWidth = 40, kHeight = 30;
constexpr float kX0 = 0.0f, kX1 = 3.0f, kY0 = -0.5f, kY1 = 1.5f;
constexpr int kTexW = 4, kTexH = 2;

// The two textures' texels (column from the left, row from the top); no
// texel of one is a texel of the other.
Rgba texelA(int column, int row)
{
    return Rgba{30 + 50 * column, 200 - 90 * row, 60 + 40 * column + 20 * row, 255};
}
Rgba texelB(int column, int row)
{
    return Rgba{240 - 30 * column, 20 + 60 * row, 250 - 50 * row, 255};
}
using TexelOf = Rgba (*)(int, int);

// Where a pixel centre falls on the quad, as uv.
void uvAt(int px, int py, double& u, double& v)
{
    const double x = -0.5 + (px + 0.5) / kWidth * 4.0, y = 2.0 - (py + 0.5) / kHeight * 3.0;
    u = (x - kX0) / (kX1 - kX0);
    v = (y - kY0) / (kY1 - kY0);
}

// The texel a pixel shows under identity uv and wrapping, or false where it
// is outside the quad or too near a texel edge to say.
bool expectedTexel(int px, int py, TexelOf texelOf, Rgba& out)
{
    double u, v;
    uvAt(px, py, u, v);
    if (u < 0.02 || u > 0.98 || v < 0.02 || v > 0.98)
        return false;
    const double cs = u * kTexW, rs = (1.0 - v) * kTexH;
    const auto nearEdge = [](double t) { return std::fabs(t - std::round(t)) < 0.1; };
    if (nearEdge(cs) || nearEdge(rs))
        return false;
    out = texelOf(int(std::floor(cs)), int(std::floor(rs)));
    return true;
}

std::vector<unsigned char> textureBytes(TexelOf texelOf)
{
    std::vector<unsigned char> bytes;
    for (int row = 0; row < kTexH; ++row)
        for (int column = 0; column < kTexW; ++column) {
            const Rgba c = texelOf(column, row);
            bytes.insert(bytes.end(), {(unsigned char)c.r, (unsigned char)c.g, (unsigned char)c.b});
        }
    return bytes;
}

// Which texture a pixel's uv should show: A, B, or (0) none decided here.
using Region = std::function<TexelOf(double u, double v)>;

class AttributeTextureRenderTest : public OwningApiTest, protected InteractiveRendering<kWidth, kHeight> {
protected:
    void SetUp() override
    {
        OwningApiTest::SetUp();
        m_shaderA = shaderOf(texelA, m_bytesA);
        m_shaderB = shaderOf(texelB, m_bytesB);
    }

    TQ3ShaderObject shaderOf(TexelOf texelOf, std::vector<unsigned char>& bytes)
    {
        bytes = textureBytes(texelOf);
        TQ3StorageObject storage = own(Q3MemoryStorage_New(bytes.data(), static_cast<unsigned long>(bytes.size())));
        const TQ3StoragePixmap pixmap{storage, kTexW, kTexH, 3 * kTexW, 24, kQ3PixelTypeRGB24, kQ3EndianBig,
                                      kQ3EndianBig};
        TQ3TextureObject texture = own(Q3PixmapTexture_New(&pixmap));
        TQ3ShaderObject shader = own(Q3TextureShader_New(texture));
        EXPECT_NE(shader, nullptr);
        return shader;
    }

    // A set with a red diffuse colour (which a texture replaces) and, when
    // given, a surface shader.
    TQ3AttributeSet setWith(TQ3ShaderObject shader)
    {
        TQ3AttributeSet set = own(colorSet(1, 0, 0));
        if (shader != nullptr)
            EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
        return set;
    }

    // The quad as a TriMesh: triangle 0 (corners 0 1 2) below the diagonal
    // u = v, triangle 1 (0 2 3) above it; `set` its own attribute set,
    // `faceShaders` (two handles, or null) its triangle shader array.
    TQ3GeometryObject quadMesh(TQ3AttributeSet set, TQ3SurfaceShaderObject* faceShaders = nullptr,
                               char* faceUse = nullptr)
    {
        q3test::QuadMesh quad({{kX0, kY0, 0}, {kX1, kY0, 0}, {kX1, kY1, 0}, {kX0, kY1, 0}},
                              {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
        TQ3TriMeshAttributeData shaderArray{kQ3AttributeTypeSurfaceShader, faceShaders, faceUse};
        quad.data.triMeshAttributeSet = set;
        if (faceShaders != nullptr) {
            quad.data.numTriangleAttributeTypes = 1;
            quad.data.triangleAttributeTypes = &shaderArray;
        }
        TQ3GeometryObject mesh = own(quad.create());
        EXPECT_NE(mesh, nullptr);
        return mesh;
    }

    // The quad as a polygon: each corner's set holds its uv, and corner
    // `shaded` (or every corner, with -1) also `shader`.
    TQ3GeometryObject quadPolygon(TQ3AttributeSet own_, TQ3ShaderObject shader, int shaded)
    {
        TQ3Vertex3D vertices[4] = {{{kX0, kY0, 0}, nullptr}, {{kX1, kY0, 0}, nullptr},
                                   {{kX1, kY1, 0}, nullptr}, {{kX0, kY1, 0}, nullptr}};
        const TQ3Param2D uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int i = 0; i < 4; ++i) {
            vertices[i].attributeSet = own(Q3AttributeSet_New());
            Q3AttributeSet_Add(vertices[i].attributeSet, kQ3AttributeTypeSurfaceUV, &uvs[i]);
            if (shader != nullptr && (shaded < 0 || shaded == i))
                Q3AttributeSet_Add(vertices[i].attributeSet, kQ3AttributeTypeSurfaceShader, &shader);
        }
        const TQ3PolygonData data{4, vertices, own_};
        TQ3GeometryObject polygon = own(Q3Polygon_New(&data));
        EXPECT_NE(polygon, nullptr);
        return polygon;
    }


    // Every decidable pixel shows the texel of the texture `region` names
    // for its uv; returns how many pixels were checked.
    static int expectTexels(const Pixmap& image, const Region& region, const std::string& what)
    {
        int checked = 0;
        for (int py = 0; py < kHeight; ++py)
            for (int px = 0; px < kWidth; ++px) {
                double u, v;
                uvAt(px, py, u, v);
                const TexelOf texelOf = region(u, v);
                Rgba want{};
                if (texelOf == nullptr || !expectedTexel(px, py, texelOf, want))
                    continue;
                ++checked;
                const Rgba got = image.at(px, py);
                EXPECT_TRUE(got.r == want.r && got.g == want.g && got.b == want.b)
                    << what << ": pixel (" << px << ", " << py << ") is " << got.r << " " << got.g << " " << got.b
                    << ", expected " << want.r << " " << want.g << " " << want.b;
            }
        return checked;
    }
    static Region all(TexelOf texelOf)
    {
        return [texelOf](double, double) { return texelOf; };
    }
    // Triangle 0 (below the diagonal) one texture, triangle 1 another; the
    // pixels within 0.05 of the diagonal are not decided.
    static Region split(TexelOf below, TexelOf above)
    {
        return [below, above](double u, double v) -> TexelOf {
            if (std::fabs(u - v) < 0.05)
                return nullptr;
            return u > v ? below : above;
        };
    }

    std::vector<unsigned char> m_bytesA, m_bytesB;
    TQ3ShaderObject m_shaderA = nullptr;
    TQ3ShaderObject m_shaderB = nullptr;
};

TEST_F(AttributeTextureRenderTest, ShaderInTheGeometrysSetTexturesIt)
{
    TQ3GeometryObject mesh = quadMesh(setWith(m_shaderA));
    const Pixmap image = render([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(mesh, v), kQ3Success); });
    EXPECT_GT(expectTexels(image, all(texelA), "the geometry's shader"), 300);
}

TEST_F(AttributeTextureRenderTest, ShaderInTheGeometrysSetOverridesTheViewsShader)
{
    TQ3GeometryObject mesh = quadMesh(setWith(m_shaderA));
    const Pixmap image = renderUnder(m_shaderB, mesh);
    EXPECT_GT(expectTexels(image, all(texelA), "the geometry's shader over the view's"), 300);
}

TEST_F(AttributeTextureRenderTest, ViewsShaderTexturesAGeometryWhoseSetHasNone)
{
    TQ3GeometryObject mesh = quadMesh(setWith(nullptr));
    const Pixmap image = renderUnder(m_shaderB, mesh);
    EXPECT_GT(expectTexels(image, all(texelB), "the view's shader"), 300);
}

TEST_F(AttributeTextureRenderTest, SetSubmittedToTheViewActsAsASubmittedShaderTheLaterWins)
{
    TQ3GeometryObject mesh = quadMesh(setWith(nullptr));
    TQ3AttributeSet withB = setWith(m_shaderB);
    const Pixmap setOnly = render([&](TQ3ViewObject v) {
        EXPECT_EQ(Q3AttributeSet_Submit(withB, v), kQ3Success);
        Q3Geometry_Submit(mesh, v);
    });
    EXPECT_GT(expectTexels(setOnly, all(texelB), "a set submitted to the view"), 300);
    const Pixmap shaderAfter = render([&](TQ3ViewObject v) {
        Q3AttributeSet_Submit(withB, v);
        Q3Shader_Submit(m_shaderA, v);
        Q3Geometry_Submit(mesh, v);
    });
    EXPECT_GT(expectTexels(shaderAfter, all(texelA), "a shader submitted after the set"), 300);
    const Pixmap setAfter = render([&](TQ3ViewObject v) {
        Q3Shader_Submit(m_shaderA, v);
        Q3AttributeSet_Submit(withB, v);
        Q3Geometry_Submit(mesh, v);
    });
    EXPECT_GT(expectTexels(setAfter, all(texelB), "a set submitted after the shader"), 300);
}

TEST_F(AttributeTextureRenderTest, PopRestoresTheShaderASetSubmittedBeforeThePush)
{
    TQ3GeometryObject mesh = quadMesh(setWith(nullptr));
    TQ3AttributeSet withA = setWith(m_shaderA), withB = setWith(m_shaderB);
    const Pixmap image = render([&](TQ3ViewObject v) {
        Q3AttributeSet_Submit(withA, v);
        EXPECT_EQ(Q3Push_Submit(v), kQ3Success);
        Q3AttributeSet_Submit(withB, v);
        EXPECT_EQ(Q3Pop_Submit(v), kQ3Success);
        Q3Geometry_Submit(mesh, v);
    });
    EXPECT_GT(expectTexels(image, all(texelA), "the shader before the push"), 300);
}

TEST_F(AttributeTextureRenderTest, ShaderInTheViewsDefaultSetTexturesFromTheStart)
{
    TQ3GeometryObject mesh = quadMesh(setWith(nullptr));
    Pixmap image(kWidth, kHeight);
    TestView view(image.pixmap(), kQ3RendererTypeInteractive);
    ASSERT_EQ(Q3View_SetDefaultAttributeSet(view.view(), setWith(m_shaderB)), kQ3Success);
    EXPECT_EQ(view.render([&](TQ3ViewObject v) { Q3Geometry_Submit(mesh, v); }), kQ3ViewStatusDone);
    EXPECT_GT(expectTexels(image, all(texelB), "the default set's shader"), 300);
}

TEST_F(AttributeTextureRenderTest, HighlightStylesShaderReplacesEveryShaderOfAHighlightedGeometry)
{
    TQ3SurfaceShaderObject faces[2] = {m_shaderA, m_shaderA};
    TQ3AttributeSet own_ = setWith(m_shaderA);
    const TQ3Switch on = kQ3On;
    Q3AttributeSet_Add(own_, kQ3AttributeTypeHighlightState, &on);
    TQ3GeometryObject mesh = quadMesh(own_, faces);
    TQ3StyleObject highlight = own(Q3HighlightStyle_New(setWith(m_shaderB)));
    ASSERT_NE(highlight, nullptr);
    const Pixmap image = render([&](TQ3ViewObject v) {
        Q3Style_Submit(highlight, v);
        Q3Geometry_Submit(mesh, v);
    });
    EXPECT_GT(expectTexels(image, all(texelB), "the highlight's shader"), 300);
}

TEST_F(AttributeTextureRenderTest, TriMeshFaceShadersTextureEachFaceWithItsOwn)
{
    TQ3SurfaceShaderObject faces[2] = {m_shaderA, m_shaderB};
    TQ3GeometryObject mesh = quadMesh(setWith(nullptr), faces);
    const Pixmap image = render([&](TQ3ViewObject v) { Q3Geometry_Submit(mesh, v); });
    EXPECT_GT(expectTexels(image, split(texelA, texelB), "one shader per face"), 250);
}

TEST_F(AttributeTextureRenderTest, FaceShaderOverridesTheGeometrysAndAFaceWithoutOneTakesIt)
{
    // Triangle 1's element is switched off by the use array: its value is
    // never read, so it may hold anything.
    TQ3SurfaceShaderObject faces[2] = {m_shaderB, reinterpret_cast<TQ3SurfaceShaderObject>(std::uintptr_t(0x10))};
    char use[2] = {1, 0};
    TQ3GeometryObject mesh = quadMesh(setWith(m_shaderA), faces, use);
    const Pixmap image = renderUnder(m_shaderA, mesh);
    EXPECT_GT(expectTexels(image, split(texelB, texelA), "face over geometry"), 250);
}

TEST_F(AttributeTextureRenderTest, TwoMeshesTakingTurnsWithTwoTexturesEachDrawTheirOwn)
{
    TQ3GeometryObject meshA = quadMesh(setWith(m_shaderA));
    TQ3SurfaceShaderObject faces[2] = {m_shaderB, m_shaderA};
    TQ3GeometryObject meshAB = quadMesh(setWith(nullptr), faces);
    // The last geometry drawn wins each pixel (same depth): A B A B, then
    // the split mesh last.
    const Pixmap image = render([&](TQ3ViewObject v) {
        for (int i = 0; i < 3; ++i) {
            Q3Geometry_Submit(meshA, v);
            Q3Geometry_Submit(meshAB, v);
        }
    });
    EXPECT_GT(expectTexels(image, split(texelB, texelA), "alternating textures"), 250);
}

TEST_F(AttributeTextureRenderTest, BoxFaceSetShaderTexturesThatFace)
{
    // Face 2 (front: major axis +z) lies on the quad with u along minorAxis
    // (+x) and v along orientation (+y), its natural uv the quad's.
    TQ3AttributeSet faces[6] = {nullptr, nullptr, setWith(m_shaderA), nullptr, nullptr, nullptr};
    const TQ3BoxData data{{kX0, kY0, -1}, {0, kY1 - kY0, 0}, {0, 0, 1}, {kX1 - kX0, 0, 0}, faces, setWith(nullptr)};
    TQ3GeometryObject box = own(Q3Box_New(&data));
    ASSERT_NE(box, nullptr);
    const Pixmap image = render([&](TQ3ViewObject v) { Q3Geometry_Submit(box, v); });
    EXPECT_GT(expectTexels(image, all(texelA), "the front face's shader"), 300);
}

TEST_F(AttributeTextureRenderTest, ShaderAddedToAFaceSetAfterDrawingIsDrawnNextTime)
{
    TQ3AttributeSet front = setWith(nullptr);
    TQ3AttributeSet faces[6] = {nullptr, nullptr, front, nullptr, nullptr, nullptr};
    const TQ3BoxData data{{kX0, kY0, -1}, {0, kY1 - kY0, 0}, {0, 0, 1}, {kX1 - kX0, 0, 0}, faces, nullptr};
    TQ3GeometryObject box = own(Q3Box_New(&data));
    const Pixmap before = render([&](TQ3ViewObject v) { Q3Geometry_Submit(box, v); });
    const Rgba red = before.at(20, 15);
    EXPECT_TRUE(red.r == 255 && red.g == 0 && red.b == 0) << red.r << " " << red.g << " " << red.b;
    ASSERT_EQ(Q3AttributeSet_Add(front, kQ3AttributeTypeSurfaceShader, &m_shaderB), kQ3Success);
    const Pixmap after = render([&](TQ3ViewObject v) { Q3Geometry_Submit(box, v); });
    EXPECT_GT(expectTexels(after, all(texelB), "the shader added to the face set"), 300);
    ASSERT_EQ(Q3AttributeSet_Clear(front, kQ3AttributeTypeSurfaceShader), kQ3Success);
    const Pixmap cleared = render([&](TQ3ViewObject v) { Q3Geometry_Submit(box, v); });
    const Rgba again = cleared.at(20, 15);
    EXPECT_TRUE(again.r == 255 && again.g == 0 && again.b == 0) << again.r << " " << again.g << " " << again.b;
}

TEST_F(AttributeTextureRenderTest, PolygonWhoseVertexSetsAllHoldAShaderIsTexturedWithIt)
{
    TQ3GeometryObject polygon = quadPolygon(setWith(m_shaderB), m_shaderA, -1);
    const Pixmap image = render([&](TQ3ViewObject v) { Q3Geometry_Submit(polygon, v); });
    EXPECT_GT(expectTexels(image, all(texelA), "every vertex's shader over the polygon's"), 300);
}

TEST_F(AttributeTextureRenderTest, ShaderOfOneVertexIsOutvotedByTheOthers)
{
    // Each triangle has at most one corner holding B: both take the
    // polygon's A.
    TQ3GeometryObject polygon = quadPolygon(setWith(m_shaderA), m_shaderB, 0);
    const Pixmap image = render([&](TQ3ViewObject v) { Q3Geometry_Submit(polygon, v); });
    EXPECT_GT(expectTexels(image, all(texelA), "one vertex's shader"), 300);
}

TEST_F(AttributeTextureRenderTest, TriMeshVertexShaderArrayTexturesTheTrianglesWhoseCornersShareIt)
{
    // Corners 0 1 2 hold B, corner 3 A: triangle 0 (0 1 2) takes B;
    // triangle 1 (0 2 3) has two corners with B, so B too.
    q3test::QuadMesh quad({{kX0, kY0, 0}, {kX1, kY0, 0}, {kX1, kY1, 0}, {kX0, kY1, 0}}, {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    TQ3SurfaceShaderObject shaders[4] = {m_shaderB, m_shaderB, m_shaderB, m_shaderA};
    TQ3TriMeshAttributeData arrays[2] = {quad.uvArray, {kQ3AttributeTypeSurfaceShader, shaders, nullptr}};
    quad.data.numVertexAttributeTypes = 2;
    quad.data.vertexAttributeTypes = arrays;
    TQ3GeometryObject mesh = own(quad.create());
    ASSERT_NE(mesh, nullptr);
    const Pixmap image = render([&](TQ3ViewObject v) { Q3Geometry_Submit(mesh, v); });
    EXPECT_GT(expectTexels(image, all(texelB), "vertex shaders"), 300);
}

// ---- TriMesh surface shader arrays: references and checks ----------------

TEST_F(AttributeTextureRenderTest, TriMeshHoldsAReferencePerShaderElementAndGivesThemBack)
{
    const unsigned long a0 = referenceCount(m_shaderA), b0 = referenceCount(m_shaderB);
    TQ3SurfaceShaderObject faces[2] = {m_shaderA, m_shaderB};
    TQ3GeometryObject mesh = quadMesh(nullptr, faces);
    EXPECT_EQ(referenceCount(m_shaderA), a0 + 1);
    EXPECT_EQ(referenceCount(m_shaderB), b0 + 1);

    TQ3TriMeshData data{};
    ASSERT_EQ(Q3TriMesh_GetData(mesh, &data), kQ3Success);
    ASSERT_EQ(data.numTriangleAttributeTypes, 1ul);
    EXPECT_EQ(data.triangleAttributeTypes[0].attributeType, TQ3AttributeType(kQ3AttributeTypeSurfaceShader));
    const auto* got = static_cast<TQ3SurfaceShaderObject*>(data.triangleAttributeTypes[0].data);
    EXPECT_EQ(got[0], m_shaderA);
    EXPECT_EQ(got[1], m_shaderB);
    EXPECT_EQ(referenceCount(m_shaderA), a0 + 2);
    ASSERT_EQ(Q3TriMesh_EmptyData(&data), kQ3Success);
    EXPECT_EQ(referenceCount(m_shaderA), a0 + 1);

    // A duplicate shares the shaders, as a duplicated attribute set does.
    TQ3GeometryObject copy = Q3Object_Duplicate(mesh);
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(referenceCount(m_shaderA), a0 + 2);
    EXPECT_EQ(referenceCount(m_shaderB), b0 + 2);
    Q3Object_Dispose(copy);
    EXPECT_EQ(referenceCount(m_shaderA), a0 + 1);

    // SetData takes the new data's references and gives back the old ones.
    TQ3SurfaceShaderObject both[2] = {m_shaderB, m_shaderB};
    TQ3Point3D points[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    TQ3TriMeshTriangleData triangle = {{0, 1, 2}};
    TQ3TriMeshAttributeData shaderArray{kQ3AttributeTypeSurfaceShader, both, nullptr};
    TQ3TriMeshData replacement{};
    replacement.numTriangles = 1;
    replacement.triangles = &triangle;
    replacement.numTriangleAttributeTypes = 1;
    replacement.triangleAttributeTypes = &shaderArray;
    replacement.numPoints = 3;
    replacement.points = points;
    ASSERT_EQ(Q3TriMesh_SetData(mesh, &replacement), kQ3Success);
    EXPECT_EQ(referenceCount(m_shaderA), a0);
    EXPECT_EQ(referenceCount(m_shaderB), b0 + 1);
}

TEST_F(AttributeTextureRenderTest, TriMeshRefusesAShaderElementThatIsNotALiveSurfaceShader)
{
    TQ3AttributeSet notAShader = setWith(nullptr);
    TQ3SurfaceShaderObject faces[2] = {m_shaderA, notAShader};
    const unsigned long a0 = referenceCount(m_shaderA);
    TQ3Point3D points[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    TQ3TriMeshTriangleData triangles[2] = {{{0, 1, 2}}, {{0, 2, 3}}};
    TQ3TriMeshAttributeData shaderArray{kQ3AttributeTypeSurfaceShader, faces, nullptr};
    TQ3TriMeshData data{};
    data.numTriangles = 2;
    data.triangles = triangles;
    data.numTriangleAttributeTypes = 1;
    data.triangleAttributeTypes = &shaderArray;
    data.numPoints = 4;
    data.points = points;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_New(&data), nullptr), kQ3ErrorInvalidObjectType);
    faces[1] = deadObject();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_New(&data), nullptr), kQ3ErrorInvalidObject);
    // Nothing stays retained after a refusal.
    EXPECT_EQ(referenceCount(m_shaderA), a0);
    // A NULL element is a triangle without a shader of its own.
    faces[1] = nullptr;
    TQ3GeometryObject mesh = own(Q3TriMesh_New(&data));
    EXPECT_NE(mesh, nullptr);
    EXPECT_EQ(referenceCount(m_shaderA), a0 + 1);
}

TEST_F(AttributeTextureRenderTest, DecomposedBoxKeepsItsFaceShaderAsATriangleShaderArray)
{
    TQ3AttributeSet faces[6] = {nullptr, nullptr, setWith(m_shaderA), nullptr, nullptr, nullptr};
    const TQ3BoxData boxData{{kX0, kY0, -1}, {0, kY1 - kY0, 0}, {0, 0, 1}, {kX1 - kX0, 0, 0}, faces, nullptr};
    TQ3GeometryObject box = own(Q3Box_New(&boxData));
    ASSERT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
    TQ3GeometryObject mesh = Q3Geometry_GetDecomposed(box, view());
    TQ3BoundingBox bounds;
    EXPECT_EQ(Q3View_EndBoundingBox(view(), &bounds), kQ3ViewStatusDone);
    ASSERT_NE(mesh, nullptr);
    own(mesh);
    TQ3TriMeshData data{};
    ASSERT_EQ(Q3TriMesh_GetData(mesh, &data), kQ3Success);
    ASSERT_EQ(data.numTriangleAttributeTypes, 1ul);
    const TQ3TriMeshAttributeData& array = data.triangleAttributeTypes[0];
    EXPECT_EQ(array.attributeType, TQ3AttributeType(kQ3AttributeTypeSurfaceShader));
    ASSERT_NE(array.attributeUseArray, nullptr);
    unsigned long shaded = 0;
    for (unsigned long t = 0; t < data.numTriangles; ++t) {
        const TQ3SurfaceShaderObject shader = static_cast<TQ3SurfaceShaderObject*>(array.data)[t];
        EXPECT_EQ(array.attributeUseArray[t] != 0, shader != nullptr);
        if (shader != nullptr) {
            EXPECT_EQ(shader, m_shaderA);
            ++shaded;
        }
    }
    // The front face and nothing else.
    EXPECT_GT(shaded, 0ul);
    EXPECT_LT(shaded, data.numTriangles);
    Q3TriMesh_EmptyData(&data);
}

} // namespace
