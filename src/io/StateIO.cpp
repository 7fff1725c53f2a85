// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Styles, illumination shaders, lights and transforms (3D Metafile
// Reference, "Style objects", "Shader objects", "Light objects",
// "Transform objects").

#include "io/ClassIO.h"

namespace q3::io {

void addStateClasses(std::vector<ClassIO>&) {}

} // namespace q3::io
