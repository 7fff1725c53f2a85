// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The simple geometries' 3DMF forms, read and written from their data
// descriptions: a geometry whose object is a fixed sequence of its struct's
// fields (Describe<S>::fileFields(), core/DataLayout.h) followed by
// subobjects (Describe<S>::fileParts()) gets readSimple<T> and
// writeSimple<T> and one table row, nothing written by hand. This file maps
// the description's plain kinds to DataReader and Encoder calls and to the
// subobjects' tags:
//
//   point3D / vector3D / float32      Point3D, Vector3D, Float32
//   vertexPoints                      one Point3D per vertex (a counted
//                                     array: the Uns32 count first)
//   trailing(...)                     read when data is left; written unless
//                                     every field is its default (the
//                                     quadrics' u and v ranges)
//   ownSetPart                        the geometry's AttributeSet
//   vertexSetsPart                    a VertexAttributeSetList
//   setListPart                       a FaceAttributeSetList (kFaces), a
//                                     GeometryAttributeSetList (kOtherParts)
//   endCapsPart                       Caps (Top 1, Bottom 2, Interior 4)
//   capSetPart                        a TopCapAttributeSet (BottomCap...,
//                                     FaceCap..., InteriorCap...) container:
//                                     the part's object, with no data, then
//                                     its attribute set ("Top Cap Attribute
//                                     Sets"; the interior's set, which
//                                     QuickDraw 3D 1.5 added, the same way)
//
// The subobjects are written in the order the description lists them, in a
// container when any of them writes something; a reader finds each by type,
// the geometry's own set last. Every geometry read goes through its class's
// validation (make<T>), as every other class's does.

#include "io/ClassIO.h"
#include "io/GeometryIOSupport.h"

#include "geometry/Box.h"
#include "geometry/Cone.h"
#include "geometry/Cylinder.h"
#include "geometry/Disk.h"
#include "geometry/Ellipse.h"
#include "geometry/Ellipsoid.h"
#include "geometry/Line.h"
#include "geometry/Point.h"
#include "geometry/PolyLine.h"
#include "geometry/Polygon.h"
#include "geometry/Torus.h"
#include "geometry/Triangle.h"

#include <memory>
#include <tuple>
#include <type_traits>
#include <vector>

namespace q3::io {
namespace {

using layout::CapPart;
using layout::Primitive;

struct CapSet {
    TQ3ObjectType type;
    const char* name;
};
constexpr CapSet kTopCap = {Q3_OBJECT_TYPE('t', 'c', 'a', 's'), "TopCapAttributeSet"};
constexpr CapSet kBottomCap = {Q3_OBJECT_TYPE('b', 'c', 'a', 's'), "BottomCapAttributeSet"};
constexpr CapSet kFaceCap = {Q3_OBJECT_TYPE('f', 'c', 'a', 's'), "FaceCapAttributeSet"};
constexpr CapSet kInteriorCap = {Q3_OBJECT_TYPE('i', 'c', 'a', 's'), "InteriorCapAttributeSet"};

const CapSet& capSetOf(CapPart part)
{
    switch (part) {
    case CapPart::kTop:
        return kTopCap;
    case CapPart::kBottom:
        return kBottomCap;
    case CapPart::kFace:
        return kFaceCap;
    case CapPart::kInterior:
        break;
    }
    return kInteriorCap;
}

Ref<SharedObject> refusePart(ReadContext&, const Parts& parts)
{
    fail(kQ3ErrorInvalidMetafileObject,
         (parts.root.name.empty() ? typeName(parts.root.type) : parts.root.name) + " outside its geometry");
}

void writeNothing(WriteContext&, const Object&) {}

/// What the data read holds until the geometry is made: the arrays it
/// points to and the sets it names.
struct Held {
    std::vector<std::vector<TQ3Vertex3D>> vertices;
    std::vector<std::unique_ptr<TQ3AttributeSet[]>> setArrays;
    std::vector<Ref<AttributeSet>> references;
};

// ---- the data ------------------------------------------------------------------

template <class F>
struct IsTrailing : std::false_type {};
template <class... F>
struct IsTrailing<layout::Trailing<F...>> : std::true_type {};
template <class F>
constexpr bool isTrailing = IsTrailing<std::decay_t<F>>::value;

template <class S, class T, Primitive K>
void readField(DataReader& in, S& data, Held&, const layout::FileField<S, T, K>& field)
{
    if constexpr (K == Primitive::kPoint3D)
        data.*field.member = in.point3D();
    else if constexpr (K == Primitive::kVector3D)
        data.*field.member = in.vector3D();
    else
        data.*field.member = in.f32();
}

template <class S, class E, std::size_t N>
void readField(DataReader& in, S& data, Held&, const layout::VertexPointsField<S, E, N>& field)
{
    for (E& vertex : data.*field.member)
        vertex.point = in.point3D();
}

template <class S, class N>
void readField(DataReader& in, S& data, Held& held, const layout::CountedVertexPointsField<S, N, TQ3Vertex3D>& field)
{
    const std::uint32_t n = in.count(12, 3, "vertices");
    std::vector<TQ3Vertex3D> vertices(n);
    for (TQ3Vertex3D& vertex : vertices) {
        vertex.point = in.point3D();
        vertex.attributeSet = nullptr;
    }
    data.*field.count = n;
    data.*field.member = vertices.data();
    held.vertices.push_back(std::move(vertices));
}

template <class S, class T, Primitive K>
void writeField(Encoder& out, const S& data, const layout::FileField<S, T, K>& field)
{
    if constexpr (K == Primitive::kPoint3D)
        out.point3D(data.*field.member);
    else if constexpr (K == Primitive::kVector3D)
        out.vector3D(data.*field.member);
    else
        out.f32(data.*field.member);
}

template <class S, class E, std::size_t N>
void writeField(Encoder& out, const S& data, const layout::VertexPointsField<S, E, N>& field)
{
    for (const E& vertex : data.*field.member)
        out.point3D(vertex.point);
}

template <class S, class N, class E>
void writeField(Encoder& out, const S& data, const layout::CountedVertexPointsField<S, N, E>& field)
{
    const std::size_t n = std::size_t(data.*field.count);
    out.u32(static_cast<std::uint32_t>(n));
    for (std::size_t i = 0; i < n; ++i)
        out.point3D((data.*field.member)[i].point);
}

template <class S, class T, Primitive K>
bool hasDefault(const layout::FileField<S, T, K>& field)
{
    return field.hasDefault;
}
template <class F>
bool hasDefault(const F&)
{
    return false;
}

template <class S, class T, Primitive K>
void takeDefault(S& data, const layout::FileField<S, T, K>& field)
{
    data.*field.member = field.fallback;
}
template <class S, class F>
void takeDefault(S&, const F&)
{
}

// Trailing fields are numbers (the ranges); -0 counts as the default 0, as
// the hand-written writers had it.
template <class S, Primitive K>
bool isDefault(const S& data, const layout::FileField<S, float, K>& field)
{
    return field.hasDefault && data.*field.member == field.fallback;
}

template <class Tuple, class F>
void each(const Tuple& tuple, F&& f)
{
    std::apply([&](const auto&... item) { (f(item), ...); }, tuple);
}

// The fields outside trailing(): all read, or, when each has a default and
// the object has no data at all, all defaults (MF3D's "0-sized objects").
// Then each trailing group: read when data is left, else its defaults.
template <class S>
void readData(DataReader& in, S& data, Held& held)
{
    const auto fields = layout::Describe<S>::fileFields();
    bool allDefaults = true;
    each(fields, [&](const auto& field) {
        if constexpr (!isTrailing<decltype(field)>)
            allDefaults = allDefaults && hasDefault(field);
    });
    const bool defaults = allDefaults && in.atEnd();
    each(fields, [&](const auto& field) {
        if constexpr (isTrailing<decltype(field)>) {
            const bool present = !in.atEnd();
            each(field.fields, [&](const auto& tail) {
                if (present)
                    readField(in, data, held, tail);
                else
                    takeDefault(data, tail);
            });
        } else if (defaults) {
            takeDefault(data, field);
        } else {
            readField(in, data, held, field);
        }
    });
}

template <class S>
void writeData(Encoder& out, const S& data)
{
    each(layout::Describe<S>::fileFields(), [&](const auto& field) {
        if constexpr (isTrailing<decltype(field)>) {
            bool whole = true;
            each(field.fields, [&](const auto& tail) { whole = whole && isDefault(data, tail); });
            if (!whole)
                each(field.fields, [&](const auto& tail) { writeField(out, data, tail); });
        } else {
            writeField(out, data, field);
        }
    });
}

// ---- the subobjects ------------------------------------------------------------

TQ3EndCap readCaps(ReadContext& context, const Parts& parts)
{
    const Node* node = parts.find(kTypeCaps);
    if (node == nullptr)
        return kQ3EndCapNone;
    DataReader in = context.reader(*node);
    return static_cast<TQ3EndCap>(in.flags(kCaps));
}

void writeCaps(Encoder& out, TQ3EndCap caps)
{
    if (caps == kQ3EndCapNone)
        return;
    out.begin(kTypeCaps, "Caps");
    out.flags(kCaps, static_cast<std::uint32_t>(caps));
    out.end();
}

Ref<AttributeSet> readCapSet(ReadContext& context, const Parts& parts, const CapSet& cap)
{
    const Node* node = parts.find(cap.type);
    if (node == nullptr)
        return {};
    if (node->type != kTypeContainer || node->children.size() != 2)
        fail(kQ3ErrorInvalidMetafileSubObject, std::string("a ") + cap.name + " without exactly one attribute set");
    return context.objectAs<AttributeSet>(node->children[1], cap.name);
}

void writeCapSet(WriteContext& context, const CapSet& cap, const AttributeSet* set)
{
    if (!WriteContext::hasAttributes(set))
        return;
    Encoder& out = context.out();
    out.begin(kTypeContainer, "Container");
    out.begin(cap.type, cap.name);
    out.end();
    context.attributeSet(set);
    out.end();
}

struct SetListTag {
    TQ3ObjectType type;
    const char* name;
};
constexpr SetListTag kFaceSets = {kTypeFaceSets, "FaceAttributeSetList"};
constexpr SetListTag kOtherSets = {kTypeGeometrySets, "GeometryAttributeSetList"};

const SetListTag& tagOf(layout::SetList list)
{
    return list == layout::SetList::kFaces ? kFaceSets : kOtherSets;
}

// The list's sets, one per element, or none when the array is NULL.
template <class S, class Count>
std::vector<const AttributeSet*> setsOf(const S& data, const layout::SetListPart<S, Count>& part)
{
    std::vector<const AttributeSet*> sets;
    if (data.*part.member != nullptr) {
        const std::size_t n = part.count(data);
        for (std::size_t i = 0; i < n; ++i)
            sets.push_back(setOf((data.*part.member)[i]));
    }
    return sets;
}

void readVertexSetsInto(ReadContext& context, const Parts& parts, TQ3Vertex3D* vertices, std::size_t n, Held& held)
{
    std::vector<Ref<AttributeSet>> sets = readVertexSets(context, parts, n);
    for (std::size_t i = 0; i < n; ++i) {
        vertices[i].attributeSet = sets[i].get();
        held.references.push_back(std::move(sets[i]));
    }
}

template <class S>
void readPart(ReadContext& context, const Parts& parts, S& data, Held& held, const layout::OwnSetPart<S>& part)
{
    held.references.push_back(context.attributeSet(parts));
    data.*part.member = held.references.back().get();
}

template <class S>
void readPart(ReadContext& context, const Parts& parts, S& data, Held& held, const layout::CapSetPart<S>& part)
{
    held.references.push_back(readCapSet(context, parts, capSetOf(part.part)));
    data.*part.member = held.references.back().get();
}

template <class S, std::size_t N>
void readPart(ReadContext& context, const Parts& parts, S& data, Held& held, const layout::VertexSetsPart<S, TQ3Vertex3D, N>& part)
{
    readVertexSetsInto(context, parts, data.*part.member, N, held);
}

template <class S, class N>
void readPart(ReadContext& context, const Parts& parts, S& data, Held& held,
              const layout::CountedVertexSetsPart<S, N, TQ3Vertex3D>& part)
{
    readVertexSetsInto(context, parts, data.*part.member, std::size_t(data.*part.count), held);
}

template <class S, class Count>
void readPart(ReadContext& context, const Parts& parts, S& data, Held& held, const layout::SetListPart<S, Count>& part)
{
    const SetListTag& tag = tagOf(part.list);
    const std::size_t n = part.count(data);
    std::vector<Ref<AttributeSet>> sets = readSetList(context, parts, tag.type, tag.name, n);
    auto handles = std::make_unique<TQ3AttributeSet[]>(n);
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
        handles[i] = sets[i].get();
        any = any || handles[i] != nullptr;
        held.references.push_back(std::move(sets[i]));
    }
    data.*part.member = any ? handles.get() : nullptr;
    held.setArrays.push_back(std::move(handles));
}

template <class S, class T>
void readPart(ReadContext& context, const Parts& parts, S& data, Held&, const layout::EndCapsPart<S, T>& part)
{
    data.*part.member = readCaps(context, parts);
}

template <class S>
bool writesSomething(const S& data, const layout::OwnSetPart<S>& part)
{
    return WriteContext::hasAttributes(setOf(data.*part.member));
}
template <class S>
bool writesSomething(const S& data, const layout::CapSetPart<S>& part)
{
    return WriteContext::hasAttributes(setOf(data.*part.member));
}
template <class S, class E, std::size_t N>
bool writesSomething(const S& data, const layout::VertexSetsPart<S, E, N>& part)
{
    return anyVertexSet(data.*part.member, N);
}
template <class S, class N, class E>
bool writesSomething(const S& data, const layout::CountedVertexSetsPart<S, N, E>& part)
{
    return anyVertexSet(data.*part.member, static_cast<unsigned long>(data.*part.count));
}
template <class S, class Count>
bool writesSomething(const S& data, const layout::SetListPart<S, Count>& part)
{
    return anySet(setsOf(data, part));
}
template <class S, class T>
bool writesSomething(const S& data, const layout::EndCapsPart<S, T>& part)
{
    return data.*part.member != kQ3EndCapNone;
}

template <class S>
void writePart(WriteContext& context, const S& data, const layout::OwnSetPart<S>& part)
{
    context.attributeSet(setOf(data.*part.member));
}
template <class S>
void writePart(WriteContext& context, const S& data, const layout::CapSetPart<S>& part)
{
    writeCapSet(context, capSetOf(part.part), setOf(data.*part.member));
}
template <class S, class E, std::size_t N>
void writePart(WriteContext& context, const S& data, const layout::VertexSetsPart<S, E, N>& part)
{
    writeVertexSets(context, data.*part.member, N);
}
template <class S, class N, class E>
void writePart(WriteContext& context, const S& data, const layout::CountedVertexSetsPart<S, N, E>& part)
{
    writeVertexSets(context, data.*part.member, static_cast<unsigned long>(data.*part.count));
}
template <class S, class Count>
void writePart(WriteContext& context, const S& data, const layout::SetListPart<S, Count>& part)
{
    const SetListTag& tag = tagOf(part.list);
    writeSetList(context, tag.type, tag.name, setsOf(data, part));
}
template <class S, class T>
void writePart(WriteContext& context, const S& data, const layout::EndCapsPart<S, T>& part)
{
    writeCaps(context.out(), data.*part.member);
}

template <class P>
struct IsOwnSet : std::false_type {};
template <class S>
struct IsOwnSet<layout::OwnSetPart<S>> : std::true_type {};
template <class P>
constexpr bool isOwnSet = IsOwnSet<std::decay_t<P>>::value;

// ---- the class's reader and writer ----------------------------------------------

template <class T>
Ref<SharedObject> readSimple(ReadContext& context, const Parts& parts)
{
    using S = typename T::DataType;
    DataReader in = context.reader(parts.root);
    S data{};
    Held held;
    readData(in, data, held);
    const auto partList = layout::Describe<S>::fileParts();
    each(partList, [&](const auto& part) {
        if constexpr (!isOwnSet<decltype(part)>)
            readPart(context, parts, data, held, part);
    });
    each(partList, [&](const auto& part) {
        if constexpr (isOwnSet<decltype(part)>)
            readPart(context, parts, data, held, part);
    });
    return make<T>(data);
}

template <class T>
void writeSimple(WriteContext& context, const Object& object)
{
    using S = typename T::DataType;
    static const char* const name = classOfType(T::kClassType)->name;
    const S& data = dataOf<T>(object);
    const auto partList = layout::Describe<S>::fileParts();
    bool container = false;
    each(partList, [&](const auto& part) { container = container || writesSomething(data, part); });
    maybeContainer(context, container, [&] {
        Encoder& out = context.out();
        out.begin(T::kClassType, name);
        writeData(out, data);
        out.end();
        each(partList, [&](const auto& part) { writePart(context, data, part); });
    });
}

template <class T>
ClassIO simpleClass(const char* name)
{
    return {T::kClassType, name, readSimple<T>, writeSimple<T>};
}

} // namespace

void addSimpleGeometryClasses(std::vector<ClassIO>& table)
{
    table.insert(table.end(), {
                                  simpleClass<Point>("Point"),
                                  simpleClass<Line>("Line"),
                                  simpleClass<PolyLine>("PolyLine"),
                                  simpleClass<Triangle>("Triangle"),
                                  simpleClass<Polygon>("Polygon"),
                                  simpleClass<Box>("Box"),
                                  simpleClass<Cone>("Cone"),
                                  simpleClass<Cylinder>("Cylinder"),
                                  simpleClass<Disk>("Disk"),
                                  simpleClass<Ellipse>("Ellipse"),
                                  simpleClass<Ellipsoid>("Ellipsoid"),
                                  simpleClass<Torus>("Torus"),
                                  {kTopCap.type, kTopCap.name, refusePart, writeNothing},
                                  {kBottomCap.type, kBottomCap.name, refusePart, writeNothing},
                                  {kFaceCap.type, kFaceCap.name, refusePart, writeNothing},
                                  {kInteriorCap.type, kInteriorCap.name, refusePart, writeNothing},
                              });
}

} // namespace q3::io
