// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Every class Q3 writes, written and read back in every encoding and mode:
// the data compared field by field, and the two objects rendered to the same
// image.

#include "FileTestSupport.h"
#include "Q3ApiTest.h"
#include "RenderTestSupport.h"

#include "QD3DCamera.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DSet.h"

#include <cmath>
#include <cstring>
#include <functional>
#include <string>

using namespace q3test;

namespace {

TQ3AttributeSet colorSet(float r, float g, float b)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB color = {r, g, b};
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color);
    return set;
}

bool sameVector(const TQ3Vector3D& a, const TQ3Vector3D& b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

using Case = q3test::RoundTripCase;

template <class Data, class Get, class Empty, class Compare>
std::function<bool(TQ3Object, TQ3Object)> byData(Get get, Empty empty, Compare compare)
{
    return [=](TQ3Object a, TQ3Object b) {
        Data da{}, db{};
        if (get(a, &da) != kQ3Success || get(b, &db) != kQ3Success)
            return false;
        const bool same = compare(da, db);
        empty(&da);
        empty(&db);
        return same;
    };
}

template <class Data>
bool sameSolid(const Data& a, const Data& b)
{
    return samePoint(a.origin, b.origin) && sameVector(a.orientation, b.orientation) &&
           sameVector(a.majorRadius, b.majorRadius) && sameVector(a.minorRadius, b.minorRadius) &&
           a.uMin == b.uMin && a.uMax == b.uMax && a.vMin == b.vMin && a.vMax == b.vMax && a.caps == b.caps;
}

std::vector<Case> cases()
{
    std::vector<Case> all;
    all.push_back({"Point",
                   [] {
                       TQ3AttributeSet set = colorSet(1, 0, 0);
                       TQ3PointData d = {{0.5f, -1.25f, 3}, set};
                       TQ3Object o = Q3Point_New(&d);
                       Q3Object_Dispose(set);
                       return o;
                   },
                   byData<TQ3PointData>(Q3Point_GetData, Q3Point_EmptyData, [](auto& a, auto& b) {
                       return samePoint(a.point, b.point) && sameSet(a.pointAttributeSet, b.pointAttributeSet);
                   })});
    all.push_back({"Line",
                   [] {
                       TQ3AttributeSet set = colorSet(0, 1, 0);
                       TQ3LineData d = {{{{-2, -1, 0}, set}, {{2, 1.5f, 0.25f}, nullptr}}, nullptr};
                       TQ3Object o = Q3Line_New(&d);
                       Q3Object_Dispose(set);
                       return o;
                   },
                   byData<TQ3LineData>(Q3Line_GetData, Q3Line_EmptyData, [](auto& a, auto& b) {
                       return sameVertices(a.vertices, b.vertices, 2) &&
                              sameSet(a.lineAttributeSet, b.lineAttributeSet);
                   })});
    all.push_back({"PolyLine",
                   [] {
                       TQ3Vertex3D v[4] = {{{-2, -1, 0}, nullptr}, {{-1, 1, 0}, nullptr}, {{1, -1, 0}, nullptr},
                                           {{2, 1, 0}, nullptr}};
                       TQ3AttributeSet set = colorSet(0, 0, 1);
                       TQ3PolyLineData d = {4, v, nullptr, set};
                       TQ3Object o = Q3PolyLine_New(&d);
                       Q3Object_Dispose(set);
                       return o;
                   },
                   byData<TQ3PolyLineData>(Q3PolyLine_GetData, Q3PolyLine_EmptyData, [](auto& a, auto& b) {
                       return a.numVertices == b.numVertices && sameVertices(a.vertices, b.vertices, a.numVertices) &&
                              sameSet(a.polyLineAttributeSet, b.polyLineAttributeSet);
                   })});
    all.push_back({"Triangle",
                   [] {
                       TQ3AttributeSet red = colorSet(1, 0, 0), blue = colorSet(0, 0, 1);
                       TQ3TriangleData d = {{{{-2, -1, 0}, red}, {{2, -1, 0}, blue}, {{0, 2, 0}, nullptr}}, red};
                       TQ3Object o = Q3Triangle_New(&d);
                       Q3Object_Dispose(red);
                       Q3Object_Dispose(blue);
                       return o;
                   },
                   byData<TQ3TriangleData>(Q3Triangle_GetData, Q3Triangle_EmptyData, [](auto& a, auto& b) {
                       return sameVertices(a.vertices, b.vertices, 3) &&
                              sameSet(a.triangleAttributeSet, b.triangleAttributeSet);
                   })});
    all.push_back({"Polygon",
                   [] {
                       TQ3Vertex3D v[5] = {{{-2, -1, 0}, nullptr}, {{2, -1, 0}, nullptr}, {{2.5f, 1, 0}, nullptr},
                                           {{0, 2, 0}, nullptr}, {{-2.5f, 1, 0}, nullptr}};
                       TQ3AttributeSet set = colorSet(0.5f, 0.25f, 1);
                       TQ3PolygonData d = {5, v, set};
                       TQ3Object o = Q3Polygon_New(&d);
                       Q3Object_Dispose(set);
                       return o;
                   },
                   byData<TQ3PolygonData>(Q3Polygon_GetData, Q3Polygon_EmptyData, [](auto& a, auto& b) {
                       return a.numVertices == b.numVertices && sameVertices(a.vertices, b.vertices, a.numVertices) &&
                              sameSet(a.polygonAttributeSet, b.polygonAttributeSet);
                   })});
    all.push_back({"TriMesh",
                   [] {
                       TQ3Point3D p[4] = {{-2, -1, 0}, {2, -1, 0}, {2, 1.5f, 0}, {-2, 1.5f, -1}};
                       TQ3TriMeshTriangleData t[2] = {{{0, 1, 2}}, {{0, 2, 3}}};
                       TQ3TriMeshEdgeData e[1] = {{{0, 2}, {0, 1}}};
                       TQ3AttributeSet set = colorSet(0.9f, 0.6f, 0.1f);
                       static TQ3ColorRGB faceColors[2] = {{1, 0, 0}, {0, 0, 1}};
                       static char faceUse[2] = {1, 0};
                       static TQ3Vector3D normals[4] = {{0, 0, 1}, {0, 0, 1}, {0, 0.5f, 1}, {0, 0, 1}};
                       static TQ3TriMeshAttributeData faces[1] = {
                           {kQ3AttributeTypeDiffuseColor, faceColors, faceUse}};
                       static TQ3TriMeshAttributeData vertices[1] = {{kQ3AttributeTypeNormal, normals, nullptr}};
                       // The set, two triangles with one attribute array,
                       // one edge without, four points with one.
                       TQ3TriMeshData d{set, 2, t, 1, faces, 1, e, 0, nullptr, 4, p, 1, vertices,
                                        {{-2, -1, -1}, {2, 1.5f, 0}, kQ3False}};
                       TQ3Object o = Q3TriMesh_New(&d);
                       Q3Object_Dispose(set);
                       return o;
                   },
                   byData<TQ3TriMeshData>(Q3TriMesh_GetData, Q3TriMesh_EmptyData, [](auto& a, auto& b) {
                       if (a.numTriangles != b.numTriangles || a.numPoints != b.numPoints || a.numEdges != b.numEdges)
                           return false;
                       if (a.numTriangleAttributeTypes != b.numTriangleAttributeTypes ||
                           a.numVertexAttributeTypes != b.numVertexAttributeTypes ||
                           a.numEdgeAttributeTypes != b.numEdgeAttributeTypes)
                           return false;
                       if (a.numTriangleAttributeTypes == 1 &&
                           (a.triangleAttributeTypes[0].attributeType != b.triangleAttributeTypes[0].attributeType ||
                            std::memcmp(a.triangleAttributeTypes[0].data, b.triangleAttributeTypes[0].data,
                                        2 * sizeof(TQ3ColorRGB)) != 0 ||
                            b.triangleAttributeTypes[0].attributeUseArray == nullptr ||
                            std::memcmp(a.triangleAttributeTypes[0].attributeUseArray,
                                        b.triangleAttributeTypes[0].attributeUseArray, 2) != 0))
                           return false;
                       if (a.numVertexAttributeTypes == 1 &&
                           (a.vertexAttributeTypes[0].attributeType != b.vertexAttributeTypes[0].attributeType ||
                            std::memcmp(a.vertexAttributeTypes[0].data, b.vertexAttributeTypes[0].data,
                                        4 * sizeof(TQ3Vector3D)) != 0 ||
                            b.vertexAttributeTypes[0].attributeUseArray != nullptr))
                           return false;
                       for (unsigned long i = 0; i < a.numTriangles; ++i)
                           for (int k = 0; k < 3; ++k)
                               if (a.triangles[i].pointIndices[k] != b.triangles[i].pointIndices[k])
                                   return false;
                       for (unsigned long i = 0; i < a.numEdges; ++i)
                           for (int k = 0; k < 2; ++k)
                               if (a.edges[i].pointIndices[k] != b.edges[i].pointIndices[k] ||
                                   a.edges[i].triangleIndices[k] != b.edges[i].triangleIndices[k])
                                   return false;
                       for (unsigned long i = 0; i < a.numPoints; ++i)
                           if (!samePoint(a.points[i], b.points[i]))
                               return false;
                       return samePoint(a.bBox.min, b.bBox.min) && samePoint(a.bBox.max, b.bBox.max) &&
                              a.bBox.isEmpty == b.bBox.isEmpty &&
                              sameSet(a.triMeshAttributeSet, b.triMeshAttributeSet);
                   })});
    all.push_back({"NURBCurve",
                   [] {
                       TQ3RationalPoint4D p[5] = {{-2, -1, 0, 1}, {-1, 2, 0, 1}, {0, -1, 0, 0.5f}, {2, 2, 0, 2},
                                                  {2.5f, -1, 0, 1}};
                       float k[9] = {0, 0, 0, 0, 0.3f, 1, 1, 1, 1};
                       TQ3AttributeSet set = colorSet(0.1f, 0.2f, 0.3f);
                       TQ3NURBCurveData d = {4, 5, p, k, set};
                       TQ3Object o = Q3NURBCurve_New(&d);
                       Q3Object_Dispose(set);
                       return o;
                   },
                   byData<TQ3NURBCurveData>(Q3NURBCurve_GetData, Q3NURBCurve_EmptyData, [](auto& a, auto& b) {
                       if (a.order != b.order || a.numPoints != b.numPoints)
                           return false;
                       for (unsigned long i = 0; i < a.numPoints; ++i)
                           if (std::memcmp(&a.controlPoints[i], &b.controlPoints[i], sizeof(TQ3RationalPoint4D)) != 0)
                               return false;
                       for (unsigned long i = 0; i < a.order + a.numPoints; ++i)
                           if (a.knots[i] != b.knots[i])
                               return false;
                       return sameSet(a.curveAttributeSet, b.curveAttributeSet);
                   })});
    all.push_back({"Box",
                   [] {
                       TQ3AttributeSet set = colorSet(0.2f, 0.4f, 0.9f);
                       TQ3BoxData d = {{-1, -1, -1}, {0, 2, 0}, {2, 0, 0}, {0, 0, 1.5f}, nullptr, set};
                       TQ3Object o = Q3Box_New(&d);
                       Q3Object_Dispose(set);
                       return o;
                   },
                   byData<TQ3BoxData>(Q3Box_GetData, Q3Box_EmptyData, [](auto& a, auto& b) {
                       return samePoint(a.origin, b.origin) && sameVector(a.orientation, b.orientation) &&
                              sameVector(a.majorAxis, b.majorAxis) && sameVector(a.minorAxis, b.minorAxis) &&
                              sameSet(a.boxAttributeSet, b.boxAttributeSet);
                   })});
    all.push_back({"Cone",
                   [] {
                       // Radius 1 about +y from y = -1 to 1, a quarter cut
                       // away, the bottom and the cut closed, an orange set.
                       TQ3ConeData d{{0, -1, 0},
                                     {0, 2, 0},
                                     {1, 0, 0},
                                     {0, 0, 1},
                                     0,
                                     0.75f,
                                     0,
                                     1,
                                     kQ3EndCapMaskBottom | kQ3EndCapMaskInterior,
                                     nullptr,
                                     nullptr,
                                     nullptr,
                                     colorSet(1, 0.5f, 0)};
                       TQ3Object o = Q3Cone_New(&d);
                       Q3Object_Dispose(d.coneAttributeSet);
                       return o;
                   },
                   byData<TQ3ConeData>(Q3Cone_GetData, Q3Cone_EmptyData, [](auto& a, auto& b) {
                       return sameSolid(a, b) && sameSet(a.coneAttributeSet, b.coneAttributeSet);
                   })});
    all.push_back({"Cylinder",
                   [] {
                       // Elliptic, about +y from y = -1 to 1, whole, both ends
                       // closed, no sets.
                       TQ3CylinderData d{{0, -1, 0}, {0, 2, 0}, {1, 0, 0}, {0, 0, 0.5f}, 0, 1, 0, 1,
                                         kQ3EndCapMaskTop | kQ3EndCapMaskBottom};
                       TQ3Object o = Q3Cylinder_New(&d);
                       return o;
                   },
                   byData<TQ3CylinderData>(Q3Cylinder_GetData, Q3Cylinder_EmptyData, [](auto& a, auto& b) {
                       return sameSolid(a, b) && sameSet(a.cylinderAttributeSet, b.cylinderAttributeSet);
                   })});
    all.push_back({"Disk",
                   [] {
                       // u from a quarter round to the end, all of v, a cyan set.
                       TQ3DiskData d{{0, 0, 0}, {2, 0, 0}, {0, 1.5f, 0}, 0.25f, 1, 0, 1, colorSet(0, 1, 1)};
                       TQ3Object o = Q3Disk_New(&d);
                       Q3Object_Dispose(d.diskAttributeSet);
                       return o;
                   },
                   byData<TQ3DiskData>(Q3Disk_GetData, Q3Disk_EmptyData, [](auto& a, auto& b) {
                       return samePoint(a.origin, b.origin) && sameVector(a.majorRadius, b.majorRadius) &&
                              sameVector(a.minorRadius, b.minorRadius) && a.uMin == b.uMin && a.uMax == b.uMax &&
                              a.vMin == b.vMin && a.vMax == b.vMax && sameSet(a.diskAttributeSet, b.diskAttributeSet);
                   })});
    all.push_back({"Ellipse",
                   [] {
                       TQ3EllipseData d{{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, 0, 0.5f, nullptr}; // half of it
                       TQ3Object o = Q3Ellipse_New(&d);
                       return o;
                   },
                   byData<TQ3EllipseData>(Q3Ellipse_GetData, Q3Ellipse_EmptyData, [](auto& a, auto& b) {
                       return samePoint(a.origin, b.origin) && sameVector(a.majorRadius, b.majorRadius) &&
                              sameVector(a.minorRadius, b.minorRadius) && a.uMin == b.uMin && a.uMax == b.uMax &&
                              sameSet(a.ellipseAttributeSet, b.ellipseAttributeSet);
                   })});
    all.push_back({"Ellipsoid",
                   [] {
                       TQ3EllipsoidData d{};
                       d.orientation = {0, 0, 1.5f};
                       d.majorRadius = {2, 0, 0};
                       d.minorRadius = {0, 1, 0};
                       d.uMax = 1;
                       d.vMax = 1;
                       d.ellipsoidAttributeSet = colorSet(0.5f, 0.5f, 0.5f);
                       TQ3Object o = Q3Ellipsoid_New(&d);
                       Q3Object_Dispose(d.ellipsoidAttributeSet);
                       return o;
                   },
                   byData<TQ3EllipsoidData>(Q3Ellipsoid_GetData, Q3Ellipsoid_EmptyData, [](auto& a, auto& b) {
                       return sameSolid(a, b) && sameSet(a.ellipsoidAttributeSet, b.ellipsoidAttributeSet);
                   })});
    all.push_back({"Torus",
                   [] {
                       TQ3TorusData d{};
                       d.orientation = {0, 0.5f, 0};
                       d.majorRadius = {2, 0, 0};
                       d.minorRadius = {0, 0, 2};
                       d.ratio = 0.75f;
                       d.uMax = 1;
                       d.vMin = 0.1f;
                       d.vMax = 0.9f;
                       TQ3Object o = Q3Torus_New(&d);
                       return o;
                   },
                   byData<TQ3TorusData>(Q3Torus_GetData, Q3Torus_EmptyData, [](auto& a, auto& b) {
                       return sameSolid(a, b) && a.ratio == b.ratio &&
                              sameSet(a.torusAttributeSet, b.torusAttributeSet);
                   })});
    return all;
}

class FileRoundTripTest : public Q3ApiTest, public ::testing::WithParamInterface<std::size_t> {};

} // namespace

TEST_P(FileRoundTripTest, WrittenAndReadBackInEveryModeGivesTheSameDataAndImage)
{
    expectRoundTripInEveryMode(cases()[GetParam()], /*isGeometry=*/true, /*mustDraw=*/false);
}

INSTANTIATE_TEST_SUITE_P(EveryClass, FileRoundTripTest, ::testing::Range<std::size_t>(0, 14),
                         [](const ::testing::TestParamInfo<std::size_t>& info) { return cases()[info.param].name; });
