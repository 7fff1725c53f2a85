// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStyle.h"
#include "api/StyleEntry.h"
#include "style/ValueStyles.h"

extern "C" {

Q3_VALUE_STYLE_ENTRY_POINTS(PickID, unsigned long, pickIDObject, id)

} // extern "C"
