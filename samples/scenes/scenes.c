/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#include "scenes.h"
#include "scene_util.h"

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGeometry.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

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

/* ---- Quadrics and solids ------------------------------------------------- */

/* The box faces' colours, in Apple's order: left, right, front, back, top, bottom. */
static void box_face_sets(TQ3AttributeSet faces[6])
{
    faces[0] = color_set(rgb(0.90f, 0.20f, 0.20f));
    faces[1] = color_set(rgb(0.20f, 0.80f, 0.30f));
    faces[2] = color_set(rgb(0.20f, 0.40f, 0.95f));
    faces[3] = color_set(rgb(0.95f, 0.85f, 0.20f));
    faces[4] = color_set(rgb(0.20f, 0.85f, 0.90f));
    faces[5] = color_set(rgb(0.85f, 0.30f, 0.85f));
}

/* A unit box at origin, spanned by x (minor), y (orientation) and z (major),
 * scaled by `side` and point-reflected when `turned`. */
static void set_box(TQ3BoxData *data, TQ3Point3D origin, float side, int turned)
{
    const float s = turned ? -side : side;
    memset(data, 0, sizeof *data);
    data->origin = origin;
    data->orientation = vector3(0, s, 0);
    data->majorAxis = vector3(0, 0, s);
    data->minorAxis = vector3(s, 0, 0);
}

static TQ3Status submit_boxes(TQ3ViewObject view)
{
    TQ3AttributeSet faces[6];
    TQ3BoxData data;
    TQ3Status status = kQ3Success;
    int i;

    box_face_sets(faces);
    /* Seen from above, in front and to the right: the left box shows its
     * right, front and top faces; the right one, point-reflected through its
     * centre, its left, back and bottom faces. */
    set_box(&data, point3(-1.9f, -0.6f, -0.6f), 1.2f, 0);
    data.faceAttributeSet = faces;
    if (submit_new(Q3Box_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    set_box(&data, point3(1.9f, 0.6f, 0.6f), 1.2f, 1);
    data.faceAttributeSet = faces;
    if (submit_new(Q3Box_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    for (i = 0; i < 6; i++)
        dispose(faces[i]);
    return status;
}

/* A quadric's frame: origin, orientation along y, majorRadius along z,
 * minorRadius along x, so u = 0 faces a camera on +z and u = 1/4 the +x side. */
#define SET_FRAME(data, ox, oy, oz, height, radius)                                                           \
    do {                                                                                                        \
        memset(&(data), 0, sizeof(data));                                                                       \
        (data).origin = point3(ox, oy, oz);                                                                     \
        (data).orientation = vector3(0, height, 0);                                                             \
        (data).majorRadius = vector3(0, 0, radius);                                                             \
        (data).minorRadius = vector3(radius, 0, 0);                                                             \
        (data).uMax = (data).vMax = 1.0f;                                                                       \
    } while (0)

static TQ3Status submit_cones(TQ3ViewObject view)
{
    TQ3ConeData data;
    TQ3Status status = kQ3Success;
    TQ3AttributeSet side = color_set(rgb(0.95f, 0.55f, 0.15f));
    TQ3AttributeSet bottom = color_set(rgb(0.20f, 0.40f, 0.95f));
    TQ3AttributeSet interior = color_set(rgb(0.25f, 0.80f, 0.30f));

    /* Seen from below: a whole cone with its bottom closed, and one with the
     * quarter from u = 0 to 1/4 (facing the camera) cut away and closed. */
    SET_FRAME(data, -1.3f, -0.6f, 0.0f, 1.7f, 0.9f);
    data.caps = kQ3EndCapMaskBottom;
    data.faceAttributeSet = side;
    data.bottomAttributeSet = bottom;
    data.interiorAttributeSet = interior;
    if (submit_new(Q3Cone_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    data.origin.x = 1.3f;
    data.uMin = 0.25f;
    data.caps = kQ3EndCapMaskBottom | kQ3EndCapMaskInterior;
    if (submit_new(Q3Cone_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    dispose(side);
    dispose(bottom);
    dispose(interior);
    return status;
}

static TQ3Status submit_cylinders(TQ3ViewObject view)
{
    TQ3CylinderData data;
    TQ3Status status = kQ3Success;
    TQ3AttributeSet side = color_set(rgb(0.15f, 0.65f, 0.65f));
    TQ3AttributeSet top = color_set(rgb(0.95f, 0.85f, 0.20f));
    TQ3AttributeSet bottom = color_set(rgb(0.85f, 0.30f, 0.85f));
    TQ3AttributeSet interior = color_set(rgb(0.90f, 0.20f, 0.20f));

    /* Seen from above: a closed cylinder, and its back half (u from 1/4 to
     * 3/4) with the cut face turned to the camera. */
    SET_FRAME(data, -1.3f, -0.8f, 0.0f, 1.5f, 0.8f);
    data.caps = kQ3EndCapMaskTop | kQ3EndCapMaskBottom;
    data.faceAttributeSet = side;
    data.topAttributeSet = top;
    data.bottomAttributeSet = bottom;
    data.interiorAttributeSet = interior;
    if (submit_new(Q3Cylinder_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    data.origin.x = 1.3f;
    data.uMin = 0.25f;
    data.uMax = 0.75f;
    data.caps = kQ3EndCapMaskTop | kQ3EndCapMaskBottom | kQ3EndCapMaskInterior;
    if (submit_new(Q3Cylinder_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    dispose(side);
    dispose(top);
    dispose(bottom);
    dispose(interior);
    return status;
}

static TQ3Status submit_disks(TQ3ViewObject view)
{
    TQ3DiskData data;
    TQ3Status status = kQ3Success;

    /* In the x-y plane, facing the camera: a whole disk, and three quarters
     * of a ring (u from 0 to 3/4, v from 0.4 to 1). */
    memset(&data, 0, sizeof data);
    data.origin = point3(-1.2f, 0.0f, 0.0f);
    data.majorRadius = vector3(1.0f, 0.0f, 0.0f);
    data.minorRadius = vector3(0.0f, 0.8f, 0.0f);
    data.uMax = data.vMax = 1.0f;
    data.diskAttributeSet = color_set(rgb(0.60f, 0.35f, 0.90f));
    if (submit_new(Q3Disk_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    dispose(data.diskAttributeSet);
    data.origin.x = 1.2f;
    data.minorRadius.y = 1.0f;
    data.uMax = 0.75f;
    data.vMin = 0.4f;
    data.diskAttributeSet = color_set(rgb(0.95f, 0.55f, 0.15f));
    if (submit_new(Q3Disk_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    dispose(data.diskAttributeSet);
    return status;
}

static TQ3Status submit_ellipses(TQ3ViewObject view)
{
    TQ3EllipseData data;
    TQ3Status status = kQ3Success;

    /* A whole ellipse, and a circle's arc open to the right (u from 1/8 to 7/8). */
    memset(&data, 0, sizeof data);
    data.origin = point3(-1.1f, 0.0f, 0.0f);
    data.majorRadius = vector3(0.9f, 0.0f, 0.0f);
    data.minorRadius = vector3(0.0f, 0.55f, 0.0f);
    data.uMax = 1.0f;
    data.ellipseAttributeSet = color_set(rgb(0.10f, 0.25f, 0.90f));
    if (submit_new(Q3Ellipse_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    dispose(data.ellipseAttributeSet);
    data.origin.x = 1.1f;
    data.majorRadius.x = 0.8f;
    data.minorRadius.y = 0.8f;
    data.uMin = 0.125f;
    data.uMax = 0.875f;
    data.ellipseAttributeSet = color_set(rgb(0.90f, 0.10f, 0.10f));
    if (submit_new(Q3Ellipse_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    dispose(data.ellipseAttributeSet);
    return status;
}

static TQ3Status submit_ellipsoids(TQ3ViewObject view)
{
    TQ3EllipsoidData data;
    TQ3Status status = kQ3Success;
    TQ3AttributeSet surface = color_set(rgb(0.90f, 0.25f, 0.25f));
    TQ3AttributeSet interior = color_set(rgb(0.95f, 0.85f, 0.20f));

    /* A sphere with the quarter facing the camera (u from 0 to 1/4) cut away,
     * and a flattened ellipsoid with its top cut off at v = 3/4 and closed. */
    SET_FRAME(data, -1.2f, 0.0f, 0.0f, 0.9f, 0.9f);
    data.uMin = 0.25f;
    data.caps = kQ3EndCapMaskInterior;
    data.ellipsoidAttributeSet = surface;
    data.interiorAttributeSet = interior;
    if (submit_new(Q3Ellipsoid_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    SET_FRAME(data, 1.3f, 0.0f, 0.0f, 0.6f, 0.8f);
    data.minorRadius.x = 0.6f;
    data.vMax = 0.75f;
    data.caps = kQ3EndCapMaskTop;
    data.ellipsoidAttributeSet = surface;
    data.interiorAttributeSet = interior;
    if (submit_new(Q3Ellipsoid_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    dispose(surface);
    dispose(interior);
    return status;
}

static TQ3Status submit_tori(TQ3ViewObject view)
{
    TQ3TorusData data;
    TQ3Status status = kQ3Success;
    TQ3AttributeSet interior = color_set(rgb(0.25f, 0.80f, 0.30f));

    /* Lying flat, seen from above: a whole torus, and one with the quarter
     * facing the camera (u from 0 to 1/4) cut away, its cross-sections closed. */
    SET_FRAME(data, -1.3f, 0.0f, 0.0f, 0.3f, 0.8f);
    data.ratio = 1.0f;
    data.torusAttributeSet = color_set(rgb(0.95f, 0.55f, 0.15f));
    if (submit_new(Q3Torus_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    dispose(data.torusAttributeSet);
    data.origin.x = 1.3f;
    data.uMin = 0.25f;
    data.caps = kQ3EndCapMaskInterior;
    data.interiorAttributeSet = interior;
    data.torusAttributeSet = color_set(rgb(0.20f, 0.40f, 0.95f));
    if (submit_new(Q3Torus_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    dispose(data.torusAttributeSet);
    dispose(interior);
    return status;
}

/* All seven, small, in two rows, each in its own colour: the wireframe
 * renderer shows their triangles under a screen-space subdivision of 12
 * pixels. */
static TQ3Status submit_all_quadrics(TQ3ViewObject view)
{
    TQ3SubdivisionStyleData style;
    TQ3AttributeSet colors[7];
    TQ3BoxData box;
    TQ3ConeData cone;
    TQ3CylinderData cylinder;
    TQ3DiskData disk;
    TQ3EllipseData ellipse;
    TQ3EllipsoidData ellipsoid;
    TQ3TorusData torus;
    TQ3Status status = kQ3Success;
    int i;

    colors[0] = color_set(rgb(0.95f, 0.35f, 0.35f));
    colors[1] = color_set(rgb(0.95f, 0.65f, 0.25f));
    colors[2] = color_set(rgb(0.95f, 0.90f, 0.30f));
    colors[3] = color_set(rgb(0.40f, 0.90f, 0.40f));
    colors[4] = color_set(rgb(0.35f, 0.85f, 0.95f));
    colors[5] = color_set(rgb(0.50f, 0.60f, 1.00f));
    colors[6] = color_set(rgb(0.90f, 0.50f, 0.95f));
    set_box(&box, point3(-2.75f, 0.4f, -0.35f), 0.7f, 0);
    box.boxAttributeSet = colors[0];
    SET_FRAME(cone, -0.9f, 0.4f, 0.0f, 1.0f, 0.45f);
    cone.caps = kQ3EndCapMaskBottom;
    cone.coneAttributeSet = colors[1];
    SET_FRAME(cylinder, 0.7f, 0.4f, 0.0f, 0.8f, 0.4f);
    cylinder.caps = kQ3EndCapMaskTop | kQ3EndCapMaskBottom;
    cylinder.cylinderAttributeSet = colors[2];
    memset(&disk, 0, sizeof disk);
    disk.origin = point3(2.4f, 0.8f, 0.0f);
    disk.majorRadius = vector3(0.5f, 0.0f, 0.0f);
    disk.minorRadius = vector3(0.0f, 0.35f, 0.35f);
    disk.uMax = disk.vMax = 1.0f;
    disk.diskAttributeSet = colors[3];
    memset(&ellipse, 0, sizeof ellipse);
    ellipse.origin = point3(-1.8f, -1.2f, 0.0f);
    ellipse.majorRadius = vector3(0.6f, 0.0f, 0.0f);
    ellipse.minorRadius = vector3(0.0f, 0.4f, 0.0f);
    ellipse.uMax = 1.0f;
    ellipse.ellipseAttributeSet = colors[4];
    SET_FRAME(ellipsoid, 0.0f, -1.2f, 0.0f, 0.5f, 0.5f);
    ellipsoid.ellipsoidAttributeSet = colors[5];
    SET_FRAME(torus, 1.8f, -1.2f, 0.0f, 0.18f, 0.45f);
    torus.ratio = 1.0f;
    torus.torusAttributeSet = colors[6];

    style.method = kQ3SubdivisionMethodScreenSpace;
    style.c1 = style.c2 = 12.0f;
    if (Q3SubdivisionStyle_Submit(&style, view) != kQ3Success || submit_new(Q3Box_New(&box), view) != kQ3Success ||
        submit_new(Q3Cone_New(&cone), view) != kQ3Success ||
        submit_new(Q3Cylinder_New(&cylinder), view) != kQ3Success ||
        submit_new(Q3Disk_New(&disk), view) != kQ3Success ||
        submit_new(Q3Ellipse_New(&ellipse), view) != kQ3Success ||
        submit_new(Q3Ellipsoid_New(&ellipsoid), view) != kQ3Success ||
        submit_new(Q3Torus_New(&torus), view) != kQ3Success)
        status = kQ3Failure;
    for (i = 0; i < 7; i++)
        dispose(colors[i]);
    return status;
}

/* ---- A Mesh: a holed face and a folded neighbour ------------------------ */

static TQ3MeshVertex mesh_vertex(TQ3GeometryObject mesh, float x, float y, float z, TQ3AttributeSet set)
{
    TQ3Vertex3D vertex;
    vertex.point = point3(x, y, z);
    vertex.attributeSet = set;
    return Q3Mesh_VertexNew(mesh, &vertex);
}

/*
 * An orange square with a square hole (a second contour, so the background
 * shows through it), and beside it, sharing the square's right edge, a
 * quad folded back whose vertices are red, green and blue; the shared top
 * corner is yellow as a vertex, but magenta in the folded face (a corner
 * set). The shared edge is white in the wireframe (an edge set).
 */
static TQ3Status submit_mesh(TQ3ViewObject view)
{
    TQ3GeometryObject mesh = Q3Mesh_New();
    TQ3AttributeSet orange = color_set(rgb(0.95f, 0.55f, 0.15f));
    TQ3AttributeSet red = color_set(rgb(0.90f, 0.15f, 0.15f));
    TQ3AttributeSet green = color_set(rgb(0.20f, 0.85f, 0.30f));
    TQ3AttributeSet blue = color_set(rgb(0.20f, 0.35f, 0.95f));
    TQ3AttributeSet yellow = color_set(rgb(0.95f, 0.90f, 0.20f));
    TQ3AttributeSet magenta = color_set(rgb(0.90f, 0.25f, 0.85f));
    TQ3AttributeSet white = color_set(rgb(1.0f, 1.0f, 1.0f));
    TQ3MeshVertex square[4], hole[4], fold[4];
    TQ3MeshFace outer, inner, side;
    TQ3MeshIterator iterator;
    TQ3MeshEdge edge;
    TQ3Status status = kQ3Failure;

    if (mesh != NULL) {
        Q3Mesh_DelayUpdates(mesh);
        square[0] = mesh_vertex(mesh, -2.2f, -1.5f, 0.0f, NULL);
        square[1] = mesh_vertex(mesh, 0.2f, -1.5f, 0.0f, NULL);
        square[2] = mesh_vertex(mesh, 0.2f, 1.5f, 0.0f, yellow);
        square[3] = mesh_vertex(mesh, -2.2f, 1.5f, 0.0f, NULL);
        hole[0] = mesh_vertex(mesh, -1.5f, -0.6f, 0.0f, NULL);
        hole[1] = mesh_vertex(mesh, -0.5f, -0.6f, 0.0f, NULL);
        hole[2] = mesh_vertex(mesh, -0.5f, 0.6f, 0.0f, NULL);
        hole[3] = mesh_vertex(mesh, -1.5f, 0.6f, 0.0f, NULL);
        fold[0] = square[1];
        fold[1] = mesh_vertex(mesh, 2.0f, -1.2f, -1.0f, red);
        fold[2] = mesh_vertex(mesh, 2.0f, 1.2f, -1.0f, green);
        fold[3] = square[2];
        outer = Q3Mesh_FaceNew(mesh, 4, square, orange);
        inner = Q3Mesh_FaceNew(mesh, 4, hole, NULL);
        side = Q3Mesh_FaceNew(mesh, 4, fold, NULL);
        Q3Mesh_SetVertexAttributeSet(mesh, square[1], blue);
        if (outer != NULL && inner != NULL && side != NULL && Q3Mesh_FaceToContour(mesh, outer, inner) != NULL &&
            Q3Mesh_SetCornerAttributeSet(mesh, square[2], side, magenta) == kQ3Success &&
            Q3Mesh_SetCornerAttributeSet(mesh, square[1], outer, orange) == kQ3Success &&
            Q3Mesh_SetCornerAttributeSet(mesh, square[2], outer, orange) == kQ3Success) {
            Q3ForEachFaceEdge(side, edge, &iterator)
            {
                TQ3MeshFace face1, face2;
                if (Q3Mesh_GetEdgeFaces(mesh, edge, &face1, &face2) == kQ3Success && face2 != NULL)
                    Q3Mesh_SetEdgeAttributeSet(mesh, edge, white);
            }
            Q3Mesh_ResumeUpdates(mesh);
            status = Q3Geometry_Submit(mesh, view);
        }
    }
    dispose(mesh);
    dispose(orange);
    dispose(red);
    dispose(green);
    dispose(blue);
    dispose(yellow);
    dispose(magenta);
    dispose(white);
    return status;
}

/* ---- NURB patches --------------------------------------------------------- */

/* A rational point (x, y, z) of weight w, pre-multiplied. */
static TQ3RationalPoint4D patch_point(float x, float y, float z, float w)
{
    TQ3RationalPoint4D p;
    p.x = x * w;
    p.y = y * w;
    p.z = z * w;
    p.w = w;
    return p;
}

static TQ3RationalPoint3D trim_point(float u, float v, float w)
{
    TQ3RationalPoint3D p;
    p.x = u * w;
    p.y = v * w;
    p.w = w;
    return p;
}

/* Submits the style, then a retained patch made from data (then disposed). */
static TQ3Status submit_patch_data(TQ3ViewObject view, const TQ3NURBPatchData *data, float pixels)
{
    TQ3SubdivisionStyleData style;
    style.method = kQ3SubdivisionMethodScreenSpace;
    style.c1 = pixels;
    style.c2 = pixels;
    if (Q3SubdivisionStyle_Submit(&style, view) != kQ3Success)
        return kQ3Failure;
    return submit_new(Q3NURBPatch_New(data), view);
}

/* A bicubic patch of 5 x 5 control points over x, z in [-1.6, 1.6], a hill
 * in its middle and a dip at one corner, its knots clamped and uniform. */
static void plain_patch(TQ3NURBPatchData *data, TQ3RationalPoint4D points[25], float knots[9])
{
    static const float heights[5][5] = {{0.0f, 0.1f, 0.2f, 0.1f, 0.0f},
                                        {0.1f, 0.5f, 0.7f, 0.4f, 0.0f},
                                        {0.2f, 0.7f, 1.3f, 0.6f, -0.1f},
                                        {0.1f, 0.4f, 0.6f, 0.2f, -0.4f},
                                        {0.0f, 0.0f, -0.1f, -0.4f, -0.8f}};
    static const float clamped[9] = {0, 0, 0, 0, 1, 2, 2, 2, 2};
    int row, column;
    for (row = 0; row < 5; row++)
        for (column = 0; column < 5; column++)
            points[row * 5 + column] =
                patch_point(-1.6f + 0.8f * (float)column, heights[row][column] - 0.3f, 1.6f - 0.8f * (float)row, 1.0f);
    memcpy(knots, clamped, sizeof clamped);
    memset(data, 0, sizeof *data);
    data->uOrder = 4;
    data->vOrder = 4;
    data->numRows = 5;
    data->numColumns = 5;
    data->controlPoints = points;
    data->uKnots = knots;
    data->vKnots = knots;
}

TQ3Status q3scene_submit_plain_patch(TQ3ViewObject view, TQ3AttributeSet set, float pixels)
{
    TQ3NURBPatchData data;
    TQ3RationalPoint4D points[25];
    float knots[9];
    plain_patch(&data, points, knots);
    data.patchAttributeSet = set;
    return submit_patch_data(view, &data, pixels);
}

TQ3Status q3scene_submit_trimmed_patch(TQ3ViewObject view, TQ3AttributeSet set, float pixels)
{
    /* The hole: a circle of radius 0.7 around the middle of the domain
     * [0, 2] x [0, 2], running clockwise (exactly: a rational quadratic in
     * four quarters); the island: a square inside it, counterclockwise. */
    static const float circleKnots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    static const float squareKnots[7] = {0, 0, 1, 2, 3, 4, 4};
    const float r = 0.7f, s = 0.70710678f, h = 0.3f;
    static const float offsets[9][2] = {{1, 0}, {1, -1}, {0, -1}, {-1, -1}, {-1, 0}, {-1, 1}, {0, 1}, {1, 1}, {1, 0}};
    TQ3NURBPatchData data;
    TQ3RationalPoint4D points[25];
    float knots[9];
    TQ3RationalPoint3D circle[9], square[5];
    TQ3NURBPatchTrimCurveData curves[2];
    TQ3NURBPatchTrimLoopData loops[2];
    int i;
    for (i = 0; i < 9; i++)
        circle[i] = trim_point(1.0f + r * offsets[i][0], 1.0f + r * offsets[i][1], i % 2 ? s : 1.0f);
    square[0] = trim_point(1.0f - h, 1.0f - h, 1.0f);
    square[1] = trim_point(1.0f + h, 1.0f - h, 1.0f);
    square[2] = trim_point(1.0f + h, 1.0f + h, 1.0f);
    square[3] = trim_point(1.0f - h, 1.0f + h, 1.0f);
    square[4] = square[0];
    curves[0].order = 3;
    curves[0].numPoints = 9;
    curves[0].controlPoints = circle;
    curves[0].knots = (float *)circleKnots;
    curves[1].order = 2;
    curves[1].numPoints = 5;
    curves[1].controlPoints = square;
    curves[1].knots = (float *)squareKnots;
    loops[0].numTrimCurves = 1;
    loops[0].trimCurves = &curves[0];
    loops[1].numTrimCurves = 1;
    loops[1].trimCurves = &curves[1];
    plain_patch(&data, points, knots);
    data.numTrimLoops = 2;
    data.trimLoops = loops;
    data.patchAttributeSet = set;
    return submit_patch_data(view, &data, pixels);
}

TQ3Status q3scene_submit_cylinder_patch(TQ3ViewObject view, TQ3AttributeSet set, float pixels)
{
    /* Half a cylinder of radius 1 around the line x = 0, y = -0.5, from
     * z = -1.4 to 1.4, on the side y >= -0.5 (its normals outwards): in u two rational quadratic quarter circles
     * (weights 1, sqrt(2)/2, 1), in v a straight line (order 2). */
    static const float uKnots[8] = {0, 0, 0, 1, 1, 2, 2, 2};
    static const float vKnots[4] = {0, 0, 1, 1};
    static const float arc[5][3] = {{1, 0, 1}, {1, 1, 0.70710678f}, {0, 1, 1}, {-1, 1, 0.70710678f}, {-1, 0, 1}};
    TQ3NURBPatchData data;
    TQ3RationalPoint4D points[10];
    int row, column;
    for (row = 0; row < 2; row++)
        for (column = 0; column < 5; column++)
            points[row * 5 + column] =
                patch_point(arc[column][0], arc[column][1] - 0.5f, row == 0 ? -1.4f : 1.4f, arc[column][2]);
    memset(&data, 0, sizeof data);
    data.uOrder = 3;
    data.vOrder = 2;
    data.numColumns = 5;
    data.numRows = 2;
    data.controlPoints = points;
    data.uKnots = (float *)uKnots;
    data.vKnots = (float *)vKnots;
    data.patchAttributeSet = set;
    return submit_patch_data(view, &data, pixels);
}

static TQ3Status submit_patch_wireframe(TQ3ViewObject view, TQ3Status (*submit)(TQ3ViewObject, TQ3AttributeSet, float),
                                        TQ3ColorRGB color)
{
    TQ3AttributeSet set = color_set(color);
    TQ3Status status = set == NULL ? kQ3Failure : submit(view, set, 16.0f);
    dispose(set);
    return status;
}

static TQ3Status submit_plain_patch_wireframe(TQ3ViewObject view)
{
    return submit_patch_wireframe(view, q3scene_submit_plain_patch, rgb(0.95f, 0.75f, 0.25f));
}

static TQ3Status submit_trimmed_patch_wireframe(TQ3ViewObject view)
{
    return submit_patch_wireframe(view, q3scene_submit_trimmed_patch, rgb(0.35f, 0.85f, 0.45f));
}

static TQ3Status submit_cylinder_patch_wireframe(TQ3ViewObject view)
{
    return submit_patch_wireframe(view, q3scene_submit_cylinder_patch, rgb(0.45f, 0.65f, 1.0f));
}

/* ---- General polygons, polyhedra, triangle grids, markers ---------------- */

/* Square contour of half-size h around (cx, cy) in the plane z = 0,
 * counterclockwise, into v[0..3]. */
static void set_square(TQ3Vertex3D *v, float cx, float cy, float h)
{
    memset(v, 0, 4 * sizeof *v);
    v[0].point = point3(cx - h, cy - h, 0.0f);
    v[1].point = point3(cx + h, cy - h, 0.0f);
    v[2].point = point3(cx + h, cy + h, 0.0f);
    v[3].point = point3(cx - h, cy + h, 0.0f);
}

/* Left: an orange square with a square hole holding a small island (three
 * nested contours, even-odd). Right: a concave star-like outline whose
 * vertices run from red to blue, with a triangular hole. */
static TQ3Status submit_general_polygons_into(TQ3ViewObject view)
{
    TQ3Vertex3D outer[4], hole[4], island[4], star[8], notch[3];
    TQ3GeneralPolygonContourData left[3], right[2];
    TQ3GeneralPolygonData data;
    TQ3AttributeSet orange = color_set(rgb(0.95f, 0.55f, 0.15f));
    TQ3AttributeSet corner[8];
    TQ3Status status = kQ3Success;
    int i;

    set_square(outer, -1.3f, 0.0f, 1.0f);
    set_square(hole, -1.3f, 0.0f, 0.6f);
    set_square(island, -1.3f, 0.0f, 0.25f);
    left[0].numVertices = 4;
    left[0].vertices = outer;
    left[1].numVertices = 4;
    left[1].vertices = hole;
    left[2].numVertices = 4;
    left[2].vertices = island;
    memset(&data, 0, sizeof data);
    data.numContours = 3;
    data.contours = left;
    data.shapeHint = kQ3GeneralPolygonShapeHintComplex;
    data.generalPolygonAttributeSet = orange;
    if (submit_new(Q3GeneralPolygon_New(&data), view) != kQ3Success)
        status = kQ3Failure;

    memset(star, 0, sizeof star);
    for (i = 0; i < 8; i++) {
        const float angle = 3.14159265f * 2.0f * (float)i / 8.0f;
        const float radius = (i % 2 == 0) ? 1.05f : 0.55f;
        star[i].point = point3(1.4f + radius * cosf(angle), radius * sinf(angle), 0.0f);
        corner[i] = color_set(rgb(1.0f - (float)i / 7.0f, 0.2f, (float)i / 7.0f));
        star[i].attributeSet = corner[i];
    }
    memset(notch, 0, sizeof notch);
    notch[0].point = point3(1.25f, -0.2f, 0.0f);
    notch[1].point = point3(1.6f, -0.2f, 0.0f);
    notch[2].point = point3(1.4f, 0.2f, 0.0f);
    right[0].numVertices = 8;
    right[0].vertices = star;
    right[1].numVertices = 3;
    right[1].vertices = notch;
    data.numContours = 2;
    data.contours = right;
    data.shapeHint = kQ3GeneralPolygonShapeHintConcave;
    data.generalPolygonAttributeSet = NULL;
    if (Q3GeneralPolygon_Submit(&data, view) != kQ3Success)
        status = kQ3Failure;
    for (i = 0; i < 8; i++)
        dispose(corner[i]);
    dispose(orange);
    return status;
}

static TQ3Status submit_general_polygons(TQ3ViewObject view)
{
    return submit_general_polygons_into(view);
}

/* A square pyramid whose four sides are red, green, blue and yellow, its
 * base purple; the wireframe draws the outline of each face (the base's
 * diagonal is left out by the edge flags) and its apex edges are white. */
static TQ3Status submit_pyramid(TQ3ViewObject view, float x, float y)
{
    TQ3Vertex3D vertices[5];
    TQ3PolyhedronTriangleData triangles[6];
    TQ3PolyhedronEdgeData edges[4];
    TQ3PolyhedronData data;
    TQ3AttributeSet sides[5];
    TQ3AttributeSet white = color_set(rgb(1.0f, 1.0f, 1.0f));
    static const unsigned long kFaces[6][3] = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 3, 2}, {0, 2, 1}};
    static const TQ3PolyhedronEdge kFlags[6] = {kQ3PolyhedronEdge01, kQ3PolyhedronEdge01, kQ3PolyhedronEdge01,
                                                kQ3PolyhedronEdge01, kQ3PolyhedronEdge01 | kQ3PolyhedronEdge12,
                                                kQ3PolyhedronEdge20 | kQ3PolyhedronEdge12};
    TQ3Status status;
    int i, k;

    memset(vertices, 0, sizeof vertices);
    vertices[0].point = point3(x - 0.8f, y - 0.7f, 0.8f);
    vertices[1].point = point3(x + 0.8f, y - 0.7f, 0.8f);
    vertices[2].point = point3(x + 0.8f, y - 0.7f, -0.8f);
    vertices[3].point = point3(x - 0.8f, y - 0.7f, -0.8f);
    vertices[4].point = point3(x, y + 0.9f, 0.0f);
    sides[0] = color_set(rgb(0.90f, 0.25f, 0.25f));
    sides[1] = color_set(rgb(0.25f, 0.80f, 0.30f));
    sides[2] = color_set(rgb(0.25f, 0.45f, 0.95f));
    sides[3] = color_set(rgb(0.95f, 0.85f, 0.25f));
    sides[4] = color_set(rgb(0.70f, 0.35f, 0.85f));
    for (i = 0; i < 6; i++) {
        for (k = 0; k < 3; k++)
            triangles[i].vertexIndices[k] = kFaces[i][k];
        triangles[i].edgeFlag = kFlags[i];
        triangles[i].triangleAttributeSet = sides[i < 4 ? i : 4];
    }
    for (i = 0; i < 4; i++) {
        edges[i].vertexIndices[0] = (unsigned long)i;
        edges[i].vertexIndices[1] = 4;
        edges[i].triangleIndices[0] = (unsigned long)i;
        edges[i].triangleIndices[1] = (unsigned long)((i + 3) % 4);
        edges[i].edgeAttributeSet = white;
    }
    memset(&data, 0, sizeof data);
    data.numVertices = 5;
    data.vertices = vertices;
    data.numEdges = 4;
    data.edges = edges;
    data.numTriangles = 6;
    data.triangles = triangles;
    status = submit_new(Q3Polyhedron_New(&data), view);
    for (i = 0; i < 5; i++)
        dispose(sides[i]);
    dispose(white);
    return status;
}

/* A 4 x 6 grid over a gentle wave, its facets alternately cyan and pink,
 * one corner vertex yellow. */
static TQ3Status submit_wave_grid(TQ3ViewObject view, float x, float y)
{
    enum { ROWS = 4, COLUMNS = 6, FACETS = 2 * (ROWS - 1) * (COLUMNS - 1) };
    TQ3Vertex3D vertices[ROWS * COLUMNS];
    TQ3AttributeSet facets[FACETS];
    TQ3AttributeSet cyan = color_set(rgb(0.30f, 0.85f, 0.90f));
    TQ3AttributeSet pink = color_set(rgb(0.95f, 0.45f, 0.70f));
    TQ3AttributeSet yellow = color_set(rgb(1.0f, 0.95f, 0.2f));
    TQ3TriGridData data;
    TQ3Status status;
    int row, column, i;

    memset(vertices, 0, sizeof vertices);
    for (row = 0; row < ROWS; row++)
        for (column = 0; column < COLUMNS; column++)
            vertices[row * COLUMNS + column].point =
                point3(x + 0.4f * (float)column - 1.0f, y - 0.45f * (float)row + 0.7f,
                       0.25f * sinf(1.3f * (float)column) * cosf(0.9f * (float)row));
    vertices[0].attributeSet = yellow;
    for (i = 0; i < FACETS; i++)
        facets[i] = (i % 2 == 0) ? cyan : pink;
    memset(&data, 0, sizeof data);
    data.numRows = ROWS;
    data.numColumns = COLUMNS;
    data.vertices = vertices;
    data.facetAttributeSet = facets;
    status = submit_new(Q3TriGrid_New(&data), view);
    dispose(cyan);
    dispose(pink);
    dispose(yellow);
    return status;
}

static TQ3Status submit_polyhedron_and_grid(TQ3ViewObject view)
{
    TQ3Status status = submit_pyramid(view, -1.3f, 0.0f);
    if (submit_wave_grid(view, 1.4f, 0.0f) != kQ3Success)
        status = kQ3Failure;
    return status;
}

/* An 8 x 8 cross-hair bitmap (most significant bit first). */
static const unsigned char kCross[8] = {0x18, 0x18, 0x18, 0xFF, 0xFF, 0x18, 0x18, 0x18};
/* A 12 x 3 bar (two bytes a row, least significant bit first). */
static const unsigned char kBar[6] = {0xFF, 0x0F, 0xFF, 0x0F, 0xFF, 0x0F};

static void set_marker(TQ3MarkerData *data, TQ3Point3D at, long x, long y, const unsigned char *bits,
                       unsigned long width, unsigned long height, unsigned long rowBytes, TQ3Endian order)
{
    memset(data, 0, sizeof *data);
    data->location = at;
    data->xOffset = x;
    data->yOffset = y;
    data->bitmap.image = (unsigned char *)bits;
    data->bitmap.width = width;
    data->bitmap.height = height;
    data->bitmap.rowBytes = rowBytes;
    data->bitmap.bitOrder = order;
}

/* Markers at the corners of a grey triangle: a red cross centred on the
 * left corner, a green cross above and right of the top corner, a blue bar
 * under the right corner, and a white cross on the nearer side of the
 * triangle (drawn over it) and a yellow one behind it (hidden by it in the
 * interactive renderer). */
static TQ3Status submit_markers(TQ3ViewObject view)
{
    TQ3TriangleData triangle;
    TQ3MarkerData data;
    TQ3AttributeSet grey = color_set(rgb(0.5f, 0.5f, 0.55f));
    TQ3AttributeSet red = color_set(rgb(0.95f, 0.2f, 0.2f));
    TQ3AttributeSet green = color_set(rgb(0.2f, 0.9f, 0.3f));
    TQ3AttributeSet blue = color_set(rgb(0.3f, 0.5f, 1.0f));
    TQ3AttributeSet white = color_set(rgb(1.0f, 1.0f, 1.0f));
    TQ3AttributeSet yellow = color_set(rgb(1.0f, 0.9f, 0.2f));
    TQ3Status status = kQ3Success;

    memset(&triangle, 0, sizeof triangle);
    triangle.vertices[0].point = point3(-1.5f, -1.0f, 0.0f);
    triangle.vertices[1].point = point3(1.5f, -1.0f, 0.0f);
    triangle.vertices[2].point = point3(0.0f, 1.2f, 0.0f);
    triangle.triangleAttributeSet = grey;
    if (Q3Triangle_Submit(&triangle, view) != kQ3Success)
        status = kQ3Failure;

    set_marker(&data, triangle.vertices[0].point, -4, -4, kCross, 8, 8, 1, kQ3EndianBig);
    data.markerAttributeSet = red;
    if (submit_new(Q3Marker_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    set_marker(&data, triangle.vertices[2].point, 6, -14, kCross, 8, 8, 1, kQ3EndianBig);
    data.markerAttributeSet = green;
    if (Q3Marker_Submit(&data, view) != kQ3Success)
        status = kQ3Failure;
    set_marker(&data, triangle.vertices[1].point, -6, 6, kBar, 12, 3, 2, kQ3EndianLittle);
    data.markerAttributeSet = blue;
    if (Q3Marker_Submit(&data, view) != kQ3Success)
        status = kQ3Failure;
    set_marker(&data, point3(-0.3f, 0.0f, 0.5f), -4, -4, kCross, 8, 8, 1, kQ3EndianBig);
    data.markerAttributeSet = white;
    if (Q3Marker_Submit(&data, view) != kQ3Success)
        status = kQ3Failure;
    set_marker(&data, point3(0.3f, 0.0f, -0.5f), -4, -4, kCross, 8, 8, 1, kQ3EndianBig);
    data.markerAttributeSet = yellow;
    if (Q3Marker_Submit(&data, view) != kQ3Success)
        status = kQ3Failure;
    dispose(grey);
    dispose(red);
    dispose(green);
    dispose(blue);
    dispose(white);
    dispose(yellow);
    return status;
}

/* Everything above in one wireframe picture. */
static TQ3Status submit_polygons_wireframe(TQ3ViewObject view)
{
    TQ3Status status = kQ3Success;
    TQ3TransformObject shift;
    TQ3Vector3D up = {0.0f, 1.4f, 0.0f};
    TQ3Vector3D down = {0.0f, -2.8f, 0.0f};

    if (Q3Push_Submit(view) != kQ3Success)
        return kQ3Failure;
    shift = Q3TranslateTransform_New(&up);
    if (shift == NULL || Q3Object_Submit(shift, view) != kQ3Success ||
        submit_general_polygons_into(view) != kQ3Success)
        status = kQ3Failure;
    dispose(shift);
    shift = Q3TranslateTransform_New(&down);
    if (shift == NULL || Q3Object_Submit(shift, view) != kQ3Success ||
        submit_polyhedron_and_grid(view) != kQ3Success)
        status = kQ3Failure;
    dispose(shift);
    if (Q3Pop_Submit(view) != kQ3Success)
        status = kQ3Failure;
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
    {"box_faces", "Two Boxes in their six face colours: right, front, top; and turned, left, back, bottom",
     kQ3RendererTypeInteractive, {2.6f, 2.4f, 5.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_boxes},
    {"cone_bottom", "Cones seen from below: orange sides, blue bottoms, a green cut where a quarter is missing",
     kQ3RendererTypeInteractive, {0.8f, -2.6f, 5.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_cones},
    {"cylinder_caps", "A Cylinder with a yellow top, and its back half with the red cut face",
     kQ3RendererTypeInteractive, {0.8f, 2.8f, 5.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_cylinders},
    {"disk_sector", "A purple elliptic Disk and an orange ring sector (u 0 to 3/4, v 0.4 to 1)",
     kQ3RendererTypeInteractive, {0.0f, 1.0f, 5.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_disks},
    {"ellipse_arcs", "A blue Ellipse and a red arc of a circle (u 1/8 to 7/8)", kQ3RendererTypeInteractive,
     {0.0f, 0.0f, 5.0f}, 0.75f, {0.95f, 0.95f, 0.95f}, submit_ellipses},
    {"ellipsoid_cutaway", "A red sphere with a yellow-faced quarter cut, an ellipsoid with its top capped",
     kQ3RendererTypeInteractive, {1.6f, 2.2f, 5.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_ellipsoids},
    {"torus_cutaway", "An orange Torus, and a blue one with a quarter cut and green cross-sections",
     kQ3RendererTypeInteractive, {0.0f, 3.2f, 4.2f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_tori},
    {"quadrics_wireframe", "Box, cone, cylinder, disk; ellipse, ellipsoid, torus in wireframe, 12-pixel subdivision",
     kQ3RendererTypeWireFrame, {1.2f, 1.6f, 7.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_all_quadrics},
    {"mesh_interactive", "A Mesh: an orange face with a hole, a folded face in vertex colours and a magenta corner",
     kQ3RendererTypeInteractive, {0.0f, 0.0f, 6.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_mesh},
    {"mesh_wireframe", "The same Mesh outlined: both contours of the holed face, the shared edge in white",
     kQ3RendererTypeWireFrame, {0.0f, 0.0f, 6.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_mesh},
    {"patch_plain_wireframe", "A bicubic NURB patch, a hill and a dipping corner, 16-pixel subdivision",
     kQ3RendererTypeWireFrame, {0.0f, 3.8f, 5.4f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_plain_patch_wireframe},
    {"patch_trimmed_wireframe", "The same patch trimmed: a circular hole with a square island in it",
     kQ3RendererTypeWireFrame, {0.0f, 3.8f, 5.4f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_trimmed_patch_wireframe},
    {"patch_cylinder_wireframe", "A rational patch that is exactly half a cylinder, 16-pixel subdivision",
     kQ3RendererTypeWireFrame, {4.2f, 3.0f, 1.8f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_cylinder_patch_wireframe},
    {"general_polygons", "GeneralPolygons: a square with a hole and an island; a concave star, red to blue, with a hole of white corners",
     kQ3RendererTypeInteractive, {0.0f, 0.0f, 5.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_general_polygons},
    {"polyhedron_trigrid", "A Polyhedron pyramid in its triangles' colours and a TriGrid wave in its facets' colours",
     kQ3RendererTypeInteractive, {0.6f, 1.8f, 5.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_polyhedron_and_grid},
    {"polygons_wireframe", "The general polygons, the polyhedron (edge flags, white edges) and the grid in wireframe",
     kQ3RendererTypeWireFrame, {0.6f, 1.0f, 7.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_polygons_wireframe},
    {"markers", "Markers in screen space at a triangle's corners; a white one in front of it, a yellow one hidden",
     kQ3RendererTypeInteractive, {0.0f, 0.0f, 5.0f}, 0.75f, {0.12f, 0.12f, 0.16f}, submit_markers},
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

static TQ3ViewObject new_view(const Q3Scene *scene, TQ3GroupObject lights, unsigned long width,
                              unsigned long height, unsigned char *argb)
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
        Q3View_SetRendererByType(view, scene->renderer) != kQ3Success ||
        (lights != NULL && Q3View_SetLightGroup(view, lights) != kQ3Success))
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
    return q3scene_render_lit(scene, NULL, width, height, rgba);
}

int q3scene_render_lit(const Q3Scene *scene, TQ3GroupObject lights, unsigned long width, unsigned long height,
                       unsigned char *rgba)
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
    view = new_view(scene, lights, width, height, argb);
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
