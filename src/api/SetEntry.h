// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The element data of QD3DSet.h's Add and Get calls, shared by the Q3Set_
// and Q3AttributeSet_ families (and the view's attribute state): a plain
// value copied in and out, or for kQ3AttributeTypeSurfaceShader a
// TQ3SurfaceShaderObject handle read from, or written to, *data.

#include "core/AttributeSet.h"
#include "shader/TextureShader.h"

#include <cstring>

namespace q3::api {

/// Stores *data as the element `type` of `set`: the set copies a value, or
/// retains the surface shader *data names (checked to be a live surface
/// shader first). Nothing changes on failure.
inline void addElement(Set& set, TQ3ElementType type, const void* data)
{
    if (type != kQ3AttributeTypeSurfaceShader)
        return set.add(type, data);
    requireNonNull(data, "data");
    TQ3Object handle;
    std::memcpy(&handle, data, sizeof handle);
    set.addShader(Ref<SharedObject>(lookupRef<SurfaceShader>(handle, "*data (the surface shader)")));
}

/// Copies the element `type` of `set` to *data: a value, or a new reference
/// to the surface shader, which the caller disposes. *data is unchanged on
/// failure.
inline void getElement(const Set& set, TQ3ElementType type, void* data)
{
    if (type != kQ3AttributeTypeSurfaceShader)
        return set.get(type, data);
    requireNonNull(data, "data");
    if (set.shader() == nullptr)
        fail(kQ3ErrorAttributeNotContained, "the set holds no surface shader");
    TQ3Object handle = Ref<SharedObject>::retain(set.shader()).detach();
    std::memcpy(data, &handle, sizeof handle);
}

} // namespace q3::api
