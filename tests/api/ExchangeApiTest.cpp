// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Q3Exchange_Write and Q3Exchange_Read (Q3Exchange.h, a Q3 extension):
// round trips 3DMF -> glTF -> Q3 that keep, for every geometry of the test
// files, what Q3Geometry_GetDecomposed gives under the same subdivision
// (triangle count, positions to 1e-6 relative, normals, uvs, vertex colours)
// and a textured, transparent, grouped model's texture pixels exactly; every
// file written passes the Khronos glTF validator (scripts/gltf-validate.js)
// with no errors; broken inputs are clear errors that leave nothing behind.

#include "FileTestSupport.h"
#include "RenderTestSupport.h"
#include "TextureTestSupport.h"

#include "Q3Exchange.h"
#include "QD3DCamera.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DIO.h"
#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"
#include "QD3DString.h"
#include "QD3DStyle.h"
#include "QD3DMath.h"
#include "QD3DTransform.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace {

using namespace q3test;

constexpr float kSegments = 6.0f;

std::string temporaryPath(const std::string& name)
{
    return ::testing::TempDir() + "q3exchange-" + std::to_string(long(::getpid())) + "-" + name;
}

bool exists(const std::string& path)
{
    return std::ifstream(path).good();
}

// The Khronos validator's verdict: empty when the file has no error, else
// its report.
std::string validatorErrors(const std::string& path)
{
    const std::string script = std::string(Q3_TEST_DATA_DIR) + "/../../scripts/gltf-validate.js";
    const std::string log = path + ".log";
    const int status = std::system(("node '" + script + "' '" + path + "' > '" + log + "' 2>&1").c_str());
    std::ifstream in(log);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::remove(log.c_str());
    return status == 0 ? std::string() : "validator exit status " + std::to_string(status) + ":\n" + text;
}

// Triangles and their per-vertex attributes, gathered from TriMeshes in
// order, so that a decomposition and what a round trip read back compare.
struct Triangles {
    std::vector<TQ3Point3D> points;
    std::vector<std::array<unsigned long, 3>> triangles;
    // Per vertex, NaN where a vertex has none.
    std::vector<TQ3Vector3D> normals;
    std::vector<TQ3Param2D> uvs;
    std::vector<TQ3ColorRGB> colors;
    bool hasNormals = false, hasUVs = false, hasColors = false;

    void add(TQ3GeometryObject triMesh)
    {
        TQ3TriMeshData data{};
        ASSERT_EQ(Q3TriMesh_GetData(triMesh, &data), kQ3Success);
        const unsigned long base = static_cast<unsigned long>(points.size());
        const float none = std::nanf("");
        for (unsigned long i = 0; i < data.numPoints; ++i) {
            points.push_back(data.points[i]);
            normals.push_back({none, none, none});
            uvs.push_back({none, none});
            colors.push_back({none, none, none});
        }
        for (unsigned long t = 0; t < data.numTriangles; ++t)
            triangles.push_back({base + data.triangles[t].pointIndices[0], base + data.triangles[t].pointIndices[1],
                                 base + data.triangles[t].pointIndices[2]});
        for (unsigned long a = 0; a < data.numVertexAttributeTypes; ++a) {
            const TQ3TriMeshAttributeData& attribute = data.vertexAttributeTypes[a];
            for (unsigned long i = 0; i < data.numPoints; ++i) {
                if (attribute.attributeUseArray != nullptr && attribute.attributeUseArray[i] == 0)
                    continue;
                if (attribute.attributeType == kQ3AttributeTypeNormal) {
                    hasNormals = true;
                    normals[base + i] = static_cast<const TQ3Vector3D*>(attribute.data)[i];
                } else if (attribute.attributeType == kQ3AttributeTypeSurfaceUV) {
                    hasUVs = true;
                    uvs[base + i] = static_cast<const TQ3Param2D*>(attribute.data)[i];
                } else if (attribute.attributeType == kQ3AttributeTypeDiffuseColor) {
                    hasColors = true;
                    colors[base + i] = static_cast<const TQ3ColorRGB*>(attribute.data)[i];
                }
            }
        }
        Q3TriMesh_EmptyData(&data);
    }
};

// Every object of one of `types` inside a group (or the object itself),
// depth first, in order; the group keeps the references.
void collectOfTypes(TQ3Object object, std::initializer_list<TQ3ObjectType> types, std::vector<TQ3Object>& out)
{
    for (TQ3ObjectType type : types)
        if (Q3Object_IsType(object, type) == kQ3True) {
            out.push_back(object);
            return;
        }
    if (Q3Object_IsType(object, kQ3ShapeTypeGroup) != kQ3True)
        return;
    TQ3GroupPosition position = nullptr;
    Q3Group_GetFirstPosition(object, &position);
    while (position != nullptr) {
        TQ3Object child = nullptr;
        Q3Group_GetPositionObject(object, position, &child);
        collectOfTypes(child, types, out);
        Q3Object_Dispose(child);
        Q3Group_GetNextPosition(object, &position);
    }
}

// The first object of `type` in `group` (a new reference), or NULL.
TQ3Object firstOfType(TQ3GroupObject group, TQ3ObjectType type)
{
    TQ3GroupPosition position = nullptr;
    TQ3Object object = nullptr;
    if (Q3Group_GetFirstPositionOfType(group, type, &position) == kQ3Success && position != nullptr)
        Q3Group_GetPositionObject(group, position, &object);
    return object;
}

// Every TriMesh inside a group, depth first, in order.
void collectTriMeshes(TQ3Object object, std::vector<TQ3Object>& out)
{
    collectOfTypes(object, {kQ3GeometryTypeTriMesh}, out);
}

// Every triangle of every TriMesh inside a group.
Triangles trianglesIn(TQ3Object group)
{
    std::vector<TQ3Object> meshes;
    collectTriMeshes(group, meshes);
    Triangles all;
    for (TQ3Object mesh : meshes)
        all.add(mesh);
    return all;
}

double relative(double a, double b)
{
    return std::fabs(a - b) / std::max(1.0, std::max(std::fabs(a), std::fabs(b)));
}

std::vector<TQ3Object> readFile(const std::string& path)
{
    TQ3StorageObject storage = Q3UnixPathStorage_New(path.c_str());
    TQ3FileObject file = Q3File_New();
    TQ3FileMode mode = 0;
    EXPECT_EQ(Q3File_SetStorage(file, storage), kQ3Success);
    Q3Object_Dispose(storage);
    EXPECT_EQ(Q3File_OpenRead(file, &mode), kQ3Success) << path;
    return readAllAndClose(file);
}

class ExchangeApiTest : public Q3ApiTest {
protected:
    void TearDown() override
    {
        for (const std::string& path : m_written)
            std::remove(path.c_str());
        Q3ApiTest::TearDown();
    }

    // A display group holding `objects` in order; it takes over the
    // caller's reference to each.
    static TQ3GroupObject displayGroupOf(std::initializer_list<TQ3Object> objects)
    {
        TQ3GroupObject group = Q3DisplayGroup_New();
        for (TQ3Object object : objects) {
            EXPECT_NE(Q3Group_AddObject(group, object), nullptr);
            Q3Object_Dispose(object);
        }
        return group;
    }

    // Writes object with constant subdivision, checks the file with the
    // validator, reads it back.
    TQ3GroupObject roundTrip(TQ3Object object, const std::string& name)
    {
        const std::string path = temporaryPath(name);
        m_written.push_back(path);
        TQ3ExchangeOptions options;
        EXPECT_EQ(Q3Exchange_InitOptions(&options), kQ3Success);
        options.subdivisionFromSize = kQ3False;
        options.subdivisionMethod = kQ3SubdivisionMethodConstant;
        options.subdivisionValue = kSegments;
        EXPECT_EQ(Q3Exchange_Write(object, path.c_str(), &options), kQ3Success) << name;
        EXPECT_EQ(validatorErrors(path), "") << name;
        return Q3Exchange_Read(path.c_str(), kQ3ExchangeFormatAny);
    }

    // What a view draws the geometry as under the same subdivision.
    Triangles decomposition(TQ3GeometryObject geometry)
    {
        Triangles out;
        if (Q3Geometry_GetType(geometry) == kQ3GeometryTypeTriMesh) {
            out.add(geometry);
            return out;
        }
        Pixmap image(8, 8);
        TestView view(image.pixmap());
        EXPECT_EQ(Q3View_StartRendering(view.view()), kQ3Success);
        const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodConstant, kSegments, kSegments};
        Q3SubdivisionStyle_Submit(&style, view.view());
        TQ3GeometryObject decomposed = Q3Geometry_GetDecomposed(geometry, view.view());
        if (decomposed != nullptr && Q3Geometry_GetType(decomposed) == kQ3GeometryTypeTriMesh)
            out.add(decomposed);
        if (decomposed != nullptr)
            Q3Object_Dispose(decomposed);
        EXPECT_EQ(Q3View_EndRendering(view.view()), kQ3ViewStatusDone);
        return out;
    }

    // One triangle's corners with their attributes (NaN where none), for
    // comparing decompositions whose triangles a round trip may regroup: a
    // geometry drawn in parts (face attribute sets) becomes a primitive per
    // part.
    struct Corner {
        TQ3Point3D point;
        TQ3Vector3D normal;
        TQ3Param2D uv;
        TQ3ColorRGB color;
    };
    using Face = std::array<Corner, 3>;

    static std::vector<Face> faces(const Triangles& t)
    {
        std::vector<Face> out;
        for (const auto& tri : t.triangles) {
            Face face;
            for (int k = 0; k < 3; ++k)
                face[k] = Corner{t.points[tri[k]], t.normals[tri[k]], t.uvs[tri[k]], t.colors[tri[k]]};
            out.push_back(face);
        }
        // Sorted by position: exact in both (positions are copied as floats).
        std::stable_sort(out.begin(), out.end(), [](const Face& a, const Face& b) {
            for (int k = 0; k < 3; ++k) {
                const float x[3] = {a[k].point.x, a[k].point.y, a[k].point.z};
                const float y[3] = {b[k].point.x, b[k].point.y, b[k].point.z};
                for (int c = 0; c < 3; ++c)
                    if (x[c] != y[c])
                        return x[c] < y[c];
            }
            return false;
        });
        return out;
    }

    static void expectSame(const Triangles& original, const Triangles& back, const std::string& what)
    {
        ASSERT_EQ(back.triangles.size(), original.triangles.size()) << what;
        const std::vector<Face> a = faces(original);
        const std::vector<Face> b = faces(back);
        for (std::size_t t = 0; t < a.size(); ++t)
            for (int k = 0; k < 3; ++k) {
                const Corner& o = a[t][k];
                const Corner& r = b[t][k];
                const std::string where = what + " triangle " + std::to_string(t) + " corner " + std::to_string(k);
                ASSERT_LE(relative(o.point.x, r.point.x) + relative(o.point.y, r.point.y) +
                              relative(o.point.z, r.point.z),
                          1e-6)
                    << where;
                if (o.normal.x == o.normal.x) {
                    const TQ3Vector3D& n = o.normal;
                    const double length = std::sqrt(double(n.x) * n.x + double(n.y) * n.y + double(n.z) * n.z);
                    EXPECT_NEAR(r.normal.x, n.x / length, 1e-6) << where;
                    EXPECT_NEAR(r.normal.y, n.y / length, 1e-6) << where;
                    EXPECT_NEAR(r.normal.z, n.z / length, 1e-6) << where;
                }
                if (o.uv.u == o.uv.u) {
                    // v goes through 1 - (1 - v): a rounding of at most 2^-24.
                    EXPECT_EQ(r.uv.u, o.uv.u) << where;
                    EXPECT_NEAR(r.uv.v, o.uv.v, 1.2e-7) << where;
                }
                if (o.color.r == o.color.r) {
                    EXPECT_EQ(r.color.r, o.color.r) << where;
                    EXPECT_EQ(r.color.g, o.color.g) << where;
                    EXPECT_EQ(r.color.b, o.color.b) << where;
                }
            }
    }

    std::vector<std::string> m_written;
};

TEST_F(ExchangeApiTest, EveryGeometryOfTheTestFilesKeepsItsDecomposition)
{
    int checked = 0;
    for (const char* name : {"curves_quadrics.3dmf", "polygons.3dmf", "mesh.3dmf", "nurbpatch.3dmf",
                             "textured_box.3dmf", "triangle_le.3dmf", "attributes.3dmf", "part_sets.3dmf"}) {
        std::vector<TQ3Object> objects = readFile(std::string(Q3_TEST_DATA_DIR) + "/" + name);
        for (std::size_t k = 0; k < objects.size(); ++k) {
            TQ3Object object = objects[k];
            if (Q3Object_IsType(object, kQ3ShapeTypeGeometry) != kQ3True)
                continue;
            const std::string what = std::string(name) + " object " + std::to_string(k);
            const Triangles original = decomposition(object);
            if (original.triangles.empty())
                continue; // curves and points: no triangles to compare
            TQ3GroupObject back = roundTrip(object, std::to_string(k) + "-" + name + ".glb");
            ASSERT_NE(back, nullptr) << what;
            const Triangles read = trianglesIn(back);
            expectSame(original, read, what);
            Q3Object_Dispose(back);
            ++checked;
        }
        for (TQ3Object object : objects)
            Q3Object_Dispose(object);
    }
    EXPECT_GE(checked, 8);
}

// A model with everything a material carries: a TriMesh with vertex
// normals, uvs and colours under an attribute set holding a diffuse colour,
// a transparency colour and a texture shader (mipmap texture with alpha,
// clamped in u) as its surface shader; drawn twice, translated and then
// also scaled inside a nested group.
class ExchangeModelTest : public ExchangeApiTest {
protected:
    void SetUp() override
    {
        ExchangeApiTest::SetUp();
        for (unsigned i = 0; i < kWidth * kHeight; ++i) {
            m_pixels.push_back(static_cast<unsigned char>(40 + 50 * (i % 4))); // alpha
            m_pixels.push_back(static_cast<unsigned char>(17 * i));
            m_pixels.push_back(static_cast<unsigned char>(255 - 13 * i));
            m_pixels.push_back(static_cast<unsigned char>(i * i));
        }
        TQ3StorageObject storage = Q3MemoryStorage_New(m_pixels.data(), static_cast<unsigned long>(m_pixels.size()));
        const TQ3Mipmap mipmap =
            q3test::bigEndianMipmap(storage, kQ3PixelTypeARGB32, false, {{kWidth, kHeight, kWidth * 4, 0}});
        TQ3TextureObject texture = Q3MipmapTexture_New(&mipmap);
        Q3Object_Dispose(storage);
        TQ3ShaderObject shader = Q3TextureShader_New(texture);
        Q3Object_Dispose(texture);
        ASSERT_EQ(Q3Shader_SetUBoundary(shader, kQ3ShaderUVBoundaryClamp), kQ3Success);

        TQ3AttributeSet set = Q3AttributeSet_New();
        const TQ3ColorRGB diffuse{0.25f, 0.5f, 0.75f};
        const TQ3ColorRGB transparency{0.5f, 0.5f, 0.5f};
        Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &diffuse);
        Q3AttributeSet_Add(set, kQ3AttributeTypeTransparencyColor, &transparency);
        ASSERT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
        Q3Object_Dispose(shader);

        TQ3Point3D points[4] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0.5f}};
        TQ3TriMeshTriangleData triangles[2] = {{{0, 1, 2}}, {{0, 2, 3}}};
        TQ3Vector3D normals[4] = {{0, 0, 1}, {0, 0, 1}, {0, 0.6f, 0.8f}, {0, 0.6f, 0.8f}};
        TQ3Param2D uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0.125f, 0.875f}};
        TQ3ColorRGB colors[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.3f, 0.6f, 0.9f}};
        TQ3TriMeshAttributeData vertex[3] = {{kQ3AttributeTypeNormal, normals, nullptr},
                                             {kQ3AttributeTypeSurfaceUV, uvs, nullptr},
                                             {kQ3AttributeTypeDiffuseColor, colors, nullptr}};
        // The set, two triangles, no triangle or edge attributes, no edges,
        // four points with three attribute arrays.
        TQ3TriMeshData data{set, 2, triangles, 0, nullptr, 0, nullptr, 0, nullptr, 4, points, 3, vertex,
                            {{0, 0, 0}, {2, 1, 0.5f}, kQ3False}};
        TQ3GeometryObject mesh = Q3TriMesh_New(&data);
        Q3Object_Dispose(set);
        ASSERT_NE(mesh, nullptr);

        m_group = Q3DisplayGroup_New();
        const TQ3Vector3D move{1, 2, 3};
        const TQ3Vector3D scale{2, 2, 2};
        TQ3TransformObject translate = Q3TranslateTransform_New(&move);
        TQ3TransformObject grow = Q3ScaleTransform_New(&scale);
        TQ3GroupObject inner = Q3DisplayGroup_New();
        Q3Group_AddObject(inner, grow);
        Q3Group_AddObject(inner, mesh);
        Q3Group_AddObject(m_group, translate);
        Q3Group_AddObject(m_group, mesh);
        Q3Group_AddObject(m_group, inner);
        for (TQ3Object o : {TQ3Object(translate), TQ3Object(grow), TQ3Object(inner), TQ3Object(mesh)})
            Q3Object_Dispose(o);
    }

    void TearDown() override
    {
        Q3Object_Dispose(m_group);
        ExchangeApiTest::TearDown();
    }

    TQ3BoundingBox bounds(TQ3Object object)
    {
        Pixmap image(8, 8);
        TestView view(image.pixmap());
        TQ3BoundingBox box{};
        EXPECT_EQ(Q3View_StartBoundingBox(view.view(), kQ3ComputeBoundsExact), kQ3Success);
        do
            Q3Object_Submit(object, view.view());
        while (Q3View_EndBoundingBox(view.view(), &box) == kQ3ViewStatusRetraverse);
        return box;
    }

    static constexpr unsigned long kWidth = 4, kHeight = 3;
    std::vector<unsigned char> m_pixels;
    TQ3GroupObject m_group = nullptr;
};

TEST_F(ExchangeModelTest, TexturedTransparentGroupedModelSurvivesGlbAndGltf)
{
    for (const char* name : {"model.glb", "model.gltf"}) {
        TQ3GroupObject back = roundTrip(m_group, name);
        ASSERT_NE(back, nullptr) << name;

        // Placement: the same world-space box.
        const TQ3BoundingBox a = bounds(m_group);
        const TQ3BoundingBox b = bounds(back);
        EXPECT_NEAR(b.min.x, a.min.x, 1e-6 * 8);
        EXPECT_NEAR(b.min.y, a.min.y, 1e-6 * 8);
        EXPECT_NEAR(b.min.z, a.min.z, 1e-6 * 8);
        EXPECT_NEAR(b.max.x, a.max.x, 1e-6 * 8);
        EXPECT_NEAR(b.max.y, a.max.y, 1e-6 * 8);
        EXPECT_NEAR(b.max.z, a.max.z, 1e-6 * 8);

        // The shared mesh stays one object, drawn twice.
        std::vector<TQ3Object> meshes;
        collectTriMeshes(back, meshes);
        ASSERT_EQ(meshes.size(), 2u) << name;
        EXPECT_EQ(meshes[0], meshes[1]) << name;

        Triangles read;
        read.add(meshes[0]);
        ASSERT_EQ(read.triangles.size(), 2u);
        const TQ3ColorRGB colors[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.3f, 0.6f, 0.9f}};
        const TQ3Param2D uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0.125f, 0.875f}};
        for (int i = 0; i < 4; ++i) {
            EXPECT_EQ(read.colors[i].r, colors[i].r);
            EXPECT_EQ(read.colors[i].g, colors[i].g);
            EXPECT_EQ(read.colors[i].b, colors[i].b);
            EXPECT_EQ(read.uvs[i].u, uvs[i].u);
            EXPECT_NEAR(read.uvs[i].v, uvs[i].v, 1.2e-7);
        }

        // The material: transparency per vertex (the vertex colours carry
        // alpha), the diffuse colour, the texture's pixels exactly.
        TQ3TriMeshData data{};
        ASSERT_EQ(Q3TriMesh_GetData(meshes[0], &data), kQ3Success);
        bool transparency = false;
        for (unsigned long k = 0; k < data.numVertexAttributeTypes; ++k)
            if (data.vertexAttributeTypes[k].attributeType == kQ3AttributeTypeTransparencyColor) {
                transparency = true;
                const auto* t = static_cast<const TQ3ColorRGB*>(data.vertexAttributeTypes[k].data);
                EXPECT_EQ(t[0].r, 0.5f);
            }
        EXPECT_TRUE(transparency) << name;
        TQ3AttributeSet set = data.triMeshAttributeSet;
        ASSERT_NE(set, nullptr);
        TQ3ColorRGB diffuse{};
        EXPECT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeDiffuseColor, &diffuse), kQ3Success);
        EXPECT_EQ(diffuse.b, 0.75f);
        TQ3ShaderObject shader = nullptr;
        ASSERT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
        TQ3ShaderUVBoundary u = kQ3ShaderUVBoundaryWrap, v = kQ3ShaderUVBoundaryClamp;
        Q3Shader_GetUBoundary(shader, &u);
        Q3Shader_GetVBoundary(shader, &v);
        EXPECT_EQ(u, kQ3ShaderUVBoundaryClamp);
        EXPECT_EQ(v, kQ3ShaderUVBoundaryWrap);
        TQ3TextureObject texture = nullptr;
        ASSERT_EQ(Q3TextureShader_GetTexture(shader, &texture), kQ3Success);
        TQ3Mipmap mipmap{};
        ASSERT_EQ(Q3MipmapTexture_GetMipmap(texture, &mipmap), kQ3Success);
        EXPECT_EQ(mipmap.pixelType, kQ3PixelTypeARGB32);
        EXPECT_EQ(mipmap.mipmaps[0].width, kWidth);
        EXPECT_EQ(mipmap.mipmaps[0].height, kHeight);
        std::vector<unsigned char> pixels(m_pixels.size());
        unsigned long got = 0;
        EXPECT_EQ(Q3Storage_GetData(mipmap.image, 0, static_cast<unsigned long>(pixels.size()), pixels.data(), &got),
                  kQ3Success);
        EXPECT_EQ(mipmap.mipmaps[0].rowBytes, kWidth * 4);
        EXPECT_EQ(pixels, m_pixels) << name;
        Q3Object_Dispose(mipmap.image);
        Q3Object_Dispose(texture);
        Q3Object_Dispose(shader);
        Q3TriMesh_EmptyData(&data);
        Q3Object_Dispose(back);
    }
}

// A file that transforms its texture coordinates with KHR_texture_transform
// (as an atlas does) reads with the transform applied to the uvs.
TEST_F(ExchangeModelTest, KhrTextureTransformIsAppliedToTheUvs)
{
    const std::string path = temporaryPath("transformed.gltf");
    m_written.push_back(path);
    ASSERT_EQ(Q3Exchange_Write(m_group, path.c_str(), nullptr), kQ3Success);
    std::string json;
    {
        std::ifstream in(path);
        json.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const std::size_t texture = json.find("\"baseColorTexture\"");
    ASSERT_NE(texture, std::string::npos);
    const std::size_t brace = json.find('{', texture);
    json.insert(brace + 1, "\"extensions\": { \"KHR_texture_transform\": { \"offset\": [0.5, 0], "
                           "\"scale\": [2, 2], \"rotation\": 0 } }, ");
    const std::size_t used = json.find("\"extensionsUsed\"");
    if (used == std::string::npos)
        json.insert(json.find('{') + 1, "\"extensionsUsed\": [\"KHR_texture_transform\"], ");
    else
        json.insert(json.find('[', used) + 1, "\"KHR_texture_transform\", ");
    std::ofstream(path) << json;
    EXPECT_EQ(validatorErrors(path), "");

    TQ3GroupObject back = Q3Exchange_Read(path.c_str(), kQ3ExchangeFormatAny);
    ASSERT_NE(back, nullptr);
    std::vector<TQ3Object> meshes;
    collectTriMeshes(back, meshes);
    ASSERT_FALSE(meshes.empty());
    Triangles read;
    read.add(meshes[0]);
    const TQ3Param2D uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0.125f, 0.875f}};
    for (int i = 0; i < 4; ++i) {
        // s = u, t = 1 - v; s' = 2 s + 0.5, t' = 2 t; back: u' = s', v' = 1 - t'.
        EXPECT_NEAR(read.uvs[i].u, 2 * uvs[i].u + 0.5, 1e-6) << i;
        EXPECT_NEAR(read.uvs[i].v, 1 - 2 * (1 - uvs[i].v), 1e-6) << i;
    }
    Q3Object_Dispose(back);
}

TEST_F(ExchangeModelTest, TheDefaultSubdivisionAndNullOptionsWrite)
{
    const std::string path = temporaryPath("defaults.glb");
    m_written.push_back(path);
    EXPECT_EQ(Q3Exchange_Write(m_group, path.c_str(), nullptr), kQ3Success);
    EXPECT_EQ(validatorErrors(path), "");
}

TEST_F(ExchangeApiTest, BrokenInputsAreClearErrors)
{
    const std::string broken = temporaryPath("broken.gltf");
    m_written.push_back(broken);
    {
        std::ofstream out(broken);
        out << "{ \"asset\": { \"version\": \"2.0\" }, \"meshes\": [ { \"primitives\": [ { \"attributes\": "
               "{ \"POSITION\": 7 } } ] } ] }";
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Exchange_Read(broken.c_str(), kQ3ExchangeFormatAny), nullptr), kQ3ErrorInvalidData);
    const std::string garbage = temporaryPath("garbage.glb");
    m_written.push_back(garbage);
    {
        std::ofstream out(garbage);
        out << "glTF not really";
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Exchange_Read(garbage.c_str(), kQ3ExchangeFormatAny), nullptr), kQ3ErrorInvalidData);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Exchange_Read(temporaryPath("absent.glb").c_str(), kQ3ExchangeFormatAny), nullptr),
                    kQ3ErrorFileNotOpen);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Exchange_Read(nullptr, kQ3ExchangeFormatAny), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Exchange_Read(broken.c_str(), TQ3ExchangeFormat(99)), nullptr),
                    kQ3ErrorInvalidParameter);
}

// Well-formed JSON that glTF's references make impossible: each is
// kQ3ErrorInvalidData, never a crash or a half-built group.
TEST_F(ExchangeApiTest, ImpossibleReferencesAreInvalidData)
{
    const std::string buffer = "\"buffers\": [ { \"byteLength\": 36, \"uri\": "
                               "\"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\" } ], "
                               "\"bufferViews\": [ { \"buffer\": 0, \"byteLength\": 36 } ], "
                               "\"accessors\": [ { \"bufferView\": 0, \"componentType\": 5126, \"count\": 3, "
                               "\"type\": \"VEC3\", \"min\": [0, 0, 0], \"max\": [1, 1, 0] } ], "
                               "\"meshes\": [ { \"primitives\": [ { \"attributes\": { \"POSITION\": 0 } } ] } ], ";
    const std::string asset = "{ \"asset\": { \"version\": \"2.0\" }, ";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"cycle", asset + buffer + "\"nodes\": [ { \"children\": [1] }, { \"children\": [0] } ], "
                  "\"scenes\": [ { \"nodes\": [0] } ] }"},
        {"no-such-mesh", asset + buffer + "\"nodes\": [ { \"mesh\": 5 } ], \"scenes\": [ { \"nodes\": [0] } ] }"},
        {"no-such-node", asset + buffer + "\"nodes\": [ { \"mesh\": 0 } ], \"scenes\": [ { \"nodes\": [3] } ] }"},
        {"short-buffer", asset + "\"buffers\": [ { \"byteLength\": 4, \"uri\": "
                                 "\"data:application/octet-stream;base64,AAAAAA==\" } ], "
                                 "\"bufferViews\": [ { \"buffer\": 0, \"byteLength\": 4 } ], "
                                 "\"accessors\": [ { \"bufferView\": 0, \"componentType\": 5126, \"count\": 3, "
                                 "\"type\": \"VEC3\" } ], "
                                 "\"meshes\": [ { \"primitives\": [ { \"attributes\": { \"POSITION\": 0 } } ] } ], "
                                 "\"nodes\": [ { \"mesh\": 0 } ], \"scenes\": [ { \"nodes\": [0] } ] }"},
        {"bad-index", asset + buffer.substr(0, buffer.find("\"meshes\"")) +
                          "\"meshes\": [ { \"primitives\": [ { \"attributes\": { \"POSITION\": 0 }, \"indices\": 0 } ] } ], "
                          "\"nodes\": [ { \"mesh\": 0 } ], \"scenes\": [ { \"nodes\": [0] } ] }"},
    };
    for (const auto& [name, json] : cases) {
        const std::string path = temporaryPath(name + ".gltf");
        m_written.push_back(path);
        std::ofstream(path) << json;
        TQ3GroupObject group = nullptr;
        EXPECT_Q3_ERROR(group = Q3Exchange_Read(path.c_str(), kQ3ExchangeFormatAny), kQ3ErrorInvalidData);
        EXPECT_EQ(group, nullptr) << name;
        if (group != nullptr)
            Q3Object_Dispose(group);
    }
    // The same buffer with a good scene reads.
    const std::string good = temporaryPath("good.gltf");
    m_written.push_back(good);
    std::ofstream(good) << asset + buffer + "\"nodes\": [ { \"mesh\": 0 } ], \"scenes\": [ { \"nodes\": [0] } ] }";
    TQ3GroupObject group = Q3Exchange_Read(good.c_str(), kQ3ExchangeFormatAny);
    ASSERT_NE(group, nullptr);
    std::vector<TQ3Object> meshes;
    collectTriMeshes(group, meshes);
    EXPECT_EQ(meshes.size(), 1u);
    Q3Object_Dispose(group);
}

TEST_F(ExchangeApiTest, AFailedWriteLeavesNothingAndBadOptionsAreRefused)
{
    TQ3GroupObject group = Q3DisplayGroup_New();
    const std::string unwritable = temporaryPath("no-such-directory/out.glb");
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Exchange_Write(group, unwritable.c_str(), nullptr), kQ3Failure), kQ3ErrorFileNotOpen);
    EXPECT_FALSE(exists(unwritable));
    const std::string unknown = temporaryPath("out.xyz");
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Exchange_Write(group, unknown.c_str(), nullptr), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_FALSE(exists(unknown));
    TQ3ExchangeOptions options;
    Q3Exchange_InitOptions(&options);
    options.subdivisionFromSize = kQ3False;
    const std::string path = temporaryPath("out.glb");
    for (float bad : {0.0f, -1.0f, std::nanf(""), INFINITY}) {
        options.subdivisionValue = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Exchange_Write(group, path.c_str(), &options), kQ3Failure),
                        kQ3ErrorInvalidParameter);
    }
    options.subdivisionMethod = kQ3SubdivisionMethodScreenSpace;
    options.subdivisionValue = 1.0f;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Exchange_Write(group, path.c_str(), &options), kQ3Failure), kQ3ErrorInvalidParameter);
    // Screen space needs a view with a camera and a draw context; the view
    // must be one.
    TQ3ViewObject bare = Q3View_New();
    options.view = bare;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Exchange_Write(group, path.c_str(), &options), kQ3Failure), kQ3ErrorInvalidParameter);
    options.view = group;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Exchange_Write(group, path.c_str(), &options), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    options.view = nullptr;
    Q3Object_Dispose(bare);
    EXPECT_FALSE(exists(path));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Exchange_Write(nullptr, path.c_str(), nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Exchange_Write(group, nullptr, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Exchange_InitOptions(nullptr), kQ3ErrorNULLParameter);
    Q3Object_Dispose(group);
}

// OBJ and STL are flat: the two instances come back as separate meshes with
// the transforms applied, so the world box and the triangle count are what
// must survive; OBJ also keeps the uvs, the material and the texels.
TEST_F(ExchangeModelTest, ObjKeepsTheModelFlattenedWithItsMaterialAndTexture)
{
    const std::string path = temporaryPath("model.obj");
    const std::string stem = path.substr(0, path.size() - 4);
    for (const std::string& file : {path, stem + ".mtl", stem + "_0.png"})
        m_written.push_back(file);
    ASSERT_EQ(Q3Exchange_Write(m_group, path.c_str(), nullptr), kQ3Success);
    EXPECT_TRUE(exists(stem + ".mtl"));
    EXPECT_TRUE(exists(stem + "_0.png"));
    TQ3GroupObject back = Q3Exchange_Read(path.c_str(), kQ3ExchangeFormatAny);
    ASSERT_NE(back, nullptr);
    const TQ3BoundingBox a = bounds(m_group);
    const TQ3BoundingBox b = bounds(back);
    EXPECT_NEAR(b.min.x, a.min.x, 1e-5);
    EXPECT_NEAR(b.max.x, a.max.x, 1e-5);
    EXPECT_NEAR(b.min.z, a.min.z, 1e-5);
    EXPECT_NEAR(b.max.z, a.max.z, 1e-5);
    const Triangles read = trianglesIn(back);
    EXPECT_EQ(read.triangles.size(), 4u);
    std::vector<TQ3Object> meshes;
    collectTriMeshes(back, meshes);
    ASSERT_FALSE(meshes.empty());
    TQ3TriMeshData data{};
    ASSERT_EQ(Q3TriMesh_GetData(meshes[0], &data), kQ3Success);
    ASSERT_NE(data.triMeshAttributeSet, nullptr);
    TQ3ShaderObject shader = nullptr;
    ASSERT_EQ(Q3AttributeSet_Get(data.triMeshAttributeSet, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
    TQ3TextureObject texture = nullptr;
    ASSERT_EQ(Q3TextureShader_GetTexture(shader, &texture), kQ3Success);
    TQ3Mipmap mipmap{};
    ASSERT_EQ(Q3MipmapTexture_GetMipmap(texture, &mipmap), kQ3Success);
    std::vector<unsigned char> pixels(m_pixels.size());
    unsigned long got = 0;
    Q3Storage_GetData(mipmap.image, 0, static_cast<unsigned long>(pixels.size()), pixels.data(), &got);
    EXPECT_EQ(pixels, m_pixels);
    EXPECT_TRUE(read.hasUVs);
    Q3Object_Dispose(mipmap.image);
    Q3Object_Dispose(texture);
    Q3Object_Dispose(shader);
    Q3TriMesh_EmptyData(&data);
    Q3Object_Dispose(back);

    // Without its material file the OBJ is an error, not grey.
    std::remove((stem + ".mtl").c_str());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Exchange_Read(path.c_str(), kQ3ExchangeFormatAny), nullptr), kQ3ErrorInvalidData);
}

TEST_F(ExchangeModelTest, StlKeepsTheTrianglesFlattened)
{
    const std::string path = temporaryPath("model.stl");
    m_written.push_back(path);
    ASSERT_EQ(Q3Exchange_Write(m_group, path.c_str(), nullptr), kQ3Success);
    TQ3GroupObject back = Q3Exchange_Read(path.c_str(), kQ3ExchangeFormatAny);
    ASSERT_NE(back, nullptr);
    const Triangles read = trianglesIn(back);
    EXPECT_EQ(read.triangles.size(), 4u);
    const TQ3BoundingBox a = bounds(m_group);
    const TQ3BoundingBox b = bounds(back);
    EXPECT_NEAR(b.min.y, a.min.y, 1e-5);
    EXPECT_NEAR(b.max.y, a.max.y, 1e-5);
    EXPECT_NEAR(b.max.z, a.max.z, 1e-5);
    Q3Object_Dispose(back);
}

TEST_F(ExchangeApiTest, EveryGeometryKeepsItsTriangleCountThroughStlAndObj)
{
    for (const char* name : {"curves_quadrics.3dmf", "polygons.3dmf", "nurbpatch.3dmf"}) {
        std::vector<TQ3Object> objects = readFile(std::string(Q3_TEST_DATA_DIR) + "/" + name);
        for (std::size_t k = 0; k < objects.size(); ++k) {
            if (Q3Object_IsType(objects[k], kQ3ShapeTypeGeometry) != kQ3True)
                continue;
            const Triangles original = decomposition(objects[k]);
            if (original.triangles.empty())
                continue;
            for (const char* ext : {".stl", ".obj"}) {
                const std::string path = temporaryPath(std::to_string(k) + "-" + name + ext);
                const std::string stem = path.substr(0, path.size() - 4);
                m_written.push_back(path);
                m_written.push_back(stem + ".mtl");
                TQ3ExchangeOptions options;
                Q3Exchange_InitOptions(&options);
                options.subdivisionFromSize = kQ3False;
                options.subdivisionMethod = kQ3SubdivisionMethodConstant;
                options.subdivisionValue = kSegments;
                ASSERT_EQ(Q3Exchange_Write(objects[k], path.c_str(), &options), kQ3Success) << path;
                TQ3GroupObject back = Q3Exchange_Read(path.c_str(), kQ3ExchangeFormatAny);
                ASSERT_NE(back, nullptr) << path;
                const Triangles read = trianglesIn(back);
                EXPECT_EQ(read.triangles.size(), original.triangles.size()) << name << " " << k << ext;
                Q3Object_Dispose(back);
            }
        }
        for (TQ3Object object : objects)
            Q3Object_Dispose(object);
    }
}

// A file's camera and lights reach glTF (a camera, KHR_lights_punctual) and
// come back placed where they were: the camera in the root group, the
// lights in a light group there.
TEST_F(ExchangeApiTest, CamerasAndLightsSurviveGlb)
{
    TQ3GroupObject file = Q3Group_New();
    TQ3ViewAngleAspectCameraData camera{};
    camera.cameraData.placement = {{10, 0, 4}, {10, 0, 0}, {0, 1, 0}};
    camera.cameraData.range = {1, 20};
    camera.cameraData.viewPort = {{-1, 1}, 2, 2};
    camera.fov = 0.5f;
    camera.aspectRatioXToY = 1.5f;
    TQ3CameraObject cameraObject = Q3ViewAngleAspectCamera_New(&camera);
    TQ3DirectionalLightData sun{{kQ3True, 0.75f, {1, 0.9f, 0.8f}}, kQ3True, {0, -1, -1}};
    TQ3PointLightData bulb{{kQ3True, 0.5f, {1, 1, 1}}, kQ3False, kQ3AttenuationTypeNone, {1, 2, 3}};
    TQ3LightObject sunObject = Q3DirectionalLight_New(&sun);
    TQ3LightObject bulbObject = Q3PointLight_New(&bulb);
    TQ3GroupObject lights = Q3LightGroup_New();
    Q3Group_AddObject(lights, sunObject);
    Q3Group_AddObject(lights, bulbObject);
    TQ3GroupObject scene = Q3DisplayGroup_New();
    TQ3TriangleData triangle{{{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{0, 1, 0}, nullptr}}, nullptr};
    TQ3GeometryObject geometry = Q3Triangle_New(&triangle);
    Q3Group_AddObject(scene, geometry);
    Q3Group_AddObject(file, cameraObject);
    Q3Group_AddObject(file, lights);
    Q3Group_AddObject(file, scene);
    for (TQ3Object o : {TQ3Object(cameraObject), TQ3Object(sunObject), TQ3Object(bulbObject), TQ3Object(lights),
                        TQ3Object(scene), TQ3Object(geometry)})
        Q3Object_Dispose(o);

    TQ3GroupObject back = roundTrip(file, "camera-lights.glb");
    ASSERT_NE(back, nullptr);
    TQ3GroupPosition position = nullptr;
    ASSERT_EQ(Q3Group_GetFirstPositionOfType(back, kQ3ShapeTypeCamera, &position), kQ3Success);
    ASSERT_NE(position, nullptr);
    TQ3Object readCamera = nullptr;
    Q3Group_GetPositionObject(back, position, &readCamera);
    TQ3CameraPlacement placement{};
    EXPECT_EQ(Q3Camera_GetPlacement(readCamera, &placement), kQ3Success);
    EXPECT_NEAR(placement.cameraLocation.x, 10, 1e-5);
    EXPECT_NEAR(placement.cameraLocation.z, 4, 1e-5);
    // The point of interest is along the same line of sight.
    EXPECT_NEAR(placement.pointOfInterest.x, 10, 1e-5);
    EXPECT_NEAR(placement.pointOfInterest.y, 0, 1e-5);
    EXPECT_LT(placement.pointOfInterest.z, 4);
    EXPECT_NEAR(placement.upVector.y, 1, 1e-5);
    float fov = 0;
    EXPECT_EQ(Q3ViewAngleAspectCamera_GetFOV(readCamera, &fov), kQ3Success);
    EXPECT_NEAR(fov, 0.5f, 1e-5);
    Q3Object_Dispose(readCamera);

    ASSERT_EQ(Q3Group_GetFirstPositionOfType(back, kQ3GroupTypeLight, &position), kQ3Success);
    ASSERT_NE(position, nullptr);
    TQ3Object readLights = nullptr;
    Q3Group_GetPositionObject(back, position, &readLights);
    unsigned long count = 0;
    Q3Group_CountObjects(readLights, &count);
    EXPECT_EQ(count, 2u);
    TQ3Object readSun = firstOfType(readLights, kQ3LightTypeDirectional);
    ASSERT_NE(readSun, nullptr);
    TQ3Vector3D direction{};
    Q3DirectionalLight_GetDirection(readSun, &direction);
    EXPECT_NEAR(direction.x, 0, 1e-5);
    EXPECT_NEAR(direction.y, -std::sqrt(0.5), 1e-5);
    EXPECT_NEAR(direction.z, -std::sqrt(0.5), 1e-5);
    TQ3Object readBulb = firstOfType(readLights, kQ3LightTypePoint);
    ASSERT_NE(readBulb, nullptr);
    TQ3Point3D location{};
    Q3PointLight_GetLocation(readBulb, &location);
    EXPECT_NEAR(location.x, 1, 1e-5);
    EXPECT_NEAR(location.y, 2, 1e-5);
    EXPECT_NEAR(location.z, 3, 1e-5);
    // Written again from where Q3Exchange_Read put them, they are kept.
    TQ3GroupObject again = roundTrip(back, "camera-lights-again.glb");
    ASSERT_NE(again, nullptr);
    unsigned long cameras = 0, lightGroups = 0;
    Q3Group_CountObjectsOfType(again, kQ3ShapeTypeCamera, &cameras);
    Q3Group_CountObjectsOfType(again, kQ3GroupTypeLight, &lightGroups);
    EXPECT_EQ(cameras, 1u);
    EXPECT_EQ(lightGroups, 1u);
    for (TQ3Object o : {readSun, readBulb, readLights, back, TQ3Object(file), TQ3Object(again)})
        Q3Object_Dispose(o);
}

TEST_F(ExchangeApiTest, AnEmptyGroupWritesAValidFileThatReadsBackEmpty)
{
    TQ3GroupObject group = Q3DisplayGroup_New();
    for (const char* name : {"empty.glb", "empty.gltf"}) {
        TQ3GroupObject back = roundTrip(group, name);
        ASSERT_NE(back, nullptr);
        std::vector<TQ3Object> meshes;
        collectTriMeshes(back, meshes);
        EXPECT_TRUE(meshes.empty());
        Q3Object_Dispose(back);
    }
    Q3Object_Dispose(group);
}

// Curves and points have no triangles: a NURB curve comes back as the
// PolyLine of its line strip, a point as a Point.
TEST_F(ExchangeApiTest, CurvesAndPointsComeBackAsPolyLinesAndPoints)
{
    TQ3PointData point{{1, 2, 3}, nullptr};
    TQ3Vertex3D vertices[3] = {{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{1, 1, 0}, nullptr}};
    TQ3PolyLineData polyLine{3, vertices, nullptr, nullptr};
    TQ3GroupObject group = displayGroupOf({Q3Point_New(&point), Q3PolyLine_New(&polyLine)});
    TQ3GroupObject back = roundTrip(group, "curves-points.glb");
    ASSERT_NE(back, nullptr);
    std::vector<TQ3Object> found;
    collectOfTypes(back, {kQ3GeometryTypePoint, kQ3GeometryTypePolyLine}, found);
    ASSERT_EQ(found.size(), 2u);
    int points = 0, polyLines = 0;
    for (TQ3Object object : found) {
        if (Q3Object_IsType(object, kQ3GeometryTypePoint) == kQ3True) {
            ++points;
            TQ3PointData data{};
            ASSERT_EQ(Q3Point_GetData(object, &data), kQ3Success);
            EXPECT_EQ(data.point.x, 1);
            EXPECT_EQ(data.point.y, 2);
            EXPECT_EQ(data.point.z, 3);
            Q3Point_EmptyData(&data);
        } else {
            ++polyLines;
            TQ3PolyLineData data{};
            ASSERT_EQ(Q3PolyLine_GetData(object, &data), kQ3Success);
            ASSERT_EQ(data.numVertices, 3u);
            EXPECT_EQ(data.vertices[2].point.y, 1);
            Q3PolyLine_EmptyData(&data);
        }
    }
    EXPECT_EQ(points, 1);
    EXPECT_EQ(polyLines, 1);
    Q3Object_Dispose(back);
    Q3Object_Dispose(group);
}

// What the formats have no place for (an info group's strings) is left out
// with a warning; the rest is written.
TEST_F(ExchangeApiTest, ObjectsWithNoCounterpartAreLeftOutWithAWarning)
{
    TQ3GroupObject file = Q3Group_New();
    TQ3GroupObject info = Q3InfoGroup_New();
    TQ3StringObject note = Q3CString_New("made by hand");
    Q3Group_AddObject(info, note);
    TQ3TriangleData triangle{{{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{0, 1, 0}, nullptr}}, nullptr};
    TQ3GeometryObject geometry = Q3Triangle_New(&triangle);
    Q3Group_AddObject(file, info);
    Q3Group_AddObject(file, geometry);
    const std::string path = temporaryPath("info.glb");
    m_written.push_back(path);
    EXPECT_Q3_WARNING(EXPECT_EQ(Q3Exchange_Write(file, path.c_str(), nullptr), kQ3Success),
                      kQ3WarningFunctionalityNotSupported);
    EXPECT_EQ(validatorErrors(path), "");
    TQ3GroupObject back = Q3Exchange_Read(path.c_str(), kQ3ExchangeFormatAny);
    ASSERT_NE(back, nullptr);
    std::vector<TQ3Object> meshes;
    collectTriMeshes(back, meshes);
    EXPECT_EQ(meshes.size(), 1u);
    for (TQ3Object o : {TQ3Object(note), TQ3Object(info), TQ3Object(geometry), TQ3Object(file), back})
        Q3Object_Dispose(o);
}

// A shear is no glTF node matrix (translation, rotation and scale only):
// the mesh is written in world space instead, and lands where it was.
TEST_F(ExchangeApiTest, AShearedGeometryIsWrittenInWorldSpace)
{
    TQ3Matrix4x4 shear;
    Q3Matrix4x4_SetIdentity(&shear);
    shear.value[1][0] = 0.5f; // x += 0.5 y
    shear.value[3][2] = 2.0f; // then z += 2
    TQ3TriangleData triangle{{{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{0, 1, 0}, nullptr}}, nullptr};
    TQ3GroupObject group = displayGroupOf({Q3MatrixTransform_New(&shear), Q3Triangle_New(&triangle)});
    TQ3GroupObject back = roundTrip(group, "shear.glb");
    ASSERT_NE(back, nullptr);
    std::vector<TQ3Object> meshes;
    collectTriMeshes(back, meshes);
    ASSERT_EQ(meshes.size(), 1u);
    Triangles read;
    read.add(meshes[0]);
    ASSERT_EQ(read.points.size(), 3u);
    // (0,1,0) sheared: (0.5, 1, 2).
    bool found = false;
    for (const TQ3Point3D& p : read.points)
        found = found || (std::fabs(p.x - 0.5f) < 1e-6 && std::fabs(p.y - 1) < 1e-6 && std::fabs(p.z - 2) < 1e-6);
    EXPECT_TRUE(found);
    Q3Object_Dispose(back);
    Q3Object_Dispose(group);
}

} // namespace
