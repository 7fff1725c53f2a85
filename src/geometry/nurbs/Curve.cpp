// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/nurbs/Curve.h"

namespace q3::nurbs {

HomogeneousCurve toHomogeneous(const CurveRef& curve)
{
    HomogeneousCurve result;
    result.order = curve.order;
    result.knots.assign(curve.knots, curve.knots + curve.numPoints + curve.order);
    result.points.resize(curve.numPoints);
    for (std::size_t i = 0; i < curve.numPoints; ++i) {
        const float* p = curve.points + 4 * i;
        result.points[i] = Point4{p[0], p[1], p[2], p[3]};
    }
    return result;
}

} // namespace q3::nurbs
