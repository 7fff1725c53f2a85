// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The contract every geometry with a data structure keeps (QD3DGeometry.h,
// docs/architecture.md "The contract suite"), tried once for every such type:
// New, GetData, SetData, EmptyData, Submit and Q3Object_Duplicate against
// NULL, dead, stray and wrong-class handles; NULL data; every array NULL and
// every array count above kQ3GeometryMaxArrayCount; NaN and +-Inf in every
// float the type requires to be finite; a failed New keeping no reference and
// a failed SetData leaving the object and its edit index as they were; the
// references GetData hands out and EmptyData gives back; Duplicate copying
// every attribute set once and keeping sharing.
//
// Each type is described here, by the test and independently of the
// library: a valid sample, the floats that must be finite, the attribute set
// slots (the geometry's own set last) and the counted arrays. What is
// particular to a type stays in its own *ApiTest.cpp.

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DStorage.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

// A typed test's body is a template whose fixture is a dependent base, so the
// fixture's consume() must be named through this.
#undef EXPECT_Q3_ERROR
#define EXPECT_Q3_ERROR(statement, code)                                                      \
    do {                                                                                      \
        statement;                                                                            \
        EXPECT_EQ(Q3Error_Get(nullptr), (code)) << #statement;                                \
        this->consume(q3test::Kind::Error, (code), #statement, __FILE__, __LINE__);           \
    } while (0)

namespace {

using namespace q3test;

/// A counted array of a struct: its name, the count that sizes it (a count
/// field, or the factor of a product) and how to make it NULL.
struct ArrayRef {
    const char* name;
    unsigned long* count;
    std::function<void()> makeNull;
};

/// What the suite reads and changes in one data struct.
struct Fields {
    std::vector<float*> floats;          // each must be finite
    std::vector<TQ3AttributeSet*> sets;  // every attribute set slot, the geometry's own last
    std::vector<ArrayRef> arrays;
};

void addPoint(Fields& f, TQ3Point3D& p)
{
    f.floats.insert(f.floats.end(), {&p.x, &p.y, &p.z});
}
void addVector(Fields& f, TQ3Vector3D& v)
{
    f.floats.insert(f.floats.end(), {&v.x, &v.y, &v.z});
}
void addVertices(Fields& f, TQ3Vertex3D* vertices, unsigned long count)
{
    if (vertices == nullptr)
        return;
    for (unsigned long i = 0; i < count; ++i) {
        addPoint(f, vertices[i].point);
        f.sets.push_back(&vertices[i].attributeSet);
    }
}
void addSets(Fields& f, TQ3AttributeSet* sets, unsigned long count)
{
    if (sets != nullptr)
        for (unsigned long i = 0; i < count; ++i)
            f.sets.push_back(&sets[i]);
}
template <class P>
void addArray(Fields& f, const char* name, unsigned long& count, P*& pointer)
{
    f.arrays.push_back({name, &count, [&pointer] { pointer = nullptr; }});
}

// ---- The types -----------------------------------------------------------------

#define Q3_CONTRACT_CALLS(Prefix, DataType, TypeCode)                                               \
    using Data = DataType;                                                                          \
    static constexpr const char* kName = #Prefix;                                                   \
    static constexpr TQ3ObjectType kType = TypeCode;                                                \
    static TQ3GeometryObject make(const Data* d) { return Q3##Prefix##_New(d); }                    \
    static TQ3Status submit(const Data* d, TQ3ViewObject v) { return Q3##Prefix##_Submit(d, v); }   \
    static TQ3Status setData(TQ3GeometryObject g, const Data* d) { return Q3##Prefix##_SetData(g, d); } \
    static TQ3Status getData(TQ3GeometryObject g, Data* d) { return Q3##Prefix##_GetData(g, d); }   \
    static TQ3Status emptyData(Data* d) { return Q3##Prefix##_EmptyData(d); }

// Apple's per-vertex calls, which the line, triangle, polygon and polyline
// share.
#define Q3_VERTEX_CALLS(Prefix)                                                                       \
    static TQ3Status getPosition(TQ3GeometryObject g, unsigned long i, TQ3Point3D* p)                 \
    {                                                                                                 \
        return Q3##Prefix##_GetVertexPosition(g, i, p);                                               \
    }                                                                                                 \
    static TQ3Status setPosition(TQ3GeometryObject g, unsigned long i, const TQ3Point3D* p)           \
    {                                                                                                 \
        return Q3##Prefix##_SetVertexPosition(g, i, p);                                               \
    }                                                                                                 \
    static TQ3Status getSet(TQ3GeometryObject g, unsigned long i, TQ3AttributeSet* s)                 \
    {                                                                                                 \
        return Q3##Prefix##_GetVertexAttributeSet(g, i, s);                                           \
    }                                                                                                 \
    static TQ3Status setSet(TQ3GeometryObject g, unsigned long i, TQ3AttributeSet s)                  \
    {                                                                                                 \
        return Q3##Prefix##_SetVertexAttributeSet(g, i, s);                                           \
    }

struct PointType {
    Q3_CONTRACT_CALLS(Point, TQ3PointData, kQ3GeometryTypePoint)
    struct Sample {
        Data data{{1, -2, 3}, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addPoint(f, d.point);
        f.sets.push_back(&d.pointAttributeSet);
        return f;
    }
};

struct LineType {
    Q3_CONTRACT_CALLS(Line, TQ3LineData, kQ3GeometryTypeLine)
    Q3_VERTEX_CALLS(Line)
    static TQ3Vertex3D* vertices(Data& d, unsigned long& count) { return count = 2, d.vertices; }
    struct Sample {
        Data data{{{{1, -2, 3}, nullptr}, {{-4, 5, 6}, nullptr}}, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addVertices(f, d.vertices, 2);
        f.sets.push_back(&d.lineAttributeSet);
        return f;
    }
};

struct TriangleType {
    Q3_CONTRACT_CALLS(Triangle, TQ3TriangleData, kQ3GeometryTypeTriangle)
    Q3_VERTEX_CALLS(Triangle)
    static TQ3Vertex3D* vertices(Data& d, unsigned long& count) { return count = 3, d.vertices; }
    struct Sample {
        Data data{{{{1, -2, 3}, nullptr}, {{-4, 5, 6}, nullptr}, {{7, 8, -9}, nullptr}}, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addVertices(f, d.vertices, 3);
        f.sets.push_back(&d.triangleAttributeSet);
        return f;
    }
};

struct PolygonType {
    Q3_CONTRACT_CALLS(Polygon, TQ3PolygonData, kQ3GeometryTypePolygon)
    Q3_VERTEX_CALLS(Polygon)
    static TQ3Vertex3D* vertices(Data& d, unsigned long& count) { return count = d.numVertices, d.vertices; }
    struct Sample {
        TQ3Vertex3D vertices[4] = {{{0, 0, 0}, nullptr}, {{2, 0, 0}, nullptr}, {{2, 1, 0}, nullptr},
                                   {{0, 1, 1}, nullptr}};
        Data data{4, vertices, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addVertices(f, d.vertices, d.numVertices);
        addArray(f, "vertices", d.numVertices, d.vertices);
        f.sets.push_back(&d.polygonAttributeSet);
        return f;
    }
};

struct PolyLineType {
    Q3_CONTRACT_CALLS(PolyLine, TQ3PolyLineData, kQ3GeometryTypePolyLine)
    Q3_VERTEX_CALLS(PolyLine)
    static TQ3Vertex3D* vertices(Data& d, unsigned long& count) { return count = d.numVertices, d.vertices; }
    struct Sample {
        TQ3Vertex3D vertices[3] = {{{0, 0, 0}, nullptr}, {{2, 0, 0}, nullptr}, {{2, 1, 3}, nullptr}};
        TQ3AttributeSet segments[2] = {nullptr, nullptr};
        Data data{3, vertices, segments, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addVertices(f, d.vertices, d.numVertices);
        addSets(f, d.segmentAttributeSet, d.numVertices - 1);
        addArray(f, "vertices", d.numVertices, d.vertices);
        f.sets.push_back(&d.polyLineAttributeSet);
        return f;
    }
};

struct GeneralPolygonType {
    Q3_CONTRACT_CALLS(GeneralPolygon, TQ3GeneralPolygonData, kQ3GeometryTypeGeneralPolygon)
    struct Sample {
        TQ3Vertex3D outer[4] = {{{0, 0, 0}, nullptr}, {{4, 0, 0}, nullptr}, {{4, 4, 0}, nullptr},
                                {{0, 4, 0}, nullptr}};
        TQ3Vertex3D hole[3] = {{{1, 1, 0}, nullptr}, {{2, 1, 0}, nullptr}, {{1, 2, 0}, nullptr}};
        TQ3GeneralPolygonContourData contours[2] = {{4, outer}, {3, hole}};
        Data data{2, contours, kQ3GeneralPolygonShapeHintComplex, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        if (d.contours != nullptr)
            for (unsigned long c = 0; c < d.numContours; ++c)
                addVertices(f, d.contours[c].vertices, d.contours[c].numVertices);
        addArray(f, "contours", d.numContours, d.contours);
        if (d.contours != nullptr)
            addArray(f, "contours[1].vertices", d.contours[1].numVertices, d.contours[1].vertices);
        f.sets.push_back(&d.generalPolygonAttributeSet);
        return f;
    }
};

struct PolyhedronType {
    Q3_CONTRACT_CALLS(Polyhedron, TQ3PolyhedronData, kQ3GeometryTypePolyhedron)
    struct Sample {
        TQ3Vertex3D vertices[4] = {{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{0, 1, 0}, nullptr},
                                   {{0, 0, 1}, nullptr}};
        TQ3PolyhedronTriangleData triangles[2] = {{{0, 1, 2}, kQ3PolyhedronEdgeAll, nullptr},
                                                  {{0, 1, 3}, kQ3PolyhedronEdgeNone, nullptr}};
        TQ3PolyhedronEdgeData edges[1] = {{{0, 1}, {0, 1}, nullptr}};
        Data data{4, vertices, 1, edges, 2, triangles, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addVertices(f, d.vertices, d.numVertices);
        if (d.edges != nullptr)
            for (unsigned long e = 0; e < d.numEdges; ++e)
                f.sets.push_back(&d.edges[e].edgeAttributeSet);
        if (d.triangles != nullptr)
            for (unsigned long t = 0; t < d.numTriangles; ++t)
                f.sets.push_back(&d.triangles[t].triangleAttributeSet);
        addArray(f, "vertices", d.numVertices, d.vertices);
        addArray(f, "edges", d.numEdges, d.edges);
        addArray(f, "triangles", d.numTriangles, d.triangles);
        f.sets.push_back(&d.polyhedronAttributeSet);
        return f;
    }
};

struct TriGridType {
    Q3_CONTRACT_CALLS(TriGrid, TQ3TriGridData, kQ3GeometryTypeTriGrid)
    struct Sample {
        TQ3Vertex3D vertices[6] = {{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{2, 0, 1}, nullptr},
                                   {{0, 1, 0}, nullptr}, {{1, 1, 0}, nullptr}, {{2, 1, 1}, nullptr}};
        TQ3AttributeSet facets[4] = {nullptr, nullptr, nullptr, nullptr};
        Data data{2, 3, vertices, facets, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addVertices(f, d.vertices, d.numRows * d.numColumns);
        addSets(f, d.facetAttributeSet, 2 * (d.numRows - 1) * (d.numColumns - 1));
        addArray(f, "vertices (numRows)", d.numRows, d.vertices);
        addArray(f, "vertices (numColumns)", d.numColumns, d.vertices);
        f.sets.push_back(&d.triGridAttributeSet);
        return f;
    }
};

struct TriMeshType {
    Q3_CONTRACT_CALLS(TriMesh, TQ3TriMeshData, kQ3GeometryTypeTriMesh)
    struct Sample {
        TQ3Point3D points[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}};
        TQ3TriMeshTriangleData triangles[2] = {{{0, 1, 2}}, {{1, 3, 2}}};
        TQ3TriMeshEdgeData edges[1] = {{{1, 2}, {0, 1}}};
        TQ3Vector3D normals[4] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
        TQ3TriMeshAttributeData vertexAttributes[1] = {{kQ3AttributeTypeNormal, normals, nullptr}};
        Data data{nullptr, 2, triangles, 0, nullptr, 1, edges, 0, nullptr, 4, points, 1, vertexAttributes,
                  {{0, 0, 0}, {1, 1, 1}, kQ3False}};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        if (d.points != nullptr)
            for (unsigned long i = 0; i < d.numPoints; ++i)
                addPoint(f, d.points[i]);
        addArray(f, "triangles", d.numTriangles, d.triangles);
        addArray(f, "edges", d.numEdges, d.edges);
        addArray(f, "points", d.numPoints, d.points);
        addArray(f, "vertexAttributeTypes", d.numVertexAttributeTypes, d.vertexAttributeTypes);
        f.sets.push_back(&d.triMeshAttributeSet);
        return f;
    }
};

struct BoxType {
    Q3_CONTRACT_CALLS(Box, TQ3BoxData, kQ3GeometryTypeBox)
    struct Sample {
        TQ3AttributeSet faces[6] = {};
        Data data{{1, 2, 3}, {0, 0, 2}, {3, 0, 0}, {0, 1, 0}, faces, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addPoint(f, d.origin);
        addVector(f, d.orientation);
        addVector(f, d.majorAxis);
        addVector(f, d.minorAxis);
        addSets(f, d.faceAttributeSet, 6);
        f.sets.push_back(&d.boxAttributeSet);
        return f;
    }
};

// The fields the revolved shapes share.
template <class D>
void addRevolved(Fields& f, D& d)
{
    addPoint(f, d.origin);
    addVector(f, d.orientation);
    addVector(f, d.majorRadius);
    addVector(f, d.minorRadius);
    f.floats.insert(f.floats.end(), {&d.uMin, &d.uMax, &d.vMin, &d.vMax});
}

struct ConeType {
    Q3_CONTRACT_CALLS(Cone, TQ3ConeData, kQ3GeometryTypeCone)
    struct Sample {
        Data data{{1, 2, 3}, {0, 0, 2}, {1, 0, 0}, {0, 1, 0}, 0, 1, 0, 1, kQ3EndCapMaskBottom,
                  nullptr, nullptr, nullptr, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addRevolved(f, d);
        f.sets.insert(f.sets.end(), {&d.interiorAttributeSet, &d.faceAttributeSet, &d.bottomAttributeSet,
                                     &d.coneAttributeSet});
        return f;
    }
};

struct CylinderType {
    Q3_CONTRACT_CALLS(Cylinder, TQ3CylinderData, kQ3GeometryTypeCylinder)
    struct Sample {
        Data data{{1, 2, 3}, {0, 0, 2}, {1, 0, 0}, {0, 1, 0}, 0, 1, 0, 1,
                  kQ3EndCapMaskTop | kQ3EndCapMaskBottom, nullptr, nullptr, nullptr, nullptr, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addRevolved(f, d);
        f.sets.insert(f.sets.end(), {&d.interiorAttributeSet, &d.topAttributeSet, &d.faceAttributeSet,
                                     &d.bottomAttributeSet, &d.cylinderAttributeSet});
        return f;
    }
};

struct EllipsoidType {
    Q3_CONTRACT_CALLS(Ellipsoid, TQ3EllipsoidData, kQ3GeometryTypeEllipsoid)
    struct Sample {
        Data data{{1, 2, 3}, {0, 0, 2}, {1, 0, 0}, {0, 1, 0}, 0, 1, 0, 1, kQ3EndCapNone, nullptr, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addRevolved(f, d);
        f.sets.insert(f.sets.end(), {&d.interiorAttributeSet, &d.ellipsoidAttributeSet});
        return f;
    }
};

struct TorusType {
    Q3_CONTRACT_CALLS(Torus, TQ3TorusData, kQ3GeometryTypeTorus)
    struct Sample {
        Data data{{1, 2, 3}, {0, 0, 1}, {2, 0, 0}, {0, 2, 0}, 0.5f, 0, 1, 0, 1, kQ3EndCapNone, nullptr, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addRevolved(f, d);
        f.floats.push_back(&d.ratio);
        f.sets.insert(f.sets.end(), {&d.interiorAttributeSet, &d.torusAttributeSet});
        return f;
    }
};

struct DiskType {
    Q3_CONTRACT_CALLS(Disk, TQ3DiskData, kQ3GeometryTypeDisk)
    struct Sample {
        Data data{{1, 2, 3}, {2, 0, 0}, {0, 1, 0}, 0, 1, 0, 1, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addPoint(f, d.origin);
        addVector(f, d.majorRadius);
        addVector(f, d.minorRadius);
        f.floats.insert(f.floats.end(), {&d.uMin, &d.uMax, &d.vMin, &d.vMax});
        f.sets.push_back(&d.diskAttributeSet);
        return f;
    }
};

struct EllipseType {
    Q3_CONTRACT_CALLS(Ellipse, TQ3EllipseData, kQ3GeometryTypeEllipse)
    struct Sample {
        Data data{{1, 2, 3}, {2, 0, 0}, {0, 1, 0}, 0, 1, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addPoint(f, d.origin);
        addVector(f, d.majorRadius);
        addVector(f, d.minorRadius);
        f.floats.insert(f.floats.end(), {&d.uMin, &d.uMax});
        f.sets.push_back(&d.ellipseAttributeSet);
        return f;
    }
};

struct NURBCurveType {
    Q3_CONTRACT_CALLS(NURBCurve, TQ3NURBCurveData, kQ3GeometryTypeNURBCurve)
    // QD3DGeometry.h checks a NURB curve's order and counts before its arrays.
    static constexpr bool kCountsBeforePresence = true;
    struct Sample {
        TQ3RationalPoint4D points[3] = {{0, 0, 0, 1}, {1, 2, 0, 2}, {2, 0, 1, 1}};
        float knots[6] = {0, 0, 0, 1, 1, 1};
        Data data{3, 3, points, knots, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        if (d.controlPoints != nullptr)
            for (unsigned long i = 0; i < d.numPoints; ++i)
                f.floats.insert(f.floats.end(), {&d.controlPoints[i].x, &d.controlPoints[i].y,
                                                 &d.controlPoints[i].z, &d.controlPoints[i].w});
        if (d.knots != nullptr)
            for (unsigned long i = 0; i < d.numPoints + d.order; ++i)
                f.floats.push_back(&d.knots[i]);
        addArray(f, "controlPoints", d.numPoints, d.controlPoints);
        addArray(f, "knots", d.numPoints, d.knots);
        f.sets.push_back(&d.curveAttributeSet);
        return f;
    }
};

struct NURBPatchType {
    Q3_CONTRACT_CALLS(NURBPatch, TQ3NURBPatchData, kQ3GeometryTypeNURBPatch)
    // QD3DGeometry.h checks a NURB patch's orders and counts before its arrays.
    static constexpr bool kCountsBeforePresence = true;
    struct Sample {
        TQ3RationalPoint4D points[4] = {{0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 1, 2}, {1, 1, 0, 1}};
        float uKnots[4] = {0, 0, 1, 1};
        float vKnots[4] = {0, 0, 1, 1};
        Data data{2, 2, 2, 2, points, uKnots, vKnots, 0, nullptr, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        if (d.controlPoints != nullptr)
            for (unsigned long i = 0; i < d.numRows * d.numColumns; ++i)
                f.floats.insert(f.floats.end(), {&d.controlPoints[i].x, &d.controlPoints[i].y,
                                                 &d.controlPoints[i].z, &d.controlPoints[i].w});
        for (float* knots : {d.uKnots, d.vKnots})
            if (knots != nullptr)
                for (unsigned long i = 0; i < 4; ++i)
                    f.floats.push_back(&knots[i]);
        addArray(f, "controlPoints", d.numRows, d.controlPoints);
        addArray(f, "uKnots", d.numColumns, d.uKnots);
        addArray(f, "vKnots", d.numRows, d.vKnots);
        f.sets.push_back(&d.patchAttributeSet);
        return f;
    }
};

struct MarkerType {
    Q3_CONTRACT_CALLS(Marker, TQ3MarkerData, kQ3GeometryTypeMarker)
    struct Sample {
        unsigned char bits[4] = {0xF0, 0x90, 0x90, 0xF0};
        Data data{{1, 2, 3}, -2, 1, {bits, 4, 4, 1, kQ3EndianBig}, nullptr};
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addPoint(f, d.location);
        addArray(f, "bitmap.image (rowBytes)", d.bitmap.rowBytes, d.bitmap.image);
        f.sets.push_back(&d.markerAttributeSet);
        return f;
    }
};

struct PixmapMarkerType {
    Q3_CONTRACT_CALLS(PixmapMarker, TQ3PixmapMarkerData, kQ3GeometryTypePixmapMarker)
    struct Sample {
        unsigned char pixels[2 * 2 * 4] = {};
        TQ3StorageObject storage = Q3MemoryStorage_New(pixels, sizeof pixels);
        Data data{{1, 2, 3},
                  0,
                  0,
                  {storage, 2, 2, 8, 32, kQ3PixelTypeARGB32, kQ3EndianBig, kQ3EndianBig},
                  nullptr};
        ~Sample() { Q3Object_Dispose(storage); }
    };
    static Fields fields(Data& d)
    {
        Fields f;
        addPoint(f, d.position);
        f.sets.push_back(&d.pixmapMarkerAttributeSet);
        return f;
    }
};

#undef Q3_CONTRACT_CALLS
#undef Q3_VERTEX_CALLS

// Whether a type's header checks its counts before its arrays' presence (the
// NURB types); every other type checks presence first.
template <class G, class = void>
struct CountsBeforePresence : std::false_type {};
template <class G>
struct CountsBeforePresence<G, std::void_t<decltype(G::kCountsBeforePresence)>> : std::true_type {};

// ---- The suite -----------------------------------------------------------------

template <class G>
class GeometryContractTest : public OwningApiTest {
protected:
    using Data = typename G::Data;

    void SetUp() override
    {
        OwningApiTest::SetUp();
        m_sample = std::make_unique<typename G::Sample>();
    }
    void TearDown() override
    {
        m_sample.reset();
        m_fresh.clear();
        OwningApiTest::TearDown();
    }

    /// The sample the fixture keeps (left as it is but by the per-vertex
    /// tests, which set up their case in it).
    Data& sample() { return m_sample->data; }

    /// A new sample with arrays of its own, to change freely (a copy of the
    /// struct would share the sample's arrays); kept until TearDown.
    Data& fresh()
    {
        m_fresh.push_back(std::make_unique<typename G::Sample>());
        return m_fresh.back()->data;
    }

    /// A new sample with `set` in every attribute set slot.
    Data& freshWithSet(TQ3AttributeSet set)
    {
        Data& data = fresh();
        for (TQ3AttributeSet* slot : G::fields(data).sets)
            *slot = set;
        return data;
    }

    /// What GetData reports of a geometry (its floats and sets) and its edit
    /// index.
    struct State {
        std::vector<float> floats;
        std::vector<TQ3AttributeSet> sets;
        unsigned long editIndex = 0;
    };

    State stateOf(TQ3GeometryObject geometry)
    {
        State state;
        Data data{};
        EXPECT_EQ(G::getData(geometry, &data), kQ3Success);
        const Fields f = G::fields(data);
        for (float* v : f.floats)
            state.floats.push_back(*v);
        for (TQ3AttributeSet* s : f.sets)
            state.sets.push_back(*s);
        EXPECT_EQ(G::emptyData(&data), kQ3Success);
        state.editIndex = Q3Shared_GetEditIndex(geometry);
        return state;
    }

    void expectSameState(const State& before, const State& after)
    {
        ASSERT_EQ(before.floats.size(), after.floats.size());
        for (std::size_t i = 0; i < before.floats.size(); ++i)
            EXPECT_EQ(before.floats[i], after.floats[i]) << "float " << i;
        EXPECT_EQ(before.sets, after.sets);
        EXPECT_EQ(before.editIndex, after.editIndex);
    }

    /// Handles that are not of the type: an attribute set and another
    /// geometry.
    std::vector<TQ3Object> wrongClass()
    {
        const TQ3PointData point{{0, 0, 0}, nullptr};
        const TQ3LineData line{{{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}}, nullptr};
        TQ3Object other = G::kType == kQ3GeometryTypePoint ? Q3Line_New(&line) : Q3Point_New(&point);
        return {own(Q3AttributeSet_New()), own(other), view()};
    }

private:
    std::unique_ptr<typename G::Sample> m_sample;
    std::vector<std::unique_ptr<typename G::Sample>> m_fresh;
};

using GeometryTypes = ::testing::Types<PointType, LineType, TriangleType, PolygonType, PolyLineType,
                                       GeneralPolygonType, PolyhedronType, TriGridType, TriMeshType, BoxType,
                                       ConeType, CylinderType, EllipsoidType, TorusType, DiskType, EllipseType,
                                       NURBCurveType, NURBPatchType, MarkerType, PixmapMarkerType>;

struct TypeName {
    template <class G>
    static std::string GetName(int)
    {
        return G::kName;
    }
};

TYPED_TEST_SUITE(GeometryContractTest, GeometryTypes, TypeName);

TYPED_TEST(GeometryContractTest, NewMakesTheTypeAndGetDataReturnsTheData)
{
    using G = TypeParam;
    TQ3GeometryObject geometry = this->own(G::make(&this->sample()));
    ASSERT_NE(geometry, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(geometry), G::kType);
    EXPECT_EQ(Q3Geometry_GetType(geometry), G::kType);
    EXPECT_EQ(Q3Shape_GetType(geometry), kQ3ShapeTypeGeometry);
    EXPECT_EQ(Q3Object_IsDrawable(geometry), kQ3True);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_Submit(geometry, this->view()), kQ3Failure), kQ3ErrorViewNotStarted);
    const auto state = this->stateOf(geometry);
    const Fields given = G::fields(this->sample());
    ASSERT_EQ(state.floats.size(), given.floats.size());
    for (std::size_t i = 0; i < given.floats.size(); ++i)
        EXPECT_EQ(state.floats[i], *given.floats[i]) << "float " << i;
    for (TQ3AttributeSet set : state.sets)
        EXPECT_EQ(set, nullptr);
}

TYPED_TEST(GeometryContractTest, NewCopiesTheCallersDataAndHoldsItsOwnReferences)
{
    using G = TypeParam;
    TQ3AttributeSet set = colorSet(0.25f, 0.5f, 0.75f);
    typename G::Data& data = this->freshWithSet(set);
    TQ3GeometryObject geometry = this->own(G::make(&data));
    ASSERT_NE(geometry, nullptr);
    const auto before = this->stateOf(geometry);
    // Changing the caller's data afterwards changes nothing in the geometry.
    for (float* v : G::fields(data).floats)
        *v += 1;
    for (TQ3AttributeSet* slot : G::fields(data).sets)
        *slot = nullptr;
    this->expectSameState(before, this->stateOf(geometry));
    // The geometry outlives the caller's reference to its set.
    const unsigned long live = Q3Memory_CountLiveObjects();
    Q3Object_Dispose(set);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live);
    TQ3AttributeSet held = nullptr;
    ASSERT_EQ(Q3Geometry_GetAttributeSet(geometry, &held), kQ3Success);
    EXPECT_EQ(held, set);
    EXPECT_EQ(colorOf(held).b, 0.75f);
    Q3Object_Dispose(held);
}

TYPED_TEST(GeometryContractTest, NullDataAndNullOrBadHandlesAreRefused)
{
    using G = TypeParam;
    typename G::Data out{};
    EXPECT_Q3_ERROR(EXPECT_EQ(G::make(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(G::emptyData(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(G::submit(nullptr, this->view()), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(G::submit(&this->sample(), nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(G::submit(&this->sample(), this->view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(G::submit(&this->sample(), strayHandle()), kQ3Failure), kQ3ErrorInvalidObject);
    // The view is checked before the data's rules.
    typename G::Data& badData = this->fresh();
    *G::fields(badData).floats[0] = kInf;
    EXPECT_Q3_ERROR(EXPECT_EQ(G::submit(&badData, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(G::submit(&badData, this->own(Q3AttributeSet_New())), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(G::submit(&badData, this->view()), kQ3Failure), kQ3ErrorViewNotStarted);

    TQ3GeometryObject geometry = this->own(G::make(&this->sample()));
    ASSERT_NE(geometry, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(G::setData(geometry, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(G::getData(geometry, nullptr), kQ3Failure), kQ3ErrorNULLParameter);

    std::vector<std::pair<TQ3Object, TQ3Error>> bad = {{nullptr, kQ3ErrorNULLParameter},
                                                       {strayHandle(), kQ3ErrorInvalidObject}};
    for (TQ3Object wrong : this->wrongClass())
        bad.emplace_back(wrong, kQ3ErrorInvalidObjectType);
    // Made last: an object made after it could be given its address.
    TQ3GeometryObject dead = G::make(&this->sample());
    Q3Object_Dispose(dead);
    bad.emplace_back(dead, kQ3ErrorInvalidObject);
    *G::fields(badData).floats[0] = kNaN;
    std::memset(static_cast<void*>(&out), 0x5A, sizeof out);
    const typename G::Data pattern = out;
    for (const auto& [handle, code] : bad) {
        EXPECT_Q3_ERROR(EXPECT_EQ(G::setData(handle, &this->sample()), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(G::setData(handle, &badData), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(G::getData(handle, &out), kQ3Failure), code);
        EXPECT_EQ(std::memcmp(&out, &pattern, sizeof out), 0); // a failed GetData writes nothing
        // The handle is checked before the pointer.
        EXPECT_Q3_ERROR(G::setData(handle, nullptr), code);
        EXPECT_Q3_ERROR(G::getData(handle, nullptr), code);
    }
}

TYPED_TEST(GeometryContractTest, EveryNullArrayIsRefusedAndChangesNothing)
{
    using G = TypeParam;
    TQ3GeometryObject geometry = this->own(G::make(&this->sample()));
    ASSERT_NE(geometry, nullptr);
    const auto before = this->stateOf(geometry);
    const std::size_t arrays = G::fields(this->sample()).arrays.size();
    for (std::size_t i = 0; i < arrays; ++i) {
        typename G::Data& data = this->fresh();
        const ArrayRef array = G::fields(data).arrays[i];
        SCOPED_TRACE(array.name);
        array.makeNull();
        EXPECT_Q3_ERROR(EXPECT_EQ(G::make(&data), nullptr), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(G::setData(geometry, &data), kQ3Failure), kQ3ErrorNULLParameter);
        // Presence is checked before every count (but for the NURB types).
        *array.count = (unsigned long)kQ3GeometryMaxArrayCount + 1;
        EXPECT_Q3_ERROR(EXPECT_EQ(G::make(&data), nullptr), CountsBeforePresence<G>::value
                                                               ? kQ3ErrorParameterOutOfRange
                                                               : kQ3ErrorNULLParameter);
    }
    this->expectSameState(before, this->stateOf(geometry));
}

TYPED_TEST(GeometryContractTest, EveryCountAboveTheLimitIsRefusedWithoutReadingTheArray)
{
    using G = TypeParam;
    TQ3GeometryObject geometry = this->own(G::make(&this->sample()));
    ASSERT_NE(geometry, nullptr);
    const auto before = this->stateOf(geometry);
    const std::size_t arrays = G::fields(this->sample()).arrays.size();
    for (std::size_t i = 0; i < arrays; ++i)
        for (unsigned long count : {(unsigned long)kQ3GeometryMaxArrayCount + 1, 0xFFFFFFFFUL}) {
            typename G::Data& data = this->fresh();
            const ArrayRef array = G::fields(data).arrays[i];
            SCOPED_TRACE(std::string(array.name) + " = " + std::to_string(count));
            *array.count = count; // the arrays stay as small as they are: a read would be out of bounds
            EXPECT_Q3_ERROR(EXPECT_EQ(G::make(&data), nullptr), kQ3ErrorParameterOutOfRange);
            EXPECT_Q3_ERROR(EXPECT_EQ(G::setData(geometry, &data), kQ3Failure), kQ3ErrorParameterOutOfRange);
        }
    this->expectSameState(before, this->stateOf(geometry));
}

TYPED_TEST(GeometryContractTest, EveryFloatThatIsNotFiniteIsRefusedAndChangesNothing)
{
    using G = TypeParam;
    TQ3AttributeSet set = this->own(Q3AttributeSet_New());
    TQ3GeometryObject geometry = this->own(G::make(&this->sample()));
    ASSERT_NE(geometry, nullptr);
    const auto before = this->stateOf(geometry);
    const std::size_t floats = G::fields(this->sample()).floats.size();
    ASSERT_GT(floats, 0u);
    for (std::size_t i = 0; i < floats; ++i)
        for (float bad : kNonFinite) {
            // Good sets in every slot: the failure must give their references back.
            typename G::Data& data = this->freshWithSet(set);
            *G::fields(data).floats[i] = bad;
            // A set of the wrong class too: the coordinates are checked first.
            *G::fields(data).sets.back() = this->view();
            SCOPED_TRACE("float " + std::to_string(i) + " = " + std::to_string(bad));
            EXPECT_Q3_ERROR(EXPECT_EQ(G::make(&data), nullptr), kQ3ErrorInvalidData);
            EXPECT_Q3_ERROR(EXPECT_EQ(G::setData(geometry, &data), kQ3Failure), kQ3ErrorInvalidData);
            const TQ3BoundingBox box = this->boundsOf([&](TQ3ViewObject v) {
                EXPECT_Q3_ERROR(EXPECT_EQ(G::submit(&data, v), kQ3Failure), kQ3ErrorInvalidData);
            });
            EXPECT_EQ(box.isEmpty, kQ3True);
        }
    this->expectSameState(before, this->stateOf(geometry));
    EXPECT_EQ(referenceCount(set), 1u);
}

TYPED_TEST(GeometryContractTest, BadAttributeSetsInEverySlotAreRefusedAndKeepNoReference)
{
    using G = TypeParam;
    TQ3AttributeSet good = this->own(Q3AttributeSet_New());
    TQ3GeometryObject geometry = this->own(G::make(&this->sample()));
    ASSERT_NE(geometry, nullptr);
    const auto before = this->stateOf(geometry);
    const std::size_t slots = G::fields(this->sample()).sets.size();
    const std::vector<TQ3Object> wrong = this->wrongClass();
    for (std::size_t i = 0; i < slots; ++i) {
        SCOPED_TRACE("slot " + std::to_string(i));
        std::vector<std::pair<TQ3Object, TQ3Error>> bad = {{strayHandle(), kQ3ErrorInvalidObject},
                                                           {wrong[1], kQ3ErrorInvalidObjectType},
                                                           {wrong[2], kQ3ErrorInvalidObjectType}};
        for (const auto& [handle, code] : bad) {
            typename G::Data& data = this->freshWithSet(good);
            *G::fields(data).sets[i] = handle;
            EXPECT_Q3_ERROR(EXPECT_EQ(G::make(&data), nullptr), code);
            EXPECT_Q3_ERROR(EXPECT_EQ(G::setData(geometry, &data), kQ3Failure), code);
        }
        typename G::Data& data = this->freshWithSet(good);
        *G::fields(data).sets[i] = deadObject();
        EXPECT_Q3_ERROR(EXPECT_EQ(G::make(&data), nullptr), kQ3ErrorInvalidObject);
        *G::fields(data).sets[i] = wrong[2];
        const TQ3BoundingBox box = this->boundsOf([&](TQ3ViewObject v) {
            EXPECT_Q3_ERROR(EXPECT_EQ(G::submit(&data, v), kQ3Failure), kQ3ErrorInvalidObjectType);
        });
        EXPECT_EQ(box.isEmpty, kQ3True);
        EXPECT_EQ(referenceCount(good), 1u);
    }
    this->expectSameState(before, this->stateOf(geometry));
}

TYPED_TEST(GeometryContractTest, SetDataReplacesTheDataAndBumpsTheEditIndex)
{
    using G = TypeParam;
    TQ3AttributeSet set = this->own(Q3AttributeSet_New());
    TQ3GeometryObject geometry = this->own(G::make(&this->sample()));
    ASSERT_NE(geometry, nullptr);
    const unsigned long edit = Q3Shared_GetEditIndex(geometry);
    const typename G::Data& data = this->freshWithSet(set);
    const std::size_t slots = G::fields(this->sample()).sets.size();
    ASSERT_EQ(G::setData(geometry, &data), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(geometry), edit);
    EXPECT_EQ(referenceCount(set), 1 + slots);
    const auto state = this->stateOf(geometry);
    for (TQ3AttributeSet held : state.sets)
        EXPECT_EQ(held, set);
    // The geometry's own set is the one Q3Geometry_GetAttributeSet reads.
    TQ3AttributeSet own = nullptr;
    ASSERT_EQ(Q3Geometry_GetAttributeSet(geometry, &own), kQ3Success);
    EXPECT_EQ(own, set);
    Q3Object_Dispose(own);
    ASSERT_EQ(G::setData(geometry, &this->sample()), kQ3Success);
    EXPECT_EQ(referenceCount(set), 1u);
}

TYPED_TEST(GeometryContractTest, GetDataHandsOutReferencesThatEmptyDataGivesBack)
{
    using G = TypeParam;
    TQ3AttributeSet shared = this->own(colorSet(1, 0, 0));
    const typename G::Data& given = this->freshWithSet(shared);
    const std::size_t slots = G::fields(this->sample()).sets.size();
    TQ3GeometryObject geometry = G::make(&given);
    ASSERT_NE(geometry, nullptr);
    EXPECT_EQ(referenceCount(shared), 1 + slots); // the caller's and one per slot

    typename G::Data out{};
    ASSERT_EQ(G::getData(geometry, &out), kQ3Success);
    for (TQ3AttributeSet* slot : G::fields(out).sets)
        EXPECT_EQ(*slot, shared);
    EXPECT_EQ(referenceCount(shared), 1 + 2 * slots);
    Q3Object_Dispose(geometry);
    EXPECT_EQ(referenceCount(shared), 1 + slots); // GetData's outlive the geometry

    // A bad handle in the data: EmptyData releases nothing.
    TQ3AttributeSet* last = G::fields(out).sets.back();
    for (TQ3Object bad : {strayHandle(), this->view()}) {
        *last = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(G::emptyData(&out), kQ3Failure),
                        bad == this->view() ? kQ3ErrorInvalidObjectType : kQ3ErrorInvalidObject);
        EXPECT_EQ(*G::fields(out).sets.front(), slots > 1 ? shared : bad); // nothing cleared
        EXPECT_EQ(referenceCount(shared), 1 + slots);                      // nothing released
    }
    *last = shared;
    ASSERT_EQ(G::emptyData(&out), kQ3Success);
    EXPECT_EQ(referenceCount(shared), 1u);
    for (TQ3AttributeSet* slot : G::fields(out).sets)
        EXPECT_EQ(*slot, nullptr);
    EXPECT_EQ(G::emptyData(&out), kQ3Success); // nothing left to release
}

TYPED_TEST(GeometryContractTest, DuplicateCopiesEverySetOnceAndKeepsSharing)
{
    using G = TypeParam;
    TQ3AttributeSet shared = this->own(colorSet(0, 1, 0));
    TQ3AttributeSet single = this->own(colorSet(1, 0, 0));
    typename G::Data& given = this->freshWithSet(shared);
    const std::size_t slots = G::fields(given).sets.size();
    *G::fields(given).sets[0] = single;
    TQ3GeometryObject geometry = this->own(G::make(&given));
    ASSERT_NE(geometry, nullptr);
    const unsigned long live = Q3Memory_CountLiveObjects();
    TQ3GeometryObject copy = Q3Object_Duplicate(geometry);
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(copy), G::kType);
    EXPECT_EQ(referenceCount(shared), slots); // the original is untouched
    EXPECT_EQ(referenceCount(single), 2u);
    const auto state = this->stateOf(copy);
    const auto original = this->stateOf(geometry);
    EXPECT_EQ(state.floats, original.floats);
    ASSERT_EQ(state.sets.size(), slots);
    ASSERT_NE(state.sets[0], nullptr);
    EXPECT_NE(state.sets[0], single);
    EXPECT_EQ(colorOf(state.sets[0]).r, 1.0f);
    EXPECT_EQ(referenceCount(state.sets[0]), 1u);
    if (slots > 1) {
        EXPECT_NE(state.sets[1], shared);
        EXPECT_NE(state.sets[1], state.sets[0]);
        for (std::size_t i = 1; i < slots; ++i)
            EXPECT_EQ(state.sets[i], state.sets[1]); // one copy, shared as the original was
        EXPECT_EQ(colorOf(state.sets[1]).g, 1.0f);
        EXPECT_EQ(referenceCount(state.sets[1]), slots - 1);
    }
    // Changing the copy leaves the original alone.
    ASSERT_EQ(G::setData(copy, &this->sample()), kQ3Success);
    this->expectSameState(original, this->stateOf(geometry));
    Q3Object_Dispose(copy);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live); // the copied sets went with it
}

TYPED_TEST(GeometryContractTest, TheGeometryAttributeSetIsTheLastSlot)
{
    using G = TypeParam;
    TQ3AttributeSet first = this->own(Q3AttributeSet_New());
    TQ3AttributeSet second = this->own(Q3AttributeSet_New());
    typename G::Data& data = this->fresh();
    *G::fields(data).sets.back() = first;
    TQ3GeometryObject geometry = this->own(G::make(&data));
    ASSERT_NE(geometry, nullptr);
    TQ3AttributeSet got = nullptr;
    ASSERT_EQ(Q3Geometry_GetAttributeSet(geometry, &got), kQ3Success);
    EXPECT_EQ(got, first);
    Q3Object_Dispose(got);
    const unsigned long edit = Q3Shared_GetEditIndex(geometry);
    ASSERT_EQ(Q3Geometry_SetAttributeSet(geometry, second), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(geometry), edit);
    EXPECT_EQ(this->stateOf(geometry).sets.back(), second);
    EXPECT_EQ(referenceCount(first), 1u);
    EXPECT_EQ(referenceCount(second), 2u);
    const auto before = this->stateOf(geometry);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_SetAttributeSet(geometry, this->view()), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    // A shared object of another class, the geometry itself, is no set either.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_SetAttributeSet(geometry, geometry), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    this->expectSameState(before, this->stateOf(geometry));
    ASSERT_EQ(Q3Geometry_SetAttributeSet(geometry, nullptr), kQ3Success);
    ASSERT_EQ(Q3Geometry_GetAttributeSet(geometry, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    EXPECT_EQ(referenceCount(second), 1u);
}

TYPED_TEST(GeometryContractTest, ImmediateModeKeepsNoReference)
{
    using G = TypeParam;
    TQ3AttributeSet set = this->own(Q3AttributeSet_New());
    const typename G::Data& data = this->freshWithSet(set);
    const TQ3BoundingBox box = this->boundsOf([&](TQ3ViewObject v) { EXPECT_EQ(G::submit(&data, v), kQ3Success); });
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_EQ(referenceCount(set), 1u);
}

// ---- The per-vertex calls ---------------------------------------------------------------

template <class G>
class VertexCallsContractTest : public GeometryContractTest<G> {
protected:
    /// The sample's vertices (in the fixture's sample) and their count.
    TQ3Vertex3D* sampleVertices(unsigned long& count) { return G::vertices(this->sample(), count); }
};

using VertexGeometryTypes = ::testing::Types<LineType, TriangleType, PolygonType, PolyLineType>;
TYPED_TEST_SUITE(VertexCallsContractTest, VertexGeometryTypes, TypeName);

TYPED_TEST(VertexCallsContractTest, GetVertexPositionReadsEveryVertexAndRejectsOtherIndices)
{
    using G = TypeParam;
    unsigned long n = 0;
    const TQ3Vertex3D* given = this->sampleVertices(n);
    TQ3GeometryObject geometry = this->own(G::make(&this->sample()));
    ASSERT_NE(geometry, nullptr);
    for (unsigned long index = 0; index < n; ++index) {
        TQ3Point3D position{};
        ASSERT_EQ(G::getPosition(geometry, index, &position), kQ3Success);
        EXPECT_TRUE(samePoint(position, given[index].point)) << index;
    }
    for (unsigned long index : indicesPastTheEnd(n)) {
        TQ3Point3D position{42, 42, 42};
        EXPECT_Q3_ERROR(EXPECT_EQ(G::getPosition(geometry, index, &position), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        EXPECT_EQ(position.x, 42.0f);
    }
}

TYPED_TEST(VertexCallsContractTest, SetVertexPositionMovesOneVertexKeepsItsSetAndBumpsTheEditIndex)
{
    using G = TypeParam;
    TQ3AttributeSet set = this->own(Q3AttributeSet_New());
    unsigned long n = 0;
    TQ3Vertex3D* given = this->sampleVertices(n);
    given[n - 1].attributeSet = set;
    TQ3GeometryObject geometry = this->own(G::make(&this->sample()));
    ASSERT_NE(geometry, nullptr);
    for (unsigned long index : {0UL, n - 1}) {
        const unsigned long edit = Q3Shared_GetEditIndex(geometry);
        const TQ3Point3D moved{float(index) + 0.5f, -8, 9};
        ASSERT_EQ(G::setPosition(geometry, index, &moved), kQ3Success);
        EXPECT_NE(Q3Shared_GetEditIndex(geometry), edit);
        typename G::Data data{};
        ASSERT_EQ(G::getData(geometry, &data), kQ3Success);
        unsigned long count = 0;
        const TQ3Vertex3D* now = G::vertices(data, count);
        EXPECT_TRUE(samePoint(now[index].point, moved));
        EXPECT_TRUE(samePoint(now[1].point, given[1].point) || index == 1); // the others stay
        EXPECT_EQ(now[n - 1].attributeSet, set);
        EXPECT_EQ(G::emptyData(&data), kQ3Success);
    }
}

TYPED_TEST(VertexCallsContractTest, SetVertexPositionRejectsBadIndicesAndNonFiniteCoordinatesAndChangesNothing)
{
    using G = TypeParam;
    unsigned long n = 0;
    this->sampleVertices(n);
    TQ3GeometryObject geometry = this->own(G::make(&this->sample()));
    ASSERT_NE(geometry, nullptr);
    const auto before = this->stateOf(geometry);
    const TQ3Point3D fine{1, 1, 1};
    for (unsigned long index : indicesPastTheEnd(n))
        EXPECT_Q3_ERROR(EXPECT_EQ(G::setPosition(geometry, index, &fine), kQ3Failure), kQ3ErrorParameterOutOfRange);
    for (unsigned long index = 0; index < n; ++index)
        for (int axis = 0; axis < 3; ++axis)
            for (float value : kNonFinite) {
                TQ3Point3D position = fine;
                float* coordinates[] = {&position.x, &position.y, &position.z};
                *coordinates[axis] = value;
                EXPECT_Q3_ERROR(EXPECT_EQ(G::setPosition(geometry, index, &position), kQ3Failure),
                                kQ3ErrorInvalidData);
            }
    const TQ3Point3D nan{kNaN, 0, 0};
    EXPECT_Q3_ERROR(G::setPosition(geometry, n, &nan), kQ3ErrorParameterOutOfRange); // the index first
    EXPECT_Q3_ERROR(G::setPosition(geometry, n, nullptr), kQ3ErrorNULLParameter);     // the pointer first
    this->expectSameState(before, this->stateOf(geometry));
}

TYPED_TEST(VertexCallsContractTest, VertexAttributeSetsAreReadAndReplacedWithBalancedReferences)
{
    using G = TypeParam;
    TQ3AttributeSet first = this->own(Q3AttributeSet_New());
    TQ3AttributeSet second = this->own(Q3AttributeSet_New());
    unsigned long n = 0;
    this->sampleVertices(n)[0].attributeSet = first;
    TQ3GeometryObject geometry = G::make(&this->sample());
    ASSERT_NE(geometry, nullptr);

    TQ3AttributeSet got = second;
    ASSERT_EQ(G::getSet(geometry, n - 1, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    ASSERT_EQ(G::getSet(geometry, 0, &got), kQ3Success);
    EXPECT_EQ(got, first);
    EXPECT_EQ(referenceCount(first), 3u); // the caller's, the geometry's, Get's
    Q3Object_Dispose(got);

    unsigned long edit = Q3Shared_GetEditIndex(geometry);
    EXPECT_EQ(G::setSet(geometry, 0, second), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(geometry), edit);
    EXPECT_EQ(referenceCount(first), 1u);
    EXPECT_EQ(G::setSet(geometry, n - 1, second), kQ3Success);
    EXPECT_EQ(G::setSet(geometry, n - 1, second), kQ3Success); // the same set again
    EXPECT_EQ(referenceCount(second), 3u);
    ASSERT_EQ(G::getSet(geometry, n - 1, &got), kQ3Success);
    EXPECT_EQ(got, second);
    Q3Object_Dispose(got);

    edit = Q3Shared_GetEditIndex(geometry);
    EXPECT_EQ(G::setSet(geometry, 0, nullptr), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(geometry), edit);
    ASSERT_EQ(G::getSet(geometry, 0, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    EXPECT_EQ(referenceCount(second), 2u);
    Q3Object_Dispose(geometry);
    EXPECT_EQ(referenceCount(second), 1u);
}

TYPED_TEST(VertexCallsContractTest, PerVertexCallsRejectBadHandlesPointersAndIndicesAndChangeNothing)
{
    using G = TypeParam;
    TQ3AttributeSet set = this->own(Q3AttributeSet_New());
    unsigned long n = 0;
    this->sampleVertices(n)[0].attributeSet = set;
    TQ3GeometryObject geometry = this->own(G::make(&this->sample()));
    ASSERT_NE(geometry, nullptr);
    const auto before = this->stateOf(geometry);

    for (unsigned long index : indicesPastTheEnd(n)) {
        TQ3AttributeSet got = set;
        EXPECT_Q3_ERROR(EXPECT_EQ(G::getSet(geometry, index, &got), kQ3Failure), kQ3ErrorParameterOutOfRange);
        EXPECT_EQ(got, set);
        EXPECT_Q3_ERROR(EXPECT_EQ(G::setSet(geometry, index, nullptr), kQ3Failure), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(EXPECT_EQ(G::setSet(geometry, index, set), kQ3Failure), kQ3ErrorParameterOutOfRange);
    }
    TQ3Point3D position{};
    TQ3AttributeSet got = nullptr;
    std::vector<std::pair<TQ3Object, TQ3Error>> wrongs = {{nullptr, kQ3ErrorNULLParameter},
                                                          {strayHandle(), kQ3ErrorInvalidObject}};
    for (TQ3Object wrong : this->wrongClass())
        wrongs.emplace_back(wrong, kQ3ErrorInvalidObjectType);
    // Made last: an object made after it could be given its address.
    TQ3GeometryObject dead = G::make(&this->sample());
    Q3Object_Dispose(dead);
    wrongs.emplace_back(dead, kQ3ErrorInvalidObject);
    for (const auto& [wrong, code] : wrongs) {
        EXPECT_Q3_ERROR(EXPECT_EQ(G::getPosition(wrong, 0, &position), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(G::setPosition(wrong, 0, &position), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(G::getSet(wrong, 0, &got), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(G::setSet(wrong, 0, set), kQ3Failure), code);
        // The handle comes before the pointer and the index.
        EXPECT_Q3_ERROR(G::getPosition(wrong, 7, nullptr), code);
    }
    EXPECT_Q3_ERROR(G::getPosition(geometry, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(G::getPosition(geometry, 9, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(G::setPosition(geometry, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(G::getSet(geometry, 0, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(G::getSet(geometry, 9, nullptr), kQ3ErrorNULLParameter);
    // The attribute set argument comes before the index.
    EXPECT_Q3_ERROR(EXPECT_EQ(G::setSet(geometry, 1, this->view()), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(G::setSet(geometry, 1, geometry), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(G::setSet(geometry, 5, strayHandle()), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(G::setSet(geometry, 1, deadObject()), kQ3Failure), kQ3ErrorInvalidObject);
    this->expectSameState(before, this->stateOf(geometry));
    EXPECT_EQ(referenceCount(set), 2u);
}

/// The box of a vertex array's points, each mapped by `map`.
template <class Map>
TQ3BoundingBox boxOf(const TQ3Vertex3D* vertices, unsigned long count, Map map)
{
    TQ3BoundingBox box{{1e9f, 1e9f, 1e9f}, {-1e9f, -1e9f, -1e9f}, kQ3False};
    for (unsigned long i = 0; i < count; ++i) {
        const TQ3Point3D p = map(vertices[i].point);
        box.min = {std::min(box.min.x, p.x), std::min(box.min.y, p.y), std::min(box.min.z, p.z)};
        box.max = {std::max(box.max.x, p.x), std::max(box.max.y, p.y), std::max(box.max.z, p.z)};
    }
    return box;
}

void expectSameBox(const TQ3BoundingBox& box, const TQ3BoundingBox& expected)
{
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_FLOAT_EQ(box.min.x, expected.min.x);
    EXPECT_FLOAT_EQ(box.min.y, expected.min.y);
    EXPECT_FLOAT_EQ(box.min.z, expected.min.z);
    EXPECT_FLOAT_EQ(box.max.x, expected.max.x);
    EXPECT_FLOAT_EQ(box.max.y, expected.max.y);
    EXPECT_FLOAT_EQ(box.max.z, expected.max.z);
}

TYPED_TEST(VertexCallsContractTest, ImmediateAndRetainedGeometriesBoundTheirTransformedVertices)
{
    using G = TypeParam;
    // Scale by (2, 1, -1), then translate by (10, 0, 1): world = (2x + 10, y, 1 - z).
    const TQ3Vector3D translate{10, 0, 1};
    const TQ3Vector3D scale{2, 1, -1};
    unsigned long n = 0;
    const TQ3Vertex3D* given = this->sampleVertices(n);
    const TQ3BoundingBox expected =
        boxOf(given, n, [](const TQ3Point3D& p) { return TQ3Point3D{2 * p.x + 10, p.y, 1 - p.z}; });
    TQ3GeometryObject geometry = this->own(G::make(&this->sample()));
    for (bool retained : {false, true}) {
        SCOPED_TRACE(retained ? "retained" : "immediate");
        const TQ3BoundingBox box = this->boundsOf([&](TQ3ViewObject v) {
            Q3TranslateTransform_Submit(&translate, v);
            Q3ScaleTransform_Submit(&scale, v);
            EXPECT_EQ(retained ? Q3Geometry_Submit(geometry, v) : G::submit(&this->sample(), v), kQ3Success);
        });
        expectSameBox(box, expected);
    }
}

TYPED_TEST(VertexCallsContractTest, AMovedVertexIsBoundedWhereItNowIs)
{
    using G = TypeParam;
    unsigned long n = 0;
    const TQ3Vertex3D* given = this->sampleVertices(n);
    TQ3GeometryObject geometry = this->own(G::make(&this->sample()));
    ASSERT_NE(geometry, nullptr);
    auto bounds = [&] {
        return this->boundsOf([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(geometry, v), kQ3Success); });
    };
    auto same = [](const TQ3Point3D& p) { return p; };
    expectSameBox(bounds(), boxOf(given, n, same));
    const TQ3Point3D far{20, -30, 40};
    ASSERT_EQ(G::setPosition(geometry, n - 1, &far), kQ3Success);
    std::vector<TQ3Vertex3D> moved(given, given + n);
    moved[n - 1].point = far;
    expectSameBox(bounds(), boxOf(moved.data(), n, same));
    const TQ3Point3D nan{kNaN, 0, 0};
    EXPECT_Q3_ERROR(G::setPosition(geometry, n - 1, &nan), kQ3ErrorInvalidData);
    expectSameBox(bounds(), boxOf(moved.data(), n, same)); // unchanged
}

// ---- Before Q3Initialize ---------------------------------------------------------------

// No Q3ApiTest here: the library is not initialized.
template <class G>
class NotInitializedContractTest : public ::testing::Test {};
TYPED_TEST_SUITE(NotInitializedContractTest, GeometryTypes, TypeName);

template <class G>
class VertexCallsNotInitializedContractTest : public ::testing::Test {};
TYPED_TEST_SUITE(VertexCallsNotInitializedContractTest, VertexGeometryTypes, TypeName);

TYPED_TEST(NotInitializedContractTest, EveryDataCallFailsWithNotInitialized)
{
    using G = TypeParam;
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    typename G::Data data{};
    auto failed = [] { return Q3Error_Get(nullptr) == kQ3ErrorNotInitialized; };
    EXPECT_EQ(G::make(&data), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(G::submit(&data, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(G::setData(nullptr, &data), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(G::getData(nullptr, &data), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(G::emptyData(&data), kQ3Failure);
    EXPECT_TRUE(failed());
}

TYPED_TEST(VertexCallsNotInitializedContractTest, EveryPerVertexCallFailsWithNotInitialized)
{
    using G = TypeParam;
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    TQ3Point3D position{};
    TQ3AttributeSet set = nullptr;
    auto failed = [] { return Q3Error_Get(nullptr) == kQ3ErrorNotInitialized; };
    EXPECT_EQ(G::getPosition(nullptr, 0, &position), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(G::setPosition(nullptr, 0, &position), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(G::getSet(nullptr, 0, &set), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(G::setSet(nullptr, 0, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
}

} // namespace
