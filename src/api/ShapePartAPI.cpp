// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DPick.h"

#include "api/Entry.h"
#include "geometry/ShapePart.h"

using namespace q3;
using namespace q3::api;

namespace {

// The handle of a mesh part of class Part, written to *out.
template <class Part, class Handle, class Read>
TQ3Status readPart(const char* function, TQ3Object handle, const char* name, Handle* out, const char* outName,
                   Read read)
{
    return guardStatus(function, [&] {
        const Part& part = lookup<Part>(handle, name);
        requireNonNull(out, outName);
        *out = static_cast<Handle>(read(part));
    });
}

} // namespace

extern "C" {

TQ3Status Q3ShapePart_GetShape(TQ3ShapePartObject shapePartObject, TQ3ShapeObject* shapeObject)
{
    return getValue<ShapePart>(__func__, shapePartObject, "shapePartObject", shapeObject, "shapeObject",
                               [&](const ShapePart& part) { return Ref<Geometry>::retain(&part.shape()).detach(); });
}

TQ3ObjectType Q3ShapePart_GetType(TQ3ShapePartObject shapePartObject)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid}, [&] {
        return lookup<ShapePart>(shapePartObject, "shapePartObject").classInfo().typeAtLevel(3);
    });
}

TQ3ObjectType Q3MeshPart_GetType(TQ3MeshPartObject meshPartObject)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid}, [&] {
        return lookup<MeshPartObject>(meshPartObject, "meshPartObject").classInfo().typeAtLevel(4);
    });
}

TQ3Status Q3MeshPart_GetComponent(TQ3MeshPartObject meshPartObject, TQ3MeshComponent* component)
{
    return readPart<MeshPartObject>(__func__, meshPartObject, "meshPartObject", component, "component",
                                    [](const MeshPartObject& p) { return p.componentHandle(); });
}

TQ3Status Q3MeshFacePart_GetFace(TQ3MeshFacePartObject meshFacePartObject, TQ3MeshFace* face)
{
    return readPart<MeshFacePart>(__func__, meshFacePartObject, "meshFacePartObject", face, "face",
                                  [](const MeshPartObject& p) { return p.partHandle(); });
}

TQ3Status Q3MeshEdgePart_GetEdge(TQ3MeshEdgePartObject meshEdgePartObject, TQ3MeshEdge* edge)
{
    return readPart<MeshEdgePart>(__func__, meshEdgePartObject, "meshEdgePartObject", edge, "edge",
                                  [](const MeshPartObject& p) { return p.partHandle(); });
}

TQ3Status Q3MeshVertexPart_GetVertex(TQ3MeshVertexPartObject meshVertexPartObject, TQ3MeshVertex* vertex)
{
    return readPart<MeshVertexPart>(__func__, meshVertexPartObject, "meshVertexPartObject", vertex, "vertex",
                                    [](const MeshPartObject& p) { return p.partHandle(); });
}

} // extern "C"
