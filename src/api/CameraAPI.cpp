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

} // namespace

// A C entry point cannot come from a template, so each family of entry points
// below is written once as a macro that defines them through the templates
// above. Kind names the class (q3::<Kind>Camera), its data
// (TQ3<Kind>CameraData) and the C prefix (Q3<Kind>Camera_); the parameter
// names are QD3DCamera.h's, so the error messages name them as every other
// call does.

/// Q3Camera_Set<Field> and _Get<Field> of the member `member` of every
/// camera's TQ3CameraData, a Type given through a pointer and set through
/// Camera::set<Field>.
#define Q3_CAMERA_MEMBER_ENTRY_POINTS(Field, Type, member)                                                      \
    TQ3Status Q3Camera_Set##Field(TQ3CameraObject camera, const Type* member)                                   \
    {                                                                                                           \
        return setValue<Camera>(__func__, camera, "camera", member, #member, &Camera::set##Field);              \
    }                                                                                                           \
    TQ3Status Q3Camera_Get##Field(TQ3CameraObject camera, Type* member)                                         \
    {                                                                                                           \
        return getValue<Camera>(__func__, camera, "camera", member, #member,                                    \
                                [&](const Camera& source) { return source.data().member; });                    \
    }

/// Q3Camera_Get<Matrix>, the matrix Camera::<member>() computes.
#define Q3_CAMERA_MATRIX_ENTRY_POINT(Matrix, member)                                                            \
    TQ3Status Q3Camera_Get##Matrix(TQ3CameraObject camera, TQ3Matrix4x4* member)                                \
    {                                                                                                           \
        return getValue<Camera>(__func__, camera, "camera", member, #member,                                    \
                                [&](const Camera& source) { return toQ3(source.member()); });                   \
    }

/// Q3<Kind>Camera_New (its data called `newData`), _GetData and _SetData.
#define Q3_CAMERA_KIND_ENTRY_POINTS(Kind, newData)                                                              \
    TQ3CameraObject Q3##Kind##Camera_New(const TQ3##Kind##CameraData* newData)                                  \
    {                                                                                                           \
        return newCamera<Kind##Camera>(__func__, newData, #newData);                                            \
    }                                                                                                           \
    TQ3Status Q3##Kind##Camera_GetData(TQ3CameraObject camera, TQ3##Kind##CameraData* cameraData)               \
    {                                                                                                           \
        return getCameraData<Kind##Camera>(__func__, camera, cameraData);                                       \
    }                                                                                                           \
    TQ3Status Q3##Kind##Camera_SetData(TQ3CameraObject camera, const TQ3##Kind##CameraData* cameraData)         \
    {                                                                                                           \
        return setCameraData<Kind##Camera>(__func__, camera, cameraData);                                       \
    }

/// Q3<Kind>Camera_Set<Field> and _Get<Field> of the float `member` of
/// TQ3<Kind>CameraData.
#define Q3_CAMERA_FIELD_ENTRY_POINTS(Kind, Field, member)                                                       \
    TQ3Status Q3##Kind##Camera_Set##Field(TQ3CameraObject camera, float member)                                 \
    {                                                                                                           \
        return setCameraField<Kind##Camera>(__func__, camera, member, &TQ3##Kind##CameraData::member);          \
    }                                                                                                           \
    TQ3Status Q3##Kind##Camera_Get##Field(TQ3CameraObject camera, float* member)                                \
    {                                                                                                           \
        return getCameraField<Kind##Camera>(__func__, camera, member, #member, &TQ3##Kind##CameraData::member); \
    }

extern "C" {

TQ3Status Q3Camera_SetData(TQ3CameraObject camera, const TQ3CameraData* cameraData)
{
    return setValue<Camera>(__func__, camera, "camera", cameraData, "cameraData", &Camera::setData);
}

TQ3Status Q3Camera_GetData(TQ3CameraObject camera, TQ3CameraData* cameraData)
{
    return getValue<Camera>(__func__, camera, "camera", cameraData, "cameraData", &Camera::data);
}

TQ3ObjectType Q3Camera_GetType(TQ3CameraObject camera)
{
    return api::getLeafType<Camera>(__func__, camera, "camera");
}

Q3_CAMERA_MEMBER_ENTRY_POINTS(Placement, TQ3CameraPlacement, placement)
Q3_CAMERA_MEMBER_ENTRY_POINTS(Range, TQ3CameraRange, range)
Q3_CAMERA_MEMBER_ENTRY_POINTS(ViewPort, TQ3CameraViewPort, viewPort)

Q3_CAMERA_MATRIX_ENTRY_POINT(WorldToView, worldToView)
Q3_CAMERA_MATRIX_ENTRY_POINT(ViewToFrustum, viewToFrustum)
Q3_CAMERA_MATRIX_ENTRY_POINT(WorldToFrustum, worldToFrustum)

Q3_CAMERA_KIND_ENTRY_POINTS(Orthographic, orthographicData)
Q3_CAMERA_FIELD_ENTRY_POINTS(Orthographic, Left, left)
Q3_CAMERA_FIELD_ENTRY_POINTS(Orthographic, Top, top)
Q3_CAMERA_FIELD_ENTRY_POINTS(Orthographic, Right, right)
Q3_CAMERA_FIELD_ENTRY_POINTS(Orthographic, Bottom, bottom)

Q3_CAMERA_KIND_ENTRY_POINTS(ViewAngleAspect, cameraData)
Q3_CAMERA_FIELD_ENTRY_POINTS(ViewAngleAspect, FOV, fov)
Q3_CAMERA_FIELD_ENTRY_POINTS(ViewAngleAspect, AspectRatio, aspectRatioXToY)

Q3_CAMERA_KIND_ENTRY_POINTS(ViewPlane, cameraData)
Q3_CAMERA_FIELD_ENTRY_POINTS(ViewPlane, ViewPlane, viewPlane)
Q3_CAMERA_FIELD_ENTRY_POINTS(ViewPlane, HalfWidth, halfWidthAtViewPlane)
Q3_CAMERA_FIELD_ENTRY_POINTS(ViewPlane, HalfHeight, halfHeightAtViewPlane)
Q3_CAMERA_FIELD_ENTRY_POINTS(ViewPlane, CenterX, centerXOnViewPlane)
Q3_CAMERA_FIELD_ENTRY_POINTS(ViewPlane, CenterY, centerYOnViewPlane)

} // extern "C"

#undef Q3_CAMERA_MEMBER_ENTRY_POINTS
#undef Q3_CAMERA_MATRIX_ENTRY_POINT
#undef Q3_CAMERA_KIND_ENTRY_POINTS
#undef Q3_CAMERA_FIELD_ENTRY_POINTS
