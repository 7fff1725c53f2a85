// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Curve.h"

#include <cmath>
#include <cstddef>

// Uniform read access to the two curve forms (the caller's float arrays behind a
// CurveRef, and the library's double HomogeneousCurve), so that an algorithm
// written once as a template reads either without copying; and the few point
// operations the curve tools share.
namespace q3::nurbs::access {

inline unsigned order(const CurveRef& c) { return c.order; }
inline unsigned order(const HomogeneousCurve& c) { return c.order; }

inline std::size_t count(const CurveRef& c) { return c.numPoints; }
inline std::size_t count(const HomogeneousCurve& c) { return c.points.size(); }

inline double knot(const CurveRef& c, std::size_t i) { return double(c.knots[i]); }
inline double knot(const HomogeneousCurve& c, std::size_t i) { return c.knots[i]; }

inline Point4 point(const CurveRef& c, std::size_t i)
{
    const float* p = c.points + 4 * i;
    return Point4{p[0], p[1], p[2], p[3]};
}
inline Point4 point(const HomogeneousCurve& c, std::size_t i) { return c.points[i]; }

inline Point4 add(const Point4& a, const Point4& b) { return Point4{a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w}; }
inline Point4 sub(const Point4& a, const Point4& b) { return Point4{a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w}; }
inline Point4 scale(const Point4& a, double s) { return Point4{s * a.x, s * a.y, s * a.z, s * a.w}; }

/// (1 - alpha) a + alpha b, written so that alpha = 0 and alpha = 1 give a and b exactly.
inline Point4 lerp(const Point4& a, const Point4& b, double alpha)
{
    const double beta = 1.0 - alpha;
    return Point4{beta * a.x + alpha * b.x, beta * a.y + alpha * b.y, beta * a.z + alpha * b.z,
                  beta * a.w + alpha * b.w};
}

/// Euclidean distance of two homogeneous points in four dimensions.
inline double distance4(const Point4& a, const Point4& b)
{
    const Point4 d = sub(a, b);
    return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z + d.w * d.w);
}

inline Point3 sub3(const Point3& a, const Point3& b) { return Point3{a.x - b.x, a.y - b.y, a.z - b.z}; }
inline double dot3(const Point3& a, const Point3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Point3 cross3(const Point3& a, const Point3& b)
{
    return Point3{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length3(const Point3& a) { return std::sqrt(dot3(a, a)); }

} // namespace q3::nurbs::access
