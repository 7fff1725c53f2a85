// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Cameras and their matrices, in QuickDraw 3D's row-vector convention (see
// base/Matrix.h for how that maps onto glm).
//
// World to view is the usual "look at" frame: the eye at the origin, looking
// down -z, +y towards the up vector. The projections follow the frustum that
// QD3DCamera.h defines (QuickDraw 3D's, as Quesa's E3Camera also has it):
// after the homogeneous divide x and y run from -1 to 1 across the view
// port, and z from 0 at the hither plane to -1 at the yon plane.
//   Orthographic: x' = (2x - (r + l)) / (r - l), likewise y with top and
//     bottom; z' = (z + hither) / (yon - hither), which is 0 at z = -hither
//     and -1 at z = -yon.
//   Perspective: w' = -z (the distance in front of the eye) and
//     z' = q (z + hither) with q = yon / (yon - hither), so z'/w' is 0 at
//     z = -hither and -1 at z = -yon. A view plane camera at distance d
//     with centre (cx, cy) and half sizes (hw, hh) has
//     x' = (d x + cx z) / hw, so that x'/w' = (d x / -z - cx) / hw: the
//     point's projection onto the view plane, measured across the
//     rectangle. The view angle aspect camera is the centred case with
//     d / hw = cot(fov / 2) across its narrower dimension.
// The view port then selects a rectangle of that -1..1 square: origin is its
// top-left corner, so its centre is (ox + w/2, oy - h/2).

#include "view/Camera.h"

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstddef>
#include <string>

namespace q3 {

const ClassInfo kCameraClass{kQ3ShapeTypeCamera, &kShapeClass, "camera"};
const ClassInfo kOrthographicCameraClass{kQ3CameraTypeOrthographic, &kCameraClass,
                                         "orthographic camera"};
const ClassInfo kViewPlaneCameraClass{kQ3CameraTypeViewPlane, &kCameraClass, "view plane camera"};
const ClassInfo kViewAngleAspectCameraClass{kQ3CameraTypeViewAngleAspect, &kCameraClass,
                                            "view angle aspect camera"};

namespace {

// Below this sine of the angle between the up vector and the viewing
// direction the two count as parallel: the camera's x axis would be the
// normalized cross product of nearly parallel vectors, which float input
// cannot determine.
constexpr double kMinUpSine = 1e-6;

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] void invalid(const std::string& why)
{
    fail(kQ3ErrorInvalidCameraValues, why);
}

void requireFinite(float value, const char* name)
{
    if (!std::isfinite(value))
        invalid(std::string(name) + " is not a finite number");
}

// A camera kind's own fields, each finite, in their order.
template <class Data, std::size_t N>
void requireFinite(const Data& data, const CameraField<Data> (&fields)[N])
{
    for (const CameraField<Data>& field : fields)
        requireFinite(data.*field.member, field.name);
}

glm::dvec3 toVec(const TQ3Point3D& p)
{
    return glm::dvec3(p.x, p.y, p.z);
}

glm::dvec3 toVec(const TQ3Vector3D& v)
{
    return glm::dvec3(v.x, v.y, v.z);
}

double cotangent(double angle)
{
    return std::cos(angle) / std::sin(angle);
}

// The perspective part common to both perspective cameras: w' = -z and the
// z mapping described at the top of the file.
Matrix perspectiveDepth(const TQ3CameraRange& range)
{
    const double q = double(range.yon) / (double(range.yon) - double(range.hither));
    Matrix m(0.0);
    m[2][2] = q;
    m[3][2] = q * range.hither;
    m[2][3] = -1.0;
    return m;
}

} // namespace

void validatePlacement(const TQ3CameraPlacement& placement)
{
    requireFinite(placement.cameraLocation.x, "cameraLocation.x");
    requireFinite(placement.cameraLocation.y, "cameraLocation.y");
    requireFinite(placement.cameraLocation.z, "cameraLocation.z");
    requireFinite(placement.pointOfInterest.x, "pointOfInterest.x");
    requireFinite(placement.pointOfInterest.y, "pointOfInterest.y");
    requireFinite(placement.pointOfInterest.z, "pointOfInterest.z");
    requireFinite(placement.upVector.x, "upVector.x");
    requireFinite(placement.upVector.y, "upVector.y");
    requireFinite(placement.upVector.z, "upVector.z");
    const glm::dvec3 direction = toVec(placement.pointOfInterest) - toVec(placement.cameraLocation);
    const glm::dvec3 up = toVec(placement.upVector);
    if (glm::length(direction) == 0.0)
        invalid("cameraLocation equals pointOfInterest, so there is no viewing direction");
    if (glm::length(up) == 0.0)
        invalid("upVector is zero");
    const double sine = glm::length(glm::cross(glm::normalize(direction), glm::normalize(up)));
    if (!(sine >= kMinUpSine))
        invalid("upVector is parallel to the viewing direction");
}

void validateRange(const TQ3CameraRange& range, bool perspective)
{
    requireFinite(range.hither, "range.hither");
    requireFinite(range.yon, "range.yon");
    if (!(range.hither < range.yon))
        invalid("range.hither " + std::to_string(range.hither) + " is not less than range.yon " +
                std::to_string(range.yon));
    if (perspective && !(range.hither > 0.0f))
        invalid("range.hither " + std::to_string(range.hither) +
                " must be greater than 0 for a perspective camera");
}

void validateViewPort(const TQ3CameraViewPort& viewPort)
{
    requireFinite(viewPort.origin.x, "viewPort.origin.x");
    requireFinite(viewPort.origin.y, "viewPort.origin.y");
    requireFinite(viewPort.width, "viewPort.width");
    requireFinite(viewPort.height, "viewPort.height");
    if (!(viewPort.width > 0.0f) || !(viewPort.height > 0.0f))
        invalid("the view port's width and height must be greater than 0");
}

void validateCameraData(const TQ3CameraData& data, bool perspective)
{
    validatePlacement(data.placement);
    validateRange(data.range, perspective);
    validateViewPort(data.viewPort);
}

Matrix viewPortMatrix(const TQ3CameraViewPort& viewPort)
{
    const double width = viewPort.width;
    const double height = viewPort.height;
    const double centerX = viewPort.origin.x + width / 2.0;
    const double centerY = viewPort.origin.y - height / 2.0;
    Matrix m(1.0);
    m[0][0] = 2.0 / width;
    m[3][0] = -centerX * 2.0 / width;
    m[1][1] = 2.0 / height;
    m[3][1] = -centerY * 2.0 / height;
    return m;
}

void Camera::setData(const TQ3CameraData& data)
{
    validateCameraData(data, isPerspective());
    m_data = data;
    markEdited();
}

void Camera::setPlacement(const TQ3CameraPlacement& placement)
{
    validatePlacement(placement);
    m_data.placement = placement;
    markEdited();
}

void Camera::setRange(const TQ3CameraRange& range)
{
    validateRange(range, isPerspective());
    m_data.range = range;
    markEdited();
}

void Camera::setViewPort(const TQ3CameraViewPort& viewPort)
{
    validateViewPort(viewPort);
    m_data.viewPort = viewPort;
    markEdited();
}

Matrix Camera::worldToView() const
{
    return glm::lookAtRH(toVec(m_data.placement.cameraLocation), toVec(m_data.placement.pointOfInterest),
                         toVec(m_data.placement.upVector));
}

Matrix Camera::viewToFrustum() const
{
    return then(projection(), viewPortMatrix(m_data.viewPort));
}

void OrthographicCamera::validate(const TQ3OrthographicCameraData& data)
{
    validateCameraData(data.cameraData, false);
    requireFinite(data, kFields);
    if (data.left == data.right)
        invalid("left equals right, so the visible rectangle has no width");
    if (data.top == data.bottom)
        invalid("top equals bottom, so the visible rectangle has no height");
}

Matrix OrthographicCamera::projection() const
{
    const TQ3OrthographicCameraData& bounds = kind();
    const double width = double(bounds.right) - double(bounds.left);
    const double height = double(bounds.top) - double(bounds.bottom);
    const double depth = double(data().range.yon) - double(data().range.hither);
    Matrix m(1.0);
    m[0][0] = 2.0 / width;
    m[3][0] = -(double(bounds.right) + double(bounds.left)) / width;
    m[1][1] = 2.0 / height;
    m[3][1] = -(double(bounds.top) + double(bounds.bottom)) / height;
    m[2][2] = 1.0 / depth;
    m[3][2] = double(data().range.hither) / depth;
    return m;
}

void ViewPlaneCamera::validate(const TQ3ViewPlaneCameraData& data)
{
    validateCameraData(data.cameraData, true);
    requireFinite(data, kFields);
    if (!(data.viewPlane > 0.0f))
        invalid("viewPlane must be greater than 0");
    if (!(data.halfWidthAtViewPlane > 0.0f) || !(data.halfHeightAtViewPlane > 0.0f))
        invalid("halfWidthAtViewPlane and halfHeightAtViewPlane must be greater than 0");
}

Matrix ViewPlaneCamera::projection() const
{
    const TQ3ViewPlaneCameraData& plane = kind();
    Matrix m = perspectiveDepth(data().range);
    m[0][0] = double(plane.viewPlane) / plane.halfWidthAtViewPlane;
    m[2][0] = double(plane.centerXOnViewPlane) / plane.halfWidthAtViewPlane;
    m[1][1] = double(plane.viewPlane) / plane.halfHeightAtViewPlane;
    m[2][1] = double(plane.centerYOnViewPlane) / plane.halfHeightAtViewPlane;
    return m;
}

void ViewAngleAspectCamera::validate(const TQ3ViewAngleAspectCameraData& data)
{
    validateCameraData(data.cameraData, true);
    requireFinite(data, kFields);
    if (!(data.fov > 0.0f) || !(double(data.fov) < kPi))
        invalid("fov " + std::to_string(data.fov) + " is not between 0 and pi radians");
    if (!(data.aspectRatioXToY > 0.0f))
        invalid("aspectRatioXToY must be greater than 0");
}

Matrix ViewAngleAspectCamera::projection() const
{
    // fov spans the narrower dimension: vertical when the view is at least as
    // wide as it is high.
    const double across = cotangent(double(kind().fov) / 2.0);
    const double aspect = kind().aspectRatioXToY;
    Matrix m = perspectiveDepth(data().range);
    m[0][0] = aspect >= 1.0 ? across / aspect : across;
    m[1][1] = aspect >= 1.0 ? across : across * aspect;
    return m;
}

} // namespace q3
