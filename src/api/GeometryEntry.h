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

// A C entry point cannot come from a template, so the entry points above are
// also written once as macros that define them. Name names the class
// (q3::<Name>), its data (TQ3<Name>Data) and the C prefix (Q3<Name>_).

/// Q3<Name>_New, _Submit, _GetData, _SetData and _EmptyData.
#define Q3_DATA_GEOMETRY_ENTRY_POINTS(Name)                                                                     \
    TQ3GeometryObject Q3##Name##_New(const TQ3##Name##Data* data)                                               \
    {                                                                                                           \
        return q3::api::newGeometry<q3::Name>(__func__, data);                                                  \
    }                                                                                                           \
    TQ3Status Q3##Name##_Submit(const TQ3##Name##Data* data, TQ3ViewObject view)                                \
    {                                                                                                           \
        return q3::api::submitGeometry<q3::Name>(__func__, data, view);                                         \
    }                                                                                                           \
    TQ3Status Q3##Name##_GetData(TQ3GeometryObject geometry, TQ3##Name##Data* data)                             \
    {                                                                                                           \
        return q3::api::getGeometryData<q3::Name>(__func__, geometry, data);                                    \
    }                                                                                                           \
    TQ3Status Q3##Name##_SetData(TQ3GeometryObject geometry, const TQ3##Name##Data* data)                       \
    {                                                                                                           \
        return q3::api::setGeometryData<q3::Name>(__func__, geometry, data);                                    \
    }                                                                                                           \
    TQ3Status Q3##Name##_EmptyData(TQ3##Name##Data* data)                                                       \
    {                                                                                                           \
        return q3::api::emptyGeometryData<q3::Name>(__func__, data);                                            \
    }

/// Q3<Name>_Get/SetVertexPosition and _Get/SetVertexAttributeSet of a
/// geometry whose vertices have one index; `handle` and `position` are
/// Apple's parameter names (the error messages name them).
#define Q3_INDEXED_VERTEX_ENTRY_POINTS(Name, handle, position)                                                  \
    TQ3Status Q3##Name##_GetVertexPosition(TQ3GeometryObject handle, unsigned long index, TQ3Point3D* position) \
    {                                                                                                           \
        return q3::api::getVertexPosition<q3::Name>(__func__, handle, #handle, position, #position, index);     \
    }                                                                                                           \
    TQ3Status Q3##Name##_SetVertexPosition(TQ3GeometryObject handle, unsigned long index,                       \
                                           const TQ3Point3D* position)                                          \
    {                                                                                                           \
        return q3::api::setVertexPosition<q3::Name>(__func__, handle, #handle, position, #position, index);     \
    }                                                                                                           \
    TQ3Status Q3##Name##_GetVertexAttributeSet(TQ3GeometryObject handle, unsigned long index,                   \
                                               TQ3AttributeSet* attributeSet)                                   \
    {                                                                                                           \
        return q3::api::getVertexAttributeSet<q3::Name>(__func__, handle, #handle, attributeSet, index);        \
    }                                                                                                           \
    TQ3Status Q3##Name##_SetVertexAttributeSet(TQ3GeometryObject handle, unsigned long index,                   \
                                               TQ3AttributeSet attributeSet)                                    \
    {                                                                                                           \
        return q3::api::setVertexAttributeSet<q3::Name>(__func__, handle, #handle, attributeSet, index);        \
    }
