// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DTransform.h"
#include "core/Object.h"

namespace q3 {

extern const ClassInfo kTransformClass;
extern const ClassInfo kMatrixTransformClass;
extern const ClassInfo kTranslateTransformClass;
extern const ClassInfo kScaleTransformClass;
extern const ClassInfo kRotateTransformClass;
extern const ClassInfo kResetTransformClass;
extern const ClassInfo kQuaternionTransformClass;
extern const ClassInfo kRotateAboutPointTransformClass;
extern const ClassInfo kRotateAboutAxisTransformClass;

/// The checks QD3DTransform.h lists, one per kind of data; each is the one
/// routine behind that transform's _New, _Submit and setters (the
/// constructors and the set methods call it). Matrix, translate and scale throw kQ3ErrorInvalidParameter for a
/// value that is not finite; rotate throws kQ3ErrorInvalidData for an axis
/// that is not a TQ3Axis or an angle that is not finite. Zero and negative
/// scale factors are accepted without a post, as in QuickDraw 3D ("when two
/// or three of the scale factors are 0, nothing is drawn").
void validateMatrixTransform(const TQ3Matrix4x4& matrix);
void validateTranslateTransform(const TQ3Vector3D& translate);
void validateScaleTransform(const TQ3Vector3D& scale);
void validateRotateTransform(const TQ3RotateTransformData& data);
/// Quaternion: kQ3ErrorInvalidParameter for a component that is not finite
/// or the zero quaternion. Rotate about point and about axis:
/// kQ3ErrorInvalidData for the rule of QD3DTransform.h each breaks.
void validateQuaternionTransform(const TQ3Quaternion& quaternion);
void validateRotateAboutPointTransform(const TQ3RotateAboutPointTransformData& data);
void validateRotateAboutAxisTransform(const TQ3RotateAboutAxisTransformData& data);

/// A QuickDraw 3D transform: a drawable that changes the view's
/// local-to-world matrix L when submitted, to matrix() * L, or, for the reset
/// transform only, to the identity. Invariant: matrix() has finite entries.
class Transform : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShapeTypeTransform;

    bool isDrawable() const override { return true; }
    void accept(ShapeVisitor& visitor) const override;

    /// The transform as a QuickDraw 3D matrix (row vectors: p' = p * M).
    virtual TQ3Matrix4x4 matrix() const = 0;
    /// True only for the reset transform, which replaces the local-to-world
    /// matrix with the identity instead of multiplying it.
    virtual bool isReset() const { return false; }

protected:
    Transform() = default;
};

/// A transform whose whole state is one QD3DTransform.h value (a matrix, a
/// vector, a quaternion or a data struct), kept as given and checked by
/// Validate, the one routine behind the kind's _New, _Submit and setters.
/// Invariant: Validate(value()) does not throw.
template <class Self, class Value, void (*Validate)(const Value&)>
class ValueTransform : public Transform {
public:
    using ValueType = Value;

    /// Throws as Validate.
    explicit ValueTransform(const Value& value) : m_value(value) { Validate(value); }

    Object* duplicate() const override { return makeShared<Self>(m_value).detach(); }
    const Value& value() const { return m_value; }
    /// Throws as Validate and then changes nothing.
    void setValue(const Value& value)
    {
        Validate(value);
        m_value = value;
        markEdited();
    }

private:
    Value m_value;
};

/// An arbitrary matrix. Invariant: every entry is finite.
class MatrixTransform final : public ValueTransform<MatrixTransform, TQ3Matrix4x4, validateMatrixTransform> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TransformTypeMatrix;
    using ValueTransform::ValueTransform;

    const ClassInfo& classInfo() const override { return kMatrixTransformClass; }
    TQ3Matrix4x4 matrix() const override { return value(); }
};

/// A translation. Invariant: the offset is finite.
class TranslateTransform final
    : public ValueTransform<TranslateTransform, TQ3Vector3D, validateTranslateTransform> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TransformTypeTranslate;
    using ValueTransform::ValueTransform;

    const ClassInfo& classInfo() const override { return kTranslateTransformClass; }
    TQ3Matrix4x4 matrix() const override;
};

/// A scale about the local origin. Invariant: the factors are finite (zero
/// and negative factors are allowed).
class ScaleTransform final : public ValueTransform<ScaleTransform, TQ3Vector3D, validateScaleTransform> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TransformTypeScale;
    using ValueTransform::ValueTransform;

    const ClassInfo& classInfo() const override { return kScaleTransformClass; }
    TQ3Matrix4x4 matrix() const override;
};

/// A rotation about a coordinate axis. Invariant: the axis is X, Y or Z and
/// the angle is finite.
class RotateTransform final
    : public ValueTransform<RotateTransform, TQ3RotateTransformData, validateRotateTransform> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TransformTypeRotate;
    using ValueTransform::ValueTransform;

    const ClassInfo& classInfo() const override { return kRotateTransformClass; }
    TQ3Matrix4x4 matrix() const override;
    /// Each throws as validateRotateTransform (on the whole data, with the
    /// one field replaced) and then changes nothing. The axis is taken by
    /// reference because a C caller may pass any int: it is read as bytes
    /// until validated (core/EnumValue.h).
    void setAxis(const TQ3Axis& axis);
    void setAngle(float radians);
};

/// A rotation given as a quaternion. Invariant: the quaternion is finite and
/// not zero; it is kept as set and normalized only to build the matrix.
class QuaternionTransform final
    : public ValueTransform<QuaternionTransform, TQ3Quaternion, validateQuaternionTransform> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TransformTypeQuaternion;
    using ValueTransform::ValueTransform;

    const ClassInfo& classInfo() const override { return kQuaternionTransformClass; }
    TQ3Matrix4x4 matrix() const override;
};

/// A rotation about the line through a point parallel to a coordinate axis.
/// Invariant: the data obey validateRotateAboutPointTransform. Field setters
/// go through setValue.
class RotateAboutPointTransform final
    : public ValueTransform<RotateAboutPointTransform, TQ3RotateAboutPointTransformData,
                            validateRotateAboutPointTransform> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TransformTypeRotateAboutPoint;
    using ValueTransform::ValueTransform;

    const ClassInfo& classInfo() const override { return kRotateAboutPointTransformClass; }
    TQ3Matrix4x4 matrix() const override;
};

/// A rotation about an arbitrary line. Invariant: the data obey
/// validateRotateAboutAxisTransform. Field setters go through setValue.
class RotateAboutAxisTransform final
    : public ValueTransform<RotateAboutAxisTransform, TQ3RotateAboutAxisTransformData,
                            validateRotateAboutAxisTransform> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TransformTypeRotateAboutAxis;
    using ValueTransform::ValueTransform;

    const ClassInfo& classInfo() const override { return kRotateAboutAxisTransformClass; }
    TQ3Matrix4x4 matrix() const override;
};

/// The reset transform: no data. Invariant: matrix() is the identity and
/// isReset() is true.
class ResetTransform final : public Transform {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TransformTypeReset;

    ResetTransform() = default;

    const ClassInfo& classInfo() const override { return kResetTransformClass; }
    Object* duplicate() const override;
    TQ3Matrix4x4 matrix() const override;
    bool isReset() const override { return true; }
};

} // namespace q3
