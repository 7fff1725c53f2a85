// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/Entry.h"
#include "geometry/Geometry.h"
#include "view/View.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3ObjectType Q3Geometry_GetType(TQ3GeometryObject geometry)
{
    return api::getLeafType<Geometry>(__func__, geometry, "geometry");
}

TQ3Status Q3Geometry_GetAttributeSet(TQ3GeometryObject geometry, TQ3AttributeSet* attributeSet)
{
    return getValue<Geometry>(__func__, geometry, "geometry", attributeSet, "attributeSet",
                              [&](const Geometry& source) { return attributeSetToHandle(source.attributeSet()); });
}

TQ3Status Q3Geometry_SetAttributeSet(TQ3GeometryObject geometry, TQ3AttributeSet attributeSet)
{
    return guardStatus(__func__, [&] {
        Geometry& target = lookup<Geometry>(geometry, "geometry");
        target.setAttributeSet(attributeSetFromHandle(attributeSet, "attributeSet"));
    });
}

TQ3Status Q3Geometry_Submit(TQ3GeometryObject geometry, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        const Geometry& shape = lookup<Geometry>(geometry, "geometry");
        shape.accept(lookup<View>(view, "view").submitTarget());
    });
}

TQ3GeometryObject Q3Geometry_GetDecomposed(TQ3GeometryObject geometry, TQ3ViewObject view)
{
    return guard(__func__, TQ3GeometryObject{nullptr}, [&]() -> TQ3GeometryObject {
        const Geometry& shape = lookup<Geometry>(geometry, "geometry");
        return lookup<View>(view, "view").decompose(shape).detach();
    });
}

} // extern "C"
