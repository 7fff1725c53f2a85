// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Triangles for the patches of Shapes.h, and a polyline for the ellipse, under
// QuickDraw 3D's subdivision methods. Plain values in and out: a mapping into
// the space lengths are measured in, no view, no error manager.
//
// The constant method divides each patch direction by its ConstantRule (c1
// segments per full turn of u, c2 over the whole v range, one segment across
// a flat part), rows at uniform parameters, each quad split along its
// shorter diagonal.
//
// World and screen space ("measured") guarantee that every triangle edge's
// drawn length is at most c1: the distance between the mapped images of its
// ends; for an edge with one end without an image (nearer than the hither
// plane), the length of its part that has one (found by bisection: the
// points with an image form a half-space); nothing for an edge with neither.
// Each patch is built in rows along u at fixed v:
//   1. rows at v values marched so that the drawn distance between
//      consecutive rows, probed at kProbes + 1 values of u, is close to
//      kRowSpacing c1 (kDerivedRowSpacing c1 for derived rows), with at
//      least one segment per quarter turn where v is an angle;
//   2. each row's points by one of three strategies, the patch built with
//      each that applies and the one with fewer triangles kept:
//        uniform  points at uniform u, as few as keep every chord at most
//                 kRowChord c1, alternate rows offset by half a step so
//                 that the triangles between them are close to equilateral;
//        derived  each row from its neighbour, from the longest row out:
//                 the neighbour's midpoints (the stagger) with a segment
//                 split where its chord is too long (or, kRowAverage, where
//                 the row's chords would average too long) and a point
//                 dropped where two chords together are short (kRowDrop);
//                 best where rows grow fast along v (disks, tori);
//        aligned  for a disk-like patch closing a curved edge (a cap, a
//                 torus's cross-section: collapsed at v0, its v1 row given
//                 by the patch it closes): every row on the rays of the
//                 given row (every other ray once the row has shrunk
//                 enough), so rows nest and no triangle folds however the
//                 view squeezes the given row;
//      at least one segment per quarter turn of u;
//   3. consecutive rows stitched in parameter order, with the shorter
//      drawn diagonal where the next points of the two rows are within
//      0.35 of a segment of each other, and never a triangle that faces
//      against the surface's normal where the other choice does not;
//   4. every edge of a stitched strip measured: a strip with one longer than
//      c1 gets a row halfway between its rows and is stitched again, up to
//      kMaxRefinement times (the guarantee holds by this check, not by the
//      estimates of 1 and 2; `unresolved` counts strips left as they are).
// Patches linked to earlier ones (Shapes.h, Link) take their rows from them,
// so shared curved edges have the same vertices.
//
// Both methods keep the triangle count at most `maxTriangles`: the constant
// counts are scaled down, the measured method's c1 scaled up (first from an
// estimate of the drawn area, then doubled while an attempt runs over, at
// most kMaxDoublings times before the coarsest is taken); then
// `reduced` is set and `effectiveC1` / `effectiveC2` say what was used, as
// curves do with their segment cap. A cap below the coarsest tessellation
// (one segment per quarter turn, the constant minimums) gives the coarsest.

#include "core/Limits.h"
#include "geometry/quadric/Shapes.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace q3::quadric {

/// Maps a local point into the space lengths are measured in (world units,
/// or pane pixels with z 0). Returns false where the point has no image; a
/// result that is not finite counts as none.
using Mapping = std::function<bool(const Vec3& local, Vec3& mapped)>;

enum class Method { kConstant, kMeasured };

struct Subdivision {
    Method method = Method::kConstant;
    /// Constant: segment counts per unit of span (whole numbers >= 1).
    /// Measured: c1 is the longest drawn edge (> 0); c2 is not used.
    double c1 = 1.0;
    double c2 = 1.0;
    Mapping map; ///< measured only
    std::size_t maxTriangles = limits::kMaxTrianglesPerSurface;
};

/// Measured method: the target drawn distance between rows and the longest
/// chord along a row, as fractions of c1. With rows staggered by half a
/// step, a triangle between them has sides of about
/// sqrt(kRowSpacing^2 + (kRowChord / 2)^2) c1 < c1. Rows derived from their
/// neighbour have shorter chords on average (new points halve a chord), so
/// they stand further apart. (Tuned on disks, tori, spheres and cones: the
/// triangle counts the tests report.)
constexpr double kRowSpacing = 0.8;
constexpr double kDerivedRowSpacing = 0.9;
constexpr double kRowChord = 0.95;
/// Measured method: the average chord a row derived from its neighbour aims
/// at, and the longest two neighbouring chords may be together before the
/// point between them is dropped (fractions of kRowChord c1).
constexpr double kRowAverage = 0.92;
constexpr double kRowDrop = 0.8;
/// Probes across a row (for the row spacing and a row's first estimate).
constexpr int kProbes = 24;
/// How many times a strip may be halved before it is taken as it is.
constexpr int kMaxRefinement = 24;
/// How many times the measured method doubles c1 after an attempt runs over
/// maxTriangles before it takes the coarsest tessellation. An attempt that
/// runs over has built a whole cap's triangles first (about 0.4 s at
/// kQ3SubdivisionMaxTrianglesPerSurface in a Release build), so the
/// retries are few: a surface costs at most kMaxDoublings + 1 of them.
constexpr int kMaxDoublings = 2;

struct Tessellation {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals; ///< unit, outward
    std::vector<Vec2> uvs;
    std::vector<int> parts;               ///< each vertex's patch part
    std::vector<std::uint32_t> triangles; ///< counterclockwise seen from outside
    bool reduced = false;                 ///< maxTriangles forced a coarser subdivision
    double effectiveC1 = 0.0;             ///< the c1 used (counts for constant, a length for measured)
    double effectiveC2 = 0.0;             ///< constant only
    std::size_t unresolved = 0;           ///< measured: strips left with a long edge after kMaxRefinement halvings
    int overruns = 0;                     ///< attempts that ran over maxTriangles before this one

    std::size_t triangleCount() const { return triangles.size() / 3; }
};

/// The triangles of `patches` (in their order, linked patches after the ones
/// they link to).
/// Errors: none. Ownership: the mapping is used during the call only.
Tessellation tessellate(const Patches& patches, const Subdivision& subdivision);

struct Polyline {
    std::vector<Vec3> points;
    bool reduced = false;
    double effective = 0.0; ///< segments per turn (constant) or the longest drawn segment (measured)
};

/// A polyline along curve(t), t from t0 to t1 (turns; `closed` for a full
/// turn): constant, ceil(c1 (t1 - t0)) segments at uniform t (at least 3 for
/// a full turn); measured, segments of drawn length at most c1 and at least
/// (1 - kCurveTolerance) c1 but the last, marched along probes of 1/256 of
/// the range. At most maxSegments segments (then `reduced`).
constexpr double kCurveTolerance = 0.02;
Polyline tessellateCurve(const std::function<Vec3(double)>& curve, double t0, double t1, bool closed,
                         const Subdivision& subdivision, std::size_t maxSegments);

} // namespace q3::quadric
