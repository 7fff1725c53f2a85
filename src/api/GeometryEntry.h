// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The five entry points every geometry with a data structure has (New,
// Submit, GetData, SetData, EmptyData), written once for any DataGeometry T.
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

} // namespace q3::api
