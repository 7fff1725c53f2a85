// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Bezier pieces and splitting, both by knot insertion.
//
// A piece is the article's NURB-to-Bezier conversion ("CONVERTING NURB TO BEZIER
// CURVES") restricted to one span: spanToBezier (Bezier.cpp) inserts both span ends
// until each occurs order - 1 times and returns the k control points that then govern
// the span. Splitting inserts the cut parameter order - 1 times (refine,
// KnotRefinement.cpp); the control point made by the last insertion is the curve's
// point there and is shared by both halves.

#include "geometry/nurbs/Split.h"

#include "geometry/nurbs/Bezier.h"
#include "geometry/nurbs/KnotRefinement.h"
#include "geometry/nurbs/Knots.h"

#include <algorithm>

namespace q3::nurbs {

ToolResult<HomogeneousCurve> bezierPiece(const CurveRef& curve, std::size_t index)
{
    std::size_t seen = 0;
    for (std::size_t l = curve.order - 1; l < curve.numPoints; ++l) {
        const double a = curve.knots[l];
        const double b = curve.knots[l + 1];
        if (!(a < b))
            continue;
        if (seen++ != index)
            continue;
        HomogeneousCurve piece;
        piece.order = curve.order;
        piece.points.resize(curve.order);
        spanToBezier(curve, l, piece.points.data());
        piece.knots.assign(curve.order, a);
        piece.knots.resize(2 * std::size_t(curve.order), b);
        return toolValue(std::move(piece));
    }
    return toolFailure<HomogeneousCurve>(
        ToolError::kOutOfRange,
        formatMessage("piece index %zu is past the last piece; the curve has %zu Bezier pieces", index, seen));
}

ToolResult<SplitCurves> splitAt(const HomogeneousCurve& curve, double t)
{
    const ToolResult<double> checked = checkParameter(t, domainOf(curve), true, "t");
    if (!checked.ok())
        return toolFailure<SplitCurves>(checked);
    const std::size_t p = curve.order - 1;
    const auto run = std::equal_range(curve.knots.begin(), curve.knots.end(), t);
    const std::size_t existing = std::size_t(run.second - run.first);
    const HomogeneousCurve cut = refine(curve, std::vector<double>(p - existing, t));

    // The p copies of t sit at first .. first + p - 1; control point first - 1 is C(t).
    const std::size_t first = std::size_t(std::lower_bound(cut.knots.begin(), cut.knots.end(), t) - cut.knots.begin());
    const std::size_t shared = first - 1;
    SplitCurves result;
    result.left.order = curve.order;
    result.left.points.assign(cut.points.begin(), cut.points.begin() + std::ptrdiff_t(shared + 1));
    result.left.knots.assign(cut.knots.begin(), cut.knots.begin() + std::ptrdiff_t(first + p));
    result.left.knots.push_back(t);
    result.right.order = curve.order;
    result.right.points.assign(cut.points.begin() + std::ptrdiff_t(shared), cut.points.end());
    result.right.knots.push_back(t);
    result.right.knots.insert(result.right.knots.end(), cut.knots.begin() + std::ptrdiff_t(first), cut.knots.end());
    return toolValue(std::move(result));
}

} // namespace q3::nurbs
