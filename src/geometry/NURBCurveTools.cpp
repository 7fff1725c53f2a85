// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/NURBCurveTools.h"

#include "core/EnumValue.h"
#include "core/Error.h"
#include "core/ErrorManager.h"
#include "geometry/NURBCurve.h"
#include "geometry/nurbs/ArcLength.h"
#include "geometry/nurbs/ClosestPoint.h"
#include "geometry/nurbs/DegreeElevation.h"
#include "geometry/nurbs/Derivatives.h"
#include "geometry/nurbs/Evaluate.h"
#include "geometry/nurbs/Fitting.h"
#include "geometry/nurbs/KnotRefinement.h"
#include "geometry/nurbs/Knots.h"
#include "geometry/nurbs/Split.h"

#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>
#include <vector>

namespace q3::curvetools {
namespace {

static_assert(kQ3NURBCurveToolsMaxPoints == nurbs::kMaxToolPoints,
              "Q3NURBCurveTools.h documents the tools' point limit");
static_assert(kQ3NURBCurveToolsMaxBisections == nurbs::kMaxArcLengthBisections,
              "Q3NURBCurveTools.h documents the arc-length bisection limit");
static_assert(kQ3NURBCurveMaxOrder == nurbs::kMaxOrder, "QD3DGeometry.h documents the highest order");

TQ3Error errorCode(nurbs::ToolError error)
{
    switch (error) {
    case nurbs::ToolError::kOutOfRange:
        return kQ3ErrorParameterOutOfRange;
    case nurbs::ToolError::kTooFewPoints:
        return kQ3ErrorGeometryInsufficientNumberOfPoints;
    case nurbs::ToolError::kZeroDerivative:
        return kQ3ErrorVector3DZeroLength;
    case nurbs::ToolError::kDegenerate:
        return kQ3ErrorDegenerateGeometry;
    case nurbs::ToolError::kNotFinite:
    case nurbs::ToolError::kInvalidArgument:
    case nurbs::ToolError::kNone:
        break;
    }
    return kQ3ErrorInvalidParameter;
}

// The value of a tool's result: throws its failure, posts its warning.
template <class T>
T take(nurbs::ToolResult<T> result)
{
    if (!result.ok())
        fail(errorCode(result.error), result.message);
    if (!result.warning.empty())
        errors::postWarning(kQ3WarningParameterOutOfRange, result.warning);
    return std::move(result.value);
}

float toFloat(double value, const char* what)
{
    const float f = float(value);
    if (!std::isfinite(f))
        fail(kQ3ErrorDegenerateGeometry, std::string(what) + " is " + std::to_string(value) +
                                             ", too large for a float");
    return f;
}

TQ3Point3D toPoint(const nurbs::Point3& p, const char* what)
{
    return TQ3Point3D{toFloat(p.x, what), toFloat(p.y, what), toFloat(p.z, what)};
}

TQ3Vector3D toVector(const nurbs::Point3& p, const char* what)
{
    return TQ3Vector3D{toFloat(p.x, what), toFloat(p.y, what), toFloat(p.z, what)};
}

struct FreeDeleter {
    void operator()(void* p) const { std::free(p); }
};

template <class T>
std::unique_ptr<T, FreeDeleter> allocate(std::size_t count)
{
    T* p = static_cast<T*>(std::malloc(count * sizeof(T)));
    if (p == nullptr)
        throw std::bad_alloc();
    return std::unique_ptr<T, FreeDeleter>(p);
}

// The float curve the caller receives, checked against the TQ3NURBCurveData rules
// (float rounding could break one); owns its arrays until released.
class OwnedCurve {
public:
    explicit OwnedCurve(const nurbs::HomogeneousCurve& curve)
        : m_order(curve.order),
          m_count(curve.points.size()),
          m_points(allocate<TQ3RationalPoint4D>(curve.points.size())),
          m_knots(allocate<float>(curve.knots.size()))
    {
        for (std::size_t i = 0; i < m_count; ++i) {
            const nurbs::Point4& p = curve.points[i];
            m_points.get()[i] = TQ3RationalPoint4D{float(p.x), float(p.y), float(p.z), float(p.w)};
        }
        for (std::size_t i = 0; i < curve.knots.size(); ++i)
            m_knots.get()[i] = float(curve.knots[i]);
        const nurbs::CurveRef ref{m_order, m_count, reinterpret_cast<const float*>(m_points.get()), m_knots.get()};
        const nurbs::CurveValidation validation = nurbs::validateCurve(ref);
        if (!validation.ok())
            fail(kQ3ErrorDegenerateGeometry, "the resulting curve cannot be stored in float: " + validation.message);
    }

    /// Hands the arrays to C; the caller frees them with Q3NURBCurve_EmptyData.
    TQ3NURBCurveData release()
    {
        return TQ3NURBCurveData{m_order, m_count, m_points.release(), m_knots.release(), nullptr};
    }

private:
    unsigned m_order;
    std::size_t m_count;
    std::unique_ptr<TQ3RationalPoint4D, FreeDeleter> m_points;
    std::unique_ptr<float, FreeDeleter> m_knots;
};

TQ3NURBCurveData handOut(const nurbs::HomogeneousCurve& curve)
{
    return OwnedCurve(curve).release();
}

} // namespace

nurbs::CurveRef checkedCurve(const TQ3NURBCurveData* data)
{
    validateNURBCurveData(data);
    return curveRefOf(*data);
}

void getDomain(const nurbs::CurveRef& curve, float& start, float& end)
{
    start = curve.knots[curve.order - 1];
    end = curve.knots[curve.numPoints];
}

TQ3Point3D evaluate(const nurbs::CurveRef& curve, float t)
{
    return toPoint(take(nurbs::positionAt(curve, t)), "a coordinate of the point");
}

void evaluateDerivatives(const nurbs::CurveRef& curve, float t, TQ3Point3D& point, TQ3Vector3D& first,
                         TQ3Vector3D& second)
{
    const nurbs::CurveDerivatives d = take(nurbs::derivativesAt(curve, t));
    const TQ3Point3D p = toPoint(d.point, "a coordinate of the point");
    const TQ3Vector3D d1 = toVector(d.first, "a component of the first derivative");
    const TQ3Vector3D d2 = toVector(d.second, "a component of the second derivative");
    point = p;
    first = d1;
    second = d2;
}

TQ3Vector3D getTangent(const nurbs::CurveRef& curve, float t)
{
    return toVector(take(nurbs::tangentAt(curve, t)), "a component of the tangent");
}

float getCurvature(const nurbs::CurveRef& curve, float t)
{
    return toFloat(take(nurbs::curvatureAt(curve, t)), "the curvature");
}

TQ3NURBCurveData insertKnot(const nurbs::CurveRef& curve, float knot, unsigned long times)
{
    return handOut(take(nurbs::insertKnotTimes(nurbs::toHomogeneous(curve), knot, times)));
}

TQ3NURBCurveData refineKnots(const nurbs::CurveRef& curve, unsigned long numKnots, const float* knots)
{
    if (numKnots > nurbs::kMaxToolPoints - curve.numPoints)
        fail(kQ3ErrorParameterOutOfRange,
             "inserting " + std::to_string(numKnots) + " knots into a curve of " + std::to_string(curve.numPoints) +
                 " control points would exceed Q3's limit of " + std::to_string(nurbs::kMaxToolPoints));
    std::vector<double> values(knots, knots + numKnots);
    return handOut(take(nurbs::refineKnots(nurbs::toHomogeneous(curve), std::move(values))));
}

TQ3NURBCurveData removeKnot(const nurbs::CurveRef& curve, unsigned long knotIndex, unsigned long times,
                            float tolerance, unsigned long& numRemoved)
{
    const nurbs::KnotRemoval removal =
        take(nurbs::removeKnot(nurbs::toHomogeneous(curve), knotIndex, times, tolerance));
    const TQ3NURBCurveData result = handOut(removal.curve);
    numRemoved = removal.removed;
    return result;
}

TQ3NURBCurveData elevateDegree(const nurbs::CurveRef& curve, unsigned long times)
{
    return handOut(take(nurbs::elevateDegree(curve, times)));
}

unsigned long countBezierPieces(const nurbs::CurveRef& curve)
{
    return nurbs::countNonEmptySpans(curve);
}

TQ3NURBCurveData getBezierPiece(const nurbs::CurveRef& curve, unsigned long pieceIndex)
{
    return handOut(take(nurbs::bezierPiece(curve, pieceIndex)));
}

void split(const nurbs::CurveRef& curve, float t, TQ3NURBCurveData& left, TQ3NURBCurveData& right)
{
    if (&left == &right)
        fail(kQ3ErrorInvalidParameter, "left and right are the same structure; each half needs its own");
    const nurbs::SplitCurves halves = take(nurbs::splitAt(nurbs::toHomogeneous(curve), t));
    OwnedCurve first(halves.left);
    OwnedCurve second(halves.right);
    left = first.release();
    right = second.release();
}

float getArcLength(const nurbs::CurveRef& curve, float t0, float t1, float tolerance)
{
    return toFloat(take(nurbs::arcLength(curve, t0, t1, tolerance)), "the length");
}

float getParameterAtLength(const nurbs::CurveRef& curve, float t0, float length, float tolerance)
{
    return float(take(nurbs::parameterAtLength(curve, t0, length, tolerance)));
}

void getClosestPoint(const nurbs::CurveRef& curve, const TQ3Point3D& point, float& t, TQ3Point3D& closest)
{
    const nurbs::ClosestPoint found = take(nurbs::closestPoint(curve, nurbs::Point3{point.x, point.y, point.z}));
    // The point handed out is the curve's at the float parameter handed out.
    const float parameter = float(found.t);
    const TQ3Point3D at = toPoint(nurbs::evaluate(curve, parameter).point, "a coordinate of the point");
    t = parameter;
    closest = at;
}

TQ3NURBCurveData approximate(unsigned long order, unsigned long numPoints, const TQ3Point3D* points,
                             unsigned long numControlPoints, const TQ3NURBCurveParameterization& parameterization)
{
    take(nurbs::checkFitSizes(order, numPoints, numControlPoints));
    const long how = enumValue(parameterization);
    if (how != kQ3NURBCurveParameterizationChordLength && how != kQ3NURBCurveParameterizationCentripetal)
        fail(kQ3ErrorInvalidParameter, "parameterization " + std::to_string(how) +
                                           " is neither kQ3NURBCurveParameterizationChordLength (0) nor "
                                           "kQ3NURBCurveParameterizationCentripetal (1)");
    const nurbs::Parameterization rule = how == kQ3NURBCurveParameterizationCentripetal
                                             ? nurbs::Parameterization::kCentripetal
                                             : nurbs::Parameterization::kChordLength;
    static_assert(sizeof(TQ3Point3D) == 3 * sizeof(float), "TQ3Point3D is three packed floats");
    return handOut(take(nurbs::fitPoints(unsigned(order), reinterpret_cast<const float*>(points), numPoints,
                                         numControlPoints, rule)));
}

} // namespace q3::curvetools
