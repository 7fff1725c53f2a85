// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "core/Limits.h"
#include "geometry/nurbs/Surface.h"
#include "geometry/nurbs/Tessellate.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace q3::nurbs {

/// A patch and its trim loops, as the tessellator takes them (views of the
/// caller's arrays). Every curve and loop must obey the rules
/// validateNURBPatchData checks; whether loops cross is found here.
struct PatchRef {
    SurfaceRef surface;
    std::vector<std::vector<TrimCurveRef>> loops;
};

/// Most triangles one tessellation makes, except that every pair of spans
/// gets at least two (kQ3SubdivisionMaxTrianglesPerPatch).
constexpr std::size_t kMaxTriangles = limits::kMaxTrianglesPerPatch;

/// Adaptive method: vertices along a row (constant v) are at most
/// kAlongRows * maxEdge apart, rows at most kAcrossRows * maxEdge apart
/// (measured along v at the row's vertices). With each row's vertices halfway
/// between the previous row's, the edges between rows are then about
/// sqrt(kAcrossRows^2 + kAlongRows^2 / 4) = 0.89 maxEdge, and stay within it
/// while the two rows' vertices are up to a sixth of a step out of phase
/// (where they are not, the refinement splits what is too long).
constexpr double kAlongRows = 0.95;
constexpr double kAcrossRows = 0.75;

/// Adaptive method: each step of a row or between rows ends where the
/// measured length lies in [(1 - kStepTolerance) * bound, bound].
constexpr double kStepTolerance = 0.03;

/// A tessellated patch: triangles over vertices, each vertex a point of the
/// surface with its unit normal and parameters. Triangles are
/// counterclockwise in (u, v), so their front is the side the normals point
/// to. An invalid patch (or one whose trim loops cross, `crossing`) gives no
/// triangles.
struct TessellatedSurface {
    std::vector<float> positions;  ///< x y z per vertex
    std::vector<float> normals;    ///< unit x y z per vertex
    std::vector<float> uvs;        ///< u v per vertex (float)
    std::vector<double> parameters; ///< u v per vertex, exact
    std::vector<std::uint32_t> triangles; ///< three vertex indices per triangle

    /// The requested value was replaced by effectiveValue to respect
    /// kMaxTriangles (constant: c1 and c2 lowered, reported as their
    /// product; adaptive: a longer c1).
    bool substituted = false;
    double effectiveValue = 0.0;
    /// Constant method: the segments per span used in u and in v.
    std::uint32_t uSegments = 0;
    std::uint32_t vSegments = 0;
    /// Adaptive: some edges are longer than effectiveValue (the triangle cap
    /// was reached while refining, or an edge was too short in (u, v) to
    /// split further).
    bool capped = false;
    /// The trim loops cross or touch (themselves or each other): loops
    /// crossingLoop and crossingOther (equal for a loop with itself), near
    /// (crossingU, crossingV).
    bool crossing = false;
    std::size_t crossingLoop = 0;
    std::size_t crossingOther = 0;
    double crossingU = 0.0;
    double crossingV = 0.0;

    std::size_t vertexCount() const { return positions.size() / 3; }
    std::size_t triangleCount() const { return triangles.size() / 3; }
};

/// Tessellates a valid patch under `options` (Tessellate.h; the surface reads
/// method, c1 and c2, the mapping, and the clip with coarseOutsideClip), replacing
/// the contents of `out` and reusing its storage. See QD3DGeometry.h,
/// "Subdivision", for what each method promises; docs/subdivision.md, "Surfaces",
/// for how. Constant: clampedSegments(c1) segments per span in u and
/// clampedSegments(c2) in v.
/// Work: O(output + trim vertices * log) for typical input; every loop in it
/// is bounded by kMaxTriangles and the input's size, whatever the values.
/// Errors: none; crossing loops and substitutions are reported in the result.
void tessellateSurface(const PatchRef& patch, const TessellationOptions& options, TessellatedSurface& out);

} // namespace q3::nurbs
