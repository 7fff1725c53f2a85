// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DDrawContext.h"
#include "core/Object.h"

#include <vector>

namespace q3 {

class AttributeSet;
class Camera;
class Group;
class Renderer;
class View;

extern const ClassInfo kViewHintsClass;

/// A view hints object (QD3DIO.h): the renderer, camera, lights, attribute
/// set, image dimensions, mask and clear colour a metafile suggests for
/// drawing its model. Invariant: the light group, when there is one, is a
/// light group; the clear method is a TQ3DrawContextClearImageMethod value
/// and the clear colour is finite; the dimensions are both 0 (none given) or
/// both in 1..0xFFFFFFFF (the file's Uns32); the mask is either empty (image
/// NULL, every field 0) or a bitmap obeying Marker::checkBitmap whose image
/// this object owns.
class ViewHints final : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3SharedTypeViewHints;

    ViewHints();
    ~ViewHints() override;

    const ClassInfo& classInfo() const override { return kViewHintsClass; }
    Object* duplicate() const override;

    /// The hints a view's configuration gives (Q3ViewHints_New): its
    /// renderer, camera and light group (shared, not copied), its default
    /// attribute set, and from its draw context the clear method and colour,
    /// the mask and its state, and the size drawn into (the pane when the
    /// pane state is on, else a pixmap's size) with the dimensions state on.
    static Ref<ViewHints> fromView(const View& view);

    const Ref<Renderer>& renderer() const { return m_renderer; }
    const Ref<Camera>& camera() const { return m_camera; }
    const Ref<Group>& lightGroup() const { return m_lightGroup; }
    const Ref<AttributeSet>& attributeSet() const { return m_attributeSet; }
    void setRenderer(Ref<Renderer> renderer);
    void setCamera(Ref<Camera> camera);
    /// kQ3ErrorInvalidObjectType for a group that is not a light group.
    void setLightGroup(Ref<Group> lights);
    void setAttributeSet(Ref<AttributeSet> attributes);

    TQ3Boolean dimensionsState() const { return m_dimensionsState; }
    void setDimensionsState(const TQ3Boolean& state);
    unsigned long width() const { return m_width; }
    unsigned long height() const { return m_height; }
    /// kQ3ErrorInvalidParameter for 0 or more than 0xFFFFFFFF.
    void setDimensions(unsigned long width, unsigned long height);

    TQ3Boolean maskState() const { return m_maskState; }
    void setMaskState(const TQ3Boolean& state);
    const TQ3Bitmap& mask() const { return m_mask; }
    /// Copies the bitmap; Marker::checkBitmap's errors.
    void setMask(const TQ3Bitmap& mask);
    /// A copy of the mask whose image the caller frees (Q3Bitmap_Empty);
    /// all zero when there is none.
    void copyMask(TQ3Bitmap& out) const;

    TQ3DrawContextClearImageMethod clearMethod() const { return m_clearMethod; }
    /// kQ3ErrorInvalidParameter for a value that is not an enumerator.
    void setClearMethod(const TQ3DrawContextClearImageMethod& method);
    const TQ3ColorARGB& clearColor() const { return m_clearColor; }
    /// kQ3ErrorInvalidParameter for a non-finite component.
    void setClearColor(const TQ3ColorARGB& color);

    /// Children a file gave the hints that Q3 has no class for (a renderer
    /// among them: Q3's renderers have no 3DMF form), kept as unknown
    /// objects so that writing the hints back writes them unchanged. No C
    /// call reaches them.
    const std::vector<Ref<SharedObject>>& unknownChildren() const { return m_unknownChildren; }
    void addUnknownChild(Ref<SharedObject> child) { m_unknownChildren.push_back(std::move(child)); }

private:
    Ref<Renderer> m_renderer;
    Ref<Camera> m_camera;
    Ref<Group> m_lightGroup;
    Ref<AttributeSet> m_attributeSet;
    TQ3Boolean m_dimensionsState = kQ3False;
    unsigned long m_width = 0;
    unsigned long m_height = 0;
    TQ3Boolean m_maskState = kQ3False;
    TQ3Bitmap m_mask{};
    TQ3DrawContextClearImageMethod m_clearMethod = kQ3ClearMethodNone;
    TQ3ColorARGB m_clearColor{1.0f, 0.0f, 0.0f, 0.0f};
    std::vector<Ref<SharedObject>> m_unknownChildren;
};

} // namespace q3
