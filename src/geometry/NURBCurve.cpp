// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/NURBCurve.h"

#include "core/ShapeVisitor.h"
#include "geometry/nurbs/Knots.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

namespace q3 {

const ClassInfo kNURBCurveClass{kQ3GeometryTypeNURBCurve, &kGeometryClass, "NURB curve"};

namespace {

// Beyond this many control points numPoints + order could overflow the
// arithmetic below on a 32-bit long; far above any real curve.
constexpr unsigned long kMaxPoints = 1UL << 28;

template <class T>
T* mallocCopy(const std::vector<T>& values)
{
    T* copy = static_cast<T*>(std::malloc(values.size() * sizeof(T)));
    if (copy == nullptr)
        throw std::bad_alloc();
    std::memcpy(copy, values.data(), values.size() * sizeof(T));
    return copy;
}

std::string describe(unsigned long index, unsigned long count, const char* what)
{
    return std::string(what) + " index " + std::to_string(index) + " is out of range (the curve has " +
           std::to_string(count) + ")";
}

} // namespace

nurbs::CurveRef curveRefOf(const TQ3NURBCurveData& data)
{
    nurbs::CurveRef ref;
    ref.order = static_cast<unsigned>(data.order);
    ref.numPoints = static_cast<std::size_t>(data.numPoints);
    ref.points = reinterpret_cast<const float*>(data.controlPoints);
    ref.knots = data.knots;
    return ref;
}

void validateNURBCurveData(const TQ3NURBCurveData* data)
{
    requireNonNull(data, "curve data");
    if (data->order < nurbs::kMinOrder || data->order > nurbs::kMaxOrder)
        fail(kQ3ErrorParameterOutOfRange,
             "order " + std::to_string(data->order) + " is outside 2 to 16");
    if (data->numPoints < data->order)
        fail(kQ3ErrorGeometryInsufficientNumberOfPoints,
             "numPoints " + std::to_string(data->numPoints) + " is less than the order " +
                 std::to_string(data->order));
    if (data->numPoints > kMaxPoints)
        fail(kQ3ErrorParameterOutOfRange,
             "numPoints " + std::to_string(data->numPoints) + " is more than Q3's limit of " +
                 std::to_string(kMaxPoints));
    requireNonNull(data->controlPoints, "controlPoints");
    requireNonNull(data->knots, "knots");
    const nurbs::CurveValidation result = nurbs::validateCurve(curveRefOf(*data));
    if (!result.ok())
        fail(kQ3ErrorInvalidData, result.message);
}

NURBCurve::NURBCurve(const TQ3NURBCurveData& data)
{
    assign(data, attributeSetFromHandle(data.curveAttributeSet, "curveAttributeSet"));
}

void NURBCurve::assign(const TQ3NURBCurveData& data, Ref<AttributeSet> attributes)
{
    // Build the copies first so that an allocation failure changes nothing.
    std::vector<TQ3RationalPoint4D> points(data.controlPoints, data.controlPoints + data.numPoints);
    std::vector<float> knots(data.knots, data.knots + data.numPoints + data.order);
    m_order = data.order;
    m_points.swap(points);
    m_knots.swap(knots);
    replaceAttributeSet(std::move(attributes));
}

Object* NURBCurve::duplicate() const
{
    Ref<NURBCurve> copy = Ref<NURBCurve>::adopt(new NURBCurve);
    copy->m_order = m_order;
    copy->m_points = m_points;
    copy->m_knots = m_knots;
    copy->replaceAttributeSet(duplicateAttributeSet(attributeSetRef()));
    copy->registerLive();
    return copy.detach();
}

void NURBCurve::accept(ShapeVisitor& visitor) const
{
    visitor.visitNURBCurve(curve(), attributeSet(), &m_cache);
}

nurbs::CurveRef NURBCurve::curve() const
{
    nurbs::CurveRef ref;
    ref.order = static_cast<unsigned>(m_order);
    ref.numPoints = m_points.size();
    ref.points = reinterpret_cast<const float*>(m_points.data());
    ref.knots = m_knots.data();
    return ref;
}

void NURBCurve::getData(TQ3NURBCurveData& out) const
{
    TQ3RationalPoint4D* points = mallocCopy(m_points);
    float* knots = nullptr;
    try {
        knots = mallocCopy(m_knots);
    } catch (...) {
        std::free(points);
        throw;
    }
    out.order = m_order;
    out.numPoints = m_points.size();
    out.controlPoints = points;
    out.knots = knots;
    out.curveAttributeSet = attributeSetToHandle(attributeSetRef());
}

void NURBCurve::emptyData(TQ3NURBCurveData& data)
{
    // Check the handle before freeing anything, so a failure changes nothing;
    // then take back the reference GetData handed out, released on return.
    const Ref<AttributeSet> handedOut = Ref<AttributeSet>::adopt(
        lookupOptional<AttributeSet>(data.curveAttributeSet, "curveAttributeSet"));
    std::free(data.controlPoints);
    std::free(data.knots);
    data.controlPoints = nullptr;
    data.knots = nullptr;
    data.curveAttributeSet = nullptr;
}

void NURBCurve::setData(const TQ3NURBCurveData& data)
{
    validateNURBCurveData(&data);
    assign(data, attributeSetFromHandle(data.curveAttributeSet, "curveAttributeSet"));
    markEdited();
}

TQ3RationalPoint4D NURBCurve::controlPoint(unsigned long index) const
{
    if (index >= m_points.size())
        fail(kQ3ErrorParameterOutOfRange, describe(index, m_points.size(), "control point"));
    return m_points[index];
}

void NURBCurve::setControlPoint(unsigned long index, const TQ3RationalPoint4D& point)
{
    if (index >= m_points.size())
        fail(kQ3ErrorParameterOutOfRange, describe(index, m_points.size(), "control point"));
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z) ||
        !std::isfinite(point.w))
        fail(kQ3ErrorInvalidParameter,
             "control point " + std::to_string(index) + " has a component that is not finite");
    if (!(point.w > 0.0f))
        fail(kQ3ErrorInvalidParameter, "control point " + std::to_string(index) + " has weight w = " +
                                           std::to_string(point.w) + "; weights must be positive");
    m_points[index] = point;
    markEdited();
}

float NURBCurve::knot(unsigned long index) const
{
    if (index >= m_knots.size())
        fail(kQ3ErrorParameterOutOfRange, describe(index, m_knots.size(), "knot"));
    return m_knots[index];
}

void NURBCurve::setKnot(unsigned long index, float value)
{
    if (index >= m_knots.size())
        fail(kQ3ErrorParameterOutOfRange, describe(index, m_knots.size(), "knot"));
    std::vector<float> knots = m_knots;
    knots[index] = value;
    nurbs::CurveRef candidate = curve();
    candidate.knots = knots.data();
    const nurbs::CurveValidation result = nurbs::validateCurve(candidate);
    if (!result.ok())
        fail(kQ3ErrorInvalidParameter, "setting knot " + std::to_string(index) + " to " +
                                           std::to_string(value) + " would break a rule: " +
                                           result.message);
    m_knots.swap(knots);
    markEdited();
}

} // namespace q3
