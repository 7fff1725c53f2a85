// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// What the geometry readers and writers share (GeometryIO.cpp,
// SimpleGeometryIO.cpp and GeometryIOComplex.cpp): building a geometry
// through its class's rules, the attribute set handles of a geometry's data,
// and the vertices' attribute sets as a VertexAttributeSetList subobject.

#include "io/ClassIO.h"

#include <cstdint>

#include <string>
#include <utility>
#include <vector>

namespace q3::io {

constexpr TQ3ObjectType kTypeVertexSets = Q3_OBJECT_TYPE('v', 'a', 's', 'l');
constexpr TQ3ObjectType kTypeCaps = Q3_OBJECT_TYPE('c', 'a', 'p', 's');
constexpr TQ3ObjectType kTypeFaceSets = Q3_OBJECT_TYPE('f', 'a', 's', 'l');
// The sets of the parts of a geometry that are neither faces nor vertices:
// a polyline's segments ("Geometry Attribute Set Lists"; Quesa reads the
// same) and a polyhedron's edges (Q3's choice, docs/3dmf.md).
constexpr TQ3ObjectType kTypeGeometrySets = Q3_OBJECT_TYPE('g', 'a', 's', 'l');

inline const std::vector<std::pair<const char*, std::uint32_t>> kPacking = {{"Include", 0}, {"Exclude", 1}};
inline const std::vector<std::pair<const char*, std::uint32_t>> kCaps = {
    {"None", kQ3EndCapNone}, {"Top", kQ3EndCapMaskTop}, {"Bottom", kQ3EndCapMaskBottom},
    {"Interior", kQ3EndCapMaskInterior}};

/// Checks, before anything is written, that a marker's xOffset and yOffset
/// (longs, 64-bit on LP64 hosts) fit the file's Int32 fields:
/// kQ3ErrorInvalidData otherwise, naming `what`.
inline void requireInt32Offsets(long xOffset, long yOffset, const char* what)
{
    for (const long offset : {xOffset, yOffset})
        if (offset < INT32_MIN || offset > INT32_MAX)
            fail(kQ3ErrorInvalidData, std::string("the ") + what + "'s offset " + std::to_string(offset) +
                                          " does not fit the file's 32-bit field");
}

inline const AttributeSet* setOf(TQ3AttributeSet handle)
{
    return handle == nullptr ? nullptr : static_cast<const AttributeSet*>(static_cast<const Object*>(handle));
}

// Builds a geometry from data read from a file, through the class's rules.
template <class T>
Ref<SharedObject> make(const typename T::DataType& data)
{
    try {
        T::validate(&data);
    } catch (const Error& error) {
        fail(kQ3ErrorInvalidMetafileObject, std::string("the file's ") + T::kName + " breaks a rule: " + error.what());
    }
    return Ref<SharedObject>(makeShared<T>(data));
}

template <class T>
const typename T::DataType& dataOf(const Object& object)
{
    return static_cast<const T&>(object).data();
}

// ---- attribute set lists ----------------------------------------------------
//
// One set per element (vertex, face, segment...) as an AttributeSetList
// subobject: the element count, Include or Exclude, the indices listed, then
// the attribute sets of the elements that have one, in order, as children.

inline bool anySet(const std::vector<const AttributeSet*>& sets)
{
    for (const AttributeSet* set : sets)
        if (WriteContext::hasAttributes(set))
            return true;
    return false;
}

/// Writes the list (nothing when no element has a set).
inline void writeSetList(WriteContext& context, TQ3ObjectType type, const char* name,
                         const std::vector<const AttributeSet*>& sets)
{
    if (!anySet(sets))
        return;
    Encoder& out = context.out();
    out.begin(kTypeContainer, "Container");
    out.begin(type, name);
    out.u32(static_cast<std::uint32_t>(sets.size()));
    out.choice(kPacking, 1);
    std::vector<std::uint32_t> without;
    for (std::size_t i = 0; i < sets.size(); ++i)
        if (!WriteContext::hasAttributes(sets[i]))
            without.push_back(static_cast<std::uint32_t>(i));
    out.u32(static_cast<std::uint32_t>(without.size()));
    for (std::uint32_t index : without)
        out.u32(index);
    out.end();
    for (const AttributeSet* set : sets)
        context.attributeSet(set);
    out.end();
}

/// The elements' sets from the list of that type, one per element (null
/// where none, all null without a list).
inline std::vector<Ref<AttributeSet>> readSetList(ReadContext& context, const Parts& parts, TQ3ObjectType type,
                                                  const std::string& name, std::size_t n)
{
    std::vector<Ref<AttributeSet>> sets(n);
    const Node* node = parts.find(type);
    if (node == nullptr)
        return sets;
    if (node->type != kTypeContainer)
        fail(kQ3ErrorInvalidMetafileSubObject, "a " + name + " without its attribute sets");
    DataReader in = context.reader(node->children.front());
    const std::uint32_t count = in.u32();
    if (count != n)
        fail(kQ3ErrorInvalidMetafileSubObject, "a " + name + " for " + std::to_string(count) +
                                                   " elements on a geometry with " + std::to_string(n));
    const bool exclude = in.choice(kPacking) == 1;
    const std::uint32_t listed = in.count(4, 1, "indices");
    std::vector<bool> has(n, exclude);
    for (std::uint32_t i = 0; i < listed; ++i) {
        const std::uint32_t index = in.u32();
        if (index >= n)
            fail(kQ3ErrorInvalidMetafileSubObject, "a " + name + " names element " + std::to_string(index) +
                                                       " of " + std::to_string(n));
        has[index] = !exclude;
    }
    std::size_t next = 1;
    for (std::size_t i = 0; i < n; ++i) {
        if (!has[i])
            continue;
        if (next >= node->children.size())
            fail(kQ3ErrorInvalidMetafileSubObject, "a " + name + " has fewer attribute sets than it lists");
        sets[i] = context.objectAs<AttributeSet>(node->children[next++], "an element's attribute set");
    }
    return sets;
}

inline std::vector<const AttributeSet*> vertexSetsOf(const TQ3Vertex3D* vertices, unsigned long n)
{
    std::vector<const AttributeSet*> sets(n);
    for (unsigned long i = 0; i < n; ++i)
        sets[i] = setOf(vertices[i].attributeSet);
    return sets;
}

inline bool anyVertexSet(const TQ3Vertex3D* vertices, unsigned long n)
{
    return anySet(vertexSetsOf(vertices, n));
}

inline void writeVertexSets(WriteContext& context, const TQ3Vertex3D* vertices, unsigned long n)
{
    writeSetList(context, kTypeVertexSets, "VertexAttributeSetList", vertexSetsOf(vertices, n));
}

// The vertices' sets, one per vertex (null where none).
inline std::vector<Ref<AttributeSet>> readVertexSets(ReadContext& context, const Parts& parts, unsigned long n)
{
    return readSetList(context, parts, kTypeVertexSets, "VertexAttributeSetList", n);
}

inline std::vector<TQ3Vertex3D> readPoints(DataReader& in, std::uint32_t n)
{
    std::vector<TQ3Vertex3D> vertices(n);
    for (auto& vertex : vertices) {
        vertex.point = in.point3D();
        vertex.attributeSet = nullptr;
    }
    return vertices;
}

} // namespace q3::io
