// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/Entry.h"
#include "core/ErrorManager.h"
#include "core/Limits.h"
#include "geometry/DataGeometry.h"
#include "geometry/MeshGeometry.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;
using S = MeshGeometry::Serial;

namespace {

MeshGeometry& meshOf(TQ3GeometryObject mesh)
{
    return lookup<MeshGeometry>(mesh, "mesh");
}

template <class Handle>
Handle handleOf(S serial, MeshPart kind)
{
    return static_cast<Handle>(MeshGeometry::handleOf(serial, kind));
}

// One Get call on a part: mesh, part handle, output pointer, then the value.
template <class Out, class Read>
TQ3Status readPart(const char* function, TQ3GeometryObject mesh, const void* part, MeshPart kind,
                   const char* name, Out* out, const char* outName, Read read)
{
    return guardStatus(function, [&] {
        const MeshGeometry& m = meshOf(mesh);
        const S serial = m.part(part, kind, name);
        requireNonNull(out, outName);
        *out = read(m, serial);
    });
}

template <class Read>
TQ3Status readCount(const char* function, TQ3GeometryObject mesh, unsigned long* out, const char* outName,
                    Read read)
{
    return guardStatus(function, [&] { api::readInto<MeshGeometry>(mesh, "mesh", out, outName, read); });
}

template <class Write>
TQ3Status setPartSet(const char* function, TQ3GeometryObject mesh, const void* part, MeshPart kind,
                     const char* name, TQ3AttributeSet attributeSet, Write write)
{
    return guardStatus(function, [&] {
        MeshGeometry& m = meshOf(mesh);
        const S serial = m.part(part, kind, name);
        write(m, serial, attributeSetFromHandle(attributeSet, "attributeSet"));
    });
}

TQ3Boolean boolean(bool value)
{
    return value ? kQ3True : kQ3False;
}

// ---- Iterators: one engine for the sixteen walks ---------------------------
//
// An iterator holds: var1 the handle walked over (the mesh, or a part), NULL
// once the walk has ended; var2 the part given last; var3 the position of
// the next part (for walks over a list); var4.field2 the walk's tag.

using Step = S (*)(const MeshGeometry& mesh, S owner, S after, std::size_t position);

struct Walk {
    char tag[4];
    MeshPart owner; // MeshPart::Component etc., or 0 for the mesh itself
    MeshPart result;
    Step step;
};

constexpr MeshPart kTheMesh = MeshPart(0);

const MeshGeometry& ownerOf(const Walk& walk, const void* owner, S& serial)
{
    serial = 0;
    if (walk.owner == kTheMesh)
        return meshOf(static_cast<TQ3GeometryObject>(const_cast<void*>(owner)));
    return MeshGeometry::holderOf(owner, walk.owner, walk.owner == MeshPart::Component ? "component"
                                                   : walk.owner == MeshPart::Vertex  ? "vertex"
                                                   : walk.owner == MeshPart::Face    ? "face"
                                                                                     : "contour",
                                  serial);
}

void record(TQ3MeshIterator* iterator, const void* owner, S given, MeshPart kind, std::size_t position)
{
    iterator->var1 = given == 0 ? nullptr : const_cast<void*>(owner);
    iterator->var2 = MeshGeometry::handleOf(given, kind);
    iterator->var3 = reinterpret_cast<void*>(static_cast<std::uintptr_t>(position));
}

void* startWalk(const char* function, const Walk& walk, const void* owner, TQ3MeshIterator* iterator)
{
    return guard(function, static_cast<void*>(nullptr), [&]() -> void* {
        S ownerSerial = 0;
        const MeshGeometry& mesh = ownerOf(walk, owner, ownerSerial);
        requireNonNull(iterator, "iterator");
        const S first = walk.step(mesh, ownerSerial, 0, 0);
        iterator->var4.field1 = nullptr;
        std::memcpy(iterator->var4.field2, walk.tag, 4);
        record(iterator, owner, first, walk.result, 1);
        return MeshGeometry::handleOf(first, walk.result);
    });
}

void* stepWalk(const char* function, const Walk& walk, TQ3MeshIterator* iterator)
{
    return guard(function, static_cast<void*>(nullptr), [&]() -> void* {
        requireNonNull(iterator, "iterator");
        if (std::memcmp(iterator->var4.field2, walk.tag, 4) != 0) {
            iterator->var1 = nullptr;
            fail(kQ3ErrorInvalidParameter, "the iterator was not started by the matching Q3Mesh_First call");
        }
        const void* owner = iterator->var1;
        if (owner == nullptr)
            return nullptr;
        try {
            S ownerSerial = 0;
            const MeshGeometry& mesh = ownerOf(walk, owner, ownerSerial);
            const S after = S(reinterpret_cast<std::uintptr_t>(iterator->var2) >> 3);
            const auto position = static_cast<std::size_t>(reinterpret_cast<std::uintptr_t>(iterator->var3));
            const S next = walk.step(mesh, ownerSerial, after, position);
            record(iterator, owner, next, walk.result, position + 1);
            return MeshGeometry::handleOf(next, walk.result);
        } catch (...) {
            iterator->var1 = nullptr;
            throw;
        }
    });
}

S at(const std::vector<S>& list, std::size_t position)
{
    return position < list.size() ? list[position] : 0;
}

const Walk kMeshComponent{{'M', 'c', 'm', 'p'}, kTheMesh, MeshPart::Component,
                          [](const MeshGeometry& m, S, S after, std::size_t) { return m.nextComponent(after); }};
const Walk kComponentVertex{{'C', 'v', 't', 'x'}, MeshPart::Component, MeshPart::Vertex,
                            [](const MeshGeometry& m, S c, S after, std::size_t) { return m.nextVertex(c, after); }};
const Walk kComponentEdge{{'C', 'e', 'd', 'g'}, MeshPart::Component, MeshPart::Edge,
                          [](const MeshGeometry& m, S c, S after, std::size_t) { return m.nextEdge(c, after); }};
const Walk kMeshVertex{{'M', 'v', 't', 'x'}, kTheMesh, MeshPart::Vertex,
                       [](const MeshGeometry& m, S, S after, std::size_t) { return m.nextVertex(0, after); }};
const Walk kMeshFace{{'M', 'f', 'a', 'c'}, kTheMesh, MeshPart::Face,
                     [](const MeshGeometry& m, S, S after, std::size_t) { return m.nextFace(after); }};
const Walk kMeshEdge{{'M', 'e', 'd', 'g'}, kTheMesh, MeshPart::Edge,
                     [](const MeshGeometry& m, S, S after, std::size_t) { return m.nextEdge(0, after); }};
const Walk kVertexEdge{{'V', 'e', 'd', 'g'}, MeshPart::Vertex, MeshPart::Edge,
                       [](const MeshGeometry& m, S v, S, std::size_t p) { return at(m.vertexEdges(v), p); }};
const Walk kVertexVertex{{'V', 'v', 't', 'x'}, MeshPart::Vertex, MeshPart::Vertex,
                         [](const MeshGeometry& m, S v, S, std::size_t p) { return at(m.vertexVertices(v), p); }};
const Walk kVertexFace{{'V', 'f', 'a', 'c'}, MeshPart::Vertex, MeshPart::Face,
                       [](const MeshGeometry& m, S v, S, std::size_t p) { return at(m.vertexFaces(v), p); }};
const Walk kFaceEdge{{'F', 'e', 'd', 'g'}, MeshPart::Face, MeshPart::Edge,
                     [](const MeshGeometry& m, S f, S, std::size_t p) { return at(m.faceEdges(f), p); }};
const Walk kFaceVertex{{'F', 'v', 't', 'x'}, MeshPart::Face, MeshPart::Vertex,
                       [](const MeshGeometry& m, S f, S, std::size_t p) { return at(m.faceVertices(f), p); }};
const Walk kFaceFace{{'F', 'f', 'a', 'c'}, MeshPart::Face, MeshPart::Face,
                     [](const MeshGeometry& m, S f, S, std::size_t p) { return at(m.faceFaces(f), p); }};
const Walk kFaceContour{{'F', 'c', 't', 'r'}, MeshPart::Face, MeshPart::Contour,
                        [](const MeshGeometry& m, S f, S, std::size_t p) { return at(m.faceContours(f), p); }};
const Walk kContourEdge{{'H', 'e', 'd', 'g'}, MeshPart::Contour, MeshPart::Edge,
                        [](const MeshGeometry& m, S h, S, std::size_t p) { return at(m.contourEdges(h), p); }};
const Walk kContourVertex{{'H', 'v', 't', 'x'}, MeshPart::Contour, MeshPart::Vertex,
                          [](const MeshGeometry& m, S h, S, std::size_t p) { return at(m.contourVertices(h), p); }};
const Walk kContourFace{{'H', 'f', 'a', 'c'}, MeshPart::Contour, MeshPart::Face,
                        [](const MeshGeometry& m, S h, S, std::size_t p) { return at(m.contourFaces(h), p); }};

} // namespace

extern "C" {

TQ3GeometryObject Q3Mesh_New(void)
{
    return guard(__func__, TQ3GeometryObject{nullptr},
                 []() -> TQ3GeometryObject { return makeShared<MeshGeometry>().detach(); });
}

TQ3MeshVertex Q3Mesh_VertexNew(TQ3GeometryObject mesh, const TQ3Vertex3D* vertex)
{
    return guard(__func__, TQ3MeshVertex{nullptr}, [&] {
        MeshGeometry& m = meshOf(mesh);
        requireNonNull(vertex, "vertex");
        requireFinite(vertex->point, "vertex->point");
        Ref<AttributeSet> set = attributeSetFromHandle(vertex->attributeSet, "vertex->attributeSet");
        return handleOf<TQ3MeshVertex>(m.addVertex(vertex->point, std::move(set)), MeshPart::Vertex);
    });
}

TQ3MeshFace Q3Mesh_FaceNew(TQ3GeometryObject mesh, unsigned long numVertices, const TQ3MeshVertex* vertices,
                           TQ3AttributeSet attributeSet)
{
    return guard(__func__, TQ3MeshFace{nullptr}, [&] {
        MeshGeometry& m = meshOf(mesh);
        requireNonNull(vertices, "vertices");
        if (numVertices < 3)
            fail(kQ3ErrorGeometryInsufficientNumberOfPoints, "a face needs at least 3 vertices");
        if (numVertices > limits::kMaxArrayCount)
            fail(kQ3ErrorParameterOutOfRange, "numVertices is above kQ3GeometryMaxArrayCount");
        std::vector<S> ring(numVertices);
        for (unsigned long i = 0; i < numVertices; ++i) {
            try {
                ring[i] = m.part(vertices[i], MeshPart::Vertex, "the vertex");
            } catch (const Error& error) {
                fail(error.code(), "vertices[" + std::to_string(i) + "]: " + error.what());
            }
        }
        Ref<AttributeSet> set = attributeSetFromHandle(attributeSet, "attributeSet");
        return handleOf<TQ3MeshFace>(m.addFace(ring, std::move(set)), MeshPart::Face);
    });
}

TQ3Status Q3Mesh_VertexDelete(TQ3GeometryObject mesh, TQ3MeshVertex vertex)
{
    return guardStatus(__func__, [&] {
        MeshGeometry& m = meshOf(mesh);
        m.deleteVertex(m.part(vertex, MeshPart::Vertex, "vertex"));
    });
}

TQ3Status Q3Mesh_FaceDelete(TQ3GeometryObject mesh, TQ3MeshFace face)
{
    return guardStatus(__func__, [&] {
        MeshGeometry& m = meshOf(mesh);
        m.deleteFace(m.part(face, MeshPart::Face, "face"));
    });
}

TQ3Status Q3Mesh_DelayUpdates(TQ3GeometryObject mesh)
{
    return guardStatus(__func__, [&] { meshOf(mesh).setDelayed(true); });
}

TQ3Status Q3Mesh_ResumeUpdates(TQ3GeometryObject mesh)
{
    return guardStatus(__func__, [&] { meshOf(mesh).setDelayed(false); });
}

TQ3MeshContour Q3Mesh_FaceToContour(TQ3GeometryObject mesh, TQ3MeshFace containerFace, TQ3MeshFace face)
{
    return guard(__func__, TQ3MeshContour{nullptr}, [&] {
        MeshGeometry& m = meshOf(mesh);
        const S container = m.part(containerFace, MeshPart::Face, "containerFace");
        const S moved = m.part(face, MeshPart::Face, "face");
        return handleOf<TQ3MeshContour>(m.faceToContour(container, moved), MeshPart::Contour);
    });
}

TQ3MeshFace Q3Mesh_ContourToFace(TQ3GeometryObject mesh, TQ3MeshContour contour)
{
    return guard(__func__, TQ3MeshFace{nullptr}, [&] {
        MeshGeometry& m = meshOf(mesh);
        return handleOf<TQ3MeshFace>(m.contourToFace(m.part(contour, MeshPart::Contour, "contour")),
                                     MeshPart::Face);
    });
}

TQ3Status Q3Mesh_GetNumComponents(TQ3GeometryObject mesh, unsigned long* numComponents)
{
    return readCount(__func__, mesh, numComponents, "numComponents",
                     [](const MeshGeometry& m) { return static_cast<unsigned long>(m.componentCount()); });
}

TQ3Status Q3Mesh_GetNumEdges(TQ3GeometryObject mesh, unsigned long* numEdges)
{
    return readCount(__func__, mesh, numEdges, "numEdges",
                     [](const MeshGeometry& m) { return static_cast<unsigned long>(m.edgeCount()); });
}

TQ3Status Q3Mesh_GetNumVertices(TQ3GeometryObject mesh, unsigned long* numVertices)
{
    return readCount(__func__, mesh, numVertices, "numVertices",
                     [](const MeshGeometry& m) { return static_cast<unsigned long>(m.vertexCount()); });
}

TQ3Status Q3Mesh_GetNumFaces(TQ3GeometryObject mesh, unsigned long* numFaces)
{
    return readCount(__func__, mesh, numFaces, "numFaces",
                     [](const MeshGeometry& m) { return static_cast<unsigned long>(m.faceCount()); });
}

TQ3Status Q3Mesh_GetNumCorners(TQ3GeometryObject mesh, unsigned long* numCorners)
{
    return readCount(__func__, mesh, numCorners, "numCorners",
                     [](const MeshGeometry& m) { return static_cast<unsigned long>(m.cornerCount()); });
}

TQ3Status Q3Mesh_GetOrientable(TQ3GeometryObject mesh, TQ3Boolean* orientable)
{
    return guardStatus(__func__, [&] {
        api::readInto<MeshGeometry>(mesh, "mesh", orientable, "orientable",
                                    [](const MeshGeometry& m) { return boolean(m.orientable()); });
    });
}

TQ3Status Q3Mesh_GetComponentNumVertices(TQ3GeometryObject mesh, TQ3MeshComponent component,
                                         unsigned long* numVertices)
{
    return readPart(__func__, mesh, component, MeshPart::Component, "component", numVertices, "numVertices",
                    [](const MeshGeometry& m, S c) { return static_cast<unsigned long>(m.componentVertexCount(c)); });
}

TQ3Status Q3Mesh_GetComponentNumEdges(TQ3GeometryObject mesh, TQ3MeshComponent component, unsigned long* numEdges)
{
    return readPart(__func__, mesh, component, MeshPart::Component, "component", numEdges, "numEdges",
                    [](const MeshGeometry& m, S c) { return static_cast<unsigned long>(m.componentEdgeCount(c)); });
}

TQ3Status Q3Mesh_GetComponentBoundingBox(TQ3GeometryObject mesh, TQ3MeshComponent component,
                                         TQ3BoundingBox* boundingBox)
{
    return readPart(__func__, mesh, component, MeshPart::Component, "component", boundingBox, "boundingBox",
                    [](const MeshGeometry& m, S c) { return m.componentBounds(c); });
}

TQ3Status Q3Mesh_GetComponentOrientable(TQ3GeometryObject mesh, TQ3MeshComponent component, TQ3Boolean* orientable)
{
    return readPart(__func__, mesh, component, MeshPart::Component, "component", orientable, "orientable",
                    [](const MeshGeometry& m, S c) { return boolean(m.componentOrientable(c)); });
}

TQ3Status Q3Mesh_GetVertexCoordinates(TQ3GeometryObject mesh, TQ3MeshVertex vertex, TQ3Point3D* coordinates)
{
    return readPart(__func__, mesh, vertex, MeshPart::Vertex, "vertex", coordinates, "coordinates",
                    [](const MeshGeometry& m, S v) { return m.vertexPoint(v); });
}

TQ3Status Q3Mesh_GetVertexIndex(TQ3GeometryObject mesh, TQ3MeshVertex vertex, unsigned long* index)
{
    return readPart(__func__, mesh, vertex, MeshPart::Vertex, "vertex", index, "index",
                    [](const MeshGeometry& m, S v) { return static_cast<unsigned long>(m.vertexIndex(v)); });
}

TQ3Status Q3Mesh_GetVertexOnBoundary(TQ3GeometryObject mesh, TQ3MeshVertex vertex, TQ3Boolean* onBoundary)
{
    return readPart(__func__, mesh, vertex, MeshPart::Vertex, "vertex", onBoundary, "onBoundary",
                    [](const MeshGeometry& m, S v) { return boolean(m.vertexOnBoundary(v)); });
}

TQ3Status Q3Mesh_GetVertexComponent(TQ3GeometryObject mesh, TQ3MeshVertex vertex, TQ3MeshComponent* component)
{
    return readPart(__func__, mesh, vertex, MeshPart::Vertex, "vertex", component, "component",
                    [](const MeshGeometry& m, S v) {
                        const S c = m.vertexComponent(v);
                        if (c == 0)
                            errors::postNotice(kQ3NoticeMeshVertexHasNoComponent, "the vertex is in no face");
                        return handleOf<TQ3MeshComponent>(c, MeshPart::Component);
                    });
}

TQ3Status Q3Mesh_GetVertexAttributeSet(TQ3GeometryObject mesh, TQ3MeshVertex vertex, TQ3AttributeSet* attributeSet)
{
    return readPart(__func__, mesh, vertex, MeshPart::Vertex, "vertex", attributeSet, "attributeSet",
                    [](const MeshGeometry& m, S v) { return attributeSetToHandle(m.vertexSet(v)); });
}

TQ3Status Q3Mesh_SetVertexCoordinates(TQ3GeometryObject mesh, TQ3MeshVertex vertex, const TQ3Point3D* coordinates)
{
    return guardStatus(__func__, [&] {
        MeshGeometry& m = meshOf(mesh);
        const S v = m.part(vertex, MeshPart::Vertex, "vertex");
        requireNonNull(coordinates, "coordinates");
        requireFinite(*coordinates, "coordinates");
        m.setVertexPoint(v, *coordinates);
    });
}

TQ3Status Q3Mesh_SetVertexAttributeSet(TQ3GeometryObject mesh, TQ3MeshVertex vertex, TQ3AttributeSet attributeSet)
{
    return setPartSet(__func__, mesh, vertex, MeshPart::Vertex, "vertex", attributeSet,
                      [](MeshGeometry& m, S v, Ref<AttributeSet> set) { m.setVertexSet(v, std::move(set)); });
}

TQ3Status Q3Mesh_GetFaceNumVertices(TQ3GeometryObject mesh, TQ3MeshFace face, unsigned long* numVertices)
{
    return readPart(__func__, mesh, face, MeshPart::Face, "face", numVertices, "numVertices",
                    [](const MeshGeometry& m, S f) { return static_cast<unsigned long>(m.faceVertices(f).size()); });
}

TQ3Status Q3Mesh_GetFacePlaneEquation(TQ3GeometryObject mesh, TQ3MeshFace face, TQ3PlaneEquation* planeEquation)
{
    return readPart(__func__, mesh, face, MeshPart::Face, "face", planeEquation, "planeEquation",
                    [](const MeshGeometry& m, S f) { return m.facePlane(f); });
}

TQ3Status Q3Mesh_GetFaceNumContours(TQ3GeometryObject mesh, TQ3MeshFace face, unsigned long* numContours)
{
    return readPart(__func__, mesh, face, MeshPart::Face, "face", numContours, "numContours",
                    [](const MeshGeometry& m, S f) { return static_cast<unsigned long>(m.faceContourCount(f)); });
}

TQ3Status Q3Mesh_GetFaceIndex(TQ3GeometryObject mesh, TQ3MeshFace face, unsigned long* index)
{
    return readPart(__func__, mesh, face, MeshPart::Face, "face", index, "index",
                    [](const MeshGeometry& m, S f) { return static_cast<unsigned long>(m.faceIndex(f)); });
}

TQ3Status Q3Mesh_GetFaceComponent(TQ3GeometryObject mesh, TQ3MeshFace face, TQ3MeshComponent* component)
{
    return readPart(__func__, mesh, face, MeshPart::Face, "face", component, "component", [](const MeshGeometry& m, S f) {
        return handleOf<TQ3MeshComponent>(m.faceComponent(f), MeshPart::Component);
    });
}

TQ3Status Q3Mesh_GetFaceAttributeSet(TQ3GeometryObject mesh, TQ3MeshFace face, TQ3AttributeSet* attributeSet)
{
    return readPart(__func__, mesh, face, MeshPart::Face, "face", attributeSet, "attributeSet",
                    [](const MeshGeometry& m, S f) { return attributeSetToHandle(m.faceSet(f)); });
}

TQ3Status Q3Mesh_SetFaceAttributeSet(TQ3GeometryObject mesh, TQ3MeshFace face, TQ3AttributeSet attributeSet)
{
    return setPartSet(__func__, mesh, face, MeshPart::Face, "face", attributeSet,
                      [](MeshGeometry& m, S f, Ref<AttributeSet> set) { m.setFaceSet(f, std::move(set)); });
}

TQ3Status Q3Mesh_GetEdgeVertices(TQ3GeometryObject mesh, TQ3MeshEdge edge, TQ3MeshVertex* vertex1,
                                 TQ3MeshVertex* vertex2)
{
    return guardStatus(__func__, [&] {
        const MeshGeometry& m = meshOf(mesh);
        const S e = m.part(edge, MeshPart::Edge, "edge");
        requireNonNull(vertex1, "vertex1");
        requireNonNull(vertex2, "vertex2");
        const auto ends = m.edgeVertices(e);
        *vertex1 = handleOf<TQ3MeshVertex>(ends.first, MeshPart::Vertex);
        *vertex2 = handleOf<TQ3MeshVertex>(ends.second, MeshPart::Vertex);
    });
}

TQ3Status Q3Mesh_GetEdgeFaces(TQ3GeometryObject mesh, TQ3MeshEdge edge, TQ3MeshFace* face1, TQ3MeshFace* face2)
{
    return guardStatus(__func__, [&] {
        const MeshGeometry& m = meshOf(mesh);
        const S e = m.part(edge, MeshPart::Edge, "edge");
        requireNonNull(face1, "face1");
        requireNonNull(face2, "face2");
        const auto faces = m.edgeFaces(e);
        *face1 = handleOf<TQ3MeshFace>(faces.first, MeshPart::Face);
        *face2 = handleOf<TQ3MeshFace>(faces.second, MeshPart::Face);
    });
}

TQ3Status Q3Mesh_GetEdgeOnBoundary(TQ3GeometryObject mesh, TQ3MeshEdge edge, TQ3Boolean* onBoundary)
{
    return readPart(__func__, mesh, edge, MeshPart::Edge, "edge", onBoundary, "onBoundary",
                    [](const MeshGeometry& m, S e) { return boolean(m.edgeOnBoundary(e)); });
}

TQ3Status Q3Mesh_GetEdgeComponent(TQ3GeometryObject mesh, TQ3MeshEdge edge, TQ3MeshComponent* component)
{
    return readPart(__func__, mesh, edge, MeshPart::Edge, "edge", component, "component", [](const MeshGeometry& m, S e) {
        return handleOf<TQ3MeshComponent>(m.edgeComponent(e), MeshPart::Component);
    });
}

TQ3Status Q3Mesh_GetEdgeAttributeSet(TQ3GeometryObject mesh, TQ3MeshEdge edge, TQ3AttributeSet* attributeSet)
{
    return readPart(__func__, mesh, edge, MeshPart::Edge, "edge", attributeSet, "attributeSet",
                    [](const MeshGeometry& m, S e) { return attributeSetToHandle(m.edgeSet(e)); });
}

TQ3Status Q3Mesh_SetEdgeAttributeSet(TQ3GeometryObject mesh, TQ3MeshEdge edge, TQ3AttributeSet attributeSet)
{
    return setPartSet(__func__, mesh, edge, MeshPart::Edge, "edge", attributeSet,
                      [](MeshGeometry& m, S e, Ref<AttributeSet> set) { m.setEdgeSet(e, std::move(set)); });
}

TQ3Status Q3Mesh_GetContourFace(TQ3GeometryObject mesh, TQ3MeshContour contour, TQ3MeshFace* face)
{
    return readPart(__func__, mesh, contour, MeshPart::Contour, "contour", face, "face", [](const MeshGeometry& m, S h) {
        return handleOf<TQ3MeshFace>(m.contourFace(h), MeshPart::Face);
    });
}

TQ3Status Q3Mesh_GetContourNumVertices(TQ3GeometryObject mesh, TQ3MeshContour contour, unsigned long* numVertices)
{
    return readPart(__func__, mesh, contour, MeshPart::Contour, "contour", numVertices, "numVertices",
                    [](const MeshGeometry& m, S h) { return static_cast<unsigned long>(m.contourVertexCount(h)); });
}

TQ3Status Q3Mesh_GetCornerAttributeSet(TQ3GeometryObject mesh, TQ3MeshVertex vertex, TQ3MeshFace face,
                                       TQ3AttributeSet* attributeSet)
{
    return guardStatus(__func__, [&] {
        const MeshGeometry& m = meshOf(mesh);
        const S v = m.part(vertex, MeshPart::Vertex, "vertex");
        const S f = m.part(face, MeshPart::Face, "face");
        requireNonNull(attributeSet, "attributeSet");
        *attributeSet = attributeSetToHandle(m.cornerSet(v, f));
    });
}

TQ3Status Q3Mesh_SetCornerAttributeSet(TQ3GeometryObject mesh, TQ3MeshVertex vertex, TQ3MeshFace face,
                                       TQ3AttributeSet attributeSet)
{
    return guardStatus(__func__, [&] {
        MeshGeometry& m = meshOf(mesh);
        const S v = m.part(vertex, MeshPart::Vertex, "vertex");
        const S f = m.part(face, MeshPart::Face, "face");
        m.cornerSet(v, f); // the corner must exist before the set is looked at
        m.setCornerSet(v, f, attributeSetFromHandle(attributeSet, "attributeSet"));
    });
}

#define Q3_MESH_WALK(Type, Name, OwnerType, walk)                                                          \
    Type Q3Mesh_First##Name(OwnerType owner, TQ3MeshIterator* iterator)                                    \
    {                                                                                                      \
        return static_cast<Type>(startWalk(__func__, walk, owner, iterator));                              \
    }                                                                                                      \
    Type Q3Mesh_Next##Name(TQ3MeshIterator* iterator) { return static_cast<Type>(stepWalk(__func__, walk, iterator)); }

Q3_MESH_WALK(TQ3MeshComponent, MeshComponent, TQ3GeometryObject, kMeshComponent)
Q3_MESH_WALK(TQ3MeshVertex, ComponentVertex, TQ3MeshComponent, kComponentVertex)
Q3_MESH_WALK(TQ3MeshEdge, ComponentEdge, TQ3MeshComponent, kComponentEdge)
Q3_MESH_WALK(TQ3MeshVertex, MeshVertex, TQ3GeometryObject, kMeshVertex)
Q3_MESH_WALK(TQ3MeshFace, MeshFace, TQ3GeometryObject, kMeshFace)
Q3_MESH_WALK(TQ3MeshEdge, MeshEdge, TQ3GeometryObject, kMeshEdge)
Q3_MESH_WALK(TQ3MeshEdge, VertexEdge, TQ3MeshVertex, kVertexEdge)
Q3_MESH_WALK(TQ3MeshVertex, VertexVertex, TQ3MeshVertex, kVertexVertex)
Q3_MESH_WALK(TQ3MeshFace, VertexFace, TQ3MeshVertex, kVertexFace)
Q3_MESH_WALK(TQ3MeshEdge, FaceEdge, TQ3MeshFace, kFaceEdge)
Q3_MESH_WALK(TQ3MeshVertex, FaceVertex, TQ3MeshFace, kFaceVertex)
Q3_MESH_WALK(TQ3MeshFace, FaceFace, TQ3MeshFace, kFaceFace)
Q3_MESH_WALK(TQ3MeshContour, FaceContour, TQ3MeshFace, kFaceContour)
Q3_MESH_WALK(TQ3MeshEdge, ContourEdge, TQ3MeshContour, kContourEdge)
Q3_MESH_WALK(TQ3MeshVertex, ContourVertex, TQ3MeshContour, kContourVertex)
Q3_MESH_WALK(TQ3MeshFace, ContourFace, TQ3MeshContour, kContourFace)

#undef Q3_MESH_WALK

} // extern "C"
