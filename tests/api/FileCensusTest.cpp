// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Nothing is lost: a scene holding something of every kind a 3DMF file
// carries (groups of each kind, display group state, transforms, styles,
// illumination and texture shaders, lights, a camera, view hints, geometries
// with attribute sets at every level, unknown objects read from files) is
// written as text, read, written as big-endian binary, read, written as text
// again and read; the census of each file (tests/support/FileCensus.h) is the
// same.

#include "FileCensus.h"
#include "FileTestSupport.h"
#include "Q3ApiTest.h"
#include "TextureTestSupport.h"

#include "QD3DCamera.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DShader.h"
#include "QD3DString.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"

#include <string>
#include <vector>

using namespace q3test;

namespace {

class FileCensusTest : public Q3ApiTest {};

// Adds object to group and drops the caller's reference.
void put(TQ3GroupObject group, TQ3Object object)
{
    ASSERT_NE(object, nullptr);
    ASSERT_NE(Q3Group_AddObject(group, object), nullptr);
    Q3Object_Dispose(object);
}

TQ3AttributeSet colourSet(float r, float g, float b)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB colour{r, g, b};
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &colour);
    return set;
}

TQ3ShaderObject pixmapShader()
{
    std::vector<unsigned char> pixels(4 * 4 * 4);
    for (std::size_t i = 0; i < pixels.size(); ++i)
        pixels[i] = static_cast<unsigned char>(37 * i + 11);
    TQ3StorageObject storage = Q3MemoryStorage_New(pixels.data(), static_cast<unsigned long>(pixels.size()));
    const TQ3StoragePixmap pixmap{storage, 4, 4, 16, 32, kQ3PixelTypeARGB32, kQ3EndianBig, kQ3EndianBig};
    TQ3TextureObject texture = Q3PixmapTexture_New(&pixmap);
    TQ3ShaderObject shader = Q3TextureShader_New(texture);
    Q3Shader_SetUBoundary(shader, kQ3ShaderUVBoundaryClamp);
    Q3Object_Dispose(texture);
    Q3Object_Dispose(storage);
    return shader;
}

TQ3ShaderObject mipmapShader()
{
    std::vector<unsigned char> chain(4 * 4 * 2 + 2 * 2 * 2 + 2);
    for (std::size_t i = 0; i < chain.size(); ++i)
        chain[i] = static_cast<unsigned char>(29 * i + 7);
    TQ3StorageObject storage = Q3MemoryStorage_New(chain.data(), static_cast<unsigned long>(chain.size()));
    const TQ3Mipmap mipmap =
        q3test::bigEndianMipmap(storage, kQ3PixelTypeRGB16, true, {{4, 4, 8, 0}, {2, 2, 4, 32}, {1, 1, 2, 40}});
    TQ3TextureObject texture = Q3MipmapTexture_New(&mipmap);
    TQ3ShaderObject shader = Q3TextureShader_New(texture);
    Q3Object_Dispose(texture);
    Q3Object_Dispose(storage);
    return shader;
}

TQ3GroupObject lightGroup()
{
    TQ3GroupObject lights = Q3LightGroup_New();
    const TQ3LightData ambient{kQ3True, 0.25f, {1, 0.5f, 0.25f}};
    put(lights, Q3AmbientLight_New(&ambient));
    const TQ3DirectionalLightData directional{{kQ3True, 0.75f, {0.5f, 1, 1}}, kQ3False, {0, -1, 0}};
    put(lights, Q3DirectionalLight_New(&directional));
    const TQ3PointLightData point{{kQ3True, 1, {1, 1, 1}}, kQ3False, kQ3AttenuationTypeInverseDistance, {1, 2, 3}};
    put(lights, Q3PointLight_New(&point));
    const TQ3SpotLightData spot{{kQ3True, 0.5f, {1, 1, 0}}, kQ3True, kQ3AttenuationTypeInverseDistanceSquared,
                                {0, 5, 0}, {0, -1, 0}, 0.25f, 0.5f, kQ3FallOffTypeCosine};
    put(lights, Q3SpotLight_New(&spot));
    return lights;
}

TQ3CameraObject camera()
{
    const TQ3ViewAngleAspectCameraData data = viewAngleCamera({3, 4, 8}, {0, 0, 0}, {0, 1, 0}, 0.8, 4.0 / 3.0);
    return Q3ViewAngleAspectCamera_New(&data);
}

// A box with a set per face and its own set, a triangle with vertex sets, an
// ellipsoid (its own set holding a texture shader when shaderInSet), a
// polygon with a vertex set, a polyline with vertex and segment sets, a point.
void addGeometries(TQ3GroupObject group, bool shaderInSet)
{
    TQ3AttributeSet faces[6];
    for (int i = 0; i < 6; ++i)
        faces[i] = colourSet(i / 6.0f, 1 - i / 6.0f, 0.5f);
    const TQ3Vector3D normal{0, 0, 1};
    Q3AttributeSet_Add(faces[2], kQ3AttributeTypeNormal, &normal);
    TQ3AttributeSet boxSet = colourSet(0.2f, 0.4f, 0.9f);
    const float specular = 12.5f;
    Q3AttributeSet_Add(boxSet, kQ3AttributeTypeSpecularControl, &specular);
    const TQ3BoxData box{{0, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}, faces, boxSet};
    put(group, Q3Box_New(&box));
    for (TQ3AttributeSet face : faces)
        Q3Object_Dispose(face);
    Q3Object_Dispose(boxSet);

    TQ3TriangleData triangle{};
    const TQ3Point3D corners[3] = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < 3; ++i) {
        triangle.vertices[i].point = corners[i];
        triangle.vertices[i].attributeSet = colourSet(i == 0, i == 1, i == 2);
        const TQ3Param2D uv{i * 0.5f, 1 - i * 0.5f};
        Q3AttributeSet_Add(triangle.vertices[i].attributeSet, kQ3AttributeTypeSurfaceUV, &uv);
    }
    const TQ3ColorRGB transparency{0.5f, 0.5f, 0.5f};
    triangle.triangleAttributeSet = Q3AttributeSet_New();
    Q3AttributeSet_Add(triangle.triangleAttributeSet, kQ3AttributeTypeTransparencyColor, &transparency);
    put(group, Q3Triangle_New(&triangle));
    for (const TQ3Vertex3D& v : triangle.vertices)
        Q3Object_Dispose(v.attributeSet);
    Q3Object_Dispose(triangle.triangleAttributeSet);

    // A whole unit sphere at (3, 0, 0), no caps, a yellow set.
    TQ3EllipsoidData ellipsoid{{3, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}, 0, 1, 0, 1, kQ3EndCapNone, nullptr,
                               colourSet(0.9f, 0.9f, 0.1f)};
    if (shaderInSet) {
        TQ3ShaderObject shader = pixmapShader();
        Q3AttributeSet_Add(ellipsoid.ellipsoidAttributeSet, kQ3AttributeTypeSurfaceShader, &shader);
        Q3Object_Dispose(shader);
    }
    put(group, Q3Ellipsoid_New(&ellipsoid));
    Q3Object_Dispose(ellipsoid.ellipsoidAttributeSet);

    TQ3Vertex3D square[4] = {{{0, 0, 2}, nullptr}, {{1, 0, 2}, nullptr}, {{1, 1, 2}, nullptr}, {{0, 1, 2}, nullptr}};
    square[1].attributeSet = colourSet(1, 0, 1);
    const TQ3PolygonData polygon{4, square, colourSet(0, 1, 1)};
    put(group, Q3Polygon_New(&polygon));
    Q3Object_Dispose(polygon.polygonAttributeSet);
    Q3Object_Dispose(square[1].attributeSet);

    TQ3Vertex3D line[3] = {{{0, 2, 0}, nullptr}, {{1, 3, 0}, nullptr}, {{2, 2, 0}, nullptr}};
    line[2].attributeSet = colourSet(0, 0, 1);
    TQ3AttributeSet segments[2] = {colourSet(1, 1, 1), nullptr};
    const TQ3PolyLineData polyline{3, line, segments, colourSet(1, 0.5f, 0)};
    put(group, Q3PolyLine_New(&polyline));
    Q3Object_Dispose(polyline.polyLineAttributeSet);
    Q3Object_Dispose(segments[0]);
    Q3Object_Dispose(line[2].attributeSet);

    const TQ3PointData point{{5, 5, 5}, colourSet(0, 0, 0)};
    put(group, Q3Point_New(&point));
    Q3Object_Dispose(point.pointAttributeSet);
}

// Which unknown objects a scene holds: an unknown object keeps the form of
// the file it was read from, text or binary, and a file of the other
// encoding leaves it out with kQ3WarningNoObjectSupportForWriteMethod
// (docs/3dmf.md), so each round trip of a whole scene takes the kind its
// files can carry.
enum class Unknowns { kNone, kText, kBinary };

// Whether the ellipsoids' attribute sets hold a texture shader
// (kQ3AttributeTypeSurfaceShader), which 3DMF files carry in the set's
// container (docs/3dmf.md, "Textures in attribute sets").
enum class ShaderInSet { kNo, kYes };

// The scene's top-level objects, each holding one reference the caller disposes.
std::vector<TQ3Object> richScene(Unknowns kind, ShaderInSet shaderInSet = ShaderInSet::kNo)
{
    std::vector<TQ3Object> top;
    top.push_back(camera());

    TQ3ViewObject view = Q3View_New();
    TQ3ViewHintsObject hints = Q3ViewHints_New(view);
    Q3Object_Dispose(view);
    TQ3CameraObject hintsCamera = camera();
    Q3ViewHints_SetCamera(hints, hintsCamera);
    Q3Object_Dispose(hintsCamera);
    TQ3GroupObject hintsLights = lightGroup();
    Q3ViewHints_SetLightGroup(hints, hintsLights);
    Q3Object_Dispose(hintsLights);
    TQ3AttributeSet hintsSet = colourSet(0.5f, 0.5f, 0.5f);
    Q3ViewHints_SetAttributeSet(hints, hintsSet);
    Q3Object_Dispose(hintsSet);
    top.push_back(hints);

    top.push_back(lightGroup());

    TQ3GroupObject info = Q3InfoGroup_New();
    put(info, Q3CString_New("a scene with one of everything"));
    top.push_back(info);

    // The model: a display group, not inline, holding state, an ordered
    // group, an inline group and a plain group.
    TQ3GroupObject model = Q3DisplayGroup_New();
    Q3DisplayGroup_SetState(model, kQ3DisplayGroupStateMaskIsDrawn | kQ3DisplayGroupStateMaskIsPicked |
                                       kQ3DisplayGroupStateMaskIsWritten);
    const TQ3SubdivisionStyleData subdivision{kQ3SubdivisionMethodConstant, 12, 7};
    put(model, Q3SubdivisionStyle_New(&subdivision));
    put(model, Q3FillStyle_New(kQ3FillStyleFilled));
    put(model, Q3BackfacingStyle_New(kQ3BackfacingStyleFlip));
    put(model, Q3InterpolationStyle_New(kQ3InterpolationStylePixel));
    TQ3AttributeSet highlight = colourSet(1, 1, 0);
    put(model, Q3HighlightStyle_New(highlight));
    Q3Object_Dispose(highlight);
    put(model, Q3PhongIllumination_New());
    const TQ3Vector3D translation{1, -2, 3.5f};
    put(model, Q3TranslateTransform_New(&translation));
    const TQ3RotateTransformData rotation{kQ3AxisY, 0.75f};
    put(model, Q3RotateTransform_New(&rotation));

    TQ3GroupObject ordered = Q3OrderedDisplayGroup_New();
    put(ordered, Q3LambertIllumination_New());
    put(ordered, mipmapShader());
    const TQ3Vector3D scale{2, 0.5f, 1};
    put(ordered, Q3ScaleTransform_New(&scale));
    addGeometries(ordered, shaderInSet == ShaderInSet::kYes);
    put(model, ordered);

    TQ3GroupObject inlineGroup = Q3DisplayGroup_New();
    // IsWritten too: a file does not carry that flag, and a group read is
    // given it.
    Q3DisplayGroup_SetState(inlineGroup, kQ3DisplayGroupStateMaskIsDrawn | kQ3DisplayGroupStateMaskIsInline |
                                             kQ3DisplayGroupStateMaskIsWritten);
    const TQ3Matrix4x4 matrix{{{1, 2, 3, 0}, {0, 1, 0, 0}, {0, 0.5f, 1, 0}, {4, 5, 6, 1}}};
    put(inlineGroup, Q3MatrixTransform_New(&matrix));
    put(inlineGroup, Q3NULLIllumination_New());
    put(inlineGroup, colourSet(0.25f, 0.5f, 0.75f));
    put(inlineGroup, pixmapShader());
    addGeometries(inlineGroup, shaderInSet == ShaderInSet::kYes);
    put(model, inlineGroup);

    // Unknown objects read from a file: two from a text file or one from a
    // big-endian binary file, the first in an I/O proxy group beside a box.
    std::vector<TQ3Object> unknowns;
    if (kind == Unknowns::kText)
        unknowns = readAll(bytesOf("3DMetafile ( 1 6 Normal )\n"
                                   "MyPrivateThing ( 1 2.5 \"three words here\" Nested ( 4 ) )\n"
                                   "OtherPrivateThing ( 7 )\n"));
    if (kind == Unknowns::kBinary)
        for (TQ3Object o : readAll(fileBytes(std::string(Q3_TEST_DATA_DIR) + "/unknown_be.3dmf")))
            if (Q3Object_IsType(o, kQ3ShapeTypeUnknown) == kQ3True)
                unknowns.push_back(o);
            else
                Q3Object_Dispose(o);
    EXPECT_EQ(unknowns.size(), kind == Unknowns::kText ? 2u : kind == Unknowns::kBinary ? 1u : 0u);
    TQ3GroupObject proxy = Q3IOProxyDisplayGroup_New();
    if (!unknowns.empty())
        put(proxy, unknowns[0]);
    const TQ3BoxData plainBox{{0, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}, nullptr, nullptr};
    put(proxy, Q3Box_New(&plainBox));
    put(model, proxy);

    TQ3GroupObject plain = Q3Group_New();
    for (std::size_t i = 1; i < unknowns.size(); ++i)
        put(plain, unknowns[i]);
    put(plain, Q3CString_New("a string in a plain group"));
    put(model, plain);

    top.push_back(model);
    return top;
}

// What reading `bytes` gives, written again in `mode`.
std::vector<unsigned char> rewrite(const std::vector<unsigned char>& bytes, TQ3FileMode mode)
{
    const std::vector<TQ3Object> objects = readAll(bytes);
    std::vector<unsigned char> out = writeObjects(objects, mode);
    disposeAll(objects);
    return out;
}

} // namespace

namespace {

int count(const Census& census, const std::string& line)
{
    const auto it = census.lines.find(line);
    return it == census.lines.end() ? 0 : it->second;
}

// The number of times lines starting with prefix occur.
int countStartingWith(const Census& census, const std::string& prefix)
{
    int n = 0;
    for (const auto& [line, times] : census.lines)
        if (line.rfind(prefix, 0) == 0)
            n += times;
    return n;
}

} // namespace

TEST_F(FileCensusTest, TheCensusCountsWhatTheSceneHolds)
{
    const std::vector<TQ3Object> scene = richScene(Unknowns::kText, ShaderInSet::kYes);
    const Census census = censusOfObjects(scene);
    disposeAll(scene);
    SCOPED_TRACE(censusText(census));
    EXPECT_EQ(census.failure, "");
    EXPECT_EQ(census.topLevel, 5);
    // The geometries twice (the ordered group's and the inline group's),
    // and the I/O proxy group's box.
    EXPECT_EQ(count(census, "object box "), 3);
    EXPECT_EQ(count(census, "box  face attributes 5"), 10);
    EXPECT_EQ(count(census, "box  face attributes 3,5"), 2);
    EXPECT_EQ(count(census, "box  attributes 5,7"), 2);
    EXPECT_EQ(count(census, "trng vertex attributes 1,5"), 6);
    EXPECT_EQ(count(census, "trng attributes 8"), 2);
    EXPECT_EQ(count(census, "elpd attributes 5,11"), 2);
    EXPECT_EQ(count(census, "plyg attributes 5"), 2);
    EXPECT_EQ(count(census, "plyg vertex attributes 5"), 2);
    EXPECT_EQ(count(census, "plyl vertex attributes 5"), 2);
    EXPECT_EQ(count(census, "plyl segment attributes 5"), 2);
    EXPECT_EQ(count(census, "attr attributes 5"), 1);
    // The texture shaders: one in each ellipsoid's set and one in the
    // inline group (the same pixels), the mipmap in the ordered group.
    EXPECT_EQ(count(census, "object txsu"), 4);
    EXPECT_EQ(countStartingWith(census, "txsu texture txpm 4x4 type 1 pixels "), 3);
    EXPECT_EQ(countStartingWith(census, "txsu texture txmm type 2 mipmapped 4x4:"), 1);
    for (const auto& [line, n] : census.lines)
        EXPECT_EQ(line.find("storage"), std::string::npos) << line;
    // Lights at the top level and in the view hints.
    for (const char* light : {"object ambn", "object drct", "object pntl", "object spot"})
        EXPECT_EQ(count(census, light), 2) << light;
    EXPECT_EQ(count(census, "object lghg"), 2);
    EXPECT_EQ(count(census, "object vana"), 2);
    EXPECT_EQ(count(census, "object vwhn"), 1);
    EXPECT_EQ(count(census, "vwhn attributes 5"), 1);
    EXPECT_EQ(count(census, "high attributes 5"), 1);
    EXPECT_EQ(count(census, "dspg state 0x31"), 1);
    EXPECT_EQ(count(census, "dspg state 0x23"), 1);
    EXPECT_EQ(count(census, "ordg state 0x3d"), 1);
    EXPECT_EQ(count(census, "iopx state 0x3d"), 1);
    EXPECT_EQ(count(census, "object info"), 1);
    EXPECT_EQ(count(census, "object grup"), 1);
    EXPECT_EQ(count(census, "object strc"), 2);
    EXPECT_EQ(count(census, "unknown text MyPrivateThing: 1 2.5 \"three words here\" Nested ( 4 )"), 1);
    EXPECT_EQ(count(census, "unknown text OtherPrivateThing: 7"), 1);
    // A text file written from the scene gives the census of the objects it
    // was written from, the shaders in its sets included.
    const std::vector<TQ3Object> plain = richScene(Unknowns::kText, ShaderInSet::kYes);
    const Census written = censusOf(writeObjects(plain, kQ3FileModeNormal | kQ3FileModeText));
    EXPECT_TRUE(censusOfObjects(plain) == written) << censusDifference(censusOfObjects(plain), written);
    disposeAll(plain);
}

TEST_F(FileCensusTest, TextThenBinaryThenTextLosesNothing)
{
    const std::vector<TQ3Object> scene = richScene(Unknowns::kNone, ShaderInSet::kYes);
    const Census memory = censusOfObjects(scene);
    const std::vector<unsigned char> text1 = writeObjects(scene, kQ3FileModeNormal | kQ3FileModeText);
    disposeAll(scene);
    const std::vector<unsigned char> binary = rewrite(text1, kQ3FileModeNormal);
    const std::vector<unsigned char> text2 = rewrite(binary, kQ3FileModeNormal | kQ3FileModeText);
    ASSERT_EQ(std::string(binary.begin(), binary.begin() + 4), "3DMF");
    const Census a = censusOf(text1), b = censusOf(binary), c = censusOf(text2);
    SCOPED_TRACE(censusText(a));
    EXPECT_EQ(a.failure, "");
    EXPECT_GT(a.lines.size(), 30u);
    EXPECT_TRUE(memory == a) << "memory -> text:\n" << censusDifference(memory, a);
    EXPECT_TRUE(a == b) << "text -> binary:\n" << censusDifference(a, b);
    EXPECT_TRUE(b == c) << "binary -> text:\n" << censusDifference(b, c);
}

TEST_F(FileCensusTest, UnknownObjectsComeBackThroughFilesOfTheirOwnEncoding)
{
    const std::pair<Unknowns, TQ3FileMode> cases[] = {{Unknowns::kText, kQ3FileModeNormal | kQ3FileModeText},
                                                      {Unknowns::kBinary, kQ3FileModeNormal}};
    for (const auto& [kind, mode] : cases) {
        SCOPED_TRACE(mode);
        const std::vector<TQ3Object> scene = richScene(kind);
        const Census memory = censusOfObjects(scene);
        const std::vector<unsigned char> first = writeObjects(scene, mode);
        disposeAll(scene);
        const std::vector<unsigned char> second = rewrite(first, mode);
        const Census a = censusOf(first), b = censusOf(second);
        EXPECT_EQ(countStartingWith(a, "unknown "), kind == Unknowns::kText ? 2 : 1) << censusText(a);
        EXPECT_TRUE(memory == a) << censusDifference(memory, a);
        EXPECT_TRUE(a == b) << censusDifference(a, b);
    }
}
