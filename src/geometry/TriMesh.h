// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/DataGeometry.h"

#include <cstddef>
#include <cstring>
#include <type_traits>

namespace q3 {

extern const ClassInfo kTriMeshClass;

/// A triangle mesh. Invariant: its data obeys the TQ3TriMeshData rules of
/// QD3DGeometry.h (every index in range, every point and attribute value
/// finite, every attribute type a standard one Q3 stores).
class TriMesh final : public DataGeometry<TriMesh, TQ3TriMeshData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeTriMesh;
    static constexpr const char* kName = "triMesh";
    static constexpr const char* kDataName = "triMeshData";
    static constexpr TQ3AttributeSet TQ3TriMeshData::*kOwnSet = &TQ3TriMeshData::triMeshAttributeSet;

    /// The TQ3TriMeshData rules of QD3DGeometry.h, in their order.
    static void check(const TQ3TriMeshData& data);

    using DataGeometry::DataGeometry;

    /// A TriMesh of a decomposition: the mesh's triangles over its vertices,
    /// with the per-vertex attributes it has as vertex attribute arrays (an
    /// attributeUseArray where only some vertices have one), the triangles'
    /// own surface shaders as a kQ3AttributeTypeSurfaceShader triangle
    /// attribute array, and `own` (may be null) as its triMeshAttributeSet.
    static Ref<TriMesh> fromMesh(const Mesh& mesh, const AttributeSet* own);

    const ClassInfo& classInfo() const override { return kTriMeshClass; }
    /// The triangles over the points with their vertex attributes; triangle
    /// attributes apply to their own three corners (a vertex's own still
    /// win), so a mesh with any gives every triangle its own vertices. The
    /// wireframe is every distinct triangle side, then each edge of the edge
    /// array that has a colour, in that colour.
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;
    bool isPrimitive() const override { return true; }
    /// Every point, used by a triangle or not: the box GetData reports as
    /// bBox (the default, the drawn vertices, would leave out the unused
    /// points only when the mesh has triangle attributes).
    void bound(const DecomposeContext& context, std::vector<glm::dvec3>& points) const override;

    /// As DataGeometry::getData, with bBox the box of the points (the
    /// caller's bBox is not kept: Q3 computes it).
    void getData(TQ3TriMeshData& out) const;
};

/// One TriMesh attribute array (triangle, edge or vertex) as a field kind of
/// the description (core/DataLayout.h): numTypes entries, each with a data
/// block of `elementCount` values of its type and an optional
/// attributeUseArray of elementCount chars. Q3 knows the size of the
/// standard types it stores; any other type is refused
/// (kQ3ErrorAttributeInvalidType). A surface shader array
/// (kQ3AttributeTypeSurfaceShader) holds a TQ3SurfaceShaderObject per
/// element, NULL for none: the copy holds one reference to each shader an
/// element uses (a live surface shader, checked on New and SetData) and NULL
/// in the elements the use array switches off.
struct TriMeshAttributeArraysField {
    const char* name;
    TQ3TriMeshAttributeData* TQ3TriMeshData::*member;
    unsigned long TQ3TriMeshData::*typeCount;
    unsigned long TQ3TriMeshData::*elementCount;

    /// The bytes of one value of the entry's type; throws
    /// kQ3ErrorAttributeInvalidType naming `where` for a type Q3 does not store.
    static std::size_t valueSize(const TQ3TriMeshAttributeData& entry, const layout::Path& where);
    /// The handle a surface shader array holds for element `index`, or NULL
    /// (none, or switched off by the use array, whose slot may hold anything).
    static TQ3Object shaderAt(const TQ3TriMeshAttributeData& entry, std::size_t index);
    /// A caller's surface shader, checked as Q3AttributeSet_Add checks one.
    static SharedObject& lookupSurfaceShader(TQ3Object handle, const layout::Path& where);

    void check(const TQ3TriMeshData& s, const layout::Path& path, layout::Pass pass) const;
    void clear(TQ3TriMeshData& s) const { s.*member = nullptr; }
    template <class Policy>
    void fill(TQ3TriMeshData& dst, const TQ3TriMeshData& src, Policy& policy, const layout::Path& path) const
    {
        const TQ3TriMeshAttributeData* from = src.*member;
        if (from == nullptr)
            return;
        const std::size_t n = src.*typeCount;
        const std::size_t count = src.*elementCount;
        TQ3TriMeshAttributeData* to = layout::allocate<TQ3TriMeshAttributeData>(n);
        for (std::size_t i = 0; i < n; ++i)
            to[i] = TQ3TriMeshAttributeData{from[i].attributeType, nullptr, nullptr};
        dst.*member = to;
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t bytes = count * valueSize(from[i], path.child(name).element(i));
            to[i].data = layout::allocate<unsigned char>(bytes);
            if (from[i].attributeType == kQ3AttributeTypeSurfaceShader && count != 0)
                std::memset(to[i].data, 0, bytes);
            else if (bytes != 0)
                std::memcpy(to[i].data, from[i].data, bytes);
            if (from[i].attributeUseArray != nullptr && count != 0) {
                to[i].attributeUseArray = layout::allocate<char>(count);
                std::memcpy(to[i].attributeUseArray, from[i].attributeUseArray, count);
            }
            if (from[i].attributeType == kQ3AttributeTypeSurfaceShader)
                takeShaders(to[i], from[i], count, policy, path.child(name).element(i));
        }
    }
    // Fills a surface shader array's copy (all NULL) element by element, so
    // that a failure leaves only taken references for release() to drop.
    // New and SetData check each shader; GetData and Duplicate share them,
    // as a duplicated attribute set shares its surface shader
    // (AttributeSet::duplicate).
    template <class Policy>
    static void takeShaders(TQ3TriMeshAttributeData& to, const TQ3TriMeshAttributeData& from, std::size_t count,
                            Policy&, const layout::Path& where)
    {
        TQ3Object* handles = static_cast<TQ3Object*>(to.data);
        for (std::size_t e = 0; e < count; ++e) {
            const TQ3Object handle = shaderAt(from, e);
            if (handle == nullptr)
                continue;
            SharedObject* shader = std::is_same<Policy, layout::RetainChecked>::value
                                       ? &lookupSurfaceShader(handle, where.child("data").element(e))
                                       : layout::heldObject(handle);
            handles[e] = Ref<SharedObject>::retain(shader).detach();
        }
    }
    void release(TQ3TriMeshData& s) const;
    void checkHandles(const TQ3TriMeshData& s, const layout::Path& path) const;
    template <class F>
    void forEachHandle(const TQ3TriMeshData& s, F& f) const
    {
        forEachShader(s, [&](TQ3Object handle, std::size_t, std::size_t) { f(handle); });
    }
    // Calls f(handle, entry, element) for every shader a surface shader array
    // holds.
    template <class F>
    void forEachShader(const TQ3TriMeshData& s, F&& f) const
    {
        const TQ3TriMeshAttributeData* entries = s.*member;
        if (entries == nullptr)
            return;
        for (std::size_t i = 0; i < s.*typeCount; ++i)
            if (entries[i].attributeType == kQ3AttributeTypeSurfaceShader && entries[i].data != nullptr)
                for (std::size_t e = 0; e < s.*elementCount; ++e)
                    if (const TQ3Object handle = shaderAt(entries[i], e))
                        f(handle, i, e);
    }
};

// The data description (core/DataLayout.h).
namespace layout {
template <>
struct Describe<TQ3TriMeshData> {
    static auto fields()
    {
        using D = TQ3TriMeshData;
        using Attributes = TriMeshAttributeArraysField;
        return std::make_tuple(
            handle<AttributeSet>("triMeshAttributeSet", &D::triMeshAttributeSet),
            value("numTriangles", &D::numTriangles), array("triangles", &D::triangles, countOf(&D::numTriangles)),
            Attributes{"triangleAttributeTypes", &D::triangleAttributeTypes, &D::numTriangleAttributeTypes,
                       &D::numTriangles},
            value("numEdges", &D::numEdges), array("edges", &D::edges, countOf(&D::numEdges)),
            Attributes{"edgeAttributeTypes", &D::edgeAttributeTypes, &D::numEdgeAttributeTypes, &D::numEdges},
            // The points after every attribute array, so that an unknown
            // attribute type is reported before a point that is not finite.
            value("numPoints", &D::numPoints),
            Attributes{"vertexAttributeTypes", &D::vertexAttributeTypes, &D::numVertexAttributeTypes,
                       &D::numPoints},
            finiteElements(array("points", &D::points, countOf(&D::numPoints))), value("bBox", &D::bBox));
    }
};
} // namespace layout

} // namespace q3
