// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "Q3NURBCurveTools.h"
#include "geometry/nurbs/Curve.h"

// The C-facing core of Q3NURBCurveTools.h: each function is the body of the C
// call of the same name, for both its data and its object form (the caller has
// turned either into a nurbs::CurveRef: checkedCurve for data, NURBCurve::curve()
// for a retained curve). They check the call's own arguments through the pure
// tools in geometry/nurbs and turn a tool's failure into a q3::Error, its warning
// into a posted warning, and its double-precision result into the caller's float
// structures. Curves are returned in TQ3NURBCurveData whose arrays are malloc'ed
// for Q3NURBCurve_EmptyData; nothing is allocated when a call fails. The error
// codes are the header's; each message names the rule, the place and the value.
namespace q3::curvetools {

/// The curve in caller data, checked against the TQ3NURBCurveData rules
/// (validateNURBCurveData; throws its errors).
nurbs::CurveRef checkedCurve(const TQ3NURBCurveData* data);

void getDomain(const nurbs::CurveRef& curve, float& start, float& end);
TQ3Point3D evaluate(const nurbs::CurveRef& curve, float t);
void evaluateDerivatives(const nurbs::CurveRef& curve, float t, TQ3Point3D& point, TQ3Vector3D& first,
                         TQ3Vector3D& second);
TQ3Vector3D getTangent(const nurbs::CurveRef& curve, float t);
float getCurvature(const nurbs::CurveRef& curve, float t);

TQ3NURBCurveData insertKnot(const nurbs::CurveRef& curve, float knot, unsigned long times);
/// Reads knots only once numKnots has passed the size check.
TQ3NURBCurveData refineKnots(const nurbs::CurveRef& curve, unsigned long numKnots, const float* knots);
TQ3NURBCurveData removeKnot(const nurbs::CurveRef& curve, unsigned long knotIndex, unsigned long times,
                            float tolerance, unsigned long& numRemoved);
TQ3NURBCurveData elevateDegree(const nurbs::CurveRef& curve, unsigned long times);
unsigned long countBezierPieces(const nurbs::CurveRef& curve);
TQ3NURBCurveData getBezierPiece(const nurbs::CurveRef& curve, unsigned long pieceIndex);
/// Fills both halves, or neither; left and right must be different structures.
void split(const nurbs::CurveRef& curve, float t, TQ3NURBCurveData& left, TQ3NURBCurveData& right);

float getArcLength(const nurbs::CurveRef& curve, float t0, float t1, float tolerance);
float getParameterAtLength(const nurbs::CurveRef& curve, float t0, float length, float tolerance);
void getClosestPoint(const nurbs::CurveRef& curve, const TQ3Point3D& point, float& t, TQ3Point3D& closest);

/// Interpolate is approximate with numControlPoints == numPoints. The
/// parameterization is taken by reference and read as an integer (core/EnumValue.h),
/// since a C caller may pass any int. Reads points only once the counts have passed.
TQ3NURBCurveData approximate(unsigned long order, unsigned long numPoints, const TQ3Point3D* points,
                             unsigned long numControlPoints, const TQ3NURBCurveParameterization& parameterization);

} // namespace q3::curvetools
