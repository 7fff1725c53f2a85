// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The catalogue of hand-written 3DMF files (tests/data/curves_quadrics,
// attributes, styles_shaders, lights_transforms_groups, each in text and in
// big- and little-endian binary laid out by make_catalog_binary.py): every
// object read in every encoding is checked field by field against the values
// written below, which are the files' values, so the three encodings agree
// with each other too. Malformed variants of them are file errors.

#include "FileTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

using namespace q3test;

namespace {

class FileCatalogTest : public Q3ApiTest {};

std::vector<unsigned char> dataFile(const std::string& name)
{
    std::ifstream in(std::string(Q3_TEST_DATA_DIR) + "/" + name, std::ios::binary);
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// The text file and its two binary twins.
std::vector<std::string> encodings(const std::string& stem)
{
    return {stem + ".3dmf", stem + "_be.3dmf", stem + "_le.3dmf"};
}

void expectPoint(const TQ3Point3D& p, float x, float y, float z)
{
    EXPECT_EQ(p.x, x);
    EXPECT_EQ(p.y, y);
    EXPECT_EQ(p.z, z);
}

void expectVector(const TQ3Vector3D& v, float x, float y, float z)
{
    EXPECT_EQ(v.x, x);
    EXPECT_EQ(v.y, y);
    EXPECT_EQ(v.z, z);
}

void expectColor(const TQ3ColorRGB& c, float r, float g, float b)
{
    EXPECT_EQ(c.r, r);
    EXPECT_EQ(c.g, g);
    EXPECT_EQ(c.b, b);
}

/// The set holds exactly one attribute, a diffuse colour of r g b.
void expectDiffuse(TQ3AttributeSet set, float r, float g, float b)
{
    ASSERT_NE(set, nullptr);
    TQ3ColorRGB color{};
    ASSERT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeDiffuseColor, &color), kQ3Success);
    expectColor(color, r, g, b);
    for (TQ3AttributeType type = kQ3AttributeTypeSurfaceUV; type <= kQ3AttributeTypeHighlightState; ++type)
        EXPECT_EQ(Q3AttributeSet_Contains(set, type), type == kQ3AttributeTypeDiffuseColor ? kQ3True : kQ3False)
            << type;
}

/// A group's objects, each with a reference the caller disposes of.
std::vector<TQ3Object> members(TQ3GroupObject group)
{
    std::vector<TQ3Object> out;
    TQ3GroupPosition position = nullptr;
    EXPECT_EQ(Q3Group_GetFirstPosition(group, &position), kQ3Success);
    while (position != nullptr) {
        TQ3Object object = nullptr;
        EXPECT_EQ(Q3Group_GetPositionObject(group, position, &object), kQ3Success);
        out.push_back(object);
        EXPECT_EQ(Q3Group_GetNextPosition(group, &position), kQ3Success);
    }
    return out;
}

// ---- curves_quadrics --------------------------------------------------------

void expectCurvesAndQuadrics(const std::vector<TQ3Object>& objects)
{
    ASSERT_EQ(objects.size(), 9u);

    ASSERT_EQ(Q3Object_GetLeafType(objects[0]), kQ3GeometryTypeNURBCurve);
    TQ3NURBCurveData curve{};
    ASSERT_EQ(Q3NURBCurve_GetData(objects[0], &curve), kQ3Success);
    EXPECT_EQ(curve.order, 3u);
    ASSERT_EQ(curve.numPoints, 4u);
    const float points[16] = {0, 0, 0, 1, 2, 4, 0, 2, 2, -1, 0, 1, 3, 0, 0, 1};
    for (unsigned long i = 0; i < 4; ++i) {
        EXPECT_EQ(curve.controlPoints[i].x, points[4 * i]);
        EXPECT_EQ(curve.controlPoints[i].y, points[4 * i + 1]);
        EXPECT_EQ(curve.controlPoints[i].z, points[4 * i + 2]);
        EXPECT_EQ(curve.controlPoints[i].w, points[4 * i + 3]);
    }
    const float knots[7] = {0, 0, 0, 0.5f, 1, 1, 1};
    for (int i = 0; i < 7; ++i)
        EXPECT_EQ(curve.knots[i], knots[i]) << i;
    expectDiffuse(curve.curveAttributeSet, 1, 0.5f, 0);
    Q3NURBCurve_EmptyData(&curve);

    ASSERT_EQ(Q3Object_GetLeafType(objects[1]), kQ3GeometryTypeDisk);
    TQ3DiskData disk{};
    ASSERT_EQ(Q3Disk_GetData(objects[1], &disk), kQ3Success);
    expectVector(disk.majorRadius, 1, 0, 0);
    expectVector(disk.minorRadius, 0, 2, 0);
    expectPoint(disk.origin, 0, 0, 1);
    EXPECT_EQ(disk.uMin, 0);
    EXPECT_EQ(disk.uMax, 0.5f);
    EXPECT_EQ(disk.vMin, 0);
    EXPECT_EQ(disk.vMax, 1);
    expectDiffuse(disk.diskAttributeSet, 0, 0, 1);
    Q3Disk_EmptyData(&disk);

    ASSERT_EQ(Q3Object_GetLeafType(objects[2]), kQ3GeometryTypeEllipse);
    TQ3EllipseData ellipse{};
    ASSERT_EQ(Q3Ellipse_GetData(objects[2], &ellipse), kQ3Success);
    expectVector(ellipse.majorRadius, 2, 0, 0);
    expectVector(ellipse.minorRadius, 0, 1, 0);
    expectPoint(ellipse.origin, 0, 0, -1);
    EXPECT_EQ(ellipse.uMin, 0.25f);
    EXPECT_EQ(ellipse.uMax, 0.75f);
    EXPECT_EQ(ellipse.ellipseAttributeSet, nullptr);
    Q3Ellipse_EmptyData(&ellipse);

    ASSERT_EQ(Q3Object_GetLeafType(objects[3]), kQ3GeometryTypeEllipsoid);
    TQ3EllipsoidData ellipsoid{};
    ASSERT_EQ(Q3Ellipsoid_GetData(objects[3], &ellipsoid), kQ3Success);
    expectVector(ellipsoid.orientation, 0, 0, 1);
    expectVector(ellipsoid.majorRadius, 0, 1, 0);
    expectVector(ellipsoid.minorRadius, 1, 0, 0);
    expectPoint(ellipsoid.origin, 0, 0, -2);
    EXPECT_EQ(ellipsoid.uMin, 0);
    EXPECT_EQ(ellipsoid.uMax, 1);
    EXPECT_EQ(ellipsoid.caps, kQ3EndCapNone);
    expectDiffuse(ellipsoid.ellipsoidAttributeSet, 0.5f, 0.5f, 0.5f);
    EXPECT_EQ(ellipsoid.interiorAttributeSet, nullptr);
    Q3Ellipsoid_EmptyData(&ellipsoid);

    ASSERT_EQ(Q3Object_GetLeafType(objects[4]), kQ3GeometryTypeCone);
    TQ3ConeData cone{};
    ASSERT_EQ(Q3Cone_GetData(objects[4], &cone), kQ3Success);
    expectVector(cone.orientation, 0, 2, 0);
    expectVector(cone.majorRadius, 1, 0, 0);
    expectVector(cone.minorRadius, 0, 0, 1);
    expectPoint(cone.origin, 3, 0, 0);
    EXPECT_EQ(cone.caps, kQ3EndCapMaskBottom);
    expectDiffuse(cone.bottomAttributeSet, 0, 1, 0);
    EXPECT_EQ(cone.faceAttributeSet, nullptr);
    EXPECT_EQ(cone.interiorAttributeSet, nullptr);
    EXPECT_EQ(cone.coneAttributeSet, nullptr);
    Q3Cone_EmptyData(&cone);

    ASSERT_EQ(Q3Object_GetLeafType(objects[5]), kQ3GeometryTypeTorus);
    TQ3TorusData torus{};
    ASSERT_EQ(Q3Torus_GetData(objects[5], &torus), kQ3Success);
    expectVector(torus.orientation, 0, 0.5f, 0);
    expectVector(torus.majorRadius, 1, 0, 0);
    expectVector(torus.minorRadius, 0, 0, 1);
    expectPoint(torus.origin, 0, 0, 0);
    EXPECT_EQ(torus.ratio, 0.5f);
    EXPECT_EQ(torus.vMax, 1);
    Q3Torus_EmptyData(&torus);

    ASSERT_EQ(Q3Object_GetLeafType(objects[6]), kQ3GeometryTypeLine);
    TQ3LineData line{};
    ASSERT_EQ(Q3Line_GetData(objects[6], &line), kQ3Success);
    expectPoint(line.vertices[0].point, 0, 0, 0);
    expectPoint(line.vertices[1].point, 1, 1, 1);
    expectDiffuse(line.vertices[0].attributeSet, 1, 0, 0);
    EXPECT_EQ(line.vertices[1].attributeSet, nullptr);
    EXPECT_EQ(line.lineAttributeSet, nullptr);
    Q3Line_EmptyData(&line);

    ASSERT_EQ(Q3Object_GetLeafType(objects[7]), kQ3GeometryTypePolygon);
    TQ3PolygonData polygon{};
    ASSERT_EQ(Q3Polygon_GetData(objects[7], &polygon), kQ3Success);
    ASSERT_EQ(polygon.numVertices, 4u);
    expectPoint(polygon.vertices[0].point, 0, 0, 0);
    expectPoint(polygon.vertices[1].point, 1, 0, 0);
    expectPoint(polygon.vertices[2].point, 1, 1, 0);
    expectPoint(polygon.vertices[3].point, 0, 1, 0);
    expectDiffuse(polygon.polygonAttributeSet, 0.25f, 0.75f, 1);
    Q3Polygon_EmptyData(&polygon);

    ASSERT_EQ(Q3Object_GetLeafType(objects[8]), kQ3GeometryTypePoint);
    TQ3PointData point{};
    ASSERT_EQ(Q3Point_GetData(objects[8], &point), kQ3Success);
    expectPoint(point.point, 1, 2, 3);
    expectDiffuse(point.pointAttributeSet, 1, 1, 1);
    Q3Point_EmptyData(&point);
}

TEST_F(FileCatalogTest, CurvesAndQuadricsReadInTextAndBothByteOrders)
{
    for (const std::string& name : encodings("curves_quadrics")) {
        SCOPED_TRACE(name);
        const auto objects = readAll(dataFile(name));
        expectCurvesAndQuadrics(objects);
        disposeAll(objects);
    }
}

// ---- attributes ---------------------------------------------------------------

void expectAttributes(const std::vector<TQ3Object>& objects)
{
    ASSERT_EQ(objects.size(), 2u);
    ASSERT_EQ(Q3Object_GetLeafType(objects[0]), kQ3GeometryTypeTriangle);
    TQ3AttributeSet set = nullptr;
    ASSERT_EQ(Q3Geometry_GetAttributeSet(objects[0], &set), kQ3Success);
    ASSERT_NE(set, nullptr);
    TQ3Param2D uv{};
    ASSERT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeSurfaceUV, &uv), kQ3Success);
    EXPECT_EQ(uv.u, 0.25f);
    EXPECT_EQ(uv.v, 0.75f);
    ASSERT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeShadingUV, &uv), kQ3Success);
    EXPECT_EQ(uv.u, 0.5f);
    EXPECT_EQ(uv.v, 0.125f);
    TQ3Vector3D normal{};
    ASSERT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeNormal, &normal), kQ3Success);
    expectVector(normal, 0, 0, 1);
    float value = 0;
    ASSERT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeAmbientCoefficient, &value), kQ3Success);
    EXPECT_EQ(value, 0.4f);
    TQ3ColorRGB color{};
    ASSERT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeDiffuseColor, &color), kQ3Success);
    expectColor(color, 0.2f, 0.4f, 0.6f);
    ASSERT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeSpecularColor, &color), kQ3Success);
    expectColor(color, 1, 1, 0.5f);
    ASSERT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeSpecularControl, &value), kQ3Success);
    EXPECT_EQ(value, 16);
    ASSERT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeTransparencyColor, &color), kQ3Success);
    expectColor(color, 0.5f, 0.25f, 0.75f);
    TQ3Tangent2D tangent{};
    ASSERT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeSurfaceTangent, &tangent), kQ3Success);
    expectVector(tangent.uTangent, 1, 0, 0);
    expectVector(tangent.vTangent, 0, 1, 0);
    TQ3Switch highlight = kQ3Off;
    ASSERT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeHighlightState, &highlight), kQ3Success);
    EXPECT_EQ(highlight, kQ3On);
    Q3Object_Dispose(set);

    ASSERT_EQ(Q3Object_GetLeafType(objects[1]), kQ3GeometryTypeTriMesh);
    TQ3TriMeshData mesh{};
    ASSERT_EQ(Q3TriMesh_GetData(objects[1], &mesh), kQ3Success);
    ASSERT_EQ(mesh.numTriangles, 4u);
    const unsigned long triangles[12] = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    for (unsigned long t = 0; t < 4; ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(mesh.triangles[t].pointIndices[k], triangles[3 * t + k]);
    EXPECT_EQ(mesh.numEdges, 0u);
    ASSERT_EQ(mesh.numPoints, 5u);
    expectPoint(mesh.points[0], -1, -1, 0);
    expectPoint(mesh.points[2], 1, 1, 0);
    expectPoint(mesh.points[4], 0, 0, 1);
    expectPoint(mesh.bBox.min, -1, -1, 0);
    expectPoint(mesh.bBox.max, 1, 1, 1);
    EXPECT_EQ(mesh.bBox.isEmpty, kQ3False);
    ASSERT_EQ(mesh.numTriangleAttributeTypes, 1u);
    EXPECT_EQ(mesh.triangleAttributeTypes[0].attributeType, kQ3AttributeTypeDiffuseColor);
    ASSERT_NE(mesh.triangleAttributeTypes[0].attributeUseArray, nullptr);
    const char use[4] = {1, 0, 1, 1};
    EXPECT_EQ(std::memcmp(mesh.triangleAttributeTypes[0].attributeUseArray, use, 4), 0);
    const auto* colors = static_cast<const TQ3ColorRGB*>(mesh.triangleAttributeTypes[0].data);
    expectColor(colors[0], 1, 0, 0);
    expectColor(colors[2], 0, 0, 1);
    expectColor(colors[3], 1, 1, 0);
    ASSERT_EQ(mesh.numVertexAttributeTypes, 1u);
    EXPECT_EQ(mesh.vertexAttributeTypes[0].attributeType, kQ3AttributeTypeNormal);
    EXPECT_EQ(mesh.vertexAttributeTypes[0].attributeUseArray, nullptr);
    const auto* normals = static_cast<const TQ3Vector3D*>(mesh.vertexAttributeTypes[0].data);
    expectVector(normals[0], 0, 0, 1);
    expectVector(normals[4], 0, 0.6f, 0.8f);
    EXPECT_EQ(mesh.numEdgeAttributeTypes, 0u);
    Q3TriMesh_EmptyData(&mesh);
}

TEST_F(FileCatalogTest, EveryAttributeAndTriMeshArraysReadInTextAndBothByteOrders)
{
    for (const std::string& name : encodings("attributes")) {
        SCOPED_TRACE(name);
        TQ3FileMode mode = 0;
        TQ3FileObject file = openBytes(dataFile(name), &mode);
        ASSERT_NE(file, nullptr);
        EXPECT_EQ(mode & ~(kQ3FileModeText | kQ3FileModeSwap), kQ3FileModeStream);
        EXPECT_EQ((mode & kQ3FileModeSwap) != 0, name.find("_le") != std::string::npos);
        Q3File_Close(file);
        Q3Object_Dispose(file);
        const auto objects = readAll(dataFile(name));
        expectAttributes(objects);
        disposeAll(objects);
    }
}

// ---- styles_shaders -----------------------------------------------------------

void expectStylesAndShaders(const std::vector<TQ3Object>& objects)
{
    ASSERT_EQ(objects.size(), 15u);
    TQ3SubdivisionStyleData subdivision{};
    ASSERT_EQ(Q3SubdivisionStyle_GetData(objects[0], &subdivision), kQ3Success);
    EXPECT_EQ(subdivision.method, kQ3SubdivisionMethodWorldSpace);
    EXPECT_EQ(subdivision.c1, 0.5f);

    TQ3AntiAliasStyleData antiAlias{};
    ASSERT_EQ(Q3AntiAliasStyle_GetData(objects[1], &antiAlias), kQ3Success);
    EXPECT_EQ(antiAlias.state, kQ3On);
    EXPECT_EQ(antiAlias.mode, kQ3AntiAliasModeMaskEdges | kQ3AntiAliasModeMaskFilled);
    EXPECT_EQ(antiAlias.quality, 0.75f);

    TQ3FogStyleData fog{};
    ASSERT_EQ(Q3FogStyle_GetData(objects[2], &fog), kQ3Success);
    EXPECT_EQ(fog.state, kQ3On);
    EXPECT_EQ(fog.mode, kQ3FogModeExponential);
    EXPECT_EQ(fog.fogStart, 2);
    EXPECT_EQ(fog.fogEnd, 40);
    EXPECT_EQ(fog.density, 0.25f);
    EXPECT_EQ(fog.color.a, 0.5f);
    EXPECT_EQ(fog.color.r, 0.7f);
    EXPECT_EQ(fog.color.g, 0.8f);
    EXPECT_EQ(fog.color.b, 0.9f);

    TQ3InterpolationStyle interpolation = kQ3InterpolationStyleNone;
    ASSERT_EQ(Q3InterpolationStyle_Get(objects[3], &interpolation), kQ3Success);
    EXPECT_EQ(interpolation, kQ3InterpolationStylePixel);
    TQ3OrientationStyle orientation = kQ3OrientationStyleCounterClockwise;
    ASSERT_EQ(Q3OrientationStyle_Get(objects[4], &orientation), kQ3Success);
    EXPECT_EQ(orientation, kQ3OrientationStyleClockwise);
    unsigned long pickID = 0;
    ASSERT_EQ(Q3PickIDStyle_Get(objects[5], &pickID), kQ3Success);
    EXPECT_EQ(pickID, 4242u);
    TQ3PickParts parts = 0;
    ASSERT_EQ(Q3PickPartsStyle_Get(objects[6], &parts), kQ3Success);
    EXPECT_EQ(parts, static_cast<TQ3PickParts>(kQ3PickPartsMaskFace | kQ3PickPartsMaskVertex));
    TQ3Boolean casts = kQ3True;
    ASSERT_EQ(Q3CastShadowsStyle_Get(objects[7], &casts), kQ3Success);
    EXPECT_EQ(casts, kQ3False);
    TQ3Boolean receives = kQ3False;
    ASSERT_EQ(Q3ReceiveShadowsStyle_Get(objects[8], &receives), kQ3Success);
    EXPECT_EQ(receives, kQ3True);
    TQ3BackfacingStyle backfacing = kQ3BackfacingStyleBoth;
    ASSERT_EQ(Q3BackfacingStyle_Get(objects[9], &backfacing), kQ3Success);
    EXPECT_EQ(backfacing, kQ3BackfacingStyleRemove);
    TQ3FillStyle fill = kQ3FillStyleFilled;
    ASSERT_EQ(Q3FillStyle_Get(objects[10], &fill), kQ3Success);
    EXPECT_EQ(fill, kQ3FillStyleEdges);
    EXPECT_EQ(Q3Object_GetLeafType(objects[11]), kQ3IlluminationTypeLambert);
    EXPECT_EQ(Q3Object_GetLeafType(objects[12]), kQ3IlluminationTypeNULL);
    EXPECT_EQ(Q3Object_GetLeafType(objects[13]), kQ3IlluminationTypePhong);

    // The reference through the table of contents gives the pick ID style.
    ASSERT_EQ(Q3Object_GetLeafType(objects[14]), kQ3StyleTypePickID);
    pickID = 0;
    ASSERT_EQ(Q3PickIDStyle_Get(objects[14], &pickID), kQ3Success);
    EXPECT_EQ(pickID, 4242u);
}

TEST_F(FileCatalogTest, StylesAndShadersOfADatabaseFileReadInTextAndBothByteOrders)
{
    for (const std::string& name : encodings("styles_shaders")) {
        SCOPED_TRACE(name);
        TQ3FileMode mode = 0;
        TQ3FileObject file = openBytes(dataFile(name), &mode);
        ASSERT_NE(file, nullptr);
        EXPECT_EQ(mode & ~(kQ3FileModeText | kQ3FileModeSwap), kQ3FileModeDatabase);
        EXPECT_EQ((mode & kQ3FileModeSwap) != 0, name.find("_le") != std::string::npos);
        Q3File_Close(file);
        Q3Object_Dispose(file);
        const auto objects = readAll(dataFile(name));
        expectStylesAndShaders(objects);
        disposeAll(objects);
    }
}

// ---- lights_transforms_groups ---------------------------------------------------

void expectLightData(const TQ3LightData& data, TQ3Boolean isOn, float brightness, float r, float g, float b)
{
    EXPECT_EQ(data.isOn, isOn);
    EXPECT_EQ(data.brightness, brightness);
    expectColor(data.color, r, g, b);
}

void expectLights(TQ3Object group)
{
    ASSERT_EQ(Q3Object_GetLeafType(group), kQ3GroupTypeLight);
    const auto lights = members(group);
    ASSERT_EQ(lights.size(), 4u);
    TQ3LightData ambient{};
    ASSERT_EQ(Q3AmbientLight_GetData(lights[0], &ambient), kQ3Success);
    expectLightData(ambient, kQ3True, 0.25f, 1, 0.9f, 0.8f);

    TQ3DirectionalLightData directional{};
    ASSERT_EQ(Q3DirectionalLight_GetData(lights[1], &directional), kQ3Success);
    expectVector(directional.direction, 0, -1, 0);
    EXPECT_EQ(directional.castsShadows, kQ3True);
    expectLightData(directional.lightData, kQ3False, 0.5f, 0.2f, 0.3f, 0.4f);

    TQ3PointLightData point{};
    ASSERT_EQ(Q3PointLight_GetData(lights[2], &point), kQ3Success);
    expectPoint(point.location, 1, 2, 3);
    EXPECT_EQ(point.attenuation, kQ3AttenuationTypeInverseDistance);
    EXPECT_EQ(point.castsShadows, kQ3False);
    expectLightData(point.lightData, kQ3True, 0.75f, 1, 1, 1);

    TQ3SpotLightData spot{};
    ASSERT_EQ(Q3SpotLight_GetData(lights[3], &spot), kQ3Success);
    expectPoint(spot.location, 0, 5, 0);
    expectVector(spot.direction, 0, -1, 0);
    EXPECT_EQ(spot.castsShadows, kQ3True);
    EXPECT_EQ(spot.attenuation, kQ3AttenuationTypeInverseDistanceSquared);
    EXPECT_EQ(spot.hotAngle, 0.3f);
    EXPECT_EQ(spot.outerAngle, 0.6f);
    EXPECT_EQ(spot.fallOff, kQ3FallOffTypeCosine);
    expectLightData(spot.lightData, kQ3True, 1, 0.5f, 0.5f, 1);
    disposeAll(lights);
}

void expectTransformsAndGroups(TQ3Object group)
{
    ASSERT_EQ(Q3Object_GetLeafType(group), kQ3ShapeTypeGroup);
    const auto outer = members(group);
    ASSERT_EQ(outer.size(), 7u);

    TQ3Matrix4x4 matrix{};
    ASSERT_EQ(Q3MatrixTransform_Get(outer[0], &matrix), kQ3Success);
    const float expected[4][4] = {{1, 0, 0, 0}, {0, 2, 0, 0}, {0, 0, 3, 0}, {4, 5, 6, 1}};
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column)
            EXPECT_EQ(matrix.value[row][column], expected[row][column]) << row << " " << column;
    TQ3Vector3D vector{};
    ASSERT_EQ(Q3TranslateTransform_Get(outer[1], &vector), kQ3Success);
    expectVector(vector, 1, -2, 3);
    ASSERT_EQ(Q3ScaleTransform_Get(outer[2], &vector), kQ3Success);
    expectVector(vector, 2, 3, 4);
    TQ3RotateTransformData rotate{};
    ASSERT_EQ(Q3RotateTransform_GetData(outer[3], &rotate), kQ3Success);
    EXPECT_EQ(rotate.axis, kQ3AxisY);
    EXPECT_EQ(rotate.radians, 1.5f);
    EXPECT_EQ(Q3Object_GetLeafType(outer[4]), kQ3TransformTypeReset);

    // Display group (Inline, not picked) > ordered display group and I/O
    // proxy group.
    ASSERT_EQ(Q3Object_GetLeafType(outer[5]), kQ3GroupTypeDisplay);
    TQ3DisplayGroupState state = 0;
    ASSERT_EQ(Q3DisplayGroup_GetState(outer[5], &state), kQ3Success);
    EXPECT_EQ(state, kQ3DisplayGroupStateMaskIsDrawn | kQ3DisplayGroupStateMaskIsInline |
                         kQ3DisplayGroupStateMaskUseBoundingBox | kQ3DisplayGroupStateMaskUseBoundingSphere |
                         kQ3DisplayGroupStateMaskIsWritten);
    const auto inner = members(outer[5]);
    ASSERT_EQ(inner.size(), 2u);
    ASSERT_EQ(Q3Object_GetLeafType(inner[0]), kQ3DisplayGroupTypeOrdered);
    const auto ordered = members(inner[0]);
    ASSERT_EQ(ordered.size(), 2u);
    ASSERT_EQ(Q3Object_GetLeafType(ordered[0]), kQ3StyleTypeHighlight);
    TQ3AttributeSet highlight = nullptr;
    ASSERT_EQ(Q3HighlightStyle_Get(ordered[0], &highlight), kQ3Success);
    expectDiffuse(highlight, 1, 1, 0);
    Q3Object_Dispose(highlight);
    TQ3PointData point{};
    ASSERT_EQ(Q3Point_GetData(ordered[1], &point), kQ3Success);
    expectPoint(point.point, 0, 0, 0);
    Q3Point_EmptyData(&point);
    disposeAll(ordered);

    ASSERT_EQ(Q3Object_GetLeafType(inner[1]), kQ3DisplayGroupTypeIOProxy);
    const auto proxy = members(inner[1]);
    ASSERT_EQ(proxy.size(), 2u);
    EXPECT_EQ(Q3Object_GetLeafType(proxy[0]), kQ3GeometryTypePoint);
    EXPECT_EQ(Q3Object_GetLeafType(proxy[1]), kQ3GeometryTypeLine);
    disposeAll(proxy);
    disposeAll(inner);

    ASSERT_EQ(Q3Object_GetLeafType(outer[6]), kQ3GroupTypeInfo);
    EXPECT_TRUE(members(outer[6]).empty());
    disposeAll(outer);
}

TEST_F(FileCatalogTest, LightsTransformsAndNestedGroupsReadInTextAndBothByteOrders)
{
    for (const std::string& name : encodings("lights_transforms_groups")) {
        SCOPED_TRACE(name);
        const auto objects = readAll(dataFile(name));
        ASSERT_EQ(objects.size(), 2u);
        expectLights(objects[0]);
        expectTransformsAndGroups(objects[1]);
        disposeAll(objects);
    }
}

// ---- empty quadrics -----------------------------------------------------------------

// Apple's metafile parser (MF3D's mfobjcts.h) gives each quadric with no
// data a default, as for the box: orientation 1 0 0, major axis 0 1 0, minor
// axis 0 0 1, origin 0 0 0, ratio 1; disk and ellipse: major radius 1 0 0,
// minor radius 0 1 0, origin 0 0 0.
void expectDefaultQuadrics(const std::vector<TQ3Object>& objects)
{
    ASSERT_EQ(objects.size(), 6u);
    TQ3ConeData cone{};
    ASSERT_EQ(Q3Cone_GetData(objects[0], &cone), kQ3Success);
    expectVector(cone.orientation, 1, 0, 0);
    expectVector(cone.majorRadius, 0, 1, 0);
    expectVector(cone.minorRadius, 0, 0, 1);
    expectPoint(cone.origin, 0, 0, 0);
    EXPECT_EQ(cone.uMax, 1);
    Q3Cone_EmptyData(&cone);
    TQ3CylinderData cylinder{};
    ASSERT_EQ(Q3Cylinder_GetData(objects[1], &cylinder), kQ3Success);
    expectVector(cylinder.orientation, 1, 0, 0);
    expectVector(cylinder.majorRadius, 0, 1, 0);
    expectVector(cylinder.minorRadius, 0, 0, 1);
    Q3Cylinder_EmptyData(&cylinder);
    TQ3EllipsoidData ellipsoid{};
    ASSERT_EQ(Q3Ellipsoid_GetData(objects[2], &ellipsoid), kQ3Success);
    expectVector(ellipsoid.orientation, 1, 0, 0);
    expectVector(ellipsoid.minorRadius, 0, 0, 1);
    expectPoint(ellipsoid.origin, 0, 0, 0);
    Q3Ellipsoid_EmptyData(&ellipsoid);
    TQ3TorusData torus{};
    ASSERT_EQ(Q3Torus_GetData(objects[3], &torus), kQ3Success);
    expectVector(torus.orientation, 1, 0, 0);
    expectVector(torus.majorRadius, 0, 1, 0);
    EXPECT_EQ(torus.ratio, 1);
    Q3Torus_EmptyData(&torus);
    TQ3DiskData disk{};
    ASSERT_EQ(Q3Disk_GetData(objects[4], &disk), kQ3Success);
    expectVector(disk.majorRadius, 1, 0, 0);
    expectVector(disk.minorRadius, 0, 1, 0);
    expectPoint(disk.origin, 0, 0, 0);
    EXPECT_EQ(disk.uMax, 1);
    Q3Disk_EmptyData(&disk);
    TQ3EllipseData ellipse{};
    ASSERT_EQ(Q3Ellipse_GetData(objects[5], &ellipse), kQ3Success);
    expectVector(ellipse.majorRadius, 1, 0, 0);
    expectVector(ellipse.minorRadius, 0, 1, 0);
    EXPECT_EQ(ellipse.uMax, 1);
    Q3Ellipse_EmptyData(&ellipse);
}

TEST_F(FileCatalogTest, QuadricsWithNoDataAreAppleParsersDefaults)
{
    const auto text = readAll(bytesOf("3DMetafile ( 1 6 Stream )\n"
                                      "Cone ( ) Cylinder ( ) Ellipsoid ( ) Torus ( ) Disk ( ) Ellipse ( )\n"));
    expectDefaultQuadrics(text);
    disposeAll(text);
    auto bytes = binaryHeader();
    for (const char* tag : {"cone", "cyln", "elpd", "tors", "disk", "elps"}) {
        putTag(bytes, tag);
        put32(bytes, 0);
    }
    const auto binary = readAll(bytes);
    expectDefaultQuadrics(binary);
    disposeAll(binary);
}

// ---- MF3D's attenuation coefficients --------------------------------------------------

// Apple's 1995 metafile parser (MF3D) and the QD3D 1.5.4 book's point light
// example hold a point or spot light's attenuation as three coefficients
// c0 c1 c2; Q3 reads them as the QuickDraw 3D attenuation type they come
// nearest to (a squared term, else a linear one, else none).
TQ3AttenuationType pointAttenuation(TQ3Object light)
{
    TQ3PointLightData data{};
    EXPECT_EQ(Q3PointLight_GetData(light, &data), kQ3Success);
    return data.attenuation;
}

TQ3AttenuationType spotAttenuation(TQ3Object light, float* hotAngle, TQ3FallOffType* fallOff)
{
    TQ3SpotLightData data{};
    EXPECT_EQ(Q3SpotLight_GetData(light, &data), kQ3Success);
    *hotAngle = data.hotAngle;
    *fallOff = data.fallOff;
    return data.attenuation;
}

TEST_F(FileCatalogTest, AttenuationAsThreeCoefficientsReadsAsTheNearestType)
{
    const auto text = readAll(bytesOf("3DMetafile ( 1 6 Stream )\n"
                                      "PointLight ( 1 2 3  1 0 1  True )\n"
                                      "PointLight ( 1 2 3  1 0.5 0  False )\n"
                                      "PointLight ( 1 2 3  1 0 0  False )\n"
                                      "SpotLight ( 0 5 0  0 -1 0  True  0 2 0  0.3 0.6 Cosine )\n"));
    ASSERT_EQ(text.size(), 4u);
    EXPECT_EQ(pointAttenuation(text[0]), kQ3AttenuationTypeInverseDistanceSquared);
    EXPECT_EQ(pointAttenuation(text[1]), kQ3AttenuationTypeInverseDistance);
    EXPECT_EQ(pointAttenuation(text[2]), kQ3AttenuationTypeNone);
    float hot = 0;
    TQ3FallOffType fallOff = kQ3FallOffTypeNone;
    EXPECT_EQ(spotAttenuation(text[3], &hot, &fallOff), kQ3AttenuationTypeInverseDistance);
    EXPECT_EQ(hot, 0.3f);
    EXPECT_EQ(fallOff, kQ3FallOffTypeCosine);
    disposeAll(text);

    // The same in binary, laid out by hand: a 28-byte point light (location,
    // three Float32, castsShadows) and a 52-byte spot light.
    auto bytes = binaryHeader();
    putTag(bytes, "pntl");
    put32(bytes, 28);
    for (float f : {1.0f, 2.0f, 3.0f, 1.0f, 0.0f, 0.25f})
        putFloat(bytes, f);
    put32(bytes, 1);
    putTag(bytes, "spot");
    put32(bytes, 52);
    for (float f : {0.0f, 5.0f, 0.0f, 0.0f, -1.0f, 0.0f})
        putFloat(bytes, f);
    put32(bytes, 0);
    for (float f : {1.0f, 0.0f, 0.0f, 0.3f, 0.6f})
        putFloat(bytes, f);
    put32(bytes, kQ3FallOffTypeLinear);
    const auto binary = readAll(bytes);
    ASSERT_EQ(binary.size(), 2u);
    EXPECT_EQ(pointAttenuation(binary[0]), kQ3AttenuationTypeInverseDistanceSquared);
    EXPECT_EQ(spotAttenuation(binary[1], &hot, &fallOff), kQ3AttenuationTypeNone);
    EXPECT_EQ(hot, 0.3f);
    EXPECT_EQ(fallOff, kQ3FallOffTypeLinear);
    disposeAll(binary);

    // A negative coefficient is no attenuation of any kind.
    EXPECT_READ_ERROR(bytesOf("3DMetafile ( 1 6 Stream )\nPointLight ( 1 2 3  1 -1 0  True )\n"),
                      kQ3ErrorInvalidMetafileObject);
    // Four numbers fit neither form: the enumeration word is missing.
    EXPECT_READ_ERROR(bytesOf("3DMetafile ( 1 6 Stream )\nPointLight ( 1 2 3  1 0 0 0  True )\n"),
                      kQ3ErrorInvalidMetafilePrimitive);
}

// ---- malformed variants -----------------------------------------------------------

/// The text with the first `from` replaced by `to`.
std::vector<unsigned char> replaced(const std::string& name, const std::string& from, const std::string& to)
{
    const auto bytes = dataFile(name);
    std::string text(bytes.begin(), bytes.end());
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos)
        text.replace(at, from.size(), to);
    return bytesOf(text);
}

/// The binary file with the 32-bit field `fieldIndex` words after the first
/// object tagged `tag` (0: its size) replaced by `value` in the file's byte order.
std::vector<unsigned char> patched(const std::string& name, const char* tag, std::size_t fieldIndex,
                                   std::uint32_t value)
{
    auto bytes = dataFile(name);
    const bool little = name.find("_le") != std::string::npos;
    char code[4];
    for (int i = 0; i < 4; ++i)
        code[i] = little ? tag[3 - i] : tag[i];
    const auto at = std::search(bytes.begin(), bytes.end(), code, code + 4);
    EXPECT_NE(at, bytes.end()) << tag;
    if (at == bytes.end())
        return bytes;
    const std::size_t field = static_cast<std::size_t>(at - bytes.begin()) + 4 + 4 * fieldIndex;
    for (int i = 0; i < 4; ++i)
        bytes[field + i] = static_cast<unsigned char>(little ? value >> (8 * i) : value >> (24 - 8 * i));
    return bytes;
}

TEST_F(FileCatalogTest, MalformedTextVariantsAreFileErrors)
{
    // Bad enumeration words.
    EXPECT_READ_ERROR(replaced("styles_shaders.3dmf", "FogStyle ( On Exponential", "FogStyle ( On Foggy"),
                      kQ3ErrorInvalidMetafilePrimitive);
    EXPECT_READ_ERROR(replaced("styles_shaders.3dmf", "FillStyle ( Edges )", "FillStyle ( Dotted )"),
                      kQ3ErrorInvalidMetafilePrimitive);
    EXPECT_READ_ERROR(replaced("lights_transforms_groups.3dmf", "InverseDistanceSquared", "Squared"),
                      kQ3ErrorInvalidMetafilePrimitive);
    EXPECT_READ_ERROR(replaced("lights_transforms_groups.3dmf", "Rotate ( Y", "Rotate ( W"),
                      kQ3ErrorInvalidMetafilePrimitive);
    // A count the data cannot hold, and one that leaves data over.
    EXPECT_READ_ERROR(replaced("curves_quadrics.3dmf", "    3 4  ", "    3 5  "), kQ3ErrorInvalidMetafileObject);
    EXPECT_READ_ERROR(replaced("curves_quadrics.3dmf", "Polygon ( 4 ", "Polygon ( 4000000000 "),
                      kQ3ErrorInvalidMetafileObject);
    // Too few fields.
    EXPECT_READ_ERROR(replaced("lights_transforms_groups.3dmf", "Scale ( 2 3 4 )", "Scale ( 2 3 )"),
                      kQ3ErrorInvalidMetafilePrimitive);
    EXPECT_READ_ERROR(replaced("attributes.3dmf", "SurfaceTangent ( 1 0 0  0 1 0 )", "SurfaceTangent ( 1 0 0  0 1 )"),
                      kQ3ErrorInvalidMetafilePrimitive);
    // A value the class refuses: a hot angle past the outer angle.
    EXPECT_READ_ERROR(replaced("lights_transforms_groups.3dmf", "0.3 0.6 Cosine", "0.9 0.6 Cosine"),
                      kQ3ErrorInvalidMetafileObject);
    // A reference the table of contents lacks.
    EXPECT_READ_ERROR(replaced("styles_shaders.3dmf", "Reference ( 6 )", "Reference ( 16 )"),
                      kQ3ErrorInvalidMetafileObject);
    // The outer group's EndGroup missing, the file ending with an inner
    // group's EndGroup.
    const auto groups = dataFile("lights_transforms_groups.3dmf");
    const std::string groupsText(groups.begin(), groups.end());
    ASSERT_EQ(groupsText.substr(groupsText.size() - 28), "  EndGroup ( )\nEndGroup ( )\n");
    EXPECT_READ_ERROR(bytesOf(groupsText.substr(0, groupsText.size() - 13)), kQ3ErrorInvalidMetafile);
    // Truncated inside an object.
    const auto curves = dataFile("curves_quadrics.3dmf");
    const std::string text(curves.begin(), curves.end());
    EXPECT_READ_ERROR(bytesOf(text.substr(0, text.find("0 0 0 0.5 1 1 1"))), kQ3ErrorInvalidMetafile);
}

/// Where each top-level object of a binary file ends outside any group
/// (BeginGroup ... EndGroup counts as one object).
TEST_F(FileCatalogTest, MalformedBinaryVariantsAreFileErrors)
{
    for (const char* order : {"_be", "_le"}) {
        SCOPED_TRACE(order);
        const std::string styles = std::string("styles_shaders") + order + ".3dmf";
        const std::string lights = std::string("lights_transforms_groups") + order + ".3dmf";
        const std::string curves = std::string("curves_quadrics") + order + ".3dmf";
        // Enumeration values that are none of their words: fog mode 7,
        // spot fall-off 9, rotation axis 3.
        EXPECT_READ_ERROR(patched(styles, "fogg", 2, 7), kQ3ErrorInvalidMetafilePrimitive);
        EXPECT_READ_ERROR(patched(lights, "spot", 11, 9), kQ3ErrorInvalidMetafilePrimitive);
        EXPECT_READ_ERROR(patched(lights, "rott", 1, 3), kQ3ErrorInvalidMetafilePrimitive);
        // Counts the data cannot hold.
        EXPECT_READ_ERROR(patched(curves, "nrbc", 2, 5), kQ3ErrorInvalidMetafileObject);
        EXPECT_READ_ERROR(patched(curves, "plyg", 1, 0x7FFFFFFF), kQ3ErrorInvalidMetafileObject);
        // A size that overruns its container.
        EXPECT_READ_ERROR(patched(curves, "disk", 0, 0x1000), kQ3ErrorInvalidMetafile);
        // Every cut of the file is an error, never a crash.
        for (const std::string& name : {styles, lights, curves}) {
            const auto binary = dataFile(name);
            ASSERT_GT(binary.size(), 24u);
            const auto ends = topLevelEnds(binary, order[1] == 'l');
            for (std::size_t cut = 25; cut < binary.size(); cut += 11) {
                const TQ3Error error = readError(std::vector<unsigned char>(binary.begin(), binary.begin() + cut));
                if (std::find(ends.begin(), ends.end(), cut) != ends.end()) {
                    // A cut between two top-level objects leaves a whole
                    // file (the styles' table of contents is last).
                    EXPECT_EQ(error, kQ3ErrorNone) << name << " cut at " << cut;
                    continue;
                }
                if (cutLeavesJunk(binary, cut, order[1] == 'l')) {
                    consume(q3test::Kind::Warning, kQ3WarningInvalidMetafileObject, "a cut catalogue file",
                            __FILE__, __LINE__);
                    if (error == kQ3ErrorNone)
                        continue;
                }
                EXPECT_TRUE(error == kQ3ErrorInvalidMetafile || error == kQ3ErrorInvalidMetafilePrimitive ||
                            error == kQ3ErrorInvalidMetafileObject || error == kQ3ErrorInvalidMetafileLabel)
                    << name << " cut at " << cut << ": " << error;
                consume(q3test::Kind::Error, error, "a cut catalogue file", __FILE__, __LINE__);
            }
        }
    }
}

} // namespace
