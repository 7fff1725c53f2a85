// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DRenderer.h"
#include "base/RenderTarget.h"
#include "core/Object.h"

namespace q3 {

extern const ClassInfo kRendererClass;
extern const ClassInfo kWireFrameRendererClass;
extern const ClassInfo kInteractiveRendererClass;

/// A QuickDraw 3D renderer object: which renderer a view draws with and its
/// settings. The pixels themselves come from the view's OffscreenRenderer;
/// this object only decides what is drawn how. Invariant: the type is one Q3
/// provides (kQ3RendererTypeWireFrame or kQ3RendererTypeInteractive).
class Renderer : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3SharedTypeRenderer;

    /// A new renderer of a type Q3 provides; throws kQ3ErrorInvalidObjectType
    /// for any other type code.
    static Ref<Renderer> newFromType(TQ3ObjectType type);

    /// True when the renderer fills surfaces (triangles, polygons); false for
    /// one that draws only their edges. Curves, lines and points are drawn as
    /// lines and points by both.
    virtual bool fillsSurfaces() const = 0;
    /// How the renderer samples textures: nearest unless it says otherwise.
    virtual TextureFilter textureFilter() const { return TextureFilter::kNearest; }

protected:
    Renderer() = default;
};

/// The wireframe renderer: every geometry as lines and points. Invariant:
/// it has no settings, so every wireframe renderer is interchangeable.
class WireFrameRenderer final : public Renderer {
public:
    static constexpr TQ3ObjectType kClassType = kQ3RendererTypeWireFrame;

    const ClassInfo& classInfo() const override { return kWireFrameRendererClass; }
    Object* duplicate() const override;
    bool fillsSurfaces() const override { return false; }
};

/// The interactive renderer. Of its RAVE-era settings (QD3DRenderer.h) the
/// texture filter decides how textures are sampled; the others are recorded
/// and returned but do not change the image. Invariant: the double-buffer
/// bypass is exactly kQ3True or kQ3False.
class InteractiveRenderer final : public Renderer {
public:
    static constexpr TQ3ObjectType kClassType = kQ3RendererTypeInteractive;

    /// The values a new interactive renderer starts with (QD3DRenderer.h).
    struct Settings {
        TQ3CSGEquation csgEquation = kQ3CSGEquationAandB;
        long vendorID = -1;
        long engineID = 0;
        TQ3Boolean doubleBufferBypass = kQ3False;
        unsigned long raveContextHints = 0;
        unsigned long raveTextureFilter = 0;
    };

    const ClassInfo& classInfo() const override { return kInteractiveRendererClass; }
    Object* duplicate() const override;
    bool fillsSurfaces() const override { return true; }
    /// kQATextureFilter_Fast (0, the default) nearest, _Mid (1) bilinear,
    /// _Best (2) trilinear; any other value as the default.
    TextureFilter textureFilter() const override;

    const Settings& settings() const { return m_settings; }
    void setCSGEquation(TQ3CSGEquation equation);
    void setPreferences(long vendorID, long engineID);
    /// Any nonzero value (read through enumValue) is stored as kQ3True.
    void setDoubleBufferBypass(const TQ3Boolean& bypass);
    void setRAVEContextHints(unsigned long hints);
    void setRAVETextureFilter(unsigned long filter);

private:
    Settings m_settings;
};

} // namespace q3
