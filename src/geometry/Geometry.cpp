// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Geometry.h"

#include "core/ShapeVisitor.h"
#include "core/DataLayout.h"

#include <array>
#include <cstdint>
#include <mutex>

namespace q3 {

const ClassInfo kGeometryClass{kQ3ShapeTypeGeometry, &kShapeClass, "geometry"};

namespace {

// Geometries drawn by views on several threads share their cached mesh; a
// few striped locks keep that safe without a mutex in every geometry.
std::mutex& meshLock(const void* geometry)
{
    static std::array<std::mutex, 64> stripes;
    const auto address = reinterpret_cast<std::uintptr_t>(geometry);
    return stripes[(address / alignof(Geometry)) % stripes.size()];
}

// Collects the vertex positions of a decomposition (the default bound()).
class PositionCollector final : public PrimitiveSink {
public:
    explicit PositionCollector(std::vector<glm::dvec3>& points) : m_points(points) {}

    void draw(const MeshView& mesh, const AttributeSet*) override
    {
        for (std::size_t i = 0; i < mesh.vertexCount; ++i) {
            const float* p = mesh.positions + 3 * i;
            m_points.emplace_back(p[0], p[1], p[2]);
        }
    }

private:
    std::vector<glm::dvec3>& m_points;
};

} // namespace

struct Geometry::MeshCache {
    Mesh mesh;
    std::vector<double> key;
};

Geometry::Geometry() = default;

Geometry::~Geometry() = default;

void Geometry::accept(ShapeVisitor& visitor) const
{
    visitor.visitGeometry(*this);
}

void Geometry::bound(const DecomposeContext& context, std::vector<glm::dvec3>& points) const
{
    PositionCollector collector(points);
    decompose(context, collector);
}

void Geometry::withMesh(std::vector<double> key, const std::function<void(Mesh&)>& build,
                        const std::function<void(const Mesh&)>& use) const
{
    if (!m_cacheable) {
        Mesh mesh;
        build(mesh);
        use(mesh);
        return;
    }
    key.push_back(double(editIndex()));
    std::lock_guard<std::mutex> lock(meshLock(this));
    if (!m_meshCache || m_meshCache->key != key) {
        // Build into a fresh mesh so that a failure leaves no half-built one.
        auto fresh = std::make_unique<MeshCache>();
        build(fresh->mesh);
        // Its contents stay as built until the key changes: a renderer may
        // keep what it derives from them (MeshView::serial).
        fresh->mesh.setSerial(Mesh::newSerial());
        fresh->key = std::move(key);
        m_meshCache = std::move(fresh);
        ++m_meshBuilds;
    }
    use(m_meshCache->mesh);
}

void Geometry::onEdited()
{
    std::lock_guard<std::mutex> lock(meshLock(this));
    m_meshCache.reset();
}

void appendEditIndices(std::vector<double>& key, const std::vector<const AttributeSet*>& sets)
{
    for (const AttributeSet* set : sets)
        key.push_back(set != nullptr ? double(set->editIndex()) : -1.0);
}

Ref<AttributeSet> attributeSetFromHandle(TQ3AttributeSet handle, const char* name)
{
    if (handle == nullptr)
        return nullptr;
    return lookupRef<AttributeSet>(handle, name);
}

TQ3AttributeSet attributeSetToHandle(const Ref<AttributeSet>& set)
{
    return Ref<AttributeSet>(set).detach();
}

TQ3AttributeSet attributeSetToHandle(const AttributeSet* set)
{
    // A reference count is bookkeeping, not part of the set's value, so a
    // const set may gain a holder.
    return Ref<AttributeSet>::retain(const_cast<AttributeSet*>(set)).detach();
}

const AttributeSet* heldAttributeSet(TQ3AttributeSet handle)
{
    return handle == nullptr ? nullptr : static_cast<const AttributeSet*>(layout::heldObject(handle));
}

} // namespace q3
