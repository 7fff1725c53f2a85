/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * golden_pictures curves|trimesh OUT.png: draws one of two pictures with
 * QuickDraw 3D calls, in the style of a 1990s program, and saves it with
 * Q3PixmapDrawContext_WritePNG (Q3PixmapPNG.h), for the golden-image tests of
 * this folder's CMakeLists.txt.
 *   curves   the develop article's curves: Listing 1's cubic Bezier span and
 *            a circle as a rational quadratic NURB curve (nine points,
 *            corner weights sqrt(2)/2), drawn in colour on dark blue.
 *   trimesh  a square pyramid as one TriMesh, orange, Lambert-shaded under an
 *            ambient light and a directional light, seen from above and to
 *            the right.
 * Exit status 0 when the picture was written; otherwise 1, with the Q3 error
 * on standard error.
 */
#include <QD3D.h>
#include <QD3DCamera.h>
#include <QD3DDrawContext.h>
#include <QD3DErrors.h>
#include <QD3DGeometry.h>
#include <QD3DGroup.h>
#include <QD3DLight.h>
#include <QD3DMath.h>
#include <QD3DRenderer.h>
#include <QD3DSet.h>
#include <QD3DShader.h>
#include <QD3DView.h>
#include <Q3PixmapPNG.h>

#include <stdio.h>
#include <string.h>

#define kWidth 240
#define kHeight 180

static unsigned long gImage[kWidth * kHeight];

static void MyErrorHandler(TQ3Error firstError, TQ3Error lastError, long reference)
{
    (void)firstError;
    (void)reference;
    fprintf(stderr, "golden_pictures: Q3 error %d: %s\n", (int)lastError, Q3Error_GetMessage());
}

static TQ3DrawContextObject MyNewDrawContext(float red, float green, float blue)
{
    TQ3PixmapDrawContextData contextData;

    memset(&contextData, 0, sizeof contextData);
    contextData.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
    contextData.drawContextData.clearImageColor.a = 1.0f;
    contextData.drawContextData.clearImageColor.r = red;
    contextData.drawContextData.clearImageColor.g = green;
    contextData.drawContextData.clearImageColor.b = blue;
    contextData.drawContextData.paneState = kQ3False;
    contextData.drawContextData.maskState = kQ3False;
    contextData.drawContextData.doubleBufferState = kQ3False;
    contextData.pixmap.image = gImage;
    contextData.pixmap.width = kWidth;
    contextData.pixmap.height = kHeight;
    contextData.pixmap.rowBytes = kWidth * 4;
    contextData.pixmap.pixelSize = 32;
    contextData.pixmap.pixelType = kQ3PixelTypeARGB32;
    contextData.pixmap.bitOrder = kQ3EndianBig;
    contextData.pixmap.byteOrder = kQ3EndianBig;
    return Q3PixmapDrawContext_New(&contextData);
}

static void MySetPlacement(TQ3CameraData *cameraData, float x, float y, float z)
{
    cameraData->placement.cameraLocation.x = x;
    cameraData->placement.cameraLocation.y = y;
    cameraData->placement.cameraLocation.z = z;
    cameraData->placement.pointOfInterest.x = 0.0f;
    cameraData->placement.pointOfInterest.y = 0.0f;
    cameraData->placement.pointOfInterest.z = 0.0f;
    cameraData->placement.upVector.x = 0.0f;
    cameraData->placement.upVector.y = 1.0f;
    cameraData->placement.upVector.z = 0.0f;
    cameraData->range.hither = 0.5f;
    cameraData->range.yon = 50.0f;
    cameraData->viewPort.origin.x = -1.0f;
    cameraData->viewPort.origin.y = 1.0f;
    cameraData->viewPort.width = 2.0f;
    cameraData->viewPort.height = 2.0f;
}

static TQ3AttributeSet MyNewColor(float red, float green, float blue)
{
    TQ3AttributeSet attributes = Q3AttributeSet_New();
    TQ3ColorRGB color;

    color.r = red;
    color.g = green;
    color.b = blue;
    if (attributes != NULL)
        Q3AttributeSet_Add(attributes, kQ3AttributeTypeDiffuseColor, &color);
    return attributes;
}

/* ---- The article's curves ------------------------------------------------ */

static TQ3Status MySubmitCurves(TQ3ViewObject view, TQ3AttributeSet bezierColor, TQ3AttributeSet circleColor)
{
    static TQ3RationalPoint4D listing1Points[4] = {
        {-1.5f, -1.0f, 0, 1}, {-0.5f, 1.0f, 0, 1}, {0.5f, -1.0f, 0, 1}, {1.5f, 1.0f, 0, 1}};
    static float listing1Knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    /* A unit circle: the corners carry the weight sqrt(2)/2, and the
     * homogeneous points are the corners times their weight. */
    static TQ3RationalPoint4D circlePoints[9] = {
        {1, 0, 0, 1},           {0.70710678f, 0.70710678f, 0, 0.70710678f},
        {0, 1, 0, 1},           {-0.70710678f, 0.70710678f, 0, 0.70710678f},
        {-1, 0, 0, 1},          {-0.70710678f, -0.70710678f, 0, 0.70710678f},
        {0, -1, 0, 1},          {0.70710678f, -0.70710678f, 0, 0.70710678f},
        {1, 0, 0, 1}};
    static float circleKnots[12] = {0, 0, 0, 0.25f, 0.25f, 0.5f, 0.5f, 0.75f, 0.75f, 1, 1, 1};
    TQ3NURBCurveData curve;

    curve.order = 4;
    curve.numPoints = 4;
    curve.controlPoints = listing1Points;
    curve.knots = listing1Knots;
    curve.curveAttributeSet = bezierColor;
    if (Q3NURBCurve_Submit(&curve, view) != kQ3Success)
        return kQ3Failure;
    curve.order = 3;
    curve.numPoints = 9;
    curve.controlPoints = circlePoints;
    curve.knots = circleKnots;
    curve.curveAttributeSet = circleColor;
    return Q3NURBCurve_Submit(&curve, view);
}

static int MyDrawCurves(TQ3ViewObject view)
{
    TQ3OrthographicCameraData cameraData;
    TQ3CameraObject camera;
    TQ3AttributeSet yellow = MyNewColor(1.0f, 0.85f, 0.2f);
    TQ3AttributeSet cyan = MyNewColor(0.3f, 0.9f, 1.0f);
    TQ3ViewStatus status = kQ3ViewStatusError;

    memset(&cameraData, 0, sizeof cameraData);
    MySetPlacement(&cameraData.cameraData, 0.0f, 0.0f, 10.0f);
    cameraData.left = -2.0f;
    cameraData.top = 1.5f;
    cameraData.right = 2.0f;
    cameraData.bottom = -1.5f;
    camera = Q3OrthographicCamera_New(&cameraData);
    if (camera != NULL && yellow != NULL && cyan != NULL && Q3View_SetCamera(view, camera) == kQ3Success &&
        Q3View_StartRendering(view) == kQ3Success) {
        do {
            if (MySubmitCurves(view, yellow, cyan) != kQ3Success) {
                Q3View_Cancel(view);
                break;
            }
            status = Q3View_EndRendering(view);
        } while (status == kQ3ViewStatusRetraverse);
    }
    if (camera != NULL)
        Q3Object_Dispose(camera);
    if (yellow != NULL)
        Q3Object_Dispose(yellow);
    if (cyan != NULL)
        Q3Object_Dispose(cyan);
    return status == kQ3ViewStatusDone;
}

/* ---- A lit TriMesh ------------------------------------------------------- */

static TQ3GroupObject MyNewLights(void)
{
    TQ3GroupObject lights = Q3LightGroup_New();
    TQ3LightData ambientData;
    TQ3DirectionalLightData directionalData;
    TQ3LightObject light;

    if (lights == NULL)
        return NULL;
    ambientData.isOn = kQ3True;
    ambientData.brightness = 0.3f;
    ambientData.color.r = ambientData.color.g = ambientData.color.b = 1.0f;
    light = Q3AmbientLight_New(&ambientData);
    if (light != NULL) {
        Q3Group_AddObject(lights, light);
        Q3Object_Dispose(light);
    }
    directionalData.lightData = ambientData;
    directionalData.lightData.brightness = 1.0f;
    directionalData.castsShadows = kQ3False;
    directionalData.direction.x = -1.0f;
    directionalData.direction.y = -0.6f;
    directionalData.direction.z = -0.4f;
    light = Q3DirectionalLight_New(&directionalData);
    if (light != NULL) {
        Q3Group_AddObject(lights, light);
        Q3Object_Dispose(light);
    }
    return lights;
}

static int MyDrawTriMesh(TQ3ViewObject view)
{
    static TQ3Point3D points[5] = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, {0, 1.4f, 0}};
    static TQ3TriMeshTriangleData triangles[6] = {{{3, 2, 4}}, {{2, 1, 4}}, {{1, 0, 4}},
                                                  {{0, 3, 4}}, {{0, 1, 2}}, {{0, 2, 3}}};
    TQ3ViewAngleAspectCameraData cameraData;
    TQ3TriMeshData meshData;
    TQ3CameraObject camera;
    TQ3GroupObject lights = MyNewLights();
    TQ3ShaderObject shader = Q3LambertIllumination_New();
    TQ3GeometryObject mesh;
    TQ3ViewStatus status = kQ3ViewStatusError;

    memset(&cameraData, 0, sizeof cameraData);
    MySetPlacement(&cameraData.cameraData, 2.6f, 2.4f, 3.6f);
    cameraData.cameraData.placement.pointOfInterest.y = 0.45f;
    cameraData.fov = 0.75f;
    cameraData.aspectRatioXToY = (float)kWidth / (float)kHeight;
    camera = Q3ViewAngleAspectCamera_New(&cameraData);

    memset(&meshData, 0, sizeof meshData);
    meshData.triMeshAttributeSet = MyNewColor(1.0f, 0.55f, 0.1f);
    meshData.numTriangles = 6;
    meshData.triangles = triangles;
    meshData.numPoints = 5;
    meshData.points = points;
    Q3BoundingBox_SetFromPoints3D(&meshData.bBox, points, 5, sizeof(TQ3Point3D));
    mesh = Q3TriMesh_New(&meshData);

    if (camera != NULL && lights != NULL && shader != NULL && mesh != NULL &&
        Q3View_SetCamera(view, camera) == kQ3Success && Q3View_SetLightGroup(view, lights) == kQ3Success &&
        Q3View_StartRendering(view) == kQ3Success) {
        do {
            if (Q3Shader_Submit(shader, view) != kQ3Success || Q3Geometry_Submit(mesh, view) != kQ3Success) {
                Q3View_Cancel(view);
                break;
            }
            status = Q3View_EndRendering(view);
        } while (status == kQ3ViewStatusRetraverse);
    }
    if (meshData.triMeshAttributeSet != NULL)
        Q3Object_Dispose(meshData.triMeshAttributeSet);
    if (mesh != NULL)
        Q3Object_Dispose(mesh);
    if (shader != NULL)
        Q3Object_Dispose(shader);
    if (lights != NULL)
        Q3Object_Dispose(lights);
    if (camera != NULL)
        Q3Object_Dispose(camera);
    return status == kQ3ViewStatusDone;
}

int main(int argc, char **argv)
{
    TQ3ViewObject view;
    TQ3DrawContextObject drawContext;
    TQ3RendererObject renderer;
    int curves, drawn = 0, written = 0;

    if (argc != 3 || (strcmp(argv[1], "curves") != 0 && strcmp(argv[1], "trimesh") != 0)) {
        fprintf(stderr, "usage: golden_pictures curves|trimesh OUT.png\n");
        return 1;
    }
    curves = strcmp(argv[1], "curves") == 0;
    if (Q3Initialize() != kQ3Success)
        return 1;
    Q3Error_Register(MyErrorHandler, 0);

    view = Q3View_New();
    drawContext = curves ? MyNewDrawContext(0.05f, 0.08f, 0.25f) : MyNewDrawContext(0.9f, 0.9f, 0.92f);
    renderer = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
    if (view != NULL && drawContext != NULL && renderer != NULL &&
        Q3View_SetDrawContext(view, drawContext) == kQ3Success && Q3View_SetRenderer(view, renderer) == kQ3Success) {
        drawn = curves ? MyDrawCurves(view) : MyDrawTriMesh(view);
        /* What a golden test keeps: the draw context's image, as a PNG file. */
        written = drawn && Q3PixmapDrawContext_WritePNG(drawContext, argv[2]) == kQ3Success;
    }
    if (renderer != NULL)
        Q3Object_Dispose(renderer);
    if (drawContext != NULL)
        Q3Object_Dispose(drawContext);
    if (view != NULL)
        Q3Object_Dispose(view);
    Q3Exit();
    return written ? 0 : 1;
}
