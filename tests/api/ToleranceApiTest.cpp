// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Geometry QuickDraw 3D accepted though it is degenerate (docs/3dmf.md,
// "Tolerances"): each case is made, kept exactly as given and drawn without
// a crash or a value that is not finite, with the warning the table names
// (none for the polygonal cases, which QuickDraw 3D and Quesa take
// silently), through the API and through a text 3DMF file. The quadrics'
// cases are checked per type by QuadricApiTestSupport.h.

#include "FileTestSupport.h"
#include "OwningApiTest.h"
#include "RenderTestSupport.h"

#include "QD3DGeometry.h"

#include <cmath>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using namespace q3test;

class ToleranceApiTest : public OwningApiTest {
protected:
    /// GetData gives back all `count` vertices `object` was made of, as given
    /// (and says there are `count`, where the data counts them).
    template <class Data>
    static void expectVerticesKept(TQ3GeometryObject object, TQ3Status (*get)(TQ3GeometryObject, Data*),
                                   TQ3Status (*empty)(Data*), const TQ3Vertex3D* given, unsigned long count)
    {
        Data out{};
        ASSERT_EQ(get(object, &out), kQ3Success);
        if constexpr (!std::is_same_v<Data, TQ3TriangleData> && !std::is_same_v<Data, TQ3LineData>)
            EXPECT_EQ(out.numVertices, count);
        EXPECT_TRUE(sameVertices(out.vertices, given, count));
        empty(&out);
    }

    /// Draws `geometry` with `renderer` in the rendering tests' orthographic
    /// scene; the loop must finish. Returns the number of lit pixels.
    std::size_t litPixels(TQ3GeometryObject geometry, TQ3ObjectType renderer)
    {
        Pixmap image(100, 75);
        TestView drawing(image.pixmap(), renderer);
        EXPECT_EQ(drawing.render([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(geometry, v), kQ3Success); }),
                  kQ3ViewStatusDone);
        std::size_t lit = 0;
        for (unsigned long y = 0; y < image.height(); ++y)
            for (unsigned long x = 0; x < image.width(); ++x)
                lit += image.lit(x, y) ? 1 : 0;
        return lit;
    }

    static bool finite(const TQ3Point3D& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

    /// The geometry's bounds are finite (or empty), and what it decomposes
    /// into (when it is not a primitive itself) has finite points and finite
    /// vertex attributes: no NaN normal for a face with no area.
    void expectFiniteDrawing(TQ3GeometryObject geometry, const char* what)
    {
        const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) {
            EXPECT_EQ(Q3Geometry_Submit(geometry, v), kQ3Success) << what;
            TQ3GeometryObject result = Q3Geometry_GetDecomposed(geometry, v);
            if (result == nullptr)
                return;
            if (Q3Geometry_GetType(result) == kQ3GeometryTypeTriMesh) {
                TQ3TriMeshData mesh{};
                EXPECT_EQ(Q3TriMesh_GetData(result, &mesh), kQ3Success);
                for (unsigned long i = 0; i < mesh.numPoints; ++i)
                    EXPECT_TRUE(finite(mesh.points[i])) << what << ": point " << i;
                for (unsigned long a = 0; a < mesh.numVertexAttributeTypes; ++a) {
                    const TQ3TriMeshAttributeData& array = mesh.vertexAttributeTypes[a];
                    std::size_t floats = 0;
                    if (array.attributeType == kQ3AttributeTypeNormal ||
                        array.attributeType == kQ3AttributeTypeDiffuseColor ||
                        array.attributeType == kQ3AttributeTypeTransparencyColor)
                        floats = 3;
                    else if (array.attributeType == kQ3AttributeTypeSurfaceUV)
                        floats = 2;
                    const float* values = static_cast<const float*>(array.data);
                    for (std::size_t k = 0; k < floats * mesh.numPoints; ++k)
                        EXPECT_TRUE(std::isfinite(values[k])) << what << ": attribute " << array.attributeType;
                }
                Q3TriMesh_EmptyData(&mesh);
            } else {
                TQ3PolyLineData line{};
                EXPECT_EQ(Q3PolyLine_GetData(result, &line), kQ3Success);
                for (unsigned long i = 0; i < line.numVertices; ++i)
                    EXPECT_TRUE(finite(line.vertices[i].point)) << what << ": point " << i;
                Q3PolyLine_EmptyData(&line);
            }
            Q3Object_Dispose(result);
        });
        if (box.isEmpty == kQ3False) {
            EXPECT_TRUE(finite(box.min)) << what;
            EXPECT_TRUE(finite(box.max)) << what;
        }
    }
};

TEST_F(ToleranceApiTest, ATriangleWithNoAreaIsKeptSilentlyAndFillsNothing)
{
    const TQ3TriangleData cases[] = {
        {{{{0, 0, 0}, nullptr}, {{1, 0.5f, 0}, nullptr}, {{2, 1, 0}, nullptr}}, nullptr}, // collinear
        {{{{0, 0, 0}, nullptr}, {{0, 0, 0}, nullptr}, {{2, 1, 0}, nullptr}}, nullptr},    // two corners at one point
        {{{{1, 1, 0}, nullptr}, {{1, 1, 0}, nullptr}, {{1, 1, 0}, nullptr}}, nullptr},    // a point
    };
    for (const TQ3TriangleData& data : cases) {
        TQ3GeometryObject triangle = own(Q3Triangle_New(&data));
        ASSERT_NE(triangle, nullptr);
        expectVerticesKept(triangle, Q3Triangle_GetData, Q3Triangle_EmptyData, data.vertices, 3);
        EXPECT_EQ(litPixels(triangle, kQ3RendererTypeInteractive), 0u);
        litPixels(triangle, kQ3RendererTypeWireFrame);
        expectFiniteDrawing(triangle, "triangle");
    }
}

TEST_F(ToleranceApiTest, PolygonsWithRepeatedOrCollinearPointsAreKeptSilently)
{
    // A square with a corner given twice still fills the square.
    TQ3Vertex3D square[] = {{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{1, 0, 0}, nullptr},
                            {{1, 1, 0}, nullptr}, {{0, 1, 0}, nullptr}};
    const TQ3PolygonData repeated = {5, square, nullptr};
    TQ3GeometryObject polygon = own(Q3Polygon_New(&repeated));
    ASSERT_NE(polygon, nullptr);
    expectVerticesKept(polygon, Q3Polygon_GetData, Q3Polygon_EmptyData, square, 5);
    EXPECT_GT(litPixels(polygon, kQ3RendererTypeInteractive), 0u);
    expectFiniteDrawing(polygon, "polygon with a repeated corner");

    // Points on one line enclose nothing: no triangle, the outline only.
    TQ3Vertex3D line[] = {{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{2, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}};
    const TQ3PolygonData collinear = {4, line, nullptr};
    TQ3GeometryObject flat = own(Q3Polygon_New(&collinear));
    ASSERT_NE(flat, nullptr);
    EXPECT_EQ(litPixels(flat, kQ3RendererTypeInteractive), 0u);
    EXPECT_GT(litPixels(flat, kQ3RendererTypeWireFrame), 0u);
    expectFiniteDrawing(flat, "collinear polygon");

    // A general polygon whose contour is collinear, beside one that is not.
    TQ3Vertex3D hole[] = {{{0.2f, 0.5f, 0}, nullptr}, {{0.5f, 0.5f, 0}, nullptr}, {{0.8f, 0.5f, 0}, nullptr}};
    TQ3GeneralPolygonContourData contours[] = {{5, square}, {3, hole}};
    const TQ3GeneralPolygonData general = {2, contours, kQ3GeneralPolygonShapeHintComplex, nullptr};
    TQ3GeometryObject generalPolygon = own(Q3GeneralPolygon_New(&general));
    ASSERT_NE(generalPolygon, nullptr);
    EXPECT_GT(litPixels(generalPolygon, kQ3RendererTypeInteractive), 0u);
    expectFiniteDrawing(generalPolygon, "general polygon");
    TQ3GeneralPolygonContourData lineOnly[] = {{4, line}};
    const TQ3GeneralPolygonData flatGeneral = {1, lineOnly, kQ3GeneralPolygonShapeHintComplex, nullptr};
    TQ3GeometryObject flatGeneralPolygon = own(Q3GeneralPolygon_New(&flatGeneral));
    ASSERT_NE(flatGeneralPolygon, nullptr);
    EXPECT_EQ(litPixels(flatGeneralPolygon, kQ3RendererTypeInteractive), 0u);
    expectFiniteDrawing(flatGeneralPolygon, "collinear general polygon");
}

TEST_F(ToleranceApiTest, ALineWhoseEndsCoincideAndAPolyLineWithRepeatedPointsAreKeptSilently)
{
    const TQ3LineData point = {{{{1, 1, 0}, nullptr}, {{1, 1, 0}, nullptr}}, nullptr};
    TQ3GeometryObject line = own(Q3Line_New(&point));
    ASSERT_NE(line, nullptr);
    expectVerticesKept(line, Q3Line_GetData, Q3Line_EmptyData, point.vertices, 2);
    litPixels(line, kQ3RendererTypeWireFrame);
    litPixels(line, kQ3RendererTypeInteractive);
    expectFiniteDrawing(line, "line");

    TQ3Vertex3D vertices[] = {{{0, 0, 0}, nullptr}, {{0, 0, 0}, nullptr}, {{2, 1, 0}, nullptr},
                              {{2, 1, 0}, nullptr}, {{2, 1, 0}, nullptr}, {{3, 0, 0}, nullptr}};
    const TQ3PolyLineData data = {6, vertices, nullptr, nullptr};
    TQ3GeometryObject polyLine = own(Q3PolyLine_New(&data));
    ASSERT_NE(polyLine, nullptr);
    expectVerticesKept(polyLine, Q3PolyLine_GetData, Q3PolyLine_EmptyData, vertices, 6);
    EXPECT_GT(litPixels(polyLine, kQ3RendererTypeWireFrame), 0u);
    expectFiniteDrawing(polyLine, "polyline");
    // Every point the same: a polyline of no length.
    TQ3Vertex3D same[] = {{{1, 1, 0}, nullptr}, {{1, 1, 0}, nullptr}, {{1, 1, 0}, nullptr}};
    const TQ3PolyLineData still = {3, same, nullptr, nullptr};
    TQ3GeometryObject dot = own(Q3PolyLine_New(&still));
    ASSERT_NE(dot, nullptr);
    litPixels(dot, kQ3RendererTypeWireFrame);
    expectFiniteDrawing(dot, "polyline of one point");
}

TEST_F(ToleranceApiTest, TriMeshesWithRepeatedIndicesOrOddTopologyAreKeptSilently)
{
    TQ3Point3D points[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 0.5f, 1}, {0.5f, 0.5f, -1}};
    // A triangle naming a point twice, one naming one point three times,
    // three triangles on the edge 0-2 (not a manifold), an edge from a point
    // to itself, and a point no triangle uses.
    TQ3TriMeshTriangleData triangles[] = {{{0, 0, 1}}, {{3, 3, 3}}, {{0, 1, 2}}, {{0, 2, 4}}, {{2, 0, 5}},
                                          {{0, 2, 3}}};
    TQ3TriMeshEdgeData edges[] = {{{1, 1}, {0, 0}}};
    // No set, six triangles, one edge, six points, no attribute arrays.
    TQ3TriMeshData data{nullptr, 6, triangles, 0, nullptr, 1, edges, 0, nullptr, 6, points, 0, nullptr,
                        {{0, 0, -1}, {1, 1, 1}, kQ3False}};
    TQ3GeometryObject mesh = own(Q3TriMesh_New(&data));
    ASSERT_NE(mesh, nullptr);
    TQ3TriMeshData out{};
    ASSERT_EQ(Q3TriMesh_GetData(mesh, &out), kQ3Success);
    ASSERT_EQ(out.numTriangles, 6u);
    EXPECT_EQ(std::memcmp(out.triangles, triangles, sizeof triangles), 0);
    ASSERT_EQ(out.numEdges, 1u);
    EXPECT_EQ(std::memcmp(out.edges, edges, sizeof edges), 0);
    ASSERT_EQ(out.numPoints, 6u);
    EXPECT_EQ(std::memcmp(out.points, points, sizeof points), 0);
    Q3TriMesh_EmptyData(&out);
    EXPECT_GT(litPixels(mesh, kQ3RendererTypeInteractive), 0u);
    litPixels(mesh, kQ3RendererTypeWireFrame);
    expectFiniteDrawing(mesh, "trimesh");

    // A polyhedron with the same oddities.
    TQ3Vertex3D vertices[6];
    for (int i = 0; i < 6; ++i)
        vertices[i] = TQ3Vertex3D{points[i], nullptr};
    TQ3PolyhedronTriangleData faces[] = {{{0, 0, 1}, kQ3PolyhedronEdgeAll, nullptr},
                                         {{0, 1, 2}, kQ3PolyhedronEdgeAll, nullptr},
                                         {{0, 2, 4}, kQ3PolyhedronEdgeAll, nullptr},
                                         {{2, 0, 5}, kQ3PolyhedronEdgeAll, nullptr}};
    TQ3PolyhedronEdgeData sides[] = {{{2, 2}, {1, ~0ul}, nullptr}};
    const TQ3PolyhedronData polyhedronData = {6, vertices, 1, sides, 4, faces, nullptr};
    TQ3GeometryObject polyhedron = own(Q3Polyhedron_New(&polyhedronData));
    ASSERT_NE(polyhedron, nullptr);
    EXPECT_GT(litPixels(polyhedron, kQ3RendererTypeInteractive), 0u);
    litPixels(polyhedron, kQ3RendererTypeWireFrame);
    expectFiniteDrawing(polyhedron, "polyhedron");

    // A triangle grid whose rows all lie on one line.
    TQ3Vertex3D grid[] = {{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{2, 0, 0}, nullptr},
                          {{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}, {{2, 0, 0}, nullptr}};
    const TQ3TriGridData gridData = {2, 3, grid, nullptr, nullptr};
    TQ3GeometryObject triGrid = own(Q3TriGrid_New(&gridData));
    ASSERT_NE(triGrid, nullptr);
    EXPECT_EQ(litPixels(triGrid, kQ3RendererTypeInteractive), 0u);
    expectFiniteDrawing(triGrid, "triangle grid");
}

TEST_F(ToleranceApiTest, MeshFacesThatPassAVertexTwiceOrShareAnEdgeThreeWaysAreKeptSilently)
{
    TQ3GeometryObject mesh = own(Q3Mesh_New());
    TQ3MeshVertex v[6];
    const TQ3Point3D at[6] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 0.5f, 1}, {2, 0, 0}};
    for (int i = 0; i < 6; ++i) {
        const TQ3Vertex3D vertex = {at[i], nullptr};
        v[i] = Q3Mesh_VertexNew(mesh, &vertex);
        ASSERT_NE(v[i], nullptr);
    }
    // A face through vertex 1 twice (a bow tie), one that comes back along
    // itself (no area), and three faces on the edge 0-2.
    const TQ3MeshVertex bowTie[5] = {v[0], v[1], v[5], v[1], v[3]};
    const TQ3MeshVertex back[3] = {v[0], v[1], v[0]};
    const TQ3MeshVertex fan[3][3] = {{v[0], v[2], v[3]}, {v[2], v[0], v[4]}, {v[0], v[2], v[1]}};
    TQ3MeshFace twice = Q3Mesh_FaceNew(mesh, 5, bowTie, nullptr);
    ASSERT_NE(twice, nullptr);
    ASSERT_NE(Q3Mesh_FaceNew(mesh, 3, back, nullptr), nullptr);
    for (const auto& face : fan)
        ASSERT_NE(Q3Mesh_FaceNew(mesh, 3, face, nullptr), nullptr);
    unsigned long faces = 0, vertices = 0;
    ASSERT_EQ(Q3Mesh_GetNumFaces(mesh, &faces), kQ3Success);
    EXPECT_EQ(faces, 5u);
    ASSERT_EQ(Q3Mesh_GetFaceNumVertices(mesh, twice, &vertices), kQ3Success);
    EXPECT_EQ(vertices, 4u) << "the count and the walk give each vertex of a face once";
    EXPECT_GT(litPixels(mesh, kQ3RendererTypeInteractive), 0u);
    litPixels(mesh, kQ3RendererTypeWireFrame);
    expectFiniteDrawing(mesh, "mesh");
    // Deleting the twice-passed vertex deletes its faces once each.
    ASSERT_EQ(Q3Mesh_VertexDelete(mesh, v[1]), kQ3Success);
    ASSERT_EQ(Q3Mesh_GetNumFaces(mesh, &faces), kQ3Success);
    EXPECT_EQ(faces, 2u);
    expectFiniteDrawing(mesh, "mesh after the delete");

    // The same bow tie from a text file.
    const std::vector<TQ3Object> objects = readAll(bytesOf("3DMetafile ( 1 6 Stream )\n"
                                                           "Mesh ( 4  0 0 0  1 0 0  2 0 0  0 1 0\n"
                                                           "       1 0  5 0 1 2 1 3 )\n"));
    ASSERT_EQ(objects.size(), 1u);
    ASSERT_EQ(Q3Mesh_GetNumFaces(objects[0], &faces), kQ3Success);
    EXPECT_EQ(faces, 1u);
    expectFiniteDrawing(objects[0], "read mesh");
    disposeAll(objects);
}

TEST_F(ToleranceApiTest, ADegenerateQuadricInATextFileReadsWithTheWarning)
{
    // An ellipsoid with a zero minor radius and a box whose axes lie in one
    // plane, as Apple-era files hold them, between two valid objects.
    const std::string text = "3DMetafile ( 1 6 Stream )\n"
                             "Point ( 0 0 0 )\n"
                             "Ellipsoid ( 0 0 1  1 0 0  0 0 0  0 0 0  0 1 0 1 )\n"
                             "Box ( 0 0 1  1 0 0  1 0 1  0 0 0 )\n"
                             "Point ( 1 1 1 )\n";
    std::vector<TQ3Object> objects;
    // One warning for each of the two.
    EXPECT_Q3_WARNING(objects = readAll(bytesOf(text)), kQ3WarningInconsistentData);
    EXPECT_Q3_WARNING(EXPECT_EQ(objects.size(), 4u), kQ3WarningInconsistentData);
    ASSERT_EQ(objects.size(), 4u);
    ASSERT_EQ(Q3Object_GetLeafType(objects[1]), kQ3GeometryTypeEllipsoid);
    TQ3EllipsoidData ellipsoid{};
    ASSERT_EQ(Q3Ellipsoid_GetData(objects[1], &ellipsoid), kQ3Success);
    EXPECT_EQ(ellipsoid.minorRadius.x, 0.0f);
    EXPECT_EQ(ellipsoid.minorRadius.y, 0.0f);
    EXPECT_EQ(ellipsoid.minorRadius.z, 0.0f);
    EXPECT_EQ(ellipsoid.majorRadius.x, 1.0f);
    EXPECT_EQ(ellipsoid.vMax, 1.0f);
    Q3Ellipsoid_EmptyData(&ellipsoid);
    ASSERT_EQ(Q3Object_GetLeafType(objects[2]), kQ3GeometryTypeBox);
    TQ3BoxData box{};
    ASSERT_EQ(Q3Box_GetData(objects[2], &box), kQ3Success);
    EXPECT_EQ(box.minorAxis.x, 1.0f);
    EXPECT_EQ(box.minorAxis.z, 1.0f);
    Q3Box_EmptyData(&box);
    for (TQ3Object object : {objects[1], objects[2]}) {
        EXPECT_EQ(litPixels(object, kQ3RendererTypeInteractive), 0u);
        expectFiniteDrawing(object, "read quadric");
    }
    disposeAll(objects);
}

TEST_F(ToleranceApiTest, ADegenerateQuadricIsWrittenAsItIsAndReadsBackWithTheWarning)
{
    // A cone whose orientation lies in its base's plane, in text and in both
    // binary byte orders.
    TQ3ConeData data{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 0.5f, 0}, 0, 1, 0, 1, kQ3EndCapNone,
                     nullptr, nullptr, nullptr, nullptr};
    TQ3GeometryObject cone = nullptr;
    EXPECT_Q3_WARNING(cone = own(Q3Cone_New(&data)), kQ3WarningInconsistentData);
    ASSERT_NE(cone, nullptr);
    for (TQ3FileMode mode : {TQ3FileMode(kQ3FileModeText), TQ3FileMode(kQ3FileModeNormal),
                             TQ3FileMode(kQ3FileModeSwap)}) {
        const std::vector<unsigned char> bytes = writeObjects({cone}, mode);
        std::vector<TQ3Object> objects;
        EXPECT_Q3_WARNING(objects = readAll(bytes), kQ3WarningInconsistentData);
        ASSERT_EQ(objects.size(), 1u) << mode;
        TQ3ConeData out{};
        ASSERT_EQ(Q3Cone_GetData(objects[0], &out), kQ3Success);
        EXPECT_EQ(std::memcmp(&out, &data, sizeof data), 0) << mode;
        Q3Cone_EmptyData(&out);
        disposeAll(objects);
    }
}

TEST_F(ToleranceApiTest, DegeneratePolygonalGeometryInATextFileReadsSilently)
{
    const std::string text = "3DMetafile ( 1 6 Stream )\n"
                             "Triangle ( 0 0 0  1 0.5 0  2 1 0 )\n"
                             "Line ( 1 1 0  1 1 0 )\n"
                             "PolyLine ( 3  0 0 0  0 0 0  1 1 0 )\n"
                             "TriMesh ( 2 0 0 0 3 0\n"
                             "  0 0 1  0 1 2\n"
                             "  0 0 0  1 0 0  1 1 0\n"
                             "  0 0 0  1 1 0  0 )\n";
    const std::vector<TQ3Object> objects = readAll(bytesOf(text));
    ASSERT_EQ(objects.size(), 4u);
    TQ3TriMeshData mesh{};
    ASSERT_EQ(Q3TriMesh_GetData(objects[3], &mesh), kQ3Success);
    ASSERT_EQ(mesh.numTriangles, 2u);
    EXPECT_EQ(mesh.triangles[0].pointIndices[0], 0u);
    EXPECT_EQ(mesh.triangles[0].pointIndices[1], 0u);
    EXPECT_EQ(mesh.triangles[0].pointIndices[2], 1u);
    Q3TriMesh_EmptyData(&mesh);
    for (TQ3Object object : objects) {
        litPixels(object, kQ3RendererTypeInteractive);
        expectFiniteDrawing(object, "read geometry");
    }
    disposeAll(objects);
}

TEST_F(ToleranceApiTest, MalformedDataStaysAnError)
{
    // Structure, not degeneracy: an index past the points, too few points,
    // a coordinate that is not finite.
    TQ3Point3D points[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    TQ3TriMeshTriangleData triangles[] = {{{0, 1, 3}}};
    TQ3TriMeshData mesh{};
    mesh.numTriangles = 1;
    mesh.triangles = triangles;
    mesh.numPoints = 3;
    mesh.points = points;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3TriMesh_New(&mesh), nullptr), kQ3ErrorInvalidData);
    TQ3Vertex3D two[] = {{{0, 0, 0}, nullptr}, {{1, 0, 0}, nullptr}};
    const TQ3PolygonData polygon = {2, two, nullptr};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Polygon_New(&polygon), nullptr), kQ3ErrorGeometryInsufficientNumberOfPoints);
    const TQ3TriangleData nan = {
        {{{0, 0, 0}, nullptr}, {{std::nanf(""), 0, 0}, nullptr}, {{0, 1, 0}, nullptr}}, nullptr};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Triangle_New(&nan), nullptr), kQ3ErrorInvalidData);
    EXPECT_READ_ERROR(bytesOf("3DMetafile ( 1 6 Stream )\nEllipsoid ( 0 0 1  1 0 0  0 1 0  0 0 0  0 1 0 2 )\n"),
                      kQ3ErrorInvalidMetafileObject);
}

} // namespace
