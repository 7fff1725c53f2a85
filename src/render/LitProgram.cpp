// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Lighting in GLSL 1.30 (the compatibility profile's built-in attributes:
// gl_Vertex local position, gl_Normal local normal, gl_Color diffuse
// colour; gl_ModelViewProjectionMatrix local to clip). The equations are
// the QD3D Book's ("Illumination Models"), written once in shade():
//
//   Lambert:  I = ka Ia Od + sum_i f_i Ii Od (N . Li)
//   Phong:    I = Lambert + sum_i f_i Ii Os (Ri . V)^n
//
// with Ia the sum of the ambient lights, Ii a light's colour times its
// brightness, f_i its attenuation (1, 1/d or 1/d^2) times, for a spot light,
// its fall-off between the hot angle (full) and the outer angle (none):
// linear 1 - t, exponential (e^(1-t) - 1) / (e - 1), cosine cos(t pi/2),
// with t the angle's place between the two (none: full up to the outer
// angle). Lights behind the surface (N . Li <= 0) add nothing. Vertex
// interpolation evaluates shade() per vertex, pixel interpolation per
// fragment from interpolated normals; back faces use the reversed normal
// when asked (the backfacing style kQ3BackfacingStyleFlip).

#include "render/LitProgram.h"
#include "render/SurfaceFinish.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace q3 {

namespace {

// The first source strings: the version, then the variant's switches
// (LitProgram::variant: TEXTURED, PER_PIXEL, FOG, DIRECTIONAL_ONLY, ONE_SIDED,
// DRAW_OPACITY, PLAIN_VARYINGS, LOCAL_IS_WORLD, LIGHT_COUNT), both before anything else as
// GLSL requires.
constexpr const char* kVersion = "#version 130\n";
// The variant's switches (LitProgram::variant), after the version line.
std::string switches(int variant)
{
    std::string text;
    if ((variant & 1) != 0)
        text += "#define TEXTURED 1\n";
    if ((variant & 2) != 0)
        text += "#define PER_PIXEL 1\n";
    if ((variant & 4) != 0)
        text += "#define FOG 1\n";
    if ((variant & 8) != 0)
        text += "#define DIRECTIONAL_ONLY 1\n";
    if ((variant & 16) != 0)
        text += "#define ONE_SIDED 1\n";
    if ((variant & 64) != 0)
        text += "#define DRAW_OPACITY 1\n";
    if (LitProgram::usesPlainVaryings(variant))
        text += "#define PLAIN_VARYINGS 1\n";
    if ((variant & 128) != 0)
        text += "#define LOCAL_IS_WORLD 1\n";
    if (variant >= 256)
        text += "#define LIGHT_COUNT " + std::to_string(variant / 256 - 1) + "\n";
    return text;
}

constexpr const char* kShade = R"(
// A variant that knows its number of lights sizes the light arrays to it:
// the stage's uniforms are copied into a new constant buffer at every draw
// that changes one, and 32 of each made that about 4 KB a draw.
#if defined(LIGHT_COUNT) && LIGHT_COUNT > 0
#define MAX_LIGHTS LIGHT_COUNT
#elif defined(LIGHT_COUNT)
#define MAX_LIGHTS 1
#else
#define MAX_LIGHTS 32
#endif
uniform int lightCount;
uniform int lightKind[MAX_LIGHTS];
uniform vec3 lightColor[MAX_LIGHTS];
uniform vec3 lightPosition[MAX_LIGHTS];
uniform vec3 lightDirection[MAX_LIGHTS];
uniform int lightAttenuation[MAX_LIGHTS];
uniform float lightHot[MAX_LIGHTS];
uniform float lightOuter[MAX_LIGHTS];
uniform int lightFallOff[MAX_LIGHTS];
uniform vec3 ambientLight;
uniform vec3 eye;
uniform int orthographic;
uniform vec3 viewDirection;
uniform int illumination;
uniform float ambientCoefficient;
uniform vec3 specularColor;
uniform float specularControl;
uniform mat4 localToWorld;
uniform mat3 normalToWorld;
uniform int flipBack;
varying vec3 worldPosition;
varying vec3 worldNormal;
#ifdef TEXTURED
uniform sampler2D surfaceTexture;
#endif
#ifdef PLAIN_VARYINGS
// The ambient and diffuse light (times the diffuse colour, or the whole
// light untextured) and the specular light, each clamped to 0..1 as OpenGL
// clamps gl_FrontColor and gl_FrontSecondaryColor; the texture coordinate.
varying vec3 q3Lit;
varying vec3 q3Specular;
varying vec2 q3St;
#define Q3_ST q3St
#else
#define Q3_ST gl_TexCoord[0].st
#endif

// Light i at p: the unit vector l towards it and its attenuation f (with a
// spot light's fall-off); false where it adds nothing (at the light, or
// outside a spot light's cone).
bool lightAt(int i, vec3 p, out vec3 l, out float f)
{
#ifdef DIRECTIONAL_ONLY
    l = -lightDirection[i];
    f = 1.0;
#else
    f = 1.0;
    if (lightKind[i] == 1) {
        l = -lightDirection[i];
    } else {
        vec3 d = lightPosition[i] - p;
        float distance = length(d);
        if (distance <= 0.0)
            return false;
        l = d / distance;
        if (lightAttenuation[i] == 1)
            f = 1.0 / distance;
        else if (lightAttenuation[i] == 2)
            f = 1.0 / (distance * distance);
        if (lightKind[i] == 3) {
            float angle = acos(clamp(dot(-l, lightDirection[i]), -1.0, 1.0));
            if (angle > lightOuter[i])
                return false;
            if (angle > lightHot[i]) {
                float t = (angle - lightHot[i]) / (lightOuter[i] - lightHot[i]);
                if (lightFallOff[i] == 1)
                    f *= 1.0 - t;
                else if (lightFallOff[i] == 2)
                    f *= (exp(1.0 - t) - 1.0) / (exp(1.0) - 1.0);
                else if (lightFallOff[i] == 3)
                    f *= cos(t * 1.5707963267948966);
            }
        }
    }
#endif
    return true;
}

// The light at p with normal n and diffuse colour od (the equations above)
// in `lit`, and the specular light alone (the same with od = 0) in
// `specular`, in one pass over the lights, the lights' vectors found once.
void shadeTwo(vec3 p, vec3 n, vec3 od, out vec3 lit, out vec3 specular)
{
    lit = ambientCoefficient * ambientLight * od;
    specular = ambientCoefficient * ambientLight * vec3(0.0);
    vec3 toEye = orthographic == 1 ? -viewDirection : normalize(eye - p);
    // A variant that knows the number of lights loops a constant count,
    // which the compiler unrolls (LitProgram::kUnrolledLights).
#ifdef LIGHT_COUNT
    for (int i = 0; i < LIGHT_COUNT; ++i) {
#else
    for (int i = 0; i < MAX_LIGHTS; ++i) {
        if (i >= lightCount)
            break;
#endif
        vec3 l;
        float f;
        if (lightAt(i, p, l, f)) {
            float nl = dot(n, l);
            if (nl > 0.0) {
                lit += f * nl * lightColor[i] * od;
                if (illumination == 2) {
                    vec3 r = 2.0 * nl * n - l;
                    float rv = dot(r, toEye);
                    if (rv > 0.0) {
                        vec3 highlight = f * lightColor[i] * specularColor * pow(rv, specularControl);
                        lit += highlight;
                        specular += highlight;
                    }
                }
            }
        }
    }
}

// The light at p alone (shadeTwo's `lit`; the compiler drops the specular
// sum nothing reads).
vec3 shade(vec3 p, vec3 n, vec3 od)
{
    vec3 lit;
    vec3 specular;
    shadeTwo(p, n, od, lit, specular);
    return lit;
}
)";

constexpr const char* kVertex = R"(
void main()
{
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
#ifdef LOCAL_IS_WORLD
    worldPosition = gl_Vertex.xyz; // w is 1: every position array has three components
    worldNormal = gl_Normal;
#else
    vec4 w = localToWorld * gl_Vertex;
    worldPosition = w.xyz / w.w;
    worldNormal = normalToWorld * gl_Normal;
#endif
#ifdef TEXTURED
#ifdef PLAIN_VARYINGS
    q3St = gl_MultiTexCoord0.st;
#else
    gl_TexCoord[0] = gl_MultiTexCoord0;
#endif
#endif
#ifdef PER_PIXEL
    // Lit in the fragment stage from the interpolated diffuse colour.
    gl_FrontColor = gl_Color;
#ifndef ONE_SIDED
    gl_BackColor = gl_Color;
#endif
#elif defined(TEXTURED)
    // The texel takes the place of the diffuse colour: the ambient and
    // diffuse light (with Od = gl_Color) goes in the primary colour, to be
    // multiplied by the texel; the specular light (shade with Od = 0) in the
    // secondary colour, added after.
    vec3 n = normalize(worldNormal);
    vec3 lit;
    vec3 specular;
    shadeTwo(worldPosition, n, gl_Color.rgb, lit, specular);
#ifdef PLAIN_VARYINGS
    q3Lit = clamp(lit - specular, 0.0, 1.0);
    q3Specular = clamp(specular, 0.0, 1.0);
#else
    gl_FrontColor = vec4(lit - specular, 1.0);
    gl_FrontSecondaryColor = vec4(specular, 1.0);
#endif
#ifndef ONE_SIDED
    if (flipBack == 1) {
        vec3 backLit;
        vec3 backSpecular;
        shadeTwo(worldPosition, -n, gl_Color.rgb, backLit, backSpecular);
        gl_BackColor = vec4(backLit - backSpecular, 1.0);
        gl_BackSecondaryColor = vec4(backSpecular, 1.0);
    } else {
        gl_BackColor = gl_FrontColor;
        gl_BackSecondaryColor = gl_FrontSecondaryColor;
    }
#endif
#else
    vec3 n = normalize(worldNormal);
#ifdef PLAIN_VARYINGS
    q3Lit = clamp(shade(worldPosition, n, gl_Color.rgb), 0.0, 1.0);
#else
    gl_FrontColor = vec4(shade(worldPosition, n, gl_Color.rgb), 1.0);
#endif
#ifndef ONE_SIDED
    gl_BackColor = flipBack == 1 ? vec4(shade(worldPosition, -n, gl_Color.rgb), 1.0) : gl_FrontColor;
#endif
#endif
    q3FinishVertex();
}
)";

constexpr const char* kFragment = R"(
void main()
{
#ifdef TEXTURED
    vec4 texelColor = texture2D(surfaceTexture, Q3_ST);
    vec3 texel = texelColor.rgb;
    float texelAlpha = texelColor.a;
#else
    float texelAlpha = 1.0;
#endif
#ifdef PER_PIXEL
    vec3 n = normalize(worldNormal);
    if (flipBack == 1 && !gl_FrontFacing)
        n = -n;
#ifdef TEXTURED
    q3FragColor = vec4(shade(worldPosition, n, gl_Color.rgb * texel), 1.0);
#else
    q3FragColor = vec4(shade(worldPosition, n, gl_Color.rgb), 1.0);
#endif
#elif defined(TEXTURED) && defined(PLAIN_VARYINGS)
    q3FragColor = vec4(q3Lit * texel + q3Specular, 1.0);
#elif defined(TEXTURED)
    q3FragColor = vec4(gl_Color.rgb * texel + gl_SecondaryColor.rgb, 1.0);
#elif defined(PLAIN_VARYINGS)
    q3FragColor = vec4(q3Lit, 1.0);
#else
    q3FragColor = gl_Color;
#endif
    q3FragColor = q3FinishFragment(q3FragColor, texelAlpha);
}
)";

} // namespace

bool LitProgram::build(std::string& error, int variant)
{
    const bool textured = (variant & 1) != 0;
    const std::string header = switches(variant);
    const char* const vertex[5] = {kVersion, header.c_str(), kShade, kFinishVertexGlsl, kVertex};
    const char* const fragment[5] = {kVersion, header.c_str(), kShade, kFinishFragmentGlsl, kFragment};
    m_shadingLoaded = false;
    m_program = buildFinishProgram(vertex, fragment, 5, "lighting", error);
    if (m_program == 0)
        return false;
    const auto at = [this](const char* name) { return glGetUniformLocation(m_program, name); };
    m_lightCount = at("lightCount");
    m_lightKind = at("lightKind");
    m_lightColor = at("lightColor");
    m_lightPosition = at("lightPosition");
    m_lightDirection = at("lightDirection");
    m_lightAttenuation = at("lightAttenuation");
    m_lightHot = at("lightHot");
    m_lightOuter = at("lightOuter");
    m_lightFallOff = at("lightFallOff");
    m_ambientLight = at("ambientLight");
    m_eye = at("eye");
    m_orthographic = at("orthographic");
    m_viewDirection = at("viewDirection");
    m_illumination = at("illumination");
    m_ambientCoefficient = at("ambientCoefficient");
    m_specularColor = at("specularColor");
    m_specularControl = at("specularControl");
    m_localToWorld = at("localToWorld");
    m_normalToWorld = at("normalToWorld");
    m_flipBack = at("flipBack");
    m_finish.locate(m_program);
    if (textured) {
        // The texture is bound to unit 0.
        glUseProgram(m_program);
        glUniform1i(at("surfaceTexture"), 0);
        glUseProgram(0);
    }
    return true;
}

void LitProgram::release()
{
    if (m_program != 0)
        glDeleteProgram(m_program);
    m_program = 0;
    m_shadingLoaded = false;
}

void LitProgram::use() const
{
    glUseProgram(m_program);
}

void LitProgram::setLighting(const LightingSetup& lighting) const
{
    // Ambient lights add up into one term; the others are listed (at most
    // kMaxLights: OffscreenRenderer::setLighting refuses more).
    float ambient[3] = {0.0f, 0.0f, 0.0f};
    GLint kind[kMaxLights], attenuation[kMaxLights], fallOff[kMaxLights];
    float color[3 * kMaxLights], position[3 * kMaxLights], direction[3 * kMaxLights];
    float hot[kMaxLights], outer[kMaxLights];
    std::size_t listed = 0;
    for (const RenderLight& light : lighting.lights) {
        if (light.kind == RenderLight::Kind::kAmbient) {
            for (int k = 0; k < 3; ++k)
                ambient[k] += light.color[k];
            continue;
        }
        if (listed == kMaxLights)
            break;
        kind[listed] = light.kind == RenderLight::Kind::kDirectional ? 1 : light.kind == RenderLight::Kind::kPoint ? 2 : 3;
        for (int k = 0; k < 3; ++k) {
            color[3 * listed + k] = light.color[k];
            position[3 * listed + k] = light.position[k];
            direction[3 * listed + k] = light.direction[k];
        }
        attenuation[listed] = light.attenuation;
        hot[listed] = light.hotAngle;
        outer[listed] = light.outerAngle;
        fallOff[listed] = light.fallOff;
        ++listed;
    }
    const GLsizei count = GLsizei(listed);
    glUniform1i(m_lightCount, count);
    if (count > 0) {
        glUniform1iv(m_lightKind, count, kind);
        glUniform3fv(m_lightColor, count, color);
        glUniform3fv(m_lightPosition, count, position);
        glUniform3fv(m_lightDirection, count, direction);
        glUniform1iv(m_lightAttenuation, count, attenuation);
        glUniform1fv(m_lightHot, count, hot);
        glUniform1fv(m_lightOuter, count, outer);
        glUniform1iv(m_lightFallOff, count, fallOff);
    }
    glUniform3fv(m_ambientLight, 1, ambient);
    glUniform3fv(m_eye, 1, lighting.eye);
    glUniform1i(m_orthographic, lighting.orthographic ? 1 : 0);
    glUniform3fv(m_viewDirection, 1, lighting.viewDirection);
}

void LitProgram::setShading(const SurfaceShading& shading)
{
    const bool all = !m_shadingLoaded;
    const SurfaceShading was = m_shading;
    m_shading = shading;
    m_shadingLoaded = true;
    if (all || shading.illumination != was.illumination)
        glUniform1i(m_illumination, shading.illumination);
    if (all || shading.ambientCoefficient != was.ambientCoefficient)
        glUniform1f(m_ambientCoefficient, shading.ambientCoefficient);
    if (all || !std::equal(std::begin(shading.specularColor), std::end(shading.specularColor),
                           std::begin(was.specularColor)))
        glUniform3fv(m_specularColor, 1, shading.specularColor);
    if (all || shading.specularControl != was.specularControl)
        glUniform1f(m_specularControl, shading.specularControl);
    if (all || shading.flipBackFaces != was.flipBackFaces)
        glUniform1i(m_flipBack, shading.flipBackFaces ? 1 : 0);
    if (!all && std::equal(std::begin(shading.localToWorld), std::end(shading.localToWorld),
                           std::begin(was.localToWorld)))
        return;
    // localToWorld is in QuickDraw 3D's row-vector layout, which is the
    // column-major layout of the column-vector matrix GLSL multiplies with.
    glUniformMatrix4fv(m_localToWorld, 1, GL_FALSE, shading.localToWorld);
    glm::dmat3 linear;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            linear[i][j] = shading.localToWorld[4 * i + j];
    // Normals go by the inverse transpose; a singular transform (a zero
    // scale) keeps them as they are rather than producing infinities.
    const double determinant = glm::determinant(linear);
    const glm::dmat3 normals =
        determinant != 0.0 && std::isfinite(determinant) ? glm::transpose(glm::inverse(linear)) : linear;
    float normalMatrix[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            normalMatrix[3 * i + j] = float(normals[i][j]);
    glUniformMatrix3fv(m_normalToWorld, 1, GL_FALSE, normalMatrix);
}

} // namespace q3
