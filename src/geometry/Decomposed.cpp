// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Geometry::decomposed(): what decompose() gives, handed out as the geometry
// that holds it. The output types are the two primitives every other
// geometry ends up as: line strips become a PolyLine, triangles a TriMesh.

#include "geometry/Geometry.h"

#include "geometry/PolyLine.h"
#include "geometry/TriMesh.h"

namespace q3 {

namespace {

// Gathers a decomposition into one owned Mesh.
class MeshCollector final : public PrimitiveSink {
public:
    void draw(const MeshView& view, const AttributeSet*) override
    {
        const std::uint32_t base = static_cast<std::uint32_t>(m_mesh.vertexCount());
        for (std::size_t i = 0; i < view.vertexCount; ++i) {
            VertexAttributes attributes;
            if (view.colors != nullptr)
                attributes.color = TQ3ColorRGB{view.colors[3 * i], view.colors[3 * i + 1], view.colors[3 * i + 2]};
            if (view.transparency != nullptr)
                attributes.transparency =
                    TQ3ColorRGB{view.transparency[3 * i], view.transparency[3 * i + 1], view.transparency[3 * i + 2]};
            if (view.normals != nullptr)
                attributes.normal = TQ3Vector3D{view.normals[3 * i], view.normals[3 * i + 1], view.normals[3 * i + 2]};
            if (view.uvs != nullptr)
                attributes.uv = TQ3Param2D{view.uvs[2 * i], view.uvs[2 * i + 1]};
            const float* p = view.positions + 3 * i;
            m_mesh.addVertex(TQ3Point3D{p[0], p[1], p[2]}, attributes);
        }
        for (std::size_t t = 0; t < view.triangleCount; ++t) {
            const std::uint32_t shader = view.triangleShaders != nullptr ? view.triangleShaders[t] : 0;
            m_mesh.addTriangle(base + view.triangles[3 * t], base + view.triangles[3 * t + 1],
                               base + view.triangles[3 * t + 2],
                               shader != 0 ? view.shaders[shader - 1].get() : nullptr);
        }
        for (std::size_t s = 0; s < view.stripCount; ++s)
            m_mesh.addStrip(base + view.strips[s].first, view.strips[s].count);
        m_others += view.pointCount + view.lineCount;
    }

    const Mesh& mesh() const { return m_mesh; }
    /// Points and separate segments, which neither result type holds.
    std::size_t others() const { return m_others; }

private:
    Mesh m_mesh;
    std::size_t m_others = 0;
};

} // namespace

Ref<Geometry> Geometry::decomposed(const DecomposeContext& context) const
{
    MeshCollector collector;
    decompose(context, collector);
    const Mesh& mesh = collector.mesh();
    const MeshView view = mesh.view();
    if (collector.others() == 0 && view.stripCount == 0)
        return TriMesh::fromMesh(mesh, attributeSet());
    if (collector.others() == 0 && view.triangleCount == 0 && view.stripCount == 1)
        return PolyLine::fromPoints(view.positions + 3 * std::size_t(view.strips[0].first), view.strips[0].count,
                                    attributeSet());
    fail(kQ3ErrorUnsupportedGeometryType,
         std::string("a ") + classInfo().name + " decomposes into a mixture of primitives that no single geometry holds");
}

} // namespace q3
