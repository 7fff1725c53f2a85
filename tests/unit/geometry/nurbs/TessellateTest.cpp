// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/nurbs/Tessellate.h"

#include "geometry/nurbs/Evaluate.h"

#include "NurbsTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace q3::nurbs {
namespace {

using test::TestCurve;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Vertices are floats: each coordinate carries a rounding error of at most 2^-24 of
// the curve's size, so 1e-6 of the size is a safe bound for "on the curve".
constexpr double kOnCurveTolerance = 1e-6;

// The constant method with c1 = segmentsPerSpan over `base` (its culling and cap).
template <typename Source>
TessellatedCurve constantOf(const Source& source, double segmentsPerSpan, const TessellationOptions& base = {})
{
    TessellationOptions options = base;
    options.method = Method::kConstant;
    options.c1 = segmentsPerSpan;
    TessellatedCurve out;
    tessellate(source, options, out);
    return out;
}

// The adaptive method with c1 = maxSegmentLength, measured through a general mapping.
template <typename Source>
TessellatedCurve adaptiveOf(const Source& source, double maxSegmentLength, const PointMapping& mapping,
                          const TessellationOptions& base = {})
{
    TessellationOptions options = base;
    options.method = Method::kAdaptive;
    options.c1 = maxSegmentLength;
    options.customMapping = mapping;
    TessellatedCurve out;
    tessellate(source, options, out);
    return out;
}

// The same through a ProjectiveMapping (the fast path), into `out`.
template <typename Source>
void adaptiveOf(const Source& source, double maxSegmentLength, const ProjectiveMapping& mapping, TessellatedCurve& out)
{
    TessellationOptions options;
    options.method = Method::kAdaptive;
    options.c1 = maxSegmentLength;
    options.mapping = mapping;
    tessellate(source, options, out);
}

std::size_t segmentCount(const TessellatedCurve& result)
{
    return result.vertexCount() == 0 ? 0 : result.vertexCount() - 1;
}

Point3 vertex(const TessellatedCurve& result, std::size_t i)
{
    return Point3{result.vertices[3 * i], result.vertices[3 * i + 1], result.vertices[3 * i + 2]};
}

// The guarantees every tessellation gives: exact end parameters, increasing
// parameters, no repeated consecutive vertex, every vertex on the curve.
// Vertices are checked against the reference evaluator every `stride` vertices.
void expectPolylineInvariants(const TestCurve& curve, const TessellatedCurve& result, std::size_t stride = 1)
{
    ASSERT_GE(result.vertexCount(), 1u);
    ASSERT_EQ(result.vertices.size(), 3 * result.parameters.size());
    EXPECT_EQ(result.parameters.front(), curve.domainStart());
    if (result.vertexCount() > 1) {
        EXPECT_EQ(result.parameters.back(), curve.domainEnd());
    }
    const double tolerance = kOnCurveTolerance * test::curveScale(curve);
    for (std::size_t i = 0; i < result.vertexCount(); ++i) {
        if (i > 0) {
            ASSERT_LT(result.parameters[i - 1], result.parameters[i]) << i;
            const bool same = result.vertices[3 * i] == result.vertices[3 * i - 3] &&
                              result.vertices[3 * i + 1] == result.vertices[3 * i - 2] &&
                              result.vertices[3 * i + 2] == result.vertices[3 * i - 1];
            ASSERT_FALSE(same) << "repeated vertex " << i;
        }
        if (i % stride == 0 || i + 1 == result.vertexCount()) {
            ASSERT_LE(test::distance3(vertex(result, i), test::referencePoint3(curve, result.parameters[i])),
                      tolerance)
                << "vertex " << i << " t " << result.parameters[i];
        }
    }
}

// A random affine map: non-uniform scale, then a rotation, then a translation.
struct AffineMap {
    double m[3][3];
    double offset[3];

    bool operator()(const Point3& p, Point3& q) const
    {
        q.x = m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + offset[0];
        q.y = m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + offset[1];
        q.z = m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + offset[2];
        return true;
    }
};

AffineMap randomAffine(std::mt19937& rng)
{
    std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
    std::uniform_real_distribution<double> scale(0.5, 3.0);
    std::uniform_real_distribution<double> shift(-50.0, 50.0);
    const double a = angle(rng);
    const double b = angle(rng);
    const double s[3] = {scale(rng), scale(rng), scale(rng)};
    // Rotation about z by a, then about x by b.
    const double rz[3][3] = {{std::cos(a), -std::sin(a), 0}, {std::sin(a), std::cos(a), 0}, {0, 0, 1}};
    const double rx[3][3] = {{1, 0, 0}, {0, std::cos(b), -std::sin(b)}, {0, std::sin(b), std::cos(b)}};
    AffineMap map{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double sum = 0.0;
            for (int l = 0; l < 3; ++l) {
                sum += rx[i][l] * rz[l][j];
            }
            map.m[i][j] = sum * s[j];
        }
        map.offset[i] = shift(rng);
    }
    return map;
}

// Perspective projection to pixels for an eye at (0, 0, eyeZ) looking down +z; points
// closer than `nearDepth` have no image.
struct PerspectiveMap {
    double eyeZ;
    double nearDepth;
    double focal = 500.0;

    bool operator()(const Point3& p, Point3& q) const
    {
        const double depth = p.z - eyeZ;
        if (!(depth >= nearDepth)) {
            return false;
        }
        q = Point3{320.0 + focal * p.x / depth, 240.0 - focal * p.y / depth, 0.0};
        return true;
    }
};

// Mapped length of the curve from many samples per span (a lower bound of the true length).
double mappedLength(const TestCurve& curve, const PointMapping& mapping, int samplesPerSpan)
{
    double total = 0.0;
    for (const Span& span : nonEmptySpans(curve.ref())) {
        Point3 previous;
        mapping(evaluate(curve.ref(), span.start).point, previous);
        for (int i = 1; i <= samplesPerSpan; ++i) {
            const double t = i == samplesPerSpan ? span.end
                                                 : span.start + (span.end - span.start) * i / samplesPerSpan;
            Point3 q;
            mapping(evaluate(curve.ref(), t).point, q);
            total += test::distance3(previous, q);
            previous = q;
        }
    }
    return total;
}

// Longest chord between mapped end points, evaluating the curve at each vertex's
// parameter with the reference evaluator (or, for very long polylines, with de Boor,
// which the evaluation tests check against the reference); chords with an unmappable
// end are skipped.
double longestMappedChord(const TestCurve& curve, const TessellatedCurve& result, const PointMapping& mapping,
                          bool useReference = true)
{
    const auto at = [&](double t) {
        return useReference ? test::referencePoint3(curve, t) : evaluate(curve.ref(), t).point;
    };
    double longest = 0.0;
    for (std::size_t i = 1; i < result.vertexCount(); ++i) {
        Point3 a;
        Point3 b;
        if (mapping(at(result.parameters[i - 1]), a) && mapping(at(result.parameters[i]), b)) {
            longest = std::max(longest, test::distance3(a, b));
        }
    }
    return longest;
}

// A long order-k curve with n points on a wiggly path and clamped knots; interior knot
// values step by one every `multiplicity` knots.
TestCurve longCurve(unsigned k, std::size_t n, std::size_t multiplicity = 1)
{
    TestCurve curve;
    curve.order = k;
    curve.points.reserve(4 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const double t = double(i);
        curve.points.insert(curve.points.end(),
                            {float(t), float(std::sin(0.7 * t) * 3.0), float(std::cos(0.3 * t)), 1.0f});
    }
    curve.knots.reserve(n + k);
    for (std::size_t i = 0; i < n + k; ++i) {
        const std::size_t clamped = std::min(std::max(i, std::size_t(k - 1)), n);
        const std::size_t step = (clamped - (k - 1) + multiplicity - 1) / multiplicity;
        curve.knots.push_back(float(clamped == n ? (n - (k - 1) + multiplicity - 1) / multiplicity : step));
    }
    return curve;
}

TEST(NurbsTessellate, ConstantGivesMSegmentsPerSpanOnRandomCurves)
{
    std::mt19937 rng(1);
    for (int trial = 0; trial < 300; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, trial % 4 == 0 ? 0.5 : 0.0, 12});
        const std::uint32_t m = 1 + std::uint32_t(trial % 9);
        const TessellatedCurve result = constantOf(curve.ref(), m);
        const std::vector<Span> spans = nonEmptySpans(curve.ref());
        EXPECT_FALSE(result.substituted);
        EXPECT_EQ(result.effectiveValue, double(m));
        ASSERT_EQ(result.vertexCount(), m * spans.size() + 1) << "order " << k;
        expectPolylineInvariants(curve, result);
        // Uniform in each span; the span's end vertex appears once, as the next span's start.
        for (std::size_t s = 0; s < spans.size(); ++s) {
            for (std::uint32_t j = 0; j < m; ++j) {
                const double expected = spans[s].start + (spans[s].end - spans[s].start) * j / m;
                EXPECT_NEAR(result.parameters[s * m + j], expected, 1e-14 * (1.0 + std::fabs(expected)));
            }
        }
    }
}

TEST(NurbsTessellate, ConstantFromCachedFormMatchesConstantFromCurve)
{
    std::mt19937 rng(2);
    for (int trial = 0; trial < 40; ++trial) {
        const TestCurve curve = test::randomCurve(rng, 2 + trial % 15, {});
        const TessellatedCurve direct = constantOf(curve.ref(), 6);
        const TessellatedCurve cached = constantOf(BezierForm(curve.ref()), 6);
        EXPECT_EQ(direct.vertices, cached.vertices);
        EXPECT_EQ(direct.parameters, cached.parameters);
    }
}

TEST(NurbsTessellate, ConstantListingOneWithFiveSegments)
{
    // The article's subdivision example: c1 = 5 on the single-span Bezier curve.
    const TestCurve curve = test::listingOneCurve();
    const TessellatedCurve result = constantOf(curve.ref(), 5);
    ASSERT_EQ(result.vertexCount(), 6u);
    EXPECT_EQ(result.parameters[0], 0.0);
    EXPECT_EQ(result.parameters[5], 1.0);
    EXPECT_FLOAT_EQ(result.vertices[0], 0.0f);
    EXPECT_FLOAT_EQ(result.vertices[15], 3.0f);
    EXPECT_FLOAT_EQ(result.vertices[16], 1.0f);
    expectPolylineInvariants(curve, result);
}

TEST(NurbsTessellate, ConstantDropsRepeatedVertices)
{
    // Order 2 through A, A, B: the first span is a single point.
    const TestCurve curve = test::makeCurve(2, {1, 2, 3, 1, 1, 2, 3, 1, 4, 2, 3, 1}, {0, 0, 1, 2, 2});
    const TessellatedCurve result = constantOf(curve.ref(), 3);
    ASSERT_EQ(result.vertexCount(), 4u);  // A, then three points up to B
    EXPECT_EQ(result.parameters.front(), 0.0);
    EXPECT_EQ(result.parameters.back(), 2.0);
    expectPolylineInvariants(curve, result);
}

TEST(NurbsTessellate, PointCurveGivesSingleVertex)
{
    const TestCurve curve = test::makeCurve(3, {2, 2, 2, 2, 1, 1, 1, 1, 3, 3, 3, 3}, {0, 0, 0, 1, 1, 1});
    const TessellatedCurve constant = constantOf(curve.ref(), 10);
    ASSERT_EQ(constant.vertexCount(), 1u);
    EXPECT_EQ(constant.parameters[0], 0.0);
    EXPECT_EQ(constant.vertices[0], 1.0f);
    const TessellatedCurve adaptive = adaptiveOf(curve.ref(), 0.01, AffineMap{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}});
    EXPECT_EQ(adaptive.vertexCount(), 1u);
}

TEST(NurbsTessellate, ConstantReplacesZeroByOne)
{
    const TestCurve curve = test::listingOneCurve();
    const TessellatedCurve result = constantOf(curve.ref(), 0);
    EXPECT_TRUE(result.substituted);
    EXPECT_EQ(result.effectiveValue, 1.0);
    EXPECT_EQ(result.vertexCount(), 2u);
}

TEST(NurbsTessellate, ConstantCapsSegmentsPerSpan)
{
    const TestCurve curve = test::makeCurve(3, {0, 0, 0, 1, 1, 1, 0, 1, 2, 0, 0, 1, 3, 1, 0, 1, 4, 0, 0, 1},
                                            {0, 0, 0, 1, 2, 3, 3, 3});
    for (std::uint32_t requested : {kMaxSegmentsPerSpan + 1, 100000u, 0xFFFFFFFFu}) {
        const TessellatedCurve result = constantOf(curve.ref(), requested);
        EXPECT_TRUE(result.substituted);
        EXPECT_EQ(result.effectiveValue, double(kMaxSegmentsPerSpan));
        EXPECT_EQ(result.vertexCount(), 3 * kMaxSegmentsPerSpan + 1);
    }
    const TessellatedCurve exact = constantOf(curve.ref(), kMaxSegmentsPerSpan);
    EXPECT_FALSE(exact.substituted);
}

TEST(NurbsTessellate, ConstantCapsTotalSegments)
{
    const TestCurve curve = longCurve(4, 5003);  // 5000 spans
    const TessellatedCurve result = constantOf(curve.ref(), 1000);
    EXPECT_TRUE(result.substituted);
    const std::uint32_t expected = std::uint32_t(kMaxSegments / 5000);
    EXPECT_EQ(result.effectiveValue, double(expected));
    EXPECT_EQ(result.vertexCount(), 5000u * expected + 1);
    EXPECT_LE(segmentCount(result), kMaxSegments);
    EXPECT_EQ(result.parameters.back(), curve.domainEnd());
}

TEST(NurbsTessellate, HugeOrderSixteenCurveStaysBounded)
{
    // A million points of order 16: more spans than kMaxSegments allows segments, so both
    // methods fall back to one segment per span (the documented floor).
    const TestCurve curve = longCurve(16, 1000000);
    const std::size_t spans = 1000000 - 15;
    const TessellatedCurve constant = constantOf(curve.ref(), 4);
    EXPECT_TRUE(constant.substituted);
    EXPECT_EQ(constant.effectiveValue, 1.0);
    EXPECT_EQ(constant.vertexCount(), spans + 1);
    EXPECT_EQ(constant.parameters.back(), curve.domainEnd());

    const double size = curve.domainEnd();
    const TessellatedCurve adaptive =
        adaptiveOf(curve.ref(), size * 1e-6, AffineMap{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}});
    EXPECT_TRUE(adaptive.substituted);
    EXPECT_LE(segmentCount(adaptive), std::max(kMaxSegments, spans));
    EXPECT_EQ(adaptive.parameters.front(), curve.domainStart());
    EXPECT_EQ(adaptive.parameters.back(), curve.domainEnd());
    // Spot-check vertices against de Boor.
    for (std::size_t i = 0; i < adaptive.vertexCount(); i += 99991) {
        const Point3 expected = evaluate(curve.ref(), adaptive.parameters[i]).point;
        EXPECT_LE(test::distance3(vertex(adaptive, i), expected), 1e-6 * size);
    }
}

TEST(NurbsTessellate, HugeCurveWithTinyLengthPlansWithinBudget)
{
    // A million order-16 points with triple interior knots: about 333 000 spans, under the
    // placement budget, so the length is measured, substituted and marched span by span.
    const TestCurve curve = longCurve(16, 1000000, 3);
    ASSERT_TRUE(validateCurve(curve.ref()).ok());
    const std::size_t spans = countNonEmptySpans(curve.ref());
    ASSERT_LT(spans, kPlacementBudget);
    const PointMapping mapping = AffineMap{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}};
    const double c1 = 1e-6 * 1e6;  // the curve is about a million units long
    const TessellatedCurve result = adaptiveOf(curve.ref(), c1, mapping);
    EXPECT_TRUE(result.substituted);
    EXPECT_GT(result.effectiveValue, c1);
    EXPECT_LE(segmentCount(result), kMaxSegments);
    EXPECT_GT(segmentCount(result), spans);
    EXPECT_EQ(result.parameters.front(), curve.domainStart());
    EXPECT_EQ(result.parameters.back(), curve.domainEnd());
    double longest = 0.0;
    for (std::size_t i = 1; i < result.vertexCount(); ++i) {
        longest = std::max(longest, test::distance3(vertex(result, i - 1), vertex(result, i)));
    }
    // Float vertices of coordinates up to 1e6 carry rounding of about 0.06.
    EXPECT_LE(longest, result.effectiveValue + 0.2);
}

TEST(NurbsTessellate, WorldSpaceChordsAreShortAndFewOnRandomCurves)
{
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> divisions(3.0, 300.0);
    double worstRatio = 0.0;
    for (int trial = 0; trial < 300; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, trial % 3 == 0 ? 0.5 : 0.0, 12});
        const AffineMap affine = randomAffine(rng);
        const PointMapping mapping = affine;
        const double length = mappedLength(curve, mapping, 400);
        const double c1 = length / divisions(rng);
        const TessellatedCurve result = adaptiveOf(curve.ref(), c1, mapping);
        EXPECT_FALSE(result.substituted);
        EXPECT_FALSE(result.capped);
        EXPECT_EQ(result.effectiveValue, c1);
        EXPECT_EQ(result.unmeasuredSegments, 0u);
        expectPolylineInvariants(curve, result);
        EXPECT_LE(longestMappedChord(curve, result, mapping), c1 * (1.0 + 1e-9)) << "order " << k;
        const std::size_t spans = countNonEmptySpans(curve.ref());
        EXPECT_LE(double(segmentCount(result)), 1.2 * length / c1 + double(spans)) << "order " << k;
        worstRatio = std::max(worstRatio, (double(segmentCount(result)) - double(spans)) / (length / c1));
    }
    RecordProperty("worstSegmentRatio", std::to_string(worstRatio));
}

TEST(NurbsTessellate, ScreenSpaceChordsAreShortAndFewUnderPerspective)
{
    std::mt19937 rng(6);
    std::uniform_real_distribution<double> pixels(2.0, 40.0);
    for (int trial = 0; trial < 200; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.2, 12});
        const PointMapping mapping = PerspectiveMap{-25.0, 1.0};
        const double c1 = pixels(rng);
        const TessellatedCurve result = adaptiveOf(curve.ref(), c1, mapping);
        EXPECT_FALSE(result.substituted);
        EXPECT_EQ(result.unmeasuredSegments, 0u);
        expectPolylineInvariants(curve, result);
        EXPECT_LE(longestMappedChord(curve, result, mapping), c1 * (1.0 + 1e-9));
        const double length = mappedLength(curve, mapping, 400);
        EXPECT_LE(double(segmentCount(result)), 1.2 * length / c1 + double(countNonEmptySpans(curve.ref())));
    }
}

TEST(NurbsTessellate, AdaptiveFromCachedFormMatchesAdaptiveFromCurve)
{
    std::mt19937 rng(12);
    const PointMapping mapping = PerspectiveMap{-25.0, 1.0};
    for (int trial = 0; trial < 30; ++trial) {
        const TestCurve curve = test::randomCurve(rng, 2 + trial % 15, {});
        const TessellatedCurve direct = adaptiveOf(curve.ref(), 3.0, mapping);
        const TessellatedCurve cached = adaptiveOf(BezierForm(curve.ref()), 3.0, mapping);
        EXPECT_EQ(direct.vertices, cached.vertices);
        EXPECT_EQ(direct.parameters, cached.parameters);
    }
}

TEST(NurbsTessellate, AdaptiveStreamingMatchesCachedFormOnLongCurve)
{
    // 20000 order-16 spans exceed the size converted up front, so the CurveRef path
    // converts span by span; it must give the same polyline as the cached form.
    const TestCurve curve = longCurve(16, 20015);
    const PointMapping mapping = AffineMap{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}};
    const TessellatedCurve streamed = adaptiveOf(curve.ref(), 0.3, mapping);
    const TessellatedCurve cached = adaptiveOf(BezierForm(curve.ref()), 0.3, mapping);
    EXPECT_FALSE(streamed.substituted);
    EXPECT_EQ(streamed.parameters, cached.parameters);
    EXPECT_EQ(streamed.vertices, cached.vertices);
}

TEST(NurbsTessellate, PartlyBehindEyeCurveTerminatesAndMeasuresVisibleChords)
{
    // The eye sits inside the curves' bounding box, so parts of every curve are behind it.
    std::mt19937 rng(9);
    std::size_t unmeasured = 0;
    for (int trial = 0; trial < 100; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.2, 12});
        const PointMapping mapping = PerspectiveMap{0.0, 0.1};
        const double c1 = 8.0;
        const TessellatedCurve result = adaptiveOf(curve.ref(), c1, mapping);
        expectPolylineInvariants(curve, result);
        EXPECT_LE(segmentCount(result), kMaxSegments);
        if (!result.capped) {
            EXPECT_LE(longestMappedChord(curve, result, mapping), result.effectiveValue * (1.0 + 1e-9));
        }
        unmeasured += result.unmeasuredSegments;
    }
    EXPECT_GT(unmeasured, 0u);
}

// PerspectiveMap{eyeZ, nearDepth} as a ProjectiveMapping: W is the depth, X and Y
// are focal times x and -y, and Z = nearDepth - depth must not be positive.
ProjectiveMapping projectiveOf(const PerspectiveMap& map)
{
    ProjectiveMapping projective;
    const double rows[4][4] = {{map.focal, 0, 0, 0},
                               {0, -map.focal, 0, 0},
                               {0, 0, -1, map.nearDepth + map.eyeZ},
                               {0, 0, 1, -map.eyeZ}};
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            projective.matrix[r][c] = rows[r][c];
        }
    }
    projective.scale[2] = 0.0;
    projective.offset[0] = 320.0;
    projective.offset[1] = 240.0;
    projective.requirePositiveW = true;
    projective.clipNearer = true;
    return projective;
}

// The ProjectiveMapping path (the mapped span sampled densely, vertices chosen among
// the samples) against the test's own perspective map and reference evaluator: random
// rational curves of every order (weights 0.25..4, so the image's speed varies
// sharply), c1 from 1 to 40 pixels and once 0.2 (so that long spans may need more
// than kMaxDenseSamples samples and take the general march), and eyes inside the curves' box (spans crossing the near plane take
// the general march too).
TEST(NurbsTessellate, ProjectiveMappingKeepsEveryChordWithinC1)
{
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> logPixels(std::log(1.0), std::log(40.0));
    std::size_t unmeasured = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, 0.2, 12});
        const bool eyeInside = trial % 5 == 4;
        const PerspectiveMap perspective = eyeInside ? PerspectiveMap{0.0, 0.1} : PerspectiveMap{-25.0, 1.0};
        const PointMapping mapping = perspective;
        const double c1 = trial == 0 ? 0.2 : std::exp(logPixels(rng));
        TessellatedCurve result;
        adaptiveOf(curve.ref(), c1, projectiveOf(perspective), result);
        expectPolylineInvariants(curve, result, 7);
        if (!result.capped) {
            EXPECT_LE(longestMappedChord(curve, result, mapping), result.effectiveValue * (1.0 + 1e-9))
                << "trial " << trial << " order " << k << " c1 " << c1;
        }
        unmeasured += result.unmeasuredSegments;
        if (!eyeInside) {
            EXPECT_FALSE(result.substituted);
            EXPECT_FALSE(result.capped);
            EXPECT_EQ(result.unmeasuredSegments, 0u);
            const double length = mappedLength(curve, mapping, 100);
            EXPECT_LE(double(segmentCount(result)), 1.2 * length / c1 + double(countNonEmptySpans(curve.ref())))
                << "trial " << trial << " order " << k << " c1 " << c1;
        }
    }
    EXPECT_GT(unmeasured, 0u);
}

// A rational cubic whose middle weights pull it into a hairpin much narrower than its
// probes' spacing: the dense samples near the turn are farther apart than c1, so the
// march searches between them; every chord stays within c1.
TEST(NurbsTessellate, ProjectiveMappingSearchesWhereDenseSamplesAreFartherThanC1)
{
    const TestCurve curve = test::makeCurve(4, {-5, 0, 0, 1, 4000, 1, 0, 400, -4000, -1, 0, 400, 5, 0.02f, 0, 1},
                                            {0, 0, 0, 0, 1, 1, 1, 1});
    const PerspectiveMap perspective{-25.0, 1.0};
    const PointMapping mapping = perspective;
    for (const double c1 : {0.5, 2.0, 7.0}) {
        TessellatedCurve result;
        adaptiveOf(curve.ref(), c1, projectiveOf(perspective), result);
        expectPolylineInvariants(curve, result);
        EXPECT_FALSE(result.capped);
        EXPECT_LE(longestMappedChord(curve, result, mapping), c1 * (1.0 + 1e-9)) << c1;
    }
}

TEST(NurbsTessellate, UnmappableCurveGetsProbeSegmentsPerSpan)
{
    const TestCurve curve = test::listingOneCurve();
    const PointMapping never = [](const Point3&, Point3&) { return false; };
    const TessellatedCurve result = adaptiveOf(curve.ref(), 0.001, never);
    EXPECT_EQ(segmentCount(result), probeSegmentsPerSpan(4));
    EXPECT_EQ(result.unmeasuredSegments, probeSegmentsPerSpan(4));
    EXPECT_FALSE(result.substituted);
    expectPolylineInvariants(curve, result);
}

// A mapping that has no image right of x = edge: the curve is measured up to the
// edge (a vertex within a few ulps of it), and beyond only unmeasured segments start.
TEST(NurbsTessellate, ACrossingProbeIntervalIsMeasuredUpToTheEdge)
{
    const TestCurve curve = test::listingOneCurve();
    const double edge = 1.3;  // inside a probe interval of the single span
    const PointMapping leftOnly = [edge](const Point3& p, Point3& q) {
        q = p;
        return p.x <= edge;
    };
    const double c1 = 0.05;
    const TessellatedCurve result = adaptiveOf(curve.ref(), c1, leftOnly);
    expectPolylineInvariants(curve, result);
    const std::vector<float>& v = result.vertices;
    bool edgeFound = false;
    for (std::size_t i = 0; i < result.vertexCount(); ++i) {
        edgeFound = edgeFound || std::fabs(v[3 * i] - edge) < 1e-6;
        if (i > 0 && v[3 * i] <= edge && v[3 * i - 3] <= edge) {
            const double dx = v[3 * i] - v[3 * i - 3], dy = v[3 * i + 1] - v[3 * i - 2];
            EXPECT_LE(std::hypot(dx, dy), c1 + 1e-6) << "segment " << i;
        }
    }
    EXPECT_TRUE(edgeFound);
    EXPECT_GT(result.unmeasuredSegments, 0u);
}

// A zigzag that crosses the edge of the mapping once in every span, with more
// spans than kMaxEdgeSearches: the first kMaxEdgeSearches crossings get their
// edge, the rest are unmeasured probe intervals, and the work stays bounded.
TEST(NurbsTessellate, EdgeSearchesStopAtTheirBudget)
{
    const std::size_t spans = kMaxEdgeSearches + 3000;
    TestCurve zigzag;
    zigzag.order = 2;
    for (std::size_t i = 0; i <= spans; ++i)
        zigzag.points.insert(zigzag.points.end(), {float(i % 2), float(i) * 0.25f, 0.0f, 1.0f});
    zigzag.knots.push_back(0.0f);
    for (std::size_t i = 0; i <= spans; ++i)
        zigzag.knots.push_back(float(i));
    zigzag.knots.push_back(float(spans));
    const double edge = 0.55;  // inside a probe interval of every span
    const PointMapping leftOnly = [edge](const Point3& p, Point3& q) {
        q = p;
        return p.x <= edge;
    };
    const TessellatedCurve result = adaptiveOf(zigzag.ref(), 10.0, leftOnly);
    ASSERT_GT(result.vertexCount(), spans);
    std::size_t edges = 0;
    for (std::size_t i = 0; i < result.vertexCount(); ++i)
        edges += std::fabs(result.vertices[3 * i] - edge) < 1e-6 ? 1 : 0;
    EXPECT_EQ(edges, kMaxEdgeSearches);
    EXPECT_FALSE(result.capped);
}

TEST(NurbsTessellate, NonFiniteMappedPointCountsAsUnmappable)
{
    const TestCurve curve = test::listingOneCurve();
    const PointMapping nan = [](const Point3& p, Point3& q) {
        q = Point3{p.x, p.x > 1.0 ? std::numeric_limits<double>::quiet_NaN() : p.y, 0.0};
        return true;
    };
    const TessellatedCurve result = adaptiveOf(curve.ref(), 0.05, nan);
    expectPolylineInvariants(curve, result);
    EXPECT_GT(result.unmeasuredSegments, 0u);
    EXPECT_LE(segmentCount(result), 200u);
}

TEST(NurbsTessellate, TinyLengthIsSubstitutedAndBounded)
{
    const TestCurve curve = longCurve(4, 40);
    const PointMapping mapping = AffineMap{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}};
    const double length = mappedLength(curve, mapping, 200);
    const double c1 = length * 1e-6 / 1e3;
    const TessellatedCurve result = adaptiveOf(curve.ref(), c1, mapping);
    EXPECT_TRUE(result.substituted);
    EXPECT_GT(result.effectiveValue, c1);
    EXPECT_LE(segmentCount(result), kMaxSegments);
    EXPECT_GE(segmentCount(result), kPlacementBudget / 2);
    EXPECT_FALSE(result.capped);
    expectPolylineInvariants(curve, result, 97);
    EXPECT_LE(longestMappedChord(curve, result, mapping, false), result.effectiveValue * (1.0 + 1e-9));
}

TEST(NurbsTessellate, NonPositiveOrNaNLengthIsSubstituted)
{
    const TestCurve curve = test::listingOneCurve();
    const PointMapping mapping = AffineMap{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}};
    for (double c1 : {0.0, -1.0, -kInf, std::numeric_limits<double>::quiet_NaN()}) {
        const TessellatedCurve result = adaptiveOf(curve.ref(), c1, mapping);
        EXPECT_TRUE(result.substituted) << c1;
        EXPECT_GT(result.effectiveValue, 0.0);
        EXPECT_LE(segmentCount(result), kMaxSegments);
        EXPECT_EQ(result.parameters.back(), 1.0);
    }
}

TEST(NurbsTessellate, InfiniteLengthGivesOneSegmentPerSpan)
{
    const TestCurve curve = longCurve(3, 12);
    const PointMapping mapping = AffineMap{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}};
    const TessellatedCurve result = adaptiveOf(curve.ref(), kInf, mapping);
    EXPECT_FALSE(result.substituted);
    EXPECT_EQ(segmentCount(result), countNonEmptySpans(curve.ref()));
    expectPolylineInvariants(curve, result);
}

TEST(NurbsTessellate, InvalidCurveGivesEmptyResult)
{
    TestCurve curve = test::listingOneCurve();
    curve.knots[2] = 5.0f;
    const PointMapping mapping = AffineMap{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}};
    EXPECT_EQ(constantOf(curve.ref(), 4).vertexCount(), 0u);
    EXPECT_EQ(adaptiveOf(curve.ref(), 0.1, mapping).vertexCount(), 0u);
    EXPECT_EQ(constantOf(BezierForm(curve.ref()), 4).vertexCount(), 0u);
}

} // namespace
} // namespace q3::nurbs

namespace q3::nurbs {
namespace {

// TessellationOptions::hidden: a span it rejects gets exactly one segment, from its start to
// its end, under both methods; the others are subdivided as without it. The predicate
// here hides spans by index (every third), counted as the tessellator asks.
TEST(NurbsTessellate, HiddenSpansGetOneSegmentUnderBothMethods)
{
    std::mt19937 rng(16);
    for (int trial = 0; trial < 60; ++trial) {
        const TestCurve curve = test::randomCurve(rng, 2 + trial % 9, {});
        const std::vector<Span> spans = nonEmptySpans(curve.ref());
        const BezierForm form(curve.ref());
        TessellationOptions limits;
        limits.hidden = [&form](const Point4* points, unsigned) {
            for (std::size_t s = 0; s < form.spanCount(); ++s)
                if (form.spanPoints(s) == points)
                    return s % 3 == 1;
            return false;
        };
        const std::size_t hiddenCount = (spans.size() + 1) / 3; // s = 1, 4, 7, ...
        const TessellatedCurve constant = constantOf(form, 8, limits);
        EXPECT_EQ(constant.hiddenSpans, hiddenCount);
        ASSERT_EQ(constant.vertexCount(), 8 * (spans.size() - hiddenCount) + hiddenCount + 1);
        expectPolylineInvariants(curve, constant);
        // A hidden span's start is followed by its end.
        std::size_t i = 0;
        for (std::size_t s = 0; s < spans.size(); ++s) {
            EXPECT_EQ(constant.parameters[i], spans[s].start);
            i += s % 3 == 1 ? 1 : 8;
        }
        const PointMapping identity = [](const Point3& p, Point3& out) {
            out = p;
            return true;
        };
        const double c1 = test::curveScale(curve) / 50;
        const TessellatedCurve adaptive = adaptiveOf(form, c1, identity, limits);
        EXPECT_EQ(adaptive.hiddenSpans, hiddenCount);
        EXPECT_FALSE(adaptive.substituted);
        expectPolylineInvariants(curve, adaptive);
        // Only segments inside a hidden span may be longer than c1.
        for (std::size_t v = 1; v < adaptive.vertexCount(); ++v) {
            const double length = test::distance3(vertex(adaptive, v - 1), vertex(adaptive, v));
            std::size_t s = 0;
            while (s + 1 < spans.size() && adaptive.parameters[v - 1] >= spans[s].end)
                ++s;
            if (s % 3 == 1) {
                EXPECT_EQ(adaptive.parameters[v - 1], spans[s].start);
                EXPECT_EQ(adaptive.parameters[v], spans[s].end);
            } else {
                EXPECT_LE(length, c1 * (1 + 1e-6)) << "segment " << v - 1;
            }
        }
    }
}

// TessellationOptions::maxSegments replaces kMaxSegments: a c1 that would need more gets a
// longer length (substituted), and the count stays within the cap.
TEST(NurbsTessellate, MaxSegmentsFromTheViewBoundsTheAdaptiveCount)
{
    const TestCurve curve = test::listingOneCurve();
    const PointMapping identity = [](const Point3& p, Point3& out) {
        out = p;
        return true;
    };
    TessellationOptions limits;
    limits.maxSegments = 4096;
    const TessellatedCurve capped = adaptiveOf(curve.ref(), 1e-6, identity, limits);
    EXPECT_TRUE(capped.substituted);
    EXPECT_GT(capped.effectiveValue, 1e-6);
    EXPECT_LE(segmentCount(capped), 4096u);
    EXPECT_GT(segmentCount(capped), 2048u);
    const TessellatedCurve fine = adaptiveOf(curve.ref(), 0.01, identity, limits);
    EXPECT_FALSE(fine.substituted);
    EXPECT_EQ(fine.effectiveValue, 0.01);
}

} // namespace
} // namespace q3::nurbs

namespace q3::nurbs {
namespace {

// A constant count as the tessellators use it: truncated, then 1 to
// kMaxSegmentsPerSpan, NaN and -infinity as 1.
TEST(NurbsTessellate, ClampedSegmentsTruncatesAndBounds)
{
    EXPECT_EQ(clampedSegments(0.0), 1u);
    EXPECT_EQ(clampedSegments(-3.0), 1u);
    EXPECT_EQ(clampedSegments(std::nan("")), 1u);
    EXPECT_EQ(clampedSegments(-kInf), 1u);
    EXPECT_EQ(clampedSegments(1.0), 1u);
    EXPECT_EQ(clampedSegments(2.99), 2u);
    EXPECT_EQ(clampedSegments(double(kMaxSegmentsPerSpan)), kMaxSegmentsPerSpan);
    EXPECT_EQ(clampedSegments(double(kMaxSegmentsPerSpan) + 0.5), kMaxSegmentsPerSpan);
    EXPECT_EQ(clampedSegments(kInf), kMaxSegmentsPerSpan);
}

// cullHiddenSpans with a clip matrix: a span is hidden exactly when all its
// Bezier control points lie outside one of the planes x = +-w, y = +-w or
// z = 0 (z > 0 outside) after the matrix, as computed here from the form.
TEST(NurbsTessellate, ClipCullsSpansWhoseControlPointsAreAllOutsideOnePlane)
{
    std::mt19937 rng(30);
    std::size_t culled = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const TestCurve curve = test::randomCurve(rng, 2 + trial % 7, {});
        const BezierForm form(curve.ref());
        // Scale so that the view volume (|x|, |y| <= w) holds part of the curve,
        // and push z behind the hither plane except for some trials.
        const double k = 1.0 / (0.5 * test::curveScale(curve));
        TessellationOptions options;
        options.c1 = 6;
        options.hasClip = true;
        options.cullHiddenSpans = true;
        options.clip = {k, 0, 0, 0.3, 0, k, 0, -0.2, 0, 0, trial % 3 == 0 ? 1.0 : 0.0, -1.0, 0, 0, 0, 1};
        std::size_t expected = 0;
        for (std::size_t s = 0; s < form.spanCount(); ++s) {
            unsigned outside[5] = {0, 0, 0, 0, 0};
            for (unsigned i = 0; i < form.order(); ++i) {
                const Point4& p = form.spanPoints(s)[i];
                const double x = k * p.x + 0.3 * p.w, y = k * p.y - 0.2 * p.w;
                const double z = (trial % 3 == 0 ? p.z : 0.0) - p.w, w = p.w;
                outside[0] += x > w;
                outside[1] += -x > w;
                outside[2] += y > w;
                outside[3] += -y > w;
                outside[4] += z > 0.0;
            }
            bool hidden = false;
            for (unsigned count : outside)
                hidden = hidden || count == form.order();
            expected += hidden ? 1 : 0;
        }
        culled += expected;
        TessellatedCurve fromCurve, fromForm;
        tessellate(curve.ref(), options, fromCurve);
        tessellate(form, options, fromForm);
        EXPECT_EQ(fromCurve.hiddenSpans, expected) << "trial " << trial;
        EXPECT_EQ(fromForm.hiddenSpans, expected);
        const std::size_t spans = form.spanCount();
        EXPECT_EQ(fromCurve.vertexCount(), 6 * (spans - expected) + expected + 1);
        expectPolylineInvariants(curve, fromCurve);
        // Without hasClip nothing is culled.
        options.hasClip = false;
        tessellate(curve.ref(), options, fromCurve);
        EXPECT_EQ(fromCurve.hiddenSpans, 0u);
    }
    EXPECT_GT(culled, 0u); // the trials do cull
}

} // namespace
} // namespace q3::nurbs
