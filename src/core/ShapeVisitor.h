// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

struct OpaqueTQ3GroupPosition;

namespace q3 {

class AttributeSet;
class DisplayGroup;
class Object;
class Geometry;
class Shader;
class Style;
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
    /// A style or shader: it sets its part of the traversal's DrawState
    /// (Style::apply, Shader::apply).
    virtual void visitStyle(const Style& style) = 0;
    virtual void visitShader(const Shader& shader) = 0;
    virtual void visitTransform(const Transform& transform) = 0;
    /// A push or pop state operator (Q3Push_New, Q3Pop_New): saves or
    /// restores the graphics state as Q3Push_Submit and Q3Pop_Submit do;
    /// popState throws kQ3ErrorNothingToPop when nothing pushed is left.
    virtual void pushState() = 0;
    virtual void popState() = 0;
    /// A display group's objects are visited between these two. beginGroup
    /// decides whether they are visited at all (the group's state, its
    /// bounding box) and saves the graphics state unless the group is
    /// inline; endGroup restores it. Throws kQ3ErrorInvalidObject beyond
    /// limits::kMaxGroupNesting.
    virtual bool beginGroup(const DisplayGroup& group) = 0;
    virtual void endGroup(const DisplayGroup& group) = 0;
    /// Inside a display group, just before each object it submits: that
    /// object's position in the group (picking records hit paths from it).
    virtual void atGroupPosition(OpaqueTQ3GroupPosition* /*position*/) {}
    /// Around a custom object's submit method (QD3DExtension.h), which
    /// submits what stands for the object: picking names the object, not
    /// what it submits, in the hits. `submitted` is false when the method
    /// failed (the submit fails).
    virtual void beginCustomObject(const Object& /*object*/) {}
    virtual void endCustomObject(const Object& /*object*/, bool /*submitted*/) {}
};

} // namespace q3
