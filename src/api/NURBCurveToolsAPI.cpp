// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "Q3NURBCurveTools.h"
#include "api/Entry.h"
#include "geometry/NURBCurve.h"
#include "geometry/NURBCurveTools.h"

// Q3NURBCurveData_* and the Q3NURBCurve_* curve tools (Q3NURBCurveTools.h). Each
// pair shares one core function (geometry/NURBCurveTools.h); the data form checks
// the caller's TQ3NURBCurveData, the object form reads a retained curve without
// changing it. Pointers are checked left to right before the curve's rules.

using namespace q3;
using namespace q3::api;

namespace {

nurbs::CurveRef retained(TQ3GeometryObject curve)
{
    return lookup<NURBCurve>(curve, "curve").curve();
}

// The two forms of a tool with one result. The data form checks curveData,
// then `out`, then the curve's rules; the object form looks the curve up, then
// checks `out`. Then *out = tool(curve).
template <class Out, class Tool>
TQ3Status dataTool(const char* function, const TQ3NURBCurveData* curveData, Out* out, const char* outName, Tool tool)
{
    return guardStatus(function, [&] {
        requireNonNull(curveData, "curveData");
        requireNonNull(out, outName);
        *out = tool(curvetools::checkedCurve(curveData));
    });
}

template <class Out, class Tool>
TQ3Status objectTool(const char* function, TQ3GeometryObject curve, Out* out, const char* outName, Tool tool)
{
    return guardStatus(function, [&] {
        const nurbs::CurveRef ref = retained(curve);
        requireNonNull(out, outName);
        *out = tool(ref);
    });
}

} // namespace

extern "C" {

TQ3Status Q3NURBCurveData_GetDomain(const TQ3NURBCurveData* curveData, float* start, float* end)
{
    return guardStatus(__func__, [&] {
        requireNonNull(curveData, "curveData");
        requireNonNull(start, "start");
        requireNonNull(end, "end");
        curvetools::getDomain(curvetools::checkedCurve(curveData), *start, *end);
    });
}

TQ3Status Q3NURBCurve_GetDomain(TQ3GeometryObject curve, float* start, float* end)
{
    return guardStatus(__func__, [&] {
        const nurbs::CurveRef ref = retained(curve);
        requireNonNull(start, "start");
        requireNonNull(end, "end");
        curvetools::getDomain(ref, *start, *end);
    });
}

TQ3Status Q3NURBCurveData_Evaluate(const TQ3NURBCurveData* curveData, float t, TQ3Point3D* point)
{
    return dataTool(__func__, curveData, point, "point",
                    [&](const nurbs::CurveRef& c) { return curvetools::evaluate(c, t); });
}

TQ3Status Q3NURBCurve_Evaluate(TQ3GeometryObject curve, float t, TQ3Point3D* point)
{
    return objectTool(__func__, curve, point, "point",
                      [&](const nurbs::CurveRef& c) { return curvetools::evaluate(c, t); });
}

TQ3Status Q3NURBCurveData_EvaluateDerivatives(const TQ3NURBCurveData* curveData, float t, TQ3Point3D* point,
                                              TQ3Vector3D* firstDerivative, TQ3Vector3D* secondDerivative)
{
    return guardStatus(__func__, [&] {
        requireNonNull(curveData, "curveData");
        requireNonNull(point, "point");
        requireNonNull(firstDerivative, "firstDerivative");
        requireNonNull(secondDerivative, "secondDerivative");
        curvetools::evaluateDerivatives(curvetools::checkedCurve(curveData), t, *point, *firstDerivative,
                                        *secondDerivative);
    });
}

TQ3Status Q3NURBCurve_EvaluateDerivatives(TQ3GeometryObject curve, float t, TQ3Point3D* point,
                                          TQ3Vector3D* firstDerivative, TQ3Vector3D* secondDerivative)
{
    return guardStatus(__func__, [&] {
        const nurbs::CurveRef ref = retained(curve);
        requireNonNull(point, "point");
        requireNonNull(firstDerivative, "firstDerivative");
        requireNonNull(secondDerivative, "secondDerivative");
        curvetools::evaluateDerivatives(ref, t, *point, *firstDerivative, *secondDerivative);
    });
}

TQ3Status Q3NURBCurveData_GetTangent(const TQ3NURBCurveData* curveData, float t, TQ3Vector3D* tangent)
{
    return dataTool(__func__, curveData, tangent, "tangent",
                    [&](const nurbs::CurveRef& c) { return curvetools::getTangent(c, t); });
}

TQ3Status Q3NURBCurve_GetTangent(TQ3GeometryObject curve, float t, TQ3Vector3D* tangent)
{
    return objectTool(__func__, curve, tangent, "tangent",
                      [&](const nurbs::CurveRef& c) { return curvetools::getTangent(c, t); });
}

TQ3Status Q3NURBCurveData_GetCurvature(const TQ3NURBCurveData* curveData, float t, float* curvature)
{
    return dataTool(__func__, curveData, curvature, "curvature",
                    [&](const nurbs::CurveRef& c) { return curvetools::getCurvature(c, t); });
}

TQ3Status Q3NURBCurve_GetCurvature(TQ3GeometryObject curve, float t, float* curvature)
{
    return objectTool(__func__, curve, curvature, "curvature",
                      [&](const nurbs::CurveRef& c) { return curvetools::getCurvature(c, t); });
}

TQ3Status Q3NURBCurveData_InsertKnot(const TQ3NURBCurveData* curveData, float knot, unsigned long times,
                                     TQ3NURBCurveData* result)
{
    return dataTool(__func__, curveData, result, "result",
                    [&](const nurbs::CurveRef& c) { return curvetools::insertKnot(c, knot, times); });
}

TQ3Status Q3NURBCurve_InsertKnot(TQ3GeometryObject curve, float knot, unsigned long times, TQ3NURBCurveData* result)
{
    return objectTool(__func__, curve, result, "result",
                      [&](const nurbs::CurveRef& c) { return curvetools::insertKnot(c, knot, times); });
}

TQ3Status Q3NURBCurveData_RefineKnots(const TQ3NURBCurveData* curveData, unsigned long numKnots, const float* knots,
                                      TQ3NURBCurveData* result)
{
    return guardStatus(__func__, [&] {
        requireNonNull(curveData, "curveData");
        if (numKnots > 0)
            requireNonNull(knots, "knots");
        requireNonNull(result, "result");
        *result = curvetools::refineKnots(curvetools::checkedCurve(curveData), numKnots, knots);
    });
}

TQ3Status Q3NURBCurve_RefineKnots(TQ3GeometryObject curve, unsigned long numKnots, const float* knots,
                                  TQ3NURBCurveData* result)
{
    return guardStatus(__func__, [&] {
        const nurbs::CurveRef ref = retained(curve);
        if (numKnots > 0)
            requireNonNull(knots, "knots");
        requireNonNull(result, "result");
        *result = curvetools::refineKnots(ref, numKnots, knots);
    });
}

TQ3Status Q3NURBCurveData_RemoveKnot(const TQ3NURBCurveData* curveData, unsigned long knotIndex, unsigned long times,
                                     float tolerance, TQ3NURBCurveData* result, unsigned long* numRemoved)
{
    return guardStatus(__func__, [&] {
        requireNonNull(curveData, "curveData");
        requireNonNull(result, "result");
        requireNonNull(numRemoved, "numRemoved");
        *result = curvetools::removeKnot(curvetools::checkedCurve(curveData), knotIndex, times, tolerance,
                                         *numRemoved);
    });
}

TQ3Status Q3NURBCurve_RemoveKnot(TQ3GeometryObject curve, unsigned long knotIndex, unsigned long times,
                                 float tolerance, TQ3NURBCurveData* result, unsigned long* numRemoved)
{
    return guardStatus(__func__, [&] {
        const nurbs::CurveRef ref = retained(curve);
        requireNonNull(result, "result");
        requireNonNull(numRemoved, "numRemoved");
        *result = curvetools::removeKnot(ref, knotIndex, times, tolerance, *numRemoved);
    });
}

TQ3Status Q3NURBCurveData_ElevateDegree(const TQ3NURBCurveData* curveData, unsigned long times,
                                        TQ3NURBCurveData* result)
{
    return dataTool(__func__, curveData, result, "result",
                    [&](const nurbs::CurveRef& c) { return curvetools::elevateDegree(c, times); });
}

TQ3Status Q3NURBCurve_ElevateDegree(TQ3GeometryObject curve, unsigned long times, TQ3NURBCurveData* result)
{
    return objectTool(__func__, curve, result, "result",
                      [&](const nurbs::CurveRef& c) { return curvetools::elevateDegree(c, times); });
}

TQ3Status Q3NURBCurveData_CountBezierPieces(const TQ3NURBCurveData* curveData, unsigned long* numPieces)
{
    return dataTool(__func__, curveData, numPieces, "numPieces",
                    [&](const nurbs::CurveRef& c) { return curvetools::countBezierPieces(c); });
}

TQ3Status Q3NURBCurve_CountBezierPieces(TQ3GeometryObject curve, unsigned long* numPieces)
{
    return objectTool(__func__, curve, numPieces, "numPieces",
                      [&](const nurbs::CurveRef& c) { return curvetools::countBezierPieces(c); });
}

TQ3Status Q3NURBCurveData_GetBezierPiece(const TQ3NURBCurveData* curveData, unsigned long pieceIndex,
                                         TQ3NURBCurveData* piece)
{
    return dataTool(__func__, curveData, piece, "piece",
                    [&](const nurbs::CurveRef& c) { return curvetools::getBezierPiece(c, pieceIndex); });
}

TQ3Status Q3NURBCurve_GetBezierPiece(TQ3GeometryObject curve, unsigned long pieceIndex, TQ3NURBCurveData* piece)
{
    return objectTool(__func__, curve, piece, "piece",
                      [&](const nurbs::CurveRef& c) { return curvetools::getBezierPiece(c, pieceIndex); });
}

TQ3Status Q3NURBCurveData_Split(const TQ3NURBCurveData* curveData, float t, TQ3NURBCurveData* left,
                                TQ3NURBCurveData* right)
{
    return guardStatus(__func__, [&] {
        requireNonNull(curveData, "curveData");
        requireNonNull(left, "left");
        requireNonNull(right, "right");
        curvetools::split(curvetools::checkedCurve(curveData), t, *left, *right);
    });
}

TQ3Status Q3NURBCurve_Split(TQ3GeometryObject curve, float t, TQ3NURBCurveData* left, TQ3NURBCurveData* right)
{
    return guardStatus(__func__, [&] {
        const nurbs::CurveRef ref = retained(curve);
        requireNonNull(left, "left");
        requireNonNull(right, "right");
        curvetools::split(ref, t, *left, *right);
    });
}

TQ3Status Q3NURBCurveData_GetArcLength(const TQ3NURBCurveData* curveData, float t0, float t1, float tolerance,
                                       float* length)
{
    return dataTool(__func__, curveData, length, "length",
                    [&](const nurbs::CurveRef& c) { return curvetools::getArcLength(c, t0, t1, tolerance); });
}

TQ3Status Q3NURBCurve_GetArcLength(TQ3GeometryObject curve, float t0, float t1, float tolerance, float* length)
{
    return objectTool(__func__, curve, length, "length",
                      [&](const nurbs::CurveRef& c) { return curvetools::getArcLength(c, t0, t1, tolerance); });
}

TQ3Status Q3NURBCurveData_GetParameterAtLength(const TQ3NURBCurveData* curveData, float t0, float length,
                                               float tolerance, float* t)
{
    return dataTool(__func__, curveData, t, "t",
                    [&](const nurbs::CurveRef& c) {
                        return curvetools::getParameterAtLength(c, t0, length, tolerance);
                    });
}

TQ3Status Q3NURBCurve_GetParameterAtLength(TQ3GeometryObject curve, float t0, float length, float tolerance,
                                           float* t)
{
    return objectTool(__func__, curve, t, "t",
                      [&](const nurbs::CurveRef& c) {
                          return curvetools::getParameterAtLength(c, t0, length, tolerance);
                      });
}

TQ3Status Q3NURBCurveData_GetClosestPoint(const TQ3NURBCurveData* curveData, const TQ3Point3D* point, float* t,
                                          TQ3Point3D* closest)
{
    return guardStatus(__func__, [&] {
        requireNonNull(curveData, "curveData");
        requireNonNull(point, "point");
        requireNonNull(t, "t");
        requireNonNull(closest, "closest");
        curvetools::getClosestPoint(curvetools::checkedCurve(curveData), *point, *t, *closest);
    });
}

TQ3Status Q3NURBCurve_GetClosestPoint(TQ3GeometryObject curve, const TQ3Point3D* point, float* t,
                                      TQ3Point3D* closest)
{
    return guardStatus(__func__, [&] {
        const nurbs::CurveRef ref = retained(curve);
        requireNonNull(point, "point");
        requireNonNull(t, "t");
        requireNonNull(closest, "closest");
        curvetools::getClosestPoint(ref, *point, *t, *closest);
    });
}

TQ3Status Q3NURBCurveData_Interpolate(unsigned long order, unsigned long numPoints, const TQ3Point3D* points,
                                      TQ3NURBCurveParameterization parameterization, TQ3NURBCurveData* result)
{
    return guardStatus(__func__, [&] {
        requireNonNull(points, "points");
        requireNonNull(result, "result");
        *result = curvetools::approximate(order, numPoints, points, numPoints, parameterization);
    });
}

TQ3Status Q3NURBCurveData_Approximate(unsigned long order, unsigned long numPoints, const TQ3Point3D* points,
                                      unsigned long numControlPoints, TQ3NURBCurveParameterization parameterization,
                                      TQ3NURBCurveData* result)
{
    return guardStatus(__func__, [&] {
        requireNonNull(points, "points");
        requireNonNull(result, "result");
        *result = curvetools::approximate(order, numPoints, points, numControlPoints, parameterization);
    });
}

} // extern "C"
