// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

namespace q3 {

class AttributeSet;
class Geometry;
class SubdivisionStyle;
class Transform;

/// What a view does with each kind of submitted shape. Drawable objects call
/// the one method that fits them from accept(), which keeps geometry and
/// styles below the view in the layering: they know this interface, not the
/// view. Every geometry arrives through visitGeometry and decomposes itself,
/// so the interface never names a geometry class.
class ShapeVisitor {
public:
    virtual ~ShapeVisitor() = default;

    /// A geometry, valid by construction (a retained object, or an
    /// immediate-mode one that lives for the call).
    virtual void visitGeometry(const Geometry& geometry) = 0;
    virtual void visitAttributeSet(const AttributeSet& attributes) = 0;
    virtual void visitSubdivisionStyle(const SubdivisionStyle& style) = 0;
    virtual void visitTransform(const Transform& transform) = 0;
};

} // namespace q3
