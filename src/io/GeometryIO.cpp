// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The geometries' 3DMF layouts (3D Metafile Reference, "Geometry objects"):
// each class's data in the reference's field order, its own attribute set
// and its parts' attribute sets as subobjects. A geometry read from a file
// goes through the class's own validation, so a file can never create a
// geometry the API would refuse. The simple geometries (point, line,
// polyline, triangle, polygon, box, the quadrics) come from their data
// descriptions (SimpleGeometryIO.cpp); here are the TriMesh and the NURB
// curve, and GeometryIOComplex.cpp has the geometries with nested parts.

#include "io/ClassIO.h"
#include "io/GeometryIOSupport.h"

#include "geometry/NURBCurve.h"
#include "geometry/TriMesh.h"

#include <cstring>
#include <vector>

namespace q3::io {
namespace {

Ref<SharedObject> refusePart(ReadContext&, const Parts& parts)
{
    fail(kQ3ErrorInvalidMetafileObject,
         (parts.root.name.empty() ? typeName(parts.root.type) : parts.root.name) + " outside its geometry");
}

void writeNothing(WriteContext&, const Object&) {}

// ---- the classes ---------------------------------------------------------------

// TriMesh indices are 8, 16 or 32 bits in binary files: 8 when the count is
// at most 0xFF, 16 when it is at most 0xFFFF, else 32, so the largest index
// is never all ones (Quesa writes and reads the same widths; the 1.0
// reference predates the TriMesh). An edge's triangle index of all ones at
// its width is kQ3ArrayIndexNULL (no triangle on that side).
std::size_t indexBytes(std::uint32_t count)
{
    return count <= 0xFF ? 1 : count <= 0xFFFF ? 2 : 4;
}

unsigned long readIndex(DataReader& in, bool text, std::size_t bytes, std::uint32_t bound, const char* what,
                        bool nullable = false)
{
    const std::uint32_t index = text || bytes == 4 ? in.u32() : bytes == 2 ? in.u16() : in.u8();
    const std::uint32_t allOnes = text || bytes == 4 ? 0xFFFFFFFFu : bytes == 2 ? 0xFFFFu : 0xFFu;
    if (nullable && index == allOnes)
        return static_cast<unsigned long>(kQ3ArrayIndexNULL);
    if (index >= bound)
        fail(kQ3ErrorInvalidMetafileObject, std::string("a TriMesh ") + what + " index " + std::to_string(index) +
                                                " is past the end (" + std::to_string(bound) + ")");
    return index;
}

void writeIndex(Encoder& out, std::size_t bytes, std::uint32_t index)
{
    if (out.encoding() == Encoding::kText || bytes == 4)
        out.u32(index);
    else if (bytes == 2)
        out.u16(static_cast<std::uint16_t>(index));
    else
        out.u8(static_cast<std::uint8_t>(index));
}

// ---- TriMesh attribute arrays ---------------------------------------------------
//
// One AttributeArray subobject per array: the attribute type, 0, which array
// (0 triangles, 1 edges, 2 vertices), its index among that kind's arrays,
// whether a use array follows; then the use array (one byte per element)
// when it does, and one value per element (the QD3D 1.5.4 book's
// "Attribute Arrays": the use array "follows immediately" the flag, and
// Quesa's reader reads it there).

constexpr TQ3ObjectType kTypeAttributeArray = Q3_OBJECT_TYPE('a', 't', 'a', 'r');

// Words (floats, or one 32-bit switch) of one value of an attribute type,
// as the attribute set stores it; none for the surface shader, whose values
// are objects after the array.
std::size_t wordsOf(TQ3AttributeType type)
{
    if (type < Set::kFirstType || type > Set::kLastStoredType)
        fail(kQ3ErrorInvalidMetafileObject,
             "a TriMesh attribute array of type " + std::to_string(type) + ", which Q3 does not store");
    if (type == kQ3AttributeTypeSurfaceShader)
        return 0;
    return Set::dataSize(type) / sizeof(std::uint32_t);
}

struct ArrayStore {
    std::vector<TQ3TriMeshAttributeData> entries;
    std::vector<std::vector<unsigned char>> values;
    std::vector<std::vector<char>> uses;
    std::vector<Ref<SharedObject>> shaders; ///< what surface shader arrays point at, until the TriMesh holds them
};

// A surface shader array's values: the objects that follow the
// AttributeArray in its container, one per element (a texture shader, or a
// reference to one), as Apple's tools and Quesa write them. Fewer objects
// than elements leave the rest NULL (no shader), as Quesa reads them.
void readShaderValues(ReadContext& context, const Node* container, std::uint32_t n, ArrayStore& store,
                      std::vector<unsigned char>& values)
{
    values.assign(std::size_t{n} * sizeof(TQ3Object), 0);
    if (container == nullptr)
        return;
    const std::size_t given = container->children.size() - 1;
    if (given > n)
        fail(kQ3ErrorInvalidMetafileSubObject, "a TriMesh surface shader array holds " + std::to_string(given) +
                                                   " shaders for " + std::to_string(n) + " elements");
    for (std::size_t i = 0; i < given; ++i) {
        Ref<SharedObject> shader = context.object(container->children[i + 1]);
        if (!shader->isType(kQ3ShaderTypeSurface))
            fail(kQ3ErrorInvalidMetafileSubObject, std::string("a TriMesh surface shader array holds a ") +
                                                       shader->classInfo().name);
        TQ3Object handle = shader.get();
        std::memcpy(values.data() + i * sizeof(TQ3Object), &handle, sizeof handle);
        store.shaders.push_back(std::move(shader));
    }
}

void readAttributeArrays(ReadContext& context, const Parts& parts, const std::uint32_t counts[3],
                         const std::uint32_t elements[3], ArrayStore stores[3])
{
    for (int kind = 0; kind < 3; ++kind) {
        stores[kind].entries.assign(counts[kind], TQ3TriMeshAttributeData{kQ3AttributeTypeNone, nullptr, nullptr});
        stores[kind].values.resize(counts[kind]);
        stores[kind].uses.resize(counts[kind]);
    }
    for (const Node* item : parts.subobjects) {
        // A surface shader array is a container: the array, then its shaders.
        const bool contained = item->type == kTypeContainer && !item->children.empty() &&
                               item->children.front().type == kTypeAttributeArray;
        const Node* node = contained ? &item->children.front() : item;
        if (node->type != kTypeAttributeArray)
            continue;
        DataReader in = context.reader(*node);
        const auto type = static_cast<TQ3AttributeType>(in.i32());
        in.u32();
        const std::uint32_t kind = in.u32();
        const std::uint32_t index = in.u32();
        const bool useFlags = in.u32() != 0;
        if (kind > 2 || index >= counts[kind])
            fail(kQ3ErrorInvalidMetafileSubObject, "a TriMesh attribute array at " + std::to_string(kind) + "/" +
                                                       std::to_string(index) + ", which the TriMesh does not have");
        ArrayStore& store = stores[kind];
        if (store.entries[index].attributeType != kQ3AttributeTypeNone)
            fail(kQ3ErrorInvalidMetafileSubObject, "two TriMesh attribute arrays at one place");
        const std::size_t words = wordsOf(type);
        const std::uint32_t n = elements[kind];
        std::vector<char> use;
        // Quesa's writer sets the flag but writes no use bytes for a built-in
        // attribute type: when the data holds the values and no room for the
        // bytes, the file is read as Quesa wrote it, every element using its
        // value.
        const bool quesaWithoutUses = useFlags && !in.hasRoom(n, 1 + 4 * words, 1 + words) &&
                                      in.hasRoom(n, 4 * words, words);
        if (useFlags && !quesaWithoutUses) {
            in.requireRoom(n, 1, 1, "use flags");
            use.resize(n);
            for (char& flag : use)
                flag = static_cast<char>(in.u8());
        }
        in.requireRoom(n, 4 * words, words, "attribute values");
        std::vector<unsigned char> values(std::size_t{n} * words * 4);
        if (type == kQ3AttributeTypeSurfaceShader)
            readShaderValues(context, contained ? item : nullptr, n, store, values);
        else if (contained)
            fail(kQ3ErrorInvalidMetafileSubObject, "a TriMesh attribute array of type " + std::to_string(type) +
                                                       " is followed by objects");
        for (std::size_t w = 0; w < std::size_t{n} * words; ++w) {
            if (type == kQ3AttributeTypeHighlightState) {
                const auto s = static_cast<TQ3Switch>(in.u32());
                std::memcpy(values.data() + 4 * w, &s, 4);
            } else {
                const float f = in.f32();
                std::memcpy(values.data() + 4 * w, &f, 4);
            }
        }
        store.values[index] = std::move(values);
        store.uses[index] = std::move(use);
        store.entries[index] = TQ3TriMeshAttributeData{type, store.values[index].data(),
                                                       store.uses[index].empty() ? nullptr : store.uses[index].data()};
    }
    for (int kind = 0; kind < 3; ++kind)
        for (const auto& entry : stores[kind].entries)
            if (entry.attributeType == kQ3AttributeTypeNone)
                fail(kQ3ErrorInvalidMetafileSubObject, "a TriMesh announces an attribute array it does not hold");
}

void writeAttributeArrays(WriteContext& context, std::uint32_t kind, const TQ3TriMeshAttributeData* entries,
                          unsigned long count, unsigned long elements)
{
    Encoder& out = context.out();
    for (unsigned long i = 0; i < count; ++i) {
        const TQ3TriMeshAttributeData& entry = entries[i];
        const std::size_t words = wordsOf(entry.attributeType);
        const bool shaders = entry.attributeType == kQ3AttributeTypeSurfaceShader;
        if (shaders)
            out.begin(kTypeContainer, "Container");
        out.begin(kTypeAttributeArray, "AttributeArray");
        out.i32(static_cast<std::int32_t>(entry.attributeType));
        out.u32(0);
        out.u32(kind);
        out.u32(static_cast<std::uint32_t>(i));
        out.u32(entry.attributeUseArray != nullptr ? 1 : 0);
        if (entry.attributeUseArray != nullptr)
            for (unsigned long e = 0; e < elements; ++e)
                out.u8(static_cast<std::uint8_t>(entry.attributeUseArray[e]));
        const auto* bytes = static_cast<const unsigned char*>(entry.data);
        for (std::size_t w = 0; w < elements * words; ++w) {
            if (entry.attributeType == kQ3AttributeTypeHighlightState) {
                TQ3Switch s;
                std::memcpy(&s, bytes + 4 * w, 4);
                out.u32(static_cast<std::uint32_t>(s));
            } else {
                float f;
                std::memcpy(&f, bytes + 4 * w, 4);
                out.f32(f);
            }
        }
        out.end();
        if (!shaders)
            continue;
        // The shaders follow, one per element up to the last one present; an
        // element without a shader before it cannot be written.
        unsigned long last = elements;
        while (last > 0 && static_cast<const TQ3Object*>(entry.data)[last - 1] == nullptr)
            --last;
        for (unsigned long e = 0; e < last; ++e) {
            const TQ3Object handle = static_cast<const TQ3Object*>(entry.data)[e];
            if (handle == nullptr)
                fail(kQ3ErrorInvalidParameter, "a TriMesh surface shader array has no shader at element " +
                                                   std::to_string(e) + " before one that has: 3DMF cannot say so");
            context.object(*static_cast<const Object*>(handle));
        }
        out.end();
    }
}

Ref<SharedObject> readTriMesh(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    const bool text = context.file().encoding == Encoding::kText;
    const std::uint32_t numTriangles = in.u32();
    const std::uint32_t numTriangleTypes = in.u32();
    const std::uint32_t numEdges = in.u32();
    const std::uint32_t numEdgeTypes = in.u32();
    const std::uint32_t numPoints = in.u32();
    const std::uint32_t numVertexTypes = in.u32();
    if (numTriangleTypes > 64 || numEdgeTypes > 64 || numVertexTypes > 64)
        fail(kQ3ErrorInvalidMetafileObject, "a TriMesh announces more attribute arrays than it could hold");
    const std::size_t pointBytes = indexBytes(numPoints);
    const std::size_t triangleBytes = indexBytes(numTriangles);
    in.requireRoom(numTriangles, 3 * pointBytes, 3, "triangles");
    std::vector<TQ3TriMeshTriangleData> triangles(numTriangles);
    for (auto& triangle : triangles)
        for (auto& index : triangle.pointIndices)
            index = readIndex(in, text, pointBytes, numPoints, "point");
    in.requireRoom(numEdges, 2 * pointBytes + 2 * triangleBytes, 4, "edges");
    std::vector<TQ3TriMeshEdgeData> edges(numEdges);
    for (auto& edge : edges) {
        for (auto& index : edge.pointIndices)
            index = readIndex(in, text, pointBytes, numPoints, "point");
        for (auto& index : edge.triangleIndices)
            index = readIndex(in, text, triangleBytes, numTriangles, "triangle", true);
    }
    in.requireRoom(numPoints, 12, 3, "points");
    std::vector<TQ3Point3D> points(numPoints);
    for (auto& point : points)
        point = in.point3D();
    TQ3BoundingBox box;
    box.min = in.point3D();
    box.max = in.point3D();
    box.isEmpty = in.u32() != 0 ? kQ3True : kQ3False;
    Ref<AttributeSet> own = context.attributeSet(parts);
    const std::uint32_t counts[3] = {numTriangleTypes, numEdgeTypes, numVertexTypes};
    const std::uint32_t elements[3] = {numTriangles, numEdges, numPoints};
    ArrayStore stores[3];
    readAttributeArrays(context, parts, counts, elements, stores);
    TQ3TriMeshData data{};
    data.triMeshAttributeSet = own.get();
    data.numTriangleAttributeTypes = numTriangleTypes;
    data.triangleAttributeTypes = numTriangleTypes ? stores[0].entries.data() : nullptr;
    data.numEdgeAttributeTypes = numEdgeTypes;
    data.edgeAttributeTypes = numEdgeTypes ? stores[1].entries.data() : nullptr;
    data.numVertexAttributeTypes = numVertexTypes;
    data.vertexAttributeTypes = numVertexTypes ? stores[2].entries.data() : nullptr;
    data.numTriangles = numTriangles;
    data.triangles = triangles.data();
    data.numEdges = numEdges;
    data.edges = edges.empty() ? nullptr : edges.data();
    data.numPoints = numPoints;
    data.points = points.data();
    data.bBox = box;
    return make<TriMesh>(data);
}

void writeTriMesh(WriteContext& context, const Object& object)
{
    const TQ3TriMeshData& data = dataOf<TriMesh>(object);
    const AttributeSet* own = setOf(data.triMeshAttributeSet);
    const bool arrays = data.numTriangleAttributeTypes + data.numEdgeAttributeTypes + data.numVertexAttributeTypes > 0;
    maybeContainer(context, WriteContext::hasAttributes(own) || arrays, [&] {
        Encoder& out = context.out();
        out.begin(kQ3GeometryTypeTriMesh, "TriMesh");
        out.u32(static_cast<std::uint32_t>(data.numTriangles));
        out.u32(static_cast<std::uint32_t>(data.numTriangleAttributeTypes));
        out.u32(static_cast<std::uint32_t>(data.numEdges));
        out.u32(static_cast<std::uint32_t>(data.numEdgeAttributeTypes));
        out.u32(static_cast<std::uint32_t>(data.numPoints));
        out.u32(static_cast<std::uint32_t>(data.numVertexAttributeTypes));
        const std::size_t pointBytes = indexBytes(static_cast<std::uint32_t>(data.numPoints));
        const std::size_t triangleBytes = indexBytes(static_cast<std::uint32_t>(data.numTriangles));
        for (unsigned long i = 0; i < data.numTriangles; ++i)
            for (unsigned long index : data.triangles[i].pointIndices)
                writeIndex(out, pointBytes, static_cast<std::uint32_t>(index));
        for (unsigned long i = 0; i < data.numEdges; ++i) {
            for (unsigned long index : data.edges[i].pointIndices)
                writeIndex(out, pointBytes, static_cast<std::uint32_t>(index));
            for (unsigned long index : data.edges[i].triangleIndices)
                writeIndex(out, triangleBytes, static_cast<std::uint32_t>(index));
        }
        for (unsigned long i = 0; i < data.numPoints; ++i)
            out.point3D(data.points[i]);
        out.point3D(data.bBox.min);
        out.point3D(data.bBox.max);
        out.u32(data.bBox.isEmpty != kQ3False ? 1 : 0);
        out.end();
        writeAttributeArrays(context, 0, data.triangleAttributeTypes, data.numTriangleAttributeTypes, data.numTriangles);
        writeAttributeArrays(context, 1, data.edgeAttributeTypes, data.numEdgeAttributeTypes, data.numEdges);
        writeAttributeArrays(context, 2, data.vertexAttributeTypes, data.numVertexAttributeTypes, data.numPoints);
        context.attributeSet(own);
    });
}

Ref<SharedObject> readNURBCurve(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    const std::uint32_t order = in.u32();
    const std::uint32_t numPoints = in.count(16, 4, "control points");
    std::vector<TQ3RationalPoint4D> points(numPoints);
    for (auto& point : points)
        point = in.point4D();
    const std::uint64_t numKnots = std::uint64_t{order} + numPoints;
    in.requireRoom(numKnots, 4, 1, "knots");
    std::vector<float> knots(static_cast<std::size_t>(numKnots));
    for (float& knot : knots)
        knot = in.f32();
    Ref<AttributeSet> own = context.attributeSet(parts);
    TQ3NURBCurveData data{order, numPoints, points.data(), knots.data(), own.get()};
    return make<NURBCurve>(data);
}

void writeNURBCurve(WriteContext& context, const Object& object)
{
    const TQ3NURBCurveData& data = dataOf<NURBCurve>(object);
    const AttributeSet* own = setOf(data.curveAttributeSet);
    maybeContainer(context, WriteContext::hasAttributes(own), [&] {
        Encoder& out = context.out();
        out.begin(kQ3GeometryTypeNURBCurve, "NURBCurve");
        out.u32(static_cast<std::uint32_t>(data.order));
        out.u32(static_cast<std::uint32_t>(data.numPoints));
        for (unsigned long i = 0; i < data.numPoints; ++i)
            out.point4D(data.controlPoints[i]);
        for (unsigned long i = 0; i < data.order + data.numPoints; ++i)
            out.f32(data.knots[i]);
        out.end();
        context.attributeSet(own);
    });
}

} // namespace

void addGeometryClasses(std::vector<ClassIO>& table)
{
    addSimpleGeometryClasses(table);
    table.insert(table.end(), {
                                  {kQ3GeometryTypeTriMesh, "TriMesh", readTriMesh, writeTriMesh},
                                  {kQ3GeometryTypeNURBCurve, "NURBCurve", readNURBCurve, writeNURBCurve},
                                  {kTypeGeometrySets, "GeometryAttributeSetList", refusePart, writeNothing},
                              });
    addComplexGeometryClasses(table);
}

} // namespace q3::io
