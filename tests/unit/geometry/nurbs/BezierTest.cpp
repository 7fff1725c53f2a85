// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/nurbs/Bezier.h"

#include "geometry/nurbs/Evaluate.h"
#include "geometry/nurbs/Tessellate.h"

#include "NurbsTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace q3::nurbs {
namespace {

using test::TestCurve;

TEST(NurbsBezier, BernsteinRowsSumToOneAndEndRowsAreExact)
{
    for (unsigned k = kMinOrder; k <= kMaxOrder; ++k) {
        for (std::uint32_t m : {1u, 2u, 7u, 64u}) {
            const BernsteinTable table(k, m);
            EXPECT_EQ(table.order(), k);
            EXPECT_EQ(table.segments(), m);
            for (std::uint32_t j = 0; j <= m; ++j) {
                double sum = 0.0;
                for (unsigned r = 0; r < k; ++r) {
                    EXPECT_GE(table.weight(j, r), 0.0);
                    sum += table.weight(j, r);
                }
                EXPECT_NEAR(sum, 1.0, 1e-14);
            }
            for (unsigned r = 0; r < k; ++r) {
                EXPECT_EQ(table.weight(0, r), r == 0 ? 1.0 : 0.0);
                EXPECT_EQ(table.weight(m, r), r == k - 1 ? 1.0 : 0.0);
            }
        }
    }
}

TEST(NurbsBezier, BernsteinTableRejectsOutOfRangeOrderAndZeroSegments)
{
    EXPECT_EQ(BernsteinTable(17, 4).order(), 0u);
    EXPECT_EQ(BernsteinTable(1, 4).order(), 0u);
    EXPECT_EQ(BernsteinTable(4, 0).order(), 0u);
    EXPECT_EQ(BernsteinTable(0xFFFFFFFFu, 4).order(), 0u);
}

TEST(NurbsBezier, BernsteinRowMatchesClosedForm)
{
    // B_{r,3}(1/4) for the cubic: 27/64, 27/64, 9/64, 1/64.
    const BernsteinTable table(4, 4);
    EXPECT_DOUBLE_EQ(table.weight(1, 0), 27.0 / 64.0);
    EXPECT_DOUBLE_EQ(table.weight(1, 1), 27.0 / 64.0);
    EXPECT_DOUBLE_EQ(table.weight(1, 2), 9.0 / 64.0);
    EXPECT_DOUBLE_EQ(table.weight(1, 3), 1.0 / 64.0);
}

TEST(NurbsBezier, BezierCurveConvertsToItsOwnControlPoints)
{
    const TestCurve curve = test::listingOneCurve();
    Point4 out[4];
    spanToBezier(curve.ref(), 3, out);
    for (int r = 0; r < 4; ++r) {
        EXPECT_DOUBLE_EQ(out[r].x, curve.points[4 * r]);
        EXPECT_DOUBLE_EQ(out[r].y, curve.points[4 * r + 1]);
        EXPECT_DOUBLE_EQ(out[r].w, 1.0);
    }
}

TEST(NurbsBezier, UniformQuadraticSpanHasMidpointBezierPoints)
{
    // Uniform quadratic B-spline: the Bezier points of a span are the midpoint of the
    // first two control points, the middle control point, the midpoint of the last two.
    const TestCurve curve = test::makeCurve(3, {0, 0, 0, 1, 2, 4, 0, 1, 6, 0, 0, 1}, {0, 1, 2, 3, 4, 5});
    Point4 out[3];
    spanToBezier(curve.ref(), 2, out);
    EXPECT_DOUBLE_EQ(out[0].x, 1.0);
    EXPECT_DOUBLE_EQ(out[0].y, 2.0);
    EXPECT_DOUBLE_EQ(out[1].x, 2.0);
    EXPECT_DOUBLE_EQ(out[1].y, 4.0);
    EXPECT_DOUBLE_EQ(out[2].x, 4.0);
    EXPECT_DOUBLE_EQ(out[2].y, 2.0);
}

TEST(NurbsBezier, EvaluateBezierIsExactAtEnds)
{
    const Point4 points[3] = {{1, 2, 3, 0.5}, {4, 5, 6, 2}, {7, 8, 9, 3}};
    const Point4 start = evaluateBezier(points, 3, 0.0);
    const Point4 end = evaluateBezier(points, 3, 1.0);
    EXPECT_EQ(start.x, 1.0);
    EXPECT_EQ(start.w, 0.5);
    EXPECT_EQ(end.y, 8.0);
    EXPECT_EQ(end.w, 3.0);
    const Point4 mid = evaluateBezier(points, 3, 0.5);
    EXPECT_DOUBLE_EQ(mid.x, 0.25 * 1 + 0.5 * 4 + 0.25 * 7);
    EXPECT_DOUBLE_EQ(mid.w, 0.25 * 0.5 + 0.5 * 2 + 0.25 * 3);
}

TEST(NurbsBezier, FormAgreesWithDeBoorForEveryOrder)
{
    // Tolerance: both paths are convex combinations of the same float inputs in double,
    // so they may differ by a few hundred ulps of the curve's size at order 16.
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 450; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, trial % 3 == 0 ? 0.5 : 0.1, 12});
        const CurveRef ref = curve.ref();
        const double tolerance = 1e-12 * test::curveScale(curve);
        const BezierForm form(ref);
        ASSERT_FALSE(form.empty());
        ASSERT_EQ(form.spanCount(), countNonEmptySpans(ref));
        EXPECT_EQ(form.domain().start, curve.domainStart());
        EXPECT_EQ(form.domain().end, curve.domainEnd());
        for (int s = 0; s <= 40; ++s) {
            const double t = s == 40 ? curve.domainEnd()
                                     : curve.domainStart() + (curve.domainEnd() - curve.domainStart()) * unit(rng);
            const Point3 byDeBoor = evaluate(ref, t).point;
            EXPECT_LE(test::distance3(form.evaluate(t), byDeBoor), tolerance) << "order " << k << " t " << t;
            EXPECT_LE(test::distance3(form.evaluate(t), test::referencePoint3(curve, t)), tolerance);
        }
        // The table kernel at its uniform samples.
        const std::uint32_t m = 5;
        const BernsteinTable table(k, m);
        std::vector<double> xyz(3 * (m + 1));
        std::vector<float> xyzFloat(3 * (m + 1));
        for (std::size_t sIndex = 0; sIndex < form.spanCount(); ++sIndex) {
            const Span& span = form.span(sIndex);
            form.sampleSpan(sIndex, table, 0, m + 1, xyz.data());
            form.sampleSpan(sIndex, table, 0, m + 1, xyzFloat.data());
            for (std::uint32_t j = 0; j <= m; ++j) {
                const double t = span.start + (span.end - span.start) * (double(j) / m);
                const Point3 expected = evaluate(ref, j == m ? span.end : t).point;
                const Point3 sampled{xyz[3 * j], xyz[3 * j + 1], xyz[3 * j + 2]};
                EXPECT_LE(test::distance3(sampled, expected), tolerance) << "order " << k;
                for (int c = 0; c < 3; ++c) {
                    EXPECT_EQ(xyzFloat[3 * j + c], float(xyz[3 * j + c]));
                }
            }
        }
    }
}

// Restores the kernels' instruction set when a test that forces one ends.
class KernelIsaScope {
public:
    KernelIsaScope() : m_saved(activeKernelIsa()) {}
    ~KernelIsaScope() { forceKernelIsa(m_saved); }
    KernelIsaScope(const KernelIsaScope&) = delete;
    KernelIsaScope& operator=(const KernelIsaScope&) = delete;

private:
    KernelIsa m_saved;
};

// Everything the two hot loops produce for one curve: its Bezier form and samples of
// every span over sample ranges that exercise each step width and tail of the kernel.
struct KernelOutput {
    std::vector<double> form;
    std::vector<float> samplesFloat;
    std::vector<double> samplesDouble;
};

KernelOutput runKernels(const CurveRef& ref)
{
    KernelOutput result;
    const BezierForm form(ref);
    for (std::size_t s = 0; s < form.spanCount(); ++s) {
        for (unsigned r = 0; r < form.order(); ++r) {
            const Point4& p = form.spanPoints(s)[r];
            result.form.insert(result.form.end(), {p.x, p.y, p.z, p.w});
        }
    }
    // The sweep from a later span (its first call converts from scratch).
    if (form.spanCount() > 1) {
        BezierSweep sweep(ref);
        Point4 out[kMaxOrder];
        sweep.convert(form.span(1).knotIndex, out);
        for (unsigned r = 0; r < form.order(); ++r) {
            result.form.insert(result.form.end(), {out[r].x, out[r].y, out[r].z, out[r].w});
        }
    }
    for (const std::uint32_t m : {1u, 2u, 3u, 5u, 7u, 8u, 9u, 12u, 17u, 64u}) {
        const BernsteinTable table(form.order(), m);
        for (std::uint32_t first = 0; first <= std::min<std::uint32_t>(m, 3); ++first) {
            const std::uint32_t count = m + 1 - first;
            std::vector<float> f(3 * count);
            std::vector<double> d(3 * count);
            for (std::size_t s = 0; s < form.spanCount(); ++s) {
                form.sampleSpan(s, table, first, count, f.data());
                form.sampleSpan(s, table, first, count, d.data());
                result.samplesFloat.insert(result.samplesFloat.end(), f.begin(), f.end());
                result.samplesDouble.insert(result.samplesDouble.end(), d.begin(), d.end());
            }
        }
    }
    return result;
}

template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(NurbsBezier, Avx2KernelsGiveTheBaselineBitsForEveryOrder)
{
    // The AVX2 paths promise identical results, so renderings (and goldens) do not
    // depend on the machine. Compared bit for bit, not within a tolerance.
    if (supportedKernelIsa() != KernelIsa::kAvx2) {
        GTEST_SKIP() << "this CPU has no AVX2; only the baseline kernels run here";
    }
    KernelIsaScope scope;
    std::mt19937 rng(2024);
    for (int trial = 0; trial < 120; ++trial) {
        const unsigned k = 2 + trial % 15;
        const TestCurve curve = test::randomCurve(rng, k, {trial % 2 == 0, trial % 3 == 0 ? 0.5 : 0.1, 12});
        ASSERT_TRUE(forceKernelIsa(KernelIsa::kBaseline));
        const KernelOutput baseline = runKernels(curve.ref());
        TessellationOptions thirteen;
        thirteen.c1 = 13;
        TessellatedCurve baselineCurve;
        tessellate(curve.ref(), thirteen, baselineCurve);
        ASSERT_TRUE(forceKernelIsa(KernelIsa::kAvx2));
        EXPECT_EQ(activeKernelIsa(), KernelIsa::kAvx2);
        const KernelOutput avx2 = runKernels(curve.ref());
        TessellatedCurve avx2Curve;
        tessellate(curve.ref(), thirteen, avx2Curve);
        ASSERT_FALSE(baseline.form.empty());
        EXPECT_TRUE(sameBits(baseline.form, avx2.form)) << "order " << k << ", trial " << trial;
        EXPECT_TRUE(sameBits(baseline.samplesFloat, avx2.samplesFloat)) << "order " << k;
        EXPECT_TRUE(sameBits(baseline.samplesDouble, avx2.samplesDouble)) << "order " << k;
        EXPECT_TRUE(sameBits(baselineCurve.vertices, avx2Curve.vertices)) << "order " << k;
    }
}

TEST(NurbsBezier, ForcingAnUnsupportedKernelIsaChangesNothing)
{
    KernelIsaScope scope;
    ASSERT_TRUE(forceKernelIsa(KernelIsa::kBaseline));
    EXPECT_EQ(activeKernelIsa(), KernelIsa::kBaseline);
    const bool haveAvx2 = supportedKernelIsa() == KernelIsa::kAvx2;
    EXPECT_EQ(forceKernelIsa(KernelIsa::kAvx2), haveAvx2);
    EXPECT_EQ(activeKernelIsa(), haveAvx2 ? KernelIsa::kAvx2 : KernelIsa::kBaseline);
}

TEST(NurbsBezier, SampleRangeWritesOnlyRequestedSamples)
{
    const TestCurve curve = test::listingOneCurve();
    const BezierForm form(curve.ref());
    const BernsteinTable table(4, 4);
    std::vector<double> all(15);
    form.sampleSpan(0, table, 0, 5, all.data());
    std::vector<double> part(7, -1.0);
    form.sampleSpan(0, table, 2, 2, part.data());
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(part[i], all[6 + i]);
    }
    EXPECT_EQ(part[6], -1.0);
    EXPECT_DOUBLE_EQ(all[6], 1.5);
    EXPECT_DOUBLE_EQ(all[7], 0.5);
}

TEST(NurbsBezier, InvalidCurveGivesEmptyForm)
{
    TestCurve curve = test::listingOneCurve();
    curve.points[3] = 0.0f;
    const BezierForm form(curve.ref());
    EXPECT_TRUE(form.empty());
    EXPECT_EQ(form.spanCount(), 0u);
    EXPECT_EQ(form.evaluateHomogeneous(0.5).w, 0.0);
    EXPECT_EQ(BezierForm().spanCount(), 0u);
}

TEST(NurbsBezier, RebuildFollowsAnEditedCurve)
{
    TestCurve curve = test::listingOneCurve();
    BezierForm form(curve.ref());
    EXPECT_DOUBLE_EQ(form.evaluate(0.5).y, 0.5);
    curve.points[4 * 1 + 1] = 3.0f;  // P1.y from 1 to 3: Q(0.5).y gains 3/8 * 2
    form.rebuild(curve.ref());
    EXPECT_DOUBLE_EQ(form.evaluate(0.5).y, 0.5 + 0.75);
    curve.knots = {0, 0, 0, 1, 2, 3, 3, 3};
    curve.order = 3;
    curve.points.insert(curve.points.end(), {4, 0, 0, 1});
    form.rebuild(curve.ref());
    EXPECT_EQ(form.order(), 3u);
    EXPECT_EQ(form.spanCount(), 3u);
    EXPECT_LE(test::distance3(form.evaluate(1.7), evaluate(curve.ref(), 1.7).point), 1e-14);
}

} // namespace
} // namespace q3::nurbs
