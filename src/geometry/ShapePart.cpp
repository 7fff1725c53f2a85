// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/ShapePart.h"

namespace q3 {

const ClassInfo kShapePartClass{kQ3SharedTypeShapePart, &kSharedClass, "shape part"};
const ClassInfo kMeshPartClass{kQ3ShapePartTypeMeshPart, &kShapePartClass, "mesh part"};
const ClassInfo kMeshFacePartClass{kQ3MeshPartTypeMeshFacePart, &kMeshPartClass, "mesh face part"};
const ClassInfo kMeshEdgePartClass{kQ3MeshPartTypeMeshEdgePart, &kMeshPartClass, "mesh edge part"};
const ClassInfo kMeshVertexPartClass{kQ3MeshPartTypeMeshVertexPart, &kMeshPartClass, "mesh vertex part"};

MeshPartObject::MeshPartObject(Ref<MeshGeometry> mesh, MeshPart kind, MeshGeometry::Serial serial)
    : ShapePart(Ref<Geometry>(std::move(mesh))), m_kind(kind), m_serial(serial)
{
}

MeshGeometry::Serial MeshPartObject::liveSerial() const
{
    if (!mesh().hasPart(m_serial, m_kind))
        fail(kQ3ErrorInvalidParameter, "the mesh part's face, edge or vertex was deleted from the mesh since the pick");
    return m_serial;
}

void* MeshPartObject::partHandle() const
{
    return MeshGeometry::handleOf(liveSerial(), m_kind);
}

void* MeshPartObject::componentHandle() const
{
    const MeshGeometry::Serial serial = liveSerial();
    const MeshGeometry& m = mesh();
    const MeshGeometry::Serial component = m_kind == MeshPart::Face   ? m.faceComponent(serial)
                                           : m_kind == MeshPart::Edge ? m.edgeComponent(serial)
                                                                      : m.vertexComponent(serial);
    if (component == 0)
        fail(kQ3ErrorInvalidParameter, "the mesh part belongs to no component");
    return MeshGeometry::handleOf(component, MeshPart::Component);
}

} // namespace q3
