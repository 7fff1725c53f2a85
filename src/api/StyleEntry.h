// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The four entry points of every style whose data is one value (New,
// Submit, Get, Set; QD3DStyle.h), written once for any ValueStyle S. The
// value may be a C caller's enum holding any int: it travels by reference
// until S's rule has checked it. Checks run in QD3DStyle.h's order: the
// handle, the pointer, the view, then the value's rules.

#include "api/Entry.h"
#include "style/ValueStyle.h"
#include "view/View.h"

namespace q3::api {

template <class S>
TQ3StyleObject newStyle(const char* function, const typename S::Value& value)
{
    return guard(function, TQ3StyleObject{nullptr},
                 [&]() -> TQ3StyleObject { return makeShared<S>(value).detach(); });
}

/// Immediate mode: the view sees a style that lives for the call only.
template <class S>
TQ3Status submitStyle(const char* function, const typename S::Value& value, TQ3ViewObject view)
{
    return guardStatus(function, [&] {
        ShapeVisitor& target = lookup<View>(view, "view").submitTarget();
        const S transient(value);
        target.visitStyle(transient);
    });
}

template <class S>
TQ3Status getStyle(const char* function, TQ3StyleObject style, const char* styleName,
                   typename S::Value* value, const char* valueName)
{
    return guardStatus(function, [&] {
        readInto<S>(style, styleName, value, valueName, [](const S& source) { return source.value(); });
    });
}

template <class S>
TQ3Status setStyle(const char* function, TQ3StyleObject style, const char* styleName,
                   const typename S::Value& value)
{
    return guardStatus(function, [&] { lookup<S>(style, styleName).setValue(value); });
}

// The data styles (anti-alias, fog) take their value through a pointer.

template <class S>
TQ3StyleObject newStyle(const char* function, const typename S::Value* data)
{
    return newShared<S>(function, data, "data");
}

template <class S>
TQ3Status submitStyle(const char* function, const typename S::Value* data, TQ3ViewObject view)
{
    return guardStatus(function, [&] {
        requireNonNull(data, "data");
        ShapeVisitor& target = lookup<View>(view, "view").submitTarget();
        const S transient(*data);
        target.visitStyle(transient);
    });
}

template <class S>
TQ3Status setStyle(const char* function, TQ3StyleObject style, const typename S::Value* data)
{
    return guardStatus(function, [&] {
        S& target = lookup<S>(style, "styleObject");
        requireNonNull(data, "data");
        target.setValue(*data);
    });
}

} // namespace q3::api

// A C entry point cannot come from a template, so the four entry points of a
// style whose data is one value are written once below as a macro that
// defines them through the templates above. Name names the class
// (q3::<Name>Style) and the C prefix (Q3<Name>Style_); the parameter names
// are QD3DStyle.h's, so the error messages name them as every other call does.

/// Q3<Name>Style_New, _Submit, _Get and _Set of a style whose value is a Type
/// given by value (an enumeration, a Boolean, an ID), called `object` and
/// `value` in Apple's Get and Set.
#define Q3_VALUE_STYLE_ENTRY_POINTS(Name, Type, object, value)                                                   \
    TQ3StyleObject Q3##Name##Style_New(Type value)                                                               \
    {                                                                                                            \
        return q3::api::newStyle<q3::Name##Style>(__func__, value);                                              \
    }                                                                                                            \
    TQ3Status Q3##Name##Style_Submit(Type value, TQ3ViewObject view)                                             \
    {                                                                                                            \
        return q3::api::submitStyle<q3::Name##Style>(__func__, value, view);                                     \
    }                                                                                                            \
    TQ3Status Q3##Name##Style_Get(TQ3StyleObject object, Type* value)                                            \
    {                                                                                                            \
        return q3::api::getStyle<q3::Name##Style>(__func__, object, #object, value, #value);                     \
    }                                                                                                            \
    TQ3Status Q3##Name##Style_Set(TQ3StyleObject object, Type value)                                             \
    {                                                                                                            \
        return q3::api::setStyle<q3::Name##Style>(__func__, object, #object, value);                             \
    }

/// Q3<Name>Style_New, _Submit, _GetData and _SetData of a style whose data is
/// a DataType given through a pointer (anti-alias, fog).
#define Q3_DATA_STYLE_ENTRY_POINTS(Name, DataType)                                                               \
    TQ3StyleObject Q3##Name##Style_New(const DataType* data)                                                     \
    {                                                                                                            \
        return q3::api::newStyle<q3::Name##Style>(__func__, data);                                               \
    }                                                                                                            \
    TQ3Status Q3##Name##Style_Submit(const DataType* data, TQ3ViewObject view)                                   \
    {                                                                                                            \
        return q3::api::submitStyle<q3::Name##Style>(__func__, data, view);                                      \
    }                                                                                                            \
    TQ3Status Q3##Name##Style_GetData(TQ3StyleObject styleObject, DataType* data)                                \
    {                                                                                                            \
        return q3::api::getStyle<q3::Name##Style>(__func__, styleObject, "styleObject", data, "data");           \
    }                                                                                                            \
    TQ3Status Q3##Name##Style_SetData(TQ3StyleObject styleObject, const DataType* data)                          \
    {                                                                                                            \
        return q3::api::setStyle<q3::Name##Style>(__func__, styleObject, data);                                  \
    }
