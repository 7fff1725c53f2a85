// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DStyle.h"
#include "exchange/Scene.h"
#include "view/CurveTessellation.h"

#include <optional>

namespace q3 {
class Object;
}

namespace q3::exchange {

/// How surfaces and curves are subdivided for export: a method and its
/// values as TQ3SubdivisionStyleData has them (world space: the longest
/// side in world units; constant: segments), or, with `fromBounds`, world
/// space at 1/32 of the model's bounding box diagonal.
struct SubdivisionChoice {
    bool fromBounds = true;
    TQ3SubdivisionStyleData style{kQ3SubdivisionMethodWorldSpace, 1.0f, 1.0f};
    /// A view's camera and pane: screen-space lengths are measured there.
    std::optional<Window> window;
};

/// The scene `root` draws: a geometry, a display group, any shape, or a plain
/// group (or light group) whose objects are taken in order, cameras and
/// lights among them. Every geometry is decomposed as a view draws it
/// (Geometry::decompose under the traversal's state), with the subdivision
/// chosen here in place of every subdivision style. Throws q3::Error.
Scene sceneFrom(const Object& root, const SubdivisionChoice& subdivision);

} // namespace q3::exchange
