// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// What every GLSL program of the OpenGL backends does to a pixel after its
// colour is known: the opacity (RenderTarget.h, OpacitySetup) and the fog
// (FogSetup). Both are written once here, as one GLSL block per stage that
// the programs include (LitProgram, UnlitProgram), and one C++ class that
// finds and sets their uniforms. Internal to the OpenGL backends: it needs a
// current OpenGL context.
//
//   vertex stage:   q3FinishVertex() after gl_Position is written
//   fragment stage: q3FragColor = q3FinishFragment(colour, texel alpha or 1)
//
// The opacity of a vertex is the generic attribute kOpacityAttribute, a vec4
// of the r, g, b opacities and their mean (1, 1, 1, 1 when no array is bound:
// setDefaultOpacity), times the texel's alpha in a textured program. The
// programs are GLSL 1.30 (compatibility profile) with two fragment outputs
// for dual-source blending (OpenGL 3.3, ARB_blend_func_extended):
// q3FragColor (index 0) is the colour with the mean opacity as alpha,
// q3FragOpacity (index 1) the per-channel opacity, which the translucent
// triangles blend with as (GL_SRC1_COLOR, GL_ONE_MINUS_SRC1_COLOR). A
// program compiled with DRAW_OPACITY has neither the attribute nor index 1:
// one grey opacity for the whole draw, the uniform q3DrawOpacity (1 for
// opaque draws, which do not blend), is the alpha, and its translucent draws
// blend with (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA): the same factors for a
// grey opacity, with nothing interpolated and one blend source, as cheap as
// an application's own blending. The fog's distance is an affine function of the world
// point, so it is interpolated exactly across a triangle as the ratio of two
// perspective-correct varyings (FogSetup says which).

#include "render/OffscreenRenderer.h"

#include "render/GlApi.h"

#include <string>

namespace q3 {

/// The generic vertex attribute that carries a vertex's opacity. (0 is
/// gl_Vertex; the others are free in the compatibility profile.)
constexpr GLuint kOpacityAttribute = 7;

/// The vertex stage's block: the opacity attribute and the fog's varyings.
extern const char* const kFinishVertexGlsl;
/// The fragment stage's block: declares the outputs q3FragColor and
/// q3FragOpacity; q3FinishFragment writes q3FragOpacity (opacity times the
/// texel's alpha: the caller's one sample of the texture, 1 untextured) and
/// returns the colour with the mean opacity as alpha, then, when FOG is
/// defined, the fog the uniforms say (a program drawn only unfogged leaves
/// the code out: llvmpipe runs a branch on a uniform in every fragment).
extern const char* const kFinishFragmentGlsl;

/// Compiles a vertex and a fragment shader, each from `count` source
/// strings (the blocks above among them), and links them into a program
/// with q3Opacity bound to kOpacityAttribute and the two fragment outputs to
/// colour 0, indices 0 and 1. 0, with `error` naming the step that failed
/// for the `what` shader and the driver's log, if one fails (nothing is
/// left behind).
GLuint buildFinishProgram(const char* const* vertexSources, const char* const* fragmentSources, int count,
                          const char* what, std::string& error);

/// Makes vertices without an opacity array opaque (the current value of
/// kOpacityAttribute, which OpenGL starts at 0).
void setDefaultOpacity();

/// The uniforms of the two blocks in one linked program.
class FinishUniforms {
public:
    void locate(GLuint program);
    /// Sets the fog of the program in use (FogSetup::Mode::kOff: none).
    void setFog(const FogSetup& fog) const;
    /// Sets the opacity of the program in use when it is a variant with one
    /// opacity for the whole draw (DRAW_OPACITY; a no-op for the others).
    void setDrawOpacity(float opacity) const;

private:
    GLint m_mode = -1, m_start = -1, m_end = -1, m_density = -1, m_color = -1;
    GLint m_depthPlane = -1, m_wPlane = -1, m_drawOpacity = -1;
};

/// Unlit drawing as the fixed-function pipeline does it (the interpolated
/// or flat colour, times the texel in the textured variant), with the two
/// blocks after it: used for fogged and for translucent unlit draws.
class UnlitProgram {
public:
    bool build(std::string& error, bool textured);
    void release();
    void forget() { m_program = 0; }
    bool built() const { return m_program != 0; }
    void use() const { glUseProgram(m_program); }
    const FinishUniforms& finish() const { return m_finish; }

private:
    GLuint m_program = 0;
    FinishUniforms m_finish;
};

} // namespace q3
