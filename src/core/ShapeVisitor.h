// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

namespace q3 {

namespace nurbs {
struct CurveRef;
}
class AttributeSet;
class PolyLine;
class Line;
class Point;
class SubdivisionStyle;
class Transform;
struct CurveCache;

/// What a view does with each kind of submitted shape. Drawable objects call
/// the one method that fits them from accept(), which keeps geometry and
/// styles below the view in the layering: they know this interface, not the
/// view.
class ShapeVisitor {
public:
    virtual ~ShapeVisitor() = default;

    /// A NURB curve, valid by construction. attributes may be null. cache is
    /// the retained curve's own cache, or null in immediate mode.
    virtual void visitNURBCurve(const nurbs::CurveRef& curve, const AttributeSet* attributes,
                                CurveCache* cache) = 0;
    virtual void visitPolyLine(const PolyLine& polyLine) = 0;
    virtual void visitLine(const Line& line) = 0;
    virtual void visitPoint(const Point& point) = 0;
    virtual void visitAttributeSet(const AttributeSet& attributes) = 0;
    virtual void visitSubdivisionStyle(const SubdivisionStyle& style) = 0;
    virtual void visitTransform(const Transform& transform) = 0;
};

} // namespace q3
