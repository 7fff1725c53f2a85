// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/RenderPass.h"

#include "geometry/Geometry.h"
#include "shader/Shader.h"
#include "shader/Texture.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <iterator>
#include <cmath>
#include <cstring>
#include <string>

namespace q3 {

namespace {

RgbColor toRgb(const TQ3ColorRGB& color)
{
    return RgbColor{color.r, color.g, color.b};
}

} // namespace

void throwIfFailed(const RenderResult& result, const char* what)
{
    switch (result.status) {
    case RenderStatus::kOk:
        return;
    case RenderStatus::kOutOfMemory:
        fail(kQ3ErrorOutOfMemory, std::string(what) + ": " + result.message);
    case RenderStatus::kInvalidArgument:
        fail(kQ3ErrorInvalidParameter, std::string(what) + ": " + result.message);
    default:
        fail(kQ3ErrorRenderingLoopFailed, std::string(what) + ": " + result.message);
    }
}

Matrix frustumToClip()
{
    Matrix m(1.0);
    m[2][2] = -2.0;
    m[3][2] = -1.0;
    return m;
}

void RenderPass::loadMatrix()
{
    const Matrix localToClip =
        then(then(state().localToWorld, window()->worldToFrustum), frustumToClip());
    if (m_loaded && *m_loaded == localToClip)
        return;
    throwIfFailed(m_target.setMatrix(&localToClip[0][0]), "setting the drawing matrix");
    m_loaded = localToClip;
}

void RenderPass::visitGeometry(const Geometry& geometry)
{
    geometry.decompose(*this, *this);
}

void RenderPass::loadFaces()
{
    const DrawState& styles = state().draw;
    FaceOptions faces;
    faces.cullBack = styles.backfacing == kQ3BackfacingStyleRemove;
    faces.clockwiseFront = styles.orientation == kQ3OrientationStyleClockwise;
    if (m_loadedFaces && *m_loadedFaces == faces)
        return;
    throwIfFailed(m_target.setFaceOptions(faces), "setting the face options");
    m_loadedFaces = faces;
}

void RenderPass::loadAntiAlias()
{
    // The anti-alias style's mode: edges smooths points and lines (and
    // surfaces drawn as edges or points), filled smooths filled triangles.
    const TQ3AntiAliasStyleData& style = state().draw.antiAlias;
    AntiAliasOptions options;
    if (style.state == kQ3On) {
        options.lines = (style.mode & kQ3AntiAliasModeMaskEdges) != 0;
        options.triangles = (style.mode & kQ3AntiAliasModeMaskFilled) != 0;
    }
    if (m_loadedAntiAlias ? *m_loadedAntiAlias == options : options == AntiAliasOptions{})
        return;
    throwIfFailed(m_target.setAntiAlias(options), "setting the anti-aliasing");
    m_loadedAntiAlias = options;
}

void RenderPass::loadFog()
{
    const TQ3FogStyleData& fog = state().draw.fog;
    const bool off = fog.state != kQ3On;
    if (m_loadedFog && (off ? m_loadedFog->state != kQ3On : std::memcmp(&*m_loadedFog, &fog, sizeof fog) == 0))
        return;
    if (!m_loadedFog && off) {
        m_loadedFog = fog;
        return;
    }
    FogSetup setup;
    if (!off) {
        if (!m_fogPlanes) {
            // Clip coordinates c = w * C for the world point w (row vectors),
            // so w = c * C^-1 and the eye distance (w - eye) . view is c times
            // C^-1 applied to the plane (view, -eye . view); w's own fourth
            // coordinate, 1 for every point drawn, is c * C^-1's last column.
            const Matrix worldToClip = then(window()->worldToFrustum, frustumToClip());
            const Matrix clipToWorld = glm::inverse(worldToClip);
            const SceneLighting& scene = m_style.lighting;
            glm::dvec3 view = scene.viewDirection;
            const double length = glm::length(view);
            view = length > 0.0 && std::isfinite(length) ? view / length : glm::dvec3(0.0, 0.0, -1.0);
            const double plane[4] = {view.x, view.y, view.z, -glm::dot(scene.eye, view)};
            FogSetup planes;
            for (int i = 0; i < 4; ++i) {
                double depth = 0.0;
                for (int j = 0; j < 4; ++j)
                    depth += clipToWorld[i][j] * plane[j];
                planes.depthPlane[i] = float(depth);
                planes.wPlane[i] = float(clipToWorld[i][3]);
            }
            m_fogPlanes = planes;
        }
        setup = *m_fogPlanes;
        setup.mode = fog.mode == kQ3FogModeExponential          ? FogSetup::Mode::kExponential
                     : fog.mode == kQ3FogModeExponentialSquared ? FogSetup::Mode::kExponentialSquared
                     : fog.mode == kQ3FogModeAlpha              ? FogSetup::Mode::kAlpha
                                                                : FogSetup::Mode::kLinear;
        setup.start = fog.fogStart;
        setup.end = fog.fogEnd;
        setup.density = fog.density;
        setup.color[0] = fog.color.r;
        setup.color[1] = fog.color.g;
        setup.color[2] = fog.color.b;
    }
    throwIfFailed(m_target.setFog(setup), "setting the fog");
    m_loadedFog = fog;
}

namespace {

// A channel of QuickDraw 3D's transparency colour as an opacity, clamped to
// 0..1 (NaN: 0).
float opacityOf(float channel)
{
    return channel >= 1.0f ? 1.0f : channel > 0.0f ? channel : 0.0f;
}

// One level of a texture as the render target reads it: the pixels where
// they are, and their layout with the checked values of its enumerations (the
// texture's data rules).
TextureLevel levelOf(const TexturePixels& pixels)
{
    TextureLevel level;
    level.pixels = pixels.data();
    level.layout.width = pixels.width;
    level.layout.height = pixels.height;
    level.layout.rowBytes = std::uint32_t(pixels.rowBytes);
    level.layout.pixelType = PixelType(pixels.pixelType);
    level.layout.byteOrder = ByteOrder(pixels.byteOrder);
    return level;
}

} // namespace

// The transparency colour is kept per channel (OpacitySetup): the QD3D Book
// blends each of r, g, b with its own opacity.
void RenderPass::prepareOpacity(const MeshView& mesh, const AttributeValues& attributes,
                                bool highlightTransparency)
{
    const TQ3ColorRGB all = attributes.transparencyColor().value_or(TQ3ColorRGB{1.0f, 1.0f, 1.0f});
    m_opacity = OpacitySetup{};
    m_opacity.uniform = RgbColor{opacityOf(all.r), opacityOf(all.g), opacityOf(all.b)};
    if (mesh.transparency == nullptr || highlightTransparency)
        return;
    m_opacityRgb.resize(3 * mesh.vertexCount);
    const float uniform[3] = {m_opacity.uniform.r, m_opacity.uniform.g, m_opacity.uniform.b};
    bool varies = false;
    for (std::size_t i = 0; i < mesh.vertexCount; ++i) {
        const float* t = mesh.transparency + 3 * i;
        // A vertex without its own transparency (NaN) takes the uniform one.
        const bool own = t[0] == t[0];
        for (int c = 0; c < 3; ++c) {
            const float value = own ? opacityOf(t[c]) : uniform[c];
            m_opacityRgb[3 * i + c] = value;
            varies = varies || value != uniform[c];
        }
    }
    if (!varies)
        return;
    m_opacity.rgb = m_opacityRgb.data();
    m_opacity.count = mesh.vertexCount;
}

RenderPass::TextureChoice RenderPass::textureOf(const DrawState& state)
{
    TextureChoice choice;
    choice.texture = state.texture.get();
    choice.uvTransform = state.uvTransform;
    choice.clampS = state.uBoundary == kQ3ShaderUVBoundaryClamp;
    choice.clampT = state.vBoundary == kQ3ShaderUVBoundaryClamp;
    return choice;
}

RenderPass::TextureChoice RenderPass::textureOf(const SharedObject* shader)
{
    // An attribute set holds only surface shaders (AttributeValues), which
    // set the state's texture as when they are submitted.
    DrawState state;
    static_cast<const Shader&>(*shader).apply(state);
    return textureOf(state);
}

std::uint32_t RenderPass::loadTexture(const TextureChoice& choice)
{
    if (choice.texture == nullptr)
        return kNoTexture;
    const Texture& texture = static_cast<const Texture&>(*choice.texture);
    const LoadedTexture* loaded = nullptr;
    for (const LoadedTexture& candidate : m_textures)
        if (candidate.texture.get() == &texture && candidate.edit == texture.editIndex() &&
            candidate.clampS == choice.clampS && candidate.clampT == choice.clampT) {
            loaded = &candidate;
            break;
        }
    if (loaded == nullptr) {
        // Read in place where the storage holds them in memory: the target
        // compares them with what it keeps, or copies them, before
        // addTexture returns, so a frame of unchanged textures copies
        // nothing.
        const TexturePixels pixels = texture.readImage(PixelAccess::kInPlace);
        const std::vector<TexturePixels> mipmaps = m_style.textureFilter == TextureFilter::kTrilinear
                                                       ? texture.readMipmaps(PixelAccess::kInPlace)
                                                       : std::vector<TexturePixels>{};
        const TextureLevel top = levelOf(pixels);
        TextureImage image{top.pixels, top.layout, choice.clampS, choice.clampT, m_style.textureFilter, {}, {}};
        for (const TexturePixels& mipmap : mipmaps)
            image.mipmaps.push_back(levelOf(mipmap));
        // Bytes of a storage Q3 owns are known by its version and their
        // offsets, and the target finds them again without comparing them.
        bool known = pixels.sourceVersion != 0;
        for (const TexturePixels& mipmap : mipmaps)
            known = known && mipmap.sourceVersion != 0;
        if (known) {
            image.sourceKey = {pixels.sourceVersion, pixels.sourceOffset};
            for (const TexturePixels& mipmap : mipmaps)
                image.sourceKey.insert(image.sourceKey.end(), {mipmap.sourceVersion, mipmap.sourceOffset});
        }
        LoadedTexture entry{Ref<SharedObject>::retain(const_cast<Texture*>(&texture)), texture.editIndex(),
                            choice.clampS, choice.clampT, 0};
        throwIfFailed(m_target.addTexture(image, entry.id), "setting the texture");
        m_textures.push_back(std::move(entry));
        loaded = &m_textures.back();
    }
    return loaded->id;
}

const float* RenderPass::textureCoordinates(const MeshView& mesh, const TextureChoice& choice, std::uint32_t& id)
{
    id = kNoTexture;
    if (choice.texture == nullptr || mesh.uvs == nullptr)
        return nullptr;
    // The target puts the uvs through the uv transform (Shading::uvs). A
    // vertex without a uv (NaN) gets (0, 0) if no triangle uses it; a
    // triangle that does leaves the mesh untextured.
    const float* uvs = mesh.uvs;
    // A retained mesh's were looked at once (MeshView::uvsComplete): the
    // scan read them every frame, which a mesh drawn from kept vertex data
    // otherwise never does (cache misses).
    bool lacking = false;
    if (!mesh.uvsComplete)
        for (std::size_t i = 0; i < mesh.vertexCount; ++i)
            lacking |= mesh.uvs[2 * i] != mesh.uvs[2 * i];
    if (lacking) {
        for (std::size_t i = 0; i < 3 * mesh.triangleCount; ++i)
            if (mesh.uvs[2 * std::size_t(mesh.triangles[i])] != mesh.uvs[2 * std::size_t(mesh.triangles[i])])
                return nullptr;
        m_uvs.assign(mesh.uvs, mesh.uvs + 2 * mesh.vertexCount);
        for (std::size_t i = 0; i < mesh.vertexCount; ++i)
            if (m_uvs[2 * i] != m_uvs[2 * i])
                m_uvs[2 * i] = m_uvs[2 * i + 1] = 0.0f;
        uvs = m_uvs.data();
    }
    id = loadTexture(choice);
    return id == kNoTexture ? nullptr : uvs;
}

void RenderPass::drawFilled(const MeshView& mesh, const Shading& base, const AttributeValues& attributes,
                            const TextureChoice& texture)
{
    const DrawState& styles = state().draw;
    Shading shading = base;
    // A texture takes the place of the diffuse colour.
    std::uint32_t id = kNoTexture;
    const float* uvs = textureCoordinates(mesh, texture, id);
    if (uvs != nullptr) {
        shading.rgb = nullptr;
        shading.color = RgbColor{1.0f, 1.0f, 1.0f};
        shading.uvs = uvs;
        shading.texture = id;
        const TQ3Matrix3x3& m = texture.uvTransform;
        const float transform[6] = {m.value[0][0], m.value[0][1], m.value[1][0],
                                    m.value[1][1], m.value[2][0], m.value[2][1]};
        std::copy(std::begin(transform), std::end(transform), std::begin(shading.stTransform));
    }
    shading.smooth = styles.interpolation != kQ3InterpolationStyleNone;
    shading.opacity = m_opacity;
    if (styles.illumination == kQ3IlluminationTypeLambert || styles.illumination == kQ3IlluminationTypePhong) {
        loadLights();
        shading.lit = true;
        shading.surface = surfaceShading(attributes);
        shading.clockwiseFront = styles.orientation == kQ3OrientationStyleClockwise;
    }
    throwIfFailed(m_target.draw(mesh, shading), "drawing triangles");
}

void RenderPass::draw(const MeshView& mesh, const AttributeSet* own)
{
    const DrawState& styles = state().draw;
    // The attributes in force: the geometry's own over the state's, and the
    // highlight style's over both where the highlight state is on.
    AttributeValues attributes = state().attributes;
    if (own != nullptr)
        attributes.overlay(own->values());
    const bool highlighted = styles.highlight && attributes.highlightState().value_or(kQ3Off) == kQ3On;
    if (highlighted)
        attributes.overlay(styles.highlight->values());
    const RgbColor color = toRgb(attributes.diffuseColor().value_or(TQ3ColorRGB{1.0f, 1.0f, 1.0f}));
    loadMatrix();
    loadAntiAlias();
    loadFog();

    // Per-vertex colours, with what a vertex lacks taken from its geometry
    // or the state (a highlight colours the whole geometry).
    const float* rgb = nullptr;
    if (mesh.colors != nullptr && !(highlighted && styles.highlight->diffuseColor())) {
        m_colors.assign(mesh.colors, mesh.colors + 3 * mesh.vertexCount);
        for (std::size_t i = 0; i < mesh.vertexCount; ++i)
            if (m_colors[3 * i] != m_colors[3 * i]) {
                m_colors[3 * i] = color.r;
                m_colors[3 * i + 1] = color.g;
                m_colors[3 * i + 2] = color.b;
            }
        rgb = m_colors.data();
    }

    Shading shading;
    shading.rgb = rgb;
    shading.color = color;
    // The wireframe renderer draws edges (or points, under the points fill
    // style), also of meshes that have only edges; the interactive renderer
    // as the fill style says.
    shading.fill = styles.fill == kQ3FillStylePoints  ? Shading::Fill::kPoints
                   : styles.fill == kQ3FillStyleEdges ? Shading::Fill::kEdges
                   : m_style.fillTriangles            ? Shading::Fill::kFilled
                                                      : Shading::Fill::kEdges;
    shading.edgesAlone = !m_style.fillTriangles;

    // The mesh's screen-space images are drawn below, not by the target.
    MeshView primitives = mesh;
    primitives.bitmaps = nullptr;
    primitives.bitmapCount = 0;
    primitives.pixmaps = nullptr;
    primitives.pixmapCount = 0;
    if (mesh.triangleCount == 0 || shading.fill != Shading::Fill::kFilled) {
        throwIfFailed(m_target.draw(primitives, shading), "drawing a mesh");
    } else {
        loadFaces();
        prepareOpacity(mesh, attributes, highlighted && styles.highlight->transparencyColor());
        // The filled triangles first, one draw per surface shader: a
        // highlight's over everything; else each triangle's own, else the
        // geometry's, else the view's.
        MeshView triangles = primitives;
        triangles.lines = nullptr;
        triangles.lineCount = 0;
        triangles.strips = nullptr;
        triangles.stripCount = 0;
        triangles.points = nullptr;
        triangles.pointCount = 0;
        const SharedObject* over = highlighted ? styles.highlight->shader() : nullptr;
        const SharedObject* geometryShader = own != nullptr ? own->shader() : nullptr;
        const TextureChoice base = over != nullptr             ? textureOf(over)
                                   : geometryShader != nullptr ? textureOf(geometryShader)
                                                               : textureOf(styles);
        if (over != nullptr || mesh.triangleShaders == nullptr) {
            drawFilled(triangles, shading, attributes, base);
        } else {
            // Triangles gathered by shader with a counting sort (group k:
            // shader k, 0 for none).
            m_runStarts.assign(mesh.shaderCount + 2, 0);
            for (std::size_t t = 0; t < mesh.triangleCount; ++t)
                ++m_runStarts[mesh.triangleShaders[t] + 1];
            for (std::size_t k = 1; k < m_runStarts.size(); ++k)
                m_runStarts[k] += m_runStarts[k - 1];
            m_runs.resize(3 * mesh.triangleCount);
            m_runNext.assign(m_runStarts.begin(), m_runStarts.end() - 1);
            for (std::size_t t = 0; t < mesh.triangleCount; ++t) {
                const std::size_t at = 3 * m_runNext[mesh.triangleShaders[t]]++;
                for (int k = 0; k < 3; ++k)
                    m_runs[at + k] = mesh.triangles[3 * t + k];
            }
            for (std::size_t k = 0; k <= mesh.shaderCount; ++k) {
                const std::size_t first = m_runStarts[k], count = m_runStarts[k + 1] - first;
                if (count == 0)
                    continue;
                MeshView run = triangles;
                run.triangles = m_runs.data() + 3 * first;
                run.triangleCount = count;
                run.serial = 0; // its triangles are not the mesh's
                drawFilled(run, shading, attributes, k == 0 ? base : textureOf(mesh.shaders[k - 1].get()));
            }
        }
        // Then the rest of the mesh (filled triangles show no edges).
        if (mesh.lineCount != 0 || mesh.stripCount != 0 || mesh.pointCount != 0) {
            MeshView rest = primitives;
            rest.triangles = nullptr;
            rest.triangleCount = 0;
            rest.triangleShaders = nullptr;
            rest.edges = nullptr;
            rest.edgeCount = 0;
            throwIfFailed(m_target.draw(rest, shading), "drawing a mesh");
        }
    }
    for (std::size_t b = 0; b < mesh.bitmapCount; ++b) {
        const ScreenBitmap& bitmap = mesh.bitmaps[b];
        const BitmapImage image{bitmap.bits,     bitmap.rowBytes, bitmap.width,  bitmap.height,
                                bitmap.lsbFirst, bitmap.xOffset,  bitmap.yOffset};
        const float* own = rgb != nullptr ? rgb + 3 * std::size_t(bitmap.vertex) : nullptr;
        const RgbColor ink = own != nullptr ? RgbColor{own[0], own[1], own[2]} : color;
        throwIfFailed(m_target.drawBitmap(mesh.positions + 3 * std::size_t(bitmap.vertex), image, ink),
                      "drawing a marker");
    }
    for (std::size_t p = 0; p < mesh.pixmapCount; ++p) {
        const ScreenPixmap& pixmap = mesh.pixmaps[p];
        PixmapImage image;
        image.pixels = pixmap.bytes;
        image.layout.width = pixmap.width;
        image.layout.height = pixmap.height;
        image.layout.rowBytes = std::uint32_t(pixmap.rowBytes);
        image.layout.pixelType = PixelType(pixmap.pixelType);
        image.layout.byteOrder = ByteOrder(pixmap.byteOrder);
        image.xOffset = pixmap.xOffset;
        image.yOffset = pixmap.yOffset;
        throwIfFailed(m_target.drawPixmap(mesh.positions + 3 * std::size_t(pixmap.vertex), image),
                      "drawing a pixmap marker");
    }
}

namespace {

// A unit vector, or +z for one that has no direction.
glm::vec3 unit(const glm::vec3& v)
{
    const float length = glm::length(v);
    return length > 0.0f && std::isfinite(length) ? v / length : glm::vec3(0.0f, 0.0f, 1.0f);
}

RenderLight toRenderLight(const LightSource& source)
{
    RenderLight light;
    switch (source.type) {
    case kQ3LightTypeDirectional:
        light.kind = RenderLight::Kind::kDirectional;
        break;
    case kQ3LightTypePoint:
        light.kind = RenderLight::Kind::kPoint;
        break;
    case kQ3LightTypeSpot:
        light.kind = RenderLight::Kind::kSpot;
        break;
    default:
        light.kind = RenderLight::Kind::kAmbient;
        break;
    }
    const float scale = source.on ? source.brightness : 0.0f;
    light.color[0] = source.color.r * scale;
    light.color[1] = source.color.g * scale;
    light.color[2] = source.color.b * scale;
    light.position[0] = source.location.x;
    light.position[1] = source.location.y;
    light.position[2] = source.location.z;
    const glm::vec3 direction = unit(glm::vec3(source.direction.x, source.direction.y, source.direction.z));
    light.direction[0] = direction.x;
    light.direction[1] = direction.y;
    light.direction[2] = direction.z;
    light.attenuation = int(source.attenuation);
    light.hotAngle = source.hotAngle;
    light.outerAngle = source.outerAngle;
    light.fallOff = int(source.fallOff);
    return light;
}

} // namespace

void RenderPass::loadLights()
{
    if (m_lightsLoaded)
        return;
    LightingSetup setup;
    for (const LightSource& source : m_style.lighting.lights) {
        if (setup.lights.size() == kMaxLights)
            break;
        setup.lights.push_back(toRenderLight(source));
    }
    const SceneLighting& scene = m_style.lighting;
    const glm::vec3 look = unit(glm::vec3(scene.viewDirection));
    for (int k = 0; k < 3; ++k) {
        setup.eye[k] = float(scene.eye[k]);
        setup.viewDirection[k] = look[k];
    }
    setup.orthographic = scene.orthographic;
    throwIfFailed(m_target.setLighting(setup), "setting the lights");
    m_lightsLoaded = true;
}

SurfaceShading RenderPass::surfaceShading(const AttributeValues& attributes) const
{
    const DrawState& styles = state().draw;
    SurfaceShading shading;
    const Matrix& toWorld = state().localToWorld;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            shading.localToWorld[4 * i + j] = float(toWorld[i][j]);
    shading.illumination = styles.illumination == kQ3IlluminationTypePhong ? 2 : 1;
    shading.ambientCoefficient = attributes.ambientCoefficient().value_or(1.0f);
    const TQ3ColorRGB specular = attributes.specularColor().value_or(TQ3ColorRGB{0.5f, 0.5f, 0.5f});
    shading.specularColor[0] = specular.r;
    shading.specularColor[1] = specular.g;
    shading.specularColor[2] = specular.b;
    shading.specularControl = attributes.specularControl().value_or(4.0f);
    shading.interpolation = styles.interpolation == kQ3InterpolationStyleNone    ? 0
                            : styles.interpolation == kQ3InterpolationStylePixel ? 2
                                                                                 : 1;
    shading.flipBackFaces = styles.backfacing == kQ3BackfacingStyleFlip;
    return shading;
}

} // namespace q3
