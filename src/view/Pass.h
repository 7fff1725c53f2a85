// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DStyle.h"
#include "QD3DView.h"
#include "core/Object.h"
#include "core/ShapeVisitor.h"
#include "geometry/Decompose.h"
#include "base/DrawState.h"
#include "view/CurveTessellation.h"
#include "base/Matrix.h"

#include <optional>
#include <vector>

namespace q3 {

class DisplayGroup;
class Geometry;

/// The attributes a traversal starts with: QuickDraw 3D's view defaults
/// (QD3DView.h: ambient coefficient 1, diffuse colour white, specular colour
/// 0.5 grey, specular control 4, transparency colour white (opaque),
/// highlight off), overlaid by the view's default attribute set if it has one.
AttributeValues defaultAttributes(const AttributeSet* viewDefaults);

/// The graphics state of a traversal (QD3DView.h): what Q3Push_Submit saves.
struct GraphicsState {
    Matrix localToWorld{1.0};
    /// Styles and shaders.
    DrawState draw;
    /// Every attribute submitted so far over the defaults.
    AttributeValues attributes;
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
    /// attributes: what the traversal starts with (defaultAttributes); a
    /// surface shader among them is the state's first surface shader.
    Pass(std::optional<Window> window, const AttributeValues& attributes);

    /// Merges the set's attributes into the state; a surface shader in the
    /// set also becomes the state's surface shader (DrawState::texture ...),
    /// as submitting the shader would.
    void visitAttributeSet(const AttributeSet& attributes) override;
    /// Styles and shaders set their part of the state.
    void visitStyle(const Style& style) override;
    void visitShader(const Shader& shader) override;
    /// Local-to-world becomes transform * local-to-world (row vectors), or the
    /// identity for a reset transform.
    void visitTransform(const Transform& transform) override;

    /// A display group: nothing when it is not drawn; past
    /// limits::kMaxGroupNesting, kQ3ErrorInvalidObject; a group with a
    /// bounding box it uses goes through enterBoundedGroup; otherwise the
    /// state is pushed (unless the group is inline) and its objects follow.
    bool beginGroup(const DisplayGroup& group) override;
    void endGroup(const DisplayGroup& group) override;
    /// Whether groups with a bounding box may be handled by their box.
    void allowGroupCulling(bool allow) { m_cullGroups = allow; }
    /// Whether curves may skip subdividing what the window cannot show
    /// (TessellationSetting::cullOutsideView): rendering loops only.
    void allowCurveCulling(bool allow) { m_cullCurves = allow; }
    /// Where curves are subdivided into (SubdivisionMeasure::curveScratch):
    /// the view's own buffer, which outlives the pass; null gives each curve
    /// a buffer of its own.
    void useCurveScratch(nurbs::TessellatedCurve* scratch) { m_curveScratch = scratch; }

    void push();
    /// Throws kQ3ErrorNothingToPop when nothing pushed is left, or nothing
    /// pushed inside the innermost display group being traversed (a group's
    /// objects cannot pop the state it was entered with).
    void pop();
    void pushState() override { push(); }
    void popState() override { pop(); }

    const GraphicsState& state() const { return m_state; }
    const std::optional<Window>& window() const { return m_window; }

    /// What a geometry submitted now would be subdivided under.
    TessellationSetting tessellationSetting() const;

    SubdivisionMeasure subdivisionMeasure() const override;

    /// Q3Geometry_GetDecomposed: what the geometry submitted now would be
    /// drawn as, as a new geometry (Geometry::decomposed), or null for a
    /// primitive.
    Ref<Geometry> decomposed(const Geometry& geometry) const;

    /// A geometry's colour: its own attribute set's diffuse colour, else the
    /// state's.
    TQ3ColorRGB colorOf(const AttributeSet* own) const;

    /// Whether a box in the current local coordinates may be seen: false only
    /// when all its corners are outside one plane of the view's frustum (true
    /// without a window).
    bool boxVisible(const TQ3BoundingBox& box) const;

protected:
    /// A group that uses its bounding box: whether to traverse its objects.
    /// Rendering skips a group whose box cannot be seen; bounding takes the
    /// box instead of the objects.
    virtual bool enterBoundedGroup(const DisplayGroup& group, const TQ3BoundingBox& box);

private:
    std::optional<Window> m_window;
    GraphicsState m_state;
    std::vector<GraphicsState> m_stack;
    /// Per group entered: whether it pushed the state, and the stack size
    /// after that push (its objects pop no lower; endGroup drops what they
    /// left pushed).
    struct GroupEntry {
        bool pushed;
        std::size_t floor;
    };
    std::vector<GroupEntry> m_groups;
    bool m_cullGroups = true;
    bool m_cullCurves = false;
    nurbs::TessellatedCurve* m_curveScratch = nullptr;
};

} // namespace q3
