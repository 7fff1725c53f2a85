// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "core/Limits.h"

#include <cstddef>
#include <vector>

// Plain value types shared by the NURBS math in this directory. Nothing here
// knows about handles, attribute sets or the error manager.
namespace q3::nurbs {

/// Smallest and largest curve order QuickDraw 3D accepts ("NURB CURVES IN QUICKDRAW 3D").
constexpr unsigned kMinOrder = limits::kMinCurveOrder;
constexpr unsigned kMaxOrder = limits::kMaxCurveOrder;

struct Point3 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
};

/// A homogeneous point: the 3D point it stands for is (x/w, y/w, z/w).
struct Point4 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
    double w = 0.0;
};

/// Divides a homogeneous point through by its w.
inline Point3 project(const Point4& p)
{
    return Point3{p.x / p.w, p.y / p.w, p.z / p.w};
}

/// A non-owning view of a curve in QuickDraw 3D's layout (TQ3NURBCurveData without
/// the attribute set), so callers pass their arrays without copying.
/// Fields are public and unprefixed because this is an aggregate mirroring the C struct.
/// Functions taking a CurveRef require validateCurve(curve).ok() unless their comment
/// says they check it. Ownership: the caller keeps the arrays alive during the call.
struct CurveRef {
    unsigned order = 0;          ///< k, 2..16
    std::size_t numPoints = 0;   ///< n >= k
    const float* points = nullptr; ///< 4 * n floats: x, y, z, w per point (TQ3RationalPoint4D, homogeneous)
    const float* knots = nullptr;  ///< n + k floats, nondecreasing
};

/// An owning curve in double precision, the result of knot insertion.
/// Invariant: knots.size() == points.size() + order once built by this library.
struct HomogeneousCurve {
    unsigned order = 0;
    std::vector<double> knots;
    std::vector<Point4> points;
};

/// Copies a curve into double precision without changing it.
HomogeneousCurve toHomogeneous(const CurveRef& curve);

} // namespace q3::nurbs
