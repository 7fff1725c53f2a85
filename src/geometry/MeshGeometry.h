// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "geometry/Geometry.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace q3 {

extern const ClassInfo kMeshClass;

/// The kinds of mesh part a handle names (its low three bits).
enum class MeshPart : unsigned { Vertex = 1, Face = 2, Edge = 3, Contour = 4, Component = 5 };

/// QuickDraw 3D's Mesh: a polyhedral surface built call by call
/// (QD3DGeometry.h, "Mesh"). Every part has a serial number drawn from one
/// process-wide counter, never reused; the C handle of a part is its serial
/// and kind packed into a pointer-sized integer, and a process-wide table
/// maps serials to the mesh that holds them, so a handle is checked without
/// ever being dereferenced. Invariants: every contour has at least 3
/// distinct vertices, each a vertex of this mesh; a face has at least one
/// contour; m_edgeByEnds holds exactly the vertex pairs some contour runs
/// along, each edge's `uses` is how many contour sides run along it; a
/// vertex's `faces` lists exactly the faces it is a corner of; every serial
/// in the maps is in the table, naming this mesh.
class MeshGeometry final : public Geometry {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeMesh;
    using Serial = std::uint64_t;

    MeshGeometry();
    ~MeshGeometry() override;

    const ClassInfo& classInfo() const override { return kMeshClass; }
    Object* duplicate() const override;
    const AttributeSet* attributeSet() const override { return m_set.get(); }
    void setAttributeSet(Ref<AttributeSet> attributes) override;
    /// Each face triangulated by the even-odd rule in the plane of its first
    /// contour (mesh/Triangulate.h), corners carrying corner > vertex > face
    /// attributes; every edge once as the wireframe, in its colour if it has
    /// one.
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;
    /// The face `local` lies in (the nearest by plane distance plus distance
    /// outside its contours), the edge nearest to it, or the vertex nearest
    /// to it, as a mesh face, edge or vertex part.
    Ref<SharedObject> shapePartAt(TQ3PickParts part, const TQ3Point3D& local) const override;
    /// Whether the mesh has a part of that kind with that serial.
    bool hasPart(Serial serial, MeshPart kind) const { return holds(serial, kind); }

    // Handles.
    static void* handleOf(Serial serial, MeshPart kind);
    /// The mesh holding the part `handle` names, for the calls that take no
    /// mesh (kQ3ErrorNULLParameter, kQ3ErrorInvalidParameter as the header
    /// says); `serial` receives the part's serial.
    static MeshGeometry& holderOf(const void* handle, MeshPart kind, const char* name, Serial& serial);
    /// The serial of a part of this mesh, checked likewise.
    Serial part(const void* handle, MeshPart kind, const char* name) const;

    // Edits.
    Serial addVertex(const TQ3Point3D& point, Ref<AttributeSet> set);
    Serial addFace(const std::vector<Serial>& vertices, Ref<AttributeSet> set);
    void deleteVertex(Serial vertex);
    void deleteFace(Serial face);
    Serial faceToContour(Serial container, Serial face);
    Serial contourToFace(Serial contour);
    void setDelayed(bool delayed) { m_delayed = delayed; }
    bool delayed() const { return m_delayed; }

    // Queries.
    std::size_t vertexCount() const { return m_vertices.size(); }
    std::size_t faceCount() const { return m_faces.size(); }
    std::size_t edgeCount() const { return m_edges.size(); }
    std::size_t componentCount() const;
    std::size_t cornerCount() const;
    bool orientable() const;

    std::size_t componentVertexCount(Serial component) const;
    std::size_t componentEdgeCount(Serial component) const;
    TQ3BoundingBox componentBounds(Serial component) const;
    bool componentOrientable(Serial component) const;

    const TQ3Point3D& vertexPoint(Serial vertex) const { return m_vertices.at(vertex).point; }
    void setVertexPoint(Serial vertex, const TQ3Point3D& point);
    std::size_t vertexIndex(Serial vertex) const;
    bool vertexOnBoundary(Serial vertex) const;
    /// The vertex's component (its first vertex's serial), or 0 for none.
    Serial vertexComponent(Serial vertex) const;
    const AttributeSet* vertexSet(Serial vertex) const { return m_vertices.at(vertex).set.get(); }
    void setVertexSet(Serial vertex, Ref<AttributeSet> set);

    std::size_t faceIndex(Serial face) const;
    TQ3PlaneEquation facePlane(Serial face) const;
    std::size_t faceContourCount(Serial face) const { return m_faces.at(face).contours.size(); }
    Serial faceComponent(Serial face) const;
    const AttributeSet* faceSet(Serial face) const { return m_faces.at(face).set.get(); }
    void setFaceSet(Serial face, Ref<AttributeSet> set);

    std::pair<Serial, Serial> edgeVertices(Serial edge) const;
    std::pair<Serial, Serial> edgeFaces(Serial edge) const;
    bool edgeOnBoundary(Serial edge) const { return m_edges.at(edge).uses == 1; }
    Serial edgeComponent(Serial edge) const { return vertexComponent(m_edges.at(edge).from); }
    const AttributeSet* edgeSet(Serial edge) const { return m_edges.at(edge).set.get(); }
    void setEdgeSet(Serial edge, Ref<AttributeSet> set);

    Serial contourFace(Serial contour) const { return m_contours.at(contour).face; }
    std::size_t contourVertexCount(Serial contour) const { return m_contours.at(contour).vertices.size(); }

    const AttributeSet* cornerSet(Serial vertex, Serial face) const;
    void setCornerSet(Serial vertex, Serial face, Ref<AttributeSet> set);

    // Walks. The parts of the mesh (or of a component, 0 for all) of one
    // kind after `after` in the order they were made, or 0 at the end.
    Serial nextVertex(Serial component, Serial after) const;
    Serial nextFace(Serial after) const;
    Serial nextEdge(Serial component, Serial after) const;
    Serial nextComponent(Serial after) const;
    /// The parts around a part, each once, in the header's order: what the
    /// vertex, face and contour walks step through by position.
    std::vector<Serial> vertexEdges(Serial vertex) const;
    std::vector<Serial> vertexVertices(Serial vertex) const;
    std::vector<Serial> vertexFaces(Serial vertex) const;
    std::vector<Serial> faceEdges(Serial face) const;
    std::vector<Serial> faceVertices(Serial face) const;
    std::vector<Serial> faceFaces(Serial face) const;
    std::vector<Serial> faceContours(Serial face) const { return m_faces.at(face).contours; }
    std::vector<Serial> contourEdges(Serial contour) const;
    std::vector<Serial> contourVertices(Serial contour) const { return m_contours.at(contour).vertices; }
    std::vector<Serial> contourFaces(Serial contour) const;

private:
    struct Vertex {
        TQ3Point3D point;
        Ref<AttributeSet> set;
        std::vector<Serial> faces;
    };
    struct Contour {
        Serial face = 0;
        std::vector<Serial> vertices;
    };
    struct Face {
        std::vector<Serial> contours;
        Ref<AttributeSet> set;
        std::map<Serial, Ref<AttributeSet>> corners;
    };
    struct Edge {
        Serial from = 0, to = 0;
        Ref<AttributeSet> set;
        std::size_t uses = 0;
    };
    // What is worked out from the parts when asked, until the next edit of
    // the topology.
    struct Derived {
        std::unordered_map<Serial, std::size_t> vertexIndex, faceIndex;
        std::unordered_map<Serial, Serial> componentOf; // vertex -> first vertex
        std::vector<Serial> components;
        std::unordered_map<Serial, bool> orientable; // component -> orientable
    };

    Serial newSerial(MeshPart kind);
    bool holds(Serial serial, MeshPart kind) const;
    Serial edgeBetween(Serial a, Serial b) const;
    void addContourEdges(const std::vector<Serial>& ring);
    void removeContourEdges(const std::vector<Serial>& ring);
    void eraseFace(Serial face);
    bool hasCorner(Serial face, Serial vertex) const;
    std::vector<Serial> facesAlong(Serial edge) const;
    void topologyEdited();
    const Derived& derived() const;

    std::map<Serial, Vertex> m_vertices;
    std::map<Serial, Face> m_faces;
    std::map<Serial, Contour> m_contours;
    std::map<Serial, Edge> m_edges;
    std::map<std::pair<Serial, Serial>, Serial> m_edgeByEnds;
    Ref<AttributeSet> m_set;
    bool m_delayed = false;
    Serial m_id = 0; // this mesh's own serial in the handle table

    mutable std::mutex m_derivedMutex;
    mutable Derived m_derived;
    mutable bool m_derivedValid = false;
};

} // namespace q3
