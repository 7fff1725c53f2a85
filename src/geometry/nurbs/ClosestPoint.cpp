// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Point inversion: the parameter of the curve point nearest to a given point.
//
// The squared distance f(t) = |C(t) - P|^2 may have several local minima, as close
// together as the curve likes, so neither one Newton iteration on f'(t) = 0 (Piegl &
// Tiller, section 6.1) nor any fixed sampling is sure to find the global one. A
// branch-and-bound search over Bezier pieces is: every non-empty knot span is
// converted to rational Bezier form (the article's "CONVERTING NURB TO BEZIER
// CURVES"), and with positive weights each piece lies inside the convex hull of its
// projected control points, hence within r of its chord, r being the largest
// distance of a control point from the chord. dist(P, chord) - r is then a lower
// bound for the distance from P to the piece that is within O(h^2) of the truth for
// a piece of width h. Pieces whose bound cannot beat the best distance found by more
// than the tolerance are dropped; the others get a safeguarded Newton iteration on
// f'(t) = 0 (a Newton step taken only inside the bracket the sign of f' keeps, and
// only while f decreases, bisection otherwise) and are split in half by de
// Casteljau's algorithm. Span ends are evaluated as candidates of their own, so a
// minimum at a corner (a knot where the curve is only C0) is seen directly.

#include "geometry/nurbs/ClosestPoint.h"

#include "geometry/nurbs/Bezier.h"
#include "geometry/nurbs/CurveAccess.h"
#include "geometry/nurbs/Derivatives.h"
#include "geometry/nurbs/Evaluate.h"
#include "geometry/nurbs/Knots.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace q3::nurbs {
namespace {

// Enough for Newton's quadratic convergence to an interior minimum; bisection towards
// a minimum at the piece's end (a candidate already) stops at 2^-30 of the piece.
constexpr int kMaxNewtonSteps = 30;

struct Candidate {
    double t = 0.0;
    double f = INFINITY; // squared distance
};

/// A piece of a span in Bezier form: the parameters [a, b] of the curve it covers.
struct Piece {
    double a = 0.0;
    double b = 0.0;
    std::array<Point4, kMaxOrder> points;
};

// Distance from q to the segment [p0, p1], and the fraction along it of the nearest point.
double segmentDistance(const Point3& q, const Point3& p0, const Point3& p1, double* fraction)
{
    const Point3 d = access::sub3(p1, p0);
    const double dd = access::dot3(d, d);
    double s = dd > 0.0 ? access::dot3(access::sub3(q, p0), d) / dd : 0.0;
    s = std::clamp(s, 0.0, 1.0);
    if (fraction)
        *fraction = s;
    const Point3 foot{p0.x + s * d.x, p0.y + s * d.y, p0.z + s * d.z};
    return access::length3(access::sub3(q, foot));
}

class Search {
public:
    Search(const CurveRef& curve, const Point3& target) : m_curve(curve), m_target(target) {}

    Candidate sample(double t) const
    {
        const Point3 d = access::sub3(evaluate(m_curve, t).point, m_target);
        return Candidate{t, access::dot3(d, d)};
    }

    void consider(const Candidate& c)
    {
        if (c.f < m_best.f || (c.f == m_best.f && c.t < m_best.t))
            m_best = c;
    }

    // Safeguarded Newton iteration for f'(t) = 0 on [lo, hi] from t: g = (C - P).C'
    // is f'/2, g' = C'.C' + (C - P).C''. The bracket shrinks by the sign of g (the
    // minimum lies downhill); a step that leaves it, meets g' <= 0, or does not lower
    // f is replaced by bisection.
    void newton(double lo, double hi, double t)
    {
        Candidate current = sample(t);
        consider(current);
        for (int step = 0; step < kMaxNewtonSteps; ++step) {
            const CurveDerivatives d = evaluateDerivatives(m_curve, current.t);
            const Point3 r = access::sub3(d.point, m_target);
            const double g = access::dot3(r, d.first);
            const double gPrime = access::dot3(d.first, d.first) + access::dot3(r, d.second);
            if (g > 0.0)
                hi = current.t;
            else if (g < 0.0)
                lo = current.t;
            else
                break;
            double next = current.t - g / gPrime;
            const bool newtonOk = gPrime > 0.0 && next > lo && next < hi;
            if (!newtonOk)
                next = 0.5 * (lo + hi);
            Candidate trial = sample(next);
            if (newtonOk && trial.f > current.f) {
                next = 0.5 * (lo + hi);
                trial = sample(next);
            }
            consider(trial);
            const double width = std::max(std::fabs(lo), std::fabs(hi)) * 4e-16;
            if (std::fabs(trial.t - current.t) <= width || hi - lo <= width)
                break;
            current = trial;
        }
    }

    const Candidate& best() const { return m_best; }

private:
    CurveRef m_curve;
    Point3 m_target;
    Candidate m_best;
};

// The size the tolerance is relative to: the diagonal of the bounding box of the
// projected control points (which holds the curve).
double controlBoxDiagonal(const CurveRef& curve)
{
    Point3 lo{INFINITY, INFINITY, INFINITY};
    Point3 hi{-INFINITY, -INFINITY, -INFINITY};
    for (std::size_t i = 0; i < curve.numPoints; ++i) {
        const Point3 p = project(access::point(curve, i));
        lo = Point3{std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = Point3{std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    return access::length3(access::sub3(hi, lo));
}

// Splits a Bezier piece at its middle parameter (de Casteljau in homogeneous form).
void splitPiece(const Piece& piece, unsigned order, Piece& left, Piece& right)
{
    std::array<Point4, kMaxOrder> work = piece.points;
    const double mid = 0.5 * (piece.a + piece.b);
    left.a = piece.a;
    left.b = mid;
    right.a = mid;
    right.b = piece.b;
    for (unsigned level = 0; level < order; ++level) {
        left.points[level] = work[0];
        right.points[order - 1 - level] = work[order - 1 - level];
        for (unsigned i = 0; i + 1 < order - level; ++i)
            work[i] = access::scale(access::add(work[i], work[i + 1]), 0.5);
    }
}

} // namespace

ToolResult<ClosestPoint> closestPoint(const CurveRef& curve, const Point3& target)
{
    if (!std::isfinite(target.x) || !std::isfinite(target.y) || !std::isfinite(target.z))
        return toolFailure<ClosestPoint>(
            ToolError::kNotFinite,
            formatMessage("the point (%g, %g, %g) has a coordinate that is not finite", target.x, target.y,
                          target.z));
    Search search(curve, target);
    const unsigned k = curve.order;
    const double tolerance = kClosestPointTolerance * controlBoxDiagonal(curve);

    // Every span end first: they are the corners, the domain's ends, and a first
    // upper bound for the pruning.
    std::vector<Piece> stack;
    for (std::size_t l = k - 1; l < curve.numPoints; ++l) {
        const double a = curve.knots[l];
        const double b = curve.knots[l + 1];
        if (!(a < b))
            continue;
        search.consider(search.sample(a));
        search.consider(search.sample(b));
        Piece piece;
        piece.a = a;
        piece.b = b;
        spanToBezier(curve, l, piece.points.data());
        stack.push_back(piece);
    }

    std::size_t splitsLeft = kMaxClosestPointSplits;
    while (!stack.empty()) {
        const Piece piece = stack.back();
        stack.pop_back();
        const Point3 first = project(piece.points[0]);
        const Point3 last = project(piece.points[k - 1]);
        double deviation = 0.0;
        for (unsigned i = 1; i + 1 < k; ++i)
            deviation = std::max(deviation, segmentDistance(project(piece.points[i]), first, last, nullptr));
        double fraction = 0.0;
        const double chordDistance = segmentDistance(target, first, last, &fraction);
        // A piece's end control points are its curve points at a and b: free candidates.
        search.consider(Candidate{piece.a, access::dot3(access::sub3(first, target), access::sub3(first, target))});
        search.consider(Candidate{piece.b, access::dot3(access::sub3(last, target), access::sub3(last, target))});
        const double bound = chordDistance - deviation;
        const double best = std::sqrt(search.best().f);
        if (bound >= best - tolerance)
            continue;
        // Where the chord's nearest point is an end, so probably is the piece's (a
        // candidate already); otherwise Newton starts from the chord's nearest point,
        // strictly inside, where the derivatives are this piece's own.
        // A piece holding the best point so far was refined by its parent's iteration.
        const bool refined = piece.a < search.best().t && search.best().t < piece.b;
        if (0.0 < fraction && fraction < 1.0 && !refined)
            search.newton(piece.a, piece.b, piece.a + std::clamp(fraction, 1e-3, 1.0 - 1e-3) * (piece.b - piece.a));
        if (std::sqrt(search.best().f) - bound <= tolerance || splitsLeft == 0 ||
            !(piece.a < 0.5 * (piece.a + piece.b) && 0.5 * (piece.a + piece.b) < piece.b))
            continue;
        --splitsLeft;
        Piece left, right;
        splitPiece(piece, k, left, right);
        // The half nearer the target is searched first, to lower the bound sooner.
        if (fraction < 0.5) {
            stack.push_back(right);
            stack.push_back(left);
        } else {
            stack.push_back(left);
            stack.push_back(right);
        }
    }
    // Newton and bisection may end a rounding error inside a span whose end is the
    // nearest point; the end itself is then returned.
    Candidate best = search.best();
    const std::size_t span = findSpan(curve, best.t);
    for (const double end : {double(curve.knots[span]), double(curve.knots[span + 1])}) {
        const double width = curve.knots[span + 1] - curve.knots[span];
        if (std::fabs(best.t - end) <= 1e-12 * width) {
            const Candidate atEnd = search.sample(end);
            if (atEnd.f <= best.f * (1.0 + 1e-14))
                best = atEnd;
        }
    }
    const CurvePoint at = evaluate(curve, best.t);
    return toolValue(ClosestPoint{best.t, at.point, access::length3(access::sub3(at.point, target))});
}

} // namespace q3::nurbs
