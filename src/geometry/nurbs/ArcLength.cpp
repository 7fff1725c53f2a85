// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Arc length by adaptive quadrature of the speed, and its inverse.
//
// The length of C over [a, b] is the integral of |C'(t)|. Inside a knot span C is a
// rational function and the speed is smooth wherever C' does not vanish, so each
// span is integrated on its own with Gauss-Legendre quadrature (8 points, exact for
// polynomials of degree 15; nodes and weights computed once by Newton's method on
// the Legendre polynomial, P_8(x) = 0, w = 2 / ((1 - x^2) P_8'(x)^2)). The error of
// an interval's estimate is taken as the difference between it and the sum of the
// estimates over its halves; the halves' sum is kept once that difference is within
// the interval's share of the tolerance (in proportion to its width), otherwise the
// interval waits to be bisected, the worst first (globally adaptive quadrature, as
// in QUADPACK). Bisections are counted against kMaxArcLengthBisections, so every
// call ends.

#include "geometry/nurbs/ArcLength.h"

#include "geometry/nurbs/CurveAccess.h"
#include "geometry/nurbs/Evaluate.h"
#include "geometry/nurbs/Knots.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace q3::nurbs {
namespace {

constexpr int kGaussPoints = 8;
constexpr int kMaxNewtonSteps = 100;

struct GaussRule {
    double node[kGaussPoints];
    double weight[kGaussPoints];
};

GaussRule makeGaussRule()
{
    GaussRule rule{};
    const double pi = std::acos(-1.0);
    const int n = kGaussPoints;
    for (int i = 0; i < n; ++i) {
        double x = std::cos(pi * (i + 0.75) / (n + 0.5));
        double derivative = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double previous = 1.0;
            double current = x;
            for (int j = 2; j <= n; ++j) {
                const double next = ((2 * j - 1) * x * current - (j - 1) * previous) / j;
                previous = current;
                current = next;
            }
            derivative = n * (x * current - previous) / (x * x - 1.0);
            const double step = current / derivative;
            x -= step;
            if (std::fabs(step) < 1e-16)
                break;
        }
        rule.node[i] = x;
        rule.weight[i] = 2.0 / ((1.0 - x * x) * derivative * derivative);
    }
    return rule;
}

const GaussRule& gaussRule()
{
    static const GaussRule rule = makeGaussRule();
    return rule;
}

double speed(const CurveRef& curve, double t)
{
    return access::length3(evaluateWithDerivative(curve, t).tangent);
}

// Adaptive integration of the speed with one bisection budget for a whole call.
// Intervals that miss their share of the tolerance wait in a heap, the one with the
// largest error estimate bisected first, so that a budget that runs out has been
// spent where the error was.
class LengthIntegrator {
public:
    explicit LengthIntegrator(const CurveRef& curve) : m_curve(curve) {}

    // The length over the intervals [a, b] that forEachPart(visit) passes to
    // visit(a, b) (each inside one span), to within errorPerUnit per unit of t.
    template <class Parts>
    double integrate(Parts forEachPart, double errorPerUnit)
    {
        std::vector<Piece> waiting;
        const auto byError = [](const Piece& x, const Piece& y) { return x.difference < y.difference; };
        double sum = 0.0;
        const auto consider = [&](const Piece& piece) {
            if (piece.difference <= errorPerUnit * (piece.b - piece.a)) {
                sum += piece.left + piece.right;
                return;
            }
            waiting.push_back(piece);
            std::push_heap(waiting.begin(), waiting.end(), byError);
        };
        forEachPart([&](double a, double b) { consider(measure(a, b, gauss(a, b))); });
        while (!waiting.empty()) {
            std::pop_heap(waiting.begin(), waiting.end(), byError);
            const Piece piece = waiting.back();
            waiting.pop_back();
            const double mid = 0.5 * (piece.a + piece.b);
            if (m_bisectionsLeft == 0 || !(piece.a < mid && mid < piece.b)) {
                sum += piece.left + piece.right;
                m_unconverged += piece.difference;
                continue;
            }
            --m_bisectionsLeft;
            consider(measure(piece.a, mid, piece.left));
            consider(measure(mid, piece.b, piece.right));
        }
        return sum;
    }

    double integrate(double a, double b, double errorPerUnit)
    {
        return integrate([a, b](auto visit) { visit(a, b); }, errorPerUnit);
    }

    // The error estimate of the intervals accepted without meeting their share.
    double unconverged() const { return m_unconverged; }

private:
    // An interval, its halves' estimates and how far their sum is from the whole's.
    struct Piece {
        double a, b, left, right, difference;
    };

    Piece measure(double a, double b, double whole) const
    {
        const double mid = 0.5 * (a + b);
        const double left = gauss(a, mid);
        const double right = gauss(mid, b);
        return Piece{a, b, left, right, std::fabs(left + right - whole)};
    }

    double gauss(double a, double b) const
    {
        const GaussRule& rule = gaussRule();
        const double half = 0.5 * (b - a);
        const double mid = 0.5 * (a + b);
        double sum = 0.0;
        for (int i = 0; i < kGaussPoints; ++i)
            sum += rule.weight[i] * speed(m_curve, mid + half * rule.node[i]);
        return half * sum;
    }

    CurveRef m_curve;
    std::size_t m_bisectionsLeft = kMaxArcLengthBisections;
    double m_unconverged = 0.0;
};

ToolResult<double> checkTolerance(double tolerance)
{
    if (!std::isfinite(tolerance))
        return toolFailure<double>(ToolError::kNotFinite,
                                   formatMessage("the tolerance is %g; it must be a finite number", tolerance));
    if (!(tolerance > 0.0))
        return toolFailure<double>(ToolError::kInvalidArgument,
                                   formatMessage("the tolerance is %g; it must be greater than 0", tolerance));
    return toolValue(tolerance);
}

std::string capWarning(double estimate, double tolerance)
{
    return formatMessage("the tolerance %g was not reached within Q3's limit of %zu interval bisections; the "
                         "length's error is estimated at %g",
                         tolerance, kMaxArcLengthBisections, estimate);
}

// Calls f(a, b) for each non-empty part of a knot span inside [t0, t1], in order.
template <class F>
void forEachSpanPart(const CurveRef& curve, double t0, double t1, F f)
{
    for (std::size_t l = curve.order - 1; l < curve.numPoints; ++l) {
        const double a = std::max(double(curve.knots[l]), t0);
        const double b = std::min(double(curve.knots[l + 1]), t1);
        if (a < b && !f(a, b))
            return;
    }
}

} // namespace

ToolResult<double> arcLength(const CurveRef& curve, double t0, double t1, double tolerance)
{
    const Domain domain = curveDomain(curve);
    const ToolResult<double> checks[] = {checkParameter(t0, domain, false, "t0"),
                                         checkParameter(t1, domain, false, "t1"), checkTolerance(tolerance)};
    // The header's order: t0 or t1 not finite, then t0 or t1 outside the domain,
    // then the tolerance.
    for (const auto& checked : checks)
        if (checked.error == ToolError::kNotFinite && &checked != &checks[2])
            return checked;
    for (const auto& checked : checks)
        if (!checked.ok())
            return checked;
    if (t0 > t1)
        return toolFailure<double>(ToolError::kInvalidArgument,
                                   formatMessage("t0 = %.9g is greater than t1 = %.9g", t0, t1));
    if (t0 == t1)
        return toolValue(0.0);
    LengthIntegrator integrator(curve);
    const double length = integrator.integrate(
        [&](auto visit) {
            forEachSpanPart(curve, t0, t1, [&](double a, double b) {
                visit(a, b);
                return true;
            });
        },
        tolerance / (t1 - t0));
    ToolResult<double> result = toolValue(length);
    if (integrator.unconverged() > 0.0)
        result.warning = capWarning(integrator.unconverged(), tolerance);
    return result;
}

ToolResult<double> parameterAtLength(const CurveRef& curve, double t0, double length, double tolerance)
{
    const Domain domain = curveDomain(curve);
    for (const auto& checked : {checkParameter(t0, domain, false, "t0"), checkTolerance(tolerance)})
        if (!checked.ok())
            return checked;
    if (!std::isfinite(length))
        return toolFailure<double>(ToolError::kNotFinite,
                                   formatMessage("the length is %g; it must be a finite number", length));
    if (length < 0.0)
        return toolFailure<double>(ToolError::kOutOfRange,
                                   formatMessage("the length is %g; it must not be negative", length));
    if (length == 0.0 || t0 == domain.end)
        return length <= tolerance ? toolValue(t0)
                                   : toolFailure<double>(ToolError::kOutOfRange,
                                                         formatMessage("the length %g is more than the curve's "
                                                                       "length from t0 = %.9g to its end, 0",
                                                                       length, t0));

    // A quarter of the tolerance for the spans before the target, a quarter for the
    // part of the target span, a half for the root.
    LengthIntegrator integrator(curve);
    const double perUnit = 0.25 * tolerance / (domain.end - t0);
    double before = 0.0;
    double spanStart = domain.end;
    double spanEnd = domain.end;
    double spanLength = 0.0;
    bool found = false;
    forEachSpanPart(curve, t0, domain.end, [&](double a, double b) {
        const double part = integrator.integrate(a, b, perUnit);
        if (before + part >= length) {
            spanStart = a;
            spanEnd = b;
            spanLength = part;
            found = true;
            return false;
        }
        before += part;
        return true;
    });
    ToolResult<double> result;
    if (!found) {
        if (length > before + tolerance)
            return toolFailure<double>(ToolError::kOutOfRange,
                                       formatMessage("the length %.9g is more than the curve's length from t0 = "
                                                     "%.9g to its end, %.9g",
                                                     length, t0, before));
        result = toolValue(domain.end);
    } else {
        const double wanted = length - before;
        const double partPerUnit = 0.25 * tolerance / (spanEnd - spanStart);
        double lo = spanStart;
        double hi = spanEnd;
        double t = std::min(spanEnd, spanStart + (spanEnd - spanStart) * (wanted / spanLength));
        bool converged = false;
        for (int step = 0; step < kMaxNewtonSteps && !converged; ++step) {
            const double excess = integrator.integrate(spanStart, t, partPerUnit) - wanted;
            if (std::fabs(excess) <= 0.5 * tolerance) {
                converged = true;
                break;
            }
            (excess > 0.0 ? hi : lo) = t;
            if (!(lo < hi) || hi - lo <= 4.0 * 2.2e-16 * std::max(std::fabs(lo), std::fabs(hi))) {
                converged = true;  // no double between lo and hi: as close as t can get
                break;
            }
            const double v = speed(curve, t);
            const double newton = v > 0.0 ? t - excess / v : NAN;
            t = (newton > lo && newton < hi) ? newton : 0.5 * (lo + hi);
        }
        result = toolValue(t);
        if (!converged)
            result.warning = formatMessage("the parameter at length %g was not found to within %g in %d steps",
                                           length, tolerance, kMaxNewtonSteps);
    }
    if (result.warning.empty() && integrator.unconverged() > 0.0)
        result.warning = capWarning(integrator.unconverged(), tolerance);
    return result;
}

} // namespace q3::nurbs
