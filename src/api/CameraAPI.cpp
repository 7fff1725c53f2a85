// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DCamera.h"
#include "api/Entry.h"
#include "view/Camera.h"

using namespace q3;
using namespace q3::api;

namespace {

// The calls every camera kind C (view/Camera.h's CameraKind) has, in
// QD3DCamera.h's order: the handle, then the pointer, then the kind's rules.

template <class C>
TQ3CameraObject newCamera(const char* function, const typename C::DataType* data, const char* dataName)
{
    return guard(function, TQ3CameraObject{nullptr}, [&]() -> TQ3CameraObject {
        requireNonNull(data, dataName);
        C::validate(*data);
        return makeShared<C>(*data).detach();
    });
}

template <class C>
TQ3Status getCameraData(const char* function, TQ3CameraObject camera, typename C::DataType* data)
{
    return getValue<C>(function, camera, "camera", data, "cameraData", &C::kindData);
}

template <class C>
TQ3Status setCameraData(const char* function, TQ3CameraObject camera, const typename C::DataType* data)
{
    return setValue<C>(function, camera, "camera", data, "cameraData", &C::setKindData);
}

template <class C>
TQ3Status getCameraField(const char* function, TQ3CameraObject camera, float* value, const char* valueName,
                         float C::DataType::*field)
{
    return getValue<C>(function, camera, "camera", value, valueName,
                       [&](const C& source) { return source.kindData().*field; });
}

/// Through C::setField: the whole data's checks, nothing changed on failure.
template <class C>
TQ3Status setCameraField(const char* function, TQ3CameraObject camera, float value, float C::DataType::*field)
{
    return guardStatus(function, [&] { lookup<C>(camera, "camera").setField(field, value); });
}

using OrthographicData = TQ3OrthographicCameraData;
using ViewPlaneData = TQ3ViewPlaneCameraData;
using ViewAngleAspectData = TQ3ViewAngleAspectCameraData;

} // namespace

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
    return newCamera<OrthographicCamera>(__func__, orthographicData, "orthographicData");
}

TQ3Status Q3OrthographicCamera_GetData(TQ3CameraObject camera, TQ3OrthographicCameraData* cameraData)
{
    return getCameraData<OrthographicCamera>(__func__, camera, cameraData);
}

TQ3Status Q3OrthographicCamera_SetData(TQ3CameraObject camera,
                                       const TQ3OrthographicCameraData* cameraData)
{
    return setCameraData<OrthographicCamera>(__func__, camera, cameraData);
}

TQ3Status Q3OrthographicCamera_SetLeft(TQ3CameraObject camera, float left)
{
    return setCameraField<OrthographicCamera>(__func__, camera, left, &OrthographicData::left);
}

TQ3Status Q3OrthographicCamera_GetLeft(TQ3CameraObject camera, float* left)
{
    return getCameraField<OrthographicCamera>(__func__, camera, left, "left", &OrthographicData::left);
}

TQ3Status Q3OrthographicCamera_SetTop(TQ3CameraObject camera, float top)
{
    return setCameraField<OrthographicCamera>(__func__, camera, top, &OrthographicData::top);
}

TQ3Status Q3OrthographicCamera_GetTop(TQ3CameraObject camera, float* top)
{
    return getCameraField<OrthographicCamera>(__func__, camera, top, "top", &OrthographicData::top);
}

TQ3Status Q3OrthographicCamera_SetRight(TQ3CameraObject camera, float right)
{
    return setCameraField<OrthographicCamera>(__func__, camera, right, &OrthographicData::right);
}

TQ3Status Q3OrthographicCamera_GetRight(TQ3CameraObject camera, float* right)
{
    return getCameraField<OrthographicCamera>(__func__, camera, right, "right", &OrthographicData::right);
}

TQ3Status Q3OrthographicCamera_SetBottom(TQ3CameraObject camera, float bottom)
{
    return setCameraField<OrthographicCamera>(__func__, camera, bottom, &OrthographicData::bottom);
}

TQ3Status Q3OrthographicCamera_GetBottom(TQ3CameraObject camera, float* bottom)
{
    return getCameraField<OrthographicCamera>(__func__, camera, bottom, "bottom", &OrthographicData::bottom);
}

TQ3CameraObject Q3ViewPlaneCamera_New(const TQ3ViewPlaneCameraData* cameraData)
{
    return newCamera<ViewPlaneCamera>(__func__, cameraData, "cameraData");
}

TQ3Status Q3ViewPlaneCamera_GetData(TQ3CameraObject camera, TQ3ViewPlaneCameraData* cameraData)
{
    return getCameraData<ViewPlaneCamera>(__func__, camera, cameraData);
}

TQ3Status Q3ViewPlaneCamera_SetData(TQ3CameraObject camera, const TQ3ViewPlaneCameraData* cameraData)
{
    return setCameraData<ViewPlaneCamera>(__func__, camera, cameraData);
}

TQ3Status Q3ViewPlaneCamera_SetViewPlane(TQ3CameraObject camera, float viewPlane)
{
    return setCameraField<ViewPlaneCamera>(__func__, camera, viewPlane, &ViewPlaneData::viewPlane);
}

TQ3Status Q3ViewPlaneCamera_GetViewPlane(TQ3CameraObject camera, float* viewPlane)
{
    return getCameraField<ViewPlaneCamera>(__func__, camera, viewPlane, "viewPlane", &ViewPlaneData::viewPlane);
}

TQ3Status Q3ViewPlaneCamera_SetHalfWidth(TQ3CameraObject camera, float halfWidthAtViewPlane)
{
    return setCameraField<ViewPlaneCamera>(__func__, camera, halfWidthAtViewPlane,
                                           &ViewPlaneData::halfWidthAtViewPlane);
}

TQ3Status Q3ViewPlaneCamera_GetHalfWidth(TQ3CameraObject camera, float* halfWidthAtViewPlane)
{
    return getCameraField<ViewPlaneCamera>(__func__, camera, halfWidthAtViewPlane, "halfWidthAtViewPlane",
                                           &ViewPlaneData::halfWidthAtViewPlane);
}

TQ3Status Q3ViewPlaneCamera_SetHalfHeight(TQ3CameraObject camera, float halfHeightAtViewPlane)
{
    return setCameraField<ViewPlaneCamera>(__func__, camera, halfHeightAtViewPlane,
                                           &ViewPlaneData::halfHeightAtViewPlane);
}

TQ3Status Q3ViewPlaneCamera_GetHalfHeight(TQ3CameraObject camera, float* halfHeightAtViewPlane)
{
    return getCameraField<ViewPlaneCamera>(__func__, camera, halfHeightAtViewPlane, "halfHeightAtViewPlane",
                                           &ViewPlaneData::halfHeightAtViewPlane);
}

TQ3Status Q3ViewPlaneCamera_SetCenterX(TQ3CameraObject camera, float centerXOnViewPlane)
{
    return setCameraField<ViewPlaneCamera>(__func__, camera, centerXOnViewPlane, &ViewPlaneData::centerXOnViewPlane);
}

TQ3Status Q3ViewPlaneCamera_GetCenterX(TQ3CameraObject camera, float* centerXOnViewPlane)
{
    return getCameraField<ViewPlaneCamera>(__func__, camera, centerXOnViewPlane, "centerXOnViewPlane",
                                           &ViewPlaneData::centerXOnViewPlane);
}

TQ3Status Q3ViewPlaneCamera_SetCenterY(TQ3CameraObject camera, float centerYOnViewPlane)
{
    return setCameraField<ViewPlaneCamera>(__func__, camera, centerYOnViewPlane, &ViewPlaneData::centerYOnViewPlane);
}

TQ3Status Q3ViewPlaneCamera_GetCenterY(TQ3CameraObject camera, float* centerYOnViewPlane)
{
    return getCameraField<ViewPlaneCamera>(__func__, camera, centerYOnViewPlane, "centerYOnViewPlane",
                                           &ViewPlaneData::centerYOnViewPlane);
}

TQ3CameraObject Q3ViewAngleAspectCamera_New(const TQ3ViewAngleAspectCameraData* cameraData)
{
    return newCamera<ViewAngleAspectCamera>(__func__, cameraData, "cameraData");
}

TQ3Status Q3ViewAngleAspectCamera_GetData(TQ3CameraObject camera,
                                          TQ3ViewAngleAspectCameraData* cameraData)
{
    return getCameraData<ViewAngleAspectCamera>(__func__, camera, cameraData);
}

TQ3Status Q3ViewAngleAspectCamera_SetData(TQ3CameraObject camera,
                                          const TQ3ViewAngleAspectCameraData* cameraData)
{
    return setCameraData<ViewAngleAspectCamera>(__func__, camera, cameraData);
}

TQ3Status Q3ViewAngleAspectCamera_SetFOV(TQ3CameraObject camera, float fov)
{
    return setCameraField<ViewAngleAspectCamera>(__func__, camera, fov, &ViewAngleAspectData::fov);
}

TQ3Status Q3ViewAngleAspectCamera_GetFOV(TQ3CameraObject camera, float* fov)
{
    return getCameraField<ViewAngleAspectCamera>(__func__, camera, fov, "fov", &ViewAngleAspectData::fov);
}

TQ3Status Q3ViewAngleAspectCamera_SetAspectRatio(TQ3CameraObject camera, float aspectRatioXToY)
{
    return setCameraField<ViewAngleAspectCamera>(__func__, camera, aspectRatioXToY,
                                                 &ViewAngleAspectData::aspectRatioXToY);
}

TQ3Status Q3ViewAngleAspectCamera_GetAspectRatio(TQ3CameraObject camera, float* aspectRatioXToY)
{
    return getCameraField<ViewAngleAspectCamera>(__func__, camera, aspectRatioXToY, "aspectRatioXToY",
                                                 &ViewAngleAspectData::aspectRatioXToY);
}

} // extern "C"
