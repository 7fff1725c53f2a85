// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "base/RenderTarget.h"

#include <string>
#include <utility>
#include <vector>

namespace q3 {

/// A RenderTarget that draws nothing and records the name of every call
/// made to it, in order: the unit tests run the view's passes through it
/// without a rendering backend. Every call succeeds; a finished frame is
/// width * height transparent black pixels; addTexture numbers the frame's
/// textures from 0. Invariant: pixels() holds width() * height() * 4 bytes.
class NullRenderTarget final : public RenderTarget {
public:
    /// What one draw call was given.
    struct DrawRecord {
        std::size_t triangles = 0;
        std::size_t lines = 0;
        std::size_t points = 0;
        std::size_t edges = 0;
        Shading::Fill fill = Shading::Fill::kFilled;
        bool lit = false;
        bool edgesAlone = false;
        /// The shading's opacity: its uniform value, and r g b per vertex
        /// when it had an array (OpacitySetup).
        RgbColor opacity{1.0f, 1.0f, 1.0f};
        std::vector<float> opacityRgb;
    };
    /// The draw calls made so far, in order.
    const std::vector<DrawRecord>& draws() const { return m_draws; }
    /// The names of the calls made so far ("beginFrame", "draw", ...).
    const std::vector<std::string>& calls() const { return m_calls; }
    /// How many of the recorded calls are named `name`.
    std::size_t count(const std::string& name) const
    {
        std::size_t n = 0;
        for (const std::string& call : m_calls)
            n += call == name ? 1 : 0;
        return n;
    }

    RenderResult beginFrame(std::uint32_t width, std::uint32_t height, const RgbaColor&, const PixelRect&,
                            const FrameOptions& = FrameOptions{}) override
    {
        m_width = width;
        m_height = height;
        m_inFrame = true;
        m_textures = 0;
        return record("beginFrame");
    }
    RenderResult setMatrix(const float[16]) override { return record("setMatrix"); }
    RenderResult setMatrix(const double[16]) override { return record("setMatrix"); }
    /// Records "draw" and keeps the mesh's counts, the shading's fill and
    /// its opacity.
    RenderResult draw(const MeshView& mesh, const Shading& shading) override
    {
        DrawRecord drawn{mesh.triangleCount, mesh.lineCount, mesh.pointCount, mesh.edgeCount, shading.fill,
                          shading.lit, shading.edgesAlone};
        drawn.opacity = shading.opacity.uniform;
        if (shading.opacity.rgb != nullptr)
            drawn.opacityRgb.assign(shading.opacity.rgb, shading.opacity.rgb + 3 * shading.opacity.count);
        m_draws.push_back(std::move(drawn));
        return record("draw");
    }
    RenderResult drawBitmap(const float*, const BitmapImage&, const RgbColor&) override
    {
        return record("drawBitmap");
    }
    RenderResult drawPixmap(const float*, const PixmapImage&) override { return record("drawPixmap"); }
    RenderResult setLighting(const LightingSetup&) override { return record("setLighting"); }
    RenderResult setFaceOptions(const FaceOptions&) override { return record("setFaceOptions"); }
    RenderResult setAntiAlias(const AntiAliasOptions&) override { return record("setAntiAlias"); }
    RenderResult addTexture(const TextureImage&, std::uint32_t& id) override
    {
        id = m_textures++;
        return record("addTexture");
    }
    RenderResult setFog(const FogSetup&) override { return record("setFog"); }
    RenderResult endFrame() override
    {
        m_inFrame = false;
        m_pixels.assign(std::size_t(m_width) * m_height * 4, 0);
        return record("endFrame");
    }
    void cancelFrame() override
    {
        m_inFrame = false;
        record("cancelFrame");
    }

    bool inFrame() const override { return m_inFrame; }
    std::uint32_t width() const override { return m_width; }
    std::uint32_t height() const override { return m_height; }
    std::size_t rowBytes() const override { return std::size_t(m_width) * 4; }
    const std::uint8_t* pixels() const override { return m_pixels.empty() ? nullptr : m_pixels.data(); }

private:
    RenderResult record(const char* name)
    {
        m_calls.emplace_back(name);
        return RenderResult::success();
    }

    std::vector<std::string> m_calls;
    std::vector<DrawRecord> m_draws;
    std::vector<std::uint8_t> m_pixels;
    std::uint32_t m_width = 0;
    std::uint32_t m_height = 0;
    std::uint32_t m_textures = 0;
    bool m_inFrame = false;
};

} // namespace q3
