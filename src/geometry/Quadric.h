// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// What the quadrics and solids (Box, Cone, Cylinder, Disk, Ellipsoid, Torus;
// Ellipse, a curve, uses the helpers) share on top of DataGeometry: the data
// rules their headers list, in the shape every such rule takes; decomposition
// through geometry/quadric (patches, then triangles under the view's
// subdivision); analytic bounds; and Apple's per-field setters, which check
// the data as SetData would with the one field changed, so a setter can never
// accept what SetData refuses.
//
// A class derives from QuadricGeometry<Derived, Data> and adds:
//   static quadric::Patches patches(const Data&);           its parts
//   std::vector<const AttributeSet*> partSets() const;      the set of each
//                                                           quadric::Part
//   static void boundPoints(const Data&, std::vector<glm::dvec3>&);
//                                                           points whose box
//                                                           holds the shape

#include "core/ErrorManager.h"
#include "geometry/DataGeometry.h"
#include "geometry/quadric/Shapes.h"
#include "geometry/quadric/Tessellate.h"

#include <string>
#include <utility>
#include <vector>

namespace q3 {

// ---- The rules ---------------------------------------------------------------

// Every float of the data is finite: the descriptions say so (finite()).

/// kQ3ErrorInvalidData when a point origin + (up to) the sum of the vectors'
/// lengths, times `scale` for the last one, could leave float's range: the
/// shape's vertices would not be finite.
void requireWithinFloatRange(const TQ3Point3D& origin, std::initializer_list<TQ3Vector3D> vectors,
                             double lastScale = 1.0);

/// kQ3ErrorInvalidData unless 0 <= value <= 1.
void requireUnitParameter(float value, const char* name);

/// kQ3ErrorInvalidData unless min <= max (a range that does not wrap).
void requireOrdered(float min, float max, const char* minName, const char* maxName);

/// kQ3ErrorInvalidData when caps has a bit that is not kQ3EndCapMaskTop,
/// kQ3EndCapMaskBottom or kQ3EndCapMaskInterior.
void requireCapBits(TQ3EndCap caps);

// ---- The tolerated cases ---------------------------------------------------------
//
// QuickDraw 3D and Quesa accept a shape whose vectors are zero or dependent,
// or whose u or v range is empty, and draw nothing for it (docs/3dmf.md,
// "Tolerances"). Q3 keeps such data as it is given, posts
// kQ3WarningInconsistentData where it is given (DataGeometry::validate), and
// draws and bounds nothing for it. Each function below describes the case it
// finds, or gives an empty string.

/// The vectors are zero or not independent (quadric::independence at or
/// below quadric::kDegenerateFrame); `what` lists their names.
std::string dependentFrame(const TQ3Vector3D& x, const TQ3Vector3D& y, const TQ3Vector3D& z, const char* what);
std::string dependentFrame(const TQ3Vector3D& x, const TQ3Vector3D& y, const char* what);

/// An empty range: an angle (wrapping when min > max) is empty when
/// min == max or min = 1, max = 0; another range when min == max.
std::string emptyAngle(float min, float max, const char* minName, const char* maxName);
std::string emptyRange(float min, float max, const char* minName, const char* maxName);

/// The first non-empty description of `cases`, or an empty string.
std::string firstCase(std::initializer_list<std::string> cases);

// ---- Conversions ---------------------------------------------------------------

inline quadric::Vec3 toVec3(const TQ3Point3D& p)
{
    return quadric::Vec3(p.x, p.y, p.z);
}
inline quadric::Vec3 toVec3(const TQ3Vector3D& v)
{
    return quadric::Vec3(v.x, v.y, v.z);
}

/// The quadric module's subdivision for a view's measure: constant counts
/// (c1, c2) or c1 as the bound on a drawn edge through the measure's map.
quadric::Subdivision subdivisionFor(const SubdivisionMeasure& measure, std::size_t maxTriangles);

/// Fills `mesh` with the triangles of `patches` under `measure`, each vertex
/// with its normal and uv and the attributes of its part's set (sets[part],
/// may be null), the wireframe the triangles' sides. Returns the warning to
/// post (empty when the subdivision was not reduced); `shape` names the
/// geometry in it.
std::string buildSurface(Mesh& mesh, const quadric::Patches& patches, const SubdivisionMeasure& measure,
                         const std::vector<const AttributeSet*>& sets, const char* shape);

/// The points bounding an ellipse of radii x, y around centre: its box's
/// corners (half-extents sqrt(x_i^2 + y_i^2), exact for the whole ellipse).
void ellipseBoxCorners(const quadric::Vec3& centre, const quadric::Vec3& x, const quadric::Vec3& y,
                       std::vector<glm::dvec3>& points);

/// The rules an ellipse and a disk share (TQ3EllipseData, TQ3DiskData: the
/// same leading fields), in QD3DGeometry.h's order: the frame within float's
/// range, then uMin and uMax in 0 to 1.
template <class D> void checkEllipseData(const D& d)
{
    requireWithinFloatRange(d.origin, {d.majorRadius, d.minorRadius});
    requireUnitParameter(d.uMin, "uMin");
    requireUnitParameter(d.uMax, "uMax");
}

/// The rules of the shapes revolved around an orientation (TQ3ConeData,
/// TQ3CylinderData, TQ3EllipsoidData: the same fields), in QD3DGeometry.h's
/// order, after their descriptions have found every float finite.
template <class D> void checkRevolvedData(const D& d)
{
    requireWithinFloatRange(d.origin, {d.orientation, d.majorRadius, d.minorRadius});
    requireUnitParameter(d.uMin, "uMin");
    requireUnitParameter(d.uMax, "uMax");
    requireUnitParameter(d.vMin, "vMin");
    requireUnitParameter(d.vMax, "vMax");
    requireOrdered(d.vMin, d.vMax, "vMin", "vMax");
    requireCapBits(d.caps);
}

/// The tolerated degenerate cases of those shapes, in the same order.
template <class D> std::string revolvedDegeneracy(const D& d)
{
    return firstCase({dependentFrame(d.orientation, d.majorRadius, d.minorRadius,
                                     "orientation, majorRadius and minorRadius"),
                      emptyAngle(d.uMin, d.uMax, "uMin", "uMax"), emptyRange(d.vMin, d.vMax, "vMin", "vMax")});
}

template <class D> quadric::RevolvedShape revolvedShape(const D& d)
{
    quadric::RevolvedShape shape;
    shape.origin = toVec3(d.origin);
    shape.orientation = toVec3(d.orientation);
    shape.majorRadius = toVec3(d.majorRadius);
    shape.minorRadius = toVec3(d.minorRadius);
    shape.u = quadric::angularRange(d.uMin, d.uMax);
    shape.v = quadric::Range{d.vMin, d.vMax};
    shape.caps = unsigned(d.caps);
    return shape;
}

// ---- The class templates ---------------------------------------------------------

/// A geometry with Apple's per-field setters.
template <class Derived, class Data> class FieldGeometry : public DataGeometry<Derived, Data> {
public:
    using DataGeometry<Derived, Data>::DataGeometry;

    /// The data with `field` set to `value` must pass checkData (its
    /// errors, in its order); then the field changes (with the warning of a
    /// tolerated degenerate case, as SetData posts it) and the edit is
    /// marked. On failure nothing changes.
    template <class T> void setField(T Data::*field, const T& value)
    {
        Data changed = this->data();
        changed.*field = value;
        this->checkData(changed);
        this->warnIfDegenerate(changed);
        this->editableData().*field = value;
        this->markEdited();
    }

    /// Replaces one of the part attribute sets (null removes it).
    void setPartSet(TQ3AttributeSet Data::*field, Ref<AttributeSet> set)
    {
        replaceHeldSet(this->editableData().*field, std::move(set));
        this->markEdited();
    }
};

/// A shape drawn as the triangles of its quadric::Patches.
template <class Derived, class Data> class QuadricGeometry : public FieldGeometry<Derived, Data> {
public:
    using FieldGeometry<Derived, Data>::FieldGeometry;

    /// The shape's parts as triangles under the view's subdivision (cached
    /// for a retained shape until its data, a part's attribute set or the
    /// subdivision changes); kQ3WarningParameterOutOfRange when
    /// kQ3SubdivisionMaxTrianglesPerSurface made it coarser. A degenerate
    /// shape (Derived::degeneracy) draws nothing.
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override
    {
        if (!Derived::degeneracy(this->data()).empty())
            return;
        const SubdivisionMeasure measure = context.subdivisionMeasure();
        const std::vector<const AttributeSet*> sets = static_cast<const Derived&>(*this).partSets();
        std::vector<double> key = measure.key();
        appendEditIndices(key, sets);
        std::string report;
        this->withMesh(
            std::move(key),
            [&](Mesh& mesh) {
                m_report = buildSurface(mesh, Derived::patches(this->data()), measure, sets, Derived::kName);
            },
            [&](const Mesh& mesh) {
                report = m_report;
                sink.draw(mesh.view(), this->attributeSet());
            });
        if (!report.empty())
            errors::postWarning(kQ3WarningParameterOutOfRange, report);
    }

    /// The analytic box of the whole shape (a partial shape is bounded by its
    /// whole); nothing for a degenerate shape, which draws nothing.
    void bound(const DecomposeContext&, std::vector<glm::dvec3>& points) const override
    {
        if (!Derived::degeneracy(this->data()).empty())
            return;
        Derived::boundPoints(this->data(), points);
    }

private:
    // The warning of the last build, read with the mesh (both under the mesh
    // lock of Geometry::withMesh).
    mutable std::string m_report;
};

} // namespace q3
