// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The geometries' 3DMF layouts (3D Metafile Reference, "Geometry objects"):
// each class's data in the reference's field order, its own attribute set
// and its vertices' attribute sets (a VertexAttributeSetList) as subobjects.
// A geometry read from a file goes through the class's own validation, so a
// file can never create a geometry the API would refuse.

#include "io/ClassIO.h"
#include "io/GeometryIOSupport.h"

#include "geometry/Box.h"
#include "geometry/Cone.h"
#include "geometry/Cylinder.h"
#include "geometry/Disk.h"
#include "geometry/Ellipse.h"
#include "geometry/Ellipsoid.h"
#include "geometry/Line.h"
#include "geometry/NURBCurve.h"
#include "geometry/Point.h"
#include "geometry/PolyLine.h"
#include "geometry/Polygon.h"
#include "geometry/Torus.h"
#include "geometry/TriMesh.h"
#include "geometry/Triangle.h"

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

Ref<SharedObject> readPoint(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    TQ3PointData data{in.point3D(), nullptr};
    Ref<AttributeSet> set = context.attributeSet(parts);
    data.pointAttributeSet = set.get();
    return make<Point>(data);
}

void writePoint(WriteContext& context, const Object& object)
{
    const TQ3PointData& data = dataOf<Point>(object);
    writeWithSets(context, setOf(data.pointAttributeSet), nullptr, 0, [&] {
        context.out().begin(kQ3GeometryTypePoint, "Point");
        context.out().point3D(data.point);
        context.out().end();
    });
}

Ref<SharedObject> readLine(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    std::vector<TQ3Vertex3D> vertices = readPoints(in, 2);
    const auto sets = readVertexSets(context, parts, 2);
    attachSets(vertices, sets);
    Ref<AttributeSet> own = context.attributeSet(parts);
    TQ3LineData data{{vertices[0], vertices[1]}, own.get()};
    return make<Line>(data);
}

void writeLine(WriteContext& context, const Object& object)
{
    const TQ3LineData& data = dataOf<Line>(object);
    writeWithSets(context, setOf(data.lineAttributeSet), data.vertices, 2, [&] {
        context.out().begin(kQ3GeometryTypeLine, "Line");
        context.out().point3D(data.vertices[0].point);
        context.out().point3D(data.vertices[1].point);
        context.out().end();
    });
}

Ref<SharedObject> readTriangle(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    std::vector<TQ3Vertex3D> vertices = readPoints(in, 3);
    const auto sets = readVertexSets(context, parts, 3);
    attachSets(vertices, sets);
    Ref<AttributeSet> own = context.attributeSet(parts);
    TQ3TriangleData data{{vertices[0], vertices[1], vertices[2]}, own.get()};
    return make<Triangle>(data);
}

void writeTriangle(WriteContext& context, const Object& object)
{
    const TQ3TriangleData& data = dataOf<Triangle>(object);
    writeWithSets(context, setOf(data.triangleAttributeSet), data.vertices, 3, [&] {
        context.out().begin(kQ3GeometryTypeTriangle, "Triangle");
        for (const TQ3Vertex3D& vertex : data.vertices)
            context.out().point3D(vertex.point);
        context.out().end();
    });
}

template <class T, class Data>
Ref<SharedObject> readVertexList(ReadContext& context, const Parts& parts, Data data, TQ3AttributeSet Data::*own)
{
    DataReader in = context.reader(parts.root);
    const std::uint32_t n = in.count(12, 3, "vertices");
    std::vector<TQ3Vertex3D> vertices = readPoints(in, n);
    const auto sets = readVertexSets(context, parts, n);
    attachSets(vertices, sets);
    Ref<AttributeSet> set = context.attributeSet(parts);
    data.numVertices = n;
    data.vertices = vertices.data();
    data.*own = set.get();
    return make<T>(data);
}

// A polyline's segments' sets: a GeometryAttributeSetList of numVertices - 1
// elements.

Ref<SharedObject> readPolyLine(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    const std::uint32_t n = in.count(12, 3, "vertices");
    std::vector<TQ3Vertex3D> vertices = readPoints(in, n);
    const auto sets = readVertexSets(context, parts, n);
    attachSets(vertices, sets);
    const auto segmentSets =
        readSetList(context, parts, kTypeGeometrySets, "GeometryAttributeSetList", n == 0 ? 0 : n - 1);
    std::vector<TQ3AttributeSet> segments(segmentSets.size());
    bool anySegment = false;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        segments[i] = segmentSets[i].get();
        anySegment = anySegment || segments[i] != nullptr;
    }
    Ref<AttributeSet> own = context.attributeSet(parts);
    TQ3PolyLineData data{n, vertices.data(), anySegment ? segments.data() : nullptr, own.get()};
    return make<PolyLine>(data);
}

Ref<SharedObject> readPolygon(ReadContext& context, const Parts& parts)
{
    return readVertexList<Polygon>(context, parts, TQ3PolygonData{0, nullptr, nullptr},
                                   &TQ3PolygonData::polygonAttributeSet);
}

void writeVertexListObject(WriteContext& context, TQ3ObjectType type, const char* name, const TQ3Vertex3D* vertices,
                           unsigned long n, const AttributeSet* own)
{
    writeWithSets(context, own, vertices, n, [&] {
        context.out().begin(type, name);
        context.out().u32(static_cast<std::uint32_t>(n));
        for (unsigned long i = 0; i < n; ++i)
            context.out().point3D(vertices[i].point);
        context.out().end();
    });
}

void writePolyLine(WriteContext& context, const Object& object)
{
    const TQ3PolyLineData& data = dataOf<PolyLine>(object);
    const AttributeSet* own = setOf(data.polyLineAttributeSet);
    std::vector<const AttributeSet*> segments;
    if (data.segmentAttributeSet != nullptr)
        for (unsigned long i = 0; i + 1 < data.numVertices; ++i)
            segments.push_back(setOf(data.segmentAttributeSet[i]));
    const bool container =
        WriteContext::hasAttributes(own) || anyVertexSet(data.vertices, data.numVertices) || anySet(segments);
    maybeContainer(context, container, [&] {
        Encoder& out = context.out();
        out.begin(kQ3GeometryTypePolyLine, "PolyLine");
        out.u32(static_cast<std::uint32_t>(data.numVertices));
        for (unsigned long i = 0; i < data.numVertices; ++i)
            out.point3D(data.vertices[i].point);
        out.end();
        context.attributeSet(own);
        writeVertexSets(context, data.vertices, data.numVertices);
        writeSetList(context, kTypeGeometrySets, "GeometryAttributeSetList", segments);
    });
}

void writePolygon(WriteContext& context, const Object& object)
{
    const TQ3PolygonData& data = dataOf<Polygon>(object);
    writeVertexListObject(context, kQ3GeometryTypePolygon, "Polygon", data.vertices, data.numVertices,
                          setOf(data.polygonAttributeSet));
}

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

// Words (floats, or one 32-bit switch) of one value of an attribute type;
// none for the surface shader, whose values are objects after the array.
std::size_t wordsOf(TQ3AttributeType type)
{
    switch (type) {
    case kQ3AttributeTypeSurfaceShader:
        return 0;
    case kQ3AttributeTypeSurfaceUV:
    case kQ3AttributeTypeShadingUV:
        return 2;
    case kQ3AttributeTypeNormal:
    case kQ3AttributeTypeDiffuseColor:
    case kQ3AttributeTypeSpecularColor:
    case kQ3AttributeTypeTransparencyColor:
        return 3;
    case kQ3AttributeTypeAmbientCoefficient:
    case kQ3AttributeTypeSpecularControl:
    case kQ3AttributeTypeHighlightState:
        return 1;
    case kQ3AttributeTypeSurfaceTangent:
        return 6;
    default:
        fail(kQ3ErrorInvalidMetafileObject,
             "a TriMesh attribute array of type " + std::to_string(type) + ", which Q3 does not store");
    }
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

Ref<SharedObject> readBox(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    TQ3BoxData data{};
    // An empty Box ( ) is the unit box at the origin.
    data.orientation = {1, 0, 0};
    data.majorAxis = {0, 1, 0};
    data.minorAxis = {0, 0, 1};
    data.origin = {0, 0, 0};
    if (!in.atEnd()) {
        data.orientation = in.vector3D();
        data.majorAxis = in.vector3D();
        data.minorAxis = in.vector3D();
        data.origin = in.point3D();
    }
    // The six faces' sets (left, right, front, back, top, bottom): a
    // FaceAttributeSetList of 6 elements.
    const auto faceSets = readSetList(context, parts, kTypeFaceSets, "FaceAttributeSetList", 6);
    TQ3AttributeSet faces[6];
    bool anyFace = false;
    for (std::size_t i = 0; i < 6; ++i) {
        faces[i] = faceSets[i].get();
        anyFace = anyFace || faces[i] != nullptr;
    }
    data.faceAttributeSet = anyFace ? faces : nullptr;
    Ref<AttributeSet> own = context.attributeSet(parts);
    data.boxAttributeSet = own.get();
    return make<Box>(data);
}

void writeBox(WriteContext& context, const Object& object)
{
    const TQ3BoxData& data = dataOf<Box>(object);
    const AttributeSet* own = setOf(data.boxAttributeSet);
    std::vector<const AttributeSet*> faces;
    if (data.faceAttributeSet != nullptr)
        for (std::size_t i = 0; i < 6; ++i)
            faces.push_back(setOf(data.faceAttributeSet[i]));
    maybeContainer(context, WriteContext::hasAttributes(own) || anySet(faces), [&] {
        Encoder& out = context.out();
        out.begin(kQ3GeometryTypeBox, "Box");
        out.vector3D(data.orientation);
        out.vector3D(data.majorAxis);
        out.vector3D(data.minorAxis);
        out.point3D(data.origin);
        out.end();
        writeSetList(context, kTypeFaceSets, "FaceAttributeSetList", faces);
        context.attributeSet(own);
    });
}

// The u and v ranges, written only when they are not the whole surface.
struct Ranges {
    float uMin = 0, uMax = 1, vMin = 0, vMax = 1;
};

void readRanges(DataReader& in, Ranges& r, bool withV)
{
    if (in.atEnd())
        return;
    r.uMin = in.f32();
    r.uMax = in.f32();
    if (withV) {
        r.vMin = in.f32();
        r.vMax = in.f32();
    }
}

void writeRanges(Encoder& out, const Ranges& r, bool withV)
{
    const bool whole = r.uMin == 0 && r.uMax == 1 && (!withV || (r.vMin == 0 && r.vMax == 1));
    if (whole)
        return;
    out.f32(r.uMin);
    out.f32(r.uMax);
    if (withV) {
        out.f32(r.vMin);
        out.f32(r.vMax);
    }
}

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

// The attribute sets of a quadric's parts: a container whose root is the
// part's cap set object (no data) followed by the attribute set ("Top Cap
// Attribute Sets", "Bottom Cap Attribute Sets", "Face Cap Attribute Sets";
// the interior's set, which QuickDraw 3D 1.5 added, the same way).
struct CapSet {
    TQ3ObjectType type;
    const char* name;
};
constexpr CapSet kTopCap = {Q3_OBJECT_TYPE('t', 'c', 'a', 's'), "TopCapAttributeSet"};
constexpr CapSet kBottomCap = {Q3_OBJECT_TYPE('b', 'c', 'a', 's'), "BottomCapAttributeSet"};
constexpr CapSet kFaceCap = {Q3_OBJECT_TYPE('f', 'c', 'a', 's'), "FaceCapAttributeSet"};
constexpr CapSet kInteriorCap = {Q3_OBJECT_TYPE('i', 'c', 'a', 's'), "InteriorCapAttributeSet"};

Ref<AttributeSet> readCapSet(ReadContext& context, const Parts& parts, const CapSet& cap)
{
    const Node* node = parts.find(cap.type);
    if (node == nullptr)
        return {};
    if (node->type != kTypeContainer || node->children.size() != 2)
        fail(kQ3ErrorInvalidMetafileSubObject, std::string("a ") + cap.name + " without exactly one attribute set");
    return context.objectAs<AttributeSet>(node->children[1], cap.name);
}

void writeCapSet(WriteContext& context, const CapSet& cap, TQ3AttributeSet handle)
{
    const AttributeSet* set = setOf(handle);
    if (!WriteContext::hasAttributes(set))
        return;
    Encoder& out = context.out();
    out.begin(kTypeContainer, "Container");
    out.begin(cap.type, cap.name);
    out.end();
    context.attributeSet(set);
    out.end();
}

// Which cap sets each solid has, as members of its data.
template <class Data>
struct CapMember {
    const CapSet* cap;
    TQ3AttributeSet Data::*member;
};

template <class Data>
std::vector<CapMember<Data>> capMembers();
template <>
std::vector<CapMember<TQ3ConeData>> capMembers()
{
    return {{&kInteriorCap, &TQ3ConeData::interiorAttributeSet},
            {&kFaceCap, &TQ3ConeData::faceAttributeSet},
            {&kBottomCap, &TQ3ConeData::bottomAttributeSet}};
}
template <>
std::vector<CapMember<TQ3CylinderData>> capMembers()
{
    return {{&kInteriorCap, &TQ3CylinderData::interiorAttributeSet},
            {&kTopCap, &TQ3CylinderData::topAttributeSet},
            {&kFaceCap, &TQ3CylinderData::faceAttributeSet},
            {&kBottomCap, &TQ3CylinderData::bottomAttributeSet}};
}
template <>
std::vector<CapMember<TQ3EllipsoidData>> capMembers()
{
    return {{&kInteriorCap, &TQ3EllipsoidData::interiorAttributeSet}};
}
template <>
std::vector<CapMember<TQ3TorusData>> capMembers()
{
    return {{&kInteriorCap, &TQ3TorusData::interiorAttributeSet}};
}

// Cone, cylinder, ellipsoid and torus: orientation, major and minor radius,
// origin (the torus then its ratio), the optional ranges; caps and the
// attribute set as subobjects.
template <class T, class Data>
Ref<SharedObject> readSolid(ReadContext& context, const Parts& parts, Data data, TQ3AttributeSet Data::*own,
                            float Data::*ratio)
{
    DataReader in = context.reader(parts.root);
    // An object with no data is the default one of Apple's metafile parser
    // (MF3D's "For 0-sized objects, default is": orientation 1 0 0, major
    // axis 0 1 0, minor axis 0 0 1, origin 0 0 0, a torus's ratio 1), as for
    // the box.
    data.orientation = {1, 0, 0};
    data.majorRadius = {0, 1, 0};
    data.minorRadius = {0, 0, 1};
    data.origin = {0, 0, 0};
    if (ratio != nullptr)
        data.*ratio = 1;
    if (!in.atEnd()) {
        data.orientation = in.vector3D();
        data.majorRadius = in.vector3D();
        data.minorRadius = in.vector3D();
        data.origin = in.point3D();
        if (ratio != nullptr)
            data.*ratio = in.f32();
    }
    Ranges r;
    readRanges(in, r, true);
    data.uMin = r.uMin;
    data.uMax = r.uMax;
    data.vMin = r.vMin;
    data.vMax = r.vMax;
    data.caps = readCaps(context, parts);
    std::vector<Ref<AttributeSet>> capSets;
    for (const CapMember<Data>& member : capMembers<Data>()) {
        capSets.push_back(readCapSet(context, parts, *member.cap));
        data.*member.member = capSets.back().get();
    }
    Ref<AttributeSet> set = context.attributeSet(parts);
    data.*own = set.get();
    return make<T>(data);
}

template <class T, class Data>
void writeSolid(WriteContext& context, const Object& object, TQ3ObjectType type, const char* name,
                TQ3AttributeSet Data::*own, float Data::*ratio)
{
    const Data& data = dataOf<T>(object);
    const AttributeSet* set = setOf(data.*own);
    bool anyCapSet = false;
    for (const CapMember<Data>& member : capMembers<Data>())
        anyCapSet = anyCapSet || WriteContext::hasAttributes(setOf(data.*member.member));
    maybeContainer(context, WriteContext::hasAttributes(set) || data.caps != kQ3EndCapNone || anyCapSet, [&] {
        Encoder& out = context.out();
        out.begin(type, name);
        out.vector3D(data.orientation);
        out.vector3D(data.majorRadius);
        out.vector3D(data.minorRadius);
        out.point3D(data.origin);
        if (ratio != nullptr)
            out.f32(data.*ratio);
        writeRanges(out, Ranges{data.uMin, data.uMax, data.vMin, data.vMax}, true);
        out.end();
        writeCaps(out, data.caps);
        for (const CapMember<Data>& member : capMembers<Data>())
            writeCapSet(context, *member.cap, data.*member.member);
        context.attributeSet(set);
    });
}

Ref<SharedObject> readCone(ReadContext& c, const Parts& p)
{
    return readSolid<Cone>(c, p, TQ3ConeData{}, &TQ3ConeData::coneAttributeSet, static_cast<float TQ3ConeData::*>(nullptr));
}
void writeCone(WriteContext& c, const Object& o)
{
    writeSolid<Cone>(c, o, kQ3GeometryTypeCone, "Cone", &TQ3ConeData::coneAttributeSet, static_cast<float TQ3ConeData::*>(nullptr));
}
Ref<SharedObject> readCylinder(ReadContext& c, const Parts& p)
{
    return readSolid<Cylinder>(c, p, TQ3CylinderData{}, &TQ3CylinderData::cylinderAttributeSet, static_cast<float TQ3CylinderData::*>(nullptr));
}
void writeCylinder(WriteContext& c, const Object& o)
{
    writeSolid<Cylinder>(c, o, kQ3GeometryTypeCylinder, "Cylinder", &TQ3CylinderData::cylinderAttributeSet, static_cast<float TQ3CylinderData::*>(nullptr));
}
Ref<SharedObject> readEllipsoid(ReadContext& c, const Parts& p)
{
    return readSolid<Ellipsoid>(c, p, TQ3EllipsoidData{}, &TQ3EllipsoidData::ellipsoidAttributeSet,
                                 static_cast<float TQ3EllipsoidData::*>(nullptr));
}
void writeEllipsoid(WriteContext& c, const Object& o)
{
    writeSolid<Ellipsoid>(c, o, kQ3GeometryTypeEllipsoid, "Ellipsoid", &TQ3EllipsoidData::ellipsoidAttributeSet,
                          static_cast<float TQ3EllipsoidData::*>(nullptr));
}
Ref<SharedObject> readTorus(ReadContext& c, const Parts& p)
{
    return readSolid<Torus>(c, p, TQ3TorusData{}, &TQ3TorusData::torusAttributeSet, &TQ3TorusData::ratio);
}
void writeTorus(WriteContext& c, const Object& o)
{
    writeSolid<Torus>(c, o, kQ3GeometryTypeTorus, "Torus", &TQ3TorusData::torusAttributeSet, &TQ3TorusData::ratio);
}

Ref<SharedObject> readDisk(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    TQ3DiskData data{};
    // No data: MF3D's default (major radius 1 0 0, minor 0 1 0, origin 0 0 0).
    data.majorRadius = {1, 0, 0};
    data.minorRadius = {0, 1, 0};
    data.origin = {0, 0, 0};
    if (!in.atEnd()) {
        data.majorRadius = in.vector3D();
        data.minorRadius = in.vector3D();
        data.origin = in.point3D();
    }
    Ranges r;
    readRanges(in, r, true);
    data.uMin = r.uMin;
    data.uMax = r.uMax;
    data.vMin = r.vMin;
    data.vMax = r.vMax;
    Ref<AttributeSet> own = context.attributeSet(parts);
    data.diskAttributeSet = own.get();
    return make<Disk>(data);
}

void writeDisk(WriteContext& context, const Object& object)
{
    const TQ3DiskData& data = dataOf<Disk>(object);
    const AttributeSet* own = setOf(data.diskAttributeSet);
    maybeContainer(context, WriteContext::hasAttributes(own), [&] {
        Encoder& out = context.out();
        out.begin(kQ3GeometryTypeDisk, "Disk");
        out.vector3D(data.majorRadius);
        out.vector3D(data.minorRadius);
        out.point3D(data.origin);
        writeRanges(out, Ranges{data.uMin, data.uMax, data.vMin, data.vMax}, true);
        out.end();
        context.attributeSet(own);
    });
}

Ref<SharedObject> readEllipse(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    TQ3EllipseData data{};
    // No data: MF3D's default (major radius 1 0 0, minor 0 1 0, origin 0 0 0).
    data.majorRadius = {1, 0, 0};
    data.minorRadius = {0, 1, 0};
    data.origin = {0, 0, 0};
    if (!in.atEnd()) {
        data.majorRadius = in.vector3D();
        data.minorRadius = in.vector3D();
        data.origin = in.point3D();
    }
    Ranges r;
    readRanges(in, r, false);
    data.uMin = r.uMin;
    data.uMax = r.uMax;
    Ref<AttributeSet> own = context.attributeSet(parts);
    data.ellipseAttributeSet = own.get();
    return make<Ellipse>(data);
}

void writeEllipse(WriteContext& context, const Object& object)
{
    const TQ3EllipseData& data = dataOf<Ellipse>(object);
    const AttributeSet* own = setOf(data.ellipseAttributeSet);
    maybeContainer(context, WriteContext::hasAttributes(own), [&] {
        Encoder& out = context.out();
        out.begin(kQ3GeometryTypeEllipse, "Ellipse");
        out.vector3D(data.majorRadius);
        out.vector3D(data.minorRadius);
        out.point3D(data.origin);
        writeRanges(out, Ranges{data.uMin, data.uMax, 0, 1}, false);
        out.end();
        context.attributeSet(own);
    });
}

} // namespace

void addGeometryClasses(std::vector<ClassIO>& table)
{
    table.insert(table.end(), {
                                  {kQ3GeometryTypePoint, "Point", readPoint, writePoint},
                                  {kQ3GeometryTypeLine, "Line", readLine, writeLine},
                                  {kQ3GeometryTypePolyLine, "PolyLine", readPolyLine, writePolyLine},
                                  {kQ3GeometryTypeTriangle, "Triangle", readTriangle, writeTriangle},
                                  {kQ3GeometryTypePolygon, "Polygon", readPolygon, writePolygon},
                                  {kQ3GeometryTypeTriMesh, "TriMesh", readTriMesh, writeTriMesh},
                                  {kQ3GeometryTypeNURBCurve, "NURBCurve", readNURBCurve, writeNURBCurve},
                                  {kQ3GeometryTypeBox, "Box", readBox, writeBox},
                                  {kQ3GeometryTypeCone, "Cone", readCone, writeCone},
                                  {kQ3GeometryTypeCylinder, "Cylinder", readCylinder, writeCylinder},
                                  {kQ3GeometryTypeDisk, "Disk", readDisk, writeDisk},
                                  {kQ3GeometryTypeEllipse, "Ellipse", readEllipse, writeEllipse},
                                  {kQ3GeometryTypeEllipsoid, "Ellipsoid", readEllipsoid, writeEllipsoid},
                                  {kQ3GeometryTypeTorus, "Torus", readTorus, writeTorus},
                                  {kTypeGeometrySets, "GeometryAttributeSetList", refusePart, writeNothing},
                                  {kTopCap.type, kTopCap.name, refusePart, writeNothing},
                                  {kBottomCap.type, kBottomCap.name, refusePart, writeNothing},
                                  {kFaceCap.type, kFaceCap.name, refusePart, writeNothing},
                                  {kInteriorCap.type, kInteriorCap.name, refusePart, writeNothing},
                              });
    addComplexGeometryClasses(table);
}

} // namespace q3::io
