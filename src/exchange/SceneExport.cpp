// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// From Q3 objects to a Scene. A Pass walks the objects exactly as a view's
// rendering loop does (groups, push/pop, transforms, styles, shaders,
// attribute sets), so what is exported is what Q3 draws. Each geometry
// decomposes itself into that pass; its triangles, strips, segments and
// points become one mesh, shared between nodes when the same geometry is
// met again under the same material and subdivision. Display groups become
// nodes; a geometry's node carries its whole local-to-world matrix, since a
// QuickDraw 3D transform applies to the objects after it in a group, not to
// a subtree.

#include "exchange/SceneExport.h"

#include "core/AttributeSet.h"
#include "core/EnumValue.h"
#include "core/ErrorManager.h"
#include "core/Error.h"
#include "geometry/Geometry.h"
#include "base/Primitives.h"
#include "group/Group.h"
#include "light/DirectionalLight.h"
#include "light/PointLight.h"
#include "light/SpotLight.h"
#include "shader/Texture.h"
#include "shader/TextureShader.h"
#include "style/SubdivisionStyle.h"
#include "view/BoundsPass.h"
#include "view/Camera.h"
#include "view/Pass.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <functional>
#include <map>
#include <tuple>

namespace q3::exchange {

namespace {

bool isNone(float value)
{
    return value != value;
}

// One 8-bit channel from an n-bit one, as QuickDraw 3D expands them
// (replicating the high bits).
unsigned char expand(std::uint32_t value, int bits)
{
    if (bits == 8)
        return static_cast<unsigned char>(value);
    if (bits == 1)
        return value != 0 ? 255 : 0;
    return static_cast<unsigned char>((value << (8 - bits)) | (value >> (2 * bits - 8)));
}

// A texture's first image as RGBA (QD3DDrawContext.h's pixel layouts).
Image imageOf(const Texture& texture)
{
    const TexturePixels pixels = texture.readImage();
    Image image;
    image.width = pixels.width;
    image.height = pixels.height;
    image.rgba.resize(std::size_t(pixels.width) * pixels.height * 4);
    const int bytes = pixels.pixelType == kQ3PixelTypeRGB32 || pixels.pixelType == kQ3PixelTypeARGB32 ? 4
                      : pixels.pixelType == kQ3PixelTypeRGB24                                          ? 3
                                                                                                       : 2;
    for (std::uint32_t y = 0; y < pixels.height; ++y)
        for (std::uint32_t x = 0; x < pixels.width; ++x) {
            const unsigned char* p = pixels.data() + y * pixels.rowBytes + std::size_t(x) * bytes;
            std::uint32_t word = 0;
            for (int b = 0; b < bytes; ++b)
                word = pixels.byteOrder == kQ3EndianBig ? (word << 8) | p[b] : word | (std::uint32_t(p[b]) << (8 * b));
            unsigned char* out = image.rgba.data() + (std::size_t(y) * pixels.width + x) * 4;
            switch (pixels.pixelType) {
            case kQ3PixelTypeARGB32:
            case kQ3PixelTypeRGB32:
            case kQ3PixelTypeRGB24:
                out[0] = (word >> 16) & 0xff;
                out[1] = (word >> 8) & 0xff;
                out[2] = word & 0xff;
                out[3] = pixels.pixelType == kQ3PixelTypeARGB32 ? (word >> 24) & 0xff : 255;
                break;
            case kQ3PixelTypeARGB16:
            case kQ3PixelTypeRGB16:
                out[0] = expand((word >> 10) & 31, 5);
                out[1] = expand((word >> 5) & 31, 5);
                out[2] = expand(word & 31, 5);
                out[3] = pixels.pixelType == kQ3PixelTypeARGB16 ? expand((word >> 15) & 1, 1) : 255;
                break;
            default: // kQ3PixelTypeRGB16_565
                out[0] = expand((word >> 11) & 31, 5);
                out[1] = expand((word >> 5) & 63, 6);
                out[2] = expand(word & 31, 5);
                out[3] = 255;
                break;
            }
            image.hasAlpha = image.hasAlpha || out[3] != 255;
        }
    return image;
}

float meanOf(const TQ3ColorRGB& c)
{
    return (c.r + c.g + c.b) / 3.0f;
}

// Keeps only the vertices the primitive's indices use, in their first use's
// order: a decomposition's draws share one vertex pool.
void compact(Primitive& p)
{
    const std::size_t count = p.positions.size() / 3;
    std::vector<std::uint32_t> map(count, UINT32_MAX);
    Primitive out;
    out.mode = p.mode;
    out.material = p.material;
    auto copy = [](const std::vector<float>& from, std::vector<float>& to, std::size_t i, int width) {
        if (!from.empty())
            to.insert(to.end(), from.begin() + i * width, from.begin() + (i + 1) * width);
    };
    for (std::uint32_t& index : p.indices) {
        if (map[index] == UINT32_MAX) {
            map[index] = std::uint32_t(out.positions.size() / 3);
            copy(p.positions, out.positions, index, 3);
            copy(p.normals, out.normals, index, 3);
            copy(p.uvs, out.uvs, index, 2);
            copy(p.colors, out.colors, index, 4);
        }
        index = map[index];
    }
    out.indices = std::move(p.indices);
    p = std::move(out);
}

std::array<double, 16> flatten(const Matrix& m)
{
    // Matrix m[i][j] holds QuickDraw 3D's value[i][j] (base/Matrix.h).
    std::array<double, 16> out{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            out[4 * i + j] = m[i][j];
    return out;
}

// A node frame at `origin` whose -z axis is `forward` (a glTF camera or
// light looks down its -z), as a row-vector matrix.
std::array<double, 16> frame(const glm::dvec3& origin, glm::dvec3 forward, glm::dvec3 up)
{
    const glm::dvec3 z = -glm::normalize(forward);
    if (glm::length(glm::cross(up, z)) < 1e-9)
        up = std::fabs(z.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 x = glm::normalize(glm::cross(up, z));
    const glm::dvec3 y = glm::cross(z, x);
    return {x.x, x.y, x.z, 0, y.x, y.y, y.z, 0, z.x, z.y, z.z, 0, origin.x, origin.y, origin.z, 1};
}

std::array<double, 16> compose(const std::array<double, 16>& a, const Matrix& b)
{
    Matrix m(1.0);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            m[i][j] = a[4 * i + j];
    return flatten(then(m, b));
}

// Whether a row-vector matrix is translation x rotation x scale, which a
// glTF node's matrix must be: no projective column, and the three axes
// orthogonal (the scale may differ per axis, and be negative).
bool isTrs(const Matrix& m)
{
    // m[i][j] holds QuickDraw 3D's value[i][j]: rows are the images of the
    // axes, column 3 the projective part.
    if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0)
        return false;
    const glm::dvec3 axes[3] = {glm::dvec3(m[0]), glm::dvec3(m[1]), glm::dvec3(m[2])};
    for (int a = 0; a < 3; ++a)
        for (int b = a + 1; b < 3; ++b) {
            const double scale = glm::length(axes[a]) * glm::length(axes[b]);
            if (scale == 0.0 || std::fabs(glm::dot(axes[a], axes[b])) > 1e-6 * scale)
                return false;
        }
    return true;
}

// A mesh moved into world space by a matrix that is not TRS: positions
// through the matrix (with the divide), normals through its inverse
// transpose, renormalized.
void bake(Mesh& mesh, const Matrix& world)
{
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
    for (Primitive& p : mesh.primitives) {
        for (std::size_t i = 0; i + 2 < p.positions.size(); i += 3) {
            const glm::dvec4 v = transformPoint(world, glm::dvec3(p.positions[i], p.positions[i + 1], p.positions[i + 2]));
            for (int d = 0; d < 3; ++d)
                p.positions[i + d] = float(v[d] / v.w);
        }
        for (std::size_t i = 0; i + 2 < p.normals.size(); i += 3) {
            glm::dvec3 n = normalMatrix * glm::dvec3(p.normals[i], p.normals[i + 1], p.normals[i + 2]);
            const double length = glm::length(n);
            n = length > 0.0 && std::isfinite(length) ? n / length : glm::dvec3(0, 0, 1);
            for (int d = 0; d < 3; ++d)
                p.normals[i + d] = float(n[d]);
        }
    }
}

class ExportPass final : public Pass, private PrimitiveSink {
public:
    ExportPass(Scene& scene, const TQ3SubdivisionStyleData& subdivision, std::optional<Window> window)
        : Pass(std::move(window), defaultAttributes(nullptr)), m_scene(scene),
          m_subdivision(makeShared<SubdivisionStyle>(subdivision))
    {
        allowGroupCulling(false);
        Pass::visitStyle(*m_subdivision);
        m_scene.nodes.emplace_back();
        m_scene.nodes[0].name = "root";
        m_scene.roots.push_back(0);
        m_nodes.push_back(0);
    }

    // The chosen subdivision stands in for every subdivision style.
    void visitStyle(const Style& style) override
    {
        Pass::visitStyle(style);
        Pass::visitStyle(*m_subdivision);
    }

    bool beginGroup(const DisplayGroup& group) override
    {
        if (!Pass::beginGroup(group))
            return false;
        m_nodes.push_back(addNode(group.classInfo().name));
        return true;
    }

    void endGroup(const DisplayGroup& group) override
    {
        m_nodes.pop_back();
        Pass::endGroup(group);
    }

    void visitGeometry(const Geometry& geometry) override
    {
        m_mesh = Mesh{};
        m_mesh.name = geometry.classInfo().name;
        m_materials.clear();
        geometry.decompose(*this, *this);
        if (m_mesh.primitives.empty())
            return;
        const Matrix& world = state().localToWorld;
        if (!isTrs(world)) {
            // glTF allows only translation, rotation and scale in a node
            // (a shear or a projection is invalid): such a mesh is placed
            // in world space itself, under an identity node.
            bake(m_mesh, world);
            m_scene.meshes.push_back(std::move(m_mesh));
            m_scene.nodes[addNode(geometry.classInfo().name)].mesh = int(m_scene.meshes.size() - 1);
            return;
        }
        const auto key = std::make_tuple(&geometry, geometry.editIndex(), m_materials, subdivisionMeasure().key());
        auto found = m_meshes.find(key);
        if (found == m_meshes.end()) {
            found = m_meshes.emplace(key, int(m_scene.meshes.size())).first;
            m_scene.meshes.push_back(std::move(m_mesh));
        }
        const int node = addNode(geometry.classInfo().name);
        m_scene.nodes[node].mesh = found->second;
        setMatrix(node, flatten(state().localToWorld));
    }

    void addCamera(const q3::Camera& camera)
    {
        exchange::Camera out;
        const TQ3CameraData& data = camera.data();
        out.znear = data.range.hither;
        out.zfar = data.range.yon;
        if (const auto* angle = dynamic_cast<const ViewAngleAspectCamera*>(&camera)) {
            const TQ3ViewAngleAspectCameraData d = angle->kindData();
            out.aspect = d.aspectRatioXToY;
            out.yfov = d.aspectRatioXToY >= 1.0f ? d.fov : 2.0 * std::atan(std::tan(d.fov / 2.0) / d.aspectRatioXToY);
        } else if (const auto* ortho = dynamic_cast<const OrthographicCamera*>(&camera)) {
            const TQ3OrthographicCameraData d = ortho->kindData();
            out.perspective = false;
            out.xmag = std::fabs(d.right - d.left) / 2.0;
            out.ymag = std::fabs(d.top - d.bottom) / 2.0;
        }
        const TQ3CameraPlacement& p = data.placement;
        const glm::dvec3 from(p.cameraLocation.x, p.cameraLocation.y, p.cameraLocation.z);
        const glm::dvec3 to(p.pointOfInterest.x, p.pointOfInterest.y, p.pointOfInterest.z);
        const int node = addNode(camera.classInfo().name);
        m_scene.nodes[node].camera = int(m_scene.cameras.size());
        m_scene.cameras.push_back(out);
        setMatrix(node, frame(from, to - from, glm::dvec3(p.upVector.x, p.upVector.y, p.upVector.z)));
    }

    void addLight(const q3::Light& light)
    {
        exchange::Light out;
        std::array<double, 16> placed = flatten(Matrix(1.0));
        auto common = [&](const TQ3LightData& data) {
            out.color = data.color;
            out.intensity = data.brightness;
            return enumValue(data.isOn) != kQ3False;
        };
        bool on = false;
        if (const auto* d = dynamic_cast<const DirectionalLight*>(&light)) {
            on = common(d->data().lightData);
            out.kind = exchange::Light::Kind::kDirectional;
            const TQ3Vector3D v = d->data().direction;
            placed = frame(glm::dvec3(0.0), glm::dvec3(v.x, v.y, v.z), glm::dvec3(0, 1, 0));
        } else if (const auto* pt = dynamic_cast<const PointLight*>(&light)) {
            on = common(pt->data().lightData);
            out.kind = exchange::Light::Kind::kPoint;
            const TQ3Point3D l = pt->data().location;
            placed = frame(glm::dvec3(l.x, l.y, l.z), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0));
        } else if (const auto* s = dynamic_cast<const SpotLight*>(&light)) {
            on = common(s->data().lightData);
            out.kind = exchange::Light::Kind::kSpot;
            const TQ3SpotLightData& d = s->data();
            out.innerCone = d.hotAngle;
            out.outerCone = std::max(d.outerAngle, d.hotAngle + 1e-4f);
            placed = frame(glm::dvec3(d.location.x, d.location.y, d.location.z),
                           glm::dvec3(d.direction.x, d.direction.y, d.direction.z), glm::dvec3(0, 1, 0));
        }
        // Ambient lights have no glTF counterpart (docs/exchange.md).
        if (!on)
            return;
        const int node = addNode(light.classInfo().name);
        m_scene.nodes[node].light = int(m_scene.lights.size());
        m_scene.lights.push_back(out);
        setMatrix(node, compose(placed, state().localToWorld));
    }

private:
    // Q3 has no name elements: a node is named after its class, which also
    // keeps a node with nothing else from being an empty JSON object.
    int addNode(const char* name)
    {
        const int index = int(m_scene.nodes.size());
        m_scene.nodes.emplace_back();
        m_scene.nodes[index].name = name;
        m_scene.nodes[m_nodes.back()].children.push_back(index);
        return index;
    }

    void setMatrix(int node, const std::array<double, 16>& matrix)
    {
        if (matrix != flatten(Matrix(1.0))) {
            m_scene.nodes[node].hasMatrix = true;
            m_scene.nodes[node].matrix = matrix;
        }
    }

    void draw(const MeshView& view, const AttributeSet* own) override
    {
        AttributeValues attributes = state().attributes;
        if (own != nullptr)
            attributes.overlay(own->values());
        Material material;
        material.diffuse = attributes.diffuseColor().value_or(TQ3ColorRGB{1.0f, 1.0f, 1.0f});
        material.alpha = meanOf(attributes.transparencyColor().value_or(TQ3ColorRGB{1.0f, 1.0f, 1.0f}));
        material.specular = attributes.specularColor().value_or(TQ3ColorRGB{0.5f, 0.5f, 0.5f});
        material.specularControl = attributes.specularControl().value_or(4.0f);
        material.illumination = state().draw.illumination;

        // The surface shader: an attribute's, else the one submitted.
        const Texture* texture = nullptr;
        TQ3Matrix3x3 uvTransform = state().draw.uvTransform;
        if (const auto* shader = dynamic_cast<const TextureShader*>(attributes.surfaceShader())) {
            texture = shader->texture().get();
            uvTransform = shader->uvTransform();
            material.uBoundary = shader->uBoundary();
            material.vBoundary = shader->vBoundary();
        } else if (state().draw.texture) {
            texture = static_cast<const Texture*>(state().draw.texture.get());
            material.uBoundary = state().draw.uBoundary;
            material.vBoundary = state().draw.vBoundary;
        }
        if (texture != nullptr) {
            auto found = m_images.find(std::make_pair(texture, texture->editIndex()));
            if (found == m_images.end()) {
                found = m_images.emplace(std::make_pair(texture, texture->editIndex()), int(m_scene.images.size())).first;
                m_scene.images.push_back(imageOf(*texture));
            }
            material.image = found->second;
        }
        material.vertexColors = view.colors != nullptr || view.transparency != nullptr;

        Primitive base;
        base.positions.assign(view.positions, view.positions + 3 * view.vertexCount);
        if (material.vertexColors) {
            base.colors.resize(4 * view.vertexCount);
            float lowest = 1.0f;
            for (std::size_t i = 0; i < view.vertexCount; ++i) {
                const float* c = view.colors != nullptr ? view.colors + 3 * i : nullptr;
                const bool has = c != nullptr && !isNone(c[0]);
                base.colors[4 * i] = has ? c[0] : material.diffuse.r;
                base.colors[4 * i + 1] = has ? c[1] : material.diffuse.g;
                base.colors[4 * i + 2] = has ? c[2] : material.diffuse.b;
                const float* t = view.transparency != nullptr ? view.transparency + 3 * i : nullptr;
                const float a = t != nullptr && !isNone(t[0]) ? (t[0] + t[1] + t[2]) / 3.0f : material.alpha;
                base.colors[4 * i + 3] = a;
                lowest = std::min(lowest, a);
            }
            material.alpha = lowest;
        }
        if (view.uvs != nullptr) {
            base.uvs.resize(2 * view.vertexCount);
            const TQ3Matrix3x3& m = uvTransform;
            for (std::size_t i = 0; i < view.vertexCount; ++i) {
                const float u = isNone(view.uvs[2 * i]) ? 0.0f : view.uvs[2 * i];
                const float v = isNone(view.uvs[2 * i + 1]) ? 0.0f : view.uvs[2 * i + 1];
                if (texture != nullptr) {
                    // The shader's uv transform (row vector [u v 1] * M) is
                    // baked into the uvs: exact for any affine map.
                    base.uvs[2 * i] = u * m.value[0][0] + v * m.value[1][0] + m.value[2][0];
                    base.uvs[2 * i + 1] = u * m.value[0][1] + v * m.value[1][1] + m.value[2][1];
                } else {
                    base.uvs[2 * i] = u;
                    base.uvs[2 * i + 1] = v;
                }
            }
        }
        const int materialIndex = materialFor(material);
        base.material = materialIndex;
        m_materials.push_back(materialIndex);

        if (view.triangleCount != 0) {
            Primitive triangles = litTriangles(view, base);
            compact(triangles);
            m_mesh.primitives.push_back(std::move(triangles));
        }
        for (std::size_t s = 0; s < view.stripCount; ++s) {
            Primitive strip = base;
            strip.mode = Primitive::Mode::kLineStrip;
            for (std::uint32_t k = 0; k < view.strips[s].count; ++k)
                strip.indices.push_back(view.strips[s].first + k);
            compact(strip);
            m_mesh.primitives.push_back(std::move(strip));
        }
        if (view.lineCount != 0) {
            Primitive lines = base;
            lines.mode = Primitive::Mode::kLines;
            lines.indices.assign(view.lines, view.lines + 2 * view.lineCount);
            compact(lines);
            m_mesh.primitives.push_back(std::move(lines));
        }
        if (view.pointCount != 0) {
            Primitive points = base;
            points.mode = Primitive::Mode::kPoints;
            points.indices.assign(view.points, view.points + view.pointCount);
            compact(points);
            m_mesh.primitives.push_back(std::move(points));
        }
    }

    // The triangles with unit normals, as the renderer lights them
    // (view/RenderPass.cpp): when every vertex has a normal, the vertices are
    // shared and keep theirs; otherwise each triangle gets three vertices of
    // its own, a vertex's normal where it has one, else the face normal
    // (counterclockwise front unless the orientation style says clockwise),
    // so that a face without normals stays flat instead of being smoothed
    // with its neighbours.
    Primitive litTriangles(const MeshView& view, const Primitive& base) const
    {
        auto unit = [](glm::dvec3 n) {
            const double length = glm::length(n);
            return length > 0.0 && std::isfinite(length) ? n / length : glm::dvec3(0, 0, 1);
        };
        auto normalAt = [&](std::uint32_t i) {
            return glm::dvec3(view.normals[3 * i], view.normals[3 * i + 1], view.normals[3 * i + 2]);
        };
        bool shared = view.normals != nullptr;
        for (std::size_t k = 0; shared && k < 3 * view.triangleCount; ++k)
            shared = !isNone(view.normals[3 * std::size_t(view.triangles[k])]);
        Primitive out = base;
        if (shared) {
            out.indices.assign(view.triangles, view.triangles + 3 * view.triangleCount);
            out.normals.resize(3 * view.vertexCount);
            for (std::uint32_t i = 0; i < view.vertexCount; ++i) {
                const glm::dvec3 n = isNone(view.normals[3 * i]) ? glm::dvec3(0, 0, 1) : unit(normalAt(i));
                for (int d = 0; d < 3; ++d)
                    out.normals[3 * i + d] = float(n[d]);
            }
            return out;
        }
        const double sign = state().draw.orientation == kQ3OrientationStyleClockwise ? -1.0 : 1.0;
        out.positions.clear();
        out.uvs.clear();
        out.colors.clear();
        auto copy = [](const std::vector<float>& from, std::vector<float>& to, std::uint32_t i, int width) {
            if (!from.empty())
                to.insert(to.end(), from.begin() + std::size_t(i) * width, from.begin() + (std::size_t(i) + 1) * width);
        };
        for (std::size_t t = 0; t < view.triangleCount; ++t) {
            const std::uint32_t* v = view.triangles + 3 * t;
            auto at = [&](int k) {
                const float* p = view.positions + 3 * std::size_t(v[k]);
                return glm::dvec3(p[0], p[1], p[2]);
            };
            const glm::dvec3 face = unit(sign * glm::cross(at(1) - at(0), at(2) - at(0)));
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3 n =
                    view.normals != nullptr && !isNone(view.normals[3 * std::size_t(v[k])]) ? unit(normalAt(v[k])) : face;
                out.indices.push_back(std::uint32_t(out.positions.size() / 3));
                copy(base.positions, out.positions, v[k], 3);
                copy(base.uvs, out.uvs, v[k], 2);
                copy(base.colors, out.colors, v[k], 4);
                for (int d = 0; d < 3; ++d)
                    out.normals.push_back(float(n[d]));
            }
        }
        return out;
    }

    int materialFor(const Material& material)
    {
        for (std::size_t i = 0; i < m_scene.materials.size(); ++i)
            if (m_scene.materials[i] == material)
                return int(i);
        m_scene.materials.push_back(material);
        return int(m_scene.materials.size() - 1);
    }

    Scene& m_scene;
    Ref<SubdivisionStyle> m_subdivision;
    std::vector<int> m_nodes;
    Mesh m_mesh;
    std::vector<int> m_materials;
    std::map<std::tuple<const Geometry*, unsigned long, std::vector<int>, std::vector<double>>, int> m_meshes;
    std::map<std::pair<const Texture*, unsigned long>, int> m_images;
};

// Plain groups, light groups and info groups are containers, not drawables:
// their objects are taken one by one. Drawables, cameras and lights are
// visited; anything else (a string, view hints) has no counterpart in the
// formats and is left out, with kQ3WarningFunctionalityNotSupported when
// `warn`.
template <class Visit>
void walk(const Object& object, const Visit& visit, bool warn)
{
    const auto* group = dynamic_cast<const Group*>(&object);
    if (group != nullptr && dynamic_cast<const DisplayGroup*>(group) == nullptr) {
        for (const Group::Node& node : group->nodes())
            if (node.object)
                walk(*node.object, visit, warn);
        return;
    }
    if (object.isDrawable() || dynamic_cast<const q3::Camera*>(&object) != nullptr ||
        dynamic_cast<const q3::Light*>(&object) != nullptr)
        visit(object);
    else if (warn)
        errors::postWarning(kQ3WarningFunctionalityNotSupported,
                            std::string("a ") + object.classInfo().name + " has no counterpart in the file: left out");
}

double diagonalOf(const Object& root)
{
    BoundsPass bounds(kQ3ComputeBoundsApproximate, std::nullopt, defaultAttributes(nullptr));
    bounds.allowGroupCulling(false);
    walk(
        root,
        [&](const Object& object) {
            if (dynamic_cast<const q3::Camera*>(&object) == nullptr && dynamic_cast<const q3::Light*>(&object) == nullptr)
                object.accept(bounds);
        },
        false);
    const TQ3BoundingBox box = bounds.box();
    if (enumValue(box.isEmpty) != kQ3False)
        return 1.0;
    const glm::dvec3 d(box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z);
    const double length = glm::length(d);
    return length > 0.0 && std::isfinite(length) ? length : 1.0;
}

} // namespace

bool Material::operator==(const Material& o) const
{
    return diffuse.r == o.diffuse.r && diffuse.g == o.diffuse.g && diffuse.b == o.diffuse.b && alpha == o.alpha &&
           specular.r == o.specular.r && specular.g == o.specular.g && specular.b == o.specular.b &&
           specularControl == o.specularControl && illumination == o.illumination && image == o.image &&
           uBoundary == o.uBoundary && vBoundary == o.vBoundary && vertexColors == o.vertexColors;
}

double roughnessFromSpecularControl(double control)
{
    return std::pow(2.0 / (std::max(control, 0.0) + 2.0), 0.25);
}

double specularControlFromRoughness(double roughness)
{
    const double r = std::clamp(roughness, 1e-3, 1.0);
    return 2.0 / std::pow(r, 4.0) - 2.0;
}

Scene sceneFrom(const Object& root, const SubdivisionChoice& choice)
{
    TQ3SubdivisionStyleData style = choice.style;
    if (choice.fromBounds)
        style = TQ3SubdivisionStyleData{kQ3SubdivisionMethodWorldSpace, float(diagonalOf(root) / 32.0),
                                       float(diagonalOf(root) / 32.0)};
    Scene scene;
    ExportPass pass(scene, style, choice.window);
    // Cameras and lights are in world coordinates; a display group holds
    // them without drawing them (Q3Exchange_Read puts them there), so they
    // are gathered from inside display groups too, after the drawing.
    std::function<void(const Object&)> undrawn = [&](const Object& object) {
        if (const auto* camera = dynamic_cast<const q3::Camera*>(&object))
            pass.addCamera(*camera);
        else if (const auto* light = dynamic_cast<const q3::Light*>(&object))
            pass.addLight(*light);
        else if (const auto* group = dynamic_cast<const Group*>(&object))
            for (const Group::Node& node : group->nodes())
                if (node.object)
                    undrawn(*node.object);
    };
    walk(root, [&](const Object& object) {
        if (dynamic_cast<const q3::Camera*>(&object) != nullptr || dynamic_cast<const q3::Light*>(&object) != nullptr) {
            undrawn(object);
            return;
        }
        object.accept(pass);
        if (dynamic_cast<const DisplayGroup*>(&object) != nullptr)
            undrawn(object);
    }, true);
    return scene;
}

} // namespace q3::exchange
