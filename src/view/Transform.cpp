// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/Transform.h"

#include "core/ShapeVisitor.h"
#include "base/MatrixMath.h"
#include "base/QuaternionMath.h"

#include <cmath>
#include <cstring>
#include <string>

namespace q3 {

const ClassInfo kTransformClass{kQ3ShapeTypeTransform, &kShapeClass, "transform"};
const ClassInfo kMatrixTransformClass{kQ3TransformTypeMatrix, &kTransformClass, "matrix transform"};
const ClassInfo kTranslateTransformClass{kQ3TransformTypeTranslate, &kTransformClass,
                                         "translate transform"};
const ClassInfo kScaleTransformClass{kQ3TransformTypeScale, &kTransformClass, "scale transform"};
const ClassInfo kRotateTransformClass{kQ3TransformTypeRotate, &kTransformClass, "rotate transform"};
const ClassInfo kResetTransformClass{kQ3TransformTypeReset, &kTransformClass, "reset transform"};
const ClassInfo kQuaternionTransformClass{kQ3TransformTypeQuaternion, &kTransformClass, "quaternion transform"};
const ClassInfo kRotateAboutPointTransformClass{kQ3TransformTypeRotateAboutPoint, &kTransformClass,
                                                "rotate about point transform"};
const ClassInfo kRotateAboutAxisTransformClass{kQ3TransformTypeRotateAboutAxis, &kTransformClass,
                                               "rotate about axis transform"};

namespace {

void requireFinite(const TQ3Vector3D& v, const char* name)
{
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        fail(kQ3ErrorInvalidParameter, std::string(name) + " has a component that is not finite");
}

} // namespace

void validateMatrixTransform(const TQ3Matrix4x4& matrix)
{
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(matrix.value[i][j]))
                fail(kQ3ErrorInvalidParameter, "matrix entry value[" + std::to_string(i) + "][" +
                                                   std::to_string(j) + "] is not finite");
}

void validateTranslateTransform(const TQ3Vector3D& translate)
{
    requireFinite(translate, "translate");
}

void validateScaleTransform(const TQ3Vector3D& scale)
{
    requireFinite(scale, "scale");
}

namespace {

// C callers may store any int in the enum; reading it as a TQ3Axis would be
// undefined behaviour in C++ for values outside the enum's range, so read
// the bits as the int C stored.
void validateAxisAndAngle(const TQ3Axis& storedAxis, float radians)
{
    int axis;
    static_assert(sizeof axis == sizeof storedAxis, "TQ3Axis is int-sized, as in C");
    std::memcpy(&axis, &storedAxis, sizeof axis);
    if (axis != kQ3AxisX && axis != kQ3AxisY && axis != kQ3AxisZ)
        fail(kQ3ErrorInvalidData,
             "axis " + std::to_string(axis) + " is none of kQ3AxisX, kQ3AxisY, kQ3AxisZ");
    if (!std::isfinite(radians))
        fail(kQ3ErrorInvalidData, "radians is not finite");
}

bool isFinite(float x, float y, float z)
{
    return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

} // namespace

void validateRotateTransform(const TQ3RotateTransformData& data)
{
    validateAxisAndAngle(data.axis, data.radians);
}

void validateQuaternionTransform(const TQ3Quaternion& q)
{
    if (!std::isfinite(q.w) || !isFinite(q.x, q.y, q.z))
        fail(kQ3ErrorInvalidParameter, "quaternion has a component that is not finite");
    // matrix() normalizes in double precision, where every finite float
    // quaternion but zero has a length.
    if (q.w == 0.0f && q.x == 0.0f && q.y == 0.0f && q.z == 0.0f)
        fail(kQ3ErrorInvalidParameter, "quaternion is (0, 0, 0, 0), which is no rotation");
}

void validateRotateAboutPointTransform(const TQ3RotateAboutPointTransformData& data)
{
    validateAxisAndAngle(data.axis, data.radians);
    if (!isFinite(data.about.x, data.about.y, data.about.z))
        fail(kQ3ErrorInvalidData, "about has a coordinate that is not finite");
}

void validateRotateAboutAxisTransform(const TQ3RotateAboutAxisTransformData& data)
{
    if (!isFinite(data.origin.x, data.origin.y, data.origin.z))
        fail(kQ3ErrorInvalidData, "origin has a coordinate that is not finite");
    const TQ3Vector3D& v = data.orientation;
    if (!isFinite(v.x, v.y, v.z))
        fail(kQ3ErrorInvalidData, "orientation has a component that is not finite");
    if (v.x == 0.0f && v.y == 0.0f && v.z == 0.0f)
        fail(kQ3ErrorInvalidData, "orientation is the zero vector");
    if (!std::isfinite(data.radians))
        fail(kQ3ErrorInvalidData, "radians is not finite");
}

void Transform::accept(ShapeVisitor& visitor) const
{
    visitor.visitTransform(*this);
}

TQ3Matrix4x4 TranslateTransform::matrix() const
{
    return math::translation(value().x, value().y, value().z);
}

TQ3Matrix4x4 ScaleTransform::matrix() const
{
    return math::scaling(value().x, value().y, value().z);
}

void RotateTransform::setAxis(const TQ3Axis& axis)
{
    TQ3RotateTransformData data = value();
    std::memcpy(&data.axis, &axis, sizeof axis);
    setValue(data);
}

void RotateTransform::setAngle(float radians)
{
    TQ3RotateTransformData data = value();
    data.radians = radians;
    setValue(data);
}

TQ3Matrix4x4 RotateTransform::matrix() const
{
    const TQ3RotateTransformData& data = value();
    switch (data.axis) {
    case kQ3AxisX:
        return math::rotationX(data.radians);
    case kQ3AxisY:
        return math::rotationY(data.radians);
    case kQ3AxisZ:
        break;
    }
    return math::rotationZ(data.radians);
}

TQ3Matrix4x4 QuaternionTransform::matrix() const
{
    return math::matrixFromQuaternion(math::normalize(value()));
}

TQ3Matrix4x4 RotateAboutPointTransform::matrix() const
{
    const TQ3RotateAboutPointTransformData& data = value();
    const float x = data.axis == kQ3AxisX ? data.radians : 0.0f;
    const float y = data.axis == kQ3AxisY ? data.radians : 0.0f;
    const float z = data.axis == kQ3AxisZ ? data.radians : 0.0f;
    return math::rotationAboutPoint(data.about, x, y, z);
}

TQ3Matrix4x4 RotateAboutAxisTransform::matrix() const
{
    const TQ3RotateAboutAxisTransformData& data = value();
    return math::rotationAboutAxis(data.origin, data.orientation, data.radians);
}

Object* ResetTransform::duplicate() const
{
    return makeShared<ResetTransform>().detach();
}

TQ3Matrix4x4 ResetTransform::matrix() const
{
    return math::identity();
}

} // namespace q3
