// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "exchange/Scene.h"

#include <string>

namespace q3::exchange {

/// Writes the scene as Wavefront OBJ (with its MTL file and the textures as
/// PNG files beside it: <stem>_<n>.png) or binary STL through Assimp. Both
/// formats are flat: every mesh instance is written with its node's matrix
/// applied. STL keeps triangles only. `directory` is where the files go,
/// `stem` the output's name without its extension. Throws
/// kQ3ErrorFileNotOpen when Assimp cannot write.
void writeObj(const Scene& scene, const std::string& directory, const std::string& stem);
void writeStl(const Scene& scene, const std::string& path);

/// Reads an OBJ (its MTL files and PNG textures must exist beside it) or
/// STL file through Assimp. Throws kQ3ErrorFileNotOpen for a file that
/// cannot be opened, kQ3ErrorInvalidData (Assimp's message) for one it
/// cannot read, or an OBJ whose material file or texture is missing.
Scene readWithAssimp(const std::string& path);

} // namespace q3::exchange
