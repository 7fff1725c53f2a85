// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// What a geometry needs from the traversal it is drawn or bounded in to
// decompose itself: the subdivision under the current style and transforms.
// The view implements it (view/Pass.h); geometries only see this interface,
// which keeps them below the view in the layering.

#include "QD3DStyle.h"
#include "geometry/nurbs/Tessellate.h"

#include <string>
#include <vector>

namespace q3 {

/// How a shape is subdivided under the current style (QD3DStyle.h): the
/// style's method (for messages) and the tessellation options it resolved to
/// (nurbs::TessellationOptions: c1 and c2 as checkSubdivisionStyle left them,
/// constant values truncated; for world and screen space the map from the
/// geometry's local coordinates to the space lengths are measured in, world
/// units or pane pixels after the perspective divide; the view's limits).
struct SubdivisionMeasure {
    TQ3SubdivisionMethod method = kQ3SubdivisionMethodConstant;
    nurbs::TessellationOptions options;
    /// Where a curve is tessellated into: a buffer the view owns, so that a
    /// frame of retained curves allocates nothing once it has grown to the
    /// largest curve; null outside a view (the caller uses its own). Whoever
    /// tessellates into it uses the polyline before the next tessellation.
    nurbs::TessellatedCurve* curveScratch = nullptr;

    /// Every value a tessellation under this measure depends on, for caches.
    /// The mapping's offset (the pane's origin) is left out on purpose: moving
    /// the pane does not change any length.
    std::vector<double> key() const;
};

/// What a tessellation gave in to, for postSubdivisionWarning.
struct SubdivisionShortfall {
    /// The shape, as the message names it ("a NURB curve", "an ellipse").
    std::string shape;
    /// The cap that was reached, e.g. "kQ3SubdivisionMaxSegmentsPerCurve (1048576) segments".
    std::string limit;
    /// What was used instead, e.g. "4 segments per span are used".
    std::string used;
    /// Whether c2 is part of the request (constant surfaces).
    bool withC2 = false;
};

/// The one place the subdivision warning is worded: "<method> subdivision of
/// <shape> with c1 = ... [and c2 = ...] would need more than <limit>;
/// <used>". A shape that caches its tessellation keeps the text to post it
/// again whenever the cached result is drawn.
std::string subdivisionWarning(const SubdivisionMeasure& measure, const SubdivisionShortfall& shortfall);

/// Posts subdivisionWarning's text as kQ3WarningParameterOutOfRange.
void postSubdivisionWarning(const SubdivisionMeasure& measure, const SubdivisionShortfall& shortfall);

class DecomposeContext {
public:
    virtual ~DecomposeContext() = default;

    /// The current subdivision, for every geometry that subdivides (curves,
    /// ellipses, patches, quadrics).
    virtual SubdivisionMeasure subdivisionMeasure() const = 0;
};

} // namespace q3
