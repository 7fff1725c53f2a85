// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DCamera.h"
#include "api/Entry.h"
#include "view/Camera.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

extern "C" {

TQ3ObjectType Q3Camera_GetType(TQ3CameraObject camera)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookup<Camera>(camera, "camera").leafType(); });
}

TQ3Status Q3Camera_SetData(TQ3CameraObject camera, const TQ3CameraData* cameraData)
{
    return guardStatus(__func__, [&] {
        Camera& target = lookup<Camera>(camera, "camera");
        requireNonNull(cameraData, "cameraData");
        target.setData(*cameraData);
    });
}

TQ3Status Q3Camera_GetData(TQ3CameraObject camera, TQ3CameraData* cameraData)
{
    return guardStatus(__func__, [&] {
        const Camera& source = lookup<Camera>(camera, "camera");
        requireNonNull(cameraData, "cameraData");
        *cameraData = source.data();
    });
}

TQ3Status Q3Camera_SetPlacement(TQ3CameraObject camera, const TQ3CameraPlacement* placement)
{
    return guardStatus(__func__, [&] {
        Camera& target = lookup<Camera>(camera, "camera");
        requireNonNull(placement, "placement");
        target.setPlacement(*placement);
    });
}

TQ3Status Q3Camera_GetPlacement(TQ3CameraObject camera, TQ3CameraPlacement* placement)
{
    return guardStatus(__func__, [&] {
        const Camera& source = lookup<Camera>(camera, "camera");
        requireNonNull(placement, "placement");
        *placement = source.data().placement;
    });
}

TQ3Status Q3Camera_SetRange(TQ3CameraObject camera, const TQ3CameraRange* range)
{
    return guardStatus(__func__, [&] {
        Camera& target = lookup<Camera>(camera, "camera");
        requireNonNull(range, "range");
        target.setRange(*range);
    });
}

TQ3Status Q3Camera_GetRange(TQ3CameraObject camera, TQ3CameraRange* range)
{
    return guardStatus(__func__, [&] {
        const Camera& source = lookup<Camera>(camera, "camera");
        requireNonNull(range, "range");
        *range = source.data().range;
    });
}

TQ3Status Q3Camera_SetViewPort(TQ3CameraObject camera, const TQ3CameraViewPort* viewPort)
{
    return guardStatus(__func__, [&] {
        Camera& target = lookup<Camera>(camera, "camera");
        requireNonNull(viewPort, "viewPort");
        target.setViewPort(*viewPort);
    });
}

TQ3Status Q3Camera_GetViewPort(TQ3CameraObject camera, TQ3CameraViewPort* viewPort)
{
    return guardStatus(__func__, [&] {
        const Camera& source = lookup<Camera>(camera, "camera");
        requireNonNull(viewPort, "viewPort");
        *viewPort = source.data().viewPort;
    });
}

TQ3Status Q3Camera_GetWorldToView(TQ3CameraObject camera, TQ3Matrix4x4* worldToView)
{
    return guardStatus(__func__, [&] {
        const Camera& source = lookup<Camera>(camera, "camera");
        requireNonNull(worldToView, "worldToView");
        *worldToView = toQ3(source.worldToView());
    });
}

TQ3Status Q3Camera_GetViewToFrustum(TQ3CameraObject camera, TQ3Matrix4x4* viewToFrustum)
{
    return guardStatus(__func__, [&] {
        const Camera& source = lookup<Camera>(camera, "camera");
        requireNonNull(viewToFrustum, "viewToFrustum");
        *viewToFrustum = toQ3(source.viewToFrustum());
    });
}

TQ3Status Q3Camera_GetWorldToFrustum(TQ3CameraObject camera, TQ3Matrix4x4* worldToFrustum)
{
    return guardStatus(__func__, [&] {
        const Camera& source = lookup<Camera>(camera, "camera");
        requireNonNull(worldToFrustum, "worldToFrustum");
        *worldToFrustum = toQ3(source.worldToFrustum());
    });
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
    return guardStatus(__func__, [&] {
        const OrthographicCamera& source = lookup<OrthographicCamera>(camera, "camera");
        requireNonNull(cameraData, "cameraData");
        *cameraData = source.orthographicData();
    });
}

TQ3Status Q3OrthographicCamera_SetData(TQ3CameraObject camera,
                                       const TQ3OrthographicCameraData* cameraData)
{
    return guardStatus(__func__, [&] {
        OrthographicCamera& target = lookup<OrthographicCamera>(camera, "camera");
        requireNonNull(cameraData, "cameraData");
        target.setOrthographicData(*cameraData);
    });
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
    return guardStatus(__func__, [&] {
        const ViewPlaneCamera& source = lookup<ViewPlaneCamera>(camera, "camera");
        requireNonNull(cameraData, "cameraData");
        *cameraData = source.viewPlaneData();
    });
}

TQ3Status Q3ViewPlaneCamera_SetData(TQ3CameraObject camera, const TQ3ViewPlaneCameraData* cameraData)
{
    return guardStatus(__func__, [&] {
        ViewPlaneCamera& target = lookup<ViewPlaneCamera>(camera, "camera");
        requireNonNull(cameraData, "cameraData");
        target.setViewPlaneData(*cameraData);
    });
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
    return guardStatus(__func__, [&] {
        ViewAngleAspectCamera& target = lookup<ViewAngleAspectCamera>(camera, "camera");
        requireNonNull(cameraData, "cameraData");
        target.setViewAngleAspectData(*cameraData);
    });
}

} // extern "C"
