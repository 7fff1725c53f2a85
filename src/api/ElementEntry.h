// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The element calls on any object (ElementAPI.cpp), shared with the custom
// element calls (CustomElementsAPI.cpp): on a set they are the Q3Set_
// calls, on any other object they use the elements the object keeps itself.

#include "QD3D.h"
#include "core/Object.h"

namespace q3::api::elements {

/// Which family checks the handle: Q3Shape_ takes shapes and sets, Q3Object_
/// any live object.
enum class Family { kShape, kObject };

void addElement(TQ3Object handle, Family family, TQ3ElementType type, const void* data);
void getElement(TQ3Object handle, Family family, TQ3ElementType type, void* data);
bool containsElement(TQ3Object handle, Family family, TQ3ElementType type);
void nextElementType(TQ3Object handle, Family family, TQ3ElementType* type);
void emptyElements(TQ3Object handle, Family family);
void clearElement(TQ3Object handle, Family family, TQ3ElementType type);

} // namespace q3::api::elements
