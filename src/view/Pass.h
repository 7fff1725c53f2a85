// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DStyle.h"
#include "QD3DView.h"
#include "core/Object.h"
#include "core/ShapeVisitor.h"
#include "geometry/Decompose.h"
#include "style/DrawState.h"
#include "view/CurveTessellation.h"
#include "view/Matrix.h"

#include <optional>
#include <vector>

namespace q3 {

class Geometry;

/// The graphics state of a traversal (QD3DView.h): what Q3Push_Submit saves.
/// Of the attributes, the view keeps those its renderers use: the diffuse
/// colour. Other attributes submitted are accepted and have no effect.
struct GraphicsState {
    Matrix localToWorld{1.0};
    /// Styles and shaders.
    DrawState draw;
    TQ3ColorRGB diffuseColor{kQ3ViewDefaultDiffuseColor};
};

/// One traversal of a rendering or bounding loop: the graphics state with its
/// push/pop stack, and the state-changing shapes (attribute sets, styles,
/// transforms). It is also the context geometries decompose themselves in
/// (the current subdivision). Subclasses decide what geometry does.
/// Invariant: a traversal starts from the default GraphicsState with an empty
/// stack, and the state changes only through the visit methods, push and pop.
class Pass : public ShapeVisitor, public DecomposeContext {
public:
    /// window: the loop's camera and pane, when it has them (always for
    /// rendering; for bounding loops when the view has a camera and a draw
    /// context).
    explicit Pass(std::optional<Window> window) : m_window(std::move(window)) {}

    /// Merges the set's attributes into the state (its diffuse colour, if any,
    /// becomes the current one).
    void visitAttributeSet(const AttributeSet& attributes) override;
    /// Styles and shaders set their part of the state.
    void visitStyle(const Style& style) override;
    void visitShader(const Shader& shader) override;
    /// Local-to-world becomes transform * local-to-world (row vectors), or the
    /// identity for a reset transform.
    void visitTransform(const Transform& transform) override;

    void push();
    /// Throws kQ3ErrorNothingToPop when nothing pushed is left.
    void pop();

    const GraphicsState& state() const { return m_state; }
    const std::optional<Window>& window() const { return m_window; }

    /// What a geometry submitted now would be subdivided under.
    TessellationSetting tessellationSetting() const;

    void curvePolyline(const nurbs::CurveRef& curve, CurveCache* cache, const PolylineUser& use) const override;
    SubdivisionMeasure subdivisionMeasure() const override;

    /// Q3Geometry_GetDecomposed: what the geometry submitted now would be
    /// drawn as, as a new geometry (Geometry::decomposed), or null for a
    /// primitive.
    Ref<Geometry> decomposed(const Geometry& geometry) const;

    /// A geometry's colour: its own attribute set's diffuse colour, else the
    /// state's.
    TQ3ColorRGB colorOf(const AttributeSet* own) const;

private:
    std::optional<Window> m_window;
    GraphicsState m_state;
    std::vector<GraphicsState> m_stack;
};

} // namespace q3
