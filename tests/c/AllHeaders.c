/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/* Proves that every public header compiles as strict C99 with warnings as
 * errors, together and in any order, and that the C ABI links and runs. */
#include "QD3D.h"
#include "QD3DAcceleration.h"
#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DErrors.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DIO.h"
#include "QD3DLight.h"
#include "QD3DMath.h"
#include "QD3DPick.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"
#include "QD3DString.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"
#include "QD3DView.h"
#include "Q3NURBCurveTools.h"
#include "Q3Exchange.h"
#include "Q3PixmapPNG.h"
#include "Q3GLDrawContext.h"
#include "QD3DController.h"
#include "QD3DCustomElements.h"
#include "QD3DExtension.h"

#include <stdio.h>
#include <string.h>

/* A few calls of QD3DStyle.h, QD3DShader.h and QD3DLight.h, with C's enums
 * and structures as legacy code writes them. */
static int styleShaderAndLightCalls(void)
{
    TQ3FogStyleData fog = {kQ3On, kQ3FogModeLinear, 1.0f, 10.0f, 0.5f, {1.0f, 0.5f, 0.5f, 0.5f}};
    TQ3SpotLightData spot = {{kQ3True, 0.75f, {1.0f, 1.0f, 1.0f}}, kQ3False, kQ3AttenuationTypeNone,
                             {0.0f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.25f, 0.5f, kQ3FallOffTypeLinear};
    TQ3FillStyle fill = kQ3FillStyleFilled;
    TQ3ShaderUVBoundary boundary = kQ3ShaderUVBoundaryWrap;
    float outer = 0.0f;
    int ok = 1;
    TQ3StyleObject fillStyle = Q3FillStyle_New(kQ3FillStyleEdges);
    TQ3StyleObject fogStyle = Q3FogStyle_New(&fog);
    TQ3ShaderObject phong = Q3PhongIllumination_New();
    TQ3LightObject light = Q3SpotLight_New(&spot);
    ok = ok && Q3FillStyle_Get(fillStyle, &fill) == kQ3Success && fill == kQ3FillStyleEdges;
    ok = ok && Q3Style_GetType(fogStyle) == kQ3StyleTypeFog;
    ok = ok && Q3Shader_SetUBoundary(phong, kQ3ShaderUVBoundaryClamp) == kQ3Success;
    ok = ok && Q3Shader_GetUBoundary(phong, &boundary) == kQ3Success && boundary == kQ3ShaderUVBoundaryClamp;
    ok = ok && Q3IlluminationShader_GetType(phong) == kQ3IlluminationTypePhong;
    ok = ok && Q3SpotLight_GetOuterAngle(light, &outer) == kQ3Success && outer == 0.5f;
    ok = ok && Q3Light_GetType(light) == kQ3LightTypeSpot;
    /* Textures: QD3D.h's TQ3Mipmap as C code fills it, a refused texture. */
    {
        TQ3Mipmap mipmap;
        TQ3ColorRGB grey;
        memset(&mipmap, 0, sizeof mipmap);
        mipmap.useMipmapping = kQ3False;
        mipmap.mipmaps[31].offset = 0;
        ok = ok && Q3MipmapTexture_New(&mipmap) == NULL && Q3Error_Get(NULL) == kQ3ErrorNULLParameter;
        ok = ok && Q3TextureShader_New(NULL) == NULL && Q3SurfaceShader_GetType(phong) == kQ3ObjectTypeInvalid;
        ok = ok && Q3ColorRGB_Lerp(Q3ColorRGB_Set(&grey, 0.0f, 0.0f, 0.0f), &grey, 0.5f, &grey) == &grey;
    }
    Q3Object_Dispose(fillStyle);
    Q3Object_Dispose(fogStyle);
    Q3Object_Dispose(phong);
    Q3Object_Dispose(light);
    return ok;
}

/* QD3DSet.h from C as legacy code writes it: a set and an attribute set,
 * the type walk, inheritance, and the surface shader passed as a handle. */
static int setCalls(void)
{
    TQ3SetObject set = Q3Set_New();
    TQ3AttributeSet parent = Q3AttributeSet_New(), child = Q3AttributeSet_New(), result = Q3AttributeSet_New();
    TQ3ShaderObject illumination = Q3PhongIllumination_New();
    TQ3SurfaceShaderObject gotShader = NULL;
    TQ3ColorRGB red = {1.0f, 0.0f, 0.0f}, blue = {0.0f, 0.0f, 1.0f}, got;
    float ambient = 0.5f;
    TQ3ElementType type = kQ3ElementTypeNone;
    TQ3AttributeType attributeType = kQ3AttributeTypeNone;
    int ok;
    ok = Q3Set_GetType(set) == kQ3SharedTypeSet && Q3Set_GetType(parent) == kQ3SetTypeAttribute &&
         Q3Set_Add(set, kQ3AttributeTypeDiffuseColor, &red) == kQ3Success &&
         Q3Set_Contains(set, kQ3AttributeTypeDiffuseColor) == kQ3True &&
         Q3Set_Get(set, kQ3AttributeTypeDiffuseColor, &got) == kQ3Success && got.r == 1.0f &&
         Q3Set_GetNextElementType(set, &type) == kQ3Success && type == kQ3AttributeTypeDiffuseColor &&
         Q3Set_GetNextElementType(set, &type) == kQ3Success && type == kQ3ElementTypeNone &&
         Q3Set_Add(set, kQ3ElementTypeUnknown, &red) == kQ3Failure &&
         Q3Error_Get(NULL) == kQ3ErrorUnknownElementType &&
         Q3Set_Clear(set, kQ3AttributeTypeDiffuseColor) == kQ3Success && Q3Set_Empty(set) == kQ3Success &&
         Q3AttributeSet_Add(parent, kQ3AttributeTypeDiffuseColor, &red) == kQ3Success &&
         Q3AttributeSet_Add(parent, kQ3AttributeTypeAmbientCoefficient, &ambient) == kQ3Success &&
         Q3AttributeSet_Add(child, kQ3AttributeTypeDiffuseColor, &blue) == kQ3Success &&
         Q3AttributeSet_Inherit(parent, child, result) == kQ3Success &&
         Q3AttributeSet_Get(result, kQ3AttributeTypeDiffuseColor, &got) == kQ3Success && got.b == 1.0f &&
         Q3AttributeSet_GetNextAttributeType(result, &attributeType) == kQ3Success &&
         attributeType == kQ3AttributeTypeAmbientCoefficient &&
         Q3AttributeSet_Add(result, kQ3AttributeTypeSurfaceShader, &illumination) == kQ3Failure &&
         Q3Error_Get(NULL) == kQ3ErrorInvalidObjectType &&
         Q3AttributeSet_Get(result, kQ3AttributeTypeSurfaceShader, &gotShader) == kQ3Failure &&
         Q3Error_Get(NULL) == kQ3ErrorAttributeNotContained && gotShader == NULL &&
         Q3Attribute_Submit(kQ3AttributeTypeDiffuseColor, &red, NULL) == kQ3Failure &&
         Q3Error_Get(NULL) == kQ3ErrorNULLParameter;
    Q3Object_Dispose(illumination);
    Q3Object_Dispose(result);
    Q3Object_Dispose(child);
    Q3Object_Dispose(parent);
    Q3Object_Dispose(set);
    return ok;
}

/* Apple's fixed-width names are their width in C too (C99 has no
 * static_assert: a negative array size stops the compile). */
typedef char checkUns8[sizeof(TQ3Uns8) == 1 && sizeof(TQ3Int8) == 1 ? 1 : -1];
typedef char checkUns16[sizeof(TQ3Uns16) == 2 && sizeof(TQ3Int16) == 2 ? 1 : -1];
typedef char checkUns32[sizeof(TQ3Uns32) == 4 && sizeof(TQ3Int32) == 4 ? 1 : -1];
typedef char checkUns64[sizeof(TQ3Uns64) == 8 && sizeof(TQ3Int64) == 8 ? 1 : -1];
typedef char checkSize[sizeof(TQ3Size) == 4 ? 1 : -1];

/* WINDOW_SYSTEM_X11 is Apple's 1, and QD3DDrawContext.h then declares
 * Apple's X11 draw context with Xlib's types. */
#if !WINDOW_SYSTEM_X11
#error "WINDOW_SYSTEM_X11 is not 1"
#endif
typedef char checkXData[sizeof(((TQ3XDrawContextData *)0)->display) == sizeof(Display *) ? 1 : -1];
#if !OS_UNIX || OS_MACINTOSH || OS_WIN32 || WINDOW_SYSTEM_MACINTOSH || WINDOW_SYSTEM_WIN32
#error "platform switches"
#endif

static int idleCount = 0;
static TQ3Status countIdle(TQ3ViewObject view, const void *idlerData)
{
    (void)view;
    (void)idlerData;
    ++idleCount;
    return kQ3Success;
}

static TQ3Status stopAtOnce(TQ3ViewObject view, const void *idlerData, unsigned long current,
                            unsigned long completed)
{
    (void)view;
    (void)idlerData;
    (void)current;
    (void)completed;
    return kQ3Failure;
}

static void endFrame(TQ3ViewObject view, void *endFrameData)
{
    (void)view;
    ++*(int *)endFrameData;
}

/* The portable calls QuickDraw 3D programs use to query the system, as C
 * code writes them: a renderer menu, RAVE constants, idle methods, a mask. */
static int portableCalls(void)
{
    TQ3SubClassData renderers;
    TQ3ObjectClassNameString name;
    TQ3ObjectType type = kQ3ObjectTypeInvalid;
    unsigned long release = 0, count = 5, n;
    int ok = 1, menuItems = 0, frames = 0;
    TQ3RendererObject renderer = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
    TQ3StorageObject storage = Q3MemoryStorage_New(NULL, 0);
    TQ3FileObject file = Q3File_New();
    TQ3ViewObject view = Q3View_New();
    TQ3Uns32 pixels[4 * 2];
    TQ3PixmapDrawContextData contextData;
    TQ3DrawContextObject context;
    TQ3CameraObject camera;
    TQ3OrthographicCameraData cameraData;
    unsigned char maskBits[2] = {0xA0, 0x50};
    TQ3Bitmap mask = {NULL, 4, 2, 1, kQ3EndianBig};
    TQ3Boolean state = kQ3False;
    TQ3PointData point = {{5.0f, 5.0f, 0.0f}, NULL}; /* outside the view: only the clear shows */
    TQ3Uns32 probe = 1;

    mask.image = maskBits;
    {
        /* The three rotation transforms, as C code fills their data. */
        TQ3Quaternion q = {1.0f, 0.0f, 0.0f, 0.0f}, gotQ;
        TQ3RotateAboutPointTransformData aboutPoint = {kQ3AxisZ, 0.5f, {1.0f, 2.0f, 3.0f}};
        TQ3RotateAboutAxisTransformData aboutAxis = {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, 0.5f};
        TQ3Matrix4x4 m1, m2;
        TQ3Point3D about;
        TQ3Vector3D orientation;
        TQ3Axis axis = kQ3AxisX;
        float angle = 0.0f;
        TQ3TransformObject tq = Q3QuaternionTransform_New(&q);
        TQ3TransformObject tp = Q3RotateAboutPointTransform_New(&aboutPoint);
        TQ3TransformObject ta = Q3RotateAboutAxisTransform_New(&aboutAxis);
        ok = ok && tq != NULL && tp != NULL && ta != NULL &&
             Q3QuaternionTransform_Set(tq, &q) == kQ3Success && Q3QuaternionTransform_Get(tq, &gotQ) == kQ3Success &&
             gotQ.w == 1.0f && Q3RotateAboutPointTransform_SetAxis(tp, kQ3AxisY) == kQ3Success &&
             Q3RotateAboutPointTransform_GetAxis(tp, &axis) == kQ3Success && axis == kQ3AxisY &&
             Q3RotateAboutPointTransform_SetAngle(tp, 0.25f) == kQ3Success &&
             Q3RotateAboutPointTransform_GetAngle(tp, &angle) == kQ3Success && angle == 0.25f &&
             Q3RotateAboutPointTransform_SetAboutPoint(tp, &aboutPoint.about) == kQ3Success &&
             Q3RotateAboutPointTransform_GetAboutPoint(tp, &about) == kQ3Success && about.z == 3.0f &&
             Q3RotateAboutPointTransform_SetData(tp, &aboutPoint) == kQ3Success &&
             Q3RotateAboutPointTransform_GetData(tp, &aboutPoint) == kQ3Success &&
             Q3RotateAboutAxisTransform_SetOrientation(ta, &aboutAxis.orientation) == kQ3Success &&
             Q3RotateAboutAxisTransform_GetOrientation(ta, &orientation) == kQ3Success && orientation.z == 1.0f &&
             Q3RotateAboutAxisTransform_SetOrigin(ta, &aboutAxis.origin) == kQ3Success &&
             Q3RotateAboutAxisTransform_GetOrigin(ta, &about) == kQ3Success &&
             Q3RotateAboutAxisTransform_SetAngle(ta, 0.5f) == kQ3Success &&
             Q3RotateAboutAxisTransform_GetAngle(ta, &angle) == kQ3Success && angle == 0.5f &&
             Q3RotateAboutAxisTransform_SetData(ta, &aboutAxis) == kQ3Success &&
             Q3RotateAboutAxisTransform_GetData(ta, &aboutAxis) == kQ3Success &&
             Q3Transform_GetMatrix(ta, &m1) == &m1 && Q3Matrix4x4_SetRotate_Z(&m2, 0.5f) == &m2 &&
             m1.value[0][1] - m2.value[0][1] < 1e-6f && m2.value[0][1] - m1.value[0][1] < 1e-6f &&
             Q3Object_IsWritable(ta, file) == kQ3True;
        if (tq != NULL)
            Q3Object_Dispose(tq);
        if (tp != NULL)
            Q3Object_Dispose(tp);
        if (ta != NULL)
            Q3Object_Dispose(ta);
        (void)Q3QuaternionTransform_Submit;
        (void)Q3RotateAboutPointTransform_Submit;
        (void)Q3RotateAboutAxisTransform_Submit;
    }
    ok = ok && Q3GetReleaseVersion(&release) == kQ3Success && release == 0x01608000ul;
    ok = ok && Q3ObjectHierarchy_GetSubClassData(kQ3SharedTypeRenderer, &renderers) == kQ3Success;
    for (n = 0; ok && n < renderers.numClasses; n++) {
        if (renderers.classTypes[n] == kQ3RendererTypeGeneric)
            continue;
        if (Q3RendererClass_GetNickNameString(renderers.classTypes[n], name) == kQ3Failure || name[0] == 0)
            ok = ok && Q3ObjectHierarchy_GetStringFromType(renderers.classTypes[n], name) == kQ3Success;
        ++menuItems;
    }
    ok = ok && Q3ObjectHierarchy_EmptySubClassData(&renderers) == kQ3Success && menuItems == 2;
    ok = ok && Q3ObjectHierarchy_GetStringFromType(kQ3GeometryTypeBox, name) == kQ3Success &&
         strcmp(name, "Box") == 0 && Q3ObjectHierarchy_GetTypeFromString(name, &type) == kQ3Success &&
         type == kQ3GeometryTypeBox && Q3ObjectHierarchy_IsTypeRegistered(kQ3GeometryTypeTriMesh) == kQ3True &&
         Q3ObjectHierarchy_IsNameRegistered("TriMesh") == kQ3True;
    ok = ok && Q3Renderer_IsInteractive(renderer) == kQ3True &&
         Q3InteractiveRenderer_SetPreferences(renderer, kQAVendor_Apple, kQAEngine_AppleSW) == kQ3Success &&
         Q3InteractiveRenderer_CountRAVEDrawContexts(renderer, &count) == kQ3Success && count == 0 &&
         Q3InteractiveRenderer_GetRAVEDrawContexts(renderer, NULL, NULL, &count, NULL) == kQ3Success &&
         kQAVendor_BestChoice == -1 && kQAEngine_AppleHW == -1;
    ok = ok && Q3MemoryStorage_GetType(storage) == kQ3ObjectTypeInvalid &&
         Q3Object_IsWritable(renderer, file) == kQ3False && Q3Shared_GetEditTrackingState(storage) == kQ3False &&
         Q3Shared_Edited(storage) == kQ3Success && Q3Shared_GetEditTrackingState(storage) == kQ3True &&
         Q3Shared_ClearEditTracking(storage) == kQ3Success && Q3Shared_GetEditTrackingState(storage) == kQ3False;

    /* A 4 x 2 image in a TQ3Uns32 array, drawn through a mask of every other
     * pixel; an idle method that cancels, then one that lets it finish. */
    memset(pixels, 0, sizeof pixels);
    memset(&contextData, 0, sizeof contextData);
    contextData.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
    contextData.drawContextData.clearImageColor.a = 1.0f;
    contextData.drawContextData.clearImageColor.r = 1.0f;
    contextData.pixmap.image = pixels;
    contextData.pixmap.width = 4;
    contextData.pixmap.height = 2;
    contextData.pixmap.rowBytes = 4 * sizeof(TQ3Uns32);
    contextData.pixmap.pixelSize = 32;
    contextData.pixmap.pixelType = kQ3PixelTypeARGB32;
    contextData.pixmap.bitOrder = kQ3EndianBig;
    contextData.pixmap.byteOrder = *(unsigned char *)&probe == 1 ? kQ3EndianLittle : kQ3EndianBig;
    context = Q3PixmapDrawContext_New(&contextData);
    memset(&cameraData, 0, sizeof cameraData);
    cameraData.cameraData.placement.cameraLocation.z = 10.0f;
    cameraData.cameraData.placement.upVector.y = 1.0f;
    cameraData.cameraData.range.hither = 1.0f;
    cameraData.cameraData.range.yon = 100.0f;
    cameraData.cameraData.viewPort.origin.x = -1.0f;
    cameraData.cameraData.viewPort.origin.y = 1.0f;
    cameraData.cameraData.viewPort.width = 2.0f;
    cameraData.cameraData.viewPort.height = 2.0f;
    cameraData.left = -1.0f;
    cameraData.right = 1.0f;
    cameraData.top = 1.0f;
    cameraData.bottom = -1.0f;
    camera = Q3OrthographicCamera_New(&cameraData);
    ok = ok && context != NULL && camera != NULL && Q3DrawContext_SetMask(context, &mask) == kQ3Success &&
         Q3DrawContext_SetMaskState(context, kQ3True) == kQ3Success &&
         Q3DrawContext_GetMaskState(context, &state) == kQ3Success && state == kQ3True &&
         Q3DrawContext_SetDoubleBufferState(context, kQ3True) == kQ3Success &&
         Q3DrawContext_GetDoubleBufferState(context, &state) == kQ3Success && state == kQ3True &&
         Q3View_SetDrawContext(view, context) == kQ3Success && Q3View_SetCamera(view, camera) == kQ3Success &&
         Q3View_SetRenderer(view, renderer) == kQ3Success;
    ok = ok && Q3View_SetIdleProgressMethod(view, stopAtOnce, NULL) == kQ3Success &&
         Q3View_SetEndFrameMethod(view, endFrame, &frames) == kQ3Success &&
         Q3View_StartRendering(view) == kQ3Success && Q3Point_Submit(&point, view) == kQ3Success &&
         Q3View_EndRendering(view) == kQ3ViewStatusCancelled && frames == 0;
    ok = ok && Q3View_SetIdleProgressMethod(view, NULL, NULL) == kQ3Success &&
         Q3View_SetIdleMethod(view, countIdle, NULL) == kQ3Success && Q3View_StartRendering(view) == kQ3Success &&
         Q3Point_Submit(&point, view) == kQ3Success && Q3View_EndRendering(view) == kQ3ViewStatusDone &&
         idleCount == 1 && frames == 1;
    /* The mask 1010 / 0101: only those pixels took the red clear colour. */
    ok = ok && pixels[0] == 0xFFFF0000u && pixels[1] == 0 && pixels[2] == 0xFFFF0000u && pixels[3] == 0 &&
         pixels[4] == 0 && pixels[5] == 0xFFFF0000u && pixels[6] == 0 && pixels[7] == 0xFFFF0000u;
    Q3Object_Dispose(view);
    if (context != NULL)
        Q3Object_Dispose(context);
    if (camera != NULL)
        Q3Object_Dispose(camera);
    Q3Object_Dispose(renderer);
    Q3Object_Dispose(storage);
    Q3Object_Dispose(file);
    return ok;
}

int main(void)
{
    TQ3NURBCurveData data;
    TQ3SubdivisionStyleData style;
    TQ3GeometryObject curve = NULL;
    unsigned long major = 0, minor = 0;
    TQ3Quaternion quarterTurn;
    TQ3Matrix4x4 matrix;
    TQ3Vector3D up;
    TQ3Point3D corners[2];
    TQ3BoundingBox box;

    data.curveAttributeSet = NULL;
    style.method = kQ3SubdivisionMethodConstant;
    style.c1 = style.c2 = 5.0f;
    (void)style;
    (void)curve;
    if (Q3Initialize() != kQ3Success)
        return 1;
    if (Q3GetVersion(&major, &minor) != kQ3Success || major != 1 || minor != 6)
        return 2;
    if (Q3NURBCurve_New(NULL) != NULL || Q3Error_Get(NULL) != kQ3ErrorNULLParameter)
        return 3;
    /* QD3DMath.h: macros and calls, as legacy code uses them. */
    if (Q3Quaternion_SetRotate_X(&quarterTurn, Q3Math_DegreesToRadians(90.0f)) != &quarterTurn ||
        Q3Matrix4x4_SetQuaternion(&matrix, &quarterTurn) != &matrix)
        return 4;
    Q3Vector3D_Set(&up, 0.0f, 1.0f, 0.0f);
    if (Q3Vector3D_Transform(&up, &matrix, &up) != &up || !(up.z > 1.0f - 1e-6f && up.z < 1.0f + 1e-6f))
        return 5;
    Q3Point3D_Set(&corners[0], -1.0f, 2.0f, kQ3RealZero);
    Q3Point3D_Set(&corners[1], Q3Math_Max(3.0f, kQ3Pi), Q3Math_Min(-2.0f, 0.0f), kQ3PiOver2);
    if (Q3BoundingBox_SetFromPoints3D(&box, corners, 2, sizeof(TQ3Point3D)) != &box || box.isEmpty != kQ3False ||
        box.max.x != kQ3Pi || box.min.y != -2.0f || box.max.z != kQ3PiOver2)
        return 6;
    if (Q3Math_RadiansToDegrees(kQ32Pi) < 359.9f || kQ33PiOver2 <= kQ3Pi || kQ3MaxFloat <= 1e38f)
        return 7;
    if (Q3Point3D_To3DTransformArray(corners, &matrix, corners, -1, sizeof(TQ3Point3D), sizeof(TQ3Point3D)) !=
            kQ3Failure ||
        Q3Error_Get(NULL) != kQ3ErrorParameterOutOfRange)
        return 8;
    {
        TQ3GroupObject group = Q3DisplayGroup_New();
        TQ3StateOperatorObject push = Q3Push_New();
        TQ3GroupPosition position = NULL;
        unsigned long count = 0;
        if (group == NULL || push == NULL || Q3Group_AddObject(group, push) == NULL)
            return 9;
        if (Q3Group_CountObjects(group, &count) != kQ3Success || count != 1 ||
            Q3Group_GetFirstPosition(group, &position) != kQ3Success || position == NULL)
            return 10;
        Q3Object_Dispose(push);
        Q3Object_Dispose(group);
    }
    if (!styleShaderAndLightCalls())
        return 11;
    if (!setCalls())
        return 22;
    {
        /* A curve tool from C: Listing 1's cubic, evaluated at its middle. */
        static TQ3RationalPoint4D points[4] = {{0, 0, 0, 1}, {1, 1, 0, 1}, {2, 0, 0, 1}, {3, 1, 0, 1}};
        static float knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
        TQ3NURBCurveData listing1;
        TQ3Point3D middle;
        TQ3NURBCurveParameterization how = kQ3NURBCurveParameterizationCentripetal;
        listing1.order = 4;
        listing1.numPoints = 4;
        listing1.controlPoints = points;
        listing1.knots = knots;
        listing1.curveAttributeSet = NULL;
        (void)how;
        if (Q3NURBCurveData_Evaluate(&listing1, 0.5f, &middle) != kQ3Success || middle.x != 1.5f)
            return 12;
    }
    {
        /* The quadrics and solids' data structures and calls, from C. */
        TQ3BoxData box;
        TQ3ConeData cone;
        TQ3CylinderData cylinder;
        TQ3DiskData disk;
        TQ3EllipseData ellipse;
        TQ3EllipsoidData ellipsoid;
        TQ3TorusData torus;
        memset(&box, 0, sizeof box);
        memset(&cone, 0, sizeof cone);
        memset(&cylinder, 0, sizeof cylinder);
        memset(&disk, 0, sizeof disk);
        memset(&ellipse, 0, sizeof ellipse);
        memset(&ellipsoid, 0, sizeof ellipsoid);
        memset(&torus, 0, sizeof torus);
        /* All zeros: vectors that span nothing and empty ranges, which
           QuickDraw 3D keeps (drawing nothing); Q3 keeps them with
           kQ3WarningInconsistentData (docs/3dmf.md, Tolerances). */
        TQ3GeometryObject made[7];
        int k;
        made[0] = Q3Box_New(&box);
        if (Q3Warning_Get(NULL) != kQ3WarningInconsistentData)
            return 13;
        made[1] = Q3Cone_New(&cone);
        made[2] = Q3Cylinder_New(&cylinder);
        made[3] = Q3Disk_New(&disk);
        made[4] = Q3Ellipse_New(&ellipse);
        made[5] = Q3Ellipsoid_New(&ellipsoid);
        made[6] = Q3Torus_New(&torus);
        if (Q3Warning_Get(NULL) != kQ3WarningInconsistentData)
            return 13;
        for (k = 0; k < 7; ++k) {
            if (made[k] == NULL)
                return 13;
            Q3Object_Dispose(made[k]);
        }
        if (Q3Torus_SetRatio(NULL, 1.0f) != kQ3Failure || Q3Box_GetFaceAttributeSet(NULL, 0, NULL) != kQ3Failure ||
            kQ3SubdivisionMaxTrianglesPerSurface < 1)
            return 13;
    }
    {
        /* A mesh from C: a triangle, walked with Apple's macros. */
        TQ3GeometryObject mesh = Q3Mesh_New();
        TQ3Vertex3D corner = {{0, 0, 0}, NULL};
        TQ3MeshVertex vertices[3];
        TQ3MeshVertex vertex;
        TQ3MeshIterator iterator;
        unsigned long numVertices = 0, walked = 0;
        int i;
        if (mesh == NULL)
            return 14;
        for (i = 0; i < 3; i++) {
            corner.point.x = (float)(i == 1);
            corner.point.y = (float)(i == 2);
            vertices[i] = Q3Mesh_VertexNew(mesh, &corner);
        }
        if (Q3Mesh_FaceNew(mesh, 3, vertices, NULL) == NULL ||
            Q3Mesh_GetNumVertices(mesh, &numVertices) != kQ3Success || numVertices != 3)
            return 14;
        Q3ForEachMeshVertex(mesh, vertex, &iterator) walked++;
        if (walked != 3)
            return 14;
        Q3Object_Dispose(mesh);
    }
    {
        /* The NURB patch's data structures and calls, from C: a bilinear
         * patch with one trim loop, made, read and edited. */
        static TQ3RationalPoint4D points[4] = {{0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1}, {1, 1, 0, 1}};
        static float knots[4] = {0, 0, 1, 1};
        static TQ3RationalPoint3D square[5] = {{0.25f, 0.25f, 1}, {0.75f, 0.25f, 1}, {0.75f, 0.75f, 1},
                                               {0.25f, 0.75f, 1}, {0.25f, 0.25f, 1}};
        static float squareKnots[7] = {0, 0, 1, 2, 3, 4, 4};
        TQ3NURBPatchTrimCurveData curve;
        TQ3NURBPatchTrimLoopData loop;
        TQ3NURBPatchData patchData, copy;
        TQ3GeometryObject patch;
        TQ3RationalPoint4D point;
        float knot = 0.0f;
        int patchOk;
        curve.order = 2;
        curve.numPoints = 5;
        curve.controlPoints = square;
        curve.knots = squareKnots;
        loop.numTrimCurves = 1;
        loop.trimCurves = &curve;
        patchData.uOrder = 2;
        patchData.vOrder = 2;
        patchData.numRows = 2;
        patchData.numColumns = 2;
        patchData.controlPoints = points;
        patchData.uKnots = knots;
        patchData.vKnots = knots;
        patchData.numTrimLoops = 1;
        patchData.trimLoops = &loop;
        patchData.patchAttributeSet = NULL;
        patch = Q3NURBPatch_New(&patchData);
        patchOk = patch != NULL && Q3NURBPatch_GetControlPoint(patch, 1, 0, &point) == kQ3Success &&
                  point.y == 1.0f && Q3NURBPatch_SetControlPoint(patch, 1, 0, &point) == kQ3Success &&
                  Q3NURBPatch_SetUKnot(patch, 0, -1.0f) == kQ3Success &&
                  Q3NURBPatch_GetUKnot(patch, 0, &knot) == kQ3Success && knot == -1.0f &&
                  Q3NURBPatch_SetVKnot(patch, 3, 2.0f) == kQ3Success &&
                  Q3NURBPatch_GetVKnot(patch, 3, &knot) == kQ3Success && knot == 2.0f &&
                  Q3NURBPatch_GetData(patch, &copy) == kQ3Success && copy.numTrimLoops == 1 &&
                  Q3NURBPatch_EmptyData(&copy) == kQ3Success &&
                  Q3NURBPatch_SetData(patch, &patchData) == kQ3Success &&
                  Q3NURBPatch_Submit(&patchData, NULL) == kQ3Failure && kQ3NURBPatchMaxOrder == 11 &&
                  kQ3SubdivisionMaxTrianglesPerPatch > 0;
        if (patch != NULL)
            Q3Object_Dispose(patch);
        if (!patchOk)
            return 15;
    }
    {
        /* A point written to a text 3DMF file in memory and read back, from C. */
        TQ3PointData pointData = {{1.0f, 2.0f, 3.0f}, NULL};
        TQ3GeometryObject point = Q3Point_New(&pointData);
        TQ3StorageObject storage = Q3MemoryStorage_New(NULL, 0);
        TQ3FileObject file = Q3File_New();
        TQ3ViewObject writer = Q3View_New();
        TQ3FileMode mode = kQ3FileModeNormal;
        TQ3Object back = NULL;
        TQ3PointData backData;
        int ok = point != NULL && Q3File_SetStorage(file, storage) == kQ3Success &&
                 Q3File_OpenWrite(file, kQ3FileModeText) == kQ3Success &&
                 Q3View_StartWriting(writer, file) == kQ3Success && Q3Object_Submit(point, writer) == kQ3Success &&
                 Q3View_EndWriting(writer) == kQ3ViewStatusDone && Q3File_Close(file) == kQ3Success &&
                 Q3File_OpenRead(file, &mode) == kQ3Success && (mode & kQ3FileModeText) != 0 &&
                 Q3File_SetReadInGroup(file, kQ3FileReadObjectsInGroup) == kQ3Success &&
                 Q3File_GetNextObjectType(file) == kQ3GeometryTypePoint;
        if (ok) {
            back = Q3File_ReadObject(file);
            ok = back != NULL && Q3Point_GetData(back, &backData) == kQ3Success && backData.point.z == 3.0f &&
                 Q3File_IsEndOfFile(file) == kQ3True && Q3File_Close(file) == kQ3Success;
        }
        if (back != NULL)
            Q3Object_Dispose(back);
        Q3Object_Dispose(writer);
        Q3Object_Dispose(file);
        Q3Object_Dispose(storage);
        Q3Object_Dispose(point);
        if (!ok)
            return 16;
    }
    {
        /* General polygons, polyhedra, triangle grids and markers from C. */
        TQ3GeneralPolygonData general;
        TQ3GeneralPolygonContourData contour;
        TQ3PolyhedronData polyhedron;
        TQ3PolyhedronTriangleData triangle;
        TQ3PolyhedronEdgeData edge;
        TQ3TriGridData grid;
        TQ3MarkerData marker;
        TQ3GeneralPolygonShapeHint hint = kQ3GeneralPolygonShapeHintConvex;
        TQ3PolyhedronEdge flag = kQ3PolyhedronEdgeAll;
        memset(&general, 0, sizeof general);
        memset(&contour, 0, sizeof contour);
        memset(&polyhedron, 0, sizeof polyhedron);
        memset(&triangle, 0, sizeof triangle);
        memset(&edge, 0, sizeof edge);
        memset(&grid, 0, sizeof grid);
        memset(&marker, 0, sizeof marker);
        general.contours = &contour;
        if (Q3GeneralPolygon_New(&general) != NULL ||
            Q3Error_Get(NULL) != kQ3ErrorGeometryInsufficientNumberOfPoints ||
            Q3GeneralPolygon_GetShapeHint(NULL, &hint) != kQ3Failure || Q3Polyhedron_New(&polyhedron) != NULL ||
            Q3Polyhedron_GetEdgeData(NULL, 0, &edge) != kQ3Failure ||
            Q3Polyhedron_SetTriangleData(NULL, 0, &triangle) != kQ3Failure || Q3TriGrid_New(&grid) != NULL ||
            Q3TriGrid_GetFacetAttributeSet(NULL, 0, NULL) != kQ3Failure || Q3Marker_New(&marker) != NULL ||
            Q3Marker_SetXOffset(NULL, 1) != kQ3Failure || Q3Bitmap_GetImageSize(9, 2) != 4 ||
            Q3Bitmap_Empty(&marker.bitmap) != kQ3Success || flag != 7)
            return 17;
    }
    {
        /* An object written by hand with the primitive calls, read back from C. */
        TQ3StorageObject storage = Q3MemoryStorage_New(NULL, 0);
        TQ3FileObject file = Q3File_New();
        TQ3FileIdleMethod idle = NULL;
        TQ3Uns32 value = 0;
        TQ3Float32 number = 0.0f;
        TQ3FileMode mode = kQ3FileModeNormal;
        int ok = Q3File_SetStorage(file, storage) == kQ3Success &&
                 Q3File_SetIdleMethod(file, idle, NULL) == kQ3Success &&
                 Q3File_OpenWrite(file, kQ3FileModeNormal) == kQ3Success &&
                 Q3Uns32_Write(Q3_OBJECT_TYPE('h', 'a', 'n', 'd'), file) == kQ3Success &&
                 Q3Uns32_Write(8, file) == kQ3Success && Q3Uns32_Write(42, file) == kQ3Success &&
                 Q3Float32_Write(0.5f, file) == kQ3Success && Q3File_Close(file) == kQ3Success &&
                 Q3File_OpenRead(file, &mode) == kQ3Success && Q3File_IsEndOfData(file) == kQ3False &&
                 Q3Uns32_Read(&value, file) == kQ3Success && Q3Float32_Read(&number, file) == kQ3Success &&
                 value == 42 && number == 0.5f && Q3File_IsEndOfData(file) == kQ3True &&
                 Q3File_IsEndOfContainer(file, NULL) == kQ3True && Q3Size_Pad(5) == 8 &&
                 Q3File_Close(file) == kQ3Success;
        Q3Object_Dispose(file);
        Q3Object_Dispose(storage);
        if (!ok)
            return 19;
    }
    {
        /* Pixmap markers from C: the pixmap lives in a storage object; an
         * out-of-range pixel type (an int, as C allows) is refused. */
        static const unsigned char pixels[8] = {0xFF, 0, 0, 0xFF, 0xFF, 0, 0xFF, 0};
        TQ3PixmapMarkerData data;
        TQ3StoragePixmap pixmap;
        TQ3GeometryObject marker;
        long offset = 0;
        int ok;
        memset(&data, 0, sizeof data);
        data.pixmap.image = Q3MemoryStorage_New(pixels, sizeof pixels);
        data.pixmap.width = 2;
        data.pixmap.height = 1;
        data.pixmap.rowBytes = 8;
        data.pixmap.pixelSize = 32;
        data.pixmap.pixelType = kQ3PixelTypeARGB32;
        data.pixmap.bitOrder = kQ3EndianBig;
        data.pixmap.byteOrder = kQ3EndianBig;
        data.xOffset = -1;
        marker = Q3PixmapMarker_New(&data);
        ok = marker != NULL && Q3Geometry_GetType(marker) == kQ3GeometryTypePixmapMarker &&
             Q3PixmapMarker_SetYOffset(marker, 3) == kQ3Success &&
             Q3PixmapMarker_GetYOffset(marker, &offset) == kQ3Success && offset == 3 &&
             Q3PixmapMarker_GetPixmap(marker, &pixmap) == kQ3Success && pixmap.image == data.pixmap.image &&
             pixmap.rowBytes == 8;
        if (ok)
            Q3Object_Dispose(pixmap.image);
        pixmap = data.pixmap;
        pixmap.pixelType = 6;
        ok = ok && Q3PixmapMarker_SetPixmap(marker, &pixmap) == kQ3Failure &&
             Q3Error_Get(NULL) == kQ3ErrorInvalidData;
        if (marker != NULL)
            Q3Object_Dispose(marker);
        Q3Object_Dispose(data.pixmap.image);
        if (!ok)
            return 18;
    }
    {
        /* C strings, and a file without external references: NULL, no error;
         * a closed file: NULL with kQ3ErrorFileNotOpen. */
        TQ3StringObject string = Q3CString_New("path.3dmf");
        TQ3FileObject file = Q3File_New();
        unsigned long length = 0;
        char *text = NULL;
        int ok = string != NULL && Q3String_GetType(string) == kQ3StringTypeCString &&
                 Q3CString_GetLength(string, &length) == kQ3Success && length == 9 &&
                 Q3CString_SetString(string, "a") == kQ3Success &&
                 Q3CString_GetString(string, &text) == kQ3Success && text != NULL && strcmp(text, "a") == 0 &&
                 Q3CString_EmptyData(&text) == kQ3Success && text == NULL &&
                 Q3File_GetExternalReferences(file) == NULL && Q3Error_Get(NULL) == kQ3ErrorFileNotOpen &&
                 Q3File_MarkAsExternalReference(file, string) == kQ3Failure &&
                 Q3Error_Get(NULL) == kQ3ErrorFileNotOpen;
        Q3Object_Dispose(file);
        if (string != NULL)
            Q3Object_Dispose(string);
        if (!ok)
            return 20;
    }
    {
        /* QD3DIO.h's view hints from C: every call, Apple's unsigned long
         * dimensions, the clear method passed as legacy code passes ints. */
        TQ3ViewObject view = Q3View_New();
        TQ3ViewHintsObject hints = view != NULL ? Q3ViewHints_New(view) : NULL;
        TQ3RendererObject renderer = Q3Renderer_NewFromType(kQ3RendererTypeWireFrame);
        TQ3RendererObject gotRenderer = NULL;
        TQ3CameraObject camera = NULL;
        TQ3GroupObject lights = Q3LightGroup_New(), gotLights = NULL;
        TQ3AttributeSet set = Q3AttributeSet_New(), gotSet = NULL;
        TQ3Boolean state = kQ3False;
        unsigned long w = 0, h = 0;
        unsigned char bits[2] = {0xF0, 0x0F};
        TQ3Bitmap mask, gotMask;
        TQ3DrawContextClearImageMethod method = kQ3ClearMethodNone;
        TQ3ColorARGB color = {1.0f, 0.25f, 0.5f, 0.75f}, gotColor;
        int ok;
        mask.image = bits;
        mask.width = 8;
        mask.height = 2;
        mask.rowBytes = 1;
        mask.bitOrder = kQ3EndianBig;
        ok = hints != NULL && Q3Object_IsType(hints, kQ3SharedTypeViewHints) == kQ3True &&
             Q3ViewHints_SetRenderer(hints, renderer) == kQ3Success &&
             Q3ViewHints_GetRenderer(hints, &gotRenderer) == kQ3Success && gotRenderer == renderer &&
             Q3ViewHints_GetCamera(hints, &camera) == kQ3Success && camera == NULL &&
             Q3ViewHints_SetCamera(hints, NULL) == kQ3Failure && Q3Error_Get(NULL) == kQ3ErrorNULLParameter &&
             Q3ViewHints_SetLightGroup(hints, lights) == kQ3Success &&
             Q3ViewHints_GetLightGroup(hints, &gotLights) == kQ3Success && gotLights == lights &&
             Q3ViewHints_SetAttributeSet(hints, set) == kQ3Success &&
             Q3ViewHints_GetAttributeSet(hints, &gotSet) == kQ3Success && gotSet == set &&
             Q3ViewHints_SetDimensionsState(hints, kQ3True) == kQ3Success &&
             Q3ViewHints_GetDimensionsState(hints, &state) == kQ3Success && state == kQ3True &&
             Q3ViewHints_SetDimensions(hints, 640, 480) == kQ3Success &&
             Q3ViewHints_GetDimensions(hints, &w, &h) == kQ3Success && w == 640 && h == 480 &&
             Q3ViewHints_SetMaskState(hints, kQ3True) == kQ3Success &&
             Q3ViewHints_GetMaskState(hints, &state) == kQ3Success && state == kQ3True &&
             Q3ViewHints_SetMask(hints, &mask) == kQ3Success && Q3ViewHints_GetMask(hints, &gotMask) == kQ3Success &&
             gotMask.image != mask.image && gotMask.image[1] == 0x0F && Q3Bitmap_Empty(&gotMask) == kQ3Success &&
             Q3ViewHints_SetClearImageMethod(hints, (TQ3DrawContextClearImageMethod)7) == kQ3Failure &&
             Q3Error_Get(NULL) == kQ3ErrorInvalidParameter &&
             Q3ViewHints_SetClearImageMethod(hints, kQ3ClearMethodWithColor) == kQ3Success &&
             Q3ViewHints_GetClearImageMethod(hints, &method) == kQ3Success && method == kQ3ClearMethodWithColor &&
             Q3ViewHints_SetClearImageColor(hints, &color) == kQ3Success &&
             Q3ViewHints_GetClearImageColor(hints, &gotColor) == kQ3Success && gotColor.g == 0.5f;
        if (gotRenderer != NULL)
            Q3Object_Dispose(gotRenderer);
        if (gotLights != NULL)
            Q3Object_Dispose(gotLights);
        if (gotSet != NULL)
            Q3Object_Dispose(gotSet);
        if (hints != NULL)
            Q3Object_Dispose(hints);
        if (view != NULL)
            Q3Object_Dispose(view);
        Q3Object_Dispose(renderer);
        Q3Object_Dispose(lights);
        Q3Object_Dispose(set);
        if (!ok)
            return 21;
    }
    if (!portableCalls())
        return 22;
    Q3Exit();
    printf("C99 headers OK (%lu.%lu), data.curveAttributeSet=%p\n", major, minor,
           (void *)data.curveAttributeSet);
    return 0;
}
