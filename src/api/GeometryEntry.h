// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The five entry points every geometry with a data structure has (New,
// Submit, GetData, SetData, EmptyData), written once for any DataGeometry T,
// and the four per-vertex calls of the geometries with vertices.
// Each checks in the order QD3DGeometry.h states: the handle, then the
// pointer, then the data's rules.

#include "api/Entry.h"
#include "geometry/DataGeometry.h"
#include "view/View.h"

namespace q3::api {

template <class T>
TQ3GeometryObject newGeometry(const char* function, const typename T::DataType* data)
{
    return guard(function, TQ3GeometryObject{nullptr}, [&]() -> TQ3GeometryObject {
        T::validate(data);
        return makeShared<T>(*data).detach();
    });
}

template <class T>
TQ3Status submitGeometry(const char* function, const typename T::DataType* data, TQ3ViewObject view)
{
    return guardStatus(function, [&] {
        requireNonNull(data, T::kDataName);
        ShapeVisitor& target = lookup<View>(view, "view").submitTarget();
        T::validate(data);
        const T borrowed(BorrowData{}, *data);
        target.visitGeometry(borrowed);
    });
}

template <class T>
TQ3Status getGeometryData(const char* function, TQ3GeometryObject geometry, typename T::DataType* data)
{
    return guardStatus(function, [&] {
        const T& source = lookup<T>(geometry, T::kName);
        requireNonNull(data, T::kDataName);
        source.getData(*data);
    });
}

template <class T>
TQ3Status setGeometryData(const char* function, TQ3GeometryObject geometry,
                          const typename T::DataType* data)
{
    return guardStatus(function, [&] {
        T& target = lookup<T>(geometry, T::kName);
        requireNonNull(data, T::kDataName);
        target.setData(*data);
    });
}

template <class T>
TQ3Status emptyGeometryData(const char* function, typename T::DataType* data)
{
    return guardStatus(function, [&] {
        requireNonNull(data, T::kDataName);
        T::emptyData(*data);
    });
}

/// Apple's four per-vertex calls of a geometry T whose vertex(index...) is a
/// TQ3Vertex3D (one index, or a contour's or a row's and a column's), written
/// once: the handle (called `handleName` in errors), then the pointer
/// (`valueName`), then T's index and value checks. Get of an attribute set
/// hands out a new reference (NULL for none); Set takes its own.
template <class T, class... Index>
TQ3Status getVertexPosition(const char* function, TQ3GeometryObject geometry, const char* handleName,
                            TQ3Point3D* position, const char* valueName, Index... index)
{
    return getValue<T>(function, geometry, handleName, position, valueName,
                       [&](const T& source) { return source.vertex(index...).point; });
}

template <class T, class... Index>
TQ3Status setVertexPosition(const char* function, TQ3GeometryObject geometry, const char* handleName,
                            const TQ3Point3D* position, const char* valueName, Index... index)
{
    return guardStatus(function, [&] {
        T& target = lookup<T>(geometry, handleName);
        requireNonNull(position, valueName);
        target.setVertexPosition(index..., *position);
    });
}

template <class T, class... Index>
TQ3Status getVertexAttributeSet(const char* function, TQ3GeometryObject geometry, const char* handleName,
                                TQ3AttributeSet* attributeSet, Index... index)
{
    return getValue<T>(function, geometry, handleName, attributeSet, "attributeSet", [&](const T& source) {
        return attributeSetToHandle(heldAttributeSet(source.vertex(index...).attributeSet));
    });
}

template <class T, class... Index>
TQ3Status setVertexAttributeSet(const char* function, TQ3GeometryObject geometry, const char* handleName,
                                TQ3AttributeSet attributeSet, Index... index)
{
    return guardStatus(function, [&] {
        T& target = lookup<T>(geometry, handleName);
        target.setVertexAttributeSet(index..., attributeSetFromHandle(attributeSet, "attributeSet"));
    });
}

} // namespace q3::api
