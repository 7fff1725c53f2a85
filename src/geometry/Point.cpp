// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Point.h"

#include "core/ShapeVisitor.h"

#include <cmath>

namespace q3 {

const ClassInfo kPointClass{kQ3GeometryTypePoint, &kGeometryClass, "point"};

namespace {

// The coordinate rule of TQ3PointData, shared by validatePointData and
// setPosition so the two paths cannot disagree.
void validatePosition(const TQ3Point3D& p)
{
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        fail(kQ3ErrorInvalidData, "point has a coordinate that is not finite");
}

} // namespace

void validatePointData(const TQ3PointData* data)
{
    requireNonNull(data, "point data");
    validatePosition(data->point);
}

Point::Point(const TQ3PointData& data)
    : Point(data.point, attributeSetFromHandle(data.pointAttributeSet, "pointAttributeSet"))
{
}

Point::Point(const TQ3Point3D& point, Ref<AttributeSet> attributes) : m_point(point)
{
    replaceAttributeSet(std::move(attributes));
}

Object* Point::duplicate() const
{
    Ref<Point> copy = Ref<Point>::adopt(new Point(m_point, duplicateAttributeSet(attributeSetRef())));
    copy->registerLive();
    return copy.detach();
}

void Point::accept(ShapeVisitor& visitor) const
{
    visitor.visitPoint(*this);
}

void Point::getData(TQ3PointData& out) const
{
    out.point = m_point;
    out.pointAttributeSet = attributeSetToHandle(attributeSetRef());
}

void Point::emptyData(TQ3PointData& data)
{
    // Check the handle first so a failure changes nothing; then take back the
    // reference GetData handed out, released on return.
    const Ref<AttributeSet> handedOut =
        Ref<AttributeSet>::adopt(lookupOptional<AttributeSet>(data.pointAttributeSet, "pointAttributeSet"));
    data.pointAttributeSet = nullptr;
}

void Point::setData(const TQ3PointData& data)
{
    validatePointData(&data);
    Ref<AttributeSet> attributes = attributeSetFromHandle(data.pointAttributeSet, "pointAttributeSet");
    m_point = data.point;
    replaceAttributeSet(std::move(attributes));
    markEdited();
}

void Point::setPosition(const TQ3Point3D& position)
{
    validatePosition(position);
    m_point = position;
    markEdited();
}

} // namespace q3
