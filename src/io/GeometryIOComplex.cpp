// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// 3DMF layouts of the geometries with nested parts (3D Metafile Reference,
// "Geometry objects"):
//
//   NURBPatch   uOrder vOrder numRows numColumns, the numRows * numColumns
//               control points (RationalPoint4D, pre-multiplied (wx wy wz w)
//               as Apple and Quesa store them, which is also Q3's form, so
//               they are read and written as they are), uKnots then vKnots.
//               The reference pairs uKnots with the third count; Apple's
//               header and the files Apple's code wrote pair it with the
//               columns (see QD3DGeometry.h), so the fields are read in the
//               struct's order and uKnots has uOrder + numColumns entries.
//               Each trim loop is a container subobject: TrimLoop ( )
//               followed by its NURBCurve2D curves ("Trim Loops", "2D NURB
//               Curves": order nPoints, RationalPoint3D points, knots).
//               Curves stay NURBs: nothing is turned into polylines.
//
// Every object read goes through its class's validation, so a file can
// never make a geometry the API would refuse.

#include "io/GeometryIOSupport.h"

#include "core/Limits.h"
#include "geometry/GeneralPolygon.h"
#include "geometry/Marker.h"
#include "geometry/MeshGeometry.h"
#include "geometry/NURBPatch.h"
#include "geometry/Polyhedron.h"
#include "geometry/TriGrid.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace q3::io {
namespace {

constexpr TQ3ObjectType kTypeTrimLoop = Q3_OBJECT_TYPE('t', 'r', 'm', 'l');
constexpr TQ3ObjectType kTypeNURBCurve2D = Q3_OBJECT_TYPE('n', 'b', '2', 'c');

Ref<SharedObject> refusePart(ReadContext&, const Parts& parts)
{
    fail(kQ3ErrorInvalidMetafileObject,
         (parts.root.name.empty() ? typeName(parts.root.type) : parts.root.name) + " outside its geometry");
}

void writeNothing(WriteContext&, const Object&) {}

// ---- NURB patches -------------------------------------------------------------

// One trim curve's arrays, kept alive while the patch is built.
struct TrimCurveStore {
    std::vector<TQ3RationalPoint3D> points;
    std::vector<float> knots;
};

TQ3NURBPatchTrimCurveData readTrimCurve(ReadContext& context, const Node& node, TrimCurveStore& store)
{
    if (node.type != kTypeNURBCurve2D)
        fail(kQ3ErrorInvalidMetafileSubObject,
             "a TrimLoop holds a " + (node.name.empty() ? typeName(node.type) : node.name) + ", not a NURBCurve2D");
    DataReader in = context.reader(node);
    const std::uint32_t order = in.u32();
    const std::uint32_t numPoints = in.count(12, 3, "trim curve control points");
    store.points.resize(numPoints);
    for (auto& point : store.points) {
        point.x = in.f32();
        point.y = in.f32();
        point.w = in.f32();
    }
    const std::uint64_t numKnots = std::uint64_t{order} + numPoints;
    in.requireRoom(numKnots, 4, 1, "trim curve knots");
    store.knots.resize(static_cast<std::size_t>(numKnots));
    for (float& knot : store.knots)
        knot = in.f32();
    if (!in.atEnd())
        fail(kQ3ErrorInvalidMetafileObject, "a NURBCurve2D has more data than its counts announce");
    return TQ3NURBPatchTrimCurveData{order, numPoints, store.points.data(), store.knots.data()};
}

void writeTrimCurve(Encoder& out, const TQ3NURBPatchTrimCurveData& curve)
{
    out.begin(kTypeNURBCurve2D, "NURBCurve2D");
    out.u32(static_cast<std::uint32_t>(curve.order));
    out.u32(static_cast<std::uint32_t>(curve.numPoints));
    for (unsigned long i = 0; i < curve.numPoints; ++i) {
        out.f32(curve.controlPoints[i].x);
        out.f32(curve.controlPoints[i].y);
        out.f32(curve.controlPoints[i].w);
    }
    for (unsigned long i = 0; i < curve.order + curve.numPoints; ++i)
        out.f32(curve.knots[i]);
    out.end();
}

Ref<SharedObject> readNURBPatch(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    const std::uint32_t uOrder = in.u32();
    const std::uint32_t vOrder = in.u32();
    const std::uint32_t numRows = in.u32();
    const std::uint32_t numColumns = in.u32();
    const std::uint64_t numPoints = std::uint64_t{numRows} * numColumns;
    in.requireRoom(numPoints, 16, 4, "patch control points");
    std::vector<TQ3RationalPoint4D> points(static_cast<std::size_t>(numPoints));
    for (auto& point : points)
        point = in.point4D();
    const std::uint64_t numUKnots = std::uint64_t{uOrder} + numColumns;
    const std::uint64_t numVKnots = std::uint64_t{vOrder} + numRows;
    in.requireRoom(numUKnots + numVKnots, 4, 1, "patch knots");
    std::vector<float> uKnots(static_cast<std::size_t>(numUKnots));
    for (float& knot : uKnots)
        knot = in.f32();
    std::vector<float> vKnots(static_cast<std::size_t>(numVKnots));
    for (float& knot : vKnots)
        knot = in.f32();
    if (!in.atEnd())
        fail(kQ3ErrorInvalidMetafileObject, "a NURBPatch has more data than its counts announce");

    // Trim loops: containers whose root is a TrimLoop, in file order. The
    // number of loops and curves is bounded by the objects the file holds.
    std::vector<std::vector<TrimCurveStore>> stores;
    std::vector<std::vector<TQ3NURBPatchTrimCurveData>> curves;
    for (const Node* node : parts.subobjects) {
        if (node->type == kTypeTrimLoop)
            fail(kQ3ErrorInvalidMetafileSubObject, "a TrimLoop without its NURBCurve2D curves");
        if (node->type != kTypeContainer || node->children.empty() || node->children.front().type != kTypeTrimLoop)
            continue;
        const std::size_t n = node->children.size() - 1;
        stores.emplace_back(n);
        curves.emplace_back(n);
        for (std::size_t i = 0; i < n; ++i)
            curves.back()[i] = readTrimCurve(context, node->children[i + 1], stores.back()[i]);
    }
    std::vector<TQ3NURBPatchTrimLoopData> loops(curves.size());
    for (std::size_t i = 0; i < loops.size(); ++i)
        loops[i] = TQ3NURBPatchTrimLoopData{curves[i].size(), curves[i].data()};

    Ref<AttributeSet> own = context.attributeSet(parts);
    TQ3NURBPatchData data{};
    data.uOrder = uOrder;
    data.vOrder = vOrder;
    data.numRows = numRows;
    data.numColumns = numColumns;
    data.controlPoints = points.data();
    data.uKnots = uKnots.data();
    data.vKnots = vKnots.data();
    data.numTrimLoops = loops.size();
    data.trimLoops = loops.empty() ? nullptr : loops.data();
    data.patchAttributeSet = own.get();
    return make<NURBPatch>(data);
}

void writeNURBPatch(WriteContext& context, const Object& object)
{
    const TQ3NURBPatchData& data = dataOf<NURBPatch>(object);
    const AttributeSet* own = setOf(data.patchAttributeSet);
    maybeContainer(context, WriteContext::hasAttributes(own) || data.numTrimLoops > 0, [&] {
        Encoder& out = context.out();
        out.begin(kQ3GeometryTypeNURBPatch, "NURBPatch");
        out.u32(static_cast<std::uint32_t>(data.uOrder));
        out.u32(static_cast<std::uint32_t>(data.vOrder));
        out.u32(static_cast<std::uint32_t>(data.numRows));
        out.u32(static_cast<std::uint32_t>(data.numColumns));
        for (unsigned long i = 0; i < data.numRows * data.numColumns; ++i)
            out.point4D(data.controlPoints[i]);
        for (unsigned long i = 0; i < data.uOrder + data.numColumns; ++i)
            out.f32(data.uKnots[i]);
        for (unsigned long i = 0; i < data.vOrder + data.numRows; ++i)
            out.f32(data.vKnots[i]);
        out.end();
        for (unsigned long l = 0; l < data.numTrimLoops; ++l) {
            const TQ3NURBPatchTrimLoopData& loop = data.trimLoops[l];
            out.begin(kTypeContainer, "Container");
            out.begin(kTypeTrimLoop, "TrimLoop");
            out.end();
            for (unsigned long c = 0; c < loop.numTrimCurves; ++c)
                writeTrimCurve(out, loop.trimCurves[c]);
            out.end();
        }
        context.attributeSet(own);
    });
}


// ---- meshes -------------------------------------------------------------------
//
// Mesh ("Meshes", "Mesh Corners"): numVertices, the points, numFaces,
// numContours, then numFaces + numContours index lists, each a signed count
// and that many vertex indices: a positive count starts a face, a negative
// one adds a contour (a hole) to the face before it. Subobjects: MeshCorners
// (the number of corners, then per corner its vertex, its number of faces
// and the faces, with one attribute set per corner as children), a
// FaceAttributeSetList, a VertexAttributeSetList and the mesh's attribute
// set. As the reference says, a face is named by its position among the
// index lists, contours included, both in MeshCorners and in the
// FaceAttributeSetList (which therefore lists numFaces + numContours
// elements; a list of numFaces elements, counting faces only as Quesa
// writes it, is read too). Vertices and faces are written in the order the
// mesh made them, so a mesh read back walks in the same order. MeshEdges are
// not read or written.

constexpr TQ3ObjectType kTypeMeshCorners = Q3_OBJECT_TYPE('c', 'r', 'n', 'r');

// The corners of MeshCorners: a vertex, the faces where it has the set.
struct Corner {
    std::uint32_t vertex;
    std::vector<std::uint32_t> faces;
    Ref<AttributeSet> set;
};

std::vector<Corner> readCorners(ReadContext& context, const Parts& parts, std::uint32_t numVertices,
                                const std::vector<std::int64_t>& faceAt)
{
    std::vector<Corner> corners;
    const Node* node = parts.find(kTypeMeshCorners);
    if (node == nullptr)
        return corners;
    if (node->type != kTypeContainer)
        fail(kQ3ErrorInvalidMetafileSubObject, "MeshCorners without their attribute sets");
    DataReader in = context.reader(node->children.front());
    const std::uint32_t count = in.count(12, 3, "mesh corners");
    if (count != node->children.size() - 1)
        fail(kQ3ErrorInvalidMetafileSubObject, "MeshCorners list " + std::to_string(count) + " corners and hold " +
                                                   std::to_string(node->children.size() - 1) + " attribute sets");
    corners.resize(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        Corner& corner = corners[i];
        corner.vertex = in.u32();
        if (corner.vertex >= numVertices)
            fail(kQ3ErrorInvalidMetafileSubObject, "a mesh corner at vertex " + std::to_string(corner.vertex) +
                                                       " of " + std::to_string(numVertices));
        corner.faces.resize(in.count(4, 1, "corner faces"));
        for (std::uint32_t& face : corner.faces) {
            const std::uint32_t position = in.u32();
            if (position >= faceAt.size() || faceAt[position] < 0)
                fail(kQ3ErrorInvalidMetafileSubObject, "a mesh corner on face " + std::to_string(position) +
                                                           ", which is no face of the mesh");
            face = static_cast<std::uint32_t>(faceAt[position]);
        }
        corner.set = context.objectAs<AttributeSet>(node->children[i + 1], "a mesh corner's attribute set");
    }
    return corners;
}

// MeshEdges ('edge', MF3D's kMF3DObjMeshEdges): the number of edges, then per
// edge its two vertex indices; one attribute set per edge as children, as
// MeshCorners have theirs. Only edges with a set are written.
constexpr TQ3ObjectType kTypeMeshEdges = Q3_OBJECT_TYPE('e', 'd', 'g', 'e');

struct EdgeSet {
    std::uint32_t from, to;
    Ref<AttributeSet> set;
};

std::vector<EdgeSet> readEdges(ReadContext& context, const Parts& parts, std::uint32_t numVertices)
{
    std::vector<EdgeSet> edges;
    const Node* node = parts.find(kTypeMeshEdges);
    if (node == nullptr)
        return edges;
    if (node->type != kTypeContainer)
        fail(kQ3ErrorInvalidMetafileSubObject, "MeshEdges without their attribute sets");
    DataReader in = context.reader(node->children.front());
    const std::uint32_t count = in.count(8, 2, "mesh edges");
    if (count != node->children.size() - 1)
        fail(kQ3ErrorInvalidMetafileSubObject, "MeshEdges list " + std::to_string(count) + " edges and hold " +
                                                   std::to_string(node->children.size() - 1) + " attribute sets");
    edges.resize(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        EdgeSet& edge = edges[i];
        edge.from = in.u32();
        edge.to = in.u32();
        if (edge.from >= numVertices || edge.to >= numVertices)
            fail(kQ3ErrorInvalidMetafileSubObject, "a mesh edge names vertex " +
                                                       std::to_string(std::max(edge.from, edge.to)) + " of " +
                                                       std::to_string(numVertices));
        edge.set = context.objectAs<AttributeSet>(node->children[i + 1], "a mesh edge's attribute set");
    }
    if (!in.atEnd())
        fail(kQ3ErrorInvalidMetafileSubObject, "MeshEdges have more data than their count announces");
    return edges;
}

Ref<SharedObject> readMesh(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    const std::uint32_t numVertices = in.count(12, 3, "mesh vertices");
    std::vector<TQ3Point3D> points(numVertices);
    for (auto& point : points)
        point = in.point3D();
    const std::uint32_t numFaces = in.u32();
    const std::uint32_t numContours = in.u32();
    // Every list is a count and at least three indices.
    in.requireRoom(std::uint64_t{numFaces} + numContours, 16, 4, "mesh faces and contours");
    std::vector<std::vector<std::vector<std::uint32_t>>> faces; // face -> contours -> indices
    std::vector<std::int64_t> faceAt; // list position -> face, or -1 for a contour
    faces.reserve(numFaces);
    for (std::uint64_t i = 0; i < std::uint64_t{numFaces} + numContours; ++i) {
        const std::int32_t count = in.i32();
        const std::uint32_t size = count < 0 ? 0u - static_cast<std::uint32_t>(count) : static_cast<std::uint32_t>(count);
        in.requireRoom(size, 4, 1, "mesh vertex indices");
        faceAt.push_back(count > 0 ? static_cast<std::int64_t>(faces.size()) : -1);
        if (count > 0)
            faces.emplace_back();
        else if (faces.empty())
            fail(kQ3ErrorInvalidMetafileObject, "a Mesh's first index list is a contour, not a face");
        faces.back().emplace_back(size);
        for (std::uint32_t& index : faces.back().back()) {
            index = in.u32();
            if (index >= numVertices)
                fail(kQ3ErrorInvalidMetafileObject, "a Mesh names vertex " + std::to_string(index) + " of " +
                                                        std::to_string(numVertices));
        }
    }
    if (faces.size() != numFaces)
        fail(kQ3ErrorInvalidMetafileObject, "a Mesh announces " + std::to_string(numFaces) + " faces and holds " +
                                                std::to_string(faces.size()));
    if (!in.atEnd())
        fail(kQ3ErrorInvalidMetafileObject, "a Mesh has more data than its counts announce");
    const auto vertexSets = readVertexSets(context, parts, numVertices);
    // Face sets by list position, or (Quesa) by face.
    std::vector<Ref<AttributeSet>> faceSets(numFaces);
    if (const Node* list = parts.find(kTypeFaceSets); list != nullptr) {
        const bool byFace = list->type == kTypeContainer && !list->children.empty() && numContours > 0 &&
                            context.reader(list->children.front()).u32() == numFaces;
        if (byFace) {
            faceSets = readSetList(context, parts, kTypeFaceSets, "FaceAttributeSetList", numFaces);
        } else {
            auto byPosition = readSetList(context, parts, kTypeFaceSets, "FaceAttributeSetList", faceAt.size());
            for (std::size_t i = 0; i < faceAt.size(); ++i) {
                if (!byPosition[i])
                    continue;
                if (faceAt[i] < 0)
                    fail(kQ3ErrorInvalidMetafileSubObject, "a FaceAttributeSetList gives a set to a contour");
                faceSets[static_cast<std::size_t>(faceAt[i])] = std::move(byPosition[i]);
            }
        }
    }
    const auto corners = readCorners(context, parts, numVertices, faceAt);
    const auto edgeSets = readEdges(context, parts, numVertices);
    Ref<AttributeSet> own = context.attributeSet(parts);

    Ref<MeshGeometry> mesh = makeShared<MeshGeometry>();
    try {
        std::vector<MeshGeometry::Serial> vertices(numVertices);
        for (std::uint32_t i = 0; i < numVertices; ++i)
            vertices[i] = mesh->addVertex(points[i], vertexSets[i]);
        // The rule Q3Mesh_FaceNew applies: at least 3 vertices (one may come
        // more than once, docs/3dmf.md, Tolerances).
        const auto serialsOf = [&](const std::vector<std::uint32_t>& indices) {
            if (indices.size() < 3)
                fail(kQ3ErrorInvalidMetafileObject, "a Mesh face or contour has fewer than 3 vertices");
            std::vector<MeshGeometry::Serial> serials(indices.size());
            for (std::size_t k = 0; k < indices.size(); ++k)
                serials[k] = vertices[indices[k]];
            return serials;
        };
        std::vector<MeshGeometry::Serial> faceSerials(faces.size());
        for (std::size_t f = 0; f < faces.size(); ++f) {
            faceSerials[f] = mesh->addFace(serialsOf(faces[f].front()), faceSets[f]);
            for (std::size_t c = 1; c < faces[f].size(); ++c)
                mesh->faceToContour(faceSerials[f], mesh->addFace(serialsOf(faces[f][c]), {}));
        }
        for (const Corner& corner : corners)
            for (std::uint32_t face : corner.faces) {
                mesh->cornerSet(vertices[corner.vertex], faceSerials[face]); // the corner must exist
                mesh->setCornerSet(vertices[corner.vertex], faceSerials[face], corner.set);
            }
        if (!edgeSets.empty()) {
            std::map<std::pair<MeshGeometry::Serial, MeshGeometry::Serial>, MeshGeometry::Serial> edgeOf;
            for (MeshGeometry::Serial e = mesh->nextEdge(0, 0); e != 0; e = mesh->nextEdge(0, e)) {
                const auto ends = mesh->edgeVertices(e);
                edgeOf[{std::min(ends.first, ends.second), std::max(ends.first, ends.second)}] = e;
            }
            for (const EdgeSet& edge : edgeSets) {
                const MeshGeometry::Serial a = vertices[edge.from], b = vertices[edge.to];
                const auto found = edgeOf.find({std::min(a, b), std::max(a, b)});
                if (found == edgeOf.end())
                    fail(kQ3ErrorInvalidMetafileSubObject, "MeshEdges name vertices " + std::to_string(edge.from) +
                                                               " and " + std::to_string(edge.to) +
                                                               ", which no face's side joins");
                mesh->setEdgeSet(found->second, edge.set);
            }
        }
    } catch (const Error& error) {
        fail(kQ3ErrorInvalidMetafileObject, std::string("the file's Mesh breaks a rule: ") + error.what());
    }
    if (own)
        mesh->setAttributeSet(std::move(own));
    return Ref<SharedObject>(std::move(mesh));
}

void writeMesh(WriteContext& context, const Object& object)
{
    const auto& mesh = static_cast<const MeshGeometry&>(object);
    std::vector<MeshGeometry::Serial> vertices;
    std::map<MeshGeometry::Serial, std::uint32_t> indexOf;
    for (MeshGeometry::Serial v = mesh.nextVertex(0, 0); v != 0; v = mesh.nextVertex(0, v)) {
        indexOf[v] = static_cast<std::uint32_t>(vertices.size());
        vertices.push_back(v);
    }
    std::vector<MeshGeometry::Serial> faces;
    std::vector<std::uint32_t> positionOf; // face -> its list position
    std::vector<const AttributeSet*> faceSets; // by list position
    std::size_t holes = 0;
    for (MeshGeometry::Serial f = mesh.nextFace(0); f != 0; f = mesh.nextFace(f)) {
        faces.push_back(f);
        positionOf.push_back(static_cast<std::uint32_t>(faceSets.size()));
        faceSets.push_back(mesh.faceSet(f));
        const std::size_t contours = mesh.faceContourCount(f);
        holes += contours - 1;
        faceSets.insert(faceSets.end(), contours - 1, nullptr);
    }
    std::vector<const AttributeSet*> vertexSets;
    for (MeshGeometry::Serial v : vertices)
        vertexSets.push_back(mesh.vertexSet(v));
    // Corners: one per vertex and set, with every face where the vertex has
    // that set.
    std::vector<std::pair<MeshGeometry::Serial, const AttributeSet*>> cornerKeys;
    std::map<std::pair<MeshGeometry::Serial, const AttributeSet*>, std::vector<std::uint32_t>> cornerFaces;
    for (std::size_t f = 0; f < faces.size(); ++f)
        for (MeshGeometry::Serial v : mesh.faceVertices(faces[f])) {
            const AttributeSet* set = mesh.cornerSet(v, faces[f]);
            if (!WriteContext::hasAttributes(set))
                continue;
            auto& list = cornerFaces[{v, set}];
            if (list.empty())
                cornerKeys.emplace_back(v, set);
            list.push_back(positionOf[f]);
        }
    std::vector<MeshGeometry::Serial> edges; // the edges with a set
    for (MeshGeometry::Serial e = mesh.nextEdge(0, 0); e != 0; e = mesh.nextEdge(0, e))
        if (WriteContext::hasAttributes(mesh.edgeSet(e)))
            edges.push_back(e);
    const AttributeSet* own = mesh.attributeSet();
    const bool container = WriteContext::hasAttributes(own) || anySet(vertexSets) || anySet(faceSets) ||
                           !cornerKeys.empty() || !edges.empty();
    maybeContainer(context, container, [&] {
        Encoder& out = context.out();
        out.begin(kQ3GeometryTypeMesh, "Mesh");
        out.u32(static_cast<std::uint32_t>(vertices.size()));
        for (MeshGeometry::Serial v : vertices)
            out.point3D(mesh.vertexPoint(v));
        out.u32(static_cast<std::uint32_t>(faces.size()));
        out.u32(static_cast<std::uint32_t>(holes));
        for (MeshGeometry::Serial f : faces) {
            bool first = true;
            for (MeshGeometry::Serial contour : mesh.faceContours(f)) {
                const auto ring = mesh.contourVertices(contour);
                const auto size = static_cast<std::int32_t>(ring.size());
                out.i32(first ? size : -size);
                for (MeshGeometry::Serial v : ring)
                    out.u32(indexOf.at(v));
                first = false;
            }
        }
        out.end();
        if (!cornerKeys.empty()) {
            out.begin(kTypeContainer, "Container");
            out.begin(kTypeMeshCorners, "MeshCorners");
            out.u32(static_cast<std::uint32_t>(cornerKeys.size()));
            for (const auto& key : cornerKeys) {
                out.u32(indexOf.at(key.first));
                const auto& list = cornerFaces.at(key);
                out.u32(static_cast<std::uint32_t>(list.size()));
                for (std::uint32_t f : list)
                    out.u32(f);
            }
            out.end();
            for (const auto& key : cornerKeys)
                context.attributeSet(key.second);
            out.end();
        }
        if (!edges.empty()) {
            out.begin(kTypeContainer, "Container");
            out.begin(kTypeMeshEdges, "MeshEdges");
            out.u32(static_cast<std::uint32_t>(edges.size()));
            for (MeshGeometry::Serial e : edges) {
                const auto ends = mesh.edgeVertices(e);
                out.u32(indexOf.at(ends.first));
                out.u32(indexOf.at(ends.second));
            }
            out.end();
            for (MeshGeometry::Serial e : edges)
                context.attributeSet(mesh.edgeSet(e));
            out.end();
        }
        writeSetList(context, kTypeFaceSets, "FaceAttributeSetList", faceSets);
        writeSetList(context, kTypeVertexSets, "VertexAttributeSetList", vertexSets);
        context.attributeSet(own);
    });
}

// ---- general polygons, triangle grids, polyhedra, markers ------------------------
//
// GeneralPolygon: numContours, then per contour numVertices and the points;
// a GeneralPolygonHint subobject (Complex, Concave or Convex; written when
// not Complex, the default), one VertexAttributeSetList over every vertex of
// every contour in order, and the attribute set.
// TriGrid: numRows, numColumns, the numRows * numColumns points; a
// FaceAttributeSetList of the 2 (numRows - 1) (numColumns - 1) facets, a
// VertexAttributeSetList and the attribute set.
// Polyhedron (QuickDraw 3D 1.5, after the 1.0 reference): numVertices, the
// points, numTriangles, numEdges, then per triangle its three vertex indices
// and its edge flags, then per edge its two vertex indices and two triangle
// indices; a FaceAttributeSetList (the triangles), a VertexAttributeSetList,
// a GeometryAttributeSetList of numEdges elements (the edges' own sets: no
// source gives them a place, and this is the list the reference keeps for
// the parts of a geometry that are neither faces nor vertices, a polyline's
// segments; a reader that does not know it skips it), the attribute set.
// Marker: location, xOffset, yOffset (Int32), then the bitmap: width,
// height, rowBytes, bitOrder (BigEndian or LittleEndian), then height *
// rowBytes bytes of image as RawData: padded with zeros to a multiple of 4 in
// binary, 0x and two hex digits a byte in text (Q3 also reads the one
// decimal number a byte it wrote before).

constexpr TQ3ObjectType kTypeShapeHint = Q3_OBJECT_TYPE('g', 'p', 'l', 'h');

const std::vector<std::pair<const char*, std::uint32_t>> kShapeHints = {
    {"Complex", kQ3GeneralPolygonShapeHintComplex},
    {"Concave", kQ3GeneralPolygonShapeHintConcave},
    {"Convex", kQ3GeneralPolygonShapeHintConvex}};
const std::vector<std::pair<const char*, std::uint32_t>> kBitOrders = {{"BigEndian", kQ3EndianBig},
                                                                       {"LittleEndian", kQ3EndianLittle}};

void attachSets(std::vector<TQ3Vertex3D>& vertices, const std::vector<Ref<AttributeSet>>& sets, std::size_t from)
{
    for (std::size_t i = 0; i < vertices.size(); ++i)
        vertices[i].attributeSet = sets[from + i].get();
}

std::vector<TQ3AttributeSet> handlesOf(const std::vector<Ref<AttributeSet>>& sets)
{
    std::vector<TQ3AttributeSet> handles(sets.size());
    for (std::size_t i = 0; i < sets.size(); ++i)
        handles[i] = sets[i].get();
    return handles;
}

Ref<SharedObject> readGeneralPolygon(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    const std::uint32_t numContours = in.count(4 + 36, 1 + 9, "contours");
    std::vector<std::vector<TQ3Vertex3D>> vertices(numContours);
    std::size_t total = 0;
    for (auto& contour : vertices) {
        contour = readPoints(in, in.count(12, 3, "contour vertices"));
        total += contour.size();
    }
    if (!in.atEnd())
        fail(kQ3ErrorInvalidMetafileObject, "a GeneralPolygon has more data than its counts announce");
    const auto sets = readVertexSets(context, parts, total);
    TQ3GeneralPolygonData data{};
    data.shapeHint = kQ3GeneralPolygonShapeHintComplex;
    if (const Node* hint = parts.find(kTypeShapeHint); hint != nullptr) {
        if (hint->type != kTypeShapeHint)
            fail(kQ3ErrorInvalidMetafileSubObject, "a GeneralPolygonHint must be written out, not referred to");
        DataReader hintIn = context.reader(*hint);
        data.shapeHint = static_cast<TQ3GeneralPolygonShapeHint>(hintIn.choice(kShapeHints));
    }
    std::vector<TQ3GeneralPolygonContourData> contours(numContours);
    std::size_t from = 0;
    for (std::uint32_t c = 0; c < numContours; ++c) {
        attachSets(vertices[c], sets, from);
        from += vertices[c].size();
        contours[c] = TQ3GeneralPolygonContourData{vertices[c].size(), vertices[c].data()};
    }
    Ref<AttributeSet> own = context.attributeSet(parts);
    data.numContours = numContours;
    data.contours = contours.data();
    data.generalPolygonAttributeSet = own.get();
    return make<GeneralPolygon>(data);
}

void writeGeneralPolygon(WriteContext& context, const Object& object)
{
    const TQ3GeneralPolygonData& data = dataOf<GeneralPolygon>(object);
    const AttributeSet* own = setOf(data.generalPolygonAttributeSet);
    std::vector<const AttributeSet*> vertexSets;
    for (unsigned long c = 0; c < data.numContours; ++c)
        for (const AttributeSet* set : vertexSetsOf(data.contours[c].vertices, data.contours[c].numVertices))
            vertexSets.push_back(set);
    const bool hint = data.shapeHint != kQ3GeneralPolygonShapeHintComplex;
    maybeContainer(context, hint || WriteContext::hasAttributes(own) || anySet(vertexSets), [&] {
        Encoder& out = context.out();
        out.begin(kQ3GeometryTypeGeneralPolygon, "GeneralPolygon");
        out.u32(static_cast<std::uint32_t>(data.numContours));
        for (unsigned long c = 0; c < data.numContours; ++c) {
            out.u32(static_cast<std::uint32_t>(data.contours[c].numVertices));
            for (unsigned long i = 0; i < data.contours[c].numVertices; ++i)
                out.point3D(data.contours[c].vertices[i].point);
        }
        out.end();
        if (hint) {
            out.begin(kTypeShapeHint, "GeneralPolygonHint");
            out.choice(kShapeHints, static_cast<std::uint32_t>(data.shapeHint));
            out.end();
        }
        writeSetList(context, kTypeVertexSets, "VertexAttributeSetList", vertexSets);
        context.attributeSet(own);
    });
}

Ref<SharedObject> readTriGrid(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    const std::uint32_t numRows = in.u32();
    const std::uint32_t numColumns = in.u32();
    const std::uint64_t n = std::uint64_t{numRows} * numColumns;
    in.requireRoom(n, 12, 3, "grid vertices");
    std::vector<TQ3Vertex3D> vertices = readPoints(in, static_cast<std::uint32_t>(n));
    if (!in.atEnd())
        fail(kQ3ErrorInvalidMetafileObject, "a TriGrid has more data than its counts announce");
    const auto sets = readVertexSets(context, parts, vertices.size());
    attachSets(vertices, sets, 0);
    const std::size_t facets = numRows < 2 || numColumns < 2 ? 0 : 2 * std::size_t{numRows - 1} * (numColumns - 1);
    const auto facetSets = readSetList(context, parts, kTypeFaceSets, "FaceAttributeSetList", facets);
    std::vector<TQ3AttributeSet> facetHandles = handlesOf(facetSets);
    bool anyFacet = false;
    for (TQ3AttributeSet handle : facetHandles)
        anyFacet = anyFacet || handle != nullptr;
    Ref<AttributeSet> own = context.attributeSet(parts);
    TQ3TriGridData data{numRows, numColumns, vertices.data(), anyFacet ? facetHandles.data() : nullptr, own.get()};
    return make<TriGrid>(data);
}

void writeTriGrid(WriteContext& context, const Object& object)
{
    const TQ3TriGridData& data = dataOf<TriGrid>(object);
    const AttributeSet* own = setOf(data.triGridAttributeSet);
    const unsigned long n = data.numRows * data.numColumns;
    std::vector<const AttributeSet*> facetSets;
    if (data.facetAttributeSet != nullptr)
        for (unsigned long i = 0; i < 2 * (data.numRows - 1) * (data.numColumns - 1); ++i)
            facetSets.push_back(setOf(data.facetAttributeSet[i]));
    maybeContainer(context, WriteContext::hasAttributes(own) || anyVertexSet(data.vertices, n) || anySet(facetSets),
                   [&] {
                       Encoder& out = context.out();
                       out.begin(kQ3GeometryTypeTriGrid, "TriGrid");
                       out.u32(static_cast<std::uint32_t>(data.numRows));
                       out.u32(static_cast<std::uint32_t>(data.numColumns));
                       for (unsigned long i = 0; i < n; ++i)
                           out.point3D(data.vertices[i].point);
                       out.end();
                       writeSetList(context, kTypeFaceSets, "FaceAttributeSetList", facetSets);
                       writeVertexSets(context, data.vertices, n);
                       context.attributeSet(own);
                   });
}

Ref<SharedObject> readPolyhedron(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    const std::uint32_t numVertices = in.count(12, 3, "polyhedron vertices");
    std::vector<TQ3Vertex3D> vertices = readPoints(in, numVertices);
    const std::uint32_t numTriangles = in.u32();
    const std::uint32_t numEdges = in.u32();
    in.requireRoom(numTriangles, 16, 4, "polyhedron triangles");
    std::vector<TQ3PolyhedronTriangleData> triangles(numTriangles);
    for (auto& triangle : triangles) {
        for (auto& index : triangle.vertexIndices)
            index = in.u32();
        triangle.edgeFlag = in.u32();
        triangle.triangleAttributeSet = nullptr;
    }
    in.requireRoom(numEdges, 16, 4, "polyhedron edges");
    std::vector<TQ3PolyhedronEdgeData> edges(numEdges);
    for (auto& edge : edges) {
        for (auto& index : edge.vertexIndices)
            index = in.u32();
        for (auto& index : edge.triangleIndices) {
            const std::uint32_t value = in.u32();
            index = value == 0xFFFFFFFFu ? static_cast<unsigned long>(kQ3ArrayIndexNULL) : value;
        }
        edge.edgeAttributeSet = nullptr;
    }
    if (!in.atEnd())
        fail(kQ3ErrorInvalidMetafileObject, "a Polyhedron has more data than its counts announce");
    const auto vertexSets = readVertexSets(context, parts, numVertices);
    attachSets(vertices, vertexSets, 0);
    const auto faceSets = readSetList(context, parts, kTypeFaceSets, "FaceAttributeSetList", numTriangles);
    for (std::uint32_t i = 0; i < numTriangles; ++i)
        triangles[i].triangleAttributeSet = faceSets[i].get();
    const auto edgeSets = readSetList(context, parts, kTypeGeometrySets, "GeometryAttributeSetList", numEdges);
    for (std::uint32_t i = 0; i < numEdges; ++i)
        edges[i].edgeAttributeSet = edgeSets[i].get();
    Ref<AttributeSet> own = context.attributeSet(parts);
    TQ3PolyhedronData data{numVertices,
                           vertices.data(),
                           numEdges,
                           edges.empty() ? nullptr : edges.data(),
                           numTriangles,
                           triangles.data(),
                           own.get()};
    return make<Polyhedron>(data);
}

void writePolyhedron(WriteContext& context, const Object& object)
{
    const TQ3PolyhedronData& data = dataOf<Polyhedron>(object);
    const AttributeSet* own = setOf(data.polyhedronAttributeSet);
    std::vector<const AttributeSet*> faceSets;
    for (unsigned long i = 0; i < data.numTriangles; ++i)
        faceSets.push_back(setOf(data.triangles[i].triangleAttributeSet));
    std::vector<const AttributeSet*> edgeSets;
    for (unsigned long i = 0; i < data.numEdges; ++i)
        edgeSets.push_back(setOf(data.edges[i].edgeAttributeSet));
    maybeContainer(context,
                   WriteContext::hasAttributes(own) || anyVertexSet(data.vertices, data.numVertices) ||
                       anySet(faceSets) || anySet(edgeSets),
                   [&] {
                       Encoder& out = context.out();
                       out.begin(kQ3GeometryTypePolyhedron, "Polyhedron");
                       out.u32(static_cast<std::uint32_t>(data.numVertices));
                       for (unsigned long i = 0; i < data.numVertices; ++i)
                           out.point3D(data.vertices[i].point);
                       out.u32(static_cast<std::uint32_t>(data.numTriangles));
                       out.u32(static_cast<std::uint32_t>(data.numEdges));
                       for (unsigned long i = 0; i < data.numTriangles; ++i) {
                           for (unsigned long index : data.triangles[i].vertexIndices)
                               out.u32(static_cast<std::uint32_t>(index));
                           out.u32(static_cast<std::uint32_t>(data.triangles[i].edgeFlag));
                       }
                       for (unsigned long i = 0; i < data.numEdges; ++i) {
                           for (unsigned long index : data.edges[i].vertexIndices)
                               out.u32(static_cast<std::uint32_t>(index));
                           for (unsigned long index : data.edges[i].triangleIndices)
                               out.u32(static_cast<std::uint32_t>(index));
                       }
                       out.end();
                       writeSetList(context, kTypeFaceSets, "FaceAttributeSetList", faceSets);
                       writeVertexSets(context, data.vertices, data.numVertices);
                       writeSetList(context, kTypeGeometrySets, "GeometryAttributeSetList", edgeSets);
                       context.attributeSet(own);
                   });
}

Ref<SharedObject> readMarker(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    TQ3MarkerData data{};
    data.location = in.point3D();
    data.xOffset = in.i32();
    data.yOffset = in.i32();
    data.bitmap.width = in.u32();
    data.bitmap.height = in.u32();
    data.bitmap.rowBytes = in.u32();
    data.bitmap.bitOrder = static_cast<TQ3Endian>(in.choice(kBitOrders));
    const std::uint64_t size = std::uint64_t{data.bitmap.height} * data.bitmap.rowBytes;
    const bool text = context.file().encoding == Encoding::kText;
    std::vector<unsigned char> image;
    if (text && size > 0 && !in.atEnd() && in.word().rfind("0x", 0) == 0) {
        // The reference's RawData: 0x tokens of hex digits (rawData allocates
        // only as the tokens supply bytes).
        in.seek(in.tell() - 1);
        if (size > limits::kMaxArrayCount)
            fail(kQ3ErrorInvalidMetafileObject, "a Marker claims " + std::to_string(size) + " bitmap bytes");
        const std::string bytes = in.rawData(static_cast<std::size_t>(size));
        image.assign(bytes.begin(), bytes.end());
    } else {
        // Binary, or text as Q3 wrote it before: one decimal number a byte.
        if (text && size > 0 && !in.atEnd())
            in.seek(in.tell() - 1);
        in.requireRoom(size, 1, 1, "bitmap bytes");
        image.resize(static_cast<std::size_t>(size));
        for (unsigned char& byte : image)
            byte = in.u8();
    }
    if (!text)
        for (std::uint64_t i = size; i % 4 != 0 && !in.atEnd(); ++i)
            in.u8();
    if (!in.atEnd())
        fail(kQ3ErrorInvalidMetafileObject, "a Marker has more data than its bitmap");
    data.bitmap.image = image.empty() ? nullptr : image.data();
    Ref<AttributeSet> own = context.attributeSet(parts);
    data.markerAttributeSet = own.get();
    return make<Marker>(data);
}

void writeMarker(WriteContext& context, const Object& object)
{
    const TQ3MarkerData& data = dataOf<Marker>(object);
    requireInt32Offsets(data.xOffset, data.yOffset, "marker");
    const AttributeSet* own = setOf(data.markerAttributeSet);
    maybeContainer(context, WriteContext::hasAttributes(own), [&] {
        Encoder& out = context.out();
        out.begin(kQ3GeometryTypeMarker, "Marker");
        out.point3D(data.location);
        out.i32(static_cast<std::int32_t>(data.xOffset));
        out.i32(static_cast<std::int32_t>(data.yOffset));
        out.u32(static_cast<std::uint32_t>(data.bitmap.width));
        out.u32(static_cast<std::uint32_t>(data.bitmap.height));
        out.u32(static_cast<std::uint32_t>(data.bitmap.rowBytes));
        out.choice(kBitOrders, static_cast<std::uint32_t>(data.bitmap.bitOrder));
        const unsigned long size = data.bitmap.height * data.bitmap.rowBytes;
        out.rawData(data.bitmap.image, size);
        out.end();
        context.attributeSet(own);
    });
}

} // namespace

void addComplexGeometryClasses(std::vector<ClassIO>& table)
{
    table.insert(table.end(), {
                                  {kQ3GeometryTypeNURBPatch, "NURBPatch", readNURBPatch, writeNURBPatch},
                                  {kTypeTrimLoop, "TrimLoop", refusePart, writeNothing},
                                  {kTypeNURBCurve2D, "NURBCurve2D", refusePart, writeNothing},
                                  {kQ3GeometryTypeMesh, "Mesh", readMesh, writeMesh},
                                  {kTypeFaceSets, "FaceAttributeSetList", refusePart, writeNothing},
                                  {kTypeMeshCorners, "MeshCorners", refusePart, writeNothing},
                                  {kTypeMeshEdges, "MeshEdges", refusePart, writeNothing},
                                  {kQ3GeometryTypeGeneralPolygon, "GeneralPolygon", readGeneralPolygon,
                                   writeGeneralPolygon},
                                  {kTypeShapeHint, "GeneralPolygonHint", refusePart, writeNothing},
                                  {kQ3GeometryTypeTriGrid, "TriGrid", readTriGrid, writeTriGrid},
                                  {kQ3GeometryTypePolyhedron, "Polyhedron", readPolyhedron, writePolyhedron},
                                  {kQ3GeometryTypeMarker, "Marker", readMarker, writeMarker},
                              });
}

} // namespace q3::io
