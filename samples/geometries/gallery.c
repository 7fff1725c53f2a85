/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#include "gallery.h"

#include "lit_scenes.h"
#include "scene_util.h"
#include "scenes.h"

#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DMath.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"
#include "QD3DStyle.h"
#include "QD3DView.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

/* ---- Helpers ------------------------------------------------------------- */

/* A new attribute set with a diffuse colour (the caller disposes it). */
static TQ3AttributeSet colour(float r, float g, float b)
{
    return color_set(rgb(r, g, b));
}

static TQ3Vertex3D vertex(float x, float y, float z, TQ3AttributeSet set)
{
    TQ3Vertex3D v;
    v.point = point3(x, y, z);
    v.attributeSet = set;
    return v;
}

/* ---- One geometry of each type ------------------------------------------ */

static TQ3GeometryObject new_point(void)
{
    TQ3PointData data;
    TQ3GeometryObject g;
    data.point = point3(0, 0, 0);
    data.pointAttributeSet = colour(1.0f, 0.9f, 0.2f);
    g = Q3Point_New(&data);
    dispose(data.pointAttributeSet);
    return g;
}

static TQ3GeometryObject new_line(void)
{
    TQ3LineData data;
    TQ3GeometryObject g;
    TQ3AttributeSet red = colour(1, 0.2f, 0.2f), blue = colour(0.2f, 0.4f, 1);
    data.vertices[0] = vertex(-1.4f, -0.8f, 0, red);
    data.vertices[1] = vertex(1.4f, 0.8f, 0, blue);
    data.lineAttributeSet = NULL;
    g = Q3Line_New(&data);
    dispose(red);
    dispose(blue);
    return g;
}

static TQ3GeometryObject new_polyline(void)
{
    TQ3Vertex3D v[6];
    TQ3PolyLineData data;
    TQ3GeometryObject g;
    int i;
    for (i = 0; i < 6; i++)
        v[i] = vertex(-1.5f + 0.6f * (float)i, (i % 2) ? 0.7f : -0.7f, 0, NULL);
    data.numVertices = 6;
    data.vertices = v;
    data.segmentAttributeSet = NULL;
    data.polyLineAttributeSet = colour(0.3f, 0.9f, 0.5f);
    g = Q3PolyLine_New(&data);
    dispose(data.polyLineAttributeSet);
    return g;
}

static TQ3GeometryObject new_triangle(void)
{
    TQ3TriangleData data;
    TQ3GeometryObject g;
    TQ3AttributeSet c[3];
    int i;
    c[0] = colour(1, 0.2f, 0.2f);
    c[1] = colour(0.2f, 1, 0.3f);
    c[2] = colour(0.2f, 0.4f, 1);
    data.vertices[0] = vertex(-1.3f, -1.0f, 0, c[0]);
    data.vertices[1] = vertex(1.3f, -1.0f, 0, c[1]);
    data.vertices[2] = vertex(0.0f, 1.2f, 0, c[2]);
    data.triangleAttributeSet = NULL;
    g = Q3Triangle_New(&data);
    for (i = 0; i < 3; i++)
        dispose(c[i]);
    return g;
}

/* A concave arrow. */
static TQ3GeometryObject new_polygon(void)
{
    const float xy[7][2] = {{-1.4f, -0.4f}, {0.2f, -0.4f}, {0.2f, -1.0f}, {1.4f, 0.0f},
                            {0.2f, 1.0f},   {0.2f, 0.4f},  {-1.4f, 0.4f}};
    TQ3Vertex3D v[7];
    TQ3PolygonData data;
    TQ3GeometryObject g;
    int i;
    for (i = 0; i < 7; i++)
        v[i] = vertex(xy[i][0], xy[i][1], 0, NULL);
    data.numVertices = 7;
    data.vertices = v;
    data.polygonAttributeSet = colour(0.95f, 0.55f, 0.15f);
    g = Q3Polygon_New(&data);
    dispose(data.polygonAttributeSet);
    return g;
}

/* A square pyramid with a colour per vertex. */
static TQ3GeometryObject new_trimesh(void)
{
    TQ3Point3D points[5];
    TQ3ColorRGB colours[5];
    TQ3TriMeshTriangleData triangles[6] = {{{0, 1, 4}}, {{1, 2, 4}}, {{2, 3, 4}}, {{3, 0, 4}}, {{0, 3, 2}}, {{0, 2, 1}}};
    TQ3TriMeshAttributeData colourArray;
    TQ3TriMeshData data;
    points[0] = point3(-1, -0.8f, 1);
    points[1] = point3(1, -0.8f, 1);
    points[2] = point3(1, -0.8f, -1);
    points[3] = point3(-1, -0.8f, -1);
    points[4] = point3(0, 1.0f, 0);
    colours[0] = rgb(1, 0.2f, 0.2f);
    colours[1] = rgb(1, 0.9f, 0.2f);
    colours[2] = rgb(0.2f, 0.9f, 0.3f);
    colours[3] = rgb(0.2f, 0.4f, 1);
    colours[4] = rgb(0.95f, 0.95f, 0.95f);
    colourArray.attributeType = kQ3AttributeTypeDiffuseColor;
    colourArray.data = colours;
    colourArray.attributeUseArray = NULL;
    memset(&data, 0, sizeof data);
    data.numTriangles = 6;
    data.triangles = triangles;
    data.numPoints = 5;
    data.points = points;
    data.numVertexAttributeTypes = 1;
    data.vertexAttributeTypes = &colourArray;
    Q3BoundingBox_SetFromPoints3D(&data.bBox, points, 5, sizeof(TQ3Point3D));
    return Q3TriMesh_New(&data);
}

/* A cubic NURB curve through a wave. */
static TQ3GeometryObject new_nurb_curve(void)
{
    static TQ3RationalPoint4D points[6] = {{-1.5f, -0.6f, 0, 1}, {-0.9f, 1.2f, 0, 1}, {-0.3f, -1.2f, 0, 1},
                                           {0.3f, 1.2f, 0, 1},   {0.9f, -1.2f, 0, 1},  {1.5f, 0.6f, 0, 1}};
    static float knots[10] = {0, 0, 0, 0, 1, 2, 3, 3, 3, 3};
    TQ3NURBCurveData data;
    TQ3GeometryObject g;
    data.order = 4;
    data.numPoints = 6;
    data.controlPoints = points;
    data.knots = knots;
    data.curveAttributeSet = colour(0.9f, 0.3f, 0.9f);
    g = Q3NURBCurve_New(&data);
    dispose(data.curveAttributeSet);
    return g;
}

/* A bicubic bulge towards the viewer with a square hole (a clockwise trim
 * loop). */
static TQ3GeometryObject new_nurb_patch(void)
{
    static TQ3RationalPoint3D hole[5] = {{0.35f, 0.35f, 1}, {0.35f, 0.65f, 1}, {0.65f, 0.65f, 1},
                                         {0.65f, 0.35f, 1}, {0.35f, 0.35f, 1}};
    static float holeKnots[7] = {0, 0, 1, 2, 3, 4, 4};
    static float knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    TQ3RationalPoint4D points[16];
    TQ3NURBPatchTrimCurveData curve;
    TQ3NURBPatchTrimLoopData loop;
    TQ3NURBPatchData data;
    TQ3GeometryObject g;
    int i, j;
    for (j = 0; j < 4; j++)
        for (i = 0; i < 4; i++) {
            TQ3RationalPoint4D *p = &points[4 * j + i];
            p->x = -1.4f + 0.933f * (float)i;
            p->y = -1.1f + 0.733f * (float)j;
            p->z = ((i == 1 || i == 2) && (j == 1 || j == 2)) ? 1.0f : -0.4f;
            p->w = 1;
        }
    curve.order = 2;
    curve.numPoints = 5;
    curve.controlPoints = hole;
    curve.knots = holeKnots;
    loop.numTrimCurves = 1;
    loop.trimCurves = &curve;
    data.uOrder = data.vOrder = 4;
    data.numRows = data.numColumns = 4;
    data.controlPoints = points;
    data.uKnots = data.vKnots = knots;
    data.numTrimLoops = 1;
    data.trimLoops = &loop;
    data.patchAttributeSet = colour(0.3f, 0.75f, 0.9f);
    g = Q3NURBPatch_New(&data);
    dispose(data.patchAttributeSet);
    return g;
}

static void set_frame(TQ3Point3D *origin, TQ3Vector3D *orientation, TQ3Vector3D *major, TQ3Vector3D *minor,
                      float height, float radius)
{
    *origin = point3(0, -height / 2, 0);
    *orientation = vector3(0, height, 0);
    *major = vector3(0, 0, radius);
    *minor = vector3(radius, 0, 0);
}

static TQ3GeometryObject new_box(void)
{
    TQ3BoxData data;
    TQ3AttributeSet faces[6];
    TQ3GeometryObject g;
    int i;
    const float c[6][3] = {{0.9f, 0.2f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.2f, 0.4f, 0.95f},
                           {0.95f, 0.85f, 0.2f}, {0.2f, 0.85f, 0.9f}, {0.85f, 0.3f, 0.85f}};
    for (i = 0; i < 6; i++)
        faces[i] = colour(c[i][0], c[i][1], c[i][2]);
    data.origin = point3(-0.8f, -0.8f, -0.8f);
    data.orientation = vector3(0, 1.6f, 0);
    data.majorAxis = vector3(0, 0, 1.6f);
    data.minorAxis = vector3(1.6f, 0, 0);
    data.faceAttributeSet = faces;
    data.boxAttributeSet = NULL;
    g = Q3Box_New(&data);
    for (i = 0; i < 6; i++)
        dispose(faces[i]);
    return g;
}

static TQ3GeometryObject new_cone(void)
{
    TQ3ConeData data;
    TQ3GeometryObject g;
    memset(&data, 0, sizeof data);
    set_frame(&data.origin, &data.orientation, &data.majorRadius, &data.minorRadius, 2.0f, 1.0f);
    data.uMax = data.vMax = 1;
    data.caps = kQ3EndCapMaskBottom;
    data.coneAttributeSet = colour(0.95f, 0.55f, 0.15f);
    data.bottomAttributeSet = colour(0.2f, 0.4f, 0.95f);
    g = Q3Cone_New(&data);
    dispose(data.coneAttributeSet);
    dispose(data.bottomAttributeSet);
    return g;
}

static TQ3GeometryObject new_cylinder(void)
{
    TQ3CylinderData data;
    TQ3GeometryObject g;
    memset(&data, 0, sizeof data);
    set_frame(&data.origin, &data.orientation, &data.majorRadius, &data.minorRadius, 1.8f, 0.9f);
    data.uMax = data.vMax = 1;
    data.caps = kQ3EndCapMaskTop | kQ3EndCapMaskBottom;
    data.cylinderAttributeSet = colour(0.3f, 0.8f, 0.4f);
    data.topAttributeSet = colour(0.95f, 0.85f, 0.2f);
    g = Q3Cylinder_New(&data);
    dispose(data.cylinderAttributeSet);
    dispose(data.topAttributeSet);
    return g;
}

static TQ3GeometryObject new_disk(void)
{
    TQ3DiskData data;
    TQ3GeometryObject g;
    memset(&data, 0, sizeof data);
    data.origin = point3(0, 0, 0);
    data.majorRadius = vector3(1.4f, 0, 0);
    data.minorRadius = vector3(0, 1.0f, 0);
    data.uMax = data.vMax = 1;
    data.diskAttributeSet = colour(0.7f, 0.35f, 0.9f);
    g = Q3Disk_New(&data);
    dispose(data.diskAttributeSet);
    return g;
}

static TQ3GeometryObject new_ellipse(void)
{
    TQ3EllipseData data;
    TQ3GeometryObject g;
    data.origin = point3(0, 0, 0);
    data.majorRadius = vector3(1.4f, 0, 0);
    data.minorRadius = vector3(0, 0.9f, 0);
    data.uMin = 0;
    data.uMax = 1;
    data.ellipseAttributeSet = colour(0.3f, 0.6f, 1.0f);
    g = Q3Ellipse_New(&data);
    dispose(data.ellipseAttributeSet);
    return g;
}

static TQ3GeometryObject new_ellipsoid(void)
{
    TQ3EllipsoidData data;
    TQ3GeometryObject g;
    memset(&data, 0, sizeof data);
    data.origin = point3(0, 0, 0);
    data.orientation = vector3(0, 0.9f, 0);
    data.majorRadius = vector3(0, 0, 1.0f);
    data.minorRadius = vector3(1.4f, 0, 0);
    data.uMax = data.vMax = 1;
    data.ellipsoidAttributeSet = colour(0.9f, 0.25f, 0.25f);
    g = Q3Ellipsoid_New(&data);
    dispose(data.ellipsoidAttributeSet);
    return g;
}

static TQ3GeometryObject new_torus(void)
{
    TQ3TorusData data;
    TQ3GeometryObject g;
    memset(&data, 0, sizeof data);
    data.origin = point3(0, 0, 0);
    data.orientation = vector3(0, 0.4f, 0);
    data.majorRadius = vector3(0, 0, 1.1f);
    data.minorRadius = vector3(1.1f, 0, 0);
    data.ratio = 1;
    data.uMax = data.vMax = 1;
    data.torusAttributeSet = colour(0.95f, 0.6f, 0.2f);
    g = Q3Torus_New(&data);
    dispose(data.torusAttributeSet);
    return g;
}

/* Two faces sharing an edge; the first has a square hole. */
static TQ3GeometryObject new_mesh(void)
{
    const float xy[11][2] = {{-1.5f, -1}, {0.3f, -1}, {0.3f, 1}, {-1.5f, 1}, {-1, -0.5f}, {-1, 0.5f},
                             {-0.2f, 0.5f}, {-0.2f, -0.5f}, {1.5f, 0}, {0, 0}, {0, 0}};
    TQ3GeometryObject mesh = Q3Mesh_New();
    TQ3MeshVertex v[9];
    TQ3MeshVertex outline[4], hole[4], right[3];
    TQ3MeshFace face, holeFace;
    TQ3AttributeSet orange = colour(0.95f, 0.55f, 0.15f), green = colour(0.3f, 0.85f, 0.4f);
    int i, ok = mesh != NULL;
    for (i = 0; ok && i < 9; i++) {
        TQ3Vertex3D vx = vertex(xy[i][0], xy[i][1], 0, NULL);
        v[i] = Q3Mesh_VertexNew(mesh, &vx);
        ok = v[i] != NULL;
    }
    if (ok) {
        for (i = 0; i < 4; i++) {
            outline[i] = v[i];
            hole[i] = v[4 + i];
        }
        right[0] = v[1];
        right[1] = v[8];
        right[2] = v[2];
        face = Q3Mesh_FaceNew(mesh, 4, outline, orange);
        holeFace = Q3Mesh_FaceNew(mesh, 4, hole, NULL);
        ok = face != NULL && holeFace != NULL && Q3Mesh_FaceToContour(mesh, face, holeFace) != NULL &&
             Q3Mesh_FaceNew(mesh, 3, right, green) != NULL;
    }
    dispose(orange);
    dispose(green);
    if (!ok) {
        dispose(mesh);
        return NULL;
    }
    return mesh;
}

/* A square with a square hole and an island in the hole (even-odd). */
static TQ3GeometryObject new_general_polygon(void)
{
    const float sizes[3] = {1.3f, 0.8f, 0.35f};
    TQ3Vertex3D v[3][4];
    TQ3GeneralPolygonContourData contours[3];
    TQ3GeneralPolygonData data;
    TQ3GeometryObject g;
    int c;
    for (c = 0; c < 3; c++) {
        const float h = sizes[c];
        v[c][0] = vertex(-h, -h, 0, NULL);
        v[c][1] = vertex(h, -h, 0, NULL);
        v[c][2] = vertex(h, h, 0, NULL);
        v[c][3] = vertex(-h, h, 0, NULL);
        contours[c].numVertices = 4;
        contours[c].vertices = v[c];
    }
    data.numContours = 3;
    data.contours = contours;
    data.shapeHint = kQ3GeneralPolygonShapeHintComplex;
    data.generalPolygonAttributeSet = colour(0.95f, 0.75f, 0.2f);
    g = Q3GeneralPolygon_New(&data);
    dispose(data.generalPolygonAttributeSet);
    return g;
}

/* A square pyramid of four side triangles in their own colours, its base
 * edges listed. */
static TQ3GeometryObject new_polyhedron(void)
{
    TQ3Vertex3D v[5];
    TQ3PolyhedronTriangleData triangles[4];
    TQ3PolyhedronEdgeData edges[4];
    TQ3PolyhedronData data;
    TQ3AttributeSet sides[4];
    TQ3GeometryObject g;
    const float c[4][3] = {{0.9f, 0.25f, 0.25f}, {0.25f, 0.8f, 0.35f}, {0.25f, 0.45f, 0.95f}, {0.95f, 0.85f, 0.25f}};
    int i;
    v[0] = vertex(-1, -0.8f, 1, NULL);
    v[1] = vertex(1, -0.8f, 1, NULL);
    v[2] = vertex(1, -0.8f, -1, NULL);
    v[3] = vertex(-1, -0.8f, -1, NULL);
    v[4] = vertex(0, 1.0f, 0, NULL);
    for (i = 0; i < 4; i++) {
        sides[i] = colour(c[i][0], c[i][1], c[i][2]);
        triangles[i].vertexIndices[0] = (unsigned long)i;
        triangles[i].vertexIndices[1] = (unsigned long)((i + 1) % 4);
        triangles[i].vertexIndices[2] = 4;
        triangles[i].edgeFlag = kQ3PolyhedronEdgeAll;
        triangles[i].triangleAttributeSet = sides[i];
        edges[i].vertexIndices[0] = (unsigned long)i;
        edges[i].vertexIndices[1] = (unsigned long)((i + 1) % 4);
        edges[i].triangleIndices[0] = (unsigned long)i;
        edges[i].triangleIndices[1] = kQ3ArrayIndexNULL;
        edges[i].edgeAttributeSet = NULL;
    }
    data.numVertices = 5;
    data.vertices = v;
    data.numEdges = 4;
    data.edges = edges;
    data.numTriangles = 4;
    data.triangles = triangles;
    data.polyhedronAttributeSet = NULL;
    g = Q3Polyhedron_New(&data);
    for (i = 0; i < 4; i++)
        dispose(sides[i]);
    return g;
}

/* A 4 x 6 grid over a wave. */
static TQ3GeometryObject new_trigrid(void)
{
    TQ3Vertex3D v[24];
    TQ3TriGridData data;
    TQ3GeometryObject g;
    int r, c;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 6; c++)
            v[6 * r + c] = vertex(-1.5f + 0.6f * (float)c, -1.0f + 0.66f * (float)r,
                                  0.35f * (float)sin(1.3 * c + 0.8 * r), NULL);
    data.numRows = 4;
    data.numColumns = 6;
    data.vertices = v;
    data.facetAttributeSet = NULL;
    data.triGridAttributeSet = colour(0.3f, 0.8f, 0.85f);
    g = Q3TriGrid_New(&data);
    dispose(data.triGridAttributeSet);
    return g;
}

/* A 16 x 16 bitmap of a ring, drawn centred on the origin. */
static TQ3GeometryObject new_marker(void)
{
    static unsigned char bits[16 * 2];
    TQ3MarkerData data;
    TQ3GeometryObject g;
    int x, y;
    memset(bits, 0, sizeof bits);
    for (y = 0; y < 16; y++)
        for (x = 0; x < 16; x++) {
            const double d = hypot(x - 7.5, y - 7.5);
            if (d > 4.5 && d < 7.5)
                bits[2 * y + x / 8] |= (unsigned char)(0x80 >> (x % 8));
        }
    data.location = point3(0, 0, 0);
    data.xOffset = -8;
    data.yOffset = -8;
    data.bitmap.image = bits;
    data.bitmap.width = 16;
    data.bitmap.height = 16;
    data.bitmap.rowBytes = 2;
    data.bitmap.bitOrder = kQ3EndianBig;
    data.markerAttributeSet = colour(1.0f, 0.4f, 0.7f);
    g = Q3Marker_New(&data);
    dispose(data.markerAttributeSet);
    return g;
}

/* A 24 x 24 ARGB32 pixmap of a disc shaded from orange at its top left to
 * blue at its bottom right, transparent around it, drawn centred on the
 * origin. Its pixels live in a memory storage that the marker references. */
static TQ3GeometryObject new_pixmap_marker(void)
{
    enum { kSize = 24 };
    static unsigned char pixels[kSize * kSize * 4];
    TQ3PixmapMarkerData data;
    TQ3GeometryObject g;
    int x, y;
    for (y = 0; y < kSize; y++)
        for (x = 0; x < kSize; x++) {
            unsigned char *p = pixels + 4 * (kSize * y + x);
            const double d = hypot(x - 11.5, y - 11.5);
            const double t = (x + y) / (2.0 * (kSize - 1));
            p[0] = d < 11.5 ? 0xFF : 0x00; /* alpha 0 outside the disc */
            p[1] = (unsigned char)(255.0 * (1.0 - t) + 0.5);
            p[2] = (unsigned char)(140.0 * (1.0 - t) + 90.0 * t + 0.5);
            p[3] = (unsigned char)(30.0 * (1.0 - t) + 255.0 * t + 0.5);
        }
    data.position = point3(0, 0, 0);
    data.xOffset = -kSize / 2;
    data.yOffset = -kSize / 2;
    data.pixmap.image = Q3MemoryStorage_New(pixels, sizeof pixels);
    data.pixmap.width = kSize;
    data.pixmap.height = kSize;
    data.pixmap.rowBytes = kSize * 4;
    data.pixmap.pixelSize = 32;
    data.pixmap.pixelType = kQ3PixelTypeARGB32;
    data.pixmap.bitOrder = kQ3EndianBig;
    data.pixmap.byteOrder = kQ3EndianBig;
    data.pixmapMarkerAttributeSet = NULL;
    g = data.pixmap.image != NULL ? Q3PixmapMarker_New(&data) : NULL;
    dispose(data.pixmap.image);
    return g;
}

typedef struct Entry {
    const char *name;
    TQ3GeometryObject (*make)(void);
} Entry;

static const Entry kEntries[] = {
    {"point", new_point},         {"line", new_line},         {"polyline", new_polyline},
    {"triangle", new_triangle},   {"polygon", new_polygon},   {"trimesh", new_trimesh},
    {"mesh", new_mesh},           {"general_polygon", new_general_polygon}, {"polyhedron", new_polyhedron},
    {"trigrid", new_trigrid},     {"marker", new_marker},     {"pixmap_marker", new_pixmap_marker},
    {"nurb_curve", new_nurb_curve}, {"nurb_patch", new_nurb_patch},
    {"box", new_box},             {"cone", new_cone},         {"cylinder", new_cylinder},
    {"disk", new_disk},           {"ellipse", new_ellipse},   {"ellipsoid", new_ellipsoid},
    {"torus", new_torus},
};

unsigned long q3gallery_count(void)
{
    return sizeof kEntries / sizeof kEntries[0];
}

const char *q3gallery_name(unsigned long index)
{
    return index < q3gallery_count() ? kEntries[index].name : NULL;
}

TQ3GeometryObject q3gallery_new(unsigned long index)
{
    return index < q3gallery_count() ? kEntries[index].make() : NULL;
}

/* ---- Drawing --------------------------------------------------------------- */

/* What the scene's submit function draws (the sample is single-threaded). */
static TQ3Object s_geometry;
static int s_lit;

static TQ3Status submit_entry(TQ3ViewObject view)
{
    TQ3SubdivisionStyleData style;
    style.method = kQ3SubdivisionMethodScreenSpace;
    style.c1 = 14.0f;
    style.c2 = 14.0f;
    if (Q3SubdivisionStyle_Submit(&style, view) != kQ3Success)
        return kQ3Failure;
    if (s_lit) {
        TQ3ShaderObject phong = Q3PhongIllumination_New();
        TQ3Status status = phong != NULL ? Q3Shader_Submit(phong, view) : kQ3Failure;
        dispose(phong);
        if (status != kQ3Success)
            return kQ3Failure;
    }
    return Q3Object_Submit(s_geometry, view);
}

int q3gallery_render(unsigned long index, int lit, unsigned long width, unsigned long height, unsigned char *rgba)
{
    TQ3GeometryObject geometry;
    int result;

    if (index >= q3gallery_count())
        return 1;
    geometry = kEntries[index].make();
    if (geometry == NULL)
        return 1;
    result = q3gallery_render_object(geometry, lit, width, height, rgba);
    dispose(geometry);
    return result;
}

int q3gallery_render_object(TQ3Object object, int lit, unsigned long width, unsigned long height,
                            unsigned char *rgba)
{
    Q3Scene scene;
    TQ3GroupObject lights = NULL;
    int result;

    if (object == NULL)
        return 1;
    memset(&scene, 0, sizeof scene);
    scene.name = "gallery";
    scene.caption = "gallery";
    scene.renderer = lit ? kQ3RendererTypeInteractive : kQ3RendererTypeWireFrame;
    scene.eye = point3(1.0f, 1.3f, 4.3f);
    scene.fieldOfView = 0.75f;
    scene.background = rgb(0.12f, 0.12f, 0.16f);
    scene.submit = submit_entry;
    s_geometry = object;
    s_lit = lit;
    if (lit && (lights = q3litscene_new_lights(0.3f, 0.9f, vector3(0.6f, -0.6f, -0.8f))) == NULL)
        return 1;
    result = q3scene_render_lit(&scene, lights, width, height, rgba);
    dispose(lights);
    s_geometry = NULL;
    return result;
}
