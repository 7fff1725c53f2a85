// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The GLSL program that lights triangles as QuickDraw 3D's illumination
// shaders do (OffscreenRenderer.h, SurfaceShading). Internal to the OpenGL
// backends: it needs a current OpenGL context.

#include "render/OffscreenRenderer.h"
#include "render/SurfaceFinish.h"

#include "render/GlApi.h"

#include <string>

namespace q3 {

class LitProgram {
public:
    /// The program comes in variants, each compiled only with the code its
    /// draws run: textured or not (the textured one takes the diffuse
    /// colour from the texture bound to unit 0 at gl_TexCoord[0], as
    /// OffscreenRenderer::drawLitTriangles says), lit at the vertices or at
    /// every pixel (SurfaceShading::interpolation 2). One program for both
    /// interpolations made llvmpipe run the per-pixel lighting loop in every
    /// fragment whatever the uniform said (benchmarks/RESULTS.md, ModelFrame);
    /// likewise fogged or not (SurfaceFinish.h), and lit by directional
    /// (and ambient) lights only or not: the point and spot code (a square
    /// root, divisions, acos, exp, cos per light) ran for every light of
    /// every vertex too; and back faces lit with the front's colours or
    /// their own (SurfaceShading::flipBackFaces): a one-sided variant
    /// (isOneSided) writes no back colours, so the back faces' lighting is
    /// not computed and llvmpipe interpolates half the colours; it is drawn
    /// with GL_VERTEX_PROGRAM_TWO_SIDE off, every face taking the front
    /// colours, which the two-sided program gives back faces anyway when
    /// they are not flipped.
    ///
    /// Two more switches serve the rasterizer, whose work per pixel grows
    /// with every value interpolated across a triangle (the built-in colour
    /// and texture-coordinate varyings have four components each). Flat
    /// shading (interpolation 0) keeps the built-in colours, which
    /// glShadeModel makes flat; a one-sided variant lit at the vertices and
    /// interpolated passes its colours and texture coordinate in varyings of
    /// three and two components instead (usesPlainVaryings), clamped to 0..1
    /// as OpenGL clamps the built-in ones, so the pixels are the same. And
    /// the variant with one opacity for the whole draw (DRAW_OPACITY: the
    /// opaque primitives, and translucent draws of one grey opacity, which
    /// blend by alpha alone) interpolates no opacity. Together they made the rasterizer threads'
    /// work that of a program written for the scene (benchmarks/RESULTS.md,
    /// ModelFrame).
    ///
    /// A draw whose local-to-world transform is the identity (geometry
    /// drawn where it was modelled, as most retained meshes of a model are)
    /// takes the variant whose world position and normal are the local
    /// ones (LOCAL_IS_WORLD): the same values (the identity maps each to
    /// itself; multiplied by it they could differ only in the sign of a
    /// zero, which no lighting sum keeps), without the two matrix products
    /// per vertex, an eighth of the vertex stage's instructions on the
    /// ModelFrame model (benchmarks/RESULTS.md, ninth round).
    ///
    /// Last, the number of lights (ambient ones aside), up to
    /// kUnrolledLights: a variant that knows it loops over a constant count,
    /// which the GLSL compiler unrolls; llvmpipe runs a loop bounded by a
    /// uniform with its exit test and masks in every vertex, a fifth of the
    /// vertex stage's time on the ModelFrame model (two lights). More lights
    /// take the variant that reads the count from a uniform.
    static constexpr int kUnrolledLights = 4;
    static constexpr int kVariants = 256 * (kUnrolledLights + 2);
    static bool isOneSided(int variant) { return (variant & 16) != 0; }
    static bool usesPlainVaryings(int variant) { return (variant & (16 | 32 | 2)) == 16; }
    static int variant(bool textured, const SurfaceShading& shading, bool fogged, const LightingSetup& lighting,
                       bool drawOpacity)
    {
        bool directionalOnly = true;
        int listed = 0; // the lights other than ambient ones
        for (const RenderLight& light : lighting.lights) {
            directionalOnly = directionalOnly && (light.kind == RenderLight::Kind::kAmbient ||
                                                  light.kind == RenderLight::Kind::kDirectional);
            listed += light.kind == RenderLight::Kind::kAmbient ? 0 : 1;
        }
        return (textured ? 1 : 0) + (shading.interpolation == 2 ? 2 : 0) + (fogged ? 4 : 0) +
               (directionalOnly ? 8 : 0) + (shading.flipBackFaces ? 0 : 16) +
               (shading.interpolation == 0 ? 32 : 0) + (drawOpacity ? 64 : 0) +
               (isIdentity(shading.localToWorld) ? 128 : 0) + 256 * (listed <= kUnrolledLights ? listed + 1 : 0);
    }
    static bool isIdentity(const float (&matrix)[16])
    {
        for (int i = 0; i < 16; ++i)
            if (matrix[i] != (i % 5 == 0 ? 1.0f : 0.0f))
                return false;
        return true;
    }
    /// Compiles and links variant `variant` in the current context; false
    /// (with the log in error) if the driver refuses it.
    bool build(std::string& error, int variant = 0);
    /// Deletes the program in the current context (when it is destroyed with
    /// its context, forgets it).
    void release();
    void forget()
    {
        m_program = 0;
        m_shadingLoaded = false;
    }
    bool built() const { return m_program != 0; }

    void use() const;
    void setLighting(const LightingSetup& lighting) const;
    /// Sets the uniforms of `shading` that differ from what the program was
    /// last given (each draw sets its shading; most of it is the same from
    /// draw to draw, and each uniform set costs Mesa a state update).
    void setShading(const SurfaceShading& shading);
    /// The opacity and fog uniforms (render/SurfaceFinish.h).
    const FinishUniforms& finish() const { return m_finish; }

private:
    GLuint m_program = 0;
    GLint m_lightCount = -1, m_lightKind = -1, m_lightColor = -1, m_lightPosition = -1, m_lightDirection = -1;
    GLint m_lightAttenuation = -1, m_lightHot = -1, m_lightOuter = -1, m_lightFallOff = -1;
    GLint m_ambientLight = -1, m_eye = -1, m_orthographic = -1, m_viewDirection = -1;
    GLint m_illumination = -1, m_ambientCoefficient = -1, m_specularColor = -1, m_specularControl = -1;
    GLint m_localToWorld = -1, m_normalToWorld = -1, m_flipBack = -1;
    FinishUniforms m_finish;
    // What setShading last gave the program, once it gave it anything.
    SurfaceShading m_shading;
    bool m_shadingLoaded = false;
};

} // namespace q3
