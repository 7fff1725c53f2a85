// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The five Q3TriMesh_* calls against QD3DGeometry.h: the seven TQ3TriMeshData
// rules in their order (the first that fails decides the code), the
// attribute arrays with and without use arrays, deep copies of every array,
// bBox, references, duplicates, immediate mode and bounds.

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"
#include "SetTestSupport.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

using namespace q3test;

constexpr unsigned long kTooMany = (unsigned long)kQ3GeometryMaxArrayCount + 1;

// Bytes of one value of each standard attribute type, from QD3DSet.h's table
// (SetTestSupport.h writes it out independently of Q3).
std::size_t valueBytes(TQ3AttributeType type)
{
    const std::size_t n = attributeSize(type);
    if (n == 0)
        ADD_FAILURE() << "not a standard type: " << type;
    return n;
}

// A square of two triangles over four points, its five edges, and every
// kind of attribute array: triangle colours, edge colours, point normals and
// point uvs (the last with a use array).
class TriMeshApiTest : public OwningApiTest {
protected:
    std::vector<TQ3Point3D> m_points{{0, 0, 0}, {2, 0, 1}, {2, 3, -1}, {0, 3, 0.5f}};
    std::vector<TQ3TriMeshTriangleData> m_triangles{{{0, 1, 2}}, {{0, 2, 3}}};
    std::vector<TQ3TriMeshEdgeData> m_edges{
        {{0, 1}, {0, (unsigned long)kQ3ArrayIndexNULL}}, {{1, 2}, {0, (unsigned long)kQ3ArrayIndexNULL}},
        {{2, 0}, {0, 1}}, {{2, 3}, {1, (unsigned long)kQ3ArrayIndexNULL}}, {{3, 0}, {1, (unsigned long)kQ3ArrayIndexNULL}}};
    std::vector<TQ3ColorRGB> m_triangleColors{{1, 0, 0}, {0, 1, 0}};
    std::vector<TQ3ColorRGB> m_edgeColors{{1, 1, 0}, {0, 1, 1}, {1, 0, 1}, {0.5f, 0.5f, 0.5f}, {1, 1, 1}};
    std::vector<TQ3Vector3D> m_normals{{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0, 0, -1}};
    std::vector<TQ3Param2D> m_uvs{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::vector<char> m_uvUse{1, 0, 1, 1};
    TQ3TriMeshAttributeData m_triangleAttributes[1] = {
        {kQ3AttributeTypeDiffuseColor, m_triangleColors.data(), nullptr}};
    TQ3TriMeshAttributeData m_edgeAttributes[1] = {{kQ3AttributeTypeDiffuseColor, m_edgeColors.data(), nullptr}};
    TQ3TriMeshAttributeData m_vertexAttributes[2] = {{kQ3AttributeTypeNormal, m_normals.data(), nullptr},
                                                     {kQ3AttributeTypeSurfaceUV, m_uvs.data(), m_uvUse.data()}};

    /// The full mesh, with a bBox that is wrong on purpose (Q3 ignores it).
    TQ3TriMeshData fullData()
    {
        // No set; triangles and edges with one attribute array each; points
        // with two.
        return TQ3TriMeshData{nullptr,
                              static_cast<unsigned long>(m_triangles.size()),
                              m_triangles.data(),
                              1,
                              m_triangleAttributes,
                              static_cast<unsigned long>(m_edges.size()),
                              m_edges.data(),
                              1,
                              m_edgeAttributes,
                              static_cast<unsigned long>(m_points.size()),
                              m_points.data(),
                              2,
                              m_vertexAttributes,
                              TQ3BoundingBox{{-100, -100, -100}, {-99, -99, -99}, kQ3True}};
    }

    /// Only the points and the triangles.
    TQ3TriMeshData plainData()
    {
        TQ3TriMeshData data{};
        data.numTriangles = m_triangles.size();
        data.triangles = m_triangles.data();
        data.numPoints = m_points.size();
        data.points = m_points.data();
        return data;
    }

    std::vector<TQ3Object> notTriMeshes()
    {
        const TQ3TriangleData triangle{{{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{0, 1, 0}, nullptr}}, nullptr};
        return {own(Q3AttributeSet_New()), view(), own(Q3Triangle_New(&triangle))};
    }

    TQ3GeometryObject newFull()
    {
        const TQ3TriMeshData data = fullData();
        return Q3TriMesh_New(&data);
    }

    /// Runs New on data and expects it to fail with code, creating nothing.
    void expectNewFails(const TQ3TriMeshData& data, TQ3Error code, const std::string& what)
    {
        SCOPED_TRACE(what);
        const unsigned long live = Q3Memory_CountLiveObjects();
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_New(&data), nullptr), code);
        EXPECT_EQ(Q3Memory_CountLiveObjects(), live);
    }
};

// Compares two TriMesh data structures value by value (not bBox, not where
// the arrays are).
void expectSameMesh(const TQ3TriMeshData& a, const TQ3TriMeshData& b)
{
    EXPECT_EQ(a.triMeshAttributeSet, b.triMeshAttributeSet);
    ASSERT_EQ(a.numTriangles, b.numTriangles);
    ASSERT_EQ(a.numEdges, b.numEdges);
    ASSERT_EQ(a.numPoints, b.numPoints);
    ASSERT_EQ(a.numTriangleAttributeTypes, b.numTriangleAttributeTypes);
    ASSERT_EQ(a.numEdgeAttributeTypes, b.numEdgeAttributeTypes);
    ASSERT_EQ(a.numVertexAttributeTypes, b.numVertexAttributeTypes);
    for (unsigned long t = 0; t < a.numTriangles; ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(a.triangles[t].pointIndices[k], b.triangles[t].pointIndices[k]) << "triangle " << t;
    for (unsigned long e = 0; e < a.numEdges; ++e)
        for (int k = 0; k < 2; ++k) {
            EXPECT_EQ(a.edges[e].pointIndices[k], b.edges[e].pointIndices[k]) << "edge " << e;
            EXPECT_EQ(a.edges[e].triangleIndices[k], b.edges[e].triangleIndices[k]) << "edge " << e;
        }
    for (unsigned long p = 0; p < a.numPoints; ++p)
        EXPECT_TRUE(samePoint(a.points[p], b.points[p])) << "point " << p;
    auto sameAttributes = [](const TQ3TriMeshAttributeData* x, const TQ3TriMeshAttributeData* y, unsigned long types,
                             unsigned long count, const char* name) {
        for (unsigned long i = 0; i < types; ++i) {
            SCOPED_TRACE(std::string(name) + "[" + std::to_string(i) + "]");
            ASSERT_EQ(x[i].attributeType, y[i].attributeType);
            const std::size_t bytes = count * valueBytes(x[i].attributeType);
            if (bytes != 0)
                EXPECT_EQ(std::memcmp(x[i].data, y[i].data, bytes), 0);
            ASSERT_EQ(x[i].attributeUseArray == nullptr, y[i].attributeUseArray == nullptr);
            if (x[i].attributeUseArray != nullptr && count != 0)
                EXPECT_EQ(std::memcmp(x[i].attributeUseArray, y[i].attributeUseArray, count), 0);
        }
    };
    sameAttributes(a.triangleAttributeTypes, b.triangleAttributeTypes, a.numTriangleAttributeTypes, a.numTriangles,
                   "triangleAttributeTypes");
    sameAttributes(a.edgeAttributeTypes, b.edgeAttributeTypes, a.numEdgeAttributeTypes, a.numEdges,
                   "edgeAttributeTypes");
    sameAttributes(a.vertexAttributeTypes, b.vertexAttributeTypes, a.numVertexAttributeTypes, a.numPoints,
                   "vertexAttributeTypes");
}

// Every array of out that GetData allocated, to check none is the caller's or
// another GetData's.
std::vector<const void*> arraysOf(const TQ3TriMeshData& d)
{
    std::vector<const void*> arrays{d.triangles, d.edges, d.points, d.triangleAttributeTypes, d.edgeAttributeTypes,
                                    d.vertexAttributeTypes};
    for (const auto& [entries, types] :
         {std::pair{d.triangleAttributeTypes, d.numTriangleAttributeTypes},
          std::pair{d.edgeAttributeTypes, d.numEdgeAttributeTypes},
          std::pair{d.vertexAttributeTypes, d.numVertexAttributeTypes}})
        for (unsigned long i = 0; i < types; ++i) {
            arrays.push_back(entries[i].data);
            if (entries[i].attributeUseArray != nullptr)
                arrays.push_back(entries[i].attributeUseArray);
        }
    return arrays;
}

// ---- New, GetData, EmptyData ----------------------------------------------------

TEST_F(TriMeshApiTest, NewMakesATriMeshThatGetDataReturnsWithTheBoxOfItsPoints)
{
    const TQ3TriMeshData data = fullData();
    TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
    ASSERT_NE(triMesh, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(triMesh), kQ3GeometryTypeTriMesh);
    EXPECT_EQ(Q3Geometry_GetType(triMesh), kQ3GeometryTypeTriMesh);
    EXPECT_EQ(Q3Shape_GetType(triMesh), kQ3ShapeTypeGeometry);
    EXPECT_EQ(Q3Object_IsDrawable(triMesh), kQ3True);
    TQ3TriMeshData out{};
    ASSERT_EQ(Q3TriMesh_GetData(triMesh, &out), kQ3Success);
    expectSameMesh(data, out);
    const std::vector<const void*> theirs = arraysOf(out), mine = arraysOf(data);
    for (std::size_t i = 0; i < theirs.size(); ++i)
        EXPECT_NE(theirs[i], mine[i]) << "array " << i;
    // The box of the four points, computed here.
    EXPECT_EQ(out.bBox.isEmpty, kQ3False);
    EXPECT_EQ(out.bBox.min.x, 0.0f);
    EXPECT_EQ(out.bBox.min.y, 0.0f);
    EXPECT_EQ(out.bBox.min.z, -1.0f);
    EXPECT_EQ(out.bBox.max.x, 2.0f);
    EXPECT_EQ(out.bBox.max.y, 3.0f);
    EXPECT_EQ(out.bBox.max.z, 1.0f);
    EXPECT_EQ(Q3TriMesh_EmptyData(&out), kQ3Success);
}

TEST_F(TriMeshApiTest, NewAndGetDataCopyEveryArray)
{
    const TQ3TriMeshData data = fullData();
    TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
    ASSERT_NE(triMesh, nullptr);
    TQ3TriMeshData first{};
    ASSERT_EQ(Q3TriMesh_GetData(triMesh, &first), kQ3Success);
    // The caller's arrays change after New.
    m_points[1].x = 50;
    m_triangles[1].pointIndices[2] = 1;
    m_edges[0].pointIndices[0] = 3;
    m_triangleColors[0].g = 0.5f;
    m_edgeColors[4].b = 0.5f;
    m_normals[3].x = 0.5f;
    m_uvs[2].v = 0.5f;
    m_uvUse[1] = 1;
    TQ3TriMeshData second{};
    ASSERT_EQ(Q3TriMesh_GetData(triMesh, &second), kQ3Success);
    expectSameMesh(first, second);
    EXPECT_EQ(second.points[1].x, 2.0f);
    EXPECT_EQ(second.vertexAttributeTypes[1].attributeUseArray[1], 0);
    // Two GetData calls share no array.
    const std::vector<const void*> a = arraysOf(first), b = arraysOf(second);
    for (const void* array : a)
        EXPECT_EQ(std::count(b.begin(), b.end(), array), 0);
    static_cast<TQ3ColorRGB*>(first.triangleAttributeTypes[0].data)[1].r = 0.25f;
    first.points[0].z = 7;
    EXPECT_EQ(static_cast<TQ3ColorRGB*>(second.triangleAttributeTypes[0].data)[1].r, 0.0f);
    EXPECT_EQ(second.points[0].z, 0.0f);
    Q3TriMesh_EmptyData(&first);
    Q3TriMesh_EmptyData(&second);
}

TEST_F(TriMeshApiTest, UseArraysAreCopiedWhereGivenAndAbsentWhereNot)
{
    std::vector<char> triangleUse{0, 1};
    std::vector<char> edgeUse{1, 1, 0, 0, 1};
    for (bool withUse : {false, true}) {
        TQ3TriMeshData data = fullData();
        m_triangleAttributes[0].attributeUseArray = withUse ? triangleUse.data() : nullptr;
        m_edgeAttributes[0].attributeUseArray = withUse ? edgeUse.data() : nullptr;
        m_vertexAttributes[1].attributeUseArray = withUse ? m_uvUse.data() : nullptr;
        TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
        ASSERT_NE(triMesh, nullptr);
        TQ3TriMeshData out{};
        ASSERT_EQ(Q3TriMesh_GetData(triMesh, &out), kQ3Success);
        expectSameMesh(data, out);
        EXPECT_EQ(out.vertexAttributeTypes[0].attributeUseArray, nullptr); // never had one
        EXPECT_EQ(out.triangleAttributeTypes[0].attributeUseArray != nullptr, withUse);
        EXPECT_EQ(out.edgeAttributeTypes[0].attributeUseArray != nullptr, withUse);
        EXPECT_EQ(out.vertexAttributeTypes[1].attributeUseArray != nullptr, withUse);
        Q3TriMesh_EmptyData(&out);
    }
}

TEST_F(TriMeshApiTest, EveryStandardAttributeTypeIsAccepted)
{
    // Four points' worth of the largest value (a tangent, 24 bytes) each.
    std::vector<float> values(4 * 6, 0.5f);
    std::vector<TQ3Switch> switches{kQ3On, kQ3Off, kQ3On, kQ3Off};
    std::vector<TQ3TriMeshAttributeData> entries;
    for (TQ3AttributeType type = kQ3AttributeTypeSurfaceUV; type <= kQ3AttributeTypeHighlightState; ++type)
        entries.push_back({type, type == kQ3AttributeTypeHighlightState ? static_cast<void*>(switches.data())
                                                                        : static_cast<void*>(values.data()),
                           nullptr});
    TQ3TriMeshData data = plainData();
    data.numVertexAttributeTypes = entries.size();
    data.vertexAttributeTypes = entries.data();
    TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
    ASSERT_NE(triMesh, nullptr);
    TQ3TriMeshData out{};
    ASSERT_EQ(Q3TriMesh_GetData(triMesh, &out), kQ3Success);
    expectSameMesh(data, out);
    Q3TriMesh_EmptyData(&out);
}

TEST_F(TriMeshApiTest, EmptyDataFreesEveryArrayKeepsTheCountsAndIsHarmlessTwice)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    TQ3TriMeshData data = fullData();
    data.triMeshAttributeSet = set;
    TQ3GeometryObject triMesh = Q3TriMesh_New(&data);
    ASSERT_NE(triMesh, nullptr);
    EXPECT_EQ(referenceCount(set), 2u);
    TQ3TriMeshData out{};
    ASSERT_EQ(Q3TriMesh_GetData(triMesh, &out), kQ3Success);
    EXPECT_EQ(out.triMeshAttributeSet, set);
    EXPECT_EQ(referenceCount(set), 3u);
    Q3Object_Dispose(triMesh);
    EXPECT_EQ(referenceCount(set), 2u); // GetData's reference outlives the trimesh
    ASSERT_EQ(Q3TriMesh_EmptyData(&out), kQ3Success);
    EXPECT_EQ(referenceCount(set), 1u);
    EXPECT_EQ(out.triMeshAttributeSet, nullptr);
    EXPECT_EQ(out.triangles, nullptr);
    EXPECT_EQ(out.triangleAttributeTypes, nullptr);
    EXPECT_EQ(out.edges, nullptr);
    EXPECT_EQ(out.edgeAttributeTypes, nullptr);
    EXPECT_EQ(out.points, nullptr);
    EXPECT_EQ(out.vertexAttributeTypes, nullptr);
    EXPECT_EQ(out.numTriangles, 2u);
    EXPECT_EQ(out.numEdges, 5u);
    EXPECT_EQ(out.numPoints, 4u);
    EXPECT_EQ(out.numVertexAttributeTypes, 2u);
    EXPECT_EQ(Q3TriMesh_EmptyData(&out), kQ3Success);
    EXPECT_EQ(referenceCount(set), 1u);
}

TEST_F(TriMeshApiTest, EmptyDataWithABadSetReleasesNothing)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    TQ3TriMeshData data = fullData();
    data.triMeshAttributeSet = set;
    TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
    TQ3TriMeshData out{};
    ASSERT_EQ(Q3TriMesh_GetData(triMesh, &out), kQ3Success);
    TQ3Point3D* const points = out.points;
    for (TQ3Object bad : {view(), strayHandle()}) {
        out.triMeshAttributeSet = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_EmptyData(&out), kQ3Failure),
                        bad == view() ? kQ3ErrorInvalidObjectType : kQ3ErrorInvalidObject);
        EXPECT_EQ(out.points, points); // not freed
    }
    out.triMeshAttributeSet = set;
    EXPECT_EQ(referenceCount(set), 3u);
    EXPECT_EQ(Q3TriMesh_EmptyData(&out), kQ3Success);
    EXPECT_EQ(referenceCount(set), 2u);
}

TEST_F(TriMeshApiTest, EmptyMeshesAreAccepted)
{
    // No triangles, no points, nothing: every array NULL with a zero count.
    TQ3TriMeshData nothing{};
    TQ3GeometryObject empty = own(Q3TriMesh_New(&nothing));
    ASSERT_NE(empty, nullptr);
    TQ3TriMeshData out{};
    out.bBox.isEmpty = kQ3False;
    ASSERT_EQ(Q3TriMesh_GetData(empty, &out), kQ3Success);
    EXPECT_EQ(out.numPoints, 0u);
    EXPECT_EQ(out.points, nullptr);
    EXPECT_EQ(out.bBox.isEmpty, kQ3True);
    Q3TriMesh_EmptyData(&out);
    EXPECT_EQ(boundsOf([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(empty, v), kQ3Success); }).isEmpty,
              kQ3True);

    // Points without triangles; an attribute entry whose data is NULL because
    // there are no triangles to hold values for.
    TQ3TriMeshData pointsOnly{};
    pointsOnly.numPoints = m_points.size();
    pointsOnly.points = m_points.data();
    TQ3TriMeshAttributeData noValues[1] = {{kQ3AttributeTypeDiffuseColor, nullptr, nullptr}};
    pointsOnly.numTriangleAttributeTypes = 1;
    pointsOnly.triangleAttributeTypes = noValues;
    pointsOnly.numEdgeAttributeTypes = 1;
    pointsOnly.edgeAttributeTypes = noValues;
    TQ3GeometryObject cloud = own(Q3TriMesh_New(&pointsOnly));
    ASSERT_NE(cloud, nullptr);
    ASSERT_EQ(Q3TriMesh_GetData(cloud, &out), kQ3Success);
    expectSameMesh(pointsOnly, out);
    EXPECT_EQ(out.bBox.isEmpty, kQ3False);
    EXPECT_EQ(out.bBox.max.y, 3.0f);
    Q3TriMesh_EmptyData(&out);
}

// ---- The TQ3TriMeshData rules, in their order ---------------------------------------

// The six arrays and the counts that size them.
struct ArrayField {
    const char* name;
    unsigned long TQ3TriMeshData::*count;
    std::function<void(TQ3TriMeshData&)> clear; // sets the pointer to NULL
};

std::vector<ArrayField> arrayFields()
{
    return {
        {"triangles", &TQ3TriMeshData::numTriangles, [](TQ3TriMeshData& d) { d.triangles = nullptr; }},
        {"triangleAttributeTypes", &TQ3TriMeshData::numTriangleAttributeTypes,
         [](TQ3TriMeshData& d) { d.triangleAttributeTypes = nullptr; }},
        {"edges", &TQ3TriMeshData::numEdges, [](TQ3TriMeshData& d) { d.edges = nullptr; }},
        {"edgeAttributeTypes", &TQ3TriMeshData::numEdgeAttributeTypes,
         [](TQ3TriMeshData& d) { d.edgeAttributeTypes = nullptr; }},
        {"points", &TQ3TriMeshData::numPoints, [](TQ3TriMeshData& d) { d.points = nullptr; }},
        {"vertexAttributeTypes", &TQ3TriMeshData::numVertexAttributeTypes,
         [](TQ3TriMeshData& d) { d.vertexAttributeTypes = nullptr; }},
    };
}

TEST_F(TriMeshApiTest, Rule1RejectsANullArrayWhoseCountIsNotZero)
{
    for (const ArrayField& field : arrayFields()) {
        TQ3TriMeshData data = fullData();
        field.clear(data);
        expectNewFails(data, kQ3ErrorNULLParameter, field.name);
    }
    for (int which = 0; which < 4; ++which) {
        TQ3TriMeshData data = fullData();
        TQ3TriMeshAttributeData* entry = which == 0   ? &m_triangleAttributes[0]
                                         : which == 1 ? &m_edgeAttributes[0]
                                                      : &m_vertexAttributes[which - 2];
        void* const saved = entry->data;
        entry->data = nullptr;
        expectNewFails(data, kQ3ErrorNULLParameter, "attribute data " + std::to_string(which));
        entry->data = saved;
    }
}

TEST_F(TriMeshApiTest, Rule2RejectsACountAboveTheMaximumWithoutReadingTheArray)
{
    // The arrays hold a few entries; a count above the limit must be refused
    // before anything past them is read (ASan would see it).
    for (const ArrayField& field : arrayFields())
        for (unsigned long count : {kTooMany, ~0UL}) {
            TQ3TriMeshData data = fullData();
            data.*field.count = count;
            expectNewFails(data, kQ3ErrorParameterOutOfRange, field.name);
        }
}

TEST_F(TriMeshApiTest, Rule1ComesBeforeRule2)
{
    // A NULL array with a huge count is a NULL error (nothing is allocated).
    for (const ArrayField& field : arrayFields()) {
        TQ3TriMeshData data = fullData();
        field.clear(data);
        data.*field.count = kTooMany;
        expectNewFails(data, kQ3ErrorNULLParameter, std::string("NULL and huge ") + field.name);
    }
    // A huge count in one array and a NULL array after it, or before it.
    const std::vector<ArrayField> fields = arrayFields();
    for (std::size_t huge = 0; huge < fields.size(); ++huge)
        for (std::size_t null = 0; null < fields.size(); ++null) {
            if (huge == null)
                continue;
            TQ3TriMeshData data = fullData();
            data.*fields[huge].count = kTooMany;
            fields[null].clear(data);
            expectNewFails(data, kQ3ErrorNULLParameter,
                           std::string("huge ") + fields[huge].name + ", NULL " + fields[null].name);
        }
    // And an attribute data block that is NULL.
    TQ3TriMeshData data = fullData();
    data.numEdges = kTooMany;
    m_vertexAttributes[0].data = nullptr;
    expectNewFails(data, kQ3ErrorNULLParameter, "huge numEdges, NULL vertex attribute data");
}

TEST_F(TriMeshApiTest, Rule3RejectsAnAttributeTypeThatIsNotStandard)
{
    const TQ3AttributeType bad[] = {kQ3AttributeTypeNone, kQ3AttributeTypeNumTypes,
                                    0x63757374 /* 'cust' */, -1};
    for (TQ3AttributeType type : bad)
        for (int which = 0; which < 4; ++which) {
            TQ3TriMeshData data = fullData();
            TQ3TriMeshAttributeData* entry = which == 0   ? &m_triangleAttributes[0]
                                             : which == 1 ? &m_edgeAttributes[0]
                                                          : &m_vertexAttributes[which - 2];
            const TQ3TriMeshAttributeData saved = *entry;
            entry->attributeType = type;
            expectNewFails(data, kQ3ErrorAttributeInvalidType, "type " + std::to_string(type));
            // Even when a use array switches every value off.
            std::vector<char> none(16, 0);
            entry->attributeUseArray = none.data();
            expectNewFails(data, kQ3ErrorAttributeInvalidType, "type " + std::to_string(type) + ", unused");
            *entry = saved;
        }
}

TEST_F(TriMeshApiTest, Rule3ComesAfterRules1And2)
{
    m_triangleAttributes[0].attributeType = kQ3AttributeTypeNumTypes;
    TQ3TriMeshData data = fullData();
    m_vertexAttributes[1].data = nullptr; // a later array's data
    expectNewFails(data, kQ3ErrorNULLParameter, "invalid type, NULL data after it");
    m_vertexAttributes[1].data = m_uvs.data();
    m_triangleAttributes[0].data = nullptr; // the same entry's data
    expectNewFails(data, kQ3ErrorNULLParameter, "invalid type with NULL data");
    m_triangleAttributes[0].data = m_triangleColors.data();
    data.numVertexAttributeTypes = kTooMany;
    expectNewFails(data, kQ3ErrorParameterOutOfRange, "invalid type, huge count after it");
}

TEST_F(TriMeshApiTest, Rule4RejectsAPointIndexOutOfRange)
{
    const std::vector<unsigned long> bad = {4, 5, 0xFFFFFFFFUL, (unsigned long)kQ3ArrayIndexNULL, ~0UL};
    for (unsigned long index : bad)
        for (int k = 0; k < 3; ++k) {
            TQ3TriMeshData data = fullData();
            const unsigned long saved = m_triangles[1].pointIndices[k];
            m_triangles[1].pointIndices[k] = index;
            expectNewFails(data, kQ3ErrorInvalidData, "triangle corner " + std::to_string(k));
            m_triangles[1].pointIndices[k] = saved;
        }
    for (unsigned long index : bad)
        for (int k = 0; k < 2; ++k) {
            TQ3TriMeshData data = fullData();
            const unsigned long saved = m_edges[4].pointIndices[k];
            m_edges[4].pointIndices[k] = index;
            expectNewFails(data, kQ3ErrorInvalidData, "edge end " + std::to_string(k));
            m_edges[4].pointIndices[k] = saved;
        }
}

TEST_F(TriMeshApiTest, Rule4RejectsAnEdgeTriangleIndexOutOfRangeButAcceptsArrayIndexNULL)
{
    for (unsigned long index : {2UL, 3UL, 0xFFFFFFFEUL})
        for (int k = 0; k < 2; ++k) {
            TQ3TriMeshData data = fullData();
            m_edges[2].triangleIndices[k] = index;
            expectNewFails(data, kQ3ErrorInvalidData, "edge triangle " + std::to_string(k));
            m_edges[2].triangleIndices[k] = (unsigned long)k;
        }
    // kQ3ArrayIndexNULL as C code writes it: ~0 converted, and the 32-bit value.
    for (unsigned long null : {(unsigned long)kQ3ArrayIndexNULL, ~0UL, 0xFFFFFFFFUL}) {
        for (TQ3TriMeshEdgeData& edge : m_edges)
            edge.triangleIndices[0] = edge.triangleIndices[1] = null;
        TQ3TriMeshData data = fullData();
        TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
        ASSERT_NE(triMesh, nullptr) << null;
        TQ3TriMeshData out{};
        ASSERT_EQ(Q3TriMesh_GetData(triMesh, &out), kQ3Success);
        EXPECT_EQ(out.edges[3].triangleIndices[1], null); // kept as given
        Q3TriMesh_EmptyData(&out);
    }
    // Edges of a mesh with no triangles may only say NULL.
    TQ3TriMeshData data = fullData();
    data.numTriangles = 0;
    data.numTriangleAttributeTypes = 0;
    TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
    EXPECT_NE(triMesh, nullptr);
    m_edges[0].triangleIndices[0] = 0;
    expectNewFails(data, kQ3ErrorInvalidData, "triangle 0 of none");
}

TEST_F(TriMeshApiTest, Rule4ComesAfterRule3)
{
    m_triangles[0].pointIndices[0] = 99;
    m_vertexAttributes[0].attributeType = kQ3AttributeTypeNumTypes;
    expectNewFails(fullData(), kQ3ErrorAttributeInvalidType, "bad index and bad type");
}

TEST_F(TriMeshApiTest, Rule5RejectsANonFinitePointCoordinate)
{
    for (std::size_t p : {std::size_t{0}, std::size_t{3}})
        for (int axis = 0; axis < 3; ++axis)
            for (float value : kNonFinite) {
                const TQ3Point3D saved = m_points[p];
                float* coordinates[] = {&m_points[p].x, &m_points[p].y, &m_points[p].z};
                *coordinates[axis] = value;
                expectNewFails(fullData(), kQ3ErrorInvalidData, "point " + std::to_string(p));
                m_points[p] = saved;
            }
}

TEST_F(TriMeshApiTest, Rule6RejectsAnAttributeValueInUseThatIsNotWellFormed)
{
    std::vector<char> triangleUse{1, 0};
    std::vector<char> edgeUse{1, 1, 1, 0, 1};
    for (float value : kNonFinite) {
        // A triangle colour, an edge colour, a point normal, a point uv.
        m_triangleColors[1].g = value;
        expectNewFails(fullData(), kQ3ErrorInvalidData, "triangle colour");
        m_triangleAttributes[0].attributeUseArray = triangleUse.data(); // triangle 1 has none
        TQ3GeometryObject accepted = newFull();
        EXPECT_NE(accepted, nullptr) << "an unused triangle colour is not checked";
        Q3Object_Dispose(accepted);
        m_triangleAttributes[0].attributeUseArray = nullptr;
        m_triangleColors[1].g = 1;

        m_edgeColors[3].r = value;
        expectNewFails(fullData(), kQ3ErrorInvalidData, "edge colour");
        m_edgeAttributes[0].attributeUseArray = edgeUse.data();
        accepted = newFull();
        EXPECT_NE(accepted, nullptr) << "an unused edge colour is not checked";
        Q3Object_Dispose(accepted);
        m_edgeAttributes[0].attributeUseArray = nullptr;
        m_edgeColors[3].r = 0.5f;

        m_normals[0].z = value;
        expectNewFails(fullData(), kQ3ErrorInvalidData, "point normal");
        m_normals[0].z = 1;

        m_uvs[1].u = value; // point 1's uv is switched off by m_uvUse
        accepted = newFull();
        EXPECT_NE(accepted, nullptr) << "an unused uv is not checked";
        Q3Object_Dispose(accepted);
        m_uvs[2].u = value;
        expectNewFails(fullData(), kQ3ErrorInvalidData, "point uv in use");
        m_uvs[1].u = 1;
        m_uvs[2].u = 1;
    }
}

TEST_F(TriMeshApiTest, Rule6RejectsAHighlightStateThatIsNeitherOnNorOff)
{
    std::vector<TQ3Switch> states{kQ3On, kQ3Off, kQ3On, kQ3On};
    std::vector<char> use{1, 1, 0, 1};
    TQ3TriMeshAttributeData entries[1] = {{kQ3AttributeTypeHighlightState, states.data(), nullptr}};
    TQ3TriMeshData data = plainData();
    data.numVertexAttributeTypes = 1;
    data.vertexAttributeTypes = entries;
    TQ3GeometryObject good = own(Q3TriMesh_New(&data));
    EXPECT_NE(good, nullptr);
    for (int bad : {2, -1}) {
        std::memcpy(&states[2], &bad, sizeof bad);
        expectNewFails(data, kQ3ErrorInvalidData, "highlight state " + std::to_string(bad));
        entries[0].attributeUseArray = use.data(); // point 2 has none
        TQ3GeometryObject accepted = Q3TriMesh_New(&data);
        EXPECT_NE(accepted, nullptr);
        Q3Object_Dispose(accepted);
        entries[0].attributeUseArray = nullptr;
    }
}

TEST_F(TriMeshApiTest, Rules5And6ComeBeforeRule7AndRule4BeforeRule5)
{
    TQ3TriMeshData data = fullData();
    data.triMeshAttributeSet = view();
    m_normals[2].y = kNaN;
    expectNewFails(data, kQ3ErrorInvalidData, "NaN normal, bad set");
    m_normals[2].y = 0;
    m_points[2].z = kInf;
    expectNewFails(data, kQ3ErrorInvalidData, "infinite point, bad set");
    m_points[2].z = -1;
    m_edges[1].triangleIndices[1] = 7;
    expectNewFails(data, kQ3ErrorInvalidData, "bad edge, bad set");
    m_edges[1].triangleIndices[1] = (unsigned long)kQ3ArrayIndexNULL;
    expectNewFails(data, kQ3ErrorInvalidObjectType, "only the set is bad");
}

TEST_F(TriMeshApiTest, Rule7RejectsATriMeshAttributeSetThatIsNotALiveAttributeSet)
{
    TQ3TriMeshData data = fullData();
    const std::vector<TQ3Object> wrongClass = notTriMeshes();
    for (TQ3Object wrong : {wrongClass[1], wrongClass[2]}) {
        data.triMeshAttributeSet = wrong;
        expectNewFails(data, kQ3ErrorInvalidObjectType, "wrong class");
    }
    data.triMeshAttributeSet = strayHandle();
    expectNewFails(data, kQ3ErrorInvalidObject, "stray");
    data.triMeshAttributeSet = deadObject();
    expectNewFails(data, kQ3ErrorInvalidObject, "dead");
}

// ---- SetData ------------------------------------------------------------------------

TEST_F(TriMeshApiTest, SetDataReplacesEverythingBumpsTheEditIndexAndReleasesTheOldSet)
{
    TQ3AttributeSet oldSet = own(Q3AttributeSet_New());
    TQ3AttributeSet newSet = own(Q3AttributeSet_New());
    TQ3TriMeshData data = plainData();
    data.triMeshAttributeSet = oldSet;
    TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
    ASSERT_NE(triMesh, nullptr);
    const unsigned long edit = Q3Shared_GetEditIndex(triMesh);
    TQ3TriMeshData replacement = fullData();
    replacement.triMeshAttributeSet = newSet;
    ASSERT_EQ(Q3TriMesh_SetData(triMesh, &replacement), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(triMesh), edit);
    EXPECT_EQ(referenceCount(oldSet), 1u);
    EXPECT_EQ(referenceCount(newSet), 2u);
    TQ3TriMeshData out{};
    ASSERT_EQ(Q3TriMesh_GetData(triMesh, &out), kQ3Success);
    expectSameMesh(replacement, out);
    Q3TriMesh_EmptyData(&out);
}

TEST_F(TriMeshApiTest, FailedSetDataChangesNothing)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    TQ3AttributeSet other = own(Q3AttributeSet_New());
    TQ3TriMeshData original = fullData();
    original.triMeshAttributeSet = set;
    TQ3GeometryObject triMesh = own(Q3TriMesh_New(&original));
    ASSERT_NE(triMesh, nullptr);
    TQ3TriMeshData before{};
    ASSERT_EQ(Q3TriMesh_GetData(triMesh, &before), kQ3Success);
    const unsigned long edit = Q3Shared_GetEditIndex(triMesh);

    // One failure per rule, each with a good set given (no reference may stay).
    std::vector<std::pair<std::function<void(TQ3TriMeshData&)>, TQ3Error>> breaks = {
        {[](TQ3TriMeshData& d) { d.edges = nullptr; }, kQ3ErrorNULLParameter},
        {[](TQ3TriMeshData& d) { d.numPoints = kTooMany; }, kQ3ErrorParameterOutOfRange},
        {[&](TQ3TriMeshData&) { m_edgeAttributes[0].attributeType = 0; }, kQ3ErrorAttributeInvalidType},
        {[&](TQ3TriMeshData&) { m_triangles[0].pointIndices[1] = 4; }, kQ3ErrorInvalidData},
        {[&](TQ3TriMeshData&) { m_points[3].y = kNaN; }, kQ3ErrorInvalidData},
        {[&](TQ3TriMeshData&) { m_uvs[3].v = -kInf; }, kQ3ErrorInvalidData},
        {[&](TQ3TriMeshData& d) { d.triMeshAttributeSet = triMesh; }, kQ3ErrorInvalidObjectType},
    };
    for (std::size_t i = 0; i < breaks.size(); ++i) {
        SCOPED_TRACE("rule break " + std::to_string(i));
        // Fresh arrays for each break: a new mesh over different points.
        m_points = {{5, 5, 5}, {6, 5, 5}, {6, 6, 5}, {5, 6, 5}};
        m_uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        m_triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
        m_edgeAttributes[0].attributeType = kQ3AttributeTypeDiffuseColor;
        TQ3TriMeshData data = fullData();
        data.triMeshAttributeSet = other;
        breaks[i].first(data);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_SetData(triMesh, &data), kQ3Failure), breaks[i].second);
        EXPECT_EQ(Q3Shared_GetEditIndex(triMesh), edit);
        TQ3TriMeshData after{};
        ASSERT_EQ(Q3TriMesh_GetData(triMesh, &after), kQ3Success);
        expectSameMesh(before, after);
        EXPECT_EQ(after.bBox.min.x, 0.0f);
        Q3TriMesh_EmptyData(&after);
        EXPECT_EQ(referenceCount(other), 1u);
    }
    Q3TriMesh_EmptyData(&before);
    EXPECT_EQ(referenceCount(set), 2u);
}

TEST_F(TriMeshApiTest, SetDataGetDataAndEmptyDataRejectBadArgumentsInOrder)
{
    const TQ3TriMeshData data = fullData();
    TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
    TQ3TriMeshData out{};
    out.numPoints = 77;
    TQ3TriMeshData bad = data;
    bad.points = nullptr;
    for (TQ3Object wrong : notTriMeshes()) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_SetData(wrong, &data), kQ3Failure), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_GetData(wrong, &out), kQ3Failure), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3TriMesh_SetData(wrong, nullptr), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3TriMesh_SetData(wrong, &bad), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3TriMesh_GetData(wrong, nullptr), kQ3ErrorInvalidObjectType);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_SetData(nullptr, &data), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_SetData(triMesh, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_GetData(nullptr, &out), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_GetData(triMesh, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_EmptyData(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_GetData(strayHandle(), &out), kQ3Failure), kQ3ErrorInvalidObject);
    TQ3GeometryObject dead = Q3TriMesh_New(&data);
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_GetData(dead, &out), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_SetData(dead, &data), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_EQ(out.numPoints, 77u); // never written by a failed GetData
    EXPECT_EQ(out.points, nullptr);
}

// ---- Duplicate ----------------------------------------------------------------------

TEST_F(TriMeshApiTest, DuplicateCopiesEveryArrayAndTheAttributeSet)
{
    TQ3AttributeSet set = own(colorSet(0, 0, 1));
    TQ3TriMeshData data = fullData();
    data.triMeshAttributeSet = set;
    TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
    ASSERT_NE(triMesh, nullptr);
    const unsigned long live = Q3Memory_CountLiveObjects();
    TQ3GeometryObject copy = Q3Object_Duplicate(triMesh);
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live + 2); // the copy and its set
    EXPECT_EQ(Q3Geometry_GetType(copy), kQ3GeometryTypeTriMesh);
    EXPECT_EQ(referenceCount(set), 2u);
    TQ3TriMeshData original{}, copied{};
    ASSERT_EQ(Q3TriMesh_GetData(triMesh, &original), kQ3Success);
    ASSERT_EQ(Q3TriMesh_GetData(copy, &copied), kQ3Success);
    const TQ3AttributeSet copySet = copied.triMeshAttributeSet;
    ASSERT_NE(copySet, nullptr);
    EXPECT_NE(copySet, set);
    EXPECT_EQ(colorOf(copySet).b, 1.0f);
    copied.triMeshAttributeSet = set; // compare the rest
    expectSameMesh(original, copied);
    copied.triMeshAttributeSet = copySet;
    // Editing the copy leaves the original alone.
    copied.points[0].x = -20;
    ASSERT_EQ(Q3TriMesh_SetData(copy, &copied), kQ3Success);
    Q3TriMesh_EmptyData(&original);
    Q3TriMesh_EmptyData(&copied);
    ASSERT_EQ(Q3TriMesh_GetData(triMesh, &original), kQ3Success);
    EXPECT_EQ(original.points[0].x, 0.0f);
    Q3TriMesh_EmptyData(&original);
    EXPECT_EQ(referenceCount(copySet), 1u); // only the copy holds it
    Q3Object_Dispose(copy);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live);
}

// ---- Submit and bounds --------------------------------------------------------------

TEST_F(TriMeshApiTest, SubmitRejectsBadArgumentsInOrder)
{
    const TQ3TriMeshData data = fullData();
    TQ3TriMeshData bad = data;
    bad.numPoints = 0; // the triangles' indices are out of range
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_Submit(nullptr, view()), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_Submit(&data, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_Submit(&bad, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    TQ3AttributeSet notAView = own(Q3AttributeSet_New());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_Submit(&bad, notAView), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_Submit(&data, strayHandle()), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_Submit(&data, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_Submit(&bad, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_Submit(triMesh, view()), kQ3Failure), kQ3ErrorViewNotStarted);
}

TEST_F(TriMeshApiTest, SubmitInsideALoopChecksTheDataRulesInOrder)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) {
        TQ3TriMeshData data = fullData();
        data.triMeshAttributeSet = v;
        data.numTriangles = kTooMany;
        data.edges = nullptr;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_Submit(&data, v), kQ3Failure), kQ3ErrorNULLParameter);
        data.edges = m_edges.data();
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_Submit(&data, v), kQ3Failure), kQ3ErrorParameterOutOfRange);
        data.numTriangles = 2;
        m_triangleAttributes[0].attributeType = kQ3AttributeTypeNumTypes;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_Submit(&data, v), kQ3Failure), kQ3ErrorAttributeInvalidType);
        m_triangleAttributes[0].attributeType = kQ3AttributeTypeDiffuseColor;
        m_edgeColors[0].g = kNaN;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_Submit(&data, v), kQ3Failure), kQ3ErrorInvalidData);
        m_edgeColors[0].g = 1;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_Submit(&data, v), kQ3Failure), kQ3ErrorInvalidObjectType);
        data.triMeshAttributeSet = deadObject();
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_Submit(&data, v), kQ3Failure), kQ3ErrorInvalidObject);
        data.triMeshAttributeSet = set;
        EXPECT_EQ(Q3TriMesh_Submit(&data, v), kQ3Success);
    });
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_EQ(box.min.z, -1.0f);
    EXPECT_EQ(box.max.y, 3.0f);
    EXPECT_EQ(referenceCount(set), 1u);
}

TEST_F(TriMeshApiTest, ImmediateAndRetainedTriMeshesBoundTheirTransformedPoints)
{
    const TQ3Vector3D translate{1, -1, 2};
    const TQ3Vector3D scale{-3, 0.5f, 2};
    auto transformed = [](const TQ3Point3D& p) { return TQ3Point3D{-3 * p.x + 1, 0.5f * p.y - 1, 2 * p.z + 2}; };
    TQ3Point3D low{1e9f, 1e9f, 1e9f}, high{-1e9f, -1e9f, -1e9f};
    for (const TQ3Point3D& point : m_points) {
        const TQ3Point3D p = transformed(point);
        low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    }
    for (const TQ3TriMeshData& data : {fullData(), plainData()}) {
        TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
        for (bool retained : {false, true}) {
            const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) {
                Q3TranslateTransform_Submit(&translate, v);
                Q3ScaleTransform_Submit(&scale, v);
                EXPECT_EQ(retained ? Q3Geometry_Submit(triMesh, v) : Q3TriMesh_Submit(&data, v), kQ3Success);
            });
            SCOPED_TRACE(retained ? "retained" : "immediate");
            EXPECT_EQ(box.isEmpty, kQ3False);
            EXPECT_FLOAT_EQ(box.min.x, low.x);
            EXPECT_FLOAT_EQ(box.min.y, low.y);
            EXPECT_FLOAT_EQ(box.min.z, low.z);
            EXPECT_FLOAT_EQ(box.max.x, high.x);
            EXPECT_FLOAT_EQ(box.max.y, high.y);
            EXPECT_FLOAT_EQ(box.max.z, high.z);
        }
    }
}

TEST_F(TriMeshApiTest, BoundsHoldEveryPointWhateverTheAttributeArrays)
{
    // A fifth point that no triangle uses: GetData's bBox holds it, and so
    // must the bounds, with or without triangle attributes (which make the
    // drawn mesh give every triangle its own vertices).
    m_points.push_back({-5, 9, 4});
    m_normals.push_back({0, 0, 1});
    m_uvs.push_back({0, 0});
    m_uvUse.push_back(1);
    m_vertexAttributes[0].data = m_normals.data();
    m_vertexAttributes[1].data = m_uvs.data();
    m_vertexAttributes[1].attributeUseArray = m_uvUse.data();
    for (const TQ3TriMeshData& data : {fullData(), plainData()}) {
        TQ3GeometryObject triMesh = own(Q3TriMesh_New(&data));
        ASSERT_NE(triMesh, nullptr);
        TQ3TriMeshData out{};
        ASSERT_EQ(Q3TriMesh_GetData(triMesh, &out), kQ3Success);
        for (bool retained : {false, true}) {
            const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) {
                EXPECT_EQ(retained ? Q3Geometry_Submit(triMesh, v) : Q3TriMesh_Submit(&data, v), kQ3Success);
            });
            SCOPED_TRACE(std::string(retained ? "retained" : "immediate") +
                         (data.numTriangleAttributeTypes != 0 ? ", triangle attributes" : ", plain"));
            EXPECT_EQ(box.isEmpty, kQ3False);
            EXPECT_EQ(box.min.x, -5.0f);
            EXPECT_EQ(box.max.y, 9.0f);
            EXPECT_EQ(box.max.z, 4.0f);
            EXPECT_EQ(box.min.x, out.bBox.min.x);
            EXPECT_EQ(box.min.z, out.bBox.min.z);
            EXPECT_EQ(box.max.y, out.bBox.max.y);
        }
        Q3TriMesh_EmptyData(&out);
    }
}

TEST(TriMeshApiUninitialized, EveryFunctionFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    TQ3TriMeshData data{};
    auto failed = [] { return Q3Error_Get(nullptr) == kQ3ErrorNotInitialized; };
    EXPECT_EQ(Q3TriMesh_New(&data), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3TriMesh_Submit(&data, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3TriMesh_SetData(nullptr, &data), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3TriMesh_GetData(nullptr, &data), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3TriMesh_EmptyData(&data), kQ3Failure);
    EXPECT_TRUE(failed());
}

} // namespace
