/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Legacy code for the QuickDraw 3D 1.6 Mesh, written the way 1990s
 * Macintosh samples were (declarations first, Apple's headers by their own
 * names, every status checked), built with nothing but -I include/Q3: it
 * must compile unmodified against Q3. It builds a square with a square hole
 * and a triangle beside it, gives parts attribute sets, walks it with every
 * Q3ForEach macro, turns the hole into a face and back, bounds it and
 * deletes it piece by piece. Returns 0 when every call did what the 1.6 API
 * promises.
 */
#include <QD3D.h>
#include <QD3DErrors.h>
#include <QD3DGeometry.h>
#include <QD3DSet.h>
#include <QD3DView.h>

#include <stdio.h>

#include "LegacyCommon.h"

const char *gMyProgramName = "LegacyMesh";

static TQ3MeshVertex MyAddVertex(TQ3GeometryObject mesh, float x, float y, float z)
{
    TQ3Vertex3D vertex;

    vertex.point.x = x;
    vertex.point.y = y;
    vertex.point.z = z;
    vertex.attributeSet = NULL;
    return Q3Mesh_VertexNew(mesh, &vertex);
}

static void MyNoticeHandler(TQ3Notice firstNotice, TQ3Notice lastNotice, long refCon)
{
    (void)firstNotice;
    (void)refCon;
    if (lastNotice != kQ3NoticeMeshVertexHasNoComponent)
        gFailures++;
}

int main(void)
{
    TQ3GeometryObject mesh;
    TQ3MeshVertex outer[4], inner[4], triangle[3], vertex, neighbour, v1, v2;
    TQ3MeshFace square, hole, side, face, other, f1, f2;
    TQ3MeshEdge edge;
    TQ3MeshContour contour;
    TQ3MeshComponent component;
    TQ3MeshIterator iterator, inside;
    TQ3AttributeSet red, green, blue, got;
    TQ3ViewObject view;
    TQ3BoundingBox bounds;
    TQ3PlaneEquation plane;
    TQ3Point3D point;
    TQ3Boolean flag;
    unsigned long count, index, total;
    int i;

    if (Q3Initialize() != kQ3Success)
        return 1;
    Q3Notice_Register(MyNoticeHandler, 0);

    mesh = Q3Mesh_New();
    if (mesh == NULL)
        return 2;
    CHECK(Q3Mesh_DelayUpdates(mesh));
    outer[0] = MyAddVertex(mesh, 0, 0, 0);
    outer[1] = MyAddVertex(mesh, 4, 0, 0);
    outer[2] = MyAddVertex(mesh, 4, 4, 0);
    outer[3] = MyAddVertex(mesh, 0, 4, 0);
    inner[0] = MyAddVertex(mesh, 1, 1, 0);
    inner[1] = MyAddVertex(mesh, 1, 3, 0);
    inner[2] = MyAddVertex(mesh, 3, 3, 0);
    inner[3] = MyAddVertex(mesh, 3, 1, 0);
    triangle[0] = outer[1];
    triangle[1] = MyAddVertex(mesh, 6, 0, 0);
    triangle[2] = outer[2];

    red = MyNewColorSet(1, 0, 0);
    green = MyNewColorSet(0, 1, 0);
    blue = MyNewColorSet(0, 0, 1);
    square = Q3Mesh_FaceNew(mesh, 4, outer, red);
    hole = Q3Mesh_FaceNew(mesh, 4, inner, NULL);
    side = Q3Mesh_FaceNew(mesh, 3, triangle, green);
    EXPECT(square != NULL && hole != NULL && side != NULL);
    contour = Q3Mesh_FaceToContour(mesh, square, hole);
    EXPECT(contour != NULL);
    CHECK(Q3Mesh_ResumeUpdates(mesh));

    CHECK(Q3Mesh_GetNumVertices(mesh, &count));
    EXPECT(count == 9);
    CHECK(Q3Mesh_GetNumFaces(mesh, &count));
    EXPECT(count == 2);
    CHECK(Q3Mesh_GetNumEdges(mesh, &count));
    EXPECT(count == 10);
    CHECK(Q3Mesh_GetNumComponents(mesh, &count));
    EXPECT(count == 1);
    CHECK(Q3Mesh_GetOrientable(mesh, &flag));
    EXPECT(flag == kQ3True);
    CHECK(Q3Mesh_GetFaceNumContours(mesh, square, &count));
    EXPECT(count == 2);
    CHECK(Q3Mesh_GetFaceNumVertices(mesh, square, &count));
    EXPECT(count == 8);
    CHECK(Q3Mesh_GetContourNumVertices(mesh, contour, &count));
    EXPECT(count == 4);
    CHECK(Q3Mesh_GetContourFace(mesh, contour, &face));
    EXPECT(face == square);
    CHECK(Q3Mesh_GetFaceIndex(mesh, side, &index));
    EXPECT(index == 1);
    CHECK(Q3Mesh_GetVertexIndex(mesh, triangle[1], &index));
    EXPECT(index == 8);
    CHECK(Q3Mesh_GetFacePlaneEquation(mesh, square, &plane));
    EXPECT(plane.normal.z > 0.99f && plane.constant == 0.0f);

    /* Attribute sets on every kind of part. */
    CHECK(Q3Mesh_SetVertexAttributeSet(mesh, outer[0], blue));
    CHECK(Q3Mesh_GetVertexAttributeSet(mesh, outer[0], &got));
    EXPECT(got == blue);
    Q3Object_Dispose(got);
    CHECK(Q3Mesh_SetFaceAttributeSet(mesh, side, blue));
    CHECK(Q3Mesh_GetFaceAttributeSet(mesh, side, &got));
    EXPECT(got == blue);
    Q3Object_Dispose(got);
    CHECK(Q3Mesh_SetCornerAttributeSet(mesh, outer[1], side, red));
    CHECK(Q3Mesh_GetCornerAttributeSet(mesh, outer[1], side, &got));
    EXPECT(got == red);
    Q3Object_Dispose(got);
    CHECK(Q3Mesh_GetNumCorners(mesh, &count));
    EXPECT(count == 1);
    point.x = 6.5f;
    point.y = -1.0f;
    point.z = 0.0f;
    CHECK(Q3Mesh_SetVertexCoordinates(mesh, triangle[1], &point));
    CHECK(Q3Mesh_GetVertexCoordinates(mesh, triangle[1], &point));
    EXPECT(point.x == 6.5f);

    /* The edge the square and the triangle share. */
    total = 0;
    Q3ForEachMeshEdge(mesh, edge, &iterator)
    {
        CHECK(Q3Mesh_GetEdgeFaces(mesh, edge, &f1, &f2));
        CHECK(Q3Mesh_GetEdgeOnBoundary(mesh, edge, &flag));
        if (f2 != NULL) {
            total++;
            EXPECT(flag == kQ3False && f1 == square && f2 == side);
            CHECK(Q3Mesh_GetEdgeVertices(mesh, edge, &v1, &v2));
            EXPECT(v1 == outer[1] && v2 == outer[2]);
            CHECK(Q3Mesh_SetEdgeAttributeSet(mesh, edge, red));
            CHECK(Q3Mesh_GetEdgeAttributeSet(mesh, edge, &got));
            EXPECT(got == red);
            Q3Object_Dispose(got);
            CHECK(Q3Mesh_GetEdgeComponent(mesh, edge, &component));
        }
    }
    EXPECT(total == 1);

    /* Every walk. */
    total = 0;
    Q3ForEachMeshComponent(mesh, component, &iterator)
    {
        CHECK(Q3Mesh_GetComponentNumVertices(mesh, component, &count));
        EXPECT(count == 9);
        CHECK(Q3Mesh_GetComponentNumEdges(mesh, component, &count));
        EXPECT(count == 10);
        CHECK(Q3Mesh_GetComponentBoundingBox(mesh, component, &bounds));
        EXPECT(bounds.max.x == 6.5f && bounds.min.y == -1.0f);
        CHECK(Q3Mesh_GetComponentOrientable(mesh, component, &flag));
        Q3ForEachComponentVertex(component, vertex, &inside) total++;
        Q3ForEachComponentEdge(component, edge, &inside) total++;
    }
    EXPECT(total == 19);
    total = 0;
    Q3ForEachMeshVertex(mesh, vertex, &iterator)
    {
        CHECK(Q3Mesh_GetVertexOnBoundary(mesh, vertex, &flag));
        CHECK(Q3Mesh_GetVertexComponent(mesh, vertex, &component));
        Q3ForEachVertexEdge(vertex, edge, &inside) total++;
        Q3ForEachVertexVertex(vertex, neighbour, &inside) total++;
        Q3ForEachVertexFace(vertex, face, &inside) total++;
    }
    /* 10 edges (20 ends), 20 neighbours, 11 corners. */
    EXPECT(total == 51);
    total = 0;
    Q3ForEachMeshFace(mesh, face, &iterator)
    {
        CHECK(Q3Mesh_GetFaceComponent(mesh, face, &component));
        Q3ForEachFaceEdge(face, edge, &inside) total++;
        Q3ForEachFaceVertex(face, vertex, &inside) total++;
        Q3ForEachFaceFace(face, other, &inside) total++;
        Q3ForEachFaceContour(face, contour, &inside)
        {
            TQ3MeshIterator around;
            Q3ForEachContourEdge(contour, edge, &around) total++;
            Q3ForEachContourVertex(contour, vertex, &around) total++;
            Q3ForEachContourFace(contour, other, &around) total++;
        }
    }
    /* square: 8 edges, 8 corners, 1 neighbour, contours 4+4 edges, 4+4
       vertices, 1 neighbour; triangle: 3, 3, 1, 3, 3, 1. */
    EXPECT(total == 8 + 8 + 1 + 8 + 8 + 1 + 3 + 3 + 1 + 3 + 3 + 1);

    /* Bounds through a bounding loop. */
    view = Q3View_New();
    CHECK(Q3View_StartBoundingBox(view, kQ3ComputeBoundsExact));
    do {
        CHECK(Q3Geometry_Submit(mesh, view));
    } while (Q3View_EndBoundingBox(view, &bounds) == kQ3ViewStatusRetraverse);
    EXPECT(bounds.min.x == 0.0f && bounds.max.x == 6.5f && bounds.max.y == 4.0f);

    /* The hole back out as a face, then taken apart. */
    contour = Q3Mesh_FirstFaceContour(square, &iterator);
    contour = Q3Mesh_NextFaceContour(&iterator);
    face = Q3Mesh_ContourToFace(mesh, contour);
    EXPECT(face != NULL);
    CHECK(Q3Mesh_GetNumComponents(mesh, &count));
    EXPECT(count == 2);
    CHECK(Q3Mesh_FaceDelete(mesh, face));
    CHECK(Q3Mesh_VertexDelete(mesh, outer[1]));
    CHECK(Q3Mesh_GetNumFaces(mesh, &count));
    EXPECT(count == 0);
    CHECK(Q3Mesh_GetNumVertices(mesh, &count));
    EXPECT(count == 8);
    /* A deleted vertex is refused, not followed. */
    EXPECT(Q3Mesh_GetVertexIndex(mesh, outer[1], &index) == kQ3Failure &&
           Q3Error_Get(NULL) == kQ3ErrorInvalidParameter);
    /* A vertex in no face has no component: a notice, not an error. */
    CHECK(Q3Mesh_GetVertexComponent(mesh, outer[0], &component));
    EXPECT(component == NULL);
    for (i = 0; i < 4; i++)
        CHECK(Q3Mesh_VertexDelete(mesh, inner[i]));

    Q3Object_Dispose(view);
    Q3Object_Dispose(red);
    Q3Object_Dispose(green);
    Q3Object_Dispose(blue);
    Q3Object_Dispose(mesh);
    Q3Exit();
    if (gFailures == 0)
        printf("LegacyMesh: OK\n");
    return gFailures == 0 ? 0 : 3;
}
