// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The 3DMF forms of the geometries with nested parts (NURB patches with trim
// loops, ...): written and read back in every encoding and mode (data
// compared field by field, both objects rendered to the same image), read
// from hand-written files in text and in both byte orders, and malformed
// variants refused with a file error.

#include "FileTestSupport.h"
#include "Q3ApiTest.h"
#include "RenderTestSupport.h"

#include "QD3DCamera.h"
#include "QD3DGeometry.h"
#include "QD3DSet.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <string>

using namespace q3test;

namespace {

std::vector<unsigned char> dataFile(const char* name)
{
    std::ifstream in(std::string(Q3_TEST_DATA_DIR) + "/" + name, std::ios::binary);
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TQ3AttributeSet colorSet(float r, float g, float b)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB color = {r, g, b};
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color);
    return set;
}

template <class T>
bool sameBytes(const T* a, const T* b, unsigned long n)
{
    return n == 0 || std::memcmp(a, b, n * sizeof(T)) == 0;
}

// ---- NURB patch -------------------------------------------------------------

// The patch of tests/data/nurbpatch*.3dmf, built through the API: 3 rows of
// 4 points (one of weight 2, pre-multiplied), a kept square and a triangular
// hole of two curves, one of them rational.
TQ3Object makePatch(bool withTrims, bool withSet)
{
    static TQ3RationalPoint4D points[12] = {
        {-1.5f, -1, 0, 1}, {-0.5f, -1, 0.5f, 1}, {0.5f, -1, 0.5f, 1}, {1.5f, -1, 0, 1},
        {-1.5f, 0, 0.5f, 1}, {-1, 0, 2, 2}, {0.5f, 0, 1, 1}, {1.5f, 0, 0.5f, 1},
        {-1.5f, 1, 0, 1}, {-0.5f, 1, 0.5f, 1}, {0.5f, 1, 0.5f, 1}, {1.5f, 1, 0, 1}};
    static float uKnots[7] = {0, 0, 0, 0.5f, 1, 1, 1};
    static float vKnots[6] = {0, 0, 0, 1, 1, 1};
    static TQ3RationalPoint3D square[5] = {
        {0.1f, 0.1f, 1}, {0.9f, 0.1f, 1}, {0.9f, 0.9f, 1}, {0.1f, 0.9f, 1}, {0.1f, 0.1f, 1}};
    static float squareKnots[7] = {0, 0, 1, 2, 3, 4, 4};
    static TQ3RationalPoint3D holeA[3] = {{0.4f, 0.4f, 1}, {0.4f, 0.6f, 1}, {0.6f, 0.6f, 1}};
    static float holeAKnots[5] = {0, 0, 1, 2, 2};
    static TQ3RationalPoint3D holeB[3] = {{0.6f, 0.6f, 1}, {1.2f, 0.8f, 2}, {0.4f, 0.4f, 1}};
    static float holeBKnots[6] = {0, 0, 0, 1, 1, 1};
    static TQ3NURBPatchTrimCurveData outer[1] = {{2, 5, square, squareKnots}};
    static TQ3NURBPatchTrimCurveData hole[2] = {{2, 3, holeA, holeAKnots}, {3, 3, holeB, holeBKnots}};
    static TQ3NURBPatchTrimLoopData loops[2] = {{1, outer}, {2, hole}};
    TQ3NURBPatchData d{};
    d.uOrder = 3;
    d.vOrder = 3;
    d.numRows = 3;
    d.numColumns = 4;
    d.controlPoints = points;
    d.uKnots = uKnots;
    d.vKnots = vKnots;
    d.numTrimLoops = withTrims ? 2 : 0;
    d.trimLoops = withTrims ? loops : nullptr;
    d.patchAttributeSet = withSet ? colorSet(0.2f, 0.6f, 0.9f) : nullptr;
    TQ3Object o = Q3NURBPatch_New(&d);
    if (d.patchAttributeSet != nullptr)
        Q3Object_Dispose(d.patchAttributeSet);
    return o;
}

bool samePatch(TQ3Object a, TQ3Object b)
{
    TQ3NURBPatchData da{}, db{};
    if (Q3NURBPatch_GetData(a, &da) != kQ3Success || Q3NURBPatch_GetData(b, &db) != kQ3Success)
        return false;
    bool same = da.uOrder == db.uOrder && da.vOrder == db.vOrder && da.numRows == db.numRows &&
                da.numColumns == db.numColumns && da.numTrimLoops == db.numTrimLoops &&
                sameBytes(da.controlPoints, db.controlPoints, da.numRows * da.numColumns) &&
                sameBytes(da.uKnots, db.uKnots, da.uOrder + da.numColumns) &&
                sameBytes(da.vKnots, db.vKnots, da.vOrder + da.numRows) &&
                sameSet(da.patchAttributeSet, db.patchAttributeSet);
    for (unsigned long l = 0; same && l < da.numTrimLoops; ++l) {
        const TQ3NURBPatchTrimLoopData& la = da.trimLoops[l];
        const TQ3NURBPatchTrimLoopData& lb = db.trimLoops[l];
        same = la.numTrimCurves == lb.numTrimCurves;
        for (unsigned long c = 0; same && c < la.numTrimCurves; ++c) {
            const TQ3NURBPatchTrimCurveData& ca = la.trimCurves[c];
            const TQ3NURBPatchTrimCurveData& cb = lb.trimCurves[c];
            same = ca.order == cb.order && ca.numPoints == cb.numPoints &&
                   sameBytes(ca.controlPoints, cb.controlPoints, ca.numPoints) &&
                   sameBytes(ca.knots, cb.knots, ca.order + ca.numPoints);
        }
    }
    Q3NURBPatch_EmptyData(&da);
    Q3NURBPatch_EmptyData(&db);
    return same;
}


// ---- Mesh ---------------------------------------------------------------------

// A square face with a square hole and a triangle beside it: a vertex set, a
// face set, a corner set and the mesh's own set.
TQ3Object makeMesh()
{
    const TQ3Point3D points[9] = {{-2, -1, 0},      {0, -1, 0},      {0, 1, 0},         {-2, 1, 0},     {-1.5f, -0.5f, 0},
                                  {-0.5f, -0.5f, 0}, {-0.5f, 0.5f, 0}, {-1.5f, 0.5f, 0}, {1.5f, 0, 0.5f}};
    TQ3GeometryObject mesh = Q3Mesh_New();
    TQ3AttributeSet red = colorSet(1, 0, 0), green = colorSet(0, 1, 0), blue = colorSet(0, 0, 1);
    TQ3MeshVertex v[9];
    for (int i = 0; i < 9; ++i) {
        const TQ3Vertex3D vertex = {points[i], i == 2 ? red : nullptr};
        v[i] = Q3Mesh_VertexNew(mesh, &vertex);
    }
    const TQ3MeshVertex outer[4] = {v[0], v[1], v[2], v[3]};
    const TQ3MeshVertex inner[4] = {v[4], v[7], v[6], v[5]};
    const TQ3MeshVertex side[3] = {v[1], v[8], v[2]};
    TQ3MeshFace square = Q3Mesh_FaceNew(mesh, 4, outer, nullptr);
    TQ3MeshFace hole = Q3Mesh_FaceNew(mesh, 4, inner, nullptr);
    Q3Mesh_FaceToContour(mesh, square, hole);
    TQ3MeshFace triangle = Q3Mesh_FaceNew(mesh, 3, side, green);
    Q3Mesh_SetCornerAttributeSet(mesh, v[1], triangle, blue);
    Q3Mesh_SetCornerAttributeSet(mesh, v[1], square, blue);
    TQ3AttributeSet own = colorSet(0.8f, 0.8f, 0.2f);
    Q3Geometry_SetAttributeSet(mesh, own);
    Q3Object_Dispose(own);
    Q3Object_Dispose(red);
    Q3Object_Dispose(green);
    Q3Object_Dispose(blue);
    return mesh;
}

// Vertices, faces, contours, corners and sets, in the order the meshes walk.
bool sameMesh(TQ3Object a, TQ3Object b)
{
    unsigned long na = 0, nb = 0, fa = 0, fb = 0;
    if (Q3Mesh_GetNumVertices(a, &na) != kQ3Success || Q3Mesh_GetNumVertices(b, &nb) != kQ3Success || na != nb)
        return false;
    if (Q3Mesh_GetNumFaces(a, &fa) != kQ3Success || Q3Mesh_GetNumFaces(b, &fb) != kQ3Success || fa != fb)
        return false;
    bool same = true;
    const auto sameHeld = [&](TQ3AttributeSet x, TQ3AttributeSet y) {
        same = same && sameSet(x, y);
        if (x != nullptr)
            Q3Object_Dispose(x);
        if (y != nullptr)
            Q3Object_Dispose(y);
    };
    TQ3MeshIterator ia, ib;
    for (TQ3MeshVertex va = Q3Mesh_FirstMeshVertex(a, &ia), vb = Q3Mesh_FirstMeshVertex(b, &ib);
         va != nullptr && vb != nullptr; va = Q3Mesh_NextMeshVertex(&ia), vb = Q3Mesh_NextMeshVertex(&ib)) {
        TQ3Point3D pa, pb;
        Q3Mesh_GetVertexCoordinates(a, va, &pa);
        Q3Mesh_GetVertexCoordinates(b, vb, &pb);
        same = same && samePoint(pa, pb);
        TQ3AttributeSet sa = nullptr, sb = nullptr;
        Q3Mesh_GetVertexAttributeSet(a, va, &sa);
        Q3Mesh_GetVertexAttributeSet(b, vb, &sb);
        sameHeld(sa, sb);
    }
    for (TQ3MeshFace xa = Q3Mesh_FirstMeshFace(a, &ia), xb = Q3Mesh_FirstMeshFace(b, &ib);
         xa != nullptr && xb != nullptr; xa = Q3Mesh_NextMeshFace(&ia), xb = Q3Mesh_NextMeshFace(&ib)) {
        TQ3AttributeSet sa = nullptr, sb = nullptr;
        Q3Mesh_GetFaceAttributeSet(a, xa, &sa);
        Q3Mesh_GetFaceAttributeSet(b, xb, &sb);
        sameHeld(sa, sb);
        unsigned long ca = 0, cb = 0;
        Q3Mesh_GetFaceNumContours(a, xa, &ca);
        Q3Mesh_GetFaceNumContours(b, xb, &cb);
        same = same && ca == cb;
        TQ3MeshIterator ja, jb;
        for (TQ3MeshContour ka = Q3Mesh_FirstFaceContour(xa, &ja), kb = Q3Mesh_FirstFaceContour(xb, &jb);
             ka != nullptr && kb != nullptr; ka = Q3Mesh_NextFaceContour(&ja), kb = Q3Mesh_NextFaceContour(&jb)) {
            TQ3MeshIterator la, lb;
            TQ3MeshVertex va = Q3Mesh_FirstContourVertex(ka, &la), vb = Q3Mesh_FirstContourVertex(kb, &lb);
            for (; va != nullptr && vb != nullptr;
                 va = Q3Mesh_NextContourVertex(&la), vb = Q3Mesh_NextContourVertex(&lb)) {
                unsigned long index_a = 0, index_b = 1;
                Q3Mesh_GetVertexIndex(a, va, &index_a);
                Q3Mesh_GetVertexIndex(b, vb, &index_b);
                same = same && index_a == index_b;
                TQ3AttributeSet corner_a = nullptr, corner_b = nullptr;
                Q3Mesh_GetCornerAttributeSet(a, va, xa, &corner_a);
                Q3Mesh_GetCornerAttributeSet(b, vb, xb, &corner_b);
                sameHeld(corner_a, corner_b);
            }
            same = same && va == nullptr && vb == nullptr;
        }
    }
    TQ3AttributeSet sa = nullptr, sb = nullptr;
    Q3Geometry_GetAttributeSet(a, &sa);
    Q3Geometry_GetAttributeSet(b, &sb);
    sameHeld(sa, sb);
    return same;
}

// ---- general polygon, triangle grid, polyhedron, marker ----------------------------

TQ3Object makeGeneralPolygon()
{
    TQ3AttributeSet red = colorSet(1, 0, 0);
    TQ3Vertex3D outer[4] = {{{-2, -1.5f, 0}, red}, {{2, -1.5f, 0}, nullptr}, {{2, 1.5f, 0}, nullptr},
                            {{-2, 1.5f, 0}, nullptr}};
    TQ3Vertex3D hole[3] = {{{-0.5f, -0.5f, 0}, nullptr}, {{0, 0.75f, 0}, red}, {{0.5f, -0.5f, 0}, nullptr}};
    TQ3GeneralPolygonContourData contours[2] = {{4, outer}, {3, hole}};
    TQ3GeneralPolygonData d = {2, contours, kQ3GeneralPolygonShapeHintConcave, colorSet(0.3f, 0.5f, 1)};
    TQ3Object o = Q3GeneralPolygon_New(&d);
    Q3Object_Dispose(d.generalPolygonAttributeSet);
    Q3Object_Dispose(red);
    return o;
}

bool sameGeneralPolygon(TQ3Object a, TQ3Object b)
{
    TQ3GeneralPolygonData da{}, db{};
    if (Q3GeneralPolygon_GetData(a, &da) != kQ3Success || Q3GeneralPolygon_GetData(b, &db) != kQ3Success)
        return false;
    bool same = da.numContours == db.numContours && da.shapeHint == db.shapeHint &&
                sameSet(da.generalPolygonAttributeSet, db.generalPolygonAttributeSet);
    for (unsigned long c = 0; same && c < da.numContours; ++c)
        same = da.contours[c].numVertices == db.contours[c].numVertices &&
               sameVertices(da.contours[c].vertices, db.contours[c].vertices, da.contours[c].numVertices);
    Q3GeneralPolygon_EmptyData(&da);
    Q3GeneralPolygon_EmptyData(&db);
    return same;
}

TQ3Object makeTriGrid()
{
    TQ3AttributeSet red = colorSet(1, 0, 0), green = colorSet(0, 1, 0);
    TQ3Vertex3D v[6] = {{{-2, -1, 0}, nullptr}, {{0, -1, 0.5f}, red}, {{2, -1, 0}, nullptr},
                        {{-2, 1, 0}, nullptr},  {{0, 1, 0.5f}, nullptr}, {{2, 1, 0}, nullptr}};
    TQ3AttributeSet facets[4] = {nullptr, green, nullptr, nullptr};
    TQ3TriGridData d = {2, 3, v, facets, colorSet(0.9f, 0.9f, 0.9f)};
    TQ3Object o = Q3TriGrid_New(&d);
    Q3Object_Dispose(d.triGridAttributeSet);
    Q3Object_Dispose(red);
    Q3Object_Dispose(green);
    return o;
}

bool sameTriGrid(TQ3Object a, TQ3Object b)
{
    TQ3TriGridData da{}, db{};
    if (Q3TriGrid_GetData(a, &da) != kQ3Success || Q3TriGrid_GetData(b, &db) != kQ3Success)
        return false;
    bool same = da.numRows == db.numRows && da.numColumns == db.numColumns &&
                sameVertices(da.vertices, db.vertices, da.numRows * da.numColumns) &&
                sameSet(da.triGridAttributeSet, db.triGridAttributeSet) &&
                (da.facetAttributeSet == nullptr) == (db.facetAttributeSet == nullptr);
    for (unsigned long i = 0; same && da.facetAttributeSet != nullptr && i < 2 * (da.numRows - 1) * (da.numColumns - 1);
         ++i)
        same = sameSet(da.facetAttributeSet[i], db.facetAttributeSet[i]);
    Q3TriGrid_EmptyData(&da);
    Q3TriGrid_EmptyData(&db);
    return same;
}

// A tetrahedron with its edges listed (one edge on the boundary of no
// second triangle would be kQ3ArrayIndexNULL; here every edge has two).
TQ3Object makePolyhedron()
{
    TQ3AttributeSet red = colorSet(1, 0, 0), blue = colorSet(0, 0, 1);
    TQ3Vertex3D v[4] = {{{-1.5f, -1, -1}, nullptr}, {{1.5f, -1, -1}, red}, {{0, -1, 1.5f}, nullptr},
                        {{0, 1.5f, 0}, nullptr}};
    TQ3PolyhedronTriangleData t[4] = {{{0, 2, 1}, kQ3PolyhedronEdgeAll, nullptr},
                                      {{0, 1, 3}, kQ3PolyhedronEdge01 | kQ3PolyhedronEdge12, blue},
                                      {{1, 2, 3}, kQ3PolyhedronEdgeAll, nullptr},
                                      {{2, 0, 3}, kQ3PolyhedronEdge20, nullptr}};
    TQ3AttributeSet cyan = colorSet(0, 1, 1);
    TQ3PolyhedronEdgeData e[2] = {{{0, 1}, {0, 1}, nullptr}, {{1, 3}, {1, 2}, cyan}};
    TQ3PolyhedronData d = {4, v, 2, e, 4, t, nullptr};
    TQ3Object o = Q3Polyhedron_New(&d);
    Q3Object_Dispose(red);
    Q3Object_Dispose(blue);
    Q3Object_Dispose(cyan);
    return o;
}

bool samePolyhedron(TQ3Object a, TQ3Object b)
{
    TQ3PolyhedronData da{}, db{};
    if (Q3Polyhedron_GetData(a, &da) != kQ3Success || Q3Polyhedron_GetData(b, &db) != kQ3Success)
        return false;
    bool same = da.numVertices == db.numVertices && da.numTriangles == db.numTriangles &&
                da.numEdges == db.numEdges && sameVertices(da.vertices, db.vertices, da.numVertices) &&
                sameSet(da.polyhedronAttributeSet, db.polyhedronAttributeSet);
    for (unsigned long i = 0; same && i < da.numTriangles; ++i)
        same = std::memcmp(da.triangles[i].vertexIndices, db.triangles[i].vertexIndices,
                           sizeof da.triangles[i].vertexIndices) == 0 &&
               da.triangles[i].edgeFlag == db.triangles[i].edgeFlag &&
               sameSet(da.triangles[i].triangleAttributeSet, db.triangles[i].triangleAttributeSet);
    for (unsigned long i = 0; same && i < da.numEdges; ++i)
        same = std::memcmp(da.edges[i].vertexIndices, db.edges[i].vertexIndices, sizeof da.edges[i].vertexIndices) ==
                   0 &&
               std::memcmp(da.edges[i].triangleIndices, db.edges[i].triangleIndices,
                           sizeof da.edges[i].triangleIndices) == 0 &&
               sameSet(da.edges[i].edgeAttributeSet, db.edges[i].edgeAttributeSet);
    Q3Polyhedron_EmptyData(&da);
    Q3Polyhedron_EmptyData(&db);
    return same;
}

// A 10 x 5 arrow, 2 bytes a row (6 bits of padding), least significant bit
// first: the padding and the bit order both have to survive.
TQ3Object makeMarker()
{
    static unsigned char image[10] = {0x01, 0x00, 0x03, 0x00, 0xFF, 0x03, 0x03, 0x00, 0x01, 0x00};
    TQ3MarkerData d{};
    d.location = {0.5f, -0.25f, 0};
    d.xOffset = -3;
    d.yOffset = 2;
    d.bitmap = {image, 10, 5, 2, kQ3EndianLittle};
    d.markerAttributeSet = colorSet(1, 1, 0);
    TQ3Object o = Q3Marker_New(&d);
    Q3Object_Dispose(d.markerAttributeSet);
    return o;
}

bool sameMarker(TQ3Object a, TQ3Object b)
{
    TQ3MarkerData da{}, db{};
    if (Q3Marker_GetData(a, &da) != kQ3Success || Q3Marker_GetData(b, &db) != kQ3Success)
        return false;
    const bool same = samePoint(da.location, db.location) && da.xOffset == db.xOffset && da.yOffset == db.yOffset &&
                      da.bitmap.width == db.bitmap.width && da.bitmap.height == db.bitmap.height &&
                      da.bitmap.rowBytes == db.bitmap.rowBytes && da.bitmap.bitOrder == db.bitmap.bitOrder &&
                      sameBytes(da.bitmap.image, db.bitmap.image, da.bitmap.height * da.bitmap.rowBytes) &&
                      sameSet(da.markerAttributeSet, db.markerAttributeSet);
    Q3Marker_EmptyData(&da);
    Q3Marker_EmptyData(&db);
    return same;
}

// ---- the parts' sets of boxes, quadrics and polylines -----------------------------

TQ3Object makeBoxWithFaces()
{
    TQ3AttributeSet faces[6] = {colorSet(1, 0, 0), nullptr, colorSet(0, 1, 0), nullptr, nullptr, colorSet(0, 0, 1)};
    TQ3BoxData d = {{-1, -1, -1}, {0, 2, 0}, {2, 0, 0}, {0, 0, 1.5f}, faces, nullptr};
    TQ3Object o = Q3Box_New(&d);
    for (TQ3AttributeSet set : faces)
        if (set != nullptr)
            Q3Object_Dispose(set);
    return o;
}

bool sameBox(TQ3Object a, TQ3Object b)
{
    TQ3BoxData da{}, db{};
    if (Q3Box_GetData(a, &da) != kQ3Success || Q3Box_GetData(b, &db) != kQ3Success)
        return false;
    bool same = samePoint(da.origin, db.origin) && sameSet(da.boxAttributeSet, db.boxAttributeSet) &&
                (da.faceAttributeSet == nullptr) == (db.faceAttributeSet == nullptr);
    for (int i = 0; same && da.faceAttributeSet != nullptr && i < 6; ++i)
        same = sameSet(da.faceAttributeSet[i], db.faceAttributeSet[i]);
    Q3Box_EmptyData(&da);
    Q3Box_EmptyData(&db);
    return same;
}

// The frame the cylinder and the cone share: radius 1 about +y from y = -1
// to 1, a quarter of the way round cut away.
template <class QuadricData>
void setUprightQuarterCut(QuadricData& d)
{
    d.origin = {0, -1, 0};
    d.orientation = {0, 2, 0};
    d.majorRadius = {1, 0, 0};
    d.minorRadius = {0, 0, 1};
    d.uMax = 0.75f;
    d.vMax = 1;
}

TQ3Object makeCylinderWithCaps()
{
    TQ3CylinderData d{};
    setUprightQuarterCut(d);
    d.caps = kQ3EndCapMaskTop | kQ3EndCapMaskBottom | kQ3EndCapMaskInterior;
    d.topAttributeSet = colorSet(1, 0, 0);
    d.bottomAttributeSet = colorSet(0, 1, 0);
    d.faceAttributeSet = colorSet(0, 0, 1);
    d.interiorAttributeSet = colorSet(1, 1, 0);
    TQ3Object o = Q3Cylinder_New(&d);
    for (TQ3AttributeSet set : {d.topAttributeSet, d.bottomAttributeSet, d.faceAttributeSet, d.interiorAttributeSet})
        Q3Object_Dispose(set);
    return o;
}

bool sameCylinder(TQ3Object a, TQ3Object b)
{
    TQ3CylinderData da{}, db{};
    if (Q3Cylinder_GetData(a, &da) != kQ3Success || Q3Cylinder_GetData(b, &db) != kQ3Success)
        return false;
    const bool same = samePoint(da.origin, db.origin) && da.caps == db.caps && da.uMax == db.uMax &&
                      sameSet(da.topAttributeSet, db.topAttributeSet) &&
                      sameSet(da.bottomAttributeSet, db.bottomAttributeSet) &&
                      sameSet(da.faceAttributeSet, db.faceAttributeSet) &&
                      sameSet(da.interiorAttributeSet, db.interiorAttributeSet) &&
                      sameSet(da.cylinderAttributeSet, db.cylinderAttributeSet);
    Q3Cylinder_EmptyData(&da);
    Q3Cylinder_EmptyData(&db);
    return same;
}

TQ3Object makeConeWithCaps()
{
    TQ3ConeData d{};
    setUprightQuarterCut(d);
    d.caps = kQ3EndCapMaskBottom | kQ3EndCapMaskInterior;
    d.bottomAttributeSet = colorSet(0, 1, 0);
    d.faceAttributeSet = colorSet(0, 0, 1);
    d.interiorAttributeSet = colorSet(1, 1, 0);
    TQ3Object o = Q3Cone_New(&d);
    for (TQ3AttributeSet set : {d.bottomAttributeSet, d.faceAttributeSet, d.interiorAttributeSet})
        Q3Object_Dispose(set);
    return o;
}

bool sameCone(TQ3Object a, TQ3Object b)
{
    TQ3ConeData da{}, db{};
    if (Q3Cone_GetData(a, &da) != kQ3Success || Q3Cone_GetData(b, &db) != kQ3Success)
        return false;
    const bool same = samePoint(da.origin, db.origin) && da.caps == db.caps &&
                      sameSet(da.bottomAttributeSet, db.bottomAttributeSet) &&
                      sameSet(da.faceAttributeSet, db.faceAttributeSet) &&
                      sameSet(da.interiorAttributeSet, db.interiorAttributeSet) &&
                      sameSet(da.coneAttributeSet, db.coneAttributeSet);
    Q3Cone_EmptyData(&da);
    Q3Cone_EmptyData(&db);
    return same;
}

TQ3Object makePolyLineWithSegments()
{
    TQ3Vertex3D v[4] = {{{-2, -1, 0}, nullptr}, {{-1, 1, 0}, nullptr}, {{1, -1, 0}, nullptr}, {{2, 1, 0}, nullptr}};
    TQ3AttributeSet segments[3] = {colorSet(1, 0, 0), nullptr, colorSet(0, 0, 1)};
    TQ3PolyLineData d = {4, v, segments, nullptr};
    TQ3Object o = Q3PolyLine_New(&d);
    Q3Object_Dispose(segments[0]);
    Q3Object_Dispose(segments[2]);
    return o;
}

bool samePolyLine(TQ3Object a, TQ3Object b)
{
    TQ3PolyLineData da{}, db{};
    if (Q3PolyLine_GetData(a, &da) != kQ3Success || Q3PolyLine_GetData(b, &db) != kQ3Success)
        return false;
    bool same = da.numVertices == db.numVertices && sameVertices(da.vertices, db.vertices, da.numVertices) &&
                (da.segmentAttributeSet == nullptr) == (db.segmentAttributeSet == nullptr);
    for (unsigned long i = 0; same && da.segmentAttributeSet != nullptr && i + 1 < da.numVertices; ++i)
        same = sameSet(da.segmentAttributeSet[i], db.segmentAttributeSet[i]);
    Q3PolyLine_EmptyData(&da);
    Q3PolyLine_EmptyData(&db);
    return same;
}

// ---- the cases ----------------------------------------------------------------

using Case = q3test::RoundTripCase;

std::vector<Case> cases()
{
    std::vector<Case> all;
    all.push_back({"NURBPatchTrimmed", [] { return makePatch(true, true); }, samePatch});
    all.push_back({"NURBPatchPlain", [] { return makePatch(false, false); }, samePatch});
    all.push_back({"Mesh", makeMesh, sameMesh});
    all.push_back({"GeneralPolygon", makeGeneralPolygon, sameGeneralPolygon});
    all.push_back({"TriGrid", makeTriGrid, sameTriGrid});
    all.push_back({"Polyhedron", makePolyhedron, samePolyhedron});
    all.push_back({"Marker", makeMarker, sameMarker});
    all.push_back({"BoxFaceSets", makeBoxWithFaces, sameBox});
    all.push_back({"CylinderCapSets", makeCylinderWithCaps, sameCylinder});
    all.push_back({"ConeCapSets", makeConeWithCaps, sameCone});
    all.push_back({"PolyLineSegmentSets", makePolyLineWithSegments, samePolyLine});
    return all;
}

// Whether an image has any pixel other than the first (the background).
class FileGeometryRoundTripTest : public Q3ApiTest, public ::testing::WithParamInterface<std::size_t> {};
class FileGeometryTest : public Q3ApiTest {
protected:
    // A text data file with the first `from` replaced by `to`, as bytes; a
    // failure when the file has no `from`.
    static std::vector<unsigned char> replaced(const std::string& text, const std::string& from, const std::string& to)
    {
        std::string out = text;
        const std::size_t at = out.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos)
            out.replace(at, from.size(), to);
        return bytesOf(out);
    }

    // One change to a text file: its first `from` replaced by `to`, and the
    // error reading the changed file must give.
    struct Change {
        std::string from, to;
        TQ3Error error;
    };
    // Each change makes a file whose reading fails with the change's error.
    void expectEachChangeFails(const std::string& text, std::initializer_list<Change> changes)
    {
        for (const Change& c : changes) {
            SCOPED_TRACE(c.to);
            EXPECT_READ_ERROR(replaced(text, c.from, c.to), c.error);
        }
    }

    // Every `step`th cut of a binary file is a file error, never a crash; a
    // cut that leaves only a few bytes after the last whole object reads
    // them with QuickDraw 3D's warning.
    void expectEveryCutFails(const std::vector<unsigned char>& binary, bool little, std::size_t step, const char* what)
    {
        ASSERT_GT(binary.size(), 24u);
        for (std::size_t cut = 25; cut < binary.size(); cut += step) {
            SCOPED_TRACE(cut);
            const TQ3Error error = readError(std::vector<unsigned char>(binary.begin(), binary.begin() + cut));
            if (cutLeavesJunk(binary, cut, little)) {
                consume(q3test::Kind::Warning, kQ3WarningInvalidMetafileObject, what, __FILE__, __LINE__);
                if (error == kQ3ErrorNone)
                    continue;
            }
            EXPECT_TRUE(error == kQ3ErrorInvalidMetafile || error == kQ3ErrorInvalidMetafilePrimitive ||
                        error == kQ3ErrorInvalidMetafileObject)
                << error;
            consume(q3test::Kind::Error, error, what, __FILE__, __LINE__);
        }
    }
};

} // namespace

TEST_P(FileGeometryRoundTripTest, WrittenAndReadBackInEveryModeGivesTheSameDataAndImage)
{
    expectRoundTripInEveryMode(cases()[GetParam()], /*isGeometry=*/false, /*mustDraw=*/true);
}

INSTANTIATE_TEST_SUITE_P(EveryClass, FileGeometryRoundTripTest, ::testing::Range<std::size_t>(0, cases().size()),
                         [](const ::testing::TestParamInfo<std::size_t>& info) { return cases()[info.param].name; });

TEST_F(FileGeometryTest, ATrimmedPatchIsWrittenAsNURBCurvesNeverPolylines)
{
    TQ3Object patch = makePatch(true, false);
    const auto bytes = writeObjects({patch}, kQ3FileModeNormal | kQ3FileModeText);
    const std::string text(bytes.begin(), bytes.end());
    EXPECT_NE(text.find("TrimLoop"), std::string::npos);
    std::size_t curves = 0;
    for (std::size_t at = text.find("NURBCurve2D"); at != std::string::npos; at = text.find("NURBCurve2D", at + 1))
        ++curves;
    EXPECT_EQ(curves, 3u);
    EXPECT_EQ(text.find("PolyLine"), std::string::npos);
    Q3Object_Dispose(patch);
}

TEST_F(FileGeometryTest, HandWrittenPatchFilesGiveThePatchInEveryEncoding)
{
    TQ3Object expected = makePatch(true, true);
    for (const char* name : {"nurbpatch.3dmf", "nurbpatch_be.3dmf", "nurbpatch_le.3dmf"}) {
        SCOPED_TRACE(name);
        const auto objects = readAll(dataFile(name));
        ASSERT_EQ(objects.size(), 1u);
        EXPECT_EQ(Q3Object_GetLeafType(objects[0]), kQ3GeometryTypeNURBPatch);
        EXPECT_TRUE(samePatch(objects[0], expected));
        for (TQ3Object o : objects)
            Q3Object_Dispose(o);
    }
    Q3Object_Dispose(expected);
}

TEST_F(FileGeometryTest, MalformedPatchFilesAreFileErrorsNeverCrashes)
{
    const std::string text = [] {
        const auto bytes = dataFile("nurbpatch.3dmf");
        return std::string(bytes.begin(), bytes.end());
    }();
    ASSERT_FALSE(text.empty());
    // Truncated in the middle of the patch.
    EXPECT_READ_ERROR(bytesOf(text.substr(0, text.find("0 0 0 0.5"))), kQ3ErrorInvalidMetafile);
    // Counts that would need gigabytes.
    expectEachChangeFails(text, {
        {"3 3 3 4", "3 3 65536 65536", kQ3ErrorInvalidMetafileObject},
        {"NURBCurve2D ( 2 5", "NURBCurve2D ( 2 4000000000", kQ3ErrorInvalidMetafileObject},
        // A malformed number.
        {"0 0 0 0.5 1 1 1", "0 0 0 0.5.5 1 1 1", kQ3ErrorInvalidMetafilePrimitive},
        // More data than the counts announce.
        {"0 0 0 1 1 1\n", "0 0 0 1 1 1 7\n", kQ3ErrorInvalidMetafileObject},
        // Something other than a 2-D NURB curve in a trim loop.
        {"NURBCurve2D ( 2 3", "Point ( 0 0 0 ) NURBCurve2D ( 2 3", kQ3ErrorInvalidMetafileSubObject},
        // A trim loop with no curve at all.
        {"Container (\n    TrimLoop ( )\n    NURBCurve2D ( 2 5 0.1 0.1 1  0.9 0.1 1  0.9 0.9 1  "
         "0.1 0.9 1  0.1 0.1 1  0 0 1 2 3 4 4 )\n  )",
         "TrimLoop ( )",
         kQ3ErrorInvalidMetafileSubObject},
        // An open trim loop, decreasing knots, a zero weight: the patch's rules.
        {"0.1 0.9 1  0.1 0.1 1  0 0", "0.1 0.9 1  0.2 0.1 1  0 0", kQ3ErrorInvalidMetafileObject},
        {"0 0 0 0.5 1 1 1", "0 0 0 0.5 0.25 1 1", kQ3ErrorInvalidMetafileObject},
        {"-1 0 2 2", "-1 0 2 0", kQ3ErrorInvalidMetafileObject},
    });
    // The reader goes on after a failed object.
    TQ3FileObject file = openBytes(bytesOf(text + "\nPoint ( 1 2 3 )\n"));
    ASSERT_NE(file, nullptr);
    TQ3Object patch = Q3File_ReadObject(file);
    EXPECT_NE(patch, nullptr);
    TQ3Object point = Q3File_ReadObject(file);
    EXPECT_NE(point, nullptr);
    Q3Object_Dispose(patch);
    Q3Object_Dispose(point);
    Q3File_Close(file);
    Q3Object_Dispose(file);

    // Binary: every cut of the big-endian file is an error, never a crash.
    const auto binary = dataFile("nurbpatch_be.3dmf");
    expectEveryCutFails(binary, false, 7, "a cut binary patch");
    // A bad tag where the trim loop's curves are.
    auto badTag = binary;
    const char nb2c[] = {'n', 'b', '2', 'c'};
    auto at = std::search(badTag.begin(), badTag.end(), nb2c, nb2c + 4);
    ASSERT_NE(at, badTag.end());
    std::memcpy(&*at, "xyzw", 4);
    EXPECT_READ_ERROR(badTag, kQ3ErrorInvalidMetafileSubObject);
}

TEST_F(FileGeometryTest, HandWrittenMeshFilesGiveTheMeshInEveryEncoding)
{
    TQ3Object expected = makeMesh();
    for (const char* name : {"mesh.3dmf", "mesh_be.3dmf", "mesh_le.3dmf"}) {
        SCOPED_TRACE(name);
        const auto objects = readAll(dataFile(name));
        ASSERT_EQ(objects.size(), 1u);
        EXPECT_EQ(Q3Object_GetLeafType(objects[0]), kQ3GeometryTypeMesh);
        EXPECT_TRUE(sameMesh(objects[0], expected));
        for (TQ3Object o : objects)
            Q3Object_Dispose(o);
    }
    // A face list counting faces only (as Quesa writes it) names the same
    // triangle.
    const auto bytes = dataFile("mesh.3dmf");
    std::string text(bytes.begin(), bytes.end());
    const std::size_t at = text.find("FaceAttributeSetList ( 3 Include 1 2 )");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 38, "FaceAttributeSetList ( 2 Include 1 1 )");
    const auto objects = readAll(bytesOf(text));
    ASSERT_EQ(objects.size(), 1u);
    EXPECT_TRUE(sameMesh(objects[0], expected));
    Q3Object_Dispose(objects[0]);
    Q3Object_Dispose(expected);
}

TEST_F(FileGeometryTest, MalformedMeshFilesAreFileErrorsNeverCrashes)
{
    const auto bytes = dataFile("mesh.3dmf");
    const std::string text(bytes.begin(), bytes.end());
    ASSERT_FALSE(text.empty());
    EXPECT_READ_ERROR(bytesOf(text.substr(0, text.find("-4 4 7"))), kQ3ErrorInvalidMetafile);
    // Counts that would need gigabytes.
    expectEachChangeFails(text, {
        {"    9\n", "    4000000000\n", kQ3ErrorInvalidMetafileObject},
        {"2 1            #", "2000000000 2000000000 #", kQ3ErrorInvalidMetafileObject},
        {"3 1 8 2", "2147483647 1 8 2", kQ3ErrorInvalidMetafileObject},
        {"-4 4 7 6 5", "-2147483648 4 7 6 5", kQ3ErrorInvalidMetafileObject},
        // A vertex index past the end; a contour before any face; fewer faces
        // than announced; a face the mesh refuses (two vertices).
        {"3 1 8 2", "3 1 9 2", kQ3ErrorInvalidMetafileObject},
        {"4 0 1 2 3\n    -4 4 7 6 5", "-4 4 7 6 5\n    4 0 1 2 3", kQ3ErrorInvalidMetafileObject},
        {"2 1            #", "3 0 #", kQ3ErrorInvalidMetafileObject},
        {"3 1 8 2", "2 1 8", kQ3ErrorInvalidMetafileObject},
    });
    // A face through one vertex twice is degenerate, not malformed: it reads
    // (docs/3dmf.md, Tolerances).
    EXPECT_EQ(readError(replaced(text, "3 1 8 2", "3 1 8 1")), kQ3ErrorNone);
    // A malformed number.
    expectEachChangeFails(text, {
        {"1.5 0 0.5", "1.5 0 0.5e", kQ3ErrorInvalidMetafilePrimitive},
        // Subobjects that do not fit: a corner on a face the mesh lacks, a corner
        // list without its sets, a face set list for another count.
        {"MeshCorners ( 1  1 2 2 0 )", "MeshCorners ( 1  1 2 2 1 )", kQ3ErrorInvalidMetafileSubObject},
        {"MeshCorners ( 1  1 2 2 0 )", "MeshCorners ( 2  1 2 2 0  2 1 0 )", kQ3ErrorInvalidMetafileSubObject},
        {"FaceAttributeSetList ( 3", "FaceAttributeSetList ( 4", kQ3ErrorInvalidMetafileSubObject},
        // A corner at a vertex its face does not have.
        {"MeshCorners ( 1  1 2 2 0 )", "MeshCorners ( 1  8 1 0 )", kQ3ErrorInvalidMetafileObject},
    });
    EXPECT_READ_ERROR(bytesOf("3DMetafile ( 1 6 Normal )\nMeshCorners ( 0 )\n"), kQ3ErrorInvalidMetafileObject);

    const auto binary = dataFile("mesh_be.3dmf");
    expectEveryCutFails(binary, false, 5, "a cut binary mesh");
}

TEST_F(FileGeometryTest, HandWrittenPolygonFilesGiveTheirObjectsInEveryEncoding)
{
    const std::vector<TQ3Object> expected = {makeGeneralPolygon(), makeTriGrid(), makePolyhedron(), makeMarker()};
    const std::vector<std::function<bool(TQ3Object, TQ3Object)>> same = {sameGeneralPolygon, sameTriGrid,
                                                                         samePolyhedron, sameMarker};
    for (const char* name : {"polygons.3dmf", "polygons_be.3dmf", "polygons_le.3dmf"}) {
        SCOPED_TRACE(name);
        const auto objects = readAll(dataFile(name));
        ASSERT_EQ(objects.size(), expected.size());
        for (std::size_t i = 0; i < objects.size(); ++i) {
            SCOPED_TRACE(i);
            EXPECT_EQ(Q3Object_GetLeafType(objects[i]), Q3Object_GetLeafType(expected[i]));
            EXPECT_TRUE(same[i](objects[i], expected[i]));
            Q3Object_Dispose(objects[i]);
        }
    }
    for (TQ3Object o : expected)
        Q3Object_Dispose(o);
}

TEST_F(FileGeometryTest, AMarkerOffsetTheFileCannotHoldIsAnErrorAndWritesNothing)
{
    if (sizeof(long) < 8)
        GTEST_SKIP() << "every long fits the file's 32-bit offsets";
    TQ3Object point = makeMarker();
    for (const long offset : {long{INT32_MAX} + 1, long{INT32_MIN} - 1}) {
        TQ3Object marker = makeMarker();
        ASSERT_EQ(Q3Marker_SetYOffset(marker, offset), kQ3Success);
        const auto objects = readAll(writeAfterRefusal(
            [&](TQ3ViewObject view) {
                EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_Submit(marker, view), kQ3Failure), kQ3ErrorInvalidData);
            },
            point));
        ASSERT_EQ(objects.size(), 1u); // the second marker alone
        EXPECT_TRUE(sameMarker(objects[0], point));
        disposeAll(objects);
        Q3Object_Dispose(marker);
    }
    Q3Object_Dispose(point);
}

TEST_F(FileGeometryTest, MalformedPolygonFilesAreFileErrorsNeverCrashes)
{
    const auto bytes = dataFile("polygons.3dmf");
    const std::string text(bytes.begin(), bytes.end());
    ASSERT_FALSE(text.empty());
    // Counts that would need gigabytes.
    expectEachChangeFails(text, {
        {"    2\n    4  -2", "    4000000000\n    4  -2", kQ3ErrorInvalidMetafileObject},
        {"    3  -0.5", "    300000000  -0.5", kQ3ErrorInvalidMetafileObject},
        {"TriGrid ( 2 3", "TriGrid ( 65536 65536", kQ3ErrorInvalidMetafileObject},
        {"4 2                                 #", "4 2000000000 #", kQ3ErrorInvalidMetafileObject},
        {"10 5 2 LittleEndian", "10 100000 100000 LittleEndian", kQ3ErrorInvalidMetafileObject},
        // Bad words and numbers.
        {"GeneralPolygonHint ( Concave )", "GeneralPolygonHint ( Wobbly )", kQ3ErrorInvalidMetafilePrimitive},
        {"LittleEndian", "MiddleEndian", kQ3ErrorInvalidMetafilePrimitive},
        {"1 0 3 0 255 3", "1 0 3 0 256 3", kQ3ErrorInvalidMetafilePrimitive},
        {"0 1.5 0\n", "0 1.5 0x\n", kQ3ErrorInvalidMetafilePrimitive},
        // Data their classes refuse: a contour of two vertices, a grid of one row,
        // a triangle naming a vertex past the end, an edge flag out of range, a
        // marker row too short for its width.
        {"    3  -0.5 -0.5 0  0 0.75 0  0.5 -0.5 0", "    2  -0.5 -0.5 0  0 0.75 0", kQ3ErrorInvalidMetafileSubObject},
        {"TriGrid ( 2 3", "TriGrid ( 1 6", kQ3ErrorInvalidMetafileSubObject},
        {"0 2 1 7  0 1 3", "0 2 9 7  0 1 3", kQ3ErrorInvalidMetafileObject},
        {"0 2 1 7  0 1 3", "0 2 1 8  0 1 3", kQ3ErrorInvalidMetafileObject},
        {"10 5 2 LittleEndian  1 0 3 0 255 3 3 0 1 0",
         "17 5 2 LittleEndian  1 0 3 0 255 3 3 0 1 0",
         kQ3ErrorInvalidMetafileObject},
        // More data than the counts announce, and attribute set lists that do
        // not fit.
        {"0 1 0.5  2 1 0 )", "0 1 0.5  2 1 0 1 )", kQ3ErrorInvalidMetafileObject},
        {"FaceAttributeSetList ( 4 Include 1  1 )",
         "FaceAttributeSetList ( 6 Include 1  1 )",
         kQ3ErrorInvalidMetafileSubObject},
        {"VertexAttributeSetList ( 7 Include 2  0 5 )",
         "VertexAttributeSetList ( 7 Include 2  0 7 )",
         kQ3ErrorInvalidMetafileSubObject},
        // The polyhedron's edge sets: a list for three edges of two, one naming
        // an edge past the end, one listing a set it does not hold.
        {"GeometryAttributeSetList ( 2 Include 1  1 )",
         "GeometryAttributeSetList ( 3 Include 1  1 )",
         kQ3ErrorInvalidMetafileSubObject},
        {"GeometryAttributeSetList ( 2 Include 1  1 )",
         "GeometryAttributeSetList ( 2 Include 1  2 )",
         kQ3ErrorInvalidMetafileSubObject},
        {"GeometryAttributeSetList ( 2 Include 1  1 )",
         "GeometryAttributeSetList ( 2 Include 2  0 1 )",
         kQ3ErrorInvalidMetafileSubObject},
    });

    for (const char* name : {"polygons_be.3dmf", "polygons_le.3dmf"}) {
        SCOPED_TRACE(name);
        const auto binary = dataFile(name);
        expectEveryCutFails(binary, name[9] == 'l', 11, "a cut binary file");
    }
}

// Binary TriMesh indices are 1 byte for counts up to 0xFF, 2 up to 0xFFFF
// (as Quesa writes them); an edge's missing triangle is all ones at that
// width and reads back as kQ3ArrayIndexNULL.
TEST_F(FileGeometryTest, TriMeshIndexWidthsFollowTheCountsAndKeepNullTriangles)
{
    struct Width {
        unsigned long points;
        std::size_t bytes;
    };
    for (const Width w : {Width{255, 1}, Width{256, 2}, Width{65535, 2}, Width{65536, 4}}) {
        SCOPED_TRACE(w.points);
        std::vector<TQ3Point3D> points(w.points);
        for (unsigned long i = 0; i < w.points; ++i)
            points[i] = {static_cast<float>(i % 7), static_cast<float>(i / 7 % 11), static_cast<float>(i % 3)};
        TQ3TriMeshTriangleData triangle = {{0, 1, w.points - 1}};
        TQ3TriMeshEdgeData edge = {{0, w.points - 1}, {0, static_cast<unsigned long>(kQ3ArrayIndexNULL)}};
        TQ3TriMeshData d{};
        d.numTriangles = 1;
        d.triangles = &triangle;
        d.numEdges = 1;
        d.edges = &edge;
        d.numPoints = w.points;
        d.points = points.data();
        TQ3Object mesh = Q3TriMesh_New(&d);
        ASSERT_NE(mesh, nullptr);
        const auto bytes = writeObjects({mesh}, kQ3FileModeStream);
        // Header (24 bytes), then 'tmsh' and its size: six counts, three
        // point indices, two point and two triangle indices, the points, the
        // box (two points and a flag).
        ASSERT_GE(bytes.size(), 32u);
        const std::size_t size = (std::size_t{bytes[28]} << 24) | (std::size_t{bytes[29]} << 16) |
                                 (std::size_t{bytes[30]} << 8) | bytes[31];
        EXPECT_EQ(size, 24 + 3 * w.bytes + 2 * w.bytes + 2 * 1 + 12 * w.points + 28);
        // The last point index of the triangle: 0xFE.., all but the top bit set.
        const std::size_t last = 32 + 24 + 2 * w.bytes;
        unsigned long value = 0;
        for (std::size_t b = 0; b < w.bytes; ++b)
            value = (value << 8) | bytes[last + b];
        EXPECT_EQ(value, w.points - 1);
        // The edge's second triangle: 0xFF (one triangle, 1-byte indices).
        EXPECT_EQ(bytes[32 + 24 + 5 * w.bytes + 1], 0xFF);
        TQ3FileObject file = openBytes(bytes);
        ASSERT_NE(file, nullptr);
        TQ3Object back = Q3File_ReadObject(file);
        ASSERT_NE(back, nullptr);
        TQ3TriMeshData db{};
        ASSERT_EQ(Q3TriMesh_GetData(back, &db), kQ3Success);
        EXPECT_EQ(db.triangles[0].pointIndices[2], w.points - 1);
        EXPECT_EQ(db.edges[0].pointIndices[1], w.points - 1);
        EXPECT_EQ(db.edges[0].triangleIndices[0], 0u);
        EXPECT_EQ(db.edges[0].triangleIndices[1], static_cast<unsigned long>(kQ3ArrayIndexNULL));
        Q3TriMesh_EmptyData(&db);
        Q3File_Close(file);
        Q3Object_Dispose(file);
        Q3Object_Dispose(back);
        Q3Object_Dispose(mesh);
    }
}

// A binary TriMesh's index bytes are not padded: the points follow the last
// index byte at once, and the object's size need not be a multiple of 4
// (Quesa's writer sizes the object so and its reader reads it so; Q3 writes
// the same). Laid out by hand: three triangles of 1-byte indices (9 bytes),
// then a Point right after the TriMesh's odd-sized data; and the same TriMesh
// padded with zeros to a multiple of 4 at its end, which reads the same.
TEST_F(FileGeometryTest, ABinaryTriMeshIsNotPaddedBetweenItsIndicesAndItsPoints)
{
    const float points[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const unsigned char indices[9] = {0, 1, 2, 0, 3, 1, 1, 3, 2};
    for (const std::size_t pad : {std::size_t{0}, std::size_t{3}}) {
        SCOPED_TRACE(pad);
        auto bytes = binaryHeader();
        putTag(bytes, "tmsh");
        put32(bytes, static_cast<std::uint32_t>(24 + 9 + 48 + 28 + pad));
        for (std::uint32_t count : {3u, 0u, 0u, 0u, 4u, 0u})
            put32(bytes, count);
        bytes.insert(bytes.end(), indices, indices + 9);
        for (const auto& point : points)
            for (float c : point)
                putFloat(bytes, c);
        for (float c : {0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f})
            putFloat(bytes, c);
        put32(bytes, 0);
        bytes.insert(bytes.end(), pad, 0);
        putTag(bytes, "pnt ");
        put32(bytes, 12);
        for (float c : {0.5f, -2.0f, 4.0f})
            putFloat(bytes, c);
        const auto objects = readAll(bytes);
        ASSERT_EQ(objects.size(), 2u);
        TQ3TriMeshData mesh{};
        ASSERT_EQ(Q3TriMesh_GetData(objects[0], &mesh), kQ3Success);
        ASSERT_EQ(mesh.numTriangles, 3u);
        for (unsigned long t = 0; t < 3; ++t)
            for (int k = 0; k < 3; ++k)
                EXPECT_EQ(mesh.triangles[t].pointIndices[k], indices[3 * t + k]);
        ASSERT_EQ(mesh.numPoints, 4u);
        for (unsigned long i = 0; i < 4; ++i)
            EXPECT_TRUE(samePoint(mesh.points[i], {points[i][0], points[i][1], points[i][2]}));
        Q3TriMesh_EmptyData(&mesh);
        TQ3PointData point{};
        ASSERT_EQ(Q3Point_GetData(objects[1], &point), kQ3Success);
        EXPECT_TRUE(samePoint(point.point, {0.5f, -2.0f, 4.0f}));
        Q3Point_EmptyData(&point);
        disposeAll(objects);
    }
    // Q3 writes it so: the same TriMesh's data is 109 bytes.
    TQ3TriMeshTriangleData triangles[3] = {{{0, 1, 2}}, {{0, 3, 1}}, {{1, 3, 2}}};
    TQ3Point3D meshPoints[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    TQ3TriMeshData d{};
    d.numTriangles = 3;
    d.triangles = triangles;
    d.numPoints = 4;
    d.points = meshPoints;
    d.bBox = {{0, 0, 0}, {1, 1, 1}, kQ3False};
    TQ3Object mesh = Q3TriMesh_New(&d);
    ASSERT_NE(mesh, nullptr);
    const auto written = writeObjects({mesh}, kQ3FileModeStream);
    ASSERT_GE(written.size(), 32u);
    EXPECT_EQ(written[31] | (written[30] << 8), 109);
    EXPECT_EQ(written.size(), 32u + 109u);
    Q3Object_Dispose(mesh);
}

TEST_F(FileGeometryTest, HandWrittenPartSetFilesGiveTheirObjectsInEveryEncoding)
{
    const std::vector<TQ3Object> expected = {makeBoxWithFaces(), makeCylinderWithCaps(), makePolyLineWithSegments()};
    const std::vector<std::function<bool(TQ3Object, TQ3Object)>> same = {sameBox, sameCylinder, samePolyLine};
    for (const char* name : {"part_sets.3dmf", "part_sets_be.3dmf", "part_sets_le.3dmf"}) {
        SCOPED_TRACE(name);
        const auto objects = readAll(dataFile(name));
        ASSERT_EQ(objects.size(), expected.size());
        for (std::size_t i = 0; i < objects.size(); ++i) {
            SCOPED_TRACE(i);
            EXPECT_TRUE(same[i](objects[i], expected[i]));
            Q3Object_Dispose(objects[i]);
        }
    }
    for (TQ3Object o : expected)
        Q3Object_Dispose(o);
}

TEST_F(FileGeometryTest, MalformedPartSetFilesAreFileErrorsNeverCrashes)
{
    const auto bytes = dataFile("part_sets.3dmf");
    const std::string text(bytes.begin(), bytes.end());
    ASSERT_FALSE(text.empty());
    // Lists for another count; a cap set without its set, or with a point.
    expectEachChangeFails(text, {
        {"FaceAttributeSetList ( 6", "FaceAttributeSetList ( 5", kQ3ErrorInvalidMetafileSubObject},
        {"GeometryAttributeSetList ( 3", "GeometryAttributeSetList ( 4", kQ3ErrorInvalidMetafileSubObject},
        {"TopCapAttributeSet ( ) Container ( AttributeSet ( ) DiffuseColor ( 1 0 0 ) )",
         "TopCapAttributeSet ( )",
         kQ3ErrorInvalidMetafileSubObject},
        {"TopCapAttributeSet ( ) Container ( AttributeSet ( ) DiffuseColor ( 1 0 0 ) )",
         "TopCapAttributeSet ( ) Point ( 0 0 0 )",
         kQ3ErrorInvalidMetafileSubObject},
    });
    EXPECT_READ_ERROR(bytesOf("3DMetafile ( 1 6 Normal )\nTopCapAttributeSet ( )\n"), kQ3ErrorInvalidMetafileObject);
    EXPECT_READ_ERROR(replaced(text, "GeometryAttributeSetList ( 3 Include 2  0 2 )", "GeometryAttributeSetList ( 3 Include 2  0 3 )"), kQ3ErrorInvalidMetafileSubObject);
}
