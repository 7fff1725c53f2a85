// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/nurbs/ToolResult.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace q3::nurbs {

std::string formatMessage(const char* pattern, ...)
{
    char buffer[512];
    va_list args;
    va_start(args, pattern);
    std::vsnprintf(buffer, sizeof buffer, pattern, args);
    va_end(args);
    return buffer;
}

ToolResult<double> checkParameter(double t, const Domain& domain, bool openInterval, const char* what)
{
    if (!std::isfinite(t))
        return toolFailure<double>(ToolError::kNotFinite,
                                   formatMessage("%s is %g; it must be a finite number", what, t));
    const bool inside = openInterval ? (domain.start < t && t < domain.end)
                                     : (domain.start <= t && t <= domain.end);
    if (!inside)
        return toolFailure<double>(
            ToolError::kOutOfRange,
            formatMessage("%s = %.9g is outside the curve's domain %s%.9g, %.9g%s", what, t,
                          openInterval ? "(" : "[", domain.start, domain.end, openInterval ? ")" : "]"));
    return toolValue(t);
}

Domain domainOf(const HomogeneousCurve& curve)
{
    return Domain{curve.knots[curve.order - 1], curve.knots[curve.points.size()]};
}

void roundToFloat(HomogeneousCurve& curve)
{
    for (double& knot : curve.knots)
        knot = double(float(knot));
    for (Point4& p : curve.points)
        p = Point4{double(float(p.x)), double(float(p.y)), double(float(p.z)), double(float(p.w))};
}

} // namespace q3::nurbs
