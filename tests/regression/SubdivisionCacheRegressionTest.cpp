// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// A retained curve is drawn right after every kind of change its polyline
// depends on, and unchanged after changes it does not depend on. A retained
// curve keeps no polyline (geometry/NURBCurve.h: issue 16's memory target),
// so every pass subdivides it again; what these tests check is the result.
// Every kind of change the polyline depends on (the curve's edit index; the
// subdivision style's method and c1; the local-to-world transform for world
// and screen space; the camera's placement, range, view port and projection,
// and the pane's size, for screen space) is made between two frames, and
// then:
//   - the frame subdivided the curve exactly once per use (the counter
//     NURBCurve::tessellations rose by 2: Q3Geometry_GetDecomposed and the
//     submit), so no stale copy can have been drawn;
//   - the polyline drawn and decomposed equals, vertex for vertex, the one a
//     brand-new curve with the same data gives under the same state (a second
//     computation that cannot be stale), and an unchanged re-render gives it
//     again.
// After changes the polyline does not depend on (reads, rejected edits, the
// same values set again, c2, another object with equal values, state that the
// method does not measure through) the polyline is the last one, vertex for
// vertex. This extends tests/unit/view/CurveCacheTest.cpp, which covers
// SetControlPoint, Q3Shared_Edited, constant c1, a scale or translate
// transform, an orthographic window and a pane's size and position; those
// are not repeated. Immediate-mode curves are subdivided at every submit,
// which the image shows when the caller edits the data in place.

#include "PixmapViewTest.h"
#include "Q3ApiTest.h"

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGeometry.h"
#include "QD3DMath.h"
#include "QD3DRenderer.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"
#include "QD3DView.h"
#include "geometry/NURBCurve.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace {

using FrameSetup = std::function<void(TQ3ViewObject)>;

constexpr unsigned long kWidth = 128;
constexpr unsigned long kHeight = 96;

class SubdivisionCacheRegressionTest : public q3test::PixmapViewTest {
protected:
    SubdivisionCacheRegressionTest() : PixmapViewTest(kWidth, kHeight) {}

    void SetUp() override
    {
        PixmapViewTest::SetUp();
        m_perspective.cameraData.placement = {{1.5f, -3.0f, 2.5f}, {1.5f, 0.5f, 0.0f}, {0, 0, 1}};
        m_perspective.cameraData.range = {0.5f, 50.0f};
        m_perspective.cameraData.viewPort = {{-1, 1}, 2, 2};
        m_perspective.fov = 1.0f;
        m_perspective.aspectRatioXToY = 4.0f / 3.0f;
        m_camera = Q3ViewAngleAspectCamera_New(&m_perspective);
        ASSERT_NE(m_camera, nullptr);
        ASSERT_EQ(Q3View_SetCamera(m_view, m_camera), kQ3Success);
        const TQ3NURBCurveData curve = {4, 6, m_points, m_knots, nullptr};
        m_curve = Q3NURBCurve_New(&curve);
        ASSERT_NE(m_curve, nullptr);
    }

    void TearDown() override
    {
        for (TQ3Object object : {m_curve, m_camera})
            Q3Object_Dispose(object);
        PixmapViewTest::TearDown();
    }

    std::uint64_t builds() const { return q3::lookup<q3::NURBCurve>(m_curve, "curve").tessellations(); }

    static std::vector<TQ3Point3D> verticesOf(TQ3GeometryObject polyLine)
    {
        std::vector<TQ3Point3D> out;
        TQ3PolyLineData data{};
        if (polyLine == nullptr || Q3PolyLine_GetData(polyLine, &data) != kQ3Success)
            return out;
        for (unsigned long i = 0; i < data.numVertices; ++i)
            out.push_back(data.vertices[i].point);
        Q3PolyLine_EmptyData(&data);
        return out;
    }

    /// One frame: `setup` runs in the loop, then `curve` is decomposed and
    /// drawn. Returns the decomposed vertices.
    std::vector<TQ3Point3D> frame(const FrameSetup& setup = {}, TQ3GeometryObject curve = nullptr)
    {
        curve = curve != nullptr ? curve : m_curve;
        std::vector<TQ3Point3D> out;
        EXPECT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        if (setup)
            setup(m_view);
        TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(curve, m_view);
        EXPECT_NE(polyLine, nullptr);
        out = verticesOf(polyLine);
        Q3Object_Dispose(polyLine);
        EXPECT_EQ(Q3Geometry_Submit(curve, m_view), kQ3Success);
        EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
        return out;
    }

    /// What a curve that was never drawn, made from m_curve's current data,
    /// decomposes into under the same state.
    std::vector<TQ3Point3D> fresh(const FrameSetup& setup = {})
    {
        TQ3NURBCurveData data{};
        EXPECT_EQ(Q3NURBCurve_GetData(m_curve, &data), kQ3Success);
        TQ3GeometryObject copy = Q3NURBCurve_New(&data);
        Q3NURBCurve_EmptyData(&data);
        std::vector<TQ3Point3D> out = frame(setup, copy);
        Q3Object_Dispose(copy);
        return out;
    }

    static bool same(const std::vector<TQ3Point3D>& a, const std::vector<TQ3Point3D>& b)
    {
        if (a.size() != b.size())
            return false;
        for (std::size_t i = 0; i < a.size(); ++i)
            if (a[i].x != b[i].x || a[i].y != b[i].y || a[i].z != b[i].z)
                return false;
        return true;
    }

    /// After a change: the next frame subdivides the curve once per use
    /// (decomposed and drawn), giving the polyline a fresh curve gives, and
    /// an unchanged frame after it gives the same again.
    void expectRebuilt(const FrameSetup& setup, const std::string& what)
    {
        const std::uint64_t before = builds();
        const std::vector<TQ3Point3D> got = frame(setup);
        EXPECT_EQ(builds(), before + 2) << what << ": not subdivided once per use";
        EXPECT_TRUE(same(got, fresh(setup))) << what << ": the polyline drawn is not the curve's";
        EXPECT_TRUE(same(frame(setup), got)) << what << ": an unchanged re-render differs";
        m_last = got;
    }

    /// After something the polyline does not depend on: the polyline is the
    /// last one, vertex for vertex.
    void expectReused(const FrameSetup& setup, const std::string& what)
    {
        const std::uint64_t before = builds();
        const std::vector<TQ3Point3D> got = frame(setup);
        EXPECT_EQ(builds(), before + 2) << what << ": not subdivided once per use";
        EXPECT_TRUE(same(got, m_last)) << what << ": the polyline changed";
    }

    static FrameSetup with(const TQ3SubdivisionStyleData& style, const FrameSetup& more = {})
    {
        return [style, more](TQ3ViewObject view) {
            Q3SubdivisionStyle_Submit(&style, view);
            if (more)
                more(view);
        };
    }

    TQ3RationalPoint4D m_points[6] = {{0, 0, 0, 1}, {0.6f, 1.2f, 0, 1}, {1.2f, -0.6f, 0, 1},
                                      {1.8f, 1.4f, 0, 1}, {2.4f, 0, 0, 1}, {3, 1, 0, 1}};
    float m_knots[10] = {0, 0, 0, 0, 1, 2, 3, 3, 3, 3};
    TQ3ViewAngleAspectCameraData m_perspective{};
    TQ3CameraObject m_camera = nullptr;
    TQ3GeometryObject m_curve = nullptr;
    std::vector<TQ3Point3D> m_last;
};

// The edit index, under each method: reads and rejected edits leave it.
TEST_F(SubdivisionCacheRegressionTest, KnotAndDataEditsRebuildUnderEveryMethodReadsAndRejectedEditsDoNot)
{
    const TQ3SubdivisionStyleData styles[] = {{kQ3SubdivisionMethodConstant, 5, 5},
                                              {kQ3SubdivisionMethodWorldSpace, 0.2f, 0.2f},
                                              {kQ3SubdivisionMethodScreenSpace, 3, 3}};
    for (const TQ3SubdivisionStyleData& style : styles) {
        const std::string method = " (method " + std::to_string(style.method) + ")";
        const TQ3NURBCurveData original = {4, 6, m_points, m_knots, nullptr};
        ASSERT_EQ(Q3NURBCurve_SetData(m_curve, &original), kQ3Success);
        expectRebuilt(with(style), "first frame" + method);

        float knot = 0;
        TQ3RationalPoint4D point{};
        TQ3NURBCurveData data{};
        EXPECT_EQ(Q3NURBCurve_GetKnot(m_curve, 4, &knot), kQ3Success);
        EXPECT_EQ(Q3NURBCurve_GetControlPoint(m_curve, 2, &point), kQ3Success);
        EXPECT_EQ(Q3NURBCurve_GetData(m_curve, &data), kQ3Success);
        Q3NURBCurve_EmptyData(&data);
        expectReused(with(style), "reads" + method);

        ASSERT_EQ(Q3NURBCurve_SetKnot(m_curve, 4, 1.5f), kQ3Success);
        expectRebuilt(with(style), "SetKnot" + method);
        // 2.5 would come after knot 5 (2): rejected, nothing changes.
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_SetKnot(m_curve, 4, 2.5f), kQ3Failure), kQ3ErrorInvalidParameter);
        const TQ3RationalPoint4D unweighted = {1, 1, 0, 0};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_SetControlPoint(m_curve, 2, &unweighted), kQ3Failure),
                        kQ3ErrorInvalidParameter);
        expectReused(with(style), "rejected edits" + method);

        // The same position with twice the weight: a different rational curve.
        const TQ3RationalPoint4D heavier = {2 * point.x, 2 * point.y, 2 * point.z, 2 * point.w};
        ASSERT_EQ(Q3NURBCurve_SetControlPoint(m_curve, 2, &heavier), kQ3Success);
        expectRebuilt(with(style), "SetControlPoint weight" + method);

        TQ3RationalPoint4D quadratic[5] = {{0, 0, 0, 1}, {1, 2, 0, 1}, {2, -1, 0, 1}, {3, 1, 0, 2}, {3.5f, 0, 0, 1}};
        float quadraticKnots[8] = {0, 0, 0, 0.5f, 2, 3, 3, 3};
        const TQ3NURBCurveData other = {3, 5, quadratic, quadraticKnots, nullptr};
        ASSERT_EQ(Q3NURBCurve_SetData(m_curve, &other), kQ3Success);
        expectRebuilt(with(style), "SetData" + method);
    }
}

// Method and c1 of world and screen space, through a retained style object
// and immediate submits: the polyline is keyed on the values, so setting the
// same values again, submitting them another way, changing c2 or the fraction
// of a constant c1, reuses.
TEST_F(SubdivisionCacheRegressionTest, StyleMethodAndC1RebuildTheSameValuesAnyWayDoNot)
{
    const TQ3SubdivisionStyleData first = {kQ3SubdivisionMethodWorldSpace, 0.3f, 0.3f};
    TQ3StyleObject style = Q3SubdivisionStyle_New(&first);
    ASSERT_NE(style, nullptr);
    const FrameSetup object = [style](TQ3ViewObject view) { Q3Object_Submit(style, view); };
    expectRebuilt(object, "world 0.3");

    const TQ3SubdivisionStyleData finer = {kQ3SubdivisionMethodWorldSpace, 0.2f, 0.3f};
    ASSERT_EQ(Q3SubdivisionStyle_SetData(style, &finer), kQ3Success);
    expectRebuilt(object, "the style object's c1 set to 0.2");
    ASSERT_EQ(Q3SubdivisionStyle_SetData(style, &finer), kQ3Success);
    expectReused(object, "the same values set again");
    expectReused(with(finer), "the same values submitted immediately");
    expectReused(with({kQ3SubdivisionMethodWorldSpace, 0.2f, 9.0f}), "another c2");

    expectRebuilt(with({kQ3SubdivisionMethodScreenSpace, 0.2f, 0.2f}), "screen space with the same c1");
    expectRebuilt(with({kQ3SubdivisionMethodScreenSpace, 0.3f, 0.2f}), "screen-space c1 0.3");
    expectReused(with({kQ3SubdivisionMethodScreenSpace, 0.3f, 1.0f}), "screen space, another c2");
    expectRebuilt(with({kQ3SubdivisionMethodConstant, 2.0f, 2.0f}), "constant c1 2");
    // A constant c1 is truncated before it is used, and before it is keyed.
    expectReused(with({kQ3SubdivisionMethodConstant, 2.5f, 2.0f}), "constant c1 2.5");
    Q3Object_Dispose(style);
}

// World space measures through the local-to-world matrix: any change of it
// rebuilds, however it was made; the same matrix reached another way does not,
// and nor does a camera change that hides no span; the pane's size does (it
// sets the view's segment cap).
TEST_F(SubdivisionCacheRegressionTest, WorldSpaceRebuildsForEveryChangeOfTheLocalToWorldMatrix)
{
    const TQ3SubdivisionStyleData world = {kQ3SubdivisionMethodWorldSpace, 0.1f, 0.1f};
    const TQ3RotateTransformData tilt = {kQ3AxisX, 0.3f};
    const TQ3RotateTransformData more = {kQ3AxisX, 0.35f};
    const TQ3RotateTransformData yaw = {kQ3AxisY, 0.35f};
    expectRebuilt(with(world, [&](TQ3ViewObject v) { Q3RotateTransform_Submit(&tilt, v); }), "rotate X 0.3");
    expectRebuilt(with(world, [&](TQ3ViewObject v) { Q3RotateTransform_Submit(&more, v); }), "rotate X 0.35");
    expectRebuilt(with(world, [&](TQ3ViewObject v) { Q3RotateTransform_Submit(&yaw, v); }), "rotate Y 0.35");

    TQ3Matrix4x4 shear;
    Q3Matrix4x4_SetIdentity(&shear);
    shear.value[1][0] = 0.75f;
    shear.value[2][2] = 3.0f;
    expectRebuilt(with(world, [&](TQ3ViewObject v) { Q3MatrixTransform_Submit(&shear, v); }), "a shear matrix");
    shear.value[1][0] = 0.8f;
    expectRebuilt(with(world, [&](TQ3ViewObject v) { Q3MatrixTransform_Submit(&shear, v); }), "another shear");

    const TQ3Vector3D stretch = {1, 2, 1};
    TQ3Matrix4x4 stretchMatrix;
    Q3Matrix4x4_SetScale(&stretchMatrix, 1, 2, 1);
    expectRebuilt(with(world, [&](TQ3ViewObject v) { Q3ScaleTransform_Submit(&stretch, v); }), "scale y by 2");
    expectReused(with(world, [&](TQ3ViewObject v) { Q3MatrixTransform_Submit(&stretchMatrix, v); }),
                 "the same scale as a matrix");
    const TQ3Vector3D away = {5, 0, 0};
    expectReused(with(world,
                      [&](TQ3ViewObject v) {
                          Q3ScaleTransform_Submit(&stretch, v);
                          Q3Push_Submit(v);
                          Q3TranslateTransform_Submit(&away, v);
                          Q3Pop_Submit(v);
                      }),
                 "a transform undone by Q3Pop_Submit");

    // Not measured through in world space: the camera.
    const FrameSetup stretched = with(world, [&](TQ3ViewObject v) { Q3ScaleTransform_Submit(&stretch, v); });
    TQ3CameraPlacement placement = m_perspective.cameraData.placement;
    placement.cameraLocation.x += 1;
    ASSERT_EQ(Q3Camera_SetPlacement(m_camera, &placement), kQ3Success);
    expectReused(stretched, "a camera change under world space that hides no span");
    // The pane sets world space's segment cap in a view
    // (kQ3SubdivisionViewSegmentsPerPixel), so its size is part of the key.
    std::vector<unsigned char> small(64 * 48 * 4, 0);
    const TQ3PixmapDrawContextData smallData = q3test::argb32ContextData(small, 64, 48);
    ASSERT_EQ(Q3PixmapDrawContext_SetPixmap(m_context, &smallData.pixmap), kQ3Success);
    expectRebuilt(stretched, "a pane size change under world space");
    const TQ3PixmapDrawContextData whole = q3test::argb32ContextData(m_memory, kWidth, kHeight);
    ASSERT_EQ(Q3PixmapDrawContext_SetPixmap(m_context, &whole.pixmap), kQ3Success);
}

// Screen space measures through local -> world -> frustum -> pane: every part
// of the camera and the pane's size count; equal values do not rebuild.
TEST_F(SubdivisionCacheRegressionTest, ScreenSpaceRebuildsForEveryCameraAndPaneChange)
{
    const FrameSetup screen = with({kQ3SubdivisionMethodScreenSpace, 2, 2});
    expectRebuilt(screen, "first frame");

    TQ3CameraPlacement placement = m_perspective.cameraData.placement;
    placement.cameraLocation.z += 0.5f;
    ASSERT_EQ(Q3Camera_SetPlacement(m_camera, &placement), kQ3Success);
    expectRebuilt(screen, "camera moved");
    placement.upVector = {0.2f, 0, 1};
    ASSERT_EQ(Q3Camera_SetPlacement(m_camera, &placement), kQ3Success);
    expectRebuilt(screen, "camera rolled");

    const TQ3CameraRange yon = {0.5f, 80.0f};
    ASSERT_EQ(Q3Camera_SetRange(m_camera, &yon), kQ3Success);
    expectRebuilt(screen, "yon");
    const TQ3CameraRange hither = {0.25f, 80.0f};
    ASSERT_EQ(Q3Camera_SetRange(m_camera, &hither), kQ3Success);
    expectRebuilt(screen, "hither");

    const TQ3CameraViewPort zoomed = {{-0.5f, 0.5f}, 1.0f, 1.0f};
    ASSERT_EQ(Q3Camera_SetViewPort(m_camera, &zoomed), kQ3Success);
    expectRebuilt(screen, "view port");

    TQ3ViewAngleAspectCameraData lens{};
    ASSERT_EQ(Q3ViewAngleAspectCamera_GetData(m_camera, &lens), kQ3Success);
    lens.fov = 0.6f;
    ASSERT_EQ(Q3ViewAngleAspectCamera_SetData(m_camera, &lens), kQ3Success);
    expectRebuilt(screen, "field of view");
    lens.aspectRatioXToY = 1.0f;
    ASSERT_EQ(Q3ViewAngleAspectCamera_SetData(m_camera, &lens), kQ3Success);
    expectRebuilt(screen, "aspect ratio");
    ASSERT_EQ(Q3ViewAngleAspectCamera_SetData(m_camera, &lens), kQ3Success);
    expectReused(screen, "the same camera data set again");

    TQ3CameraObject twin = Q3ViewAngleAspectCamera_New(&lens);
    ASSERT_EQ(Q3View_SetCamera(m_view, twin), kQ3Success);
    expectReused(screen, "another camera with the same data");
    TQ3OrthographicCameraData flat{};
    flat.cameraData = lens.cameraData;
    flat.left = -2;
    flat.right = 2;
    flat.top = 1.5f;
    flat.bottom = -1.5f;
    TQ3CameraObject orthographic = Q3OrthographicCamera_New(&flat);
    ASSERT_EQ(Q3View_SetCamera(m_view, orthographic), kQ3Success);
    expectRebuilt(screen, "an orthographic camera");
    ASSERT_EQ(Q3View_SetCamera(m_view, twin), kQ3Success);
    expectRebuilt(screen, "back to the perspective camera");

    std::vector<unsigned char> small(64 * 48 * 4, 0), other(kWidth * kHeight * 4, 0);
    const TQ3PixmapDrawContextData smallData = q3test::argb32ContextData(small, 64, 48);
    ASSERT_EQ(Q3PixmapDrawContext_SetPixmap(m_context, &smallData.pixmap), kQ3Success);
    expectRebuilt(screen, "a smaller pixmap");
    const TQ3PixmapDrawContextData otherData = q3test::argb32ContextData(other, kWidth, kHeight);
    const TQ3PixmapDrawContextData whole = q3test::argb32ContextData(m_memory, kWidth, kHeight);
    ASSERT_EQ(Q3PixmapDrawContext_SetPixmap(m_context, &otherData.pixmap), kQ3Success);
    expectRebuilt(screen, "a pixmap of the first size");
    ASSERT_EQ(Q3PixmapDrawContext_SetPixmap(m_context, &whole.pixmap), kQ3Success);
    expectReused(screen, "another pixmap of the same size");
    const TQ3ColorARGB red = {1, 1, 0, 0};
    ASSERT_EQ(Q3DrawContext_SetClearImageColor(m_context, &red), kQ3Success);
    expectReused(screen, "a clear colour");

    const TQ3RotateTransformData turn = {kQ3AxisZ, 0.2f};
    expectRebuilt(with({kQ3SubdivisionMethodScreenSpace, 2, 2},
                       [&](TQ3ViewObject v) { Q3RotateTransform_Submit(&turn, v); }),
                  "a rotation under screen space");
    Q3Object_Dispose(twin);
    Q3Object_Dispose(orthographic);
}

// The hither distance matters to the polyline itself when the curve crosses
// the hither plane: the part nearer than it has no screen image to measure.
TEST_F(SubdivisionCacheRegressionTest, AHitherChangeReshapesACurveThatCrossesIt)
{
    TQ3CameraPlacement placement = {{1.5f, 0.5f, 0.5f}, {1.5f, 0.5f, 0.0f}, {0, 1, 0}};
    ASSERT_EQ(Q3Camera_SetPlacement(m_camera, &placement), kQ3Success);
    TQ3RationalPoint4D through[4] = {{0, 0, -2, 1}, {1, 1, 2, 1}, {2, 0, -1, 1}, {3, 1, 3, 1}};
    float knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    const TQ3NURBCurveData data = {4, 4, through, knots, nullptr};
    ASSERT_EQ(Q3NURBCurve_SetData(m_curve, &data), kQ3Success);
    const FrameSetup screen = with({kQ3SubdivisionMethodScreenSpace, 1, 1});
    expectRebuilt(screen, "hither 0.5");
    const std::vector<TQ3Point3D> far = m_last;
    const TQ3CameraRange nearer = {0.05f, 50.0f};
    ASSERT_EQ(Q3Camera_SetRange(m_camera, &nearer), kQ3Success);
    expectRebuilt(screen, "hither 0.05");
    EXPECT_FALSE(same(far, m_last)) << "the hither plane should change what is measured";
}

// A bounding loop with the same camera and pane measures the same way as
// rendering: it gives the rendered polyline. A view without a camera bounds
// screen space as world space: another polyline.
TEST_F(SubdivisionCacheRegressionTest, BoundingLoopsMeasureAsRenderingWhenTheyHaveItsWindow)
{
    expectRebuilt({}, "rendering");
    const std::uint64_t before = builds();
    ASSERT_EQ(Q3View_StartBoundingBox(m_view, kQ3ComputeBoundsExact), kQ3Success);
    TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(m_curve, m_view);
    EXPECT_TRUE(same(verticesOf(polyLine), m_last));
    Q3Object_Dispose(polyLine);
    TQ3BoundingBox box;
    EXPECT_EQ(Q3View_EndBoundingBox(m_view, &box), kQ3ViewStatusDone);
    EXPECT_EQ(builds(), before + 1);

    TQ3ViewObject bare = Q3View_New();
    ASSERT_EQ(Q3View_StartBoundingSphere(bare, kQ3ComputeBoundsExact), kQ3Success);
    polyLine = Q3Geometry_GetDecomposed(m_curve, bare);
    EXPECT_FALSE(same(verticesOf(polyLine), m_last));
    Q3Object_Dispose(polyLine);
    TQ3BoundingSphere sphere;
    EXPECT_EQ(Q3View_EndBoundingSphere(bare, &sphere), kQ3ViewStatusDone);
    EXPECT_EQ(builds(), before + 2);
    Q3Object_Dispose(bare);
}

// Immediate mode keeps nothing: data edited in place between submits is
// drawn as it is at each submit, within a frame and across frames.
TEST_F(SubdivisionCacheRegressionTest, ImmediateModeCurvesAreSubdividedAtEverySubmit)
{
    // Looking down -z at the origin: x -2..2 and y -1.5..1.5 fill the image,
    // 32 pixels per unit, so y = 0.75 is pixel row 24 and y = -0.75 row 72.
    const TQ3OrthographicCameraData camera = q3test::orthographicCameraAt(0, 0, 2, 1.5f);
    TQ3CameraObject flat = Q3OrthographicCamera_New(&camera);
    ASSERT_EQ(Q3View_SetCamera(m_view, flat), kQ3Success);
    Q3Object_Dispose(flat);
    TQ3RationalPoint4D points[3] = {{-1.5f, 0.75f, 0, 1}, {0, 0.75f, 0, 1}, {1.5f, 0.75f, 0, 1}};
    float knots[5] = {0, 0, 1, 2, 2};
    const TQ3NURBCurveData data = {2, 3, points, knots, nullptr};
    auto moveTo = [&](float y) {
        for (TQ3RationalPoint4D& p : points)
            p.y = y;
    };
    auto rowLit = [&](unsigned long row) {
        unsigned long count = 0;
        for (unsigned long x = 0; x < kWidth; ++x) {
            const unsigned char* p = &m_memory[(row * kWidth + x) * 4];
            count += (p[1] > 127 || p[2] > 127 || p[3] > 127) ? 1 : 0;
        }
        return count > kWidth / 2;
    };
    auto draw = [&](const std::function<void()>& between) {
        ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        EXPECT_EQ(Q3NURBCurve_Submit(&data, m_view), kQ3Success);
        if (between) {
            between();
            EXPECT_EQ(Q3NURBCurve_Submit(&data, m_view), kQ3Success);
        }
        EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
    };
    draw({});
    EXPECT_TRUE(rowLit(24) || rowLit(23));
    EXPECT_FALSE(rowLit(72) || rowLit(71));
    moveTo(-0.75f);
    draw({});
    EXPECT_FALSE(rowLit(24) || rowLit(23));
    EXPECT_TRUE(rowLit(72) || rowLit(71));
    moveTo(0.75f);
    draw([&] { moveTo(-0.75f); });
    EXPECT_TRUE(rowLit(24) || rowLit(23));
    EXPECT_TRUE(rowLit(72) || rowLit(71));
    EXPECT_EQ(builds(), 0u) << "the retained curve was never drawn";
}

} // namespace
