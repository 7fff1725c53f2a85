// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Q3View_*: configuration, the rendering loop's rules and errors, cancel,
// sync, and Q3Object_Submit.

#include "RenderTestSupport.h"

#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"

#include <utility>

namespace {

using namespace q3test;

class ViewApiTest : public Q3ApiTest {
protected:
    // Listing 1's curve, an empty attribute set and a constant subdivision
    // style (as data and as an object), disposed of at the end of the test.
    struct Submittables {
        Listing1 listing;
        TQ3NURBCurveData data = listing.data();
        TQ3GeometryObject curve = Q3NURBCurve_New(&data);
        TQ3AttributeSet set = Q3AttributeSet_New();
        TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodConstant, 4, 4};
        TQ3StyleObject styleObject = Q3SubdivisionStyle_New(&style);
        ~Submittables()
        {
            for (TQ3Object object : {curve, set, styleObject})
                Q3Object_Dispose(object);
        }
    };

    void SetUp() override
    {
        Q3ApiTest::SetUp();
        m_view = Q3View_New();
        ASSERT_NE(m_view, nullptr);
        const TQ3OrthographicCameraData cameraData = listing1OrthographicCamera();
        m_camera = Q3OrthographicCamera_New(&cameraData);
        const TQ3PixmapDrawContextData contextData = pixmapContextData(m_image.pixmap());
        m_context = Q3PixmapDrawContext_New(&contextData);
        m_renderer = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
        ASSERT_TRUE(m_camera && m_context && m_renderer);
    }

    void TearDown() override
    {
        for (TQ3Object object : {m_view, m_camera, m_context, m_renderer})
            if (object != nullptr)
                Q3Object_Dispose(object);
        Q3ApiTest::TearDown();
    }

    void configure()
    {
        ASSERT_EQ(Q3View_SetDrawContext(m_view, m_context), kQ3Success);
        ASSERT_EQ(Q3View_SetCamera(m_view, m_camera), kQ3Success);
        ASSERT_EQ(Q3View_SetRenderer(m_view, m_renderer), kQ3Success);
    }

    // A handle that was a live object once.
    TQ3Object deadHandle()
    {
        TQ3Object object = Q3AttributeSet_New();
        Q3Object_Dispose(object);
        return object;
    }

    Pixmap m_image{64, 48};
    TQ3ViewObject m_view = nullptr;
    TQ3CameraObject m_camera = nullptr;
    TQ3DrawContextObject m_context = nullptr;
    TQ3RendererObject m_renderer = nullptr;
};

TEST(ViewApiUninitialized, NewBeforeInitializeFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    EXPECT_EQ(Q3View_New(), nullptr);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
}

TEST_F(ViewApiTest, NewViewHasNoRendererCameraOrDrawContext)
{
    // Each getter overwrites a handle it is given with NULL.
    const std::pair<TQ3Status (*)(TQ3ViewObject, TQ3Object*), TQ3Object> getters[] = {
        {Q3View_GetCamera, m_camera}, {Q3View_GetRenderer, m_renderer}, {Q3View_GetDrawContext, m_context}};
    for (const auto& [get, before] : getters) {
        TQ3Object out = before;
        EXPECT_EQ(get(m_view, &out), kQ3Success);
        EXPECT_EQ(out, nullptr);
    }
    EXPECT_EQ(Q3Object_GetType(m_view), kQ3ObjectTypeView);
}

TEST_F(ViewApiTest, GettersHandOutNewReferencesToWhatWasSet)
{
    configure();
    TQ3Object camera = nullptr, renderer = nullptr, context = nullptr;
    EXPECT_EQ(Q3View_GetCamera(m_view, &camera), kQ3Success);
    EXPECT_EQ(Q3View_GetRenderer(m_view, &renderer), kQ3Success);
    EXPECT_EQ(Q3View_GetDrawContext(m_view, &context), kQ3Success);
    EXPECT_EQ(camera, m_camera);
    EXPECT_EQ(renderer, m_renderer);
    EXPECT_EQ(context, m_context);
    // The caller, the view and this Get each hold one.
    EXPECT_EQ(Q3Shared_IsReferenced(m_camera), kQ3True);
    Q3Object_Dispose(camera);
    Q3Object_Dispose(renderer);
    Q3Object_Dispose(context);
}

TEST_F(ViewApiTest, TheViewKeepsWhatItWasGivenAlive)
{
    configure();
    Q3Object_Dispose(m_camera);
    Q3Object_Dispose(m_context);
    Q3Object_Dispose(m_renderer);
    m_camera = m_context = m_renderer = nullptr;
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    EXPECT_EQ(Q3NURBCurve_Submit(&data, m_view), kQ3Success);
    EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
    // Disposing the view releases the last references.
    Q3Object_Dispose(m_view);
    m_view = nullptr;
}

TEST_F(ViewApiTest, SettingReplacesAndReleasesThePreviousObject)
{
    configure();
    const unsigned long live = Q3Memory_CountLiveObjects();
    TQ3RendererObject other = Q3Renderer_NewFromType(kQ3RendererTypeWireFrame);
    EXPECT_EQ(Q3View_SetRenderer(m_view, other), kQ3Success);
    Q3Object_Dispose(other);
    EXPECT_EQ(Q3Renderer_GetType(m_renderer), kQ3RendererTypeInteractive);
    TQ3Object current = nullptr;
    Q3View_GetRenderer(m_view, &current);
    EXPECT_EQ(Q3Renderer_GetType(current), kQ3RendererTypeWireFrame);
    Q3Object_Dispose(current);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live + 1);
}

TEST_F(ViewApiTest, SetRendererByTypeMakesARendererOnlyTheViewHolds)
{
    const unsigned long live = Q3Memory_CountLiveObjects();
    EXPECT_EQ(Q3View_SetRendererByType(m_view, kQ3RendererTypeWireFrame), kQ3Success);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live + 1);
    TQ3Object renderer = nullptr;
    EXPECT_EQ(Q3View_GetRenderer(m_view, &renderer), kQ3Success);
    EXPECT_EQ(Q3Renderer_GetType(renderer), kQ3RendererTypeWireFrame);
    Q3Object_Dispose(renderer);
    EXPECT_EQ(Q3View_SetRendererByType(m_view, kQ3RendererTypeInteractive), kQ3Success);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live + 1);

    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_SetRendererByType(m_view, kQ3RendererTypeGeneric), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_SetRendererByType(m_view, kQ3ObjectTypeInvalid), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_SetRendererByType(m_view, kQ3GeometryTypeNURBCurve), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_SetRendererByType(nullptr, kQ3RendererTypeWireFrame), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_SetRendererByType(m_camera, kQ3RendererTypeWireFrame),
                    kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_SetRendererByType(deadHandle(), kQ3RendererTypeWireFrame),
                    kQ3ErrorInvalidObject);
    // The failures changed nothing.
    Q3View_GetRenderer(m_view, &renderer);
    EXPECT_EQ(Q3Renderer_GetType(renderer), kQ3RendererTypeInteractive);
    Q3Object_Dispose(renderer);
}

TEST_F(ViewApiTest, SettersRejectBadHandles)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_SetCamera(nullptr, m_camera), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_SetCamera(m_view, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_SetCamera(m_view, m_renderer), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_SetCamera(m_camera, m_camera), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_SetCamera(m_view, deadHandle()), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3View_SetCamera(deadHandle(), m_camera), kQ3ErrorInvalidObject);

    EXPECT_Q3_ERROR(Q3View_SetRenderer(nullptr, m_renderer), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_SetRenderer(m_view, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_SetRenderer(m_view, m_camera), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_SetRenderer(m_renderer, m_renderer), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_SetRenderer(m_view, deadHandle()), kQ3ErrorInvalidObject);

    EXPECT_Q3_ERROR(Q3View_SetDrawContext(nullptr, m_context), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_SetDrawContext(m_view, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_SetDrawContext(m_view, m_camera), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_SetDrawContext(m_context, m_context), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_SetDrawContext(m_view, deadHandle()), kQ3ErrorInvalidObject);

    // Nothing was set by the failures.
    TQ3Object out = nullptr;
    Q3View_GetCamera(m_view, &out);
    EXPECT_EQ(out, nullptr);
    Q3View_GetRenderer(m_view, &out);
    EXPECT_EQ(out, nullptr);
    Q3View_GetDrawContext(m_view, &out);
    EXPECT_EQ(out, nullptr);
}

TEST_F(ViewApiTest, GettersRejectBadArguments)
{
    TQ3Object out = reinterpret_cast<TQ3Object>(&out);
    EXPECT_Q3_ERROR(Q3View_GetCamera(m_view, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_GetCamera(nullptr, &out), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_GetCamera(m_camera, &out), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_GetCamera(deadHandle(), &out), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3View_GetRenderer(m_view, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_GetRenderer(nullptr, &out), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_GetRenderer(m_renderer, &out), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_GetRenderer(deadHandle(), &out), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3View_GetDrawContext(m_view, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_GetDrawContext(nullptr, &out), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_GetDrawContext(m_context, &out), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_GetDrawContext(deadHandle(), &out), kQ3ErrorInvalidObject);
    EXPECT_EQ(out, reinterpret_cast<TQ3Object>(&out));
}

TEST_F(ViewApiTest, StartRenderingNeedsDrawContextThenCameraThenRenderer)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_StartRendering(m_view), kQ3Failure), kQ3ErrorDrawContextNotSet);
    Q3View_SetDrawContext(m_view, m_context);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_StartRendering(m_view), kQ3Failure), kQ3ErrorCameraNotSet);
    Q3View_SetCamera(m_view, m_camera);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_StartRendering(m_view), kQ3Failure), kQ3ErrorRendererNotSet);
    // A failed start started nothing.
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    EXPECT_Q3_ERROR(Q3NURBCurve_Submit(&data, m_view), kQ3ErrorViewNotStarted);
    Q3View_SetRenderer(m_view, m_renderer);
    EXPECT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
    // Each of the others, with the rest set, on a fresh view.
    TQ3ViewObject noCamera = Q3View_New();
    Q3View_SetDrawContext(noCamera, m_context);
    Q3View_SetRenderer(noCamera, m_renderer);
    EXPECT_Q3_ERROR(Q3View_StartRendering(noCamera), kQ3ErrorCameraNotSet);
    Q3Object_Dispose(noCamera);
    TQ3ViewObject noContext = Q3View_New();
    Q3View_SetCamera(noContext, m_camera);
    Q3View_SetRenderer(noContext, m_renderer);
    EXPECT_Q3_ERROR(Q3View_StartRendering(noContext), kQ3ErrorDrawContextNotSet);
    Q3Object_Dispose(noContext);
}

TEST_F(ViewApiTest, StartRenderingRejectsBadViews)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_StartRendering(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_StartRendering(m_camera), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_StartRendering(deadHandle()), kQ3ErrorInvalidObject);
}

TEST_F(ViewApiTest, StartingAnyLoopInsideALoopFailsWithViewIsStarted)
{
    configure();
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_StartRendering(m_view), kQ3Failure), kQ3ErrorViewIsStarted);
    EXPECT_Q3_ERROR(Q3View_StartBoundingBox(m_view, kQ3ComputeBoundsExact), kQ3ErrorViewIsStarted);
    EXPECT_Q3_ERROR(Q3View_StartBoundingSphere(m_view, kQ3ComputeBoundsExact), kQ3ErrorViewIsStarted);
    // The running loop keeps running.
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    EXPECT_EQ(Q3NURBCurve_Submit(&data, m_view), kQ3Success);
    EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);

    ASSERT_EQ(Q3View_StartBoundingBox(m_view, kQ3ComputeBoundsExact), kQ3Success);
    EXPECT_Q3_ERROR(Q3View_StartRendering(m_view), kQ3ErrorViewIsStarted);
    TQ3BoundingBox box;
    EXPECT_EQ(Q3View_EndBoundingBox(m_view, &box), kQ3ViewStatusDone);
}

TEST_F(ViewApiTest, SettersInsideALoopFailWithViewIsStartedAndChangeNothing)
{
    configure();
    TQ3CameraObject otherCamera = Q3Object_Duplicate(m_camera);
    TQ3RendererObject otherRenderer = Q3Renderer_NewFromType(kQ3RendererTypeWireFrame);
    TQ3DrawContextObject otherContext = Q3Object_Duplicate(m_context);
    for (int loop = 0; loop < 2; ++loop) {
        if (loop == 0)
            ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        else
            ASSERT_EQ(Q3View_StartBoundingSphere(m_view, kQ3ComputeBoundsApproximate), kQ3Success);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_SetCamera(m_view, otherCamera), kQ3Failure), kQ3ErrorViewIsStarted);
        EXPECT_Q3_ERROR(Q3View_SetRenderer(m_view, otherRenderer), kQ3ErrorViewIsStarted);
        EXPECT_Q3_ERROR(Q3View_SetDrawContext(m_view, otherContext), kQ3ErrorViewIsStarted);
        // The loop comes before the type: an unknown type inside a loop is reported as the loop.
        EXPECT_Q3_ERROR(Q3View_SetRendererByType(m_view, kQ3RendererTypeGeneric), kQ3ErrorViewIsStarted);
        if (loop == 0) {
            EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
        } else {
            TQ3BoundingSphere sphere;
            EXPECT_EQ(Q3View_EndBoundingSphere(m_view, &sphere), kQ3ViewStatusDone);
        }
    }
    TQ3Object camera = nullptr, renderer = nullptr, context = nullptr;
    Q3View_GetCamera(m_view, &camera);
    Q3View_GetRenderer(m_view, &renderer);
    Q3View_GetDrawContext(m_view, &context);
    EXPECT_EQ(camera, m_camera);
    EXPECT_EQ(renderer, m_renderer);
    EXPECT_EQ(context, m_context);
    for (TQ3Object object : {camera, renderer, context, otherCamera, otherRenderer, otherContext})
        Q3Object_Dispose(object);
}

TEST_F(ViewApiTest, EndRenderingOutsideARenderingLoopFails)
{
    configure();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusError), kQ3ErrorRenderingNotStarted);
    ASSERT_EQ(Q3View_StartBoundingBox(m_view, kQ3ComputeBoundsExact), kQ3Success);
    EXPECT_Q3_ERROR(Q3View_EndRendering(m_view), kQ3ErrorRenderingNotStarted);
    TQ3BoundingBox box;
    EXPECT_EQ(Q3View_EndBoundingBox(m_view, &box), kQ3ViewStatusDone);
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
    EXPECT_Q3_ERROR(Q3View_EndRendering(m_view), kQ3ErrorRenderingNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_EndRendering(nullptr), kQ3ViewStatusError), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_EndRendering(m_camera), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_EndRendering(deadHandle()), kQ3ErrorInvalidObject);
}

TEST_F(ViewApiTest, EndRenderingNeverAsksForARetraversal)
{
    configure();
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    int traversals = 0;
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    TQ3ViewStatus status;
    do {
        ++traversals;
        Q3NURBCurve_Submit(&data, m_view);
        status = Q3View_EndRendering(m_view);
    } while (status == kQ3ViewStatusRetraverse);
    EXPECT_EQ(status, kQ3ViewStatusDone);
    EXPECT_EQ(traversals, 1);
}

TEST_F(ViewApiTest, ASecondFrameReusesTheViewAndRedrawsFromTheClear)
{
    configure();
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    for (int frame = 0; frame < 3; ++frame) {
        m_image.fill(0x11);
        ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        if (frame != 1)
            Q3NURBCurve_Submit(&data, m_view);
        ASSERT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
        std::size_t lit = 0;
        for (unsigned long y = 0; y < m_image.height(); ++y)
            for (unsigned long x = 0; x < m_image.width(); ++x)
                lit += m_image.lit(x, y) ? 1 : 0;
        if (frame == 1)
            EXPECT_EQ(lit, 0u);
        else
            EXPECT_GT(lit, 20u);
    }
}

TEST_F(ViewApiTest, SubmittingOutsideALoopFailsWithViewNotStarted)
{
    configure();
    const Submittables submittables;
    const auto& [listing, data, curve, set, style, styleObject] = submittables;
    const TQ3Vector3D offset = {1, 0, 0};
    for (int when = 0; when < 2; ++when) {
        if (when == 1) {
            // After a loop has ended, as before any loop.
            ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
            ASSERT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
        }
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_Submit(curve, m_view), kQ3Failure), kQ3ErrorViewNotStarted);
        EXPECT_Q3_ERROR(Q3NURBCurve_Submit(&data, m_view), kQ3ErrorViewNotStarted);
        EXPECT_Q3_ERROR(Q3Object_Submit(curve, m_view), kQ3ErrorViewNotStarted);
        EXPECT_Q3_ERROR(Q3AttributeSet_Submit(set, m_view), kQ3ErrorViewNotStarted);
        EXPECT_Q3_ERROR(Q3SubdivisionStyle_Submit(&style, m_view), kQ3ErrorViewNotStarted);
        EXPECT_Q3_ERROR(Q3Object_Submit(styleObject, m_view), kQ3ErrorViewNotStarted);
        EXPECT_Q3_ERROR(Q3TranslateTransform_Submit(&offset, m_view), kQ3ErrorViewNotStarted);
        EXPECT_Q3_ERROR(Q3Push_Submit(m_view), kQ3ErrorViewNotStarted);
        EXPECT_Q3_ERROR(Q3Pop_Submit(m_view), kQ3ErrorViewNotStarted);
        TQ3Matrix4x4 matrix;
        EXPECT_Q3_ERROR(Q3View_GetLocalToWorldMatrixState(m_view, &matrix), kQ3ErrorViewNotStarted);
        TQ3SubdivisionStyleData state;
        EXPECT_Q3_ERROR(Q3View_GetSubdivisionStyleState(m_view, &state), kQ3ErrorViewNotStarted);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_GetDecomposed(curve, m_view), nullptr), kQ3ErrorViewNotStarted);
    }
}

TEST_F(ViewApiTest, ObjectSubmitTakesEveryDrawableAndRejectsOthers)
{
    configure();
    const Submittables submittables;
    const auto& [listing, data, curve, set, style, styleObject] = submittables;
    const TQ3Vector3D offset = {0.5f, 0, 0};
    TQ3TransformObject transform = Q3TranslateTransform_New(&offset);

    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    EXPECT_EQ(Q3Object_Submit(set, m_view), kQ3Success);
    EXPECT_EQ(Q3Object_Submit(styleObject, m_view), kQ3Success);
    EXPECT_EQ(Q3Object_Submit(transform, m_view), kQ3Success);
    TQ3SubdivisionStyleData state{};
    EXPECT_EQ(Q3View_GetSubdivisionStyleState(m_view, &state), kQ3Success);
    EXPECT_EQ(state.method, kQ3SubdivisionMethodConstant);
    TQ3Matrix4x4 matrix{};
    EXPECT_EQ(Q3View_GetLocalToWorldMatrixState(m_view, &matrix), kQ3Success);
    EXPECT_FLOAT_EQ(matrix.value[3][0], 0.5f);
    EXPECT_EQ(Q3Object_Submit(curve, m_view), kQ3Success);

    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_Submit(m_camera, m_view), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Object_Submit(m_context, m_view), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Object_Submit(m_renderer, m_view), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Object_Submit(m_view, m_view), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Object_Submit(curve, curve), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Object_Submit(nullptr, m_view), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Object_Submit(curve, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Object_Submit(deadHandle(), m_view), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3Object_Submit(curve, deadHandle()), kQ3ErrorInvalidObject);
    EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
    Q3Object_Dispose(transform);
}

TEST_F(ViewApiTest, CancelEndsTheLoopWithCancelledAndIgnoresLaterSubmits)
{
    configure();
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    EXPECT_EQ(Q3View_Cancel(m_view), kQ3Success);
    EXPECT_EQ(Q3NURBCurve_Submit(&data, m_view), kQ3Success);
    EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusCancelled);
    // The loop is over: the image holds the clear only (nothing got drawn).
    for (unsigned long y = 0; y < m_image.height(); ++y)
        for (unsigned long x = 0; x < m_image.width(); ++x)
            ASSERT_FALSE(m_image.lit(x, y));
    EXPECT_Q3_ERROR(Q3View_EndRendering(m_view), kQ3ErrorRenderingNotStarted);
    // The next loop is not cancelled.
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
}

TEST_F(ViewApiTest, CancelKeepsWhatWasDrawnBeforeIt)
{
    configure();
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    EXPECT_EQ(Q3NURBCurve_Submit(&data, m_view), kQ3Success);
    EXPECT_EQ(Q3View_Cancel(m_view), kQ3Success);
    EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusCancelled);
    std::size_t lit = 0;
    for (unsigned long y = 0; y < m_image.height(); ++y)
        for (unsigned long x = 0; x < m_image.width(); ++x)
            lit += m_image.lit(x, y) ? 1 : 0;
    EXPECT_GT(lit, 20u);
}

TEST_F(ViewApiTest, CancelOutsideALoopDoesNothing)
{
    EXPECT_EQ(Q3View_Cancel(m_view), kQ3Success);
    configure();
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_Cancel(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_Cancel(m_camera), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_Cancel(deadHandle()), kQ3ErrorInvalidObject);
}

TEST_F(ViewApiTest, SyncFailsOnlyInsideARenderingLoop)
{
    configure();
    EXPECT_EQ(Q3View_Sync(m_view), kQ3Success);
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_Sync(m_view), kQ3Failure), kQ3ErrorRenderingIsActive);
    EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
    EXPECT_EQ(Q3View_Sync(m_view), kQ3Success);
    ASSERT_EQ(Q3View_StartBoundingBox(m_view, kQ3ComputeBoundsExact), kQ3Success);
    EXPECT_EQ(Q3View_Sync(m_view), kQ3Success);
    TQ3BoundingBox box;
    Q3View_EndBoundingBox(m_view, &box);
    EXPECT_Q3_ERROR(Q3View_Sync(nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_Sync(m_renderer), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_Sync(deadHandle()), kQ3ErrorInvalidObject);
}

TEST_F(ViewApiTest, DisposingAViewInsideALoopEndsIt)
{
    configure();
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    Q3NURBCurve_Submit(&data, m_view);
    EXPECT_EQ(Q3Object_Dispose(m_view), kQ3Success);
    m_view = nullptr;
    // Another view renders into the same draw context at once.
    TestView other(m_image.pixmap());
    EXPECT_EQ(other.render([&](TQ3ViewObject v) { Q3NURBCurve_Submit(&data, v); }), kQ3ViewStatusDone);
}

TEST_F(ViewApiTest, ChangesToTheDrawContextDuringALoopTakeEffectAtTheNextOne)
{
    configure();
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    Pixmap second(64, 48);
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    ASSERT_EQ(Q3PixmapDrawContext_SetPixmap(m_context, &second.pixmap()), kQ3Success);
    Q3NURBCurve_Submit(&data, m_view);
    ASSERT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
    EXPECT_NE(m_image.word(0, 0), 0x5A5A5A5Au);
    EXPECT_EQ(second.word(0, 0), 0x5A5A5A5Au);
    ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
    ASSERT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
    EXPECT_NE(second.word(0, 0), 0x5A5A5A5Au);
}

TEST_F(ViewApiTest, APixmapLargerThanTheRendererSupportsFailsAtStart)
{
    // llvmpipe's largest image is 16384 pixels wide.
    Pixmap wide(20000, 1);
    TestView view(wide.pixmap());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_StartRendering(view.view()), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(Q3View_EndRendering(view.view()), kQ3ErrorRenderingNotStarted);
}

} // namespace
