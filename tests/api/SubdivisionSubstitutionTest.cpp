// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The article's promise that an unreasonable subdivision value is replaced by
// a reasonable one with a warning ("CONTROLLING SUBDIVISION"), followed from
// the call that receives it to the polyline drawn: every case of QD3DStyle.h's
// substitution rule, in c1 and in c2, through Q3SubdivisionStyle_Submit,
// Q3SubdivisionStyle_New and Q3SubdivisionStyle_SetData, must post
// kQ3WarningParameterOutOfRange exactly once for the call, put the substituted
// value in the view's state, and draw and decompose the curve with that value.
// A c1 that is a reasonable number but would need more segments than
// kQ3SubdivisionMaxSegmentsPerCurve warns where the curve is drawn, and the
// output stays within the cap. No times are asserted: each case must finish,
// with the counts given.

#include "RenderTestSupport.h"
#include "ReferenceNurbs.h"

#include "QD3DStyle.h"

#include <cfloat>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace q3test;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kDefault = kQ3SubdivisionDefaultC1;
constexpr double kRounding = 5e-5;

/// How the style reaches the view.
enum class Path { kSubmit, kNew, kSetData };

const char* nameOf(Path path)
{
    return path == Path::kSubmit ? "Q3SubdivisionStyle_Submit"
                                 : path == Path::kNew ? "Q3SubdivisionStyle_New" : "Q3SubdivisionStyle_SetData";
}

/// An unreasonable value for one method and what QD3DStyle.h replaces it by.
struct Case {
    TQ3SubdivisionMethod method;
    float value;
    float replacement;
};

std::vector<Case> unreasonableValues()
{
    std::vector<Case> cases;
    const float big = float(kQ3SubdivisionMaxConstantSegments);
    for (const float v : {kNaN, -kNaN, kInf, -kInf})
        for (TQ3SubdivisionMethod m :
             {kQ3SubdivisionMethodConstant, kQ3SubdivisionMethodWorldSpace, kQ3SubdivisionMethodScreenSpace})
            cases.push_back({m, v, kDefault});
    for (const float v : {0.0f, -0.0f, 0.999f, std::numeric_limits<float>::denorm_min(), -3.0f, -FLT_MAX})
        cases.push_back({kQ3SubdivisionMethodConstant, v, 1.0f});
    for (const float v : {1024.5f, 1025.0f, 1e6f, FLT_MAX})
        cases.push_back({kQ3SubdivisionMethodConstant, v, big});
    for (const float v : {0.0f, -0.0f, -FLT_MIN, -1.0f, -FLT_MAX})
        for (TQ3SubdivisionMethod m : {kQ3SubdivisionMethodWorldSpace, kQ3SubdivisionMethodScreenSpace})
            cases.push_back({m, v, kDefault});
    // Positive but finer than the pane is sampled: the screen-space floor.
    for (const float v : {std::numeric_limits<float>::denorm_min(), FLT_MIN, 1e-6f, 0.01f, 0.1249f})
        cases.push_back({kQ3SubdivisionMethodScreenSpace, v, kQ3SubdivisionMinScreenSpaceC1});
    return cases;
}

/// A value each method accepts as it is.
float reasonable(TQ3SubdivisionMethod method)
{
    return method == kQ3SubdivisionMethodConstant ? 3.0f
           : method == kQ3SubdivisionMethodWorldSpace ? 0.75f : 12.0f;
}

/// An order-3 curve of four spans inside the rendering tests' orthographic
/// view (x -0.5..3.5, y -1..2), one point weighted.
struct FourSpans {
    TQ3RationalPoint4D points[6] = {{0, 0, 0, 1},     {0.5f, 1, 0, 1}, {2.4f, -1, 0, 2},
                                    {2, 1.5f, 0, 1},  {2.8f, 0, 0, 1}, {3.2f, 1, 0, 1}};
    float knots[9] = {0, 0, 0, 1, 2, 3, 4, 4, 4};
    static constexpr unsigned long kSpans = 4;

    TQ3NURBCurveData data() { return {3, 6, points, knots, nullptr}; }
};

class SubdivisionSubstitutionTest : public Q3ApiTest {
protected:
    void SetUp() override
    {
        Q3ApiTest::SetUp();
        m_view = std::make_unique<TestView>(m_image.pixmap());
        const TQ3NURBCurveData data = m_curveData.data();
        m_curve = Q3NURBCurve_New(&data);
        ASSERT_NE(m_curve, nullptr);
    }
    void TearDown() override
    {
        Q3Object_Dispose(m_curve);
        m_view.reset();
        Q3ApiTest::TearDown();
    }

    TQ3ViewObject view() const { return m_view->view(); }

    /// The decomposed polyline's vertices, in the current state of the view.
    std::vector<Point3> decompose(TQ3GeometryObject curve)
    {
        std::vector<Point3> out;
        TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(curve, view());
        EXPECT_NE(polyLine, nullptr);
        if (polyLine == nullptr)
            return out;
        TQ3PolyLineData data{};
        EXPECT_EQ(Q3PolyLine_GetData(polyLine, &data), kQ3Success);
        for (unsigned long i = 0; i < data.numVertices; ++i)
            out.push_back({data.vertices[i].point.x, data.vertices[i].point.y, data.vertices[i].point.z});
        Q3PolyLine_EmptyData(&data);
        Q3Object_Dispose(polyLine);
        return out;
    }

    /// Puts `requested` into the view by `path` inside a rendering loop,
    /// expecting exactly one warning from the call that receives it; then
    /// checks the state, decomposes and draws the curve (retained and
    /// immediate). Returns the decomposed vertices.
    std::vector<Point3> renderWith(const TQ3SubdivisionStyleData& requested, Path path,
                                   const TQ3SubdivisionStyleData& expected, const std::string& what)
    {
        TQ3StyleObject style = nullptr;
        if (path == Path::kNew) {
            EXPECT_Q3_WARNING(style = Q3SubdivisionStyle_New(&requested), kQ3WarningParameterOutOfRange);
        } else if (path == Path::kSetData) {
            const TQ3SubdivisionStyleData good = {requested.method, reasonable(requested.method),
                                                  reasonable(requested.method)};
            style = Q3SubdivisionStyle_New(&good);
            EXPECT_Q3_WARNING(EXPECT_EQ(Q3SubdivisionStyle_SetData(style, &requested), kQ3Success),
                              kQ3WarningParameterOutOfRange);
        }
        if (path != Path::kSubmit) {
            EXPECT_NE(style, nullptr) << what;
            TQ3SubdivisionStyleData stored{};
            EXPECT_EQ(Q3SubdivisionStyle_GetData(style, &stored), kQ3Success);
            expectSame(stored, expected, what + " (GetData)");
        }
        std::vector<Point3> vertices;
        EXPECT_EQ(Q3View_StartRendering(view()), kQ3Success);
        if (path == Path::kSubmit)
            EXPECT_Q3_WARNING(EXPECT_EQ(Q3SubdivisionStyle_Submit(&requested, view()), kQ3Success),
                              kQ3WarningParameterOutOfRange);
        else
            EXPECT_EQ(Q3Object_Submit(style, view()), kQ3Success);
        TQ3SubdivisionStyleData state{};
        EXPECT_EQ(Q3View_GetSubdivisionStyleState(view(), &state), kQ3Success);
        expectSame(state, expected, what + " (view state)");
        vertices = decompose(m_curve);
        EXPECT_EQ(Q3Geometry_Submit(m_curve, view()), kQ3Success);
        const TQ3NURBCurveData data = m_curveData.data();
        EXPECT_EQ(Q3NURBCurve_Submit(&data, view()), kQ3Success);
        EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
        if (style != nullptr)
            Q3Object_Dispose(style);
        return vertices;
    }

    static void expectSame(const TQ3SubdivisionStyleData& got, const TQ3SubdivisionStyleData& expected,
                           const std::string& what)
    {
        EXPECT_EQ(got.method, expected.method) << what;
        EXPECT_EQ(got.c1, expected.c1) << what << " c1";
        EXPECT_EQ(got.c2, expected.c2) << what << " c2";
    }

    /// The curve drawn under the effective style c1 (substituted or not):
    /// constant, trunc(c1) segments in each of the four spans; world space,
    /// segments at most c1 units; screen space, at most c1 pixels; and for the
    /// adaptive methods close to the fewest. Q3 measures between exact
    /// points, the test between float vertices: coordinates below 4 round by
    /// at most 4 * 2^-24 = 2.4e-7, a vertex by sqrt(3) times that and a
    /// segment by twice that, 8.3e-7 units or 2.7e-5 pixels at this view's 32
    /// pixels per unit; kRounding covers both.
    void expectDrawnWith(const TQ3SubdivisionStyleData& effective, const std::vector<Point3>& v,
                         const std::string& what)
    {
        ASSERT_GE(v.size(), 2u) << what;
        if (effective.method == kQ3SubdivisionMethodConstant) {
            EXPECT_EQ(v.size(), (unsigned long)effective.c1 * FourSpans::kSpans + 1) << what;
            return;
        }
        const Projection pixels = orthographicProjection(0, 0, double(m_image.width()), double(m_image.height()));
        const Projection identity = [](const Point3& p) { return p; };
        const Projection& measure = effective.method == kQ3SubdivisionMethodWorldSpace ? identity : pixels;
        double length = 0.0;
        const TQ3NURBCurveData data = m_curveData.data();
        Point3 previous = measure(toPoint(referenceEvaluate(data, 0.0)));
        for (int i = 1; i <= 4000; ++i) {
            const Point3 next = measure(toPoint(referenceEvaluate(data, 4.0 * i / 4000)));
            length += std::hypot(next.x - previous.x, next.y - previous.y, next.z - previous.z);
            previous = next;
        }
        for (std::size_t i = 1; i < v.size(); ++i) {
            const Point3 a = measure(v[i - 1]), b = measure(v[i]);
            EXPECT_LE(std::hypot(b.x - a.x, b.y - a.y, b.z - a.z), effective.c1 + kRounding) << what << " segment " << i;
        }
        EXPECT_LE(double(v.size() - 1), 1.2 * length / effective.c1 + FourSpans::kSpans) << what;
    }

    static Point3 toPoint(const RefPoint& p) { return {p.x, p.y, p.z}; }

    Pixmap m_image{128, 96};
    std::unique_ptr<TestView> m_view;
    FourSpans m_curveData;
    TQ3GeometryObject m_curve = nullptr;
};

TEST_F(SubdivisionSubstitutionTest, EveryUnreasonableC1IsReplacedOnEveryPathAndDrawnWithTheReplacement)
{
    for (const Case& c : unreasonableValues()) {
        for (Path path : {Path::kSubmit, Path::kNew, Path::kSetData}) {
            const float c2 = reasonable(c.method);
            const TQ3SubdivisionStyleData requested = {c.method, c.value, c2};
            const TQ3SubdivisionStyleData expected = {c.method, c.replacement, c2};
            const std::string what = std::string(nameOf(path)) + " method " + std::to_string(c.method) +
                                     " c1 " + std::to_string(c.value);
            const std::vector<Point3> v = renderWith(requested, path, expected, what);
            expectDrawnWith(expected, v, what);
        }
    }
}

// Curves use only c1, but QuickDraw 3D checks c2 as well because it cannot
// know whether a surface follows: a bad c2 is replaced with a warning and
// the curve is drawn with c1 as given.
TEST_F(SubdivisionSubstitutionTest, EveryUnreasonableC2IsReplacedOnEveryPathAndLeavesTheCurveAlone)
{
    for (const Case& c : unreasonableValues()) {
        for (Path path : {Path::kSubmit, Path::kNew, Path::kSetData}) {
            const float c1 = reasonable(c.method);
            const TQ3SubdivisionStyleData requested = {c.method, c1, c.value};
            const TQ3SubdivisionStyleData expected = {c.method, c1, c.replacement};
            const std::string what = std::string(nameOf(path)) + " method " + std::to_string(c.method) +
                                     " c2 " + std::to_string(c.value);
            const std::vector<Point3> v = renderWith(requested, path, expected, what);
            expectDrawnWith(expected, v, what);
        }
    }
}

// Both bad at once: one warning for the call, not two.
TEST_F(SubdivisionSubstitutionTest, TwoBadValuesInOneCallPostOneWarning)
{
    const TQ3SubdivisionStyleData requested = {kQ3SubdivisionMethodScreenSpace, kNaN, -1.0f};
    const TQ3SubdivisionStyleData expected = {kQ3SubdivisionMethodScreenSpace, kDefault, kDefault};
    for (Path path : {Path::kSubmit, Path::kNew, Path::kSetData})
        expectDrawnWith(expected, renderWith(requested, path, expected, nameOf(path)), nameOf(path));
}

// The edges of the rule are reasonable and kept without a warning: one
// segment per span, kQ3SubdivisionMaxConstantSegments per span (a fraction
// above it is still truncated to it), the smallest positive lengths, the
// largest finite one (one segment per span).
TEST_F(SubdivisionSubstitutionTest, ValuesAtTheEdgesOfTheRuleAreKept)
{
    const float most = float(kQ3SubdivisionMaxConstantSegments);
    const std::vector<TQ3SubdivisionStyleData> edges = {
        {kQ3SubdivisionMethodConstant, 1.0f, 1.0f},
        {kQ3SubdivisionMethodConstant, most, most},
        {kQ3SubdivisionMethodConstant, 1.999f, 1.0f},
        {kQ3SubdivisionMethodWorldSpace, FLT_MAX, FLT_MAX},
        {kQ3SubdivisionMethodScreenSpace, FLT_MAX, FLT_MAX},
        {kQ3SubdivisionMethodWorldSpace, 0.05f, std::numeric_limits<float>::denorm_min()},
        {kQ3SubdivisionMethodScreenSpace, 0.5f, kQ3SubdivisionMinScreenSpaceC1},
        {kQ3SubdivisionMethodScreenSpace, kQ3SubdivisionMinScreenSpaceC1, 20.0f},
    };
    for (const TQ3SubdivisionStyleData& style : edges) {
        const std::string what = "method " + std::to_string(style.method) + " c1 " + std::to_string(style.c1);
        ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
        EXPECT_EQ(Q3SubdivisionStyle_Submit(&style, view()), kQ3Success);
        TQ3SubdivisionStyleData state{};
        EXPECT_EQ(Q3View_GetSubdivisionStyleState(view(), &state), kQ3Success);
        expectSame(state, style, what);
        const std::vector<Point3> v = decompose(m_curve);
        EXPECT_EQ(Q3Geometry_Submit(m_curve, view()), kQ3Success);
        EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
        expectDrawnWith(style, v, what);
        if (style.c1 == FLT_MAX)
            EXPECT_EQ(v.size(), FourSpans::kSpans + 1) << what;
    }
}

// A reasonable number that would still need more than the view's cap
// (kQ3SubdivisionViewSegmentsPerPixel * (128 + 96) = 3584 segments) on
// Listing 1 (about 3.9 world units and, in this view, about 90 pixels long):
// 10^-7 units. The curve is drawn (retained and immediate) and decomposed
// with a warning each time, and with at most the cap, but not far below it:
// the subdivision gives in as little as it must. (A screen-space c1 cannot
// get there in this pane: below 1/8 pixel it is replaced when submitted.)
TEST_F(SubdivisionSubstitutionTest, ALengthNeedingMoreThanTheCapWarnsWhereTheCurveIsDrawn)
{
    const unsigned long kCap = kQ3SubdivisionViewSegmentsPerPixel * (128 + 96);
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    TQ3GeometryObject curve = Q3NURBCurve_New(&data);
    ASSERT_NE(curve, nullptr);
    for (const TQ3SubdivisionStyleData& style : {TQ3SubdivisionStyleData{kQ3SubdivisionMethodWorldSpace, 1e-7f, 1}}) {
        const std::string what = "method " + std::to_string(style.method);
        ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
        EXPECT_EQ(Q3SubdivisionStyle_Submit(&style, view()), kQ3Success);
        EXPECT_Q3_WARNING(EXPECT_EQ(Q3Geometry_Submit(curve, view()), kQ3Success), kQ3WarningParameterOutOfRange);
        EXPECT_Q3_WARNING(EXPECT_EQ(Q3NURBCurve_Submit(&data, view()), kQ3Success),
                          kQ3WarningParameterOutOfRange);
        std::vector<Point3> v;
        EXPECT_Q3_WARNING(v = decompose(curve), kQ3WarningParameterOutOfRange);
        EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
        EXPECT_LE(v.size(), kCap + 1) << what;
        EXPECT_GE(v.size(), kCap / 2) << what;
        ASSERT_GE(v.size(), 2u);
        EXPECT_EQ(v.front().x, 0.0f);
        EXPECT_EQ(v.back().x, 3.0f);
    }
    Q3Object_Dispose(curve);
}

} // namespace
