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
