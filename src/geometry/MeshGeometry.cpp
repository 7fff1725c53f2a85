// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QuickDraw 3D's Mesh. The parts live in ordered maps keyed by serial (so
// every walk is in the order parts were made and can go on after a part that
// was deleted); handles are serials, looked up in one process-wide table.
// Components, indices and orientation are derived when asked for and kept
// until the topology changes. Components are found with a union-find over
// the vertices of each face; orientation with a union-find that also keeps
// the parity between faces (two faces running along an edge the same way
// must be oriented oppositely), so a contradiction means non-orientable.

#include "geometry/MeshGeometry.h"

#include "core/Limits.h"
#include "geometry/ShapePart.h"
#include "geometry/mesh/Triangulate.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <unordered_set>

namespace q3 {

const ClassInfo kMeshClass{kQ3GeometryTypeMesh, &kGeometryClass, "mesh"};

namespace {

using Serial = MeshGeometry::Serial;

// Parts name their mesh by the mesh's own serial, and live meshes are found
// by it, so a part serial that outlived its mesh (or was issued by an edit
// that then failed) leads nowhere rather than to freed memory.
struct HandleTable {
    std::mutex mutex;
    std::unordered_map<Serial, std::pair<Serial, MeshPart>> parts;
    std::unordered_map<Serial, MeshGeometry*> meshes;
    Serial next = 1;

    Serial issue()
    {
        if (next > (std::numeric_limits<std::uintptr_t>::max() >> 3))
            fail(kQ3ErrorOutOfMemory, "every mesh part handle has been used");
        return next++;
    }
};

HandleTable& table()
{
    static HandleTable* t = new HandleTable; // outlives every mesh, also at exit
    return *t;
}

constexpr unsigned kKindBits = 3;
constexpr std::uintptr_t kKindMask = (1u << kKindBits) - 1;

const char* partName(MeshPart kind)
{
    switch (kind) {
    case MeshPart::Vertex: return "vertex";
    case MeshPart::Face: return "face";
    case MeshPart::Edge: return "edge";
    case MeshPart::Contour: return "contour";
    case MeshPart::Component: return "component";
    }
    return "part";
}

// The part a handle names, from the table: its mesh (null if none) and kind.
std::pair<MeshGeometry*, Serial> findPart(const void* handle, MeshPart kind)
{
    const auto value = reinterpret_cast<std::uintptr_t>(handle);
    if ((value & kKindMask) != static_cast<std::uintptr_t>(kind))
        return {nullptr, 0};
    const Serial serial = value >> kKindBits;
    // A component is named by its first vertex.
    const MeshPart stored = kind == MeshPart::Component ? MeshPart::Vertex : kind;
    HandleTable& t = table();
    std::lock_guard<std::mutex> lock(t.mutex);
    const auto it = t.parts.find(serial);
    if (it == t.parts.end() || it->second.second != stored)
        return {nullptr, 0};
    const auto mesh = t.meshes.find(it->second.first);
    if (mesh == t.meshes.end())
        return {nullptr, 0};
    return {mesh->second, serial};
}

[[noreturn]] void badPart(const char* name, MeshPart kind)
{
    fail(kQ3ErrorInvalidParameter, std::string(name) + " is not a " + partName(kind) +
                                       " of this mesh (deleted, of another mesh, or never made)");
}

TQ3Point3D centroidOf(const std::vector<glm::dvec3>& points)
{
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& p : points)
        sum += p;
    sum /= double(points.size());
    return TQ3Point3D{float(sum.x), float(sum.y), float(sum.z)};
}

template <class T>
void pushUnique(std::vector<T>& list, std::unordered_set<T>& seen, T value)
{
    if (seen.insert(value).second)
        list.push_back(value);
}

// Duplicates each distinct set once (Q3Object_Duplicate's sharing rule).
class SetCopier {
public:
    Ref<AttributeSet> operator()(const Ref<AttributeSet>& set)
    {
        if (!set)
            return nullptr;
        auto it = m_copies.find(set.get());
        if (it == m_copies.end())
            it = m_copies.emplace(set.get(), Ref<AttributeSet>::adopt(static_cast<AttributeSet*>(set->duplicate())))
                     .first;
        return it->second;
    }

private:
    std::unordered_map<const AttributeSet*, Ref<AttributeSet>> m_copies;
};

} // namespace

MeshGeometry::MeshGeometry()
{
    HandleTable& t = table();
    std::lock_guard<std::mutex> lock(t.mutex);
    m_id = t.issue();
    t.meshes.emplace(m_id, this);
}

MeshGeometry::~MeshGeometry()
{
    HandleTable& t = table();
    std::lock_guard<std::mutex> lock(t.mutex);
    t.meshes.erase(m_id);
    for (const auto& v : m_vertices)
        t.parts.erase(v.first);
    for (const auto& f : m_faces)
        t.parts.erase(f.first);
    for (const auto& c : m_contours)
        t.parts.erase(c.first);
    for (const auto& e : m_edges)
        t.parts.erase(e.first);
}

void* MeshGeometry::handleOf(Serial serial, MeshPart kind)
{
    if (serial == 0)
        return nullptr;
    return reinterpret_cast<void*>((std::uintptr_t(serial) << kKindBits) | static_cast<std::uintptr_t>(kind));
}

MeshGeometry& MeshGeometry::holderOf(const void* handle, MeshPart kind, const char* name, Serial& serial)
{
    if (handle == nullptr)
        fail(kQ3ErrorNULLParameter, std::string(name) + " is NULL");
    const auto found = findPart(handle, kind);
    if (found.first == nullptr)
        badPart(name, kind);
    serial = found.first->part(handle, kind, name);
    return *found.first;
}

Serial MeshGeometry::part(const void* handle, MeshPart kind, const char* name) const
{
    if (handle == nullptr)
        fail(kQ3ErrorNULLParameter, std::string(name) + " is NULL");
    const auto found = findPart(handle, kind);
    if (found.first != this || !holds(found.second, kind))
        badPart(name, kind);
    if (kind == MeshPart::Component && vertexComponent(found.second) != found.second)
        fail(kQ3ErrorInvalidParameter,
             std::string(name) + " names a component that an edit has merged, split or removed");
    return found.second;
}

MeshGeometry::Serial MeshGeometry::newSerial(MeshPart kind)
{
    HandleTable& t = table();
    std::lock_guard<std::mutex> lock(t.mutex);
    const Serial serial = t.issue();
    t.parts.emplace(serial, std::make_pair(m_id, kind));
    return serial;
}

bool MeshGeometry::holds(Serial serial, MeshPart kind) const
{
    switch (kind) {
    case MeshPart::Vertex:
    case MeshPart::Component: return m_vertices.count(serial) != 0;
    case MeshPart::Face: return m_faces.count(serial) != 0;
    case MeshPart::Edge: return m_edges.count(serial) != 0;
    case MeshPart::Contour: return m_contours.count(serial) != 0;
    }
    return false;
}

void MeshGeometry::topologyEdited()
{
    {
        std::lock_guard<std::mutex> lock(m_derivedMutex);
        m_derivedValid = false;
        m_derived = Derived{};
    }
    markEdited();
}

// ---- Edits -----------------------------------------------------------------

MeshGeometry::Serial MeshGeometry::addVertex(const TQ3Point3D& point, Ref<AttributeSet> set)
{
    if (m_vertices.size() >= limits::kMaxArrayCount)
        fail(kQ3ErrorParameterOutOfRange, "the mesh has kQ3GeometryMaxArrayCount vertices already");
    const Serial serial = newSerial(MeshPart::Vertex);
    m_vertices.emplace(serial, Vertex{point, std::move(set), {}});
    topologyEdited();
    return serial;
}

MeshGeometry::Serial MeshGeometry::edgeBetween(Serial a, Serial b) const
{
    const auto it = m_edgeByEnds.find(std::minmax(a, b));
    return it == m_edgeByEnds.end() ? 0 : it->second;
}

void MeshGeometry::addContourEdges(const std::vector<Serial>& ring)
{
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
        const Serial a = ring[i], b = ring[(i + 1) % n];
        const Serial existing = edgeBetween(a, b);
        if (existing != 0) {
            ++m_edges.at(existing).uses;
            continue;
        }
        const Serial serial = newSerial(MeshPart::Edge);
        m_edges.emplace(serial, Edge{a, b, nullptr, 1});
        m_edgeByEnds.emplace(std::minmax(a, b), serial);
    }
}

void MeshGeometry::removeContourEdges(const std::vector<Serial>& ring)
{
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
        const Serial serial = edgeBetween(ring[i], ring[(i + 1) % n]);
        Edge& edge = m_edges.at(serial);
        if (--edge.uses == 0) {
            m_edgeByEnds.erase(std::minmax(edge.from, edge.to));
            m_edges.erase(serial);
            HandleTable& t = table();
            std::lock_guard<std::mutex> lock(t.mutex);
            t.parts.erase(serial);
        }
    }
}

MeshGeometry::Serial MeshGeometry::addFace(const std::vector<Serial>& vertices, Ref<AttributeSet> set)
{
    if (m_faces.size() >= limits::kMaxArrayCount)
        fail(kQ3ErrorParameterOutOfRange, "the mesh has kQ3GeometryMaxArrayCount faces already");
    const Serial face = newSerial(MeshPart::Face);
    const Serial contour = newSerial(MeshPart::Contour);
    m_contours.emplace(contour, Contour{face, vertices});
    m_faces.emplace(face, Face{{contour}, std::move(set), {}});
    // A contour may pass a vertex more than once (QuickDraw 3D and Quesa
    // keep such faces); the vertex lists the face once.
    for (Serial v : vertices) {
        std::vector<Serial>& faces = m_vertices.at(v).faces;
        if (std::find(faces.begin(), faces.end(), face) == faces.end())
            faces.push_back(face);
    }
    addContourEdges(vertices);
    topologyEdited();
    return face;
}

void MeshGeometry::eraseFace(Serial face)
{
    Face& f = m_faces.at(face);
    std::unordered_set<Serial> corners;
    for (Serial c : f.contours) {
        const Contour& contour = m_contours.at(c);
        removeContourEdges(contour.vertices);
        corners.insert(contour.vertices.begin(), contour.vertices.end());
    }
    for (Serial v : corners) {
        std::vector<Serial>& faces = m_vertices.at(v).faces;
        faces.erase(std::remove(faces.begin(), faces.end(), face), faces.end());
    }
    HandleTable& t = table();
    {
        std::lock_guard<std::mutex> lock(t.mutex);
        for (Serial c : f.contours)
            t.parts.erase(c);
        t.parts.erase(face);
    }
    for (Serial c : f.contours)
        m_contours.erase(c);
    m_faces.erase(face);
}

void MeshGeometry::deleteFace(Serial face)
{
    eraseFace(face);
    topologyEdited();
}

void MeshGeometry::deleteVertex(Serial vertex)
{
    const std::vector<Serial> faces = m_vertices.at(vertex).faces;
    for (Serial f : faces)
        eraseFace(f);
    m_vertices.erase(vertex);
    {
        HandleTable& t = table();
        std::lock_guard<std::mutex> lock(t.mutex);
        t.parts.erase(vertex);
    }
    topologyEdited();
}

MeshGeometry::Serial MeshGeometry::faceToContour(Serial container, Serial face)
{
    if (container == face)
        fail(kQ3ErrorInvalidParameter, "face is containerFace: a face cannot become a contour of itself");
    Face& target = m_faces.at(container);
    Face& source = m_faces.at(face);
    std::size_t total = 0;
    for (Serial c : target.contours)
        total += m_contours.at(c).vertices.size();
    for (Serial c : source.contours)
        total += m_contours.at(c).vertices.size();
    if (total > limits::kMaxArrayCount)
        fail(kQ3ErrorInvalidParameter, "containerFace would have more than kQ3GeometryMaxArrayCount vertices");
    const Serial first = source.contours.front();
    for (Serial c : source.contours) {
        m_contours.at(c).face = container;
        target.contours.push_back(c);
        for (Serial v : m_contours.at(c).vertices) {
            std::vector<Serial>& faces = m_vertices.at(v).faces;
            faces.erase(std::remove(faces.begin(), faces.end(), face), faces.end());
            if (std::find(faces.begin(), faces.end(), container) == faces.end())
                faces.push_back(container);
        }
    }
    for (auto& corner : source.corners)
        target.corners.emplace(corner.first, std::move(corner.second));
    {
        HandleTable& t = table();
        std::lock_guard<std::mutex> lock(t.mutex);
        t.parts.erase(face);
    }
    m_faces.erase(face);
    topologyEdited();
    return first;
}

MeshGeometry::Serial MeshGeometry::contourToFace(Serial contour)
{
    const Serial container = m_contours.at(contour).face;
    Face& old = m_faces.at(container);
    if (old.contours.size() == 1)
        return container;
    if (m_faces.size() >= limits::kMaxArrayCount)
        fail(kQ3ErrorParameterOutOfRange, "the mesh has kQ3GeometryMaxArrayCount faces already");
    const Serial face = newSerial(MeshPart::Face);
    Face fresh{{contour}, nullptr, {}};
    const std::vector<Serial>& ring = m_contours.at(contour).vertices;
    for (Serial v : ring) {
        const auto corner = old.corners.find(v);
        if (corner != old.corners.end())
            fresh.corners.emplace(v, corner->second);
    }
    old.contours.erase(std::find(old.contours.begin(), old.contours.end(), contour));
    // Corners of the old face that none of its remaining contours has go.
    std::unordered_set<Serial> remaining;
    for (Serial c : old.contours)
        remaining.insert(m_contours.at(c).vertices.begin(), m_contours.at(c).vertices.end());
    for (Serial v : ring) {
        std::vector<Serial>& faces = m_vertices.at(v).faces;
        if (remaining.count(v) == 0) {
            faces.erase(std::remove(faces.begin(), faces.end(), container), faces.end());
            old.corners.erase(v);
        }
        if (std::find(faces.begin(), faces.end(), face) == faces.end())
            faces.push_back(face);
    }
    m_contours.at(contour).face = face;
    m_faces.emplace(face, std::move(fresh));
    topologyEdited();
    return face;
}

void MeshGeometry::setAttributeSet(Ref<AttributeSet> attributes)
{
    m_set = std::move(attributes);
    markEdited();
}

void MeshGeometry::setVertexPoint(Serial vertex, const TQ3Point3D& point)
{
    m_vertices.at(vertex).point = point;
    markEdited();
}

void MeshGeometry::setVertexSet(Serial vertex, Ref<AttributeSet> set)
{
    m_vertices.at(vertex).set = std::move(set);
    markEdited();
}

void MeshGeometry::setFaceSet(Serial face, Ref<AttributeSet> set)
{
    m_faces.at(face).set = std::move(set);
    markEdited();
}

void MeshGeometry::setEdgeSet(Serial edge, Ref<AttributeSet> set)
{
    m_edges.at(edge).set = std::move(set);
    markEdited();
}

bool MeshGeometry::hasCorner(Serial face, Serial vertex) const
{
    const std::vector<Serial>& faces = m_vertices.at(vertex).faces;
    return std::find(faces.begin(), faces.end(), face) != faces.end();
}

const AttributeSet* MeshGeometry::cornerSet(Serial vertex, Serial face) const
{
    if (!hasCorner(face, vertex))
        fail(kQ3ErrorInvalidParameter, "vertex is not a corner of face");
    const auto& corners = m_faces.at(face).corners;
    const auto it = corners.find(vertex);
    return it == corners.end() ? nullptr : it->second.get();
}

void MeshGeometry::setCornerSet(Serial vertex, Serial face, Ref<AttributeSet> set)
{
    if (!hasCorner(face, vertex))
        fail(kQ3ErrorInvalidParameter, "vertex is not a corner of face");
    auto& corners = m_faces.at(face).corners;
    if (set)
        corners[vertex] = std::move(set);
    else
        corners.erase(vertex);
    markEdited();
}

Object* MeshGeometry::duplicate() const
{
    Ref<MeshGeometry> copy = Ref<MeshGeometry>::adopt(new MeshGeometry);
    SetCopier copySet;
    std::unordered_map<Serial, Serial> vertexMap, faceMap;
    copy->m_set = copySet(m_set);
    for (const auto& v : m_vertices)
        vertexMap[v.first] = copy->addVertex(v.second.point, copySet(v.second.set));
    for (const auto& f : m_faces) {
        Serial made = 0;
        for (Serial c : f.second.contours) {
            std::vector<Serial> ring;
            for (Serial v : m_contours.at(c).vertices)
                ring.push_back(vertexMap.at(v));
            const Serial face = copy->addFace(ring, nullptr);
            made = made == 0 ? face : (copy->faceToContour(made, face), made);
        }
        Face& target = copy->m_faces.at(made);
        target.set = copySet(f.second.set);
        for (const auto& corner : f.second.corners)
            target.corners[vertexMap.at(corner.first)] = copySet(corner.second);
        faceMap[f.first] = made;
    }
    for (const auto& e : m_edges)
        if (e.second.set)
            copy->m_edges.at(copy->edgeBetween(vertexMap.at(e.second.from), vertexMap.at(e.second.to))).set =
                copySet(e.second.set);
    copy->m_delayed = m_delayed;
    copy->registerLive();
    return copy.detach();
}

// ---- Derived data ----------------------------------------------------------

const MeshGeometry::Derived& MeshGeometry::derived() const
{
    std::lock_guard<std::mutex> lock(m_derivedMutex);
    if (m_derivedValid)
        return m_derived;
    Derived d;
    std::size_t i = 0;
    for (const auto& v : m_vertices)
        d.vertexIndex[v.first] = i++;
    i = 0;
    for (const auto& f : m_faces)
        d.faceIndex[f.first] = i++;

    // Components: union-find over the vertices of each face, the root being
    // the smallest serial (the first vertex made).
    std::unordered_map<Serial, Serial> parent;
    std::function<Serial(Serial)> find = [&](Serial x) {
        Serial root = x;
        while (parent.at(root) != root)
            root = parent.at(root);
        while (parent.at(x) != root) {
            const Serial next = parent.at(x);
            parent[x] = root;
            x = next;
        }
        return root;
    };
    for (const auto& c : m_contours)
        for (Serial v : c.second.vertices)
            parent.emplace(v, v);
    for (const auto& f : m_faces) {
        const Serial anchor = m_contours.at(f.second.contours.front()).vertices.front();
        for (Serial c : f.second.contours)
            for (Serial v : m_contours.at(c).vertices) {
                const Serial a = find(anchor), b = find(v);
                if (a != b)
                    parent[std::max(a, b)] = std::min(a, b);
            }
    }
    for (const auto& p : parent)
        d.componentOf[p.first] = find(p.first);
    for (const auto& p : d.componentOf)
        if (p.first == p.second)
            d.components.push_back(p.first);
    std::sort(d.components.begin(), d.components.end());

    // Orientation: faces carry a flip bit relative to their root; each edge
    // gives a parity constraint between the faces along it.
    std::unordered_map<Serial, std::pair<Serial, bool>> faceParent; // face -> (parent, flip relative to it)
    std::function<std::pair<Serial, bool>(Serial)> rootOf = [&](Serial f) {
        bool parity = false;
        Serial x = f;
        while (faceParent.at(x).first != x) {
            parity ^= faceParent.at(x).second;
            x = faceParent.at(x).first;
        }
        return std::make_pair(x, parity);
    };
    for (const auto& f : m_faces)
        faceParent.emplace(f.first, std::make_pair(f.first, false));
    for (Serial root : d.components)
        d.orientable[root] = true;
    std::unordered_map<Serial, std::vector<std::pair<Serial, bool>>> uses; // edge -> (face, runs from->to)
    for (const auto& c : m_contours) {
        const std::vector<Serial>& ring = c.second.vertices;
        for (std::size_t k = 0, n = ring.size(); k < n; ++k) {
            const Serial edge = edgeBetween(ring[k], ring[(k + 1) % n]);
            uses[edge].emplace_back(c.second.face, m_edges.at(edge).from == ring[k]);
        }
    }
    for (const auto& u : uses) {
        const Serial component = d.componentOf.at(m_edges.at(u.first).from);
        if (u.second.size() > 2) {
            d.orientable[component] = false;
            continue;
        }
        if (u.second.size() < 2)
            continue;
        // The two sides must run oppositely once their faces' flips apply.
        const bool needFlip = u.second[0].second == u.second[1].second;
        const auto a = rootOf(u.second[0].first), b = rootOf(u.second[1].first);
        if (a.first == b.first) {
            if ((a.second ^ b.second) != needFlip)
                d.orientable[component] = false;
        } else {
            faceParent[a.first] = std::make_pair(b.first, bool(a.second ^ b.second ^ needFlip));
        }
    }
    m_derived = std::move(d);
    m_derivedValid = true;
    return m_derived;
}

std::size_t MeshGeometry::componentCount() const
{
    return derived().components.size();
}

std::size_t MeshGeometry::cornerCount() const
{
    std::size_t count = 0;
    for (const auto& f : m_faces)
        count += f.second.corners.size();
    return count;
}

bool MeshGeometry::orientable() const
{
    for (const auto& o : derived().orientable)
        if (!o.second)
            return false;
    return true;
}

std::size_t MeshGeometry::componentVertexCount(Serial component) const
{
    std::size_t count = 0;
    for (const auto& p : derived().componentOf)
        count += p.second == component;
    return count;
}

std::size_t MeshGeometry::componentEdgeCount(Serial component) const
{
    const Derived& d = derived();
    std::size_t count = 0;
    for (const auto& e : m_edges)
        count += d.componentOf.at(e.second.from) == component;
    return count;
}

TQ3BoundingBox MeshGeometry::componentBounds(Serial component) const
{
    TQ3BoundingBox box{};
    bool first = true;
    for (const auto& p : derived().componentOf) {
        if (p.second != component)
            continue;
        const TQ3Point3D& q = m_vertices.at(p.first).point;
        if (first) {
            box.min = box.max = q;
            first = false;
        }
        box.min = {std::min(box.min.x, q.x), std::min(box.min.y, q.y), std::min(box.min.z, q.z)};
        box.max = {std::max(box.max.x, q.x), std::max(box.max.y, q.y), std::max(box.max.z, q.z)};
    }
    box.isEmpty = kQ3False;
    return box;
}

bool MeshGeometry::componentOrientable(Serial component) const
{
    return derived().orientable.at(component);
}

std::size_t MeshGeometry::vertexIndex(Serial vertex) const
{
    return derived().vertexIndex.at(vertex);
}

std::size_t MeshGeometry::faceIndex(Serial face) const
{
    return derived().faceIndex.at(face);
}

MeshGeometry::Serial MeshGeometry::vertexComponent(Serial vertex) const
{
    const Derived& d = derived();
    const auto it = d.componentOf.find(vertex);
    return it == d.componentOf.end() ? 0 : it->second;
}

MeshGeometry::Serial MeshGeometry::faceComponent(Serial face) const
{
    return vertexComponent(m_contours.at(m_faces.at(face).contours.front()).vertices.front());
}

bool MeshGeometry::vertexOnBoundary(Serial vertex) const
{
    for (Serial e : vertexEdges(vertex))
        if (m_edges.at(e).uses == 1)
            return true;
    return false;
}

TQ3PlaneEquation MeshGeometry::facePlane(Serial face) const
{
    std::vector<glm::dvec3> points;
    for (Serial v : m_contours.at(m_faces.at(face).contours.front()).vertices) {
        const TQ3Point3D& p = m_vertices.at(v).point;
        points.emplace_back(p.x, p.y, p.z);
    }
    const glm::dvec3 n = mesh::newellNormal(points.data(), points.size());
    if (n == glm::dvec3(0.0))
        fail(kQ3ErrorDegenerateGeometry, "the face's first contour encloses no area");
    const TQ3Point3D c = centroidOf(points);
    TQ3PlaneEquation plane;
    plane.normal = TQ3Vector3D{float(n.x), float(n.y), float(n.z)};
    plane.constant = float(-(n.x * c.x + n.y * c.y + n.z * c.z));
    return plane;
}

std::vector<Serial> MeshGeometry::facesAlong(Serial edge) const
{
    const Edge& e = m_edges.at(edge);
    std::vector<Serial> faces;
    for (Serial f : vertexFaces(e.from))
        for (Serial c : m_faces.at(f).contours) {
            const std::vector<Serial>& ring = m_contours.at(c).vertices;
            bool along = false;
            for (std::size_t k = 0, n = ring.size(); k < n && !along; ++k)
                along = std::minmax(ring[k], ring[(k + 1) % n]) == std::minmax(e.from, e.to);
            if (along) {
                faces.push_back(f);
                break;
            }
        }
    return faces;
}

std::pair<Serial, Serial> MeshGeometry::edgeVertices(Serial edge) const
{
    const Edge& e = m_edges.at(edge);
    return {e.from, e.to};
}

std::pair<Serial, Serial> MeshGeometry::edgeFaces(Serial edge) const
{
    const std::vector<Serial> faces = facesAlong(edge);
    return {faces.empty() ? 0 : faces[0], faces.size() < 2 ? 0 : faces[1]};
}

// ---- Walks -----------------------------------------------------------------

MeshGeometry::Serial MeshGeometry::nextVertex(Serial component, Serial after) const
{
    for (auto it = m_vertices.upper_bound(after); it != m_vertices.end(); ++it)
        if (component == 0 || vertexComponent(it->first) == component)
            return it->first;
    return 0;
}

MeshGeometry::Serial MeshGeometry::nextFace(Serial after) const
{
    const auto it = m_faces.upper_bound(after);
    return it == m_faces.end() ? 0 : it->first;
}

MeshGeometry::Serial MeshGeometry::nextEdge(Serial component, Serial after) const
{
    for (auto it = m_edges.upper_bound(after); it != m_edges.end(); ++it)
        if (component == 0 || vertexComponent(it->second.from) == component)
            return it->first;
    return 0;
}

MeshGeometry::Serial MeshGeometry::nextComponent(Serial after) const
{
    const std::vector<Serial>& roots = derived().components;
    const auto it = std::upper_bound(roots.begin(), roots.end(), after);
    return it == roots.end() ? 0 : *it;
}

std::vector<Serial> MeshGeometry::vertexFaces(Serial vertex) const
{
    std::vector<Serial> faces = m_vertices.at(vertex).faces;
    std::sort(faces.begin(), faces.end());
    return faces;
}

std::vector<Serial> MeshGeometry::vertexEdges(Serial vertex) const
{
    std::vector<Serial> edges;
    std::unordered_set<Serial> seen;
    for (Serial f : vertexFaces(vertex))
        for (Serial c : m_faces.at(f).contours) {
            const std::vector<Serial>& ring = m_contours.at(c).vertices;
            for (std::size_t k = 0, n = ring.size(); k < n; ++k)
                if (ring[k] == vertex) {
                    pushUnique(edges, seen, edgeBetween(ring[(k + n - 1) % n], vertex));
                    pushUnique(edges, seen, edgeBetween(vertex, ring[(k + 1) % n]));
                }
        }
    return edges;
}

std::vector<Serial> MeshGeometry::vertexVertices(Serial vertex) const
{
    std::vector<Serial> vertices;
    for (Serial e : vertexEdges(vertex)) {
        const Edge& edge = m_edges.at(e);
        vertices.push_back(edge.from == vertex ? edge.to : edge.from);
    }
    return vertices;
}

std::vector<Serial> MeshGeometry::faceEdges(Serial face) const
{
    std::vector<Serial> edges;
    std::unordered_set<Serial> seen;
    for (Serial c : m_faces.at(face).contours)
        for (Serial e : contourEdges(c))
            pushUnique(edges, seen, e);
    return edges;
}

std::vector<Serial> MeshGeometry::faceVertices(Serial face) const
{
    std::vector<Serial> vertices;
    std::unordered_set<Serial> seen;
    for (Serial c : m_faces.at(face).contours)
        for (Serial v : m_contours.at(c).vertices)
            pushUnique(vertices, seen, v);
    return vertices;
}

std::vector<Serial> MeshGeometry::faceFaces(Serial face) const
{
    std::vector<Serial> faces;
    std::unordered_set<Serial> seen{face};
    for (Serial e : faceEdges(face))
        for (Serial f : facesAlong(e))
            pushUnique(faces, seen, f);
    return faces;
}

std::vector<Serial> MeshGeometry::contourEdges(Serial contour) const
{
    const std::vector<Serial>& ring = m_contours.at(contour).vertices;
    std::vector<Serial> edges;
    std::unordered_set<Serial> seen;
    for (std::size_t k = 0, n = ring.size(); k < n; ++k)
        pushUnique(edges, seen, edgeBetween(ring[k], ring[(k + 1) % n]));
    return edges;
}

std::vector<Serial> MeshGeometry::contourFaces(Serial contour) const
{
    std::vector<Serial> faces;
    std::unordered_set<Serial> seen{m_contours.at(contour).face};
    for (Serial e : contourEdges(contour))
        for (Serial f : facesAlong(e))
            pushUnique(faces, seen, f);
    return faces;
}

// ---- Drawing ---------------------------------------------------------------

void MeshGeometry::decompose(const DecomposeContext&, PrimitiveSink& sink) const
{
    std::vector<const AttributeSet*> sets;
    for (const auto& v : m_vertices)
        sets.push_back(v.second.set.get());
    for (const auto& f : m_faces) {
        sets.push_back(f.second.set.get());
        for (const auto& corner : f.second.corners)
            sets.push_back(corner.second.get());
    }
    for (const auto& e : m_edges)
        sets.push_back(e.second.set.get());
    std::vector<double> key;
    appendEditIndices(key, sets);
    withMesh(
        std::move(key),
        [&](Mesh& mesh) {
            std::unordered_set<Serial> drawnEdges;
            for (const auto& f : m_faces) {
                const Face& face = f.second;
                // One mesh vertex per corner of this face, with its attributes.
                std::unordered_map<Serial, std::uint32_t> cornerIndex;
                std::vector<glm::dvec3> points;
                std::vector<std::uint32_t> order;
                std::vector<std::size_t> starts;
                for (Serial c : face.contours) {
                    starts.push_back(points.size());
                    for (Serial v : m_contours.at(c).vertices) {
                        auto it = cornerIndex.find(v);
                        if (it == cornerIndex.end()) {
                            const Vertex& vertex = m_vertices.at(v);
                            VertexAttributes attributes;
                            const auto corner = face.corners.find(v);
                            if (corner != face.corners.end())
                                attributes.inheritFrom(corner->second.get());
                            attributes.inheritFrom(vertex.set.get());
                            attributes.inheritFrom(face.set.get());
                            it = cornerIndex.emplace(v, mesh.addVertex(vertex.point, attributes)).first;
                        }
                        const TQ3Point3D& p = m_vertices.at(v).point;
                        points.emplace_back(p.x, p.y, p.z);
                        order.push_back(it->second);
                    }
                }
                const glm::dvec3 normal = mesh::newellNormal(points.data(), starts.size() > 1 ? starts[1] : points.size());
                if (normal != glm::dvec3(0.0)) {
                    const std::vector<std::uint32_t> triangles =
                        mesh::triangulate(mesh::projectToPlane(points.data(), points.size(), normal), starts);
                    for (std::size_t t = 0; t < triangles.size(); t += 3)
                        mesh.addTriangle(order[triangles[t]], order[triangles[t + 1]], order[triangles[t + 2]]);
                }
                for (Serial c : face.contours) {
                    const std::vector<Serial>& ring = m_contours.at(c).vertices;
                    for (std::size_t k = 0, n = ring.size(); k < n; ++k) {
                        const Serial a = ring[k], b = ring[(k + 1) % n];
                        const Serial e = edgeBetween(a, b);
                        if (!drawnEdges.insert(e).second)
                            continue;
                        const AttributeSet* edgeSet = m_edges.at(e).set.get();
                        const auto edgeColor = edgeSet ? edgeSet->values().diffuseColor() : std::nullopt;
                        if (!edgeColor) {
                            mesh.addEdge(cornerIndex.at(a), cornerIndex.at(b));
                            continue;
                        }
                        std::uint32_t ends[2];
                        const Serial both[2] = {a, b};
                        for (int s = 0; s < 2; ++s) {
                            VertexAttributes attributes;
                            attributes.inherit(kQ3AttributeTypeDiffuseColor, &*edgeColor);
                            ends[s] = mesh.addVertex(m_vertices.at(both[s]).point, attributes);
                        }
                        mesh.addEdge(ends[0], ends[1]);
                    }
                }
            }
        },
        [&](const Mesh& mesh) { sink.draw(mesh.view(), attributeSet()); });
}


namespace {

double pointSegmentDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b)
{
    const glm::dvec3 ab = b - a;
    const double length2 = glm::dot(ab, ab);
    const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    return glm::distance(p, a + t * ab);
}

glm::dvec3 toVec(const TQ3Point3D& p)
{
    return glm::dvec3(p.x, p.y, p.z);
}

} // namespace

Ref<SharedObject> MeshGeometry::shapePartAt(TQ3PickParts part, const TQ3Point3D& local) const
{
    const glm::dvec3 p = toVec(local);
    Ref<MeshGeometry> self = Ref<MeshGeometry>::retain(const_cast<MeshGeometry*>(this));
    double best = std::numeric_limits<double>::infinity();
    Serial found = 0;
    if (part == kQ3PickPartsMaskVertex) {
        for (const auto& v : m_vertices) {
            const double d = glm::distance(p, toVec(v.second.point));
            if (d < best) {
                best = d;
                found = v.first;
            }
        }
        return found == 0 ? Ref<SharedObject>() : Ref<SharedObject>(makeShared<MeshVertexPart>(self, found));
    }
    if (part == kQ3PickPartsMaskEdge) {
        for (const auto& e : m_edges) {
            const double d = pointSegmentDistance(p, toVec(m_vertices.at(e.second.from).point),
                                                  toVec(m_vertices.at(e.second.to).point));
            if (d < best) {
                best = d;
                found = e.first;
            }
        }
        return found == 0 ? Ref<SharedObject>() : Ref<SharedObject>(makeShared<MeshEdgePart>(self, found));
    }
    if (part != kQ3PickPartsMaskFace)
        return {};
    // Each face scores its plane distance, plus, when the point falls
    // outside its contours (even-odd, projected along the normal's largest
    // axis), its distance to the nearest contour side: 0 for the face the
    // hit point lies in, up to rounding.
    for (const auto& f : m_faces) {
        std::vector<glm::dvec3> first;
        for (Serial v : m_contours.at(f.second.contours.front()).vertices)
            first.push_back(toVec(m_vertices.at(v).point));
        glm::dvec3 n = mesh::newellNormal(first.data(), first.size());
        const double length = glm::length(n);
        if (!(length > 0.0))
            continue;
        n /= length;
        const double planeDistance = std::fabs(glm::dot(p - first.front(), n));
        const glm::dvec3 a = glm::abs(n);
        const int drop = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
        const int u = drop == 0 ? 1 : 0, w = drop == 2 ? 1 : 2;
        bool inside = false;
        double edgeDistance = std::numeric_limits<double>::infinity();
        for (Serial c : f.second.contours) {
            const std::vector<Serial>& ring = m_contours.at(c).vertices;
            for (std::size_t k = 0, count = ring.size(); k < count; ++k) {
                const glm::dvec3 s = toVec(m_vertices.at(ring[k]).point);
                const glm::dvec3 t = toVec(m_vertices.at(ring[(k + 1) % count]).point);
                edgeDistance = std::min(edgeDistance, pointSegmentDistance(p, s, t));
                if ((s[w] > p[w]) != (t[w] > p[w]) &&
                    p[u] < s[u] + (p[w] - s[w]) * (t[u] - s[u]) / (t[w] - s[w]))
                    inside = !inside;
            }
        }
        const double score = planeDistance + (inside ? 0.0 : edgeDistance);
        if (score < best) {
            best = score;
            found = f.first;
        }
    }
    return found == 0 ? Ref<SharedObject>() : Ref<SharedObject>(makeShared<MeshFacePart>(self, found));
}

} // namespace q3
