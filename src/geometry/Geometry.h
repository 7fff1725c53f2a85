// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "core/AttributeSet.h"
#include "core/Object.h"
#include "geometry/Decompose.h"
#include "base/Primitives.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace q3 {

extern const ClassInfo kGeometryClass;

/// Every QuickDraw 3D geometry: a drawable shared object that decomposes
/// itself into primitives (Primitives.h). Rendering, bounding and
/// Q3Geometry_GetDecomposed go through decompose(); nothing outside a
/// geometry's own file knows its type. Invariant: a cached mesh is dropped on
/// every edit and is valid only for the key it was built under.
class Geometry : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShapeTypeGeometry;

    bool isDrawable() const override { return true; }
    void accept(ShapeVisitor& visitor) const override;

    /// The geometry's own attribute set (the xxxAttributeSet of its data), or
    /// null.
    virtual const AttributeSet* attributeSet() const = 0;
    /// Replaces it (null removes it); an edit.
    virtual void setAttributeSet(Ref<AttributeSet> attributes) = 0;

    /// Hands the geometry's points, lines, strips and triangles, in its local
    /// coordinates, to sink, subdivided as the context says.
    virtual void decompose(const DecomposeContext& context, PrimitiveSink& sink) const = 0;

    /// Appends local points whose bounds enclose the geometry. By default the
    /// vertices of decompose(); a geometry with a cheaper enclosing set (a NURB
    /// curve's control points) overrides it.
    virtual void bound(const DecomposeContext& context, std::vector<glm::dvec3>& points) const;

    /// True for the geometries that are primitives themselves (point, line,
    /// polyline, triangle, trimesh): Q3Geometry_GetDecomposed gives NULL.
    virtual bool isPrimitive() const { return false; }
    /// False for an immediate-mode geometry (a _Submit's temporary), which
    /// nothing may keep a reference to.
    bool isRetained() const { return m_cacheable; }

    /// Q3Geometry_GetDecomposed: what decompose() gives, as a new geometry (a
    /// PolyLine for one strip, a TriMesh for triangles) carrying this
    /// geometry's attribute set; null for a primitive. Throws
    /// kQ3ErrorUnsupportedGeometryType for a mixture the result types cannot hold.
    virtual Ref<Geometry> decomposed(const DecomposeContext& context) const;

    /// The shape part (QD3DPick.h) of the kind `part` (kQ3PickPartsMaskFace,
    /// Edge or Vertex) at `local`, a hit point in the geometry's own
    /// coordinates, as a new object; null for a geometry without parts (all
    /// but the mesh).
    virtual Ref<SharedObject> shapePartAt(TQ3PickParts part, const TQ3Point3D& local) const { return {}; }

    /// How many times the cached mesh has been built; tests read it.
    std::uint64_t meshBuilds() const { return m_meshBuilds; }

    ~Geometry() override;

protected:
    Geometry();

    /// Runs `use` on the mesh built by `build` under `key` (everything the
    /// mesh depends on besides the edit index, which every key includes):
    /// reused while the key is unchanged, rebuilt after an edit or when the
    /// key changes. A geometry that is not retained (immediate mode) builds it
    /// every time. Safe when several views draw the geometry at once.
    void withMesh(std::vector<double> key, const std::function<void(Mesh&)>& build,
                  const std::function<void(const Mesh&)>& use) const;
    /// Immediate-mode geometries keep nothing between submits.
    void disableCaching() { m_cacheable = false; }

    void onEdited() override;

private:
    /// The cached mesh and its key, allocated only by a geometry that
    /// builds one: most geometries (curves, lines, points) never do, and an
    /// inline Mesh and its key would add 336 bytes to each of them (issue 16's memory
    /// target counts every byte a retained curve holds).
    struct MeshCache;
    mutable std::unique_ptr<MeshCache> m_meshCache;
    mutable std::uint64_t m_meshBuilds = 0;
    bool m_cacheable = true;
};

/// The edit index of every attribute set in `sets` appended to `key`: a mesh
/// that baked their attributes in is stale once any of them is edited.
void appendEditIndices(std::vector<double>& key, const std::vector<const AttributeSet*>& sets);

/// The attribute set a geometry's data names: null stays null; a handle must
/// be a live attribute set (kQ3ErrorInvalidObject / kQ3ErrorInvalidObjectType
/// otherwise). `name` is the field's name for the message.
Ref<AttributeSet> attributeSetFromHandle(TQ3AttributeSet handle, const char* name);

/// A new reference to an attribute set, for a getter (NULL stays NULL).
TQ3AttributeSet attributeSetToHandle(const Ref<AttributeSet>& set);
TQ3AttributeSet attributeSetToHandle(const AttributeSet* set);

/// The attribute set behind a handle the library holds (checked when it was
/// taken), or null.
const AttributeSet* heldAttributeSet(TQ3AttributeSet handle);

} // namespace q3
