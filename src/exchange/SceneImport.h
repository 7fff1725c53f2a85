// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "core/Ref.h"
#include "exchange/Scene.h"

namespace q3 {
class DisplayGroup;
}

namespace q3::exchange {

/// Q3 objects for a scene, as a legacy program expects them: a display
/// group per node holding a matrix transform (when the node has one), its
/// mesh's geometries and its children's groups, in that order. Triangles
/// become a TriMesh with its vertex attribute arrays (diffuse colour,
/// transparency colour, normal, surface uv) and an attribute set holding
/// the material (diffuse, specular, specular control, transparency colours
/// and a texture shader with a mipmap texture as its surface shader); line
/// strips and segments become PolyLines, points Points. A mesh used by several nodes is
/// one set of geometries shared by their groups. An illumination shader
/// (Phong, Lambert or NULL, from the first material) opens the root group.
/// Throws kQ3ErrorInvalidData for a node cycle or a reference to nothing.
Ref<DisplayGroup> groupFrom(const Scene& scene);

} // namespace q3::exchange
