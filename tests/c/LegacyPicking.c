/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Legacy code for QuickDraw 3D 1.6 picking, written the way 1990s Macintosh
 * samples were (declarations first, Apple's headers by their own names,
 * every status checked), built with nothing but -I include/Q3: it must
 * compile unmodified against Q3. A click handler in the style of Apple's
 * samples: a model of two boxes-worth of triangles in a display group, a
 * window-point pick at the "mouse", the picking loop with its
 * kQ3ViewStatusRetraverse do/while, then the hit list walked with
 * Q3Pick_GetPickDetailValidMask / Q3Pick_GetPickDetailData and the hit path
 * released with Q3HitPath_EmptyData. Returns 0 when every call did what the
 * 1.6 API promises.
 */
#include <QD3D.h>
#include <QD3DCamera.h>
#include <QD3DDrawContext.h>
#include <QD3DErrors.h>
#include <QD3DGeometry.h>
#include <QD3DGroup.h>
#include <QD3DPick.h>
#include <QD3DRenderer.h>
#include <QD3DStyle.h>
#include <QD3DView.h>

#include <stdio.h>
#include <stdlib.h>

#include "LegacyCommon.h"

const char *gMyProgramName = "LegacyPicking";

static TQ3GeometryObject MyNewTriangle(float x, float y, float z)
{
    TQ3TriangleData data;
    int i;

    for (i = 0; i < 3; i++)
        data.vertices[i].attributeSet = NULL;
    data.vertices[0].point.x = x - 1.0f;
    data.vertices[0].point.y = y - 1.0f;
    data.vertices[0].point.z = z;
    data.vertices[1].point.x = x + 1.0f;
    data.vertices[1].point.y = y - 1.0f;
    data.vertices[1].point.z = z;
    data.vertices[2].point.x = x;
    data.vertices[2].point.y = y + 1.0f;
    data.vertices[2].point.z = z;
    data.triangleAttributeSet = NULL;
    return Q3Triangle_New(&data);
}

static TQ3ViewObject MyNewView(TQ3Pixmap *pixmap)
{
    TQ3ViewObject view;
    TQ3PixmapDrawContextData contextData;
    TQ3DrawContextObject context;
    TQ3CameraObject camera;

    contextData.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
    contextData.drawContextData.clearImageColor.a = 1.0f;
    contextData.drawContextData.clearImageColor.r = 0.0f;
    contextData.drawContextData.clearImageColor.g = 0.0f;
    contextData.drawContextData.clearImageColor.b = 0.0f;
    contextData.drawContextData.paneState = kQ3False;
    contextData.drawContextData.pane.min.x = 0.0f;
    contextData.drawContextData.pane.min.y = 0.0f;
    contextData.drawContextData.pane.max.x = 0.0f;
    contextData.drawContextData.pane.max.y = 0.0f;
    contextData.drawContextData.maskState = kQ3False;
    contextData.drawContextData.doubleBufferState = kQ3False;
    contextData.pixmap = *pixmap;

    /* The camera looks down -z at the origin and shows x and y in -4..4. */

    view = Q3View_New();
    context = Q3PixmapDrawContext_New(&contextData);
    camera = MyNewOrthographicCamera(10.0f, 1.0f, 100.0f, -4.0f, 4.0f, 4.0f, -4.0f);
    CHECK(Q3View_SetDrawContext(view, context));
    CHECK(Q3View_SetCamera(view, camera));
    CHECK(Q3View_SetRendererByType(view, kQ3RendererTypeInteractive));
    Q3Object_Dispose(context);
    Q3Object_Dispose(camera);
    return view;
}

int main(void)
{
    TQ3Pixmap pixmap;
    TQ3ViewObject view;
    TQ3GroupObject model;
    TQ3GeometryObject front, back, aside;
    TQ3StyleObject backID;
    TQ3GroupPosition frontPosition;
    TQ3WindowPointPickData pickData;
    TQ3PickObject pick;
    TQ3ViewStatus status;
    unsigned long numHits, i, pickID;
    TQ3PickDetail validMask;
    TQ3HitPath hitPath;
    TQ3Object picked;
    float distance, lastDistance;
    TQ3Point3D xyz;

    if (Q3Initialize() != kQ3Success)
        return 1;

    pixmap.width = 64;
    pixmap.height = 64;
    pixmap.rowBytes = 64 * 4;
    pixmap.pixelSize = 32;
    pixmap.pixelType = kQ3PixelTypeARGB32;
    pixmap.bitOrder = kQ3EndianBig;
    pixmap.byteOrder = kQ3EndianBig;
    pixmap.image = calloc(64 * 64, 4);
    view = MyNewView(&pixmap);

    /* Two triangles one behind the other at the centre, one to the side. */
    model = Q3OrderedDisplayGroup_New();
    front = MyNewTriangle(0.0f, 0.0f, 1.0f);
    back = MyNewTriangle(0.0f, 0.0f, -1.0f);
    aside = MyNewTriangle(3.0f, 3.0f, 0.0f);
    backID = Q3PickIDStyle_New(8);
    Q3Group_AddObject(model, backID);
    Q3Group_AddObject(model, back);
    frontPosition = Q3Group_AddObject(model, front);
    Q3Group_AddObject(model, aside);
    EXPECT(frontPosition != NULL);

    /* The mouse at the centre of the window. */
    pickData.data.sort = kQ3PickSortNearToFar;
    pickData.data.mask = kQ3PickDetailMaskPickID | kQ3PickDetailMaskPath | kQ3PickDetailMaskObject |
                         kQ3PickDetailMaskXYZ | kQ3PickDetailMaskDistance;
    pickData.data.numHitsToReturn = kQ3ReturnAllHits;
    pickData.point.x = 32.0f;
    pickData.point.y = 32.0f;
    pickData.vertexTolerance = 2.0f;
    pickData.edgeTolerance = 2.0f;
    pick = Q3WindowPointPick_New(&pickData);
    EXPECT(pick != NULL);
    EXPECT(Q3Pick_GetType(pick) == kQ3PickTypeWindowPoint);

    CHECK(Q3View_StartPicking(view, pick));
    do {
        CHECK(Q3Object_Submit(model, view));
        status = Q3View_EndPicking(view);
    } while (status == kQ3ViewStatusRetraverse);
    EXPECT(status == kQ3ViewStatusDone);

    CHECK(Q3Pick_GetNumHits(pick, &numHits));
    EXPECT(numHits == 2);
    lastDistance = 0.0f;
    for (i = 0; i < numHits; i++) {
        CHECK(Q3Pick_GetPickDetailValidMask(pick, i, &validMask));
        EXPECT((validMask & kQ3PickDetailMaskPath) != 0);
        EXPECT((validMask & kQ3PickDetailMaskObject) != 0);
        CHECK(Q3Pick_GetPickDetailData(pick, i, kQ3PickDetailMaskPickID, &pickID));
        /* Both were drawn under the pick ID style 8 (the ordered group puts
         * styles first). */
        EXPECT(pickID == 8);
        CHECK(Q3Pick_GetPickDetailData(pick, i, kQ3PickDetailMaskDistance, &distance));
        EXPECT(distance >= lastDistance);
        lastDistance = distance;
        CHECK(Q3Pick_GetPickDetailData(pick, i, kQ3PickDetailMaskXYZ, &xyz));
        CHECK(Q3Pick_GetPickDetailData(pick, i, kQ3PickDetailMaskObject, &picked));
        EXPECT(picked == (i == 0 ? front : back));
        EXPECT(xyz.z == (i == 0 ? 1.0f : -1.0f));
        Q3Object_Dispose(picked);
        CHECK(Q3Pick_GetPickDetailData(pick, i, kQ3PickDetailMaskPath, &hitPath));
        EXPECT(hitPath.rootGroup == model);
        EXPECT(hitPath.depth == 1);
        if (i == 0)
            EXPECT(hitPath.positions[0] == frontPosition);
        CHECK(Q3HitPath_EmptyData(&hitPath));
    }

    /* The mouse over nothing: no hits; asking for one is an error. */
    pickData.point.x = 2.0f;
    pickData.point.y = 60.0f;
    CHECK(Q3WindowPointPick_SetPoint(pick, &pickData.point));
    CHECK(Q3View_StartPicking(view, pick));
    do {
        CHECK(Q3Object_Submit(model, view));
        status = Q3View_EndPicking(view);
    } while (status == kQ3ViewStatusRetraverse);
    CHECK(Q3Pick_GetNumHits(pick, &numHits));
    EXPECT(numHits == 0);
    EXPECT(Q3Pick_GetPickDetailValidMask(pick, 0, &validMask) == kQ3Failure);
    EXPECT(Q3Error_Get(NULL) == kQ3ErrorParameterOutOfRange);
    EXPECT(Q3View_EndPicking(view) == kQ3ViewStatusError);
    EXPECT(Q3Error_Get(NULL) == kQ3ErrorPickingNotStarted);

    /* A mesh picked by face: the hit's shape part names the face. */
    {
        static const TQ3Point3D corners[4] = {{-1.0f, -1.0f, 0.0f}, {1.0f, -1.0f, 0.0f},
                                              {1.0f, 1.0f, 0.0f}, {-1.0f, 1.0f, 0.0f}};
        TQ3GeometryObject mesh = Q3Mesh_New();
        TQ3MeshVertex vertices[4];
        TQ3MeshFace face, partFace = NULL;
        TQ3Vertex3D vertex;
        TQ3WorldRayPickData rayData;
        TQ3PickObject rayPick;
        TQ3ShapePartObject part = NULL;
        TQ3ShapeObject shape = NULL;
        int k;

        for (k = 0; k < 4; k++) {
            vertex.point = corners[k];
            vertex.attributeSet = NULL;
            vertices[k] = Q3Mesh_VertexNew(mesh, &vertex);
        }
        face = Q3Mesh_FaceNew(mesh, 4, vertices, NULL);
        rayData.data.sort = kQ3PickSortNearToFar;
        rayData.data.mask = kQ3PickDetailMaskShapePart;
        rayData.data.numHitsToReturn = kQ3ReturnAllHits;
        rayData.ray.origin.x = 0.25f;
        rayData.ray.origin.y = 0.5f;
        rayData.ray.origin.z = 10.0f;
        rayData.ray.direction.x = 0.0f;
        rayData.ray.direction.y = 0.0f;
        rayData.ray.direction.z = -1.0f;
        rayData.vertexTolerance = 0.01f;
        rayData.edgeTolerance = 0.01f;
        rayPick = Q3WorldRayPick_New(&rayData);
        CHECK(Q3View_StartPicking(view, rayPick));
        do {
            CHECK(Q3PickPartsStyle_Submit(kQ3PickPartsMaskFace, view));
            CHECK(Q3Object_Submit(mesh, view));
            status = Q3View_EndPicking(view);
        } while (status == kQ3ViewStatusRetraverse);
        CHECK(Q3Pick_GetNumHits(rayPick, &numHits));
        EXPECT(numHits == 1);
        CHECK(Q3Pick_GetPickDetailData(rayPick, 0, kQ3PickDetailMaskShapePart, &part));
        EXPECT(Q3ShapePart_GetType(part) == kQ3ShapePartTypeMeshPart);
        EXPECT(Q3MeshPart_GetType(part) == kQ3MeshPartTypeMeshFacePart);
        EXPECT(Q3Object_GetLeafType(part) == kQ3MeshPartTypeMeshFacePart);
        CHECK(Q3MeshFacePart_GetFace(part, &partFace));
        EXPECT(partFace == face);
        CHECK(Q3ShapePart_GetShape(part, &shape));
        EXPECT(shape == mesh);
        Q3Object_Dispose(shape);
        Q3Object_Dispose(part);
        Q3Object_Dispose(rayPick);
        Q3Object_Dispose(mesh);
    }

    Q3Object_Dispose(pick);
    Q3Object_Dispose(backID);
    Q3Object_Dispose(front);
    Q3Object_Dispose(back);
    Q3Object_Dispose(aside);
    Q3Object_Dispose(model);
    Q3Object_Dispose(view);
    free(pixmap.image);
    Q3Exit();

    if (gFailures == 0)
        printf("LegacyPicking: every call did what QuickDraw 3D 1.6 promises\n");
    return gFailures == 0 ? 0 : 3;
}
