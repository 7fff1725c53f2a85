// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Point inversion: the parameter of the curve point nearest to a given point.
//
// The squared distance f(t) = |C(t) - P|^2 may have several local minima (one per
// turn of the curve towards P), so a single Newton iteration on f'(t) = 0 (Piegl &
// Tiller, section 6.1) can end in the wrong one. Sampling first finds them: within a
// span C is rational of low degree and a sampling of 4k intervals separates its
// minima in all but contrived cases; each sample that is a local minimum of the
// samples brackets a minimum of f between its neighbours, where golden-section
// search (Kiefer 1953) narrows it down without derivatives, so it cannot diverge at a
// cusp or where f is flat.

#include "geometry/nurbs/ClosestPoint.h"

#include "geometry/nurbs/CurveAccess.h"
#include "geometry/nurbs/Evaluate.h"
#include "geometry/nurbs/Knots.h"

#include <algorithm>
#include <cmath>

namespace q3::nurbs {
namespace {

constexpr int kMaxGoldenSteps = 100;

struct Sample {
    double t = 0.0;
    double f = 0.0;  // squared distance
};

class Search {
public:
    Search(const CurveRef& curve, const Point3& target) : m_curve(curve), m_target(target) {}

    Sample sample(double t) const
    {
        const Point3 d = access::sub3(evaluate(m_curve, t).point, m_target);
        return Sample{t, access::dot3(d, d)};
    }

    // Golden-section search for a minimum of f on [lo, hi] around `middle`; returns
    // the best point seen (middle itself if nothing beats it).
    Sample refine(double lo, double hi, const Sample& middle) const
    {
        constexpr double kInverseGolden = 0.6180339887498949;
        Sample best = middle;
        Sample c = sample(hi - kInverseGolden * (hi - lo));
        Sample d = sample(lo + kInverseGolden * (hi - lo));
        for (int step = 0; step < kMaxGoldenSteps; ++step) {
            best = better(best, better(c, d));
            if (!(c.t < d.t) || hi - lo <= 4e-16 * std::max(std::fabs(lo), std::fabs(hi)))
                break;
            if (c.f < d.f) {
                hi = d.t;
                d = c;
                c = sample(hi - kInverseGolden * (hi - lo));
            } else {
                lo = c.t;
                c = d;
                d = sample(lo + kInverseGolden * (hi - lo));
            }
        }
        return better(best, better(c, d));
    }

    static Sample better(const Sample& a, const Sample& b) { return b.f < a.f ? b : a; }

private:
    CurveRef m_curve;
    Point3 m_target;
};

} // namespace

ToolResult<ClosestPoint> closestPoint(const CurveRef& curve, const Point3& target)
{
    if (!std::isfinite(target.x) || !std::isfinite(target.y) || !std::isfinite(target.z))
        return toolFailure<ClosestPoint>(
            ToolError::kNotFinite,
            formatMessage("the point (%g, %g, %g) has a coordinate that is not finite", target.x, target.y,
                          target.z));
    const Search search(curve, target);
    const unsigned perSpan = 4 * curve.order;
    const Domain domain = curveDomain(curve);

    // A sliding window of three samples over the whole domain, in increasing t.
    Sample before{};
    Sample current = search.sample(domain.start);
    bool haveBefore = false;
    Sample best = current;
    const auto visit = [&](const Sample& next, bool last) {
        const bool lowerThanBefore = !haveBefore || current.f <= before.f;
        if (lowerThanBefore && current.f <= next.f)
            best = Search::better(best, search.refine(haveBefore ? before.t : current.t, next.t, current));
        before = current;
        haveBefore = true;
        current = next;
        if (last && current.f <= before.f)
            best = Search::better(best, search.refine(before.t, current.t, current));
    };
    std::size_t lastSpan = curve.order - 1;
    for (std::size_t l = curve.order - 1; l < curve.numPoints; ++l)
        if (curve.knots[l] < curve.knots[l + 1])
            lastSpan = l;
    for (std::size_t l = curve.order - 1; l <= lastSpan; ++l) {
        const double a = curve.knots[l];
        const double b = curve.knots[l + 1];
        if (!(a < b))
            continue;
        for (unsigned i = 1; i <= perSpan; ++i) {
            const double t = i == perSpan ? b : a + (b - a) * double(i) / double(perSpan);
            visit(search.sample(t), l == lastSpan && i == perSpan);
        }
    }
    const CurvePoint at = evaluate(curve, best.t);
    return toolValue(ClosestPoint{best.t, at.point, std::sqrt(best.f)});
}

} // namespace q3::nurbs
