// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DCamera.h"
#include "core/Object.h"
#include "base/Matrix.h"

namespace q3 {

extern const ClassInfo kCameraClass;
extern const ClassInfo kOrthographicCameraClass;
extern const ClassInfo kViewPlaneCameraClass;
extern const ClassInfo kViewAngleAspectCameraClass;

/// Checks the TQ3CameraData rules of QD3DCamera.h (placement, range, view
/// port); `perspective` adds hither > 0. Throws kQ3ErrorInvalidCameraValues
/// naming the broken rule.
void validateCameraData(const TQ3CameraData& data, bool perspective);
void validatePlacement(const TQ3CameraPlacement& placement);
void validateRange(const TQ3CameraRange& range, bool perspective);
void validateViewPort(const TQ3CameraViewPort& viewPort);

/// The frustum-to-window step shared by cameras and views: the row-vector
/// matrix taking a camera's view port (QD3DCamera.h: origin top-left, width,
/// height on the -1..1 view plane) to the whole -1..1 square, applied after
/// the projection and before the homogeneous divide.
Matrix viewPortMatrix(const TQ3CameraViewPort& viewPort);

/// Any QuickDraw 3D camera: a placement, a range and a view port, plus the
/// projection its subclass defines. Invariant: the common data always obey
/// validateCameraData for the subclass's kind (perspective or not), so every
/// matrix it computes is finite and invertible in x and y.
class Camera : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShapeTypeCamera;

    const TQ3CameraData& data() const { return m_data; }
    /// Each setter validates first (kQ3ErrorInvalidCameraValues) and changes
    /// nothing on failure.
    void setData(const TQ3CameraData& data);
    void setPlacement(const TQ3CameraPlacement& placement);
    void setRange(const TQ3CameraRange& range);
    void setViewPort(const TQ3CameraViewPort& viewPort);

    /// True for the view plane and view angle aspect cameras.
    virtual bool isPerspective() const = 0;

    /// World to view: the camera at the origin looking down -z, +y towards
    /// the up vector made perpendicular to the viewing direction.
    Matrix worldToView() const;
    /// View to frustum, the projection followed by the view port: x and y
    /// in -1..1 across the view port, z from 0 (hither) to -1 (yon) after
    /// the homogeneous divide.
    Matrix viewToFrustum() const;
    Matrix worldToFrustum() const { return then(worldToView(), viewToFrustum()); }

protected:
    explicit Camera(const TQ3CameraData& data) : m_data(data) {}
    /// The subclass's projection alone (the whole view plane to -1..1).
    virtual Matrix projection() const = 0;
    /// Replaces the common data (already validated) without marking an edit.
    void assignCommon(const TQ3CameraData& data) { m_data = data; }

private:
    TQ3CameraData m_data;
};

/// A parallel projection of a rectangle of view space. Invariant: the data
/// obey the TQ3OrthographicCameraData rules (finite bounds, left != right,
/// top != bottom).
class OrthographicCamera final : public Camera {
public:
    static constexpr TQ3ObjectType kClassType = kQ3CameraTypeOrthographic;

    /// Throws kQ3ErrorInvalidCameraValues on data that break a rule.
    static void validate(const TQ3OrthographicCameraData& data);
    /// Takes validated data.
    explicit OrthographicCamera(const TQ3OrthographicCameraData& data);

    const ClassInfo& classInfo() const override { return kOrthographicCameraClass; }
    Object* duplicate() const override;
    bool isPerspective() const override { return false; }

    TQ3OrthographicCameraData orthographicData() const;
    void setOrthographicData(const TQ3OrthographicCameraData& data);
    /// Replaces one field through setOrthographicData, so a single-field setter
    /// checks exactly what SetData checks and changes nothing on failure.
    void setField(float TQ3OrthographicCameraData::*field, float value);

protected:
    Matrix projection() const override;

private:
    float m_left;
    float m_top;
    float m_right;
    float m_bottom;
};

/// A perspective projection through a rectangle on a plane in front of the
/// camera (possibly off-axis). Invariant: the data obey the
/// TQ3ViewPlaneCameraData rules.
class ViewPlaneCamera final : public Camera {
public:
    static constexpr TQ3ObjectType kClassType = kQ3CameraTypeViewPlane;

    static void validate(const TQ3ViewPlaneCameraData& data);
    explicit ViewPlaneCamera(const TQ3ViewPlaneCameraData& data);

    const ClassInfo& classInfo() const override { return kViewPlaneCameraClass; }
    Object* duplicate() const override;
    bool isPerspective() const override { return true; }

    TQ3ViewPlaneCameraData viewPlaneData() const;
    void setViewPlaneData(const TQ3ViewPlaneCameraData& data);
    /// Replaces one field through setViewPlaneData, so a single-field setter
    /// checks exactly what SetData checks and changes nothing on failure.
    void setField(float TQ3ViewPlaneCameraData::*field, float value);

protected:
    Matrix projection() const override;

private:
    float m_viewPlane;
    float m_halfWidth;
    float m_halfHeight;
    float m_centerX;
    float m_centerY;
};

/// A symmetric perspective projection given by a field of view and an aspect
/// ratio. Invariant: the data obey the TQ3ViewAngleAspectCameraData rules
/// (0 < fov < pi, aspect ratio finite and positive).
class ViewAngleAspectCamera final : public Camera {
public:
    static constexpr TQ3ObjectType kClassType = kQ3CameraTypeViewAngleAspect;

    static void validate(const TQ3ViewAngleAspectCameraData& data);
    explicit ViewAngleAspectCamera(const TQ3ViewAngleAspectCameraData& data);

    const ClassInfo& classInfo() const override { return kViewAngleAspectCameraClass; }
    Object* duplicate() const override;
    bool isPerspective() const override { return true; }

    TQ3ViewAngleAspectCameraData viewAngleAspectData() const;
    void setViewAngleAspectData(const TQ3ViewAngleAspectCameraData& data);
    /// Replaces one field through setViewAngleAspectData, so a single-field setter
    /// checks exactly what SetData checks and changes nothing on failure.
    void setField(float TQ3ViewAngleAspectCameraData::*field, float value);

protected:
    Matrix projection() const override;

private:
    float m_fov;
    float m_aspect;
};

} // namespace q3
