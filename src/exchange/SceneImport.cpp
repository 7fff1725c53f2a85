// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

#include "exchange/SceneImport.h"

#include "QD3DMath.h"

#include "core/AttributeSet.h"
#include "core/Error.h"
#include "core/Limits.h"
#include "geometry/Point.h"
#include "geometry/PolyLine.h"
#include "base/Primitives.h"
#include "geometry/TriMesh.h"
#include "group/Group.h"
#include "base/Storage.h"
#include "light/DirectionalLight.h"
#include "light/PointLight.h"
#include "light/SpotLight.h"
#include "shader/IlluminationShaders.h"
#include "shader/Texture.h"
#include "shader/TextureShader.h"
#include "view/Camera.h"
#include "view/Transform.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace q3::exchange {

namespace {

class Builder {
public:
    explicit Builder(const Scene& scene)
        : m_scene(scene), m_textures(scene.images.size()), m_sets(scene.materials.size()),
          m_meshes(scene.meshes.size()), m_visiting(scene.nodes.size(), false)
    {
    }

    Ref<DisplayGroup> root()
    {
        Ref<DisplayGroup> group = makeShared<DisplayGroup>();
        TQ3ObjectType illumination = kQ3IlluminationTypePhong;
        if (!m_scene.materials.empty())
            illumination = m_scene.materials.front().illumination;
        if (illumination == kQ3IlluminationTypeLambert)
            group->add(makeShared<LambertIllumination>());
        else if (illumination == kQ3IlluminationTypeNULL)
            group->add(makeShared<NULLIllumination>());
        else
            group->add(makeShared<PhongIllumination>());
        for (int node : m_scene.roots)
            group->add(nodeGroup(node, 0, glm::dmat4(1.0)));
        // Cameras and lights are placed in world coordinates, as QuickDraw
        // 3D's are; a display group holds them without drawing them, so a
        // program finds them by type (Q3Group_GetFirstPositionOfType).
        for (const Ref<SharedObject>& camera : m_cameras)
            group->add(camera);
        if (!m_lights.empty()) {
            Ref<LightGroup> lights = makeShared<LightGroup>();
            for (const Ref<SharedObject>& light : m_lights)
                lights->add(light);
            group->add(lights);
        }
        return group;
    }

private:
    Ref<DisplayGroup> nodeGroup(int index, std::size_t depth, const glm::dmat4& parent)
    {
        if (depth >= limits::kMaxGroupNesting)
            fail(kQ3ErrorInvalidData, "nodes nest deeper than kQ3GroupMaxNesting");
        if (m_visiting[index])
            fail(kQ3ErrorInvalidData, "node " + std::to_string(index) + " is its own descendant");
        m_visiting[index] = true;
        const Node& node = m_scene.nodes[index];
        glm::dmat4 world = parent;
        if (node.hasMatrix) {
            glm::dmat4 m(1.0);
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    m[i][j] = node.matrix[4 * i + j];
            world = parent * m;
        }
        if (node.camera >= 0)
            m_cameras.push_back(camera(m_scene.cameras[node.camera], world));
        if (node.light >= 0)
            m_lights.push_back(light(m_scene.lights[node.light], world));
        Ref<DisplayGroup> group = makeShared<DisplayGroup>();
        if (node.hasMatrix) {
            TQ3Matrix4x4 m;
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    m.value[i][j] = float(node.matrix[4 * i + j]);
            group->add(makeShared<MatrixTransform>(m));
        }
        if (node.mesh >= 0) {
            if (std::size_t(node.mesh) >= m_scene.meshes.size())
                fail(kQ3ErrorInvalidData, "node " + std::to_string(index) + " refers to no mesh");
            for (const Ref<SharedObject>& geometry : meshObjects(node.mesh))
                group->add(geometry);
        }
        for (int child : node.children)
            group->add(nodeGroup(child, depth + 1, world));
        m_visiting[index] = false;
        return group;
    }

    const std::vector<Ref<SharedObject>>& meshObjects(int index)
    {
        std::vector<Ref<SharedObject>>& objects = m_meshes[index];
        if (!objects.empty() || m_scene.meshes[index].primitives.empty())
            return objects;
        for (const Primitive& p : m_scene.meshes[index].primitives) {
            const AttributeSet* set = p.material >= 0 ? attributeSet(p.material).get() : nullptr;
            if (p.mode == Primitive::Mode::kTriangles) {
                if (!p.indices.empty())
                    objects.push_back(triMesh(p, set));
            } else if (p.mode == Primitive::Mode::kLineStrip) {
                if (p.indices.size() >= 2)
                    objects.push_back(polyLine(p, p.indices, set));
            } else if (p.mode == Primitive::Mode::kPoints) {
                for (std::uint32_t i : p.indices) {
                    const TQ3PointData data{
                        TQ3Point3D{p.positions[3 * std::size_t(i)], p.positions[3 * std::size_t(i) + 1],
                                   p.positions[3 * std::size_t(i) + 2]},
                        // The point takes its own reference to the set.
                        const_cast<AttributeSet*>(set)};
                    Point::checkData(data);
                    objects.push_back(makeShared<Point>(data));
                }
            } else if (p.mode == Primitive::Mode::kLines) {
                for (std::size_t k = 0; k + 1 < p.indices.size(); k += 2)
                    objects.push_back(polyLine(p, {p.indices[k], p.indices[k + 1]}, set));
            }
        }
        return objects;
    }

    // A PolyLine through the primitive's vertices `indices`, each with its
    // colour (COLOR_0) as a vertex attribute set when the primitive has
    // colours.
    static Ref<SharedObject> polyLine(const Primitive& p, const std::vector<std::uint32_t>& indices,
                                      const AttributeSet* set)
    {
        const std::size_t count = p.positions.size() / 3;
        std::vector<TQ3Vertex3D> vertices(indices.size());
        std::vector<Ref<AttributeSet>> sets;
        for (std::size_t k = 0; k < indices.size(); ++k) {
            const std::size_t i = indices[k];
            vertices[k].point = TQ3Point3D{p.positions[3 * i], p.positions[3 * i + 1], p.positions[3 * i + 2]};
            vertices[k].attributeSet = nullptr;
            if (p.colors.size() == 4 * count) {
                sets.push_back(makeShared<AttributeSet>());
                const TQ3ColorRGB color{p.colors[4 * i], p.colors[4 * i + 1], p.colors[4 * i + 2]};
                sets.back()->add(kQ3AttributeTypeDiffuseColor, &color);
                vertices[k].attributeSet = sets.back().get();
            }
        }
        TQ3PolyLineData data{};
        data.numVertices = static_cast<unsigned long>(vertices.size());
        data.vertices = vertices.data();
        // The polyline takes its own references to the sets.
        data.polyLineAttributeSet = const_cast<AttributeSet*>(set);
        PolyLine::checkData(data);
        return makeShared<PolyLine>(data);
    }

    static Ref<SharedObject> triMesh(const Primitive& p, const AttributeSet* set)
    {
        q3::Mesh mesh;
        const std::size_t count = p.positions.size() / 3;
        mesh.reserveVertices(count);
        bool translucent = false;
        for (std::size_t i = 3; i < p.colors.size(); i += 4)
            translucent = translucent || p.colors[i] < 1.0f;
        for (std::size_t i = 0; i < count; ++i) {
            VertexAttributes a;
            if (p.normals.size() == 3 * count)
                a.normal = TQ3Vector3D{p.normals[3 * i], p.normals[3 * i + 1], p.normals[3 * i + 2]};
            if (p.uvs.size() == 2 * count)
                a.uv = TQ3Param2D{p.uvs[2 * i], p.uvs[2 * i + 1]};
            if (p.colors.size() == 4 * count) {
                a.color = TQ3ColorRGB{p.colors[4 * i], p.colors[4 * i + 1], p.colors[4 * i + 2]};
                if (translucent)
                    a.transparency = TQ3ColorRGB{p.colors[4 * i + 3], p.colors[4 * i + 3], p.colors[4 * i + 3]};
            }
            mesh.addVertex(TQ3Point3D{p.positions[3 * i], p.positions[3 * i + 1], p.positions[3 * i + 2]}, a);
        }
        for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3)
            mesh.addTriangle(p.indices[t], p.indices[t + 1], p.indices[t + 2]);
        return TriMesh::fromMesh(mesh, set);
    }

    // A node's frame in the world: its origin and the directions of its
    // axes (a glTF camera or light looks down its -z, y up).
    struct Frame {
        glm::dvec3 origin, x, y, z;
    };
    static Frame frameOf(const glm::dmat4& world)
    {
        auto axis = [&](int k) {
            const glm::dvec3 v(world[k]);
            const double length = glm::length(v);
            return length > 0.0 ? v / length : glm::dvec3(k == 0, k == 1, k == 2);
        };
        return Frame{glm::dvec3(world[3]), axis(0), axis(1), axis(2)};
    }
    static TQ3Point3D point(const glm::dvec3& v) { return TQ3Point3D{float(v.x), float(v.y), float(v.z)}; }
    static TQ3Vector3D vector(const glm::dvec3& v) { return TQ3Vector3D{float(v.x), float(v.y), float(v.z)}; }

    static Ref<SharedObject> camera(const Camera& c, const glm::dmat4& world)
    {
        const Frame f = frameOf(world);
        TQ3CameraData data{};
        data.placement.cameraLocation = point(f.origin);
        data.placement.pointOfInterest = point(f.origin - f.z);
        data.placement.upVector = vector(f.y);
        // glTF allows an infinite far plane; QuickDraw 3D's yon is finite.
        const double hither = c.znear > 0.0 ? c.znear : 0.1;
        data.range.hither = float(hither);
        data.range.yon = float(c.zfar > hither ? c.zfar : hither * 1e4);
        data.viewPort = TQ3CameraViewPort{{-1.0f, 1.0f}, 2.0f, 2.0f};
        if (!c.perspective) {
            const TQ3OrthographicCameraData ortho{data, float(-c.xmag), float(c.ymag), float(c.xmag), float(-c.ymag)};
            return makeShared<OrthographicCamera>(ortho);
        }
        // QuickDraw 3D's angle spans the narrower side.
        const double fov = c.aspect >= 1.0 ? c.yfov : 2.0 * std::atan(std::tan(c.yfov / 2.0) * c.aspect);
        return makeShared<ViewAngleAspectCamera>(TQ3ViewAngleAspectCameraData{data, float(fov), float(c.aspect)});
    }

    static Ref<SharedObject> light(const Light& l, const glm::dmat4& world)
    {
        const Frame f = frameOf(world);
        const TQ3LightData common{kQ3True, l.intensity, l.color};
        switch (l.kind) {
        case Light::Kind::kDirectional:
            return makeShared<DirectionalLight>(TQ3DirectionalLightData{common, kQ3True, vector(-f.z)});
        case Light::Kind::kPoint:
            return makeShared<PointLight>(
                TQ3PointLightData{common, kQ3True, kQ3AttenuationTypeInverseDistanceSquared, point(f.origin)});
        default:
            return makeShared<SpotLight>(TQ3SpotLightData{common, kQ3True, kQ3AttenuationTypeInverseDistanceSquared,
                                                          point(f.origin), vector(-f.z),
                                                          float(std::clamp(l.innerCone, 0.0, double(kQ3PiOver2))),
                                                          float(std::clamp(l.outerCone, 0.0, double(kQ3PiOver2))),
                                                          kQ3FallOffTypeCosine});
        }
    }

    const Ref<AttributeSet>& attributeSet(int index)
    {
        Ref<AttributeSet>& set = m_sets[index];
        if (set)
            return set;
        const Material& m = m_scene.materials[index];
        set = makeShared<AttributeSet>();
        set->add(kQ3AttributeTypeDiffuseColor, &m.diffuse);
        set->add(kQ3AttributeTypeSpecularColor, &m.specular);
        set->add(kQ3AttributeTypeSpecularControl, &m.specularControl);
        if (m.alpha < 1.0f && !m.vertexColors) {
            const TQ3ColorRGB transparency{m.alpha, m.alpha, m.alpha};
            set->add(kQ3AttributeTypeTransparencyColor, &transparency);
        }
        if (m.image >= 0) {
            Ref<TextureShader> shader = makeShared<TextureShader>(texture(m.image));
            shader->setUBoundary(m.uBoundary);
            shader->setVBoundary(m.vBoundary);
            set->addShader(shader);
        }
        return set;
    }

    // A mipmap texture of one image: ARGB32 when it has alpha, else RGB32,
    // big-endian words (each pixel A R G B bytes), so every pixel is kept.
    Ref<Texture> texture(int index)
    {
        Ref<Texture>& texture = m_textures[index];
        if (texture)
            return texture;
        const Image& image = m_scene.images[index];
        std::vector<unsigned char> bytes(std::size_t(image.width) * image.height * 4);
        for (std::size_t i = 0; i < std::size_t(image.width) * image.height; ++i) {
            bytes[4 * i] = image.hasAlpha ? image.rgba[4 * i + 3] : 0xff;
            bytes[4 * i + 1] = image.rgba[4 * i];
            bytes[4 * i + 2] = image.rgba[4 * i + 1];
            bytes[4 * i + 3] = image.rgba[4 * i + 2];
        }
        Ref<MemoryStorage> storage = makeShared<MemoryStorage>(bytes.data(), bytes.size());
        TQ3Mipmap mipmap;
        std::memset(&mipmap, 0, sizeof mipmap);
        mipmap.image = storage.get();
        mipmap.useMipmapping = kQ3False;
        mipmap.pixelType = image.hasAlpha ? kQ3PixelTypeARGB32 : kQ3PixelTypeRGB32;
        mipmap.bitOrder = kQ3EndianBig;
        mipmap.byteOrder = kQ3EndianBig;
        mipmap.mipmaps[0] = TQ3MipmapImage{image.width, image.height, image.width * 4ul, 0};
        texture = makeShared<MipmapTexture>(mipmap);
        return texture;
    }

    const Scene& m_scene;
    std::vector<Ref<Texture>> m_textures;
    std::vector<Ref<AttributeSet>> m_sets;
    std::vector<std::vector<Ref<SharedObject>>> m_meshes;
    std::vector<bool> m_visiting;
    std::vector<Ref<SharedObject>> m_cameras;
    std::vector<Ref<SharedObject>> m_lights;
};

} // namespace

Ref<DisplayGroup> groupFrom(const Scene& scene)
{
    return Builder(scene).root();
}

} // namespace q3::exchange
