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

/// An arbitrary matrix. Invariant: every entry is finite.
class MatrixTransform final : public Transform {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TransformTypeMatrix;

    /// Throws as validateMatrixTransform.
    explicit MatrixTransform(const TQ3Matrix4x4& matrix);

    const ClassInfo& classInfo() const override { return kMatrixTransformClass; }
    Object* duplicate() const override;
    TQ3Matrix4x4 matrix() const override { return m_matrix; }
    /// Throws as validateMatrixTransform and then changes nothing.
    void setMatrix(const TQ3Matrix4x4& matrix);

private:
    TQ3Matrix4x4 m_matrix;
};

/// A translation. Invariant: the offset is finite.
class TranslateTransform final : public Transform {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TransformTypeTranslate;

    /// Throws as validateTranslateTransform.
    explicit TranslateTransform(const TQ3Vector3D& translate);

    const ClassInfo& classInfo() const override { return kTranslateTransformClass; }
    Object* duplicate() const override;
    TQ3Matrix4x4 matrix() const override;
    const TQ3Vector3D& translate() const { return m_translate; }
    /// Throws as validateTranslateTransform and then changes nothing.
    void setTranslate(const TQ3Vector3D& translate);

private:
    TQ3Vector3D m_translate;
};

/// A scale about the local origin. Invariant: the factors are finite (zero
/// and negative factors are allowed).
class ScaleTransform final : public Transform {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TransformTypeScale;

    /// Throws as validateScaleTransform.
    explicit ScaleTransform(const TQ3Vector3D& scale);

    const ClassInfo& classInfo() const override { return kScaleTransformClass; }
    Object* duplicate() const override;
    TQ3Matrix4x4 matrix() const override;
    const TQ3Vector3D& scale() const { return m_scale; }
    /// Throws as validateScaleTransform and then changes nothing.
    void setScale(const TQ3Vector3D& scale);

private:
    TQ3Vector3D m_scale;
};

/// A rotation about a coordinate axis. Invariant: the axis is X, Y or Z and
/// the angle is finite.
class RotateTransform final : public Transform {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TransformTypeRotate;

    /// Throws as validateRotateTransform.
    explicit RotateTransform(const TQ3RotateTransformData& data);

    const ClassInfo& classInfo() const override { return kRotateTransformClass; }
    Object* duplicate() const override;
    TQ3Matrix4x4 matrix() const override;
    const TQ3RotateTransformData& data() const { return m_data; }
    /// Each throws as validateRotateTransform (on the whole data, with the
    /// one field replaced) and then changes nothing. The axis is taken by
    /// reference because a C caller may pass any int: it is read as bytes
    /// until validated (core/EnumValue.h).
    void setData(const TQ3RotateTransformData& data);
    void setAxis(const TQ3Axis& axis);
    void setAngle(float radians);

private:
    TQ3RotateTransformData m_data;
};

/// A rotation given as a quaternion. Invariant: the quaternion is finite and
/// not zero; it is kept as set and normalized only to build the matrix.
class QuaternionTransform final : public Transform {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TransformTypeQuaternion;

    /// Throws as validateQuaternionTransform.
    explicit QuaternionTransform(const TQ3Quaternion& quaternion);

    const ClassInfo& classInfo() const override { return kQuaternionTransformClass; }
    Object* duplicate() const override;
    TQ3Matrix4x4 matrix() const override;
    const TQ3Quaternion& quaternion() const { return m_quaternion; }
    /// Throws as validateQuaternionTransform and then changes nothing.
    void setQuaternion(const TQ3Quaternion& quaternion);

private:
    TQ3Quaternion m_quaternion;
};

/// A rotation about the line through a point parallel to a coordinate axis.
/// Invariant: the data obey validateRotateAboutPointTransform.
class RotateAboutPointTransform final : public Transform {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TransformTypeRotateAboutPoint;

    /// Throws as validateRotateAboutPointTransform.
    explicit RotateAboutPointTransform(const TQ3RotateAboutPointTransformData& data);

    const ClassInfo& classInfo() const override { return kRotateAboutPointTransformClass; }
    Object* duplicate() const override;
    TQ3Matrix4x4 matrix() const override;
    const TQ3RotateAboutPointTransformData& data() const { return m_data; }
    /// Throws as validateRotateAboutPointTransform (on the whole data) and
    /// then changes nothing. Field setters go through it.
    void setData(const TQ3RotateAboutPointTransformData& data);

private:
    TQ3RotateAboutPointTransformData m_data;
};

/// A rotation about an arbitrary line. Invariant: the data obey
/// validateRotateAboutAxisTransform.
class RotateAboutAxisTransform final : public Transform {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TransformTypeRotateAboutAxis;

    /// Throws as validateRotateAboutAxisTransform.
    explicit RotateAboutAxisTransform(const TQ3RotateAboutAxisTransformData& data);

    const ClassInfo& classInfo() const override { return kRotateAboutAxisTransformClass; }
    Object* duplicate() const override;
    TQ3Matrix4x4 matrix() const override;
    const TQ3RotateAboutAxisTransformData& data() const { return m_data; }
    /// Throws as validateRotateAboutAxisTransform (on the whole data) and
    /// then changes nothing. Field setters go through it.
    void setData(const TQ3RotateAboutAxisTransformData& data);

private:
    TQ3RotateAboutAxisTransformData m_data;
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
