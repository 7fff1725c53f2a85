// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "io/StringObject.h"

namespace q3 {

const ClassInfo kStringClass{kQ3SharedTypeString, &kSharedClass, "string"};
const ClassInfo kCStringClass{kQ3StringTypeCString, &kStringClass, "C string"};

} // namespace q3
