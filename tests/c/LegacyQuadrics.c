/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Legacy code for the QuickDraw 3D 1.6 quadrics and solids, written the way
 * 1990s Macintosh samples were (declarations first, Apple's headers by
 * their own names, every status checked), built with nothing but
 * -I include/Q3: it must compile unmodified against Q3. It calls every box,
 * cone, cylinder, disk, ellipse, ellipsoid and torus routine and bounds what
 * it made. Returns 0 when every call did what the 1.6 API promises.
 */
#include <QD3D.h>
#include <QD3DErrors.h>
#include <QD3DGeometry.h>
#include <QD3DMath.h>
#include <QD3DSet.h>
#include <QD3DStyle.h>
#include <QD3DView.h>

#include <stdio.h>

#include "LegacyCommon.h"

const char *gMyProgramName = "LegacyQuadrics";

static void MyBox(TQ3ViewObject view, TQ3AttributeSet red)
{
    TQ3BoxData boxData;
    TQ3AttributeSet faces[6];
    TQ3GeometryObject box;
    TQ3Point3D origin;
    TQ3Vector3D vector;
    TQ3AttributeSet set;
    TQ3BoundingBox bounds;
    short i;

    for (i = 0; i < 6; i++)
        faces[i] = NULL;
    faces[4] = red;
    Q3Point3D_Set(&boxData.origin, -1.0f, -1.0f, -1.0f);
    Q3Vector3D_Set(&boxData.orientation, 0.0f, 2.0f, 0.0f);
    Q3Vector3D_Set(&boxData.majorAxis, 0.0f, 0.0f, 2.0f);
    Q3Vector3D_Set(&boxData.minorAxis, 2.0f, 0.0f, 0.0f);
    boxData.faceAttributeSet = faces;
    boxData.boxAttributeSet = NULL;

    box = Q3Box_New(&boxData);
    if (box == NULL) {
        gFailures++;
        return;
    }
    CHECK(Q3Box_GetOrigin(box, &origin));
    CHECK(Q3Box_SetOrigin(box, &origin));
    CHECK(Q3Box_GetOrientation(box, &vector));
    CHECK(Q3Box_SetOrientation(box, &vector));
    CHECK(Q3Box_GetMajorAxis(box, &vector));
    CHECK(Q3Box_SetMajorAxis(box, &vector));
    CHECK(Q3Box_GetMinorAxis(box, &vector));
    CHECK(Q3Box_SetMinorAxis(box, &vector));
    CHECK(Q3Box_GetFaceAttributeSet(box, 4, &set));
    MyCheckAndDisposeSet(set, red, "the top face's set");
    CHECK(Q3Box_SetFaceAttributeSet(box, 5, red));
    Check((TQ3Boolean)(Q3Box_SetFaceAttributeSet(box, 6, red) == kQ3Failure), "face 6 refused");
    CHECK(Q3Box_GetData(box, &boxData));
    CHECK(Q3Box_SetData(box, &boxData));
    CHECK(Q3Box_EmptyData(&boxData));

    /* Immediate mode, with the data on the stack. */
    Q3Point3D_Set(&boxData.origin, 0.0f, 0.0f, 0.0f);
    boxData.faceAttributeSet = NULL;
    boxData.boxAttributeSet = NULL;
    Q3Vector3D_Set(&boxData.orientation, 0.0f, 1.0f, 0.0f);
    Q3Vector3D_Set(&boxData.majorAxis, 0.0f, 0.0f, 1.0f);
    Q3Vector3D_Set(&boxData.minorAxis, 1.0f, 0.0f, 0.0f);
    CHECK(Q3View_StartBoundingBox(view, kQ3ComputeBoundsApproximate));
    do {
        CHECK(Q3Box_Submit(&boxData, view));
    } while (Q3View_EndBoundingBox(view, &bounds) == kQ3ViewStatusRetraverse);
    MyBoundAndDispose(view, box);
}

static void MyCone(TQ3ViewObject view, TQ3AttributeSet red)
{
    TQ3BoundingBox bounds;
    TQ3ConeData coneData;
    TQ3GeometryObject cone;
    TQ3Point3D origin;
    TQ3Vector3D vector;
    TQ3EndCap caps;
    TQ3AttributeSet set;

    Q3Point3D_Set(&coneData.origin, 0.0f, 0.0f, 0.0f);
    Q3Vector3D_Set(&coneData.orientation, 0.0f, 2.0f, 0.0f);
    Q3Vector3D_Set(&coneData.majorRadius, 0.0f, 0.0f, 1.0f);
    Q3Vector3D_Set(&coneData.minorRadius, 1.0f, 0.0f, 0.0f);
    coneData.uMin = 0.0f;
    coneData.uMax = 1.0f;
    coneData.vMin = 0.0f;
    coneData.vMax = 1.0f;
    coneData.caps = kQ3EndCapMaskBottom;
    coneData.interiorAttributeSet = NULL;
    coneData.faceAttributeSet = NULL;
    coneData.bottomAttributeSet = red;
    coneData.coneAttributeSet = NULL;

    cone = Q3Cone_New(&coneData);
    if (cone == NULL) {
        gFailures++;
        return;
    }
    CHECK(Q3Cone_GetOrigin(cone, &origin));
    CHECK(Q3Cone_SetOrigin(cone, &origin));
    CHECK(Q3Cone_GetOrientation(cone, &vector));
    CHECK(Q3Cone_SetOrientation(cone, &vector));
    CHECK(Q3Cone_GetMajorRadius(cone, &vector));
    CHECK(Q3Cone_SetMajorRadius(cone, &vector));
    CHECK(Q3Cone_GetMinorRadius(cone, &vector));
    CHECK(Q3Cone_SetMinorRadius(cone, &vector));
    CHECK(Q3Cone_GetCaps(cone, &caps));
    Check((TQ3Boolean)(caps == kQ3EndCapMaskBottom), "the cone's caps");
    CHECK(Q3Cone_SetCaps(cone, caps | kQ3EndCapMaskInterior));
    CHECK(Q3Cone_GetBottomAttributeSet(cone, &set));
    MyCheckAndDisposeSet(set, red, "the cone's bottom set");
    CHECK(Q3Cone_SetBottomAttributeSet(cone, NULL));
    CHECK(Q3Cone_SetFaceAttributeSet(cone, red));
    CHECK(Q3Cone_GetFaceAttributeSet(cone, &set));
    MyCheckAndDisposeSet(set, red, "the cone's face set");
    CHECK(Q3Cone_GetData(cone, &coneData));
    CHECK(Q3Cone_SetData(cone, &coneData));
    CHECK(Q3View_StartBoundingBox(view, kQ3ComputeBoundsApproximate));
    do {
        CHECK(Q3Cone_Submit(&coneData, view));
    } while (Q3View_EndBoundingBox(view, &bounds) == kQ3ViewStatusRetraverse);
    CHECK(Q3Cone_EmptyData(&coneData));
    MyBoundAndDispose(view, cone);
}

static void MyCylinder(TQ3ViewObject view, TQ3AttributeSet red)
{
    TQ3BoundingBox bounds;
    TQ3CylinderData cylinderData;
    TQ3GeometryObject cylinder;
    TQ3Point3D origin;
    TQ3Vector3D vector;
    TQ3EndCap caps;
    TQ3AttributeSet set;

    Q3Point3D_Set(&cylinderData.origin, 0.0f, 0.0f, 0.0f);
    Q3Vector3D_Set(&cylinderData.orientation, 0.0f, 2.0f, 0.0f);
    Q3Vector3D_Set(&cylinderData.majorRadius, 0.0f, 0.0f, 1.0f);
    Q3Vector3D_Set(&cylinderData.minorRadius, 1.0f, 0.0f, 0.0f);
    cylinderData.uMin = 0.0f;
    cylinderData.uMax = 0.75f;
    cylinderData.vMin = 0.0f;
    cylinderData.vMax = 1.0f;
    cylinderData.caps = kQ3EndCapMaskTop | kQ3EndCapMaskBottom | kQ3EndCapMaskInterior;
    cylinderData.interiorAttributeSet = NULL;
    cylinderData.topAttributeSet = red;
    cylinderData.faceAttributeSet = NULL;
    cylinderData.bottomAttributeSet = NULL;
    cylinderData.cylinderAttributeSet = NULL;

    cylinder = Q3Cylinder_New(&cylinderData);
    if (cylinder == NULL) {
        gFailures++;
        return;
    }
    CHECK(Q3Cylinder_GetOrigin(cylinder, &origin));
    CHECK(Q3Cylinder_SetOrigin(cylinder, &origin));
    CHECK(Q3Cylinder_GetOrientation(cylinder, &vector));
    CHECK(Q3Cylinder_SetOrientation(cylinder, &vector));
    CHECK(Q3Cylinder_GetMajorRadius(cylinder, &vector));
    CHECK(Q3Cylinder_SetMajorRadius(cylinder, &vector));
    CHECK(Q3Cylinder_GetMinorRadius(cylinder, &vector));
    CHECK(Q3Cylinder_SetMinorRadius(cylinder, &vector));
    CHECK(Q3Cylinder_GetCaps(cylinder, &caps));
    CHECK(Q3Cylinder_SetCaps(cylinder, caps & ~(TQ3EndCap)kQ3EndCapMaskInterior));
    CHECK(Q3Cylinder_GetTopAttributeSet(cylinder, &set));
    MyCheckAndDisposeSet(set, red, "the cylinder's top set");
    CHECK(Q3Cylinder_SetTopAttributeSet(cylinder, NULL));
    CHECK(Q3Cylinder_SetBottomAttributeSet(cylinder, red));
    CHECK(Q3Cylinder_GetBottomAttributeSet(cylinder, &set));
    MyCheckAndDisposeSet(set, red, "the cylinder's bottom set");
    CHECK(Q3Cylinder_SetFaceAttributeSet(cylinder, red));
    CHECK(Q3Cylinder_GetFaceAttributeSet(cylinder, &set));
    MyCheckAndDisposeSet(set, red, "the cylinder's face set");
    CHECK(Q3Cylinder_GetData(cylinder, &cylinderData));
    CHECK(Q3Cylinder_SetData(cylinder, &cylinderData));
    CHECK(Q3View_StartBoundingBox(view, kQ3ComputeBoundsApproximate));
    do {
        CHECK(Q3Cylinder_Submit(&cylinderData, view));
    } while (Q3View_EndBoundingBox(view, &bounds) == kQ3ViewStatusRetraverse);
    CHECK(Q3Cylinder_EmptyData(&cylinderData));
    MyBoundAndDispose(view, cylinder);
}

static void MyDiskAndEllipse(TQ3ViewObject view)
{
    TQ3BoundingBox bounds;
    TQ3DiskData diskData;
    TQ3EllipseData ellipseData;
    TQ3GeometryObject disk, ellipse;
    TQ3Point3D origin;
    TQ3Vector3D vector;

    Q3Point3D_Set(&diskData.origin, 0.0f, 0.0f, 0.0f);
    Q3Vector3D_Set(&diskData.majorRadius, 2.0f, 0.0f, 0.0f);
    Q3Vector3D_Set(&diskData.minorRadius, 0.0f, 1.0f, 0.0f);
    diskData.uMin = 0.0f;
    diskData.uMax = 1.0f;
    diskData.vMin = 0.5f; /* a washer */
    diskData.vMax = 1.0f;
    diskData.diskAttributeSet = NULL;
    disk = Q3Disk_New(&diskData);
    if (disk == NULL) {
        gFailures++;
        return;
    }
    CHECK(Q3Disk_GetOrigin(disk, &origin));
    CHECK(Q3Disk_SetOrigin(disk, &origin));
    CHECK(Q3Disk_GetMajorRadius(disk, &vector));
    CHECK(Q3Disk_SetMajorRadius(disk, &vector));
    CHECK(Q3Disk_GetMinorRadius(disk, &vector));
    CHECK(Q3Disk_SetMinorRadius(disk, &vector));
    CHECK(Q3Disk_GetData(disk, &diskData));
    CHECK(Q3Disk_SetData(disk, &diskData));
    CHECK(Q3View_StartBoundingBox(view, kQ3ComputeBoundsApproximate));
    do {
        CHECK(Q3Disk_Submit(&diskData, view));
    } while (Q3View_EndBoundingBox(view, &bounds) == kQ3ViewStatusRetraverse);
    CHECK(Q3Disk_EmptyData(&diskData));
    MyBoundAndDispose(view, disk);

    Q3Point3D_Set(&ellipseData.origin, 0.0f, 0.0f, 0.0f);
    Q3Vector3D_Set(&ellipseData.majorRadius, 2.0f, 0.0f, 0.0f);
    Q3Vector3D_Set(&ellipseData.minorRadius, 0.0f, 1.0f, 0.0f);
    ellipseData.uMin = 0.0f;
    ellipseData.uMax = 0.5f;
    ellipseData.ellipseAttributeSet = NULL;
    ellipse = Q3Ellipse_New(&ellipseData);
    if (ellipse == NULL) {
        gFailures++;
        return;
    }
    CHECK(Q3Ellipse_GetOrigin(ellipse, &origin));
    CHECK(Q3Ellipse_SetOrigin(ellipse, &origin));
    CHECK(Q3Ellipse_GetMajorRadius(ellipse, &vector));
    CHECK(Q3Ellipse_SetMajorRadius(ellipse, &vector));
    CHECK(Q3Ellipse_GetMinorRadius(ellipse, &vector));
    CHECK(Q3Ellipse_SetMinorRadius(ellipse, &vector));
    CHECK(Q3Ellipse_GetData(ellipse, &ellipseData));
    CHECK(Q3Ellipse_SetData(ellipse, &ellipseData));
    CHECK(Q3View_StartBoundingBox(view, kQ3ComputeBoundsApproximate));
    do {
        CHECK(Q3Ellipse_Submit(&ellipseData, view));
    } while (Q3View_EndBoundingBox(view, &bounds) == kQ3ViewStatusRetraverse);
    CHECK(Q3Ellipse_EmptyData(&ellipseData));
    MyBoundAndDispose(view, ellipse);
}

static void MyEllipsoidAndTorus(TQ3ViewObject view, TQ3AttributeSet red)
{
    TQ3BoundingBox bounds;
    TQ3EllipsoidData ellipsoidData;
    TQ3TorusData torusData;
    TQ3GeometryObject ellipsoid, torus;
    TQ3Point3D origin;
    TQ3Vector3D vector;
    float ratio;

    Q3Point3D_Set(&ellipsoidData.origin, 0.0f, 0.0f, 0.0f);
    Q3Vector3D_Set(&ellipsoidData.orientation, 0.0f, 1.0f, 0.0f);
    Q3Vector3D_Set(&ellipsoidData.majorRadius, 0.0f, 0.0f, 1.5f);
    Q3Vector3D_Set(&ellipsoidData.minorRadius, 1.0f, 0.0f, 0.0f);
    ellipsoidData.uMin = 0.0f;
    ellipsoidData.uMax = 1.0f;
    ellipsoidData.vMin = 0.0f;
    ellipsoidData.vMax = 0.75f;
    ellipsoidData.caps = kQ3EndCapMaskTop;
    ellipsoidData.interiorAttributeSet = red;
    ellipsoidData.ellipsoidAttributeSet = NULL;
    ellipsoid = Q3Ellipsoid_New(&ellipsoidData);
    if (ellipsoid == NULL) {
        gFailures++;
        return;
    }
    CHECK(Q3Ellipsoid_GetOrigin(ellipsoid, &origin));
    CHECK(Q3Ellipsoid_SetOrigin(ellipsoid, &origin));
    CHECK(Q3Ellipsoid_GetOrientation(ellipsoid, &vector));
    CHECK(Q3Ellipsoid_SetOrientation(ellipsoid, &vector));
    CHECK(Q3Ellipsoid_GetMajorRadius(ellipsoid, &vector));
    CHECK(Q3Ellipsoid_SetMajorRadius(ellipsoid, &vector));
    CHECK(Q3Ellipsoid_GetMinorRadius(ellipsoid, &vector));
    CHECK(Q3Ellipsoid_SetMinorRadius(ellipsoid, &vector));
    CHECK(Q3Ellipsoid_GetData(ellipsoid, &ellipsoidData));
    CHECK(Q3Ellipsoid_SetData(ellipsoid, &ellipsoidData));
    CHECK(Q3View_StartBoundingBox(view, kQ3ComputeBoundsApproximate));
    do {
        CHECK(Q3Ellipsoid_Submit(&ellipsoidData, view));
    } while (Q3View_EndBoundingBox(view, &bounds) == kQ3ViewStatusRetraverse);
    CHECK(Q3Ellipsoid_EmptyData(&ellipsoidData));
    MyBoundAndDispose(view, ellipsoid);

    Q3Point3D_Set(&torusData.origin, 0.0f, 0.0f, 0.0f);
    Q3Vector3D_Set(&torusData.orientation, 0.0f, 0.25f, 0.0f);
    Q3Vector3D_Set(&torusData.majorRadius, 0.0f, 0.0f, 1.0f);
    Q3Vector3D_Set(&torusData.minorRadius, 1.0f, 0.0f, 0.0f);
    torusData.ratio = 1.0f;
    torusData.uMin = 0.0f;
    torusData.uMax = 1.0f;
    torusData.vMin = 0.0f;
    torusData.vMax = 1.0f;
    torusData.caps = kQ3EndCapNone;
    torusData.interiorAttributeSet = NULL;
    torusData.torusAttributeSet = red;
    torus = Q3Torus_New(&torusData);
    if (torus == NULL) {
        gFailures++;
        return;
    }
    CHECK(Q3Torus_GetOrigin(torus, &origin));
    CHECK(Q3Torus_SetOrigin(torus, &origin));
    CHECK(Q3Torus_GetOrientation(torus, &vector));
    CHECK(Q3Torus_SetOrientation(torus, &vector));
    CHECK(Q3Torus_GetMajorRadius(torus, &vector));
    CHECK(Q3Torus_SetMajorRadius(torus, &vector));
    CHECK(Q3Torus_GetMinorRadius(torus, &vector));
    CHECK(Q3Torus_SetMinorRadius(torus, &vector));
    CHECK(Q3Torus_GetRatio(torus, &ratio));
    CHECK(Q3Torus_SetRatio(torus, ratio * 0.5f));
    CHECK(Q3Torus_GetData(torus, &torusData));
    CHECK(Q3Torus_SetData(torus, &torusData));
    CHECK(Q3View_StartBoundingBox(view, kQ3ComputeBoundsApproximate));
    do {
        CHECK(Q3Torus_Submit(&torusData, view));
    } while (Q3View_EndBoundingBox(view, &bounds) == kQ3ViewStatusRetraverse);
    CHECK(Q3Torus_EmptyData(&torusData));
    MyBoundAndDispose(view, torus);
}

int main(void)
{
    TQ3ViewObject view;
    TQ3AttributeSet red;
    int status;

    status = MyStartBounding(&view, &red);
    if (status != 0)
        return status;

    MyBox(view, red);
    MyCone(view, red);
    MyCylinder(view, red);
    MyDiskAndEllipse(view);
    MyEllipsoidAndTorus(view, red);

    return MyFinishBounding(view, red, "every 1.6 quadric call worked");
}
