// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DCamera.h"
#include "api/Entry.h"
#include "view/Camera.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3ObjectType Q3Camera_GetType(TQ3CameraObject camera)
{
    return api::getLeafType<Camera>(__func__, camera, "camera");
}

TQ3Status Q3Camera_SetData(TQ3CameraObject camera, const TQ3CameraData* cameraData)
{
    return setValue<Camera>(__func__, camera, "camera", cameraData, "cameraData", &Camera::setData);
}

TQ3Status Q3Camera_GetData(TQ3CameraObject camera, TQ3CameraData* cameraData)
{
    return getValue<Camera>(__func__, camera, "camera", cameraData, "cameraData", &Camera::data);
}

TQ3Status Q3Camera_SetPlacement(TQ3CameraObject camera, const TQ3CameraPlacement* placement)
{
    return setValue<Camera>(__func__, camera, "camera", placement, "placement", &Camera::setPlacement);
}

TQ3Status Q3Camera_GetPlacement(TQ3CameraObject camera, TQ3CameraPlacement* placement)
{
    return getValue<Camera>(__func__, camera, "camera", placement, "placement",
                            [&](const Camera& source) { return source.data().placement; });
}

TQ3Status Q3Camera_SetRange(TQ3CameraObject camera, const TQ3CameraRange* range)
{
    return setValue<Camera>(__func__, camera, "camera", range, "range", &Camera::setRange);
}

TQ3Status Q3Camera_GetRange(TQ3CameraObject camera, TQ3CameraRange* range)
{
    return getValue<Camera>(__func__, camera, "camera", range, "range",
                            [&](const Camera& source) { return source.data().range; });
}

TQ3Status Q3Camera_SetViewPort(TQ3CameraObject camera, const TQ3CameraViewPort* viewPort)
{
    return setValue<Camera>(__func__, camera, "camera", viewPort, "viewPort", &Camera::setViewPort);
}

TQ3Status Q3Camera_GetViewPort(TQ3CameraObject camera, TQ3CameraViewPort* viewPort)
{
    return getValue<Camera>(__func__, camera, "camera", viewPort, "viewPort",
                            [&](const Camera& source) { return source.data().viewPort; });
}

TQ3Status Q3Camera_GetWorldToView(TQ3CameraObject camera, TQ3Matrix4x4* worldToView)
{
    return getValue<Camera>(__func__, camera, "camera", worldToView, "worldToView",
                            [&](const Camera& source) { return toQ3(source.worldToView()); });
}

TQ3Status Q3Camera_GetViewToFrustum(TQ3CameraObject camera, TQ3Matrix4x4* viewToFrustum)
{
    return getValue<Camera>(__func__, camera, "camera", viewToFrustum, "viewToFrustum",
                            [&](const Camera& source) { return toQ3(source.viewToFrustum()); });
}

TQ3Status Q3Camera_GetWorldToFrustum(TQ3CameraObject camera, TQ3Matrix4x4* worldToFrustum)
{
    return getValue<Camera>(__func__, camera, "camera", worldToFrustum, "worldToFrustum",
                            [&](const Camera& source) { return toQ3(source.worldToFrustum()); });
}

TQ3CameraObject Q3OrthographicCamera_New(const TQ3OrthographicCameraData* orthographicData)
{
    return guard(__func__, TQ3CameraObject{nullptr}, [&]() -> TQ3CameraObject {
        requireNonNull(orthographicData, "orthographicData");
        OrthographicCamera::validate(*orthographicData);
        return makeShared<OrthographicCamera>(*orthographicData).detach();
    });
}

TQ3Status Q3OrthographicCamera_GetData(TQ3CameraObject camera, TQ3OrthographicCameraData* cameraData)
{
    return getValue<OrthographicCamera>(__func__, camera, "camera", cameraData, "cameraData",
                                        &OrthographicCamera::orthographicData);
}

TQ3Status Q3OrthographicCamera_SetData(TQ3CameraObject camera,
                                       const TQ3OrthographicCameraData* cameraData)
{
    return setValue<OrthographicCamera>(__func__, camera, "camera", cameraData, "cameraData",
                                        &OrthographicCamera::setOrthographicData);
}

TQ3Status Q3OrthographicCamera_SetLeft(TQ3CameraObject camera, float left)
{
    return guardStatus(__func__, [&] {
        OrthographicCamera& target = lookup<OrthographicCamera>(camera, "camera");
        target.setField(&TQ3OrthographicCameraData::left, left);
    });
}

TQ3Status Q3OrthographicCamera_GetLeft(TQ3CameraObject camera, float* left)
{
    return getValue<OrthographicCamera>(__func__, camera, "camera", left, "left",
                                        [](const OrthographicCamera& c) { return c.orthographicData().left; });
}

TQ3Status Q3OrthographicCamera_SetTop(TQ3CameraObject camera, float top)
{
    return guardStatus(__func__, [&] {
        OrthographicCamera& target = lookup<OrthographicCamera>(camera, "camera");
        target.setField(&TQ3OrthographicCameraData::top, top);
    });
}

TQ3Status Q3OrthographicCamera_GetTop(TQ3CameraObject camera, float* top)
{
    return getValue<OrthographicCamera>(__func__, camera, "camera", top, "top",
                                        [](const OrthographicCamera& c) { return c.orthographicData().top; });
}

TQ3Status Q3OrthographicCamera_SetRight(TQ3CameraObject camera, float right)
{
    return guardStatus(__func__, [&] {
        OrthographicCamera& target = lookup<OrthographicCamera>(camera, "camera");
        target.setField(&TQ3OrthographicCameraData::right, right);
    });
}

TQ3Status Q3OrthographicCamera_GetRight(TQ3CameraObject camera, float* right)
{
    return getValue<OrthographicCamera>(__func__, camera, "camera", right, "right",
                                        [](const OrthographicCamera& c) { return c.orthographicData().right; });
}

TQ3Status Q3OrthographicCamera_SetBottom(TQ3CameraObject camera, float bottom)
{
    return guardStatus(__func__, [&] {
        OrthographicCamera& target = lookup<OrthographicCamera>(camera, "camera");
        target.setField(&TQ3OrthographicCameraData::bottom, bottom);
    });
}

TQ3Status Q3OrthographicCamera_GetBottom(TQ3CameraObject camera, float* bottom)
{
    return getValue<OrthographicCamera>(__func__, camera, "camera", bottom, "bottom",
                                        [](const OrthographicCamera& c) { return c.orthographicData().bottom; });
}

TQ3CameraObject Q3ViewPlaneCamera_New(const TQ3ViewPlaneCameraData* cameraData)
{
    return guard(__func__, TQ3CameraObject{nullptr}, [&]() -> TQ3CameraObject {
        requireNonNull(cameraData, "cameraData");
        ViewPlaneCamera::validate(*cameraData);
        return makeShared<ViewPlaneCamera>(*cameraData).detach();
    });
}

TQ3Status Q3ViewPlaneCamera_GetData(TQ3CameraObject camera, TQ3ViewPlaneCameraData* cameraData)
{
    return getValue<ViewPlaneCamera>(__func__, camera, "camera", cameraData, "cameraData",
                                     &ViewPlaneCamera::viewPlaneData);
}

TQ3Status Q3ViewPlaneCamera_SetData(TQ3CameraObject camera, const TQ3ViewPlaneCameraData* cameraData)
{
    return setValue<ViewPlaneCamera>(__func__, camera, "camera", cameraData, "cameraData",
                                     &ViewPlaneCamera::setViewPlaneData);
}

TQ3Status Q3ViewPlaneCamera_SetViewPlane(TQ3CameraObject camera, float viewPlane)
{
    return guardStatus(__func__, [&] {
        ViewPlaneCamera& target = lookup<ViewPlaneCamera>(camera, "camera");
        target.setField(&TQ3ViewPlaneCameraData::viewPlane, viewPlane);
    });
}

TQ3Status Q3ViewPlaneCamera_GetViewPlane(TQ3CameraObject camera, float* viewPlane)
{
    return getValue<ViewPlaneCamera>(__func__, camera, "camera", viewPlane, "viewPlane",
                                     [](const ViewPlaneCamera& c) { return c.viewPlaneData().viewPlane; });
}

TQ3Status Q3ViewPlaneCamera_SetHalfWidth(TQ3CameraObject camera, float halfWidthAtViewPlane)
{
    return guardStatus(__func__, [&] {
        ViewPlaneCamera& target = lookup<ViewPlaneCamera>(camera, "camera");
        target.setField(&TQ3ViewPlaneCameraData::halfWidthAtViewPlane, halfWidthAtViewPlane);
    });
}

TQ3Status Q3ViewPlaneCamera_GetHalfWidth(TQ3CameraObject camera, float* halfWidthAtViewPlane)
{
    return getValue<ViewPlaneCamera>(__func__, camera, "camera", halfWidthAtViewPlane, "halfWidthAtViewPlane",
                                     [](const ViewPlaneCamera& c) { return c.viewPlaneData().halfWidthAtViewPlane; });
}

TQ3Status Q3ViewPlaneCamera_SetHalfHeight(TQ3CameraObject camera, float halfHeightAtViewPlane)
{
    return guardStatus(__func__, [&] {
        ViewPlaneCamera& target = lookup<ViewPlaneCamera>(camera, "camera");
        target.setField(&TQ3ViewPlaneCameraData::halfHeightAtViewPlane, halfHeightAtViewPlane);
    });
}

TQ3Status Q3ViewPlaneCamera_GetHalfHeight(TQ3CameraObject camera, float* halfHeightAtViewPlane)
{
    return getValue<ViewPlaneCamera>(__func__, camera, "camera", halfHeightAtViewPlane, "halfHeightAtViewPlane",
                                     [](const ViewPlaneCamera& c) { return c.viewPlaneData().halfHeightAtViewPlane; });
}

TQ3Status Q3ViewPlaneCamera_SetCenterX(TQ3CameraObject camera, float centerXOnViewPlane)
{
    return guardStatus(__func__, [&] {
        ViewPlaneCamera& target = lookup<ViewPlaneCamera>(camera, "camera");
        target.setField(&TQ3ViewPlaneCameraData::centerXOnViewPlane, centerXOnViewPlane);
    });
}

TQ3Status Q3ViewPlaneCamera_GetCenterX(TQ3CameraObject camera, float* centerXOnViewPlane)
{
    return getValue<ViewPlaneCamera>(__func__, camera, "camera", centerXOnViewPlane, "centerXOnViewPlane",
                                     [](const ViewPlaneCamera& c) { return c.viewPlaneData().centerXOnViewPlane; });
}

TQ3Status Q3ViewPlaneCamera_SetCenterY(TQ3CameraObject camera, float centerYOnViewPlane)
{
    return guardStatus(__func__, [&] {
        ViewPlaneCamera& target = lookup<ViewPlaneCamera>(camera, "camera");
        target.setField(&TQ3ViewPlaneCameraData::centerYOnViewPlane, centerYOnViewPlane);
    });
}

TQ3Status Q3ViewPlaneCamera_GetCenterY(TQ3CameraObject camera, float* centerYOnViewPlane)
{
    return getValue<ViewPlaneCamera>(__func__, camera, "camera", centerYOnViewPlane, "centerYOnViewPlane",
                                     [](const ViewPlaneCamera& c) { return c.viewPlaneData().centerYOnViewPlane; });
}

TQ3CameraObject Q3ViewAngleAspectCamera_New(const TQ3ViewAngleAspectCameraData* cameraData)
{
    return guard(__func__, TQ3CameraObject{nullptr}, [&]() -> TQ3CameraObject {
        requireNonNull(cameraData, "cameraData");
        ViewAngleAspectCamera::validate(*cameraData);
        return makeShared<ViewAngleAspectCamera>(*cameraData).detach();
    });
}

TQ3Status Q3ViewAngleAspectCamera_GetData(TQ3CameraObject camera,
                                          TQ3ViewAngleAspectCameraData* cameraData)
{
    return guardStatus(__func__, [&] {
        const ViewAngleAspectCamera& source = lookup<ViewAngleAspectCamera>(camera, "camera");
        requireNonNull(cameraData, "cameraData");
        *cameraData = source.viewAngleAspectData();
    });
}

TQ3Status Q3ViewAngleAspectCamera_SetData(TQ3CameraObject camera,
                                          const TQ3ViewAngleAspectCameraData* cameraData)
{
    return setValue<ViewAngleAspectCamera>(__func__, camera, "camera", cameraData, "cameraData",
                                           &ViewAngleAspectCamera::setViewAngleAspectData);
}

TQ3Status Q3ViewAngleAspectCamera_SetFOV(TQ3CameraObject camera, float fov)
{
    return guardStatus(__func__, [&] {
        ViewAngleAspectCamera& target = lookup<ViewAngleAspectCamera>(camera, "camera");
        target.setField(&TQ3ViewAngleAspectCameraData::fov, fov);
    });
}

TQ3Status Q3ViewAngleAspectCamera_GetFOV(TQ3CameraObject camera, float* fov)
{
    return getValue<ViewAngleAspectCamera>(__func__, camera, "camera", fov, "fov",
                                           [](const ViewAngleAspectCamera& c) { return c.viewAngleAspectData().fov; });
}

TQ3Status Q3ViewAngleAspectCamera_SetAspectRatio(TQ3CameraObject camera, float aspectRatioXToY)
{
    return guardStatus(__func__, [&] {
        ViewAngleAspectCamera& target = lookup<ViewAngleAspectCamera>(camera, "camera");
        target.setField(&TQ3ViewAngleAspectCameraData::aspectRatioXToY, aspectRatioXToY);
    });
}

TQ3Status Q3ViewAngleAspectCamera_GetAspectRatio(TQ3CameraObject camera, float* aspectRatioXToY)
{
    return guardStatus(__func__, [&] {
        readInto<ViewAngleAspectCamera>(camera, "camera", aspectRatioXToY, "aspectRatioXToY",
            [](const ViewAngleAspectCamera& c) { return c.viewAngleAspectData().aspectRatioXToY; });
    });
}

} // extern "C"
