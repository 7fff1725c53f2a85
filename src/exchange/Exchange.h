// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The exchange layer (docs/exchange.md): Q3 objects to and from foreign
// model formats. It sits above src/io and src/view: it walks objects with a
// view Pass and builds them with the core classes, and knows the formats
// only through exchange/Gltf.h.

#include "Q3Exchange.h"
#include "core/Ref.h"
#include "exchange/SceneExport.h"

#include <string>

namespace q3 {
class DisplayGroup;
class Object;
} // namespace q3

namespace q3::exchange {

/// The format `requested` names, or for kQ3ExchangeFormatAny the one the
/// path's extension names; kQ3ErrorInvalidParameter for neither.
TQ3ExchangeFormat formatFor(TQ3ExchangeFormat requested, const std::string& path);

/// Q3Exchange_Write: the scene goes to a temporary file beside `path`,
/// renamed over it once complete (removed on failure).
void writeFile(const Object& object, const std::string& path, TQ3ExchangeFormat format,
               const SubdivisionChoice& subdivision);

/// Q3Exchange_Read.
Ref<DisplayGroup> readFile(const std::string& path, TQ3ExchangeFormat format);

} // namespace q3::exchange
