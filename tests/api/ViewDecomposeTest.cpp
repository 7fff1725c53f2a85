// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Q3Geometry_GetDecomposed (a Quesa extension): the polyline a view draws for
// a NURB curve under its current state, and through it the subdivision
// methods and the retained-mode cache's invalidation, observed from outside.

#include "GeometryTestSupport.h"
#include "RenderTestSupport.h"

#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"

#include <cmath>
#include <vector>

namespace {

using namespace q3test;

class ViewDecomposeTest : public Q3ApiTest {
protected:
    void SetUp() override
    {
        Q3ApiTest::SetUp();
        m_view = std::make_unique<TestView>(m_image.pixmap());
        const TQ3NURBCurveData data = m_listing.data();
        m_curve = Q3NURBCurve_New(&data);
    }
    void TearDown() override
    {
        Q3Object_Dispose(m_curve);
        m_view.reset();
        Q3ApiTest::TearDown();
    }

    TQ3ViewObject view() const { return m_view->view(); }

    /// The listing's curve with `set` as its attribute set (the caller
    /// disposes both).
    TQ3GeometryObject curveWithSet(TQ3AttributeSet set)
    {
        const TQ3NURBCurveData data = m_listing.data(set);
        return Q3NURBCurve_New(&data);
    }

    // The decomposed polyline's vertices, read back through the public API.
    std::vector<TQ3Point3D> vertices(TQ3GeometryObject polyLine)
    {
        std::vector<TQ3Point3D> out;
        TQ3PolyLineData data{};
        if (Q3PolyLine_GetData(polyLine, &data) != kQ3Success)
            return out;
        for (unsigned long i = 0; i < data.numVertices; ++i)
            out.push_back(data.vertices[i].point);
        Q3PolyLine_EmptyData(&data);
        return out;
    }

    // Decomposes the curve inside a rendering loop after `setup` ran.
    std::vector<TQ3Point3D> decompose(const std::function<void(TQ3ViewObject)>& setup = {})
    {
        std::vector<TQ3Point3D> out;
        EXPECT_EQ(Q3View_StartRendering(view()), kQ3Success);
        if (setup)
            setup(view());
        TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(m_curve, view());
        EXPECT_NE(polyLine, nullptr);
        if (polyLine != nullptr) {
            EXPECT_EQ(Q3Geometry_GetType(polyLine), kQ3GeometryTypePolyLine);
            out = vertices(polyLine);
            Q3Object_Dispose(polyLine);
        }
        EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
        return out;
    }

    static double longestSegment(const std::vector<TQ3Point3D>& points, const Projection& project)
    {
        double longest = 0.0;
        for (std::size_t i = 0; i + 1 < points.size(); ++i) {
            const Point3 a = project({points[i].x, points[i].y, points[i].z});
            const Point3 b = project({points[i + 1].x, points[i + 1].y, points[i + 1].z});
            longest = std::max(longest, std::hypot(b.x - a.x, b.y - a.y, b.z - a.z));
        }
        return longest;
    }

    Pixmap m_image{200, 150};
    std::unique_ptr<TestView> m_view;
    Listing1 m_listing;
    TQ3GeometryObject m_curve = nullptr;
};

TEST_F(ViewDecomposeTest, ConstantSubdivisionGivesC1SegmentsPerSpanOnTheCurve)
{
    const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodConstant, 5, 5};
    const std::vector<TQ3Point3D> points =
        decompose([&](TQ3ViewObject v) { Q3SubdivisionStyle_Submit(&style, v); });
    ASSERT_EQ(points.size(), 6u);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Point3 expected = listing1At(double(i) / 5.0);
        EXPECT_NEAR(points[i].x, expected.x, 1e-5);
        EXPECT_NEAR(points[i].y, expected.y, 1e-5);
        EXPECT_NEAR(points[i].z, 0.0, 1e-6);
    }
}

TEST_F(ViewDecomposeTest, AFractionalConstantC1IsTruncated)
{
    const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodConstant, 3.9f, 3.9f};
    EXPECT_EQ(decompose([&](TQ3ViewObject v) { Q3SubdivisionStyle_Submit(&style, v); }).size(), 4u);
}

TEST_F(ViewDecomposeTest, ScreenSpaceSegmentsAreAtMostC1PixelsLong)
{
    const Projection pixels = orthographicProjection(0, 0, 200, 150);
    for (float c1 : {20.0f, 5.0f, 1.5f}) {
        const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodScreenSpace, c1, c1};
        const std::vector<TQ3Point3D> points =
            decompose([&](TQ3ViewObject v) { Q3SubdivisionStyle_Submit(&style, v); });
        ASSERT_GE(points.size(), 2u);
        EXPECT_LE(longestSegment(points, pixels), c1 * (1 + 1e-6)) << "c1 " << c1;
        // Close to the fewest: the curve is about 170 px long.
        EXPECT_LT(points.size(), 1.2 * 170 / c1 + 3) << "c1 " << c1;
    }
}

TEST_F(ViewDecomposeTest, TheDefaultStyleIsScreenSpaceTwentyPixels)
{
    const Projection pixels = orthographicProjection(0, 0, 200, 150);
    const std::vector<TQ3Point3D> points = decompose();
    EXPECT_LE(longestSegment(points, pixels), 20.0 * (1 + 1e-6));
    EXPECT_GE(points.size(), 9u); // at least 170 / 20 segments
}

TEST_F(ViewDecomposeTest, WorldSpaceSegmentsAreMeasuredAfterTheTransform)
{
    const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodWorldSpace, 0.5f, 0.5f};
    const Projection identity = [](const Point3& p) { return p; };
    const std::vector<TQ3Point3D> plain =
        decompose([&](TQ3ViewObject v) { Q3SubdivisionStyle_Submit(&style, v); });
    EXPECT_LE(longestSegment(plain, identity), 0.5 * (1 + 1e-6));
    const TQ3Vector3D scale = {4, 4, 4};
    const std::vector<TQ3Point3D> scaled = decompose([&](TQ3ViewObject v) {
        Q3SubdivisionStyle_Submit(&style, v);
        Q3ScaleTransform_Submit(&scale, v);
    });
    // Vertices stay in local coordinates; measured in world space they obey c1.
    const Projection toWorld = [](const Point3& p) { return Point3{4 * p.x, 4 * p.y, 4 * p.z}; };
    EXPECT_LE(longestSegment(scaled, toWorld), 0.5 * (1 + 1e-6));
    EXPECT_GT(scaled.size(), 3 * plain.size());
}

TEST_F(ViewDecomposeTest, ScreenSpaceMeasuresAfterThePerspectiveDivide)
{
    const Point3 eye = {1.5, -1.5, 1.8}, target = {1.5, 0.5, 0.0}, up = {0, 0, 1};
    const TQ3ViewAngleAspectCameraData cameraData = viewAngleCamera(eye, target, up, 1.0, 200.0 / 150.0);
    TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&cameraData);
    ASSERT_EQ(Q3View_SetCamera(view(), camera), kQ3Success);
    const Projection pixels = perspectiveProjection(eye, target, up, 1.0, 200.0 / 150.0, 200, 150);
    for (float c1 : {20.0f, 4.0f}) {
        const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodScreenSpace, c1, c1};
        const std::vector<TQ3Point3D> points =
            decompose([&](TQ3ViewObject v) { Q3SubdivisionStyle_Submit(&style, v); });
        // float vertices and the test's own projection agree to far below 0.01 px.
        EXPECT_LE(longestSegment(points, pixels), c1 + 0.01) << "c1 " << c1;
        // And not many more segments than the curve's length in pixels asks for.
        double length = 0;
        for (int i = 0; i < 1000; ++i) {
            const Point3 a = pixels(listing1At(i / 1000.0)), b = pixels(listing1At((i + 1) / 1000.0));
            length += std::hypot(b.x - a.x, b.y - a.y);
        }
        EXPECT_LE(points.size(), 1.1 * length / c1 + 3) << "c1 " << c1;
    }
    Q3Object_Dispose(camera);
}

TEST_F(ViewDecomposeTest, ScreenSpaceFollowsTheCameraAndThePane)
{
    const std::vector<TQ3Point3D> whole = decompose();
    // Zooming in (a narrower orthographic window) doubles the pixel length.
    TQ3OrthographicCameraData zoom = listing1OrthographicCamera();
    zoom.left /= 2;
    zoom.right /= 2;
    zoom.top /= 2;
    zoom.bottom /= 2;
    ASSERT_EQ(Q3OrthographicCamera_SetData(m_view->camera(), &zoom), kQ3Success);
    const std::vector<TQ3Point3D> zoomed = decompose();
    EXPECT_GT(zoomed.size(), whole.size() + whole.size() / 2);
    // A smaller pane shrinks it again.
    const TQ3Area pane = {{10, 10}, {60, 47.5f}};
    ASSERT_EQ(Q3DrawContext_SetPane(m_view->context(), &pane), kQ3Success);
    ASSERT_EQ(Q3DrawContext_SetPaneState(m_view->context(), kQ3True), kQ3Success);
    const std::vector<TQ3Point3D> small = decompose();
    EXPECT_LT(small.size(), zoomed.size() / 2);
}

TEST_F(ViewDecomposeTest, ARetainedCurveDecomposesAgainAfterEveryKindOfChange)
{
    const std::vector<TQ3Point3D> first = decompose();
    EXPECT_EQ(decompose().size(), first.size());
    // Edit: the vertices follow the new control point.
    const TQ3RationalPoint4D moved = {1, 3, 0, 1};
    ASSERT_EQ(Q3NURBCurve_SetControlPoint(m_curve, 1, &moved), kQ3Success);
    const std::vector<TQ3Point3D> edited = decompose();
    double highest = 0;
    for (const TQ3Point3D& p : edited)
        highest = std::max(highest, double(p.y));
    EXPECT_GT(highest, 1.2);
    // Style.
    const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodConstant, 2, 2};
    EXPECT_EQ(decompose([&](TQ3ViewObject v) { Q3SubdivisionStyle_Submit(&style, v); }).size(), 3u);
    EXPECT_EQ(decompose().size(), edited.size());
    // Transform (screen space measures through it).
    const TQ3Vector3D scale = {3, 3, 3};
    EXPECT_GT(decompose([&](TQ3ViewObject v) { Q3ScaleTransform_Submit(&scale, v); }).size(),
              2 * edited.size());
    EXPECT_EQ(decompose().size(), edited.size());
}

TEST_F(ViewDecomposeTest, ThePolylineCarriesTheCurvesAttributeSet)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    TQ3GeometryObject curve = curveWithSet(set);
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(curve, view());
    ASSERT_NE(polyLine, nullptr);
    TQ3PolyLineData out{};
    ASSERT_EQ(Q3PolyLine_GetData(polyLine, &out), kQ3Success);
    EXPECT_EQ(out.polyLineAttributeSet, set);
    EXPECT_EQ(out.segmentAttributeSet, nullptr);
    for (unsigned long i = 0; i < out.numVertices; ++i)
        EXPECT_EQ(out.vertices[i].attributeSet, nullptr);
    Q3PolyLine_EmptyData(&out);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
    Q3Object_Dispose(polyLine);
    Q3Object_Dispose(curve);
    Q3Object_Dispose(set);
}

TEST_F(ViewDecomposeTest, InABoundingLoopWithoutCameraScreenSpaceActsAsWorldSpace)
{
    TQ3ViewObject bare = Q3View_New();
    const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodScreenSpace, 0.5f, 0.5f};
    ASSERT_EQ(Q3View_StartBoundingBox(bare, kQ3ComputeBoundsExact), kQ3Success);
    Q3SubdivisionStyle_Submit(&style, bare);
    TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(m_curve, bare);
    ASSERT_NE(polyLine, nullptr);
    const std::vector<TQ3Point3D> points = vertices(polyLine);
    const Projection identity = [](const Point3& p) { return p; };
    EXPECT_LE(longestSegment(points, identity), 0.5 * (1 + 1e-6));
    EXPECT_GE(points.size(), 8u); // the curve is about 3.3 units long: 7 segments at least
    TQ3BoundingBox box;
    EXPECT_EQ(Q3View_EndBoundingBox(bare, &box), kQ3ViewStatusDone);
    Q3Object_Dispose(polyLine);
    Q3Object_Dispose(bare);
}

TEST_F(ViewDecomposeTest, ABoundingLoopWithACameraDecomposesInPixels)
{
    const std::vector<TQ3Point3D> rendering = decompose();
    ASSERT_EQ(Q3View_StartBoundingSphere(view(), kQ3ComputeBoundsExact), kQ3Success);
    TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(m_curve, view());
    EXPECT_EQ(vertices(polyLine).size(), rendering.size());
    TQ3BoundingSphere sphere;
    EXPECT_EQ(Q3View_EndBoundingSphere(view(), &sphere), kQ3ViewStatusDone);
    Q3Object_Dispose(polyLine);
}

TEST_F(ViewDecomposeTest, OtherGeometriesAreNotDecomposed)
{
    TQ3Vertex3D vertices[2] = {{{0, 0, 0}, nullptr}, {{1, 1, 0}, nullptr}};
    const TQ3PolyLineData data = {2, vertices, nullptr, nullptr};
    TQ3GeometryObject polyLine = Q3PolyLine_New(&data);
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    EXPECT_EQ(Q3Geometry_GetDecomposed(polyLine, view()), nullptr);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNone);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
    Q3Object_Dispose(polyLine);
}

TEST_F(ViewDecomposeTest, BadArgumentsAreReported)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    TQ3Object dead = Q3AttributeSet_New();
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_GetDecomposed(m_curve, view()), nullptr), kQ3ErrorViewNotStarted);
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    EXPECT_Q3_ERROR(Q3Geometry_GetDecomposed(nullptr, view()), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Geometry_GetDecomposed(m_curve, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Geometry_GetDecomposed(set, view()), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Geometry_GetDecomposed(m_curve, set), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Geometry_GetDecomposed(dead, view()), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3Geometry_GetDecomposed(m_curve, dead), kQ3ErrorInvalidObject);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
    Q3Object_Dispose(set);
}

// A 1101-point order-2 curve has 1100 spans; 1000 segments per span would
// be 1.1 million segments, more than kQ3SubdivisionMaxSegmentsPerCurve (the
// constant method's cap also in a view). The curve lies inside the view, so
// no span is drawn as one segment for being out of sight.
TEST_F(ViewDecomposeTest, TheSegmentCapPostsAWarningEveryTimeTheCurveIsDrawn)
{
    std::vector<TQ3RationalPoint4D> points;
    std::vector<float> knots;
    for (int i = 0; i <= 1100; ++i)
        points.push_back({0.45f * float(i % 7), 0.45f * float(i % 5), 0, 1}); // inside the view: nothing culled
    knots.push_back(0);
    for (int i = 0; i <= 1100; ++i)
        knots.push_back(float(i));
    knots.push_back(1100);
    const TQ3NURBCurveData data = {2, points.size(), points.data(), knots.data(), nullptr};
    TQ3GeometryObject curve = Q3NURBCurve_New(&data);
    ASSERT_NE(curve, nullptr);
    const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodConstant, 1000, 1000};
    for (int pass = 0; pass < 2; ++pass) {
        ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
        Q3SubdivisionStyle_Submit(&style, view());
        TQ3GeometryObject polyLine = nullptr;
        EXPECT_Q3_WARNING(polyLine = Q3Geometry_GetDecomposed(curve, view()), kQ3WarningParameterOutOfRange);
        ASSERT_NE(polyLine, nullptr);
        TQ3PolyLineData out{};
        Q3PolyLine_GetData(polyLine, &out);
        EXPECT_LE(out.numVertices, (unsigned long)kQ3SubdivisionMaxSegmentsPerCurve + 1);
        EXPECT_GE(out.numVertices, 1100ul * 900);
        Q3PolyLine_EmptyData(&out);
        Q3Object_Dispose(polyLine);
        // Drawing it warns as well, from the cache and in immediate mode.
        EXPECT_Q3_WARNING(EXPECT_EQ(Q3Geometry_Submit(curve, view()), kQ3Success),
                          kQ3WarningParameterOutOfRange);
        EXPECT_Q3_WARNING(EXPECT_EQ(Q3NURBCurve_Submit(&data, view()), kQ3Success),
                          kQ3WarningParameterOutOfRange);
        EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
    }
    Q3Object_Dispose(curve);
}

// What GetDecomposed hands out is the program's own object (issue 30: the
// polyline is made and copied on the public path's fast track, while no
// vertex has an attribute set): every GetData is a fresh copy, an edit of a
// copy changes nothing else, and once the program gives the polyline vertex
// sets, GetData, EmptyData and Dispose hold and release them in balance.
TEST_F(ViewDecomposeTest, TheDecomposedPolylineIsTheProgramsOwnToCopyAndEdit)
{
    const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodConstant, 5, 5};
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    Q3SubdivisionStyle_Submit(&style, view());
    TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(m_curve, view());
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
    ASSERT_NE(polyLine, nullptr);

    TQ3PolyLineData first{}, second{};
    ASSERT_EQ(Q3PolyLine_GetData(polyLine, &first), kQ3Success);
    ASSERT_EQ(first.numVertices, 6u);
    EXPECT_EQ(first.segmentAttributeSet, nullptr);
    EXPECT_EQ(first.polyLineAttributeSet, nullptr);
    for (unsigned long i = 0; i < first.numVertices; ++i) {
        const Point3 expected = listing1At(double(i) / 5.0);
        EXPECT_NEAR(first.vertices[i].point.x, expected.x, 1e-5);
        EXPECT_NEAR(first.vertices[i].point.y, expected.y, 1e-5);
        EXPECT_EQ(first.vertices[i].attributeSet, nullptr);
        first.vertices[i].point = {-9, -9, -9};
    }
    ASSERT_EQ(Q3PolyLine_GetData(polyLine, &second), kQ3Success);
    EXPECT_NE(second.vertices, first.vertices);
    EXPECT_NEAR(second.vertices[5].point.x, 3.0, 1e-5);
    EXPECT_EQ(Q3PolyLine_EmptyData(&first), kQ3Success);
    EXPECT_EQ(first.vertices, nullptr);
    EXPECT_EQ(Q3PolyLine_EmptyData(&second), kQ3Success);

    // The program's vertex set: one reference held by the polyline, one more
    // by each GetData copy until EmptyData.
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3Point3D moved = {7, 8, 9};
    ASSERT_EQ(Q3PolyLine_SetVertexAttributeSet(polyLine, 2, set), kQ3Success);
    ASSERT_EQ(Q3PolyLine_SetVertexPosition(polyLine, 4, &moved), kQ3Success);
    EXPECT_EQ(q3test::referenceCount(set), 2u);
    ASSERT_EQ(Q3PolyLine_GetData(polyLine, &first), kQ3Success);
    EXPECT_EQ(first.vertices[2].attributeSet, set);
    EXPECT_EQ(first.vertices[4].point.x, 7.0f);
    EXPECT_EQ(first.vertices[3].attributeSet, nullptr);
    EXPECT_EQ(q3test::referenceCount(set), 3u);
    EXPECT_EQ(Q3PolyLine_EmptyData(&first), kQ3Success);
    EXPECT_EQ(q3test::referenceCount(set), 2u);
    EXPECT_EQ(Q3Object_Dispose(polyLine), kQ3Success);
    EXPECT_EQ(q3test::referenceCount(set), 1u);
    Q3Object_Dispose(set);
}

// EmptyData checks every handle before it releases any, whether or not the
// vertices hold sets: a bad polyline set fails it and leaves the data as it was.
TEST_F(ViewDecomposeTest, EmptyDataOfADecompositionReleasesItsSetOrNothing)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    TQ3GeometryObject curve = curveWithSet(set);
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(curve, view());
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
    ASSERT_NE(polyLine, nullptr);
    const unsigned long held = q3test::referenceCount(set);

    TQ3PolyLineData out{};
    ASSERT_EQ(Q3PolyLine_GetData(polyLine, &out), kQ3Success);
    EXPECT_EQ(out.polyLineAttributeSet, set);
    EXPECT_EQ(q3test::referenceCount(set), held + 1);
    // A handle that is not an attribute set in its place: nothing released.
    TQ3AttributeSet own = out.polyLineAttributeSet;
    TQ3Vertex3D* vertices = out.vertices;
    out.polyLineAttributeSet = curve;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PolyLine_EmptyData(&out), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(out.vertices, vertices);
    EXPECT_EQ(out.polyLineAttributeSet, curve);
    EXPECT_NEAR(out.vertices[out.numVertices - 1].point.x, 3.0, 1e-5);
    out.polyLineAttributeSet = own;
    EXPECT_EQ(Q3PolyLine_EmptyData(&out), kQ3Success);
    EXPECT_EQ(out.vertices, nullptr);
    EXPECT_EQ(out.polyLineAttributeSet, nullptr);
    EXPECT_EQ(q3test::referenceCount(set), held);
    Q3Object_Dispose(polyLine);
    Q3Object_Dispose(curve);
    EXPECT_EQ(q3test::referenceCount(set), 1u);
    Q3Object_Dispose(set);
}

// A curve whose points are finite but whose projection x / w overflows float
// has no polyline: GetDecomposed posts kQ3ErrorInvalidData and gives NULL.
TEST_F(ViewDecomposeTest, ACurveThatProjectsOutsideFloatHasNoDecomposition)
{
    TQ3RationalPoint4D points[2] = {{0, 0, 0, 1}, {3.0e38f, 0, 0, 0.25f}};
    float knots[4] = {0, 0, 1, 1};
    const TQ3NURBCurveData data = {2, 2, points, knots, nullptr};
    TQ3GeometryObject curve = Q3NURBCurve_New(&data);
    ASSERT_NE(curve, nullptr);
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_GetDecomposed(curve, view()), nullptr), kQ3ErrorInvalidData);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
    Q3Object_Dispose(curve);
}

} // namespace
