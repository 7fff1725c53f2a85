// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "core/Limits.h"
#include "geometry/nurbs/Bezier.h"
#include "geometry/nurbs/Curve.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace q3::nurbs {

/// Most segments one tessellation produces, except that a curve always gets at least
/// one segment per non-empty span (so the output never exceeds
/// max(kMaxSegments, number of spans), which is linear in the input size).
constexpr std::size_t kMaxSegments = limits::kMaxSegmentsPerCurve;

/// Most Bezier points (spans * order, 32 bytes each: 8 MB) of a curve whose Bezier form
/// is built whole: the adaptive method converts such a curve once up front instead of
/// once per pass, and a retained curve keeps it between tessellations. Larger curves
/// are converted span by span as they are visited, so memory stays O(order) beyond the
/// curve's own data and the polyline.
constexpr std::size_t kWholeFormLimit = std::size_t{1} << 18;

/// Whether a valid curve's Bezier form fits kWholeFormLimit. O(numPoints).
bool fitsWholeBezierForm(const CurveRef& curve);

/// Most segments per span for the constant method.
constexpr std::uint32_t kMaxSegmentsPerSpan = limits::kMaxConstantSegments;

/// Adaptive method: the share of kMaxSegments the planned count may use; the rest is
/// headroom for the march, which follows the true length where the plan used chord sums
/// (an underestimate).
constexpr std::size_t kPlacementBudget = kMaxSegments - kMaxSegments / 8;

/// Adaptive method: the segment count planned for a run of mapped length L is
/// ceil(kLengthPadding * L / c1); it sizes the budget and the sample tables.
constexpr double kLengthPadding = 1.03;

/// Adaptive method: each segment ends where its mapped length lies in
/// [(1 - kChordTolerance) * c1, c1] (except the last of a run, which is what is left).
constexpr double kChordTolerance = 0.03;

/// Adaptive method: probe samples per span used to estimate mapped length and to find
/// where the mapping fails. Parts of a span where the mapping fails get one segment per
/// probe interval, so at most this many segments per span.
constexpr std::uint32_t probeSegmentsPerSpan(unsigned order)
{
    return order > 8 ? order : 8;
}

/// Adaptive method: most samples in one run's table, and most evaluations spent
/// finding one segment end.
constexpr std::uint32_t kMaxLengthTableSegments = std::uint32_t{1} << 16;
constexpr unsigned kMaxRootIterations = 60;

/// Adaptive method with a ProjectiveMapping: a span with an image everywhere is sampled
/// this many times per planned segment (rounded up to 8, 12, 16, 24, ...), and its
/// vertices are placed by the samples' chord lengths, kArcTarget * maxSegmentLength
/// apart at most; a span that needs more than kMaxDenseSamples samples takes the
/// general march.
constexpr std::uint32_t kDenseSamplesPerSegment = 1;
constexpr double kArcTarget = 0.985;
constexpr std::uint32_t kMaxDenseSamples = 4096;

/// Adaptive method: most gaps (stretches without an image between two mapped samples)
/// the march of one run splits out by finding their edges; past that, a gap costs two
/// unmeasured segments. Each split inserts into the run's sample table, so this bounds
/// that work by kMaxGapsPerRun times the table.
constexpr unsigned kMaxGapsPerRun = 16;

/// Adaptive method: most edge searches (bisections of kMaxRootIterations evaluations
/// at most) one tessellation makes; past that, a probe interval with one mapped end is
/// one unmeasured segment and a gap two, as if no edge were looked for. Bounds the time
/// and the memory of the edges for a curve that crosses the edge of the mapping in
/// every probe interval.
constexpr std::size_t kMaxEdgeSearches = std::size_t{1} << 16;

/// Maps a curve point (the curve's local coordinates) into the space where segment
/// lengths are measured: local-to-world for world space, local-to-pixels including the
/// perspective divide for screen space (set z to 0 there). Returns false when the point
/// has no image, e.g. at or behind the eye; a result that is not finite counts as false.
/// A screen-space mapping should also reject points nearer than the near plane: their
/// images grow without bound, and the length they add would force a coarser c1 on the
/// whole curve.
using PointMapping = std::function<bool(const Point3& local, Point3& mapped)>;

/// A PointMapping that is a projective map followed by a scale and offset per axis: the
/// image of p is scale * (X, Y, Z) / W + offset (an axis with scale 0 is its offset),
/// where (X, Y, Z, W) = matrix * (p, 1) and matrix is given by rows. p has an image
/// when W != 0 (requirePositiveW: W > 0; clipNearer also needs Z <= 0, frustum z above
/// 0 being nearer than the hither plane) and the image is finite. Given this form,
/// the adaptive method maps a span's control points once and, where every control point
/// of a span has W > 0 (and Z < 0 with clipNearer), so that the whole span has an
/// image, samples the mapped span with the fast kernel to find where segments end,
/// instead of mapping every evaluation.
struct ProjectiveMapping {
    double matrix[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    double scale[3] = {1, 1, 1};
    double offset[3] = {0, 0, 0};
    bool requirePositiveW = false;
    bool clipNearer = false;

    bool operator()(const Point3& local, Point3& mapped) const;
};

/// Whether a span certainly cannot be seen, from its rational Bezier control points
/// (homogeneous, weights > 0, in the curve's local coordinates; `order` of them). It
/// must be conservative: true only when no point of the span can be visible, e.g. when
/// every control point lies outside one plane of a view volume (a rational Bezier span
/// with positive weights lies in the convex hull of its control points, and so does
/// every chord between two of its points).
using SpanCulling = std::function<bool(const Point4* points, unsigned order)>;


/// A polyline approximating a curve.
/// Invariant: vertices.size() == 3 * parameters.size(); parameters increase strictly;
/// the first and last parameters are the domain ends (exactly) and their vertices are
/// the curve there; no two consecutive vertices are equal. A curve that is a single
/// point in float gives a single vertex; an invalid curve gives no vertices.
struct TessellatedCurve {
    std::vector<float> vertices;     ///< x, y, z per vertex
    std::vector<double> parameters;  ///< curve parameter t of each vertex
    bool substituted = false;        ///< the requested value was replaced by effectiveValue
    double effectiveValue = 0.0;     ///< segments per span (constant) or maximum length (adaptive) used
    bool capped = false;             ///< adaptive: kMaxSegments (or a mapping too steep to resolve) left segments longer than effectiveValue
    std::size_t unmeasuredSegments = 0; ///< adaptive: segments with an endpoint the mapping rejected
    std::size_t hiddenSpans = 0;        ///< hidden spans culled (one segment each)
    /// Workspace, not output: the constant method's last Bernstein table, kept so that
    /// a caller re-tessellating into the same result (a view, every frame) does not
    /// rebuild it for every curve of the same order and count (its values do not
    /// depend on the curve, so the vertices are the same bits).
    BernsteinTable table;

    std::size_t vertexCount() const { return parameters.size(); }
};

enum class Method {
    kConstant, ///< c1 segments per non-empty span (c2 across for surfaces)
    kAdaptive, ///< no segment (triangle edge) longer than c1, measured after the mapping
};

/// Everything a tessellation depends on besides its source, fixed before it starts
/// (OpenSubdiv's Bfr::Tessellation::Options). The tessellators take it as given:
/// the one place a style's values become options is the view's
/// (view/CurveTessellation.h, measureFor), after checkSubdivisionStyle applied
/// QD3DStyle.h's substitution rule.
struct TessellationOptions {
    Method method = Method::kConstant;
    /// Constant: segments per non-empty span (in u for surfaces), a whole number
    /// from 1 to kMaxSegmentsPerSpan (kMaxConstantSegments); a fraction is
    /// truncated, anything outside is clampedSegments'. Adaptive: the longest a
    /// segment (a triangle edge) may be, measured between the mapped images of its
    /// end points; not > 0 (NaN included) is substituted, +infinity gives one
    /// segment per run.
    double c1 = 1.0;
    /// Surfaces, constant method: segments per span in v, as c1.
    double c2 = 1.0;
    /// Adaptive: the space lengths are measured in.
    ProjectiveMapping mapping;
    /// Adaptive: a general mapping used instead of `mapping` when set (every
    /// evaluation is mapped; tests use it for mappings that are not projective).
    PointMapping customMapping;
    /// Curves: the most segments (at most kMaxSegments; a curve still gets one
    /// segment per non-empty span).
    std::size_t maxSegments = kMaxSegments;
    /// The view volume: local -> homogeneous frustum coordinates, row-major
    /// (x and y within +-w, the hither plane at z = 0), when hasClip.
    bool hasClip = false;
    std::array<double, 16> clip{};
    /// Curves: spans whose control points all lie outside one plane of `clip`
    /// (or the hither plane) cannot be seen and get one segment, from their start
    /// to their end (a chord inside the span's hull, so it cannot be seen either),
    /// at no cost besides their Bezier conversion. Needs hasClip.
    bool cullHiddenSpans = false;
    /// Curves: the same with any predicate (used instead of cullHiddenSpans when set).
    SpanCulling hidden;
    /// Surfaces, adaptive: triangles whose piece of the surface lies outside `clip`
    /// (shown by the convex hull of its Bezier control points) are not held to c1.
    /// Needs hasClip.
    bool coarseOutsideClip = false;
};

/// A constant count as the tessellators use it: truncated, then at least 1 and at
/// most kMaxSegmentsPerSpan (NaN counts as 1).
std::uint32_t clampedSegments(double count);

/// Tessellates a curve, replacing the contents of `out` and reusing its storage (a
/// view re-tessellates into one result every frame). The source is a valid curve (an
/// invalid one, checked with validateCurve, gives an empty result) or its Bezier form.
///
/// Method::kConstant (kQ3SubdivisionMethodConstant): clampedSegments(c1) segments in
/// every non-empty span, at uniform parameters within the span; s spans give
/// c1 * s + 1 vertices before exact duplicates are dropped. The count is lowered so
/// the total stays within maxSegments (never below 1 per span); a count other than c1
/// sets `substituted`. Uses the Bezier sampling kernel.
///
/// Method::kAdaptive (kQ3SubdivisionMethodWorldSpace and ScreenSpace): a polyline
/// whose segments, measured between the mapped images of their end points, are at
/// most c1 long, with close to the fewest segments: every segment but the last of
/// each run of mappable curve is at least (1 - kChordTolerance) * c1. When the
/// planned count (kLengthPadding * length / c1 per run) would exceed the placement
/// budget (7/8 of maxSegments), or c1 is not > 0 (NaN included), a larger length is
/// used and `substituted` set; if one segment per run plus one per unmappable probe
/// interval is already over the budget (always so with that many spans), every span
/// gets one segment and effectiveValue is infinity.
/// Where the mapping fails, segments are not measured: the mapped part is measured up
/// to the edge where its image ends (found by bisection to the last bit of the
/// parameter), then one unmeasured segment per probe interval (probeSegmentsPerSpan)
/// without an image, and two through a gap the march meets between probes; all are
/// counted in unmeasuredSegments. So an unmeasured segment starts or ends at such an
/// edge or at a point without an image: with the near plane as the edge, its part
/// that is drawn has no length.
/// With the ProjectiveMapping (no customMapping), a span with an image everywhere is
/// mapped as a whole and sampled with the kernel, kDenseSamplesPerSegment samples per
/// planned segment; the chords between its samples give its sampled length S, and it
/// gets n = ceil(S / (kArcTarget * c1)) segments of equal sampled length. Every
/// segment is then measured between the images of its end points; if one is longer
/// than c1, the span is marched instead, one vertex at a time, each where the chord
/// reaches (1 - kChordTolerance) to 1 times c1. So none is longer than c1, and a span
/// gets at most S / (kArcTarget * c1) + 1 segments, S being at most its length.
/// For any finite input the output is O(maxSegments + spans * probeSegmentsPerSpan),
/// and the curve is evaluated and mapped O(kMaxRootIterations) times per output vertex,
/// at O(order) per evaluation, plus O(order^2) per span for its Bezier form.
///
/// Hidden spans (cullHiddenSpans, hidden) get one segment each and are counted in
/// hiddenSpans; the adaptive method neither probes nor measures them.
/// Errors: none; substitution and caps are reported in the result for the caller to
/// post (geometry/Decompose.h, postSubdivisionWarning). Ownership: the result owns its
/// arrays; the mappings and the culling are only used during the call, from this
/// thread.
void tessellate(const CurveRef& curve, const TessellationOptions& options, TessellatedCurve& out);
void tessellate(const BezierForm& form, const TessellationOptions& options, TessellatedCurve& out);

} // namespace q3::nurbs
