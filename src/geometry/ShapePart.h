// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DPick.h"
#include "core/Object.h"
#include "geometry/MeshGeometry.h"

namespace q3 {

extern const ClassInfo kShapePartClass;
extern const ClassInfo kMeshPartClass;
extern const ClassInfo kMeshFacePartClass;
extern const ClassInfo kMeshEdgePartClass;
extern const ClassInfo kMeshVertexPartClass;

/// A shape part (QD3DPick.h): the part of a shape a pick hit. Holds a
/// reference to the shape.
class ShapePart : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3SharedTypeShapePart;
    Geometry& shape() const { return *m_shape; }

protected:
    explicit ShapePart(Ref<Geometry> shape) : m_shape(std::move(shape)) {}

private:
    Ref<Geometry> m_shape;
};

/// A mesh face, edge or vertex part: the mesh and the part's serial. The
/// serial is checked against the mesh on every use (an edit may have
/// deleted the part since the pick).
class MeshPartObject : public ShapePart {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShapePartTypeMeshPart;

    MeshGeometry& mesh() const { return static_cast<MeshGeometry&>(shape()); }
    /// The part's handle (TQ3MeshFace, ...); kQ3ErrorInvalidParameter when
    /// the mesh no longer has it.
    void* partHandle() const;
    /// The handle of the component the part belongs to.
    void* componentHandle() const;

protected:
    MeshPartObject(Ref<MeshGeometry> mesh, MeshPart kind, MeshGeometry::Serial serial);

private:
    MeshGeometry::Serial liveSerial() const;

    MeshPart m_kind;
    MeshGeometry::Serial m_serial;
};

template <MeshPart Kind, TQ3ObjectType Type, const ClassInfo& Info>
class MeshPartOf final : public MeshPartObject {
public:
    static constexpr TQ3ObjectType kClassType = Type;
    MeshPartOf(Ref<MeshGeometry> mesh, MeshGeometry::Serial serial) : MeshPartObject(std::move(mesh), Kind, serial) {}
    const ClassInfo& classInfo() const override { return Info; }
};

using MeshFacePart = MeshPartOf<MeshPart::Face, kQ3MeshPartTypeMeshFacePart, kMeshFacePartClass>;
using MeshEdgePart = MeshPartOf<MeshPart::Edge, kQ3MeshPartTypeMeshEdgePart, kMeshEdgePartClass>;
using MeshVertexPart = MeshPartOf<MeshPart::Vertex, kQ3MeshPartTypeMeshVertexPart, kMeshVertexPartClass>;

} // namespace q3
