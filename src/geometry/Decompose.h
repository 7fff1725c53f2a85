// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// What a geometry needs from the traversal it is drawn or bounded in to
// decompose itself: the subdivision under the current style and transforms.
// The view implements it (view/Pass.h); geometries only see this interface,
// which keeps them below the view in the layering.

#include "QD3DStyle.h"
#include "geometry/nurbs/Curve.h"
#include "geometry/nurbs/Tessellate.h"

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace q3 {

struct CurveCache;

/// Receives a polyline: vertexCount vertices, x y z each, in the curve's
/// local coordinates.
using PolylineUser = std::function<void(const float* xyz, std::size_t vertexCount)>;

/// How a surface is subdivided under the current style (QD3DStyle.h): the
/// method and its values, and for world and screen space the map from the
/// geometry's local coordinates to the space lengths are measured in (world
/// units, or pane pixels after the perspective divide); the map returns false
/// for a point with no image there (behind the eye, nearer than hither).
/// `key` holds every value the subdivision depends on, for caches.
struct SubdivisionMeasure {
    TQ3SubdivisionMethod method = kQ3SubdivisionMethodConstant;
    double c1 = 0.0;
    double c2 = 0.0;
    nurbs::PointMapping map;
    /// Screen space with a window: local -> frustum coordinates, row-major
    /// (nurbs::SurfaceHull), so that parts outside the view volume can be
    /// left coarse. Its values are in `key` already (as the map's).
    bool hasClip = false;
    std::array<double, 16> clip{};
    std::vector<double> key;
};

class DecomposeContext {
public:
    virtual ~DecomposeContext() = default;

    /// Subdivides a valid NURB curve under the current style and hands the
    /// polyline to `use` (view/CurveTessellation.h says how); `cache` is a
    /// retained curve's own (which counts the subdivisions), or null.
    virtual void curvePolyline(const nurbs::CurveRef& curve, CurveCache* cache,
                               const PolylineUser& use) const = 0;

    /// The current subdivision, for geometries that tessellate surfaces.
    virtual SubdivisionMeasure subdivisionMeasure() const = 0;
};

} // namespace q3
