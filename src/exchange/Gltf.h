// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "exchange/Scene.h"

#include <string>

namespace q3::exchange {

/// Writes the scene as glTF 2.0 through tinygltf: a .glb (binary, textures
/// as PNG in its buffer) when `binary`, else a .gltf with the buffer
/// embedded as a data URI. Throws kQ3ErrorFileNotOpen when the file cannot
/// be written.
void writeGltf(const Scene& scene, const std::string& path, bool binary);

/// Reads a .gltf or .glb file (the form is found from its first bytes).
/// Throws kQ3ErrorFileNotOpen when the file cannot be read,
/// kQ3ErrorInvalidData (with tinygltf's message) when it is not valid glTF
/// 2.0, kQ3ErrorUnsupportedFunctionality for what Q3 cannot represent (a
/// required extension it does not know).
Scene readGltf(const std::string& path);

} // namespace q3::exchange
