// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

#include "exchange/SceneImport.h"

#include "core/AttributeSet.h"
#include "core/Error.h"
#include "core/Limits.h"
#include "geometry/PolyLine.h"
#include "geometry/Primitives.h"
#include "geometry/TriMesh.h"
#include "group/Group.h"
#include "io/Storage.h"
#include "shader/IlluminationShaders.h"
#include "shader/Texture.h"
#include "shader/TextureShader.h"
#include "view/Transform.h"

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
            group->add(nodeGroup(node, 0));
        return group;
    }

private:
    Ref<DisplayGroup> nodeGroup(int index, std::size_t depth)
    {
        if (depth >= limits::kMaxGroupNesting)
            fail(kQ3ErrorInvalidData, "nodes nest deeper than kQ3GroupMaxNesting");
        if (m_visiting[index])
            fail(kQ3ErrorInvalidData, "node " + std::to_string(index) + " is its own descendant");
        m_visiting[index] = true;
        const Node& node = m_scene.nodes[index];
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
            group->add(nodeGroup(child, depth + 1));
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
                std::vector<float> xyz;
                for (std::uint32_t i : p.indices)
                    xyz.insert(xyz.end(), &p.positions[3 * std::size_t(i)], &p.positions[3 * std::size_t(i)] + 3);
                if (p.indices.size() >= 2)
                    objects.push_back(PolyLine::fromPoints(xyz.data(), p.indices.size(), set));
            } else if (p.mode == Primitive::Mode::kLines) {
                for (std::size_t k = 0; k + 1 < p.indices.size(); k += 2) {
                    float xyz[6];
                    std::memcpy(xyz, &p.positions[3 * std::size_t(p.indices[k])], sizeof(float) * 3);
                    std::memcpy(xyz + 3, &p.positions[3 * std::size_t(p.indices[k + 1])], sizeof(float) * 3);
                    objects.push_back(PolyLine::fromPoints(xyz, 2, set));
                }
            }
        }
        return objects;
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
};

} // namespace

Ref<DisplayGroup> groupFrom(const Scene& scene)
{
    return Builder(scene).root();
}

} // namespace q3::exchange
