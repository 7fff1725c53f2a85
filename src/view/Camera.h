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

/// One of a camera kind's own fields, all floats, and its name in
/// QD3DCamera.h. A kind lists them in its struct's order (Self::kFields):
/// validation checks each to be finite in that order, and a 3DMF camera object
/// holds them in that order (io/CameraIO.cpp).
template <class Data>
struct CameraField {
    float Data::*member;
    const char* name;
};

/// What every kind of camera shares: its whole data struct (Data, whose
/// first field is the common TQ3CameraData) read and replaced as one, and one
/// float field replaced through the same checks. Self::validate(const Data&)
/// states the kind's rules. Invariant: m_kind holds the kind's own fields and
/// a zeroed cameraData (Camera holds the common data).
template <class Self, class Data>
class CameraKind : public Camera {
public:
    using DataType = Data;

    Object* duplicate() const override { return makeShared<Self>(kindData()).detach(); }

    /// The whole data, the common part included.
    Data kindData() const
    {
        Data whole = m_kind;
        whole.cameraData = data();
        return whole;
    }
    /// Validates first (Self::validate) and changes nothing on failure.
    void setKindData(const Data& whole)
    {
        Self::validate(whole);
        assignCommon(whole.cameraData);
        m_kind = ownFields(whole);
        markEdited();
    }
    /// Replaces one field through setKindData, so a single-field setter
    /// checks exactly what SetData checks and changes nothing on failure.
    void setField(float Data::*field, float value)
    {
        Data whole = kindData();
        whole.*field = value;
        setKindData(whole);
    }

protected:
    /// Takes validated data.
    explicit CameraKind(const Data& whole) : Camera(whole.cameraData), m_kind(ownFields(whole)) {}
    const Data& kind() const { return m_kind; }

private:
    static Data ownFields(Data whole)
    {
        whole.cameraData = TQ3CameraData{};
        return whole;
    }

    Data m_kind;
};

/// A parallel projection of a rectangle of view space. Invariant: the data
/// obey the TQ3OrthographicCameraData rules (finite bounds, left != right,
/// top != bottom).
class OrthographicCamera final : public CameraKind<OrthographicCamera, TQ3OrthographicCameraData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3CameraTypeOrthographic;
    using Data = TQ3OrthographicCameraData;
    static constexpr CameraField<Data> kFields[] = {
        {&Data::left, "left"}, {&Data::top, "top"}, {&Data::right, "right"}, {&Data::bottom, "bottom"}};

    /// Throws kQ3ErrorInvalidCameraValues on data that break a rule.
    static void validate(const TQ3OrthographicCameraData& data);
    /// Takes validated data.
    explicit OrthographicCamera(const TQ3OrthographicCameraData& data) : CameraKind(data) {}

    const ClassInfo& classInfo() const override { return kOrthographicCameraClass; }
    bool isPerspective() const override { return false; }

protected:
    Matrix projection() const override;
};

/// A perspective projection through a rectangle on a plane in front of the
/// camera (possibly off-axis). Invariant: the data obey the
/// TQ3ViewPlaneCameraData rules.
class ViewPlaneCamera final : public CameraKind<ViewPlaneCamera, TQ3ViewPlaneCameraData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3CameraTypeViewPlane;
    using Data = TQ3ViewPlaneCameraData;
    static constexpr CameraField<Data> kFields[] = {{&Data::viewPlane, "viewPlane"},
                                                    {&Data::halfWidthAtViewPlane, "halfWidthAtViewPlane"},
                                                    {&Data::halfHeightAtViewPlane, "halfHeightAtViewPlane"},
                                                    {&Data::centerXOnViewPlane, "centerXOnViewPlane"},
                                                    {&Data::centerYOnViewPlane, "centerYOnViewPlane"}};

    static void validate(const TQ3ViewPlaneCameraData& data);
    explicit ViewPlaneCamera(const TQ3ViewPlaneCameraData& data) : CameraKind(data) {}

    const ClassInfo& classInfo() const override { return kViewPlaneCameraClass; }
    bool isPerspective() const override { return true; }

protected:
    Matrix projection() const override;
};

/// A symmetric perspective projection given by a field of view and an aspect
/// ratio. Invariant: the data obey the TQ3ViewAngleAspectCameraData rules
/// (0 < fov < pi, aspect ratio finite and positive).
class ViewAngleAspectCamera final : public CameraKind<ViewAngleAspectCamera, TQ3ViewAngleAspectCameraData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3CameraTypeViewAngleAspect;
    using Data = TQ3ViewAngleAspectCameraData;
    static constexpr CameraField<Data> kFields[] = {{&Data::fov, "fov"},
                                                    {&Data::aspectRatioXToY, "aspectRatioXToY"}};

    static void validate(const TQ3ViewAngleAspectCameraData& data);
    explicit ViewAngleAspectCamera(const TQ3ViewAngleAspectCameraData& data) : CameraKind(data) {}

    const ClassInfo& classInfo() const override { return kViewAngleAspectCameraClass; }
    bool isPerspective() const override { return true; }

protected:
    Matrix projection() const override;
};

} // namespace q3
