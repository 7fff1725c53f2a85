// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "geometry/nurbs/Curve.h"
#include "geometry/nurbs/Knots.h"

#include <cstddef>
#include <string>
#include <utility>

// What the curve tools (Derivatives, KnotRefinement, DegreeElevation, Split,
// Fitting, ArcLength, ClosestPoint) return: a value, or the rule a caller's
// argument broke as one English sentence, the way validateCurve() reports a
// broken curve. The C layer turns each ToolError into one QuickDraw 3D error
// code; nothing here knows about error codes or the error manager.
namespace q3::nurbs {

/// The most control points a curve tool accepts or makes, and the most points it
/// fits: the numPoints limit of TQ3NURBCurveData (2^28), far from any overflow of
/// the size computations below.
constexpr std::size_t kMaxToolPoints = std::size_t(1) << 28;

/// Why a tool produced no value.
enum class ToolError {
    kNone,
    kNotFinite,        ///< a parameter, point, knot or tolerance is NaN or infinite
    kOutOfRange,       ///< a parameter outside the domain, a count or an order outside its limits
    kTooFewPoints,     ///< fewer points to fit than the order
    kInvalidArgument,  ///< any other unusable argument: tolerance <= 0, coincident points, ...
    kZeroDerivative,   ///< the first derivative vanishes, so there is no tangent direction
    kDegenerate,       ///< the result would not be a valid curve (see the message)
};

/// A tool's outcome. When error is kNone, value holds the result; warning is then
/// empty, or says why the value is only the best the tool's iteration cap allowed.
template <class T>
struct ToolResult {
    T value{};
    ToolError error = ToolError::kNone;
    std::string message;  ///< why there is no value; empty when ok()
    std::string warning;  ///< set on success when a cap was reached

    bool ok() const { return error == ToolError::kNone; }
};

template <class T>
ToolResult<T> toolFailure(ToolError error, std::string message)
{
    ToolResult<T> result;
    result.error = error;
    result.message = std::move(message);
    return result;
}

/// Carries another result's failure over to a result of type T.
template <class T, class U>
ToolResult<T> toolFailure(const ToolResult<U>& failed)
{
    return toolFailure<T>(failed.error, failed.message);
}

template <class T>
ToolResult<T> toolValue(T value)
{
    ToolResult<T> result;
    result.value = std::move(value);
    return result;
}

/// printf-style formatting for the messages (at most 511 characters).
std::string formatMessage(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

/// Checks a curve parameter: t must be finite and in [start, end] (or, with
/// openInterval, strictly between them). `what` names it in the message.
ToolResult<double> checkParameter(double t, const Domain& domain, bool openInterval, const char* what);

/// The domain [x_{k-1}, x_n] of a curve in double precision.
Domain domainOf(const HomogeneousCurve& curve);

/// Rounds every knot and control point value to the nearest float, in place.
void roundToFloat(HomogeneousCurve& curve);

} // namespace q3::nurbs
