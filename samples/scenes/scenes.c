/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#include "scenes.h"

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGeometry.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DView.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- Helpers ------------------------------------------------------------- */

static TQ3ColorRGB rgb(float r, float g, float b)
{
    TQ3ColorRGB color;
    color.r = r;
    color.g = g;
    color.b = b;
    return color;
}

static TQ3AttributeSet color_set(TQ3ColorRGB color)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    if (set != NULL && Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color) != kQ3Success) {
        Q3Object_Dispose(set);
        set = NULL;
    }
    return set;
}

static void dispose(TQ3Object object)
{
    if (object != NULL)
        Q3Object_Dispose(object);
}

/* ---- A hexagon of colours as a TriMesh ---------------------------------- */

#define HEX_RIM 6

static TQ3Status submit_color_hexagon(TQ3ViewObject view)
{
    TQ3Point3D points[HEX_RIM + 1];
    TQ3ColorRGB colors[HEX_RIM + 1];
    TQ3TriMeshTriangleData triangles[HEX_RIM];
    TQ3TriMeshAttributeData vertexColors;
    TQ3TriMeshData data;
    TQ3GeometryObject mesh;
    TQ3Status status;
    int i;

    points[0].x = points[0].y = points[0].z = 0.0f;
    colors[0] = rgb(0.9f, 0.9f, 0.9f);
    for (i = 0; i < HEX_RIM; i++) {
        const double angle = 2.0 * 3.14159265358979323846 * i / HEX_RIM;
        points[i + 1].x = (float)(1.4 * cos(angle));
        points[i + 1].y = (float)(1.4 * sin(angle));
        points[i + 1].z = 0.0f;
        triangles[i].pointIndices[0] = 0;
        triangles[i].pointIndices[1] = (unsigned long)(i + 1);
        triangles[i].pointIndices[2] = (unsigned long)((i + 1) % HEX_RIM + 1);
    }
    colors[1] = rgb(1, 0, 0);
    colors[2] = rgb(1, 1, 0);
    colors[3] = rgb(0, 1, 0);
    colors[4] = rgb(0, 1, 1);
    colors[5] = rgb(0, 0, 1);
    colors[6] = rgb(1, 0, 1);

    vertexColors.attributeType = kQ3AttributeTypeDiffuseColor;
    vertexColors.data = colors;
    vertexColors.attributeUseArray = NULL;

    memset(&data, 0, sizeof data);
    data.numTriangles = HEX_RIM;
    data.triangles = triangles;
    data.numPoints = HEX_RIM + 1;
    data.points = points;
    data.numVertexAttributeTypes = 1;
    data.vertexAttributeTypes = &vertexColors;
    data.bBox.isEmpty = kQ3True;

    mesh = Q3TriMesh_New(&data);
    if (mesh == NULL)
        return kQ3Failure;
    status = Q3Geometry_Submit(mesh, view);
    Q3Object_Dispose(mesh);
    return status;
}

/* ---- A red triangle and a green concave polygon ------------------------- */

static TQ3Status submit_triangle_and_polygon(TQ3ViewObject view)
{
    /* An arrow pointing right: concave at its shaft. */
    static const float arrow[7][2] = {{0.2f, -0.3f}, {0.9f, -0.3f}, {0.9f, -0.7f}, {1.7f, 0.0f},
                                      {0.9f, 0.7f},  {0.9f, 0.3f},  {0.2f, 0.3f}};
    TQ3TriangleData triangleData;
    TQ3Vertex3D vertices[7];
    TQ3PolygonData polygonData;
    TQ3GeometryObject triangle, polygon;
    TQ3Status status = kQ3Success;
    int i;

    memset(&triangleData, 0, sizeof triangleData);
    triangleData.vertices[0].point.x = -1.7f;
    triangleData.vertices[0].point.y = -0.8f;
    triangleData.vertices[1].point.x = -0.1f;
    triangleData.vertices[1].point.y = -0.8f;
    triangleData.vertices[2].point.x = -0.9f;
    triangleData.vertices[2].point.y = 0.9f;
    triangleData.triangleAttributeSet = color_set(rgb(0.9f, 0.15f, 0.1f));

    for (i = 0; i < 7; i++) {
        vertices[i].point.x = arrow[i][0];
        vertices[i].point.y = arrow[i][1];
        vertices[i].point.z = 0.0f;
        vertices[i].attributeSet = NULL;
    }
    polygonData.numVertices = 7;
    polygonData.vertices = vertices;
    polygonData.polygonAttributeSet = color_set(rgb(0.2f, 0.8f, 0.3f));

    triangle = Q3Triangle_New(&triangleData);
    polygon = Q3Polygon_New(&polygonData);
    if (triangle == NULL || polygon == NULL || Q3Geometry_Submit(triangle, view) != kQ3Success ||
        Q3Geometry_Submit(polygon, view) != kQ3Success)
        status = kQ3Failure;
    dispose(triangle);
    dispose(polygon);
    dispose(triangleData.triangleAttributeSet);
    dispose(polygonData.polygonAttributeSet);
    return status;
}

/* ---- A zigzag polyline, red at one end and blue at the other ------------ */

#define ZIGZAG 7

static TQ3Status submit_red_to_blue(TQ3ViewObject view)
{
    TQ3Vertex3D vertices[ZIGZAG];
    TQ3PolyLineData data;
    TQ3Status status = kQ3Success;
    int i;

    for (i = 0; i < ZIGZAG; i++) {
        const float t = (float)i / (ZIGZAG - 1);
        vertices[i].point.x = -1.6f + 3.2f * t;
        vertices[i].point.y = (i % 2 == 0) ? -0.7f : 0.7f;
        vertices[i].point.z = 0.0f;
        vertices[i].attributeSet = color_set(rgb(1.0f - t, 0.0f, t));
        if (vertices[i].attributeSet == NULL)
            status = kQ3Failure;
    }
    data.numVertices = ZIGZAG;
    data.vertices = vertices;
    data.segmentAttributeSet = NULL;
    data.polyLineAttributeSet = NULL;
    if (status == kQ3Success)
        status = Q3PolyLine_Submit(&data, view);
    for (i = 0; i < ZIGZAG; i++)
        dispose(vertices[i].attributeSet);
    return status;
}

/* ---- A near triangle hiding a far one ----------------------------------- */

static void set_triangle(TQ3TriangleData *data, float cx, float cy, float z, float size)
{
    memset(data, 0, sizeof *data);
    data->vertices[0].point.x = cx - size;
    data->vertices[0].point.y = cy - 0.8f * size;
    data->vertices[0].point.z = z;
    data->vertices[1].point.x = cx + size;
    data->vertices[1].point.y = cy - 0.8f * size;
    data->vertices[1].point.z = z;
    data->vertices[2].point.x = cx;
    data->vertices[2].point.y = cy + size;
    data->vertices[2].point.z = z;
}

static TQ3Status submit_hidden_triangle(TQ3ViewObject view)
{
    TQ3TriangleData nearData, farData;
    TQ3Status status;

    /* The near one is submitted first: only the depth test can keep it in front. */
    set_triangle(&nearData, -0.3f, -0.2f, 0.6f, 0.9f);
    nearData.triangleAttributeSet = color_set(rgb(0.15f, 0.35f, 0.95f));
    set_triangle(&farData, 0.3f, 0.1f, -0.6f, 1.3f);
    farData.triangleAttributeSet = color_set(rgb(0.95f, 0.6f, 0.1f));
    status = (nearData.triangleAttributeSet != NULL && farData.triangleAttributeSet != NULL &&
              Q3Triangle_Submit(&nearData, view) == kQ3Success && Q3Triangle_Submit(&farData, view) == kQ3Success)
                 ? kQ3Success
                 : kQ3Failure;
    dispose(nearData.triangleAttributeSet);
    dispose(farData.triangleAttributeSet);
    return status;
}

/* ---- The scenes ---------------------------------------------------------- */

static const Q3Scene kScenes[] = {
    {"trimesh_interactive", "A TriMesh hexagon with per-vertex colours, filled by the interactive renderer",
     kQ3RendererTypeInteractive, {0.6f, -0.8f, 5.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_color_hexagon},
    {"trimesh_wireframe", "The same TriMesh outlined by the wireframe renderer", kQ3RendererTypeWireFrame,
     {0.6f, -0.8f, 5.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_color_hexagon},
    {"triangle_polygon", "A Triangle and a concave Polygon in their attribute sets' colours",
     kQ3RendererTypeInteractive, {0.0f, 0.0f, 5.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_triangle_and_polygon},
    {"polyline_red_to_blue", "A PolyLine whose vertex colours run from red to blue", kQ3RendererTypeInteractive,
     {0.0f, 0.0f, 5.0f}, 0.75f, {0.95f, 0.95f, 0.95f}, submit_red_to_blue},
    {"hidden_triangle", "A nearer blue triangle, submitted first, hides a farther orange one",
     kQ3RendererTypeInteractive, {0.0f, 0.0f, 5.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_hidden_triangle},
};

unsigned long q3scene_count(void)
{
    return sizeof kScenes / sizeof kScenes[0];
}

const Q3Scene *q3scene_get(unsigned long index)
{
    return index < q3scene_count() ? &kScenes[index] : NULL;
}

const Q3Scene *q3scene_find(const char *name)
{
    unsigned long i;
    for (i = 0; i < q3scene_count(); i++)
        if (strcmp(kScenes[i].name, name) == 0)
            return &kScenes[i];
    return NULL;
}

/* ---- Rendering ----------------------------------------------------------- */

static TQ3ViewObject new_view(const Q3Scene *scene, unsigned long width, unsigned long height,
                              unsigned char *argb)
{
    TQ3PixmapDrawContextData contextData;
    TQ3ViewAngleAspectCameraData cameraData;
    TQ3DrawContextObject context;
    TQ3CameraObject camera;
    TQ3ViewObject view = Q3View_New();
    int failed = view == NULL;

    memset(&contextData, 0, sizeof contextData);
    contextData.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
    contextData.drawContextData.clearImageColor.a = 1.0f;
    contextData.drawContextData.clearImageColor.r = scene->background.r;
    contextData.drawContextData.clearImageColor.g = scene->background.g;
    contextData.drawContextData.clearImageColor.b = scene->background.b;
    contextData.drawContextData.paneState = kQ3False;
    contextData.drawContextData.maskState = kQ3False;
    contextData.drawContextData.doubleBufferState = kQ3False;
    contextData.pixmap.image = argb;
    contextData.pixmap.width = width;
    contextData.pixmap.height = height;
    contextData.pixmap.rowBytes = width * 4;
    contextData.pixmap.pixelSize = 32;
    contextData.pixmap.pixelType = kQ3PixelTypeARGB32;
    contextData.pixmap.bitOrder = kQ3EndianBig;
    contextData.pixmap.byteOrder = kQ3EndianBig;
    context = Q3PixmapDrawContext_New(&contextData);

    memset(&cameraData, 0, sizeof cameraData);
    cameraData.cameraData.placement.cameraLocation = scene->eye;
    cameraData.cameraData.placement.upVector.y = 1.0f;
    cameraData.cameraData.range.hither = 0.5f;
    cameraData.cameraData.range.yon = 20.0f;
    cameraData.cameraData.viewPort.origin.x = -1.0f;
    cameraData.cameraData.viewPort.origin.y = 1.0f;
    cameraData.cameraData.viewPort.width = 2.0f;
    cameraData.cameraData.viewPort.height = 2.0f;
    cameraData.fov = scene->fieldOfView;
    cameraData.aspectRatioXToY = (float)width / (float)height;
    camera = Q3ViewAngleAspectCamera_New(&cameraData);

    if (failed || context == NULL || camera == NULL || Q3View_SetDrawContext(view, context) != kQ3Success ||
        Q3View_SetCamera(view, camera) != kQ3Success ||
        Q3View_SetRendererByType(view, scene->renderer) != kQ3Success)
        failed = 1;
    dispose(context);
    dispose(camera);
    if (failed) {
        dispose(view);
        return NULL;
    }
    return view;
}

int q3scene_render(const Q3Scene *scene, unsigned long width, unsigned long height, unsigned char *rgba)
{
    unsigned char *argb;
    TQ3ViewObject view;
    TQ3ViewStatus status;
    unsigned long i;

    if (scene == NULL || rgba == NULL || width == 0 || height == 0)
        return 1;
    argb = calloc(width * height, 4);
    if (argb == NULL)
        return 1;
    view = new_view(scene, width, height, argb);
    if (view == NULL) {
        free(argb);
        return 1;
    }
    if (Q3View_StartRendering(view) != kQ3Success) {
        dispose(view);
        free(argb);
        return 1;
    }
    do {
        if (scene->submit(view) != kQ3Success) {
            Q3View_Cancel(view);
        }
        status = Q3View_EndRendering(view);
    } while (status == kQ3ViewStatusRetraverse);
    dispose(view);

    for (i = 0; i < width * height; i++) {
        rgba[4 * i + 0] = argb[4 * i + 1];
        rgba[4 * i + 1] = argb[4 * i + 2];
        rgba[4 * i + 2] = argb[4 * i + 3];
        rgba[4 * i + 3] = argb[4 * i + 0];
    }
    free(argb);
    return status == kQ3ViewStatusDone ? 0 : 1;
}
