// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/DataGeometry.h"
#include "geometry/nurbs/Surface.h"
#include "geometry/nurbs/SurfaceTessellate.h"

#include <string>

namespace q3 {

extern const ClassInfo kNURBPatchClass;

/// Checks a caller's TQ3NURBPatchData against every rule QD3DGeometry.h lists
/// for it, in that order: the one routine behind Q3NURBPatch_New, _SetData,
/// immediate-mode _Submit and (on a candidate copy) the knot setters. Throws
/// the rule's error with a message naming the rule, where
/// ("trimLoops[1].trimCurves[0].knots[5]") and the values. Reads only what
/// the counts it has already checked allow. Does not look at the attribute
/// set (DataGeometry checks it when it takes the data).
void validateNURBPatchData(const TQ3NURBPatchData* data);

/// The surface and trim loops of valid data, as the NURBS math takes them.
nurbs::SurfaceRef surfaceRefOf(const TQ3NURBPatchData& data);
nurbs::PatchRef patchRefOf(const TQ3NURBPatchData& data);

/// A NURB patch. Invariant: its data always satisfies validateNURBPatchData
/// (trim loops that cross are only found when it is subdivided); every edit
/// is checked on a candidate first and bumps the edit index, dropping the
/// cached triangles, only once applied.
class NURBPatch final : public DataGeometry<NURBPatch, TQ3NURBPatchData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeNURBPatch;
    static constexpr const char* kName = "nurbPatch";
    static constexpr const char* kDataName = "nurbPatchData";
    static constexpr TQ3AttributeSet TQ3NURBPatchData::*kOwnSet = &TQ3NURBPatchData::patchAttributeSet;

    static void check(const TQ3NURBPatchData& data) { validateNURBPatchData(&data); }

    using DataGeometry::DataGeometry;

    const ClassInfo& classInfo() const override { return kNURBPatchClass; }
    /// The triangles the context's subdivision gives (QD3DGeometry.h, NURB
    /// patch): normals and surface uv on every vertex, edges for the
    /// wireframe. Retained patches keep them until an edit or a change of
    /// the SubdivisionMeasure key. Throws kQ3ErrorInvalidData when the trim
    /// loops cross; posts kQ3WarningParameterOutOfRange (also when reusing)
    /// when the triangle cap made edges longer than asked.
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;
    /// The control points divided by w: the surface lies in their hull.
    void bound(const DecomposeContext& context, std::vector<glm::dvec3>& points) const override;

    TQ3RationalPoint4D controlPoint(unsigned long row, unsigned long column) const;
    void setControlPoint(unsigned long row, unsigned long column, const TQ3RationalPoint4D& point);
    float uKnot(unsigned long index) const;
    float vKnot(unsigned long index) const;
    void setUKnot(unsigned long index, float value);
    void setVKnot(unsigned long index, float value);

private:
    void setKnot(bool inU, unsigned long index, float value);

    /// The warning of the last build, posted again whenever its mesh is
    /// used (guarded by the mesh lock, like the mesh).
    mutable std::string m_warning;
};

// The data description (core/DataLayout.h).
namespace layout {
template <>
struct Describe<TQ3NURBPatchTrimCurveData> {
    static auto fields()
    {
        using D = TQ3NURBPatchTrimCurveData;
        return std::make_tuple(value("order", &D::order), value("numPoints", &D::numPoints),
                               array("controlPoints", &D::controlPoints, countOf(&D::numPoints)),
                               array("knots", &D::knots, countSum(&D::order, &D::numPoints)));
    }
};

template <>
struct Describe<TQ3NURBPatchTrimLoopData> {
    static auto fields()
    {
        using D = TQ3NURBPatchTrimLoopData;
        return std::make_tuple(value("numTrimCurves", &D::numTrimCurves),
                               array("trimCurves", &D::trimCurves, countOf(&D::numTrimCurves)));
    }
};

template <>
struct Describe<TQ3NURBPatchData> {
    static auto fields()
    {
        using D = TQ3NURBPatchData;
        return std::make_tuple(value("uOrder", &D::uOrder), value("vOrder", &D::vOrder),
                               value("numRows", &D::numRows), value("numColumns", &D::numColumns),
                               array("controlPoints", &D::controlPoints, countProduct(&D::numRows, &D::numColumns)),
                               array("uKnots", &D::uKnots, countSum(&D::uOrder, &D::numColumns)),
                               array("vKnots", &D::vKnots, countSum(&D::vOrder, &D::numRows)),
                               value("numTrimLoops", &D::numTrimLoops),
                               array("trimLoops", &D::trimLoops, countOf(&D::numTrimLoops)),
                               handle<AttributeSet>("patchAttributeSet", &D::patchAttributeSet));
    }
};
} // namespace layout

} // namespace q3
