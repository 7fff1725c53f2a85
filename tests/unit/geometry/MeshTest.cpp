// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// base/Primitives.h: a Mesh creates an attribute channel the first time
// a vertex has that attribute, with NaN ("none") for every vertex before;
// edgesFromTriangles gives each undirected triangle side exactly once;
// VertexAttributes inherit what they lack and keep what they have; a
// triangle takes the surface shader two of its corners share.

#include "core/AttributeSet.h"
#include "base/Primitives.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace q3 {
namespace {

VertexAttributes withColor(float r, float g, float b)
{
    VertexAttributes attributes;
    attributes.color = TQ3ColorRGB{r, g, b};
    return attributes;
}

TEST(Mesh, AChannelAppearsOnlyWhenAVertexHasThatAttribute)
{
    Mesh mesh;
    mesh.addVertex({0, 0, 0}, VertexAttributes{});
    mesh.addVertex({1, 0, 0}, VertexAttributes{});
    const MeshView view = mesh.view();
    EXPECT_EQ(view.vertexCount, 2u);
    EXPECT_EQ(view.colors, nullptr);
    EXPECT_EQ(view.transparency, nullptr);
    EXPECT_EQ(view.normals, nullptr);
    EXPECT_EQ(view.uvs, nullptr);
    EXPECT_EQ(view.positions[3], 1.0f);
}

TEST(Mesh, ALateChannelIsBackfilledWithNaNForEarlierVertices)
{
    Mesh mesh;
    EXPECT_EQ(mesh.addVertex({0, 0, 0}, VertexAttributes{}), 0u);
    EXPECT_EQ(mesh.addVertex({1, 0, 0}, VertexAttributes{}), 1u);
    VertexAttributes third = withColor(0.25f, 0.5f, 0.75f);
    third.uv = TQ3Param2D{0.125f, 0.875f};
    EXPECT_EQ(mesh.addVertex({2, 0, 0}, third), 2u);
    VertexAttributes fourth;
    fourth.normal = TQ3Vector3D{0, 0, 1};
    EXPECT_EQ(mesh.addVertex({3, 0, 0}, fourth), 3u);
    EXPECT_EQ(mesh.addVertex({4, 0, 0}, VertexAttributes{}), 4u);

    const MeshView view = mesh.view();
    ASSERT_EQ(view.vertexCount, 5u);
    // Colours: vertices 0, 1 NaN; 2 its colour; 3, 4 NaN (added after the channel existed).
    ASSERT_NE(view.colors, nullptr);
    for (std::size_t v : {0u, 1u, 3u, 4u})
        for (int k = 0; k < 3; ++k)
            EXPECT_TRUE(std::isnan(view.colors[3 * v + k])) << "vertex " << v;
    EXPECT_EQ(view.colors[6], 0.25f);
    EXPECT_EQ(view.colors[7], 0.5f);
    EXPECT_EQ(view.colors[8], 0.75f);
    // UVs: two values per vertex.
    ASSERT_NE(view.uvs, nullptr);
    for (std::size_t v : {0u, 1u, 3u, 4u})
        EXPECT_TRUE(std::isnan(view.uvs[2 * v]) && std::isnan(view.uvs[2 * v + 1])) << "vertex " << v;
    EXPECT_EQ(view.uvs[4], 0.125f);
    EXPECT_EQ(view.uvs[5], 0.875f);
    // Normals: only vertex 3.
    ASSERT_NE(view.normals, nullptr);
    for (std::size_t v : {0u, 1u, 2u, 4u})
        EXPECT_TRUE(std::isnan(view.normals[3 * v + 2])) << "vertex " << v;
    EXPECT_EQ(view.normals[11], 1.0f);
    EXPECT_EQ(view.transparency, nullptr);
    // Every channel holds exactly one entry per vertex: the last vertex's
    // entries are the last of each array (read at the far end).
    EXPECT_TRUE(std::isnan(view.colors[3 * 4 + 2]));
    EXPECT_TRUE(std::isnan(view.uvs[2 * 4 + 1]));
    EXPECT_TRUE(std::isnan(view.normals[3 * 4 + 2]));
}

TEST(Mesh, ViewCountsEveryPrimitive)
{
    Mesh mesh;
    for (int i = 0; i < 6; ++i)
        mesh.addVertex({float(i), 0, 0}, VertexAttributes{});
    mesh.addPoint(5);
    mesh.addLine(0, 1);
    mesh.addLine(1, 2);
    mesh.addStrip(2, 3);
    mesh.addTriangle(0, 2, 4);
    mesh.addEdge(0, 2);
    const MeshView view = mesh.view();
    EXPECT_EQ(view.pointCount, 1u);
    EXPECT_EQ(view.lineCount, 2u);
    EXPECT_EQ(view.stripCount, 1u);
    EXPECT_EQ(view.strips[0].first, 2u);
    EXPECT_EQ(view.strips[0].count, 3u);
    EXPECT_EQ(view.triangleCount, 1u);
    EXPECT_EQ(view.triangles[2], 4u);
    EXPECT_EQ(view.edgeCount, 1u);
    mesh.clear();
    EXPECT_EQ(mesh.view().vertexCount, 0u);
    EXPECT_EQ(mesh.view().triangleCount, 0u);
    EXPECT_EQ(mesh.view().colors, nullptr);
}

// The sides of the triangles as unordered pairs, and for each the direction
// in which its first triangle runs it: computed here, independently.
std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::uint32_t, std::uint32_t>>
expectedSides(const std::vector<std::uint32_t>& triangles)
{
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::uint32_t, std::uint32_t>> sides;
    for (std::size_t t = 0; t < triangles.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = triangles[t + k], b = triangles[t + (k + 1) % 3];
            sides.emplace(std::minmax(a, b), std::make_pair(a, b)); // keeps the first
        }
    return sides;
}

// The mesh's edges are its triangles' sides, each once, running the way
// its first triangle runs it, in order of (smaller, larger) vertex.
void expectEdgesOfTriangles(const Mesh& mesh, const std::vector<std::uint32_t>& triangles)
{
    const auto expected = expectedSides(triangles);
    const MeshView view = mesh.view();
    ASSERT_EQ(view.edgeCount, expected.size());
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    std::pair<std::uint32_t, std::uint32_t> previous{0, 0};
    for (std::size_t e = 0; e < view.edgeCount; ++e) {
        const std::uint32_t a = view.edges[2 * e], b = view.edges[2 * e + 1];
        const auto key = std::minmax(a, b);
        EXPECT_TRUE(seen.insert(key).second) << "side " << a << "-" << b << " twice";
        const auto found = expected.find(key);
        ASSERT_NE(found, expected.end()) << "side " << a << "-" << b << " is no triangle's";
        EXPECT_EQ(found->second, std::make_pair(a, b)) << "side " << a << "-" << b << " runs the wrong way";
        if (e > 0)
            EXPECT_LT(previous, std::make_pair(key.first, key.second)) << "side " << a << "-" << b << " out of order";
        previous = key;
    }
}

TEST(Mesh, EdgesFromTrianglesGivesEachUndirectedSideOnceInItsFirstTrianglesDirection)
{
    // A 4 x 3 grid of quads, each split into two triangles with alternating
    // diagonals, with the triangles listed in a scrambled order and some
    // wound the other way: 12 quads, 24 triangles.
    Mesh mesh;
    const int columns = 5, rows = 4;
    for (int y = 0; y < rows; ++y)
        for (int x = 0; x < columns; ++x)
            mesh.addVertex({float(x), float(y), 0}, VertexAttributes{});
    std::vector<std::uint32_t> triangles;
    auto id = [&](int x, int y) { return std::uint32_t(y * columns + x); };
    for (int y = 0; y + 1 < rows; ++y)
        for (int x = 0; x + 1 < columns; ++x) {
            const std::uint32_t a = id(x, y), b = id(x + 1, y), c = id(x + 1, y + 1), d = id(x, y + 1);
            if ((x + y) % 2 == 0)
                triangles.insert(triangles.end(), {a, b, c, a, c, d});
            else
                triangles.insert(triangles.end(), {d, b, a, d, c, b}); // clockwise, other diagonal
        }
    // Scramble the triangle order deterministically.
    std::vector<std::uint32_t> scrambled;
    const std::size_t count = triangles.size() / 3;
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t t = (i * 7) % count; // 7 is coprime with 24
        scrambled.insert(scrambled.end(), triangles.begin() + 3 * t, triangles.begin() + 3 * t + 3);
    }
    for (std::size_t t = 0; t < scrambled.size(); t += 3)
        mesh.addTriangle(scrambled[t], scrambled[t + 1], scrambled[t + 2]);
    mesh.addEdge(0, 19); // replaced by edgesFromTriangles
    mesh.edgesFromTriangles();

    // Sides of a 4 x 3 grid of quads: horizontal 4 * 4, vertical 5 * 3, diagonals 12.
    ASSERT_EQ(expectedSides(scrambled).size(), 16u + 15u + 12u);
    expectEdgesOfTriangles(mesh, scrambled);
}

TEST(Mesh, EdgesFromTrianglesOfAFanWithManySidesAtItsHub)
{
    // 40 triangles around vertex 0 (80 sides filed under it, many of them
    // the same side), listed out of order, some wound the other way and
    // some twice, and one degenerate triangle.
    Mesh mesh;
    const std::uint32_t rim = 40;
    mesh.addVertex({0, 0, 0}, VertexAttributes{});
    for (std::uint32_t i = 0; i < rim; ++i)
        mesh.addVertex({std::cos(0.1f * float(i)), std::sin(0.1f * float(i)), 0}, VertexAttributes{});
    std::vector<std::uint32_t> triangles;
    for (std::uint32_t k = 0; k < rim; ++k) {
        const std::uint32_t i = 1 + (k * 17) % rim, j = 1 + (i % rim);
        if (k % 3 == 0)
            triangles.insert(triangles.end(), {j, 0, i});
        else
            triangles.insert(triangles.end(), {0, i, j});
        if (k % 5 == 0)
            triangles.insert(triangles.end(), {i, 0, j});
    }
    triangles.insert(triangles.end(), {5, 5, 0});
    for (std::size_t t = 0; t < triangles.size(); t += 3)
        mesh.addTriangle(triangles[t], triangles[t + 1], triangles[t + 2]);
    mesh.edgesFromTriangles();
    ASSERT_EQ(expectedSides(triangles).size(), 2u * rim + 1u); // spokes, rim, and 5-5
    expectEdgesOfTriangles(mesh, triangles);
}

TEST(Mesh, EdgesFromTrianglesOfNoTrianglesIsNoEdges)
{
    Mesh mesh;
    mesh.addVertex({0, 0, 0}, VertexAttributes{});
    mesh.addVertex({1, 0, 0}, VertexAttributes{});
    mesh.addEdge(0, 1);
    mesh.edgesFromTriangles();
    EXPECT_EQ(mesh.view().edgeCount, 0u);
}

TEST(VertexAttributes, InheritanceFillsOnlyWhatIsMissing)
{
    AttributeSet set;
    const TQ3ColorRGB blue{0, 0, 1};
    const TQ3Vector3D up{0, 1, 0};
    set.add(kQ3AttributeTypeDiffuseColor, &blue);
    set.add(kQ3AttributeTypeNormal, &up);

    VertexAttributes own = withColor(1, 0, 0);
    own.inheritFrom(&set);
    EXPECT_EQ(own.color.r, 1.0f); // its own colour wins
    EXPECT_EQ(own.color.b, 0.0f);
    EXPECT_TRUE(own.hasNormal()); // the normal it lacked comes from the set
    EXPECT_EQ(own.normal.y, 1.0f);
    EXPECT_FALSE(own.hasUV());
    EXPECT_FALSE(own.hasTransparency());
    own.inheritFrom(nullptr); // nothing to inherit from

    VertexAttributes bare;
    const TQ3ColorRGB green{0, 1, 0};
    bare.inherit(kQ3AttributeTypeDiffuseColor, &green);
    bare.inherit(kQ3AttributeTypeDiffuseColor, &blue); // already has one
    EXPECT_EQ(bare.color.g, 1.0f);
    EXPECT_EQ(bare.color.b, 0.0f);
    const float ambient = 0.5f;
    bare.inherit(kQ3AttributeTypeAmbientCoefficient, &ambient); // not one the renderers use
    const TQ3Param2D uv{0.25f, 0.75f};
    bare.inherit(kQ3AttributeTypeSurfaceUV, &uv);
    EXPECT_EQ(bare.uv.v, 0.75f);
    EXPECT_FALSE(bare.hasNormal());
}

// Stand-ins for surface shaders: the mesh keeps references to whatever
// shared objects its vertices name, without looking at their class.
TEST(Mesh, ATriangleTakesTheShaderTwoOfItsCornersShare)
{
    const Ref<AttributeSet> a = makeShared<AttributeSet>(), b = makeShared<AttributeSet>();
    Mesh mesh;
    const auto vertex = [&](const SharedObject* shader) {
        VertexAttributes attributes;
        attributes.shader = shader;
        return mesh.addVertex({0, 0, 0}, attributes);
    };
    const std::uint32_t plain = vertex(nullptr), plain2 = vertex(nullptr);
    const std::uint32_t a1 = vertex(a.get()), a2 = vertex(a.get()), a3 = vertex(a.get());
    const std::uint32_t b1 = vertex(b.get()), b2 = vertex(b.get());
    mesh.addTriangle(plain, plain2, plain); // none: before the first with one
    mesh.addTriangle(a1, a2, a3);           // a
    mesh.addTriangle(a1, b1, b2);           // b outvotes a
    mesh.addTriangle(a1, plain, plain2);    // none outvotes a
    mesh.addTriangle(a1, b1, plain);        // all differ: none
    mesh.addTriangle(plain, a2, a3);        // a
    mesh.addTriangle(plain, plain, plain2, b.get()); // given: b
    const MeshView view = mesh.view();
    ASSERT_NE(view.triangleShaders, nullptr);
    ASSERT_EQ(view.shaderCount, 2u);
    EXPECT_EQ(view.shaders[0].get(), a.get());
    EXPECT_EQ(view.shaders[1].get(), b.get());
    const std::uint32_t expected[7] = {0, 1, 2, 0, 0, 1, 2};
    for (std::size_t t = 0; t < 7; ++t)
        EXPECT_EQ(view.triangleShaders[t], expected[t]) << "triangle " << t;
}

TEST(Mesh, NoShaderArrayWithoutShadersAndTheMeshHoldsItsShaders)
{
    Mesh mesh;
    mesh.addVertex({0, 0, 0}, VertexAttributes{});
    mesh.addTriangle(0, 0, 0);
    EXPECT_EQ(mesh.view().triangleShaders, nullptr);
    EXPECT_EQ(mesh.view().shaderCount, 0u);

    Ref<AttributeSet> shader = makeShared<AttributeSet>();
    VertexAttributes attributes;
    attributes.inheritFrom(shader.get()); // a set without a shader: none
    EXPECT_FALSE(attributes.hasShader());
    attributes.shader = shader.get();
    mesh.addVertex({1, 0, 0}, attributes);
    mesh.addTriangle(1, 1, 0);
    EXPECT_EQ(shader->referenceCount(), 2u);
    mesh.clear();
    EXPECT_EQ(shader->referenceCount(), 1u);
}

TEST(Mesh, InheritTakesAShaderHandleOnlyWhereTheVertexHasNone)
{
    const Ref<AttributeSet> a = makeShared<AttributeSet>(), b = makeShared<AttributeSet>();
    VertexAttributes attributes;
    TQ3Object none = nullptr;
    attributes.inherit(kQ3AttributeTypeSurfaceShader, &none);
    EXPECT_FALSE(attributes.hasShader());
    TQ3Object handle = a.get();
    attributes.inherit(kQ3AttributeTypeSurfaceShader, &handle);
    EXPECT_EQ(attributes.shader, a.get());
    handle = b.get();
    attributes.inherit(kQ3AttributeTypeSurfaceShader, &handle);
    EXPECT_EQ(attributes.shader, a.get());
}

// A serial names a mesh's contents as built (MeshView::serial): new
// numbers differ and are never 0; a copy, which may then be changed, and a
// cleared mesh have none.
TEST(Mesh, ASerialStaysWithTheMeshAsBuiltOnly)
{
    const std::uint64_t first = Mesh::newSerial(), second = Mesh::newSerial();
    EXPECT_NE(first, 0u);
    EXPECT_NE(second, 0u);
    EXPECT_NE(first, second);
    Mesh mesh;
    mesh.addVertex({0, 0, 0}, VertexAttributes{});
    EXPECT_EQ(mesh.view().serial, 0u);
    mesh.setSerial(first);
    EXPECT_EQ(mesh.view().serial, first);
    Mesh copy = mesh;
    EXPECT_EQ(copy.view().serial, 0u);
    EXPECT_EQ(copy.view().vertexCount, 1u);
    Mesh assigned;
    assigned.setSerial(second);
    assigned = mesh;
    EXPECT_EQ(assigned.view().serial, 0u);
    EXPECT_EQ(mesh.view().serial, first);
    mesh.clear();
    EXPECT_EQ(mesh.view().serial, 0u);
}

TEST(Mesh, ASerialNotesWhetherEveryVertexHasAUvAndACopyForgetsIt)
{
    // MeshView::uvsComplete: found when the serial is given; without a
    // serial, in a copy, or with a vertex lacking a uv (NaN), not promised.
    const auto withUV = [](float u, float v) {
        VertexAttributes attributes;
        attributes.uv = TQ3Param2D{u, v};
        return attributes;
    };
    Mesh complete;
    complete.addVertex({0, 0, 0}, withUV(0, 0));
    complete.addVertex({1, 0, 0}, withUV(1, 0));
    EXPECT_FALSE(complete.view().uvsComplete) << "no serial yet";
    complete.setSerial(Mesh::newSerial());
    EXPECT_TRUE(complete.view().uvsComplete);
    const Mesh copy = complete;
    EXPECT_FALSE(copy.view().uvsComplete) << "a copy has no serial";

    Mesh lacking;
    lacking.addVertex({0, 0, 0}, withUV(0, 0));
    lacking.addVertex({1, 0, 0}, VertexAttributes{});
    lacking.setSerial(Mesh::newSerial());
    EXPECT_FALSE(lacking.view().uvsComplete) << "the second vertex has no uv";

    Mesh none;
    none.addVertex({0, 0, 0}, VertexAttributes{});
    none.setSerial(Mesh::newSerial());
    EXPECT_FALSE(none.view().uvsComplete) << "no uvs at all";
}

} // namespace
} // namespace q3
