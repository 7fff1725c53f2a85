// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The fog equations are QD3DStyle.h's (the fog style): the fraction f of a
// pixel's own colour kept at eye distance z is
//   linear               (end - z) / (end - start)
//   exponential          exp(-density z)
//   exponential-squared  exp(-(density z)^2)
//   alpha                the pixel's alpha
// clamped to 0..1, and the pixel becomes f colour + (1 - f) fog colour, as
// OpenGL's fixed-function fog (and so Quesa's interactive renderer) blends.
// z is the distance from the camera plane along the viewing direction, the
// eye-space depth OpenGL's fog uses.

#include "render/SurfaceFinish.h"

namespace q3 {

const char* const kFinishVertexGlsl = R"(
attribute vec4 q3Opacity;
uniform vec4 q3FogDepthPlane;
uniform vec4 q3FogWPlane;
varying vec4 q3VertexOpacity;
varying float q3FogDepth;
varying float q3FogW;

void q3FinishVertex()
{
#ifndef DRAW_OPACITY
    q3VertexOpacity = q3Opacity;
#endif
    q3FogDepth = dot(gl_Position, q3FogDepthPlane);
    q3FogW = dot(gl_Position, q3FogWPlane);
}
)";

const char* const kFinishFragmentGlsl = R"(
uniform int q3FogMode;
uniform float q3FogStart;
uniform float q3FogEnd;
uniform float q3FogDensity;
uniform vec3 q3FogColor;
varying vec4 q3VertexOpacity;
varying float q3FogDepth;
varying float q3FogW;
out vec4 q3FragColor;
#ifdef DRAW_OPACITY
uniform float q3DrawOpacity;
#else
out vec4 q3FragOpacity;
#endif

vec4 q3FinishFragment(vec4 color, float texelAlpha)
{
#ifdef DRAW_OPACITY
    // One grey opacity for the whole draw (1 for opaque draws), blended by
    // alpha alone.
    vec4 opacity = vec4(q3DrawOpacity * texelAlpha);
#else
    vec4 opacity = q3VertexOpacity * texelAlpha;
    q3FragOpacity = opacity; // the blend's second source
#endif
    float a = opacity.a;
    color.a = a;
#ifdef FOG
    if (q3FogMode != 0) {
        float z = q3FogDepth / q3FogW;
        float f;
        if (q3FogMode == 1)
            f = (q3FogEnd - z) / (q3FogEnd - q3FogStart);
        else if (q3FogMode == 2)
            f = exp(-q3FogDensity * z);
        else if (q3FogMode == 3)
            f = exp(-(q3FogDensity * z) * (q3FogDensity * z));
        else
            f = a;
        f = clamp(f, 0.0, 1.0);
        color.rgb = f * color.rgb + (1.0 - f) * q3FogColor;
    }
#endif
    return color;
}
)";

namespace {

constexpr const char* kVersion = "#version 130\n";
// The unlit program always has the fog code (its draws may be fogged or
// not; the uniform q3FogMode says).
constexpr const char* kUnlitSwitches[2] = {"#define FOG 1\n", "#define FOG 1\n#define TEXTURED 1\n"};

constexpr const char* kUnlitDeclarations = R"(
#ifdef TEXTURED
uniform sampler2D surfaceTexture;
#endif
)";

constexpr const char* kUnlitVertex = R"(
void main()
{
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
    gl_FrontColor = gl_Color;
    gl_BackColor = gl_Color;
#ifdef TEXTURED
    gl_TexCoord[0] = gl_MultiTexCoord0;
#endif
    q3FinishVertex();
}
)";

constexpr const char* kUnlitFragment = R"(
void main()
{
    vec4 color = gl_Color;
#ifdef TEXTURED
    vec4 texel = texture2D(surfaceTexture, gl_TexCoord[0].st);
    color.rgb *= texel.rgb;
    q3FragColor = q3FinishFragment(color, texel.a);
#else
    q3FragColor = q3FinishFragment(color, 1.0);
#endif
}
)";

GLuint compileShader(GLenum kind, const char* const* sources, int count, const char* what, std::string& error)
{
    const GLuint shader = glCreateShader(kind);
    glShaderSource(shader, count, sources, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        char log[2048] = {0};
        glGetShaderInfoLog(shader, sizeof log - 1, nullptr, log);
        error = std::string("compiling the ") + what + " shader failed: " + log;
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

} // namespace

GLuint buildFinishProgram(const char* const* vertexSources, const char* const* fragmentSources, int count,
                          const char* what, std::string& error)
{
    const GLuint vertex = compileShader(GL_VERTEX_SHADER, vertexSources, count, what, error);
    if (vertex == 0)
        return 0;
    const GLuint fragment = compileShader(GL_FRAGMENT_SHADER, fragmentSources, count, what, error);
    if (fragment == 0) {
        glDeleteShader(vertex);
        return 0;
    }
    const GLuint program = glCreateProgram();
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    glBindAttribLocation(program, kOpacityAttribute, "q3Opacity");
    glBindFragDataLocationIndexed(program, 0, 0, "q3FragColor");
    glBindFragDataLocationIndexed(program, 0, 1, "q3FragOpacity");
    glLinkProgram(program);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        char log[2048] = {0};
        glGetProgramInfoLog(program, sizeof log - 1, nullptr, log);
        error = std::string("linking the ") + what + " shader failed: " + log;
        glDeleteProgram(program);
        return 0;
    }
    return program;
}

void setDefaultOpacity()
{
    glVertexAttrib4f(kOpacityAttribute, 1.0f, 1.0f, 1.0f, 1.0f);
}

void FinishUniforms::locate(GLuint program)
{
    const auto at = [program](const char* name) { return glGetUniformLocation(program, name); };
    m_mode = at("q3FogMode");
    m_start = at("q3FogStart");
    m_end = at("q3FogEnd");
    m_density = at("q3FogDensity");
    m_color = at("q3FogColor");
    m_depthPlane = at("q3FogDepthPlane");
    m_wPlane = at("q3FogWPlane");
    m_drawOpacity = at("q3DrawOpacity");
}

void FinishUniforms::setDrawOpacity(float opacity) const
{
    glUniform1f(m_drawOpacity, opacity);
}

void FinishUniforms::setFog(const FogSetup& fog) const
{
    int mode = 0;
    switch (fog.mode) {
    case FogSetup::Mode::kOff:
        mode = 0;
        break;
    case FogSetup::Mode::kLinear:
        mode = 1;
        break;
    case FogSetup::Mode::kExponential:
        mode = 2;
        break;
    case FogSetup::Mode::kExponentialSquared:
        mode = 3;
        break;
    case FogSetup::Mode::kAlpha:
        mode = 4;
        break;
    }
    glUniform1i(m_mode, mode);
    glUniform1f(m_start, fog.start);
    glUniform1f(m_end, fog.end);
    glUniform1f(m_density, fog.density);
    glUniform3fv(m_color, 1, fog.color);
    glUniform4fv(m_depthPlane, 1, fog.depthPlane);
    glUniform4fv(m_wPlane, 1, fog.wPlane);
}

bool UnlitProgram::build(std::string& error, bool textured)
{
    const char* const switches = kUnlitSwitches[textured ? 1 : 0];
    const char* const vertex[5] = {kVersion, switches, kUnlitDeclarations, kFinishVertexGlsl, kUnlitVertex};
    const char* const fragment[5] = {kVersion, switches, kUnlitDeclarations, kFinishFragmentGlsl, kUnlitFragment};
    m_program = buildFinishProgram(vertex, fragment, 5, "unlit", error);
    if (m_program == 0)
        return false;
    m_finish.locate(m_program);
    if (textured) {
        glUseProgram(m_program);
        glUniform1i(glGetUniformLocation(m_program, "surfaceTexture"), 0);
        glUseProgram(0);
    }
    return true;
}

void UnlitProgram::release()
{
    if (m_program != 0)
        glDeleteProgram(m_program);
    m_program = 0;
}

} // namespace q3
