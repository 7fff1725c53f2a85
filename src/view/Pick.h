// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DPick.h"
#include "core/Object.h"
#include "core/Ref.h"
#include "geometry/Geometry.h"
#include "group/Group.h"

#include <vector>

namespace q3 {

extern const ClassInfo kPickClass;
extern const ClassInfo kWindowPointPickClass;
extern const ClassInfo kWindowRectPickClass;
extern const ClassInfo kWorldRayPickClass;

/// One hit of a pick: the details QD3DPick.h lists, with `valid` saying
/// which hold something. The hit keeps the geometry and the root group
/// alive (a reference each) until the hit list is emptied.
struct PickHit {
    TQ3PickDetail valid = kQ3PickDetailNone;
    unsigned long pickID = 0;
    Ref<Group> rootGroup;
    std::vector<TQ3GroupPosition> positions;
    /// The object submitted: a geometry, or a custom object (its class's
    /// submit method submitted the geometries hit).
    Ref<SharedObject> object;
    TQ3Matrix4x4 localToWorld{};
    TQ3Point3D xyz{};
    float distance = 0.0f;
    TQ3Vector3D normal{};
    TQ3PickParts part = kQ3PickPartsObject;
    TQ3Param2D uv{};
    /// The shape part hit (a mesh face, edge or vertex part), or null.
    Ref<SharedObject> shapePart;
    /// The distance the hits are sorted by, when `valid` has Distance.
    double sortDistance = 0.0;
};

/// A QuickDraw 3D pick (QD3DPick.h): what to test, how to report, and the
/// hits of the last picking loop. Not shared: disposing it destroys it.
/// Invariant: the settings always satisfy QD3DPick.h's data rules (every
/// setter validates before it changes anything); the hits are sorted and
/// at most numHitsToReturn (when that is not 0).
class Pick final : public Object {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ObjectTypePick;
    enum class Kind { kWindowPoint, kWindowRect, kWorldRay };

    explicit Pick(const TQ3WindowPointPickData& data);
    explicit Pick(const TQ3WindowRectPickData& data);
    explicit Pick(const TQ3WorldRayPickData& data);

    const ClassInfo& classInfo() const override;
    Kind kind() const { return m_kind; }

    /// The pick if it is of `kind`, else kQ3ErrorInvalidObjectType naming
    /// `what` (e.g. "a window-point pick").
    static Pick& ofKind(TQ3Object handle, Kind kind, const char* what);

    const TQ3PickData& data() const { return m_data; }
    /// This and the kinds' setters below apply the new sort, count and mask
    /// to the hit list at once, as a picking loop ending would: a pick never
    /// holds more hits or details than it asks for (a list is cut, never
    /// grown back).
    void setData(const TQ3PickData& data);

    /// Tolerances: kQ3ErrorInvalidObjectType for a window-rect pick.
    float vertexTolerance() const;
    float edgeTolerance() const;
    void setVertexTolerance(float tolerance);
    void setEdgeTolerance(float tolerance);

    const TQ3WindowPointPickData& windowPoint() const { return m_point; }
    const TQ3WindowRectPickData& windowRect() const { return m_rect; }
    const TQ3WorldRayPickData& worldRay() const { return m_ray; }
    void setWindowPoint(const TQ3WindowPointPickData& data);
    void setWindowRect(const TQ3WindowRectPickData& data);
    void setWorldRay(const TQ3WorldRayPickData& data);
    void setPoint(const TQ3Point2D& point);
    void setRect(const TQ3Area& rect);
    void setRay(const TQ3Ray3D& ray);

    /// The data rules (QD3DPick.h), each throwing kQ3ErrorInvalidParameter.
    static void check(const TQ3PickData& data);
    static void check(const TQ3WindowPointPickData& data);
    static void check(const TQ3WindowRectPickData& data);
    static void check(const TQ3WorldRayPickData& data);

    /// Sorts the hits as the settings say, keeps numHitsToReturn of them and
    /// makes them the hit list.
    void setHits(std::vector<PickHit> hits);
    void emptyHits() { m_hits.clear(); }
    std::size_t hitCount() const { return m_hits.size(); }
    /// kQ3ErrorParameterOutOfRange unless index < hitCount().
    const PickHit& hit(unsigned long index) const;

private:
    Kind m_kind;
    TQ3PickData m_data{};
    TQ3WindowPointPickData m_point{};
    TQ3WindowRectPickData m_rect{};
    TQ3WorldRayPickData m_ray{};
    std::vector<PickHit> m_hits;
};

} // namespace q3
