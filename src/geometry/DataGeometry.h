// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The shape every QuickDraw 3D geometry with a data structure shares: the
// object keeps a private deep copy of its C struct (core/DataLayout.h), and
// New, GetData, SetData, EmptyData, Duplicate, immediate-mode Submit and the
// geometry attribute set all come from the struct's description. A geometry
// class adds only what is its own:
//
//   class Triangle final : public DataGeometry<Triangle, TQ3TriangleData> {
//   public:
//       static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeTriangle;
//       static constexpr const char* kName = "triangle";           // messages
//       static constexpr const char* kDataName = "triangleData";   // messages
//       static constexpr TQ3AttributeSet TQ3TriangleData::*kOwnSet =
//           &TQ3TriangleData::triangleAttributeSet;
//       // optional: the data rules its description cannot say (index
//       // ranges, enumerations), run after the description's own checks
//       static void check(const TQ3TriangleData& data);
//       // optional: data QuickDraw 3D accepted though it is degenerate, and
//       // what makes it so ("" when it is not; docs/3dmf.md, Tolerances)
//       static std::string degeneracy(const TQ3TriangleData& data);
//       using DataGeometry::DataGeometry;
//       const ClassInfo& classInfo() const override;
//       void decompose(const DecomposeContext&, PrimitiveSink&) const override;
//       ... Apple's per-field accessors ...
//   };
//
// the description (layout::Describe<TQ3TriangleData>: in its header when it
// also gives the 3DMF form, which src/io reads, else in its .cpp), and in its
// .cpp `template class DataGeometry<Triangle, TQ3TriangleData>;`, which
// compiles the shared members there, where the description is visible.

#include "geometry/Geometry.h"

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace q3 {

/// Constructor tags: immediate mode (the caller's data, used in place for one
/// submit), Duplicate (a deep copy with every attribute set duplicated) and
/// adoption (data the library built itself, already owned).
struct BorrowData {};
struct DuplicateData {};
struct AdoptData {};

template <class Derived, class Data>
class DataGeometry : public Geometry {
public:
    using DataType = Data;

    /// Everything New, SetData and Submit require of the caller's data, in
    /// this order: data is not NULL (kQ3ErrorNULLParameter, named
    /// Derived::kDataName); checkData. Attribute sets are checked when the
    /// data is taken (the constructors and setData). Data that passes and is
    /// degenerate gets warnIfDegenerate's warning.
    static void validate(const Data* data);

    /// The rules of the data, in two steps: the structural check its
    /// description gives (layout::checkStructure: every required array and
    /// handle present, every count at least its minimum, every count within
    /// kQ3GeometryMaxArrayCount, every field described as finite() finite),
    /// then Derived::check, the
    /// class's own rules, which may therefore read every array. The per-field
    /// setters check a changed copy of the data through it too.
    static void checkData(const Data& data);

    /// The class's own rules, beyond its description; a class with some
    /// hides this one (Derived::check).
    static void check(const Data&) {}

    /// For a class that defines Derived::degeneracy: when it describes a
    /// case, the attribute sets are checked (so that a call refused for them
    /// posts its error alone) and kQ3WarningInconsistentData is posted,
    /// naming the case. The data is kept as it is.
    static void warnIfDegenerate(const Data& data);

    /// A retained geometry owning a copy of data, which passed validate():
    /// every attribute set is checked (kQ3ErrorInvalidObject /
    /// kQ3ErrorInvalidObjectType, naming the field) and retained.
    explicit DataGeometry(const Data& data);
    /// Immediate mode: data (validated) is used in place for the life of this
    /// object, which must end before the caller's call returns; attribute sets
    /// are checked, not retained; nothing is cached.
    DataGeometry(BorrowData, const Data& data);
    /// Duplicate: a deep copy of source's data with every distinct attribute
    /// set duplicated once (shared where the original was shared).
    DataGeometry(DuplicateData, const Data& source);
    /// Takes over data whose arrays are malloc'ed and whose handles each hold
    /// a reference for it (what the library builds, as decompositions);
    /// `owned` is left holding nothing.
    DataGeometry(AdoptData, Data& owned);
    ~DataGeometry() override;

    const Data& data() const { return m_data; }

    /// Q3xxx_GetData: a deep copy, arrays malloc'ed and one new reference per
    /// attribute set, for emptyData to give back.
    void getData(Data& out) const;
    /// Q3xxx_SetData: validates, takes a copy, then releases the old data;
    /// on failure nothing changes (not even the edit index).
    void setData(const Data& data);
    /// Q3xxx_EmptyData: checks every attribute set handle in data (a failure
    /// releases nothing), then releases them and frees the arrays.
    static void emptyData(Data& data);

    Object* duplicate() const override;
    const AttributeSet* attributeSet() const override;
    void setAttributeSet(Ref<AttributeSet> attributes) override;

protected:
    /// For Apple's per-field setters, after they have checked their argument;
    /// they call markEdited() once they have changed it.
    Data& editableData() { return m_data; }
    /// True for an immediate-mode geometry (BorrowData).
    bool borrowed() const { return m_borrowed; }
    /// Draws into `sink`, with the geometry's attribute set, the mesh of
    /// `count` vertices with their own attributes joined by what `connect`
    /// adds to it: cached under the edit indices of the vertices' sets.
    void drawVertexMesh(const TQ3Vertex3D* vertices, std::size_t count, const std::function<void(Mesh&)>& connect,
                        PrimitiveSink& sink) const;
    /// Draws into `sink`, with the geometry's attribute set, `mesh` (whose
    /// point, bitmap or pixmap the caller has set) as its one vertex at
    /// `position`.
    void drawAt(const TQ3Point3D& position, MeshView& mesh, PrimitiveSink& sink) const
    {
        mesh.positions = &position.x;
        mesh.vertexCount = 1;
        sink.draw(mesh, attributeSet());
    }

private:
    Data m_data;
    bool m_borrowed = false;
};

/// Puts `set` (its reference is handed over; null clears) into an attribute
/// set slot of data the library owns, releasing what the slot held. Not an
/// edit by itself.
void replaceHeldSet(TQ3AttributeSet& slot, Ref<AttributeSet> set);

/// Apple's per-vertex calls, for data holding an array of `count` TQ3Vertex3D:
/// vertex `index` (kQ3ErrorParameterOutOfRange unless index < count, the
/// message naming `owner`, e.g. "the triangle"); moving it
/// (kQ3ErrorParameterOutOfRange, then kQ3ErrorInvalidData for a coordinate
/// that is not finite); replacing its attribute set. The setters change
/// nothing on failure; the caller marks the edit.
const TQ3Vertex3D& vertexAt(const TQ3Vertex3D* vertices, std::size_t count, std::size_t index, const char* owner);
void moveVertex(TQ3Vertex3D* vertices, std::size_t count, std::size_t index, const TQ3Point3D& position,
                const char* owner);
void replaceVertexSet(TQ3Vertex3D* vertices, std::size_t count, std::size_t index, Ref<AttributeSet> set,
                      const char* owner);

/// For meshes built from TQ3Vertex3D arrays: the edit indices of the vertices'
/// attribute sets (the part of a cache key they decide), and the vertices
/// added to a mesh with their own attributes. addVertices returns the index
/// of the first.
void appendVertexSetKeys(std::vector<double>& key, const TQ3Vertex3D* vertices, std::size_t count);
std::uint32_t addVertices(Mesh& mesh, const TQ3Vertex3D* vertices, std::size_t count);
/// One vertex with its own attributes over those of the part it belongs to
/// (a face's or an edge's set; null for none); returns its index.
std::uint32_t addVertex(Mesh& mesh, const TQ3Vertex3D& vertex, const AttributeSet* part);

template <class Derived, class Data>
void DataGeometry<Derived, Data>::drawVertexMesh(const TQ3Vertex3D* vertices, std::size_t count,
                                                 const std::function<void(Mesh&)>& connect, PrimitiveSink& sink) const
{
    std::vector<double> key;
    appendVertexSetKeys(key, vertices, count);
    withMesh(
        std::move(key),
        [&](Mesh& mesh) {
            addVertices(mesh, vertices, count);
            connect(mesh);
        },
        [&](const Mesh& mesh) { sink.draw(mesh.view(), attributeSet()); });
}

/// kQ3ErrorParameterOutOfRange unless index < count; `what` names the index
/// ("vertex index") and `owner` the geometry ("the triangle") in the message.
void checkIndex(std::size_t index, std::size_t count, const char* what, const char* owner);

/// kQ3ErrorInvalidData, naming `where`, unless every coordinate is finite:
/// the coordinate rule every geometry's data and its setters share.
void requireFinite(const TQ3Point3D& point, const char* where, std::size_t index);
void requireFinite(const TQ3Point3D& point, const std::string& where);

} // namespace q3
