/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Legacy code for QuickDraw 3D 1.6's general polygons, polyhedra, triangle
 * grids, markers and pixmap markers, written the way 1990s Macintosh samples were
 * (declarations first, Apple's headers by their own names, every status
 * checked), built with nothing but -I include/Q3: it must compile unmodified
 * against Q3. It calls every routine of the five types, bounds what it made
 * and draws it into a pixmap. Returns 0 when every call did what the 1.6 API
 * promises.
 */
#include <QD3D.h>
#include <QD3DCamera.h>
#include <QD3DDrawContext.h>
#include <QD3DErrors.h>
#include <QD3DGeometry.h>
#include <QD3DMath.h>
#include <QD3DRenderer.h>
#include <QD3DSet.h>
#include <QD3DStorage.h>
#include <QD3DView.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "LegacyCommon.h"

const char *gMyProgramName = "LegacyPolygons";

static void MyGeneralPolygon(TQ3ViewObject view, TQ3AttributeSet red)
{
    TQ3Vertex3D outer[4], hole[3];
    TQ3GeneralPolygonContourData contours[2];
    TQ3GeneralPolygonData data;
    TQ3GeometryObject polygon;
    TQ3GeneralPolygonShapeHint hint;
    TQ3Point3D point;
    TQ3AttributeSet set;
    TQ3BoundingBox bounds;
    short i;

    for (i = 0; i < 4; i++)
        outer[i].attributeSet = NULL;
    for (i = 0; i < 3; i++)
        hole[i].attributeSet = NULL;
    Q3Point3D_Set(&outer[0].point, -2.0f, -2.0f, 0.0f);
    Q3Point3D_Set(&outer[1].point, 2.0f, -2.0f, 0.0f);
    Q3Point3D_Set(&outer[2].point, 2.0f, 2.0f, 0.0f);
    Q3Point3D_Set(&outer[3].point, -2.0f, 2.0f, 0.0f);
    Q3Point3D_Set(&hole[0].point, -1.0f, -1.0f, 0.0f);
    Q3Point3D_Set(&hole[1].point, 1.0f, -1.0f, 0.0f);
    Q3Point3D_Set(&hole[2].point, 0.0f, 1.0f, 0.0f);
    contours[0].numVertices = 4;
    contours[0].vertices = outer;
    contours[1].numVertices = 3;
    contours[1].vertices = hole;
    data.numContours = 2;
    data.contours = contours;
    data.shapeHint = kQ3GeneralPolygonShapeHintComplex;
    data.generalPolygonAttributeSet = red;

    polygon = Q3GeneralPolygon_New(&data);
    if (polygon == NULL) {
        gFailures++;
        return;
    }
    CHECK(Q3GeneralPolygon_GetVertexPosition(polygon, 1, 2, &point));
    Check((TQ3Boolean)(point.y == 1.0f), "the hole's third vertex");
    point.z = 0.5f;
    CHECK(Q3GeneralPolygon_SetVertexPosition(polygon, 1, 2, &point));
    CHECK(Q3GeneralPolygon_SetVertexAttributeSet(polygon, 0, 3, red));
    CHECK(Q3GeneralPolygon_GetVertexAttributeSet(polygon, 0, 3, &set));
    MyCheckAndDisposeSet(set, red, "the corner's set");
    CHECK(Q3GeneralPolygon_SetShapeHint(polygon, kQ3GeneralPolygonShapeHintConcave));
    CHECK(Q3GeneralPolygon_GetShapeHint(polygon, &hint));
    Check((TQ3Boolean)(hint == kQ3GeneralPolygonShapeHintConcave), "the shape hint");
    Check((TQ3Boolean)(Q3GeneralPolygon_GetVertexPosition(polygon, 2, 0, &point) == kQ3Failure),
          "contour 2 refused");
    CHECK(Q3GeneralPolygon_GetData(polygon, &data));
    CHECK(Q3GeneralPolygon_SetData(polygon, &data));
    CHECK(Q3View_StartBoundingBox(view, kQ3ComputeBoundsApproximate));
    do {
        CHECK(Q3GeneralPolygon_Submit(&data, view));
    } while (Q3View_EndBoundingBox(view, &bounds) == kQ3ViewStatusRetraverse);
    CHECK(Q3GeneralPolygon_EmptyData(&data));
    MyBoundAndDispose(view, polygon);
}

static void MyPolyhedron(TQ3ViewObject view, TQ3AttributeSet red)
{
    TQ3Vertex3D vertices[4];
    TQ3PolyhedronTriangleData triangles[4];
    TQ3PolyhedronEdgeData edges[1];
    TQ3PolyhedronData data;
    TQ3GeometryObject polyhedron;
    TQ3PolyhedronTriangleData triangle;
    TQ3PolyhedronEdgeData edge;
    TQ3Point3D point;
    TQ3AttributeSet set;
    TQ3BoundingBox bounds;
    static unsigned long faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    short i, k;

    for (i = 0; i < 4; i++) {
        vertices[i].attributeSet = NULL;
        for (k = 0; k < 3; k++)
            triangles[i].vertexIndices[k] = faces[i][k];
        triangles[i].edgeFlag = kQ3PolyhedronEdgeAll;
        triangles[i].triangleAttributeSet = NULL;
    }
    Q3Point3D_Set(&vertices[0].point, 0.0f, 0.0f, 0.0f);
    Q3Point3D_Set(&vertices[1].point, 1.0f, 0.0f, 0.0f);
    Q3Point3D_Set(&vertices[2].point, 0.0f, 1.0f, 0.0f);
    Q3Point3D_Set(&vertices[3].point, 0.0f, 0.0f, 1.0f);
    triangles[2].edgeFlag = kQ3PolyhedronEdge01 | kQ3PolyhedronEdge12;
    triangles[3].triangleAttributeSet = red;
    edges[0].vertexIndices[0] = 1;
    edges[0].vertexIndices[1] = 3;
    edges[0].triangleIndices[0] = 1;
    edges[0].triangleIndices[1] = kQ3ArrayIndexNULL;
    edges[0].edgeAttributeSet = red;
    data.numVertices = 4;
    data.vertices = vertices;
    data.numEdges = 1;
    data.edges = edges;
    data.numTriangles = 4;
    data.triangles = triangles;
    data.polyhedronAttributeSet = NULL;

    polyhedron = Q3Polyhedron_New(&data);
    if (polyhedron == NULL) {
        gFailures++;
        return;
    }
    CHECK(Q3Polyhedron_GetVertexPosition(polyhedron, 3, &point));
    CHECK(Q3Polyhedron_SetVertexPosition(polyhedron, 3, &point));
    CHECK(Q3Polyhedron_SetVertexAttributeSet(polyhedron, 0, red));
    CHECK(Q3Polyhedron_GetVertexAttributeSet(polyhedron, 0, &set));
    MyCheckAndDisposeSet(set, red, "vertex 0's set");
    CHECK(Q3Polyhedron_GetTriangleData(polyhedron, 3, &triangle));
    MyCheckAndDisposeSet(triangle.triangleAttributeSet, red, "triangle 3's set");
    triangle.triangleAttributeSet = NULL;
    triangle.edgeFlag = kQ3PolyhedronEdgeNone;
    CHECK(Q3Polyhedron_SetTriangleData(polyhedron, 3, &triangle));
    CHECK(Q3Polyhedron_GetEdgeData(polyhedron, 0, &edge));
    MyCheckAndDisposeSet(edge.edgeAttributeSet, red, "edge 0's set");
    edge.edgeAttributeSet = NULL;
    CHECK(Q3Polyhedron_SetEdgeData(polyhedron, 0, &edge));
    Check((TQ3Boolean)(Q3Polyhedron_GetEdgeData(polyhedron, 1, &edge) == kQ3Failure), "edge 1 refused");
    CHECK(Q3Polyhedron_GetData(polyhedron, &data));
    CHECK(Q3Polyhedron_SetData(polyhedron, &data));
    CHECK(Q3View_StartBoundingBox(view, kQ3ComputeBoundsApproximate));
    do {
        CHECK(Q3Polyhedron_Submit(&data, view));
    } while (Q3View_EndBoundingBox(view, &bounds) == kQ3ViewStatusRetraverse);
    CHECK(Q3Polyhedron_EmptyData(&data));
    MyBoundAndDispose(view, polyhedron);
}

static void MyTriGrid(TQ3ViewObject view, TQ3AttributeSet red)
{
    TQ3Vertex3D vertices[6];
    TQ3TriGridData data;
    TQ3GeometryObject grid;
    TQ3Point3D point;
    TQ3AttributeSet set;
    TQ3BoundingBox bounds;
    short i;

    for (i = 0; i < 6; i++) {
        Q3Point3D_Set(&vertices[i].point, (float)(i % 3), (float)(i / 3), 0.0f);
        vertices[i].attributeSet = NULL;
    }
    data.numRows = 2;
    data.numColumns = 3;
    data.vertices = vertices;
    data.facetAttributeSet = NULL;
    data.triGridAttributeSet = red;

    grid = Q3TriGrid_New(&data);
    if (grid == NULL) {
        gFailures++;
        return;
    }
    CHECK(Q3TriGrid_GetVertexPosition(grid, 1, 2, &point));
    Check((TQ3Boolean)(point.x == 2.0f && point.y == 1.0f), "vertex (1, 2)");
    point.z = 1.0f;
    CHECK(Q3TriGrid_SetVertexPosition(grid, 1, 2, &point));
    CHECK(Q3TriGrid_SetVertexAttributeSet(grid, 0, 0, red));
    CHECK(Q3TriGrid_GetVertexAttributeSet(grid, 0, 0, &set));
    MyCheckAndDisposeSet(set, red, "vertex (0, 0)'s set");
    CHECK(Q3TriGrid_SetFacetAttributeSet(grid, 3, red));
    CHECK(Q3TriGrid_GetFacetAttributeSet(grid, 3, &set));
    MyCheckAndDisposeSet(set, red, "facet 3's set");
    Check((TQ3Boolean)(Q3TriGrid_SetFacetAttributeSet(grid, 4, red) == kQ3Failure), "facet 4 refused");
    CHECK(Q3TriGrid_GetData(grid, &data));
    CHECK(Q3TriGrid_SetData(grid, &data));
    CHECK(Q3View_StartBoundingBox(view, kQ3ComputeBoundsApproximate));
    do {
        CHECK(Q3TriGrid_Submit(&data, view));
    } while (Q3View_EndBoundingBox(view, &bounds) == kQ3ViewStatusRetraverse);
    CHECK(Q3TriGrid_EmptyData(&data));
    MyBoundAndDispose(view, grid);
}

static TQ3GeometryObject MyMarker(TQ3AttributeSet red)
{
    static unsigned char bits[4] = {0xF0, 0x90, 0x90, 0xF0};
    TQ3MarkerData data;
    TQ3GeometryObject marker;
    TQ3Point3D location;
    TQ3Bitmap bitmap;
    long offset;

    Q3Point3D_Set(&data.location, 0.0f, 0.0f, 0.0f);
    data.xOffset = -2;
    data.yOffset = -2;
    data.bitmap.image = bits;
    data.bitmap.width = 4;
    data.bitmap.height = 4;
    data.bitmap.rowBytes = 1;
    data.bitmap.bitOrder = kQ3EndianBig;
    data.markerAttributeSet = red;

    marker = Q3Marker_New(&data);
    if (marker == NULL) {
        gFailures++;
        return NULL;
    }
    CHECK(Q3Marker_GetPosition(marker, &location));
    CHECK(Q3Marker_SetPosition(marker, &location));
    CHECK(Q3Marker_GetXOffset(marker, &offset));
    CHECK(Q3Marker_SetXOffset(marker, offset - 1));
    CHECK(Q3Marker_GetYOffset(marker, &offset));
    CHECK(Q3Marker_SetYOffset(marker, offset - 1));
    CHECK(Q3Marker_GetBitmap(marker, &bitmap));
    Check((TQ3Boolean)(bitmap.image != bits && bitmap.image[1] == 0x90), "the bitmap's copy");
    CHECK(Q3Marker_SetBitmap(marker, &bitmap));
    CHECK(Q3Bitmap_Empty(&bitmap));
    CHECK(Q3Marker_GetData(marker, &data));
    CHECK(Q3Marker_SetData(marker, &data));
    CHECK(Q3Marker_EmptyData(&data));
    return marker;
}

/* A 2 x 2 pixmap marker of red ARGB32 pixels (one transparent), its pixels in
 * a memory storage. */
static TQ3GeometryObject MyPixmapMarker(void)
{
    static unsigned char pixels[16] = {0xFF, 0xFF, 0, 0, 0xFF, 0xFF, 0, 0,
                                       0xFF, 0xFF, 0, 0, 0x00, 0xFF, 0, 0};
    TQ3PixmapMarkerData data;
    TQ3GeometryObject marker;
    TQ3Point3D position;
    TQ3StoragePixmap pixmap;
    long offset;

    Q3Point3D_Set(&data.position, 0.0f, 0.0f, 0.0f);
    data.xOffset = 0;
    data.yOffset = 0;
    data.pixmap.image = Q3MemoryStorage_New(pixels, sizeof pixels);
    data.pixmap.width = 2;
    data.pixmap.height = 2;
    data.pixmap.rowBytes = 8;
    data.pixmap.pixelSize = 32;
    data.pixmap.pixelType = kQ3PixelTypeARGB32;
    data.pixmap.bitOrder = kQ3EndianBig;
    data.pixmap.byteOrder = kQ3EndianBig;
    data.pixmapMarkerAttributeSet = NULL;

    marker = Q3PixmapMarker_New(&data);
    Q3Object_Dispose(data.pixmap.image);
    if (marker == NULL) {
        gFailures++;
        return NULL;
    }
    CHECK(Q3PixmapMarker_GetPosition(marker, &position));
    CHECK(Q3PixmapMarker_SetPosition(marker, &position));
    CHECK(Q3PixmapMarker_GetXOffset(marker, &offset));
    CHECK(Q3PixmapMarker_SetXOffset(marker, offset - 1));
    CHECK(Q3PixmapMarker_GetYOffset(marker, &offset));
    CHECK(Q3PixmapMarker_SetYOffset(marker, offset - 1));
    CHECK(Q3PixmapMarker_GetPixmap(marker, &pixmap));
    Check((TQ3Boolean)(pixmap.width == 2 && pixmap.rowBytes == 8), "the pixmap");
    CHECK(Q3PixmapMarker_SetPixmap(marker, &pixmap));
    Q3Object_Dispose(pixmap.image);
    CHECK(Q3PixmapMarker_GetData(marker, &data));
    CHECK(Q3PixmapMarker_SetData(marker, &data));
    CHECK(Q3PixmapMarker_EmptyData(&data));
    return marker;
}

/* Draws the marker into a 64 x 64 pixmap with the wireframe renderer and
 * counts the red pixels: a marker's set bits, a pixmap marker's opaque
 * pixels. */
static void MyDrawMarker(TQ3GeometryObject marker, long expected)
{
    TQ3DrawContextObject context;
    TQ3CameraObject camera;
    TQ3ViewObject view;
    unsigned char *pixels;
    long red = 0, i;

    pixels = (unsigned char *)calloc(64 * 64, 4);
    view = Q3View_New();
    context = MyNewARGBDrawContext(pixels, 64, 64);
    camera = MyNewViewAngleCamera(5.0f, 0.5f, 20.0f, 0.75f);
    if (pixels == NULL || view == NULL || context == NULL || camera == NULL) {
        gFailures++;
        return;
    }
    CHECK(Q3View_SetDrawContext(view, context));
    CHECK(Q3View_SetCamera(view, camera));
    CHECK(Q3View_SetRendererByType(view, kQ3RendererTypeWireFrame));
    CHECK(Q3View_StartRendering(view));
    do {
        CHECK(Q3Geometry_Submit(marker, view));
    } while (Q3View_EndRendering(view) == kQ3ViewStatusRetraverse);
    for (i = 0; i < 64 * 64; i++)
        if (pixels[4 * i + 1] == 255 && pixels[4 * i + 2] == 0 && pixels[4 * i + 3] == 0)
            red++;
    Check((TQ3Boolean)(red == expected), "the red pixels");
    Q3Object_Dispose(camera);
    Q3Object_Dispose(context);
    Q3Object_Dispose(view);
    free(pixels);
}

int main(void)
{
    TQ3ViewObject view;
    TQ3AttributeSet red;
    int status;
    TQ3GeometryObject marker;

    status = MyStartBounding(&view, &red);
    if (status != 0)
        return status;

    MyGeneralPolygon(view, red);
    MyPolyhedron(view, red);
    MyTriGrid(view, red);
    marker = MyMarker(red);
    if (marker != NULL) {
        MyDrawMarker(marker, 12);
        MyBoundAndDispose(view, marker);
    }
    marker = MyPixmapMarker();
    if (marker != NULL) {
        MyDrawMarker(marker, 3);
        MyBoundAndDispose(view, marker);
    }

    return MyFinishBounding(view, red,
                            "every 1.6 general polygon, polyhedron, trigrid, marker and pixmap marker call worked");
}
