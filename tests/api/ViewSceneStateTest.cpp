// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The rest of QD3DView.h's graphics state: the style states' defaults, the
// attribute state and the default attribute set, the frustum and window
// matrices, Q3View_IsBoundingBoxVisible, Q3View_Flush, the light group, and
// the errors of each outside a loop.

#include "RenderTestSupport.h"

#include "QD3DGroup.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"

#include <cmath>
#include <memory>

namespace {

using namespace q3test;

class ViewSceneStateTest : public TestViewApiTest {
protected:
    ViewSceneStateTest() : TestViewApiTest(40, 30) {}

    /// Reads every style state of the view (inside a loop), each call
    /// succeeding.
    void readStyleStates(TQ3BackfacingStyle& backfacing, TQ3InterpolationStyle& interpolation, TQ3FillStyle& fill,
                         TQ3OrientationStyle& orientation, TQ3Boolean& receives, unsigned long& pickID,
                         TQ3PickParts& parts, TQ3AntiAliasStyleData& antiAlias, TQ3AttributeSet& highlight)
    {
        EXPECT_EQ(Q3View_GetBackfacingStyleState(view(), &backfacing), kQ3Success);
        EXPECT_EQ(Q3View_GetInterpolationStyleState(view(), &interpolation), kQ3Success);
        EXPECT_EQ(Q3View_GetFillStyleState(view(), &fill), kQ3Success);
        EXPECT_EQ(Q3View_GetOrientationStyleState(view(), &orientation), kQ3Success);
        EXPECT_EQ(Q3View_GetReceiveShadowsStyleState(view(), &receives), kQ3Success);
        EXPECT_EQ(Q3View_GetPickIDStyleState(view(), &pickID), kQ3Success);
        EXPECT_EQ(Q3View_GetPickPartsStyleState(view(), &parts), kQ3Success);
        EXPECT_EQ(Q3View_GetAntiAliasStyleState(view(), &antiAlias), kQ3Success);
        EXPECT_EQ(Q3View_GetHighlightStyleState(view(), &highlight), kQ3Success);
    }

    static void expectColor(const TQ3ColorRGB& c, float r, float g, float b)
    {
        EXPECT_EQ(c.r, r);
        EXPECT_EQ(c.g, g);
        EXPECT_EQ(c.b, b);
    }

    /// (x, y, z, 1) * m.
    static void apply(const TQ3Matrix4x4& m, double x, double y, double z, double out[4])
    {
        const double in[4] = {x, y, z, 1.0};
        for (int j = 0; j < 4; ++j) {
            out[j] = 0.0;
            for (int i = 0; i < 4; ++i)
                out[j] += in[i] * m.value[i][j];
        }
    }
};

TEST_F(ViewSceneStateTest, StyleStatesStartAtQuickDraw3DsDefaults)
{
    for (int loop = 0; loop < 2; ++loop) {
        if (loop == 0)
            ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
        else
            ASSERT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
        TQ3BackfacingStyle backfacing = TQ3BackfacingStyle(99);
        TQ3InterpolationStyle interpolation = TQ3InterpolationStyle(99);
        TQ3FillStyle fill = TQ3FillStyle(99);
        TQ3OrientationStyle orientation = TQ3OrientationStyle(99);
        TQ3Boolean receives = TQ3Boolean(99);
        unsigned long pickID = 99;
        TQ3PickParts parts = 99;
        TQ3AntiAliasStyleData antiAlias{kQ3On, kQ3AntiAliasModeMaskFilled, 0.25f};
        TQ3AttributeSet highlight = reinterpret_cast<TQ3AttributeSet>(this);
        readStyleStates(backfacing, interpolation, fill, orientation, receives, pickID, parts, antiAlias, highlight);
        EXPECT_EQ(backfacing, kQ3BackfacingStyleBoth);
        EXPECT_EQ(interpolation, kQ3InterpolationStyleVertex);
        EXPECT_EQ(fill, kQ3FillStyleFilled);
        EXPECT_EQ(orientation, kQ3OrientationStyleCounterClockwise);
        EXPECT_EQ(receives, kQ3True);
        EXPECT_EQ(pickID, 0u);
        EXPECT_EQ(parts, (TQ3PickParts)kQ3PickPartsObject);
        EXPECT_EQ(antiAlias.state, kQ3Off);
        EXPECT_EQ(highlight, nullptr);
        if (loop == 0) {
            EXPECT_EQ(Q3View_Flush(view()), kQ3Success);
            EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
        } else {
            TQ3BoundingBox box{};
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_Flush(view()), kQ3Failure), kQ3ErrorRenderingNotStarted);
            EXPECT_EQ(Q3View_EndBoundingBox(view(), &box), kQ3ViewStatusDone);
        }
    }
}

// Each style submitted (immediately, or as an object) becomes the state its
// Get*StyleState reads; a pop brings back what the push saved.
TEST_F(ViewSceneStateTest, StyleStatesFollowSubmittedStylesAndPopBack)
{
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    ASSERT_EQ(Q3Push_Submit(view()), kQ3Success);
    TQ3AttributeSet highlightSet = Q3AttributeSet_New();
    ASSERT_NE(highlightSet, nullptr);
    EXPECT_EQ(Q3BackfacingStyle_Submit(kQ3BackfacingStyleFlip, view()), kQ3Success);
    EXPECT_EQ(Q3InterpolationStyle_Submit(kQ3InterpolationStyleNone, view()), kQ3Success);
    TQ3StyleObject fillObject = Q3FillStyle_New(kQ3FillStyleEdges);
    ASSERT_NE(fillObject, nullptr);
    EXPECT_EQ(Q3Style_Submit(fillObject, view()), kQ3Success);
    Q3Object_Dispose(fillObject);
    EXPECT_EQ(Q3OrientationStyle_Submit(kQ3OrientationStyleClockwise, view()), kQ3Success);
    EXPECT_EQ(Q3ReceiveShadowsStyle_Submit(kQ3False, view()), kQ3Success);
    EXPECT_EQ(Q3PickIDStyle_Submit(77, view()), kQ3Success);
    EXPECT_EQ(Q3PickPartsStyle_Submit(kQ3PickPartsMaskFace | kQ3PickPartsMaskEdge, view()), kQ3Success);
    const TQ3AntiAliasStyleData smooth{kQ3On, kQ3AntiAliasModeMaskEdges, 0.5f};
    EXPECT_EQ(Q3AntiAliasStyle_Submit(&smooth, view()), kQ3Success);
    EXPECT_EQ(Q3HighlightStyle_Submit(highlightSet, view()), kQ3Success);

    TQ3BackfacingStyle backfacing = kQ3BackfacingStyleBoth;
    TQ3InterpolationStyle interpolation = kQ3InterpolationStyleVertex;
    TQ3FillStyle fill = kQ3FillStyleFilled;
    TQ3OrientationStyle orientation = kQ3OrientationStyleCounterClockwise;
    TQ3Boolean receives = kQ3True;
    unsigned long pickID = 0;
    TQ3PickParts parts = 0;
    TQ3AntiAliasStyleData antiAlias{};
    TQ3AttributeSet highlight = nullptr;
    readStyleStates(backfacing, interpolation, fill, orientation, receives, pickID, parts, antiAlias, highlight);
    EXPECT_EQ(backfacing, kQ3BackfacingStyleFlip);
    EXPECT_EQ(interpolation, kQ3InterpolationStyleNone);
    EXPECT_EQ(fill, kQ3FillStyleEdges);
    EXPECT_EQ(orientation, kQ3OrientationStyleClockwise);
    EXPECT_EQ(receives, kQ3False);
    EXPECT_EQ(pickID, 77u);
    EXPECT_EQ(parts, TQ3PickParts(kQ3PickPartsMaskFace | kQ3PickPartsMaskEdge));
    EXPECT_EQ(antiAlias.state, kQ3On);
    EXPECT_EQ(antiAlias.mode, TQ3AntiAliasMode(kQ3AntiAliasModeMaskEdges));
    EXPECT_EQ(antiAlias.quality, 0.5f);
    EXPECT_EQ(highlight, highlightSet);
    if (highlight != nullptr)
        Q3Object_Dispose(highlight); // the state call's reference

    ASSERT_EQ(Q3Pop_Submit(view()), kQ3Success);
    EXPECT_EQ(Q3View_GetBackfacingStyleState(view(), &backfacing), kQ3Success);
    EXPECT_EQ(Q3View_GetFillStyleState(view(), &fill), kQ3Success);
    EXPECT_EQ(Q3View_GetPickIDStyleState(view(), &pickID), kQ3Success);
    EXPECT_EQ(Q3View_GetHighlightStyleState(view(), &highlight), kQ3Success);
    EXPECT_EQ(backfacing, kQ3BackfacingStyleBoth);
    EXPECT_EQ(fill, kQ3FillStyleFilled);
    EXPECT_EQ(pickID, 0u);
    EXPECT_EQ(highlight, nullptr);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
    Q3Object_Dispose(highlightSet);
}

TEST_F(ViewSceneStateTest, StateCallsFailOutsideALoopAndWithNullOutputs)
{
    // A sentinel that is a valid TQ3FillStyle (an out-of-range enum value would be
    // undefined behaviour to read back) and not the default, kQ3FillStyleFilled.
    TQ3FillStyle fill = kQ3FillStylePoints;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_GetFillStyleState(view(), &fill), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_EQ(fill, kQ3FillStylePoints);
    TQ3Matrix4x4 m{};
    m.value[0][0] = 42;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_GetWorldToFrustumMatrixState(view(), &m), kQ3Failure),
                    kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_GetFrustumToWindowMatrixState(view(), &m), kQ3Failure),
                    kQ3ErrorViewNotStarted);
    EXPECT_EQ(m.value[0][0], 42.0f);
    TQ3AttributeSet set = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_GetAttributeSetState(view(), &set), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_EQ(set, nullptr);
    TQ3ColorRGB color{};
    EXPECT_Q3_ERROR(Q3View_GetAttributeState(view(), kQ3AttributeTypeDiffuseColor, &color), kQ3ErrorViewNotStarted);
    const TQ3BoundingBox box{{0, 0, 0}, {1, 1, 1}, kQ3False};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_IsBoundingBoxVisible(view(), &box), kQ3False), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_Flush(view()), kQ3Failure), kQ3ErrorRenderingNotStarted);

    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_GetFillStyleState(view(), nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_GetHighlightStyleState(view(), nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_GetAttributeState(view(), kQ3AttributeTypeDiffuseColor, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_IsBoundingBoxVisible(view(), nullptr), kQ3False), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_GetPickIDStyleState(nullptr, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
}

TEST_F(ViewSceneStateTest, TheAttributeStateFollowsSubmittedSetsAndPopsBack)
{
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    // The defaults: QD3DView.h's kQ3ViewDefault* values.
    TQ3ColorRGB diffuse{}, specular{};
    float ambient = 0, control = 0;
    TQ3Switch highlight = kQ3On;
    ASSERT_EQ(Q3View_GetAttributeState(view(), kQ3AttributeTypeDiffuseColor, &diffuse), kQ3Success);
    ASSERT_EQ(Q3View_GetAttributeState(view(), kQ3AttributeTypeSpecularColor, &specular), kQ3Success);
    ASSERT_EQ(Q3View_GetAttributeState(view(), kQ3AttributeTypeAmbientCoefficient, &ambient), kQ3Success);
    ASSERT_EQ(Q3View_GetAttributeState(view(), kQ3AttributeTypeSpecularControl, &control), kQ3Success);
    ASSERT_EQ(Q3View_GetAttributeState(view(), kQ3AttributeTypeHighlightState, &highlight), kQ3Success);
    expectColor(diffuse, 1, 1, 1);
    expectColor(specular, 0.5f, 0.5f, 0.5f);
    EXPECT_EQ(ambient, 1.0f);
    EXPECT_EQ(control, 4.0f);
    EXPECT_EQ(highlight, kQ3Off);
    TQ3Vector3D normal{7, 7, 7};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_GetAttributeState(view(), kQ3AttributeTypeNormal, &normal), kQ3Failure),
                    kQ3ErrorAttributeNotContained);
    EXPECT_EQ(normal.x, 7.0f);
    EXPECT_Q3_ERROR(Q3View_GetAttributeState(view(), 9999, &normal), kQ3ErrorAttributeInvalidType);

    // A submitted set overrides what it holds; a pop undoes it.
    Q3Push_Submit(view());
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB red{1, 0, 0};
    const TQ3Vector3D up{0, 0, 1};
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &red);
    Q3AttributeSet_Add(set, kQ3AttributeTypeNormal, &up);
    ASSERT_EQ(Q3AttributeSet_Submit(set, view()), kQ3Success);
    Q3Object_Dispose(set);
    Q3View_GetAttributeState(view(), kQ3AttributeTypeDiffuseColor, &diffuse);
    expectColor(diffuse, 1, 0, 0);
    ASSERT_EQ(Q3View_GetAttributeState(view(), kQ3AttributeTypeNormal, &normal), kQ3Success);
    EXPECT_EQ(normal.z, 1.0f);
    TQ3AttributeSet state = nullptr;
    ASSERT_EQ(Q3View_GetAttributeSetState(view(), &state), kQ3Success);
    ASSERT_NE(state, nullptr);
    EXPECT_EQ(Q3AttributeSet_Contains(state, kQ3AttributeTypeNormal), kQ3True);
    EXPECT_EQ(Q3AttributeSet_Contains(state, kQ3AttributeTypeSpecularColor), kQ3True);
    Q3AttributeSet_Get(state, kQ3AttributeTypeDiffuseColor, &diffuse);
    expectColor(diffuse, 1, 0, 0);
    Q3Object_Dispose(state);
    Q3Pop_Submit(view());
    Q3View_GetAttributeState(view(), kQ3AttributeTypeDiffuseColor, &diffuse);
    expectColor(diffuse, 1, 1, 1);
    EXPECT_Q3_ERROR(Q3View_GetAttributeState(view(), kQ3AttributeTypeNormal, &normal), kQ3ErrorAttributeNotContained);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
}

TEST_F(ViewSceneStateTest, TheDefaultAttributeSetStartsEveryTraversal)
{
    TQ3AttributeSet defaults = nullptr;
    ASSERT_EQ(Q3View_GetDefaultAttributeSet(view(), &defaults), kQ3Success);
    ASSERT_NE(defaults, nullptr);
    TQ3ColorRGB diffuse{};
    ASSERT_EQ(Q3AttributeSet_Get(defaults, kQ3AttributeTypeDiffuseColor, &diffuse), kQ3Success);
    expectColor(diffuse, 1, 1, 1);
    Q3Object_Dispose(defaults);

    TQ3AttributeSet mine = Q3AttributeSet_New();
    const TQ3ColorRGB blue{0, 0, 1};
    Q3AttributeSet_Add(mine, kQ3AttributeTypeDiffuseColor, &blue);
    ASSERT_EQ(Q3View_SetDefaultAttributeSet(view(), mine), kQ3Success);
    ASSERT_EQ(Q3View_GetDefaultAttributeSet(view(), &defaults), kQ3Success);
    EXPECT_EQ(defaults, mine);
    Q3Object_Dispose(defaults);
    Q3Object_Dispose(mine); // the view keeps its own reference

    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    Q3View_GetAttributeState(view(), kQ3AttributeTypeDiffuseColor, &diffuse);
    expectColor(diffuse, 0, 0, 1);
    // What the set lacks keeps QuickDraw 3D's default.
    float control = 0;
    ASSERT_EQ(Q3View_GetAttributeState(view(), kQ3AttributeTypeSpecularControl, &control), kQ3Success);
    EXPECT_EQ(control, 4.0f);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_SetDefaultAttributeSet(view(), nullptr), kQ3Failure), kQ3ErrorViewIsStarted);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);

    ASSERT_EQ(Q3View_SetDefaultAttributeSet(view(), nullptr), kQ3Success);
    ASSERT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
    Q3View_GetAttributeState(view(), kQ3AttributeTypeDiffuseColor, &diffuse);
    expectColor(diffuse, 1, 1, 1);
    TQ3BoundingBox box{};
    Q3View_EndBoundingBox(view(), &box);

    TQ3GroupObject group = Q3Group_New();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_SetDefaultAttributeSet(view(), group), kQ3Failure), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(group);
}

TEST_F(ViewSceneStateTest, TheMatricesCarryWorldPointsToPixels)
{
    // The camera shows x -0.5..3.5 and y -1..2 on a 40 x 30 image
    // (listing1OrthographicCamera); hither at distance 1, yon at 100 from
    // z = 10.
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    TQ3Matrix4x4 toFrustum{}, toWindow{};
    ASSERT_EQ(Q3View_GetWorldToFrustumMatrixState(view(), &toFrustum), kQ3Success);
    ASSERT_EQ(Q3View_GetFrustumToWindowMatrixState(view(), &toWindow), kQ3Success);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);

    const Projection project = orthographicProjection(0, 0, 40, 30);
    const double points[][3] = {{-0.5, -1, 0}, {3.5, 2, 0}, {1.5, 0.5, 5}, {0.3, 1.7, -20}};
    for (const auto& p : points) {
        double frustum[4], window[4];
        apply(toFrustum, p[0], p[1], p[2], frustum);
        EXPECT_NEAR(frustum[3], 1.0, 1e-6); // orthographic: w stays 1
        apply(toWindow, frustum[0], frustum[1], frustum[2], window);
        const Point3 expected = project(Point3{p[0], p[1], p[2]});
        EXPECT_NEAR(window[0], expected.x, 1e-4) << p[0] << ", " << p[1];
        EXPECT_NEAR(window[1], expected.y, 1e-4) << p[0] << ", " << p[1];
    }
    // Depth: hither (z = 9) maps to 0, yon (z = -90) to -1.
    double hither[4], yon[4];
    apply(toFrustum, 1.5, 0.5, 9.0, hither);
    apply(toFrustum, 1.5, 0.5, -90.0, yon);
    EXPECT_NEAR(hither[2], 0.0, 1e-5);
    EXPECT_NEAR(yon[2], -1.0, 1e-5);
}

TEST_F(ViewSceneStateTest, ABoxIsVisibleUnlessItIsWhollyBeyondOnePlane)
{
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    const TQ3BoundingBox inside{{1, 0, -1}, {2, 1, 1}, kQ3False};
    const TQ3BoundingBox straddling{{3, 0, 0}, {9, 1, 1}, kQ3False};
    const TQ3BoundingBox right{{4, 0, 0}, {9, 1, 1}, kQ3False};
    const TQ3BoundingBox behind{{1, 0, 20}, {2, 1, 30}, kQ3False};
    const TQ3BoundingBox beyondYon{{1, 0, -200}, {2, 1, -95}, kQ3False};
    const TQ3BoundingBox empty{{1, 0, 0}, {2, 1, 1}, kQ3True};
    EXPECT_EQ(Q3View_IsBoundingBoxVisible(view(), &inside), kQ3True);
    EXPECT_EQ(Q3View_IsBoundingBoxVisible(view(), &straddling), kQ3True);
    EXPECT_EQ(Q3View_IsBoundingBoxVisible(view(), &right), kQ3False);
    EXPECT_EQ(Q3View_IsBoundingBoxVisible(view(), &behind), kQ3False);
    EXPECT_EQ(Q3View_IsBoundingBoxVisible(view(), &beyondYon), kQ3False);
    EXPECT_EQ(Q3View_IsBoundingBoxVisible(view(), &empty), kQ3False);
    // In local coordinates: translated back into view, the box is visible.
    const TQ3Vector3D left{-3, 0, 0};
    Q3TranslateTransform_Submit(&left, view());
    EXPECT_EQ(Q3View_IsBoundingBoxVisible(view(), &right), kQ3True);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
}

TEST_F(ViewSceneStateTest, TheLightGroupIsALightGroupOrNothing)
{
    TQ3GroupObject read = reinterpret_cast<TQ3GroupObject>(this);
    ASSERT_EQ(Q3View_GetLightGroup(view(), &read), kQ3Success);
    EXPECT_EQ(read, nullptr);

    TQ3GroupObject lights = Q3LightGroup_New();
    ASSERT_EQ(Q3View_SetLightGroup(view(), lights), kQ3Success);
    ASSERT_EQ(Q3View_GetLightGroup(view(), &read), kQ3Success);
    EXPECT_EQ(read, lights);
    Q3Object_Dispose(read);
    Q3Object_Dispose(lights); // the view keeps its reference
    ASSERT_EQ(Q3View_GetLightGroup(view(), &read), kQ3Success);
    EXPECT_EQ(Q3Group_GetType(read), kQ3GroupTypeLight);
    Q3Object_Dispose(read);

    TQ3GroupObject display = Q3DisplayGroup_New();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_SetLightGroup(view(), display), kQ3Failure), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(display);
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_SetLightGroup(view(), nullptr), kQ3Failure), kQ3ErrorViewIsStarted);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
    ASSERT_EQ(Q3View_SetLightGroup(view(), nullptr), kQ3Success);
    ASSERT_EQ(Q3View_GetLightGroup(view(), &read), kQ3Success);
    EXPECT_EQ(read, nullptr);
    EXPECT_Q3_ERROR(Q3View_GetLightGroup(view(), nullptr), kQ3ErrorNULLParameter);
}

TEST_F(ViewSceneStateTest, ABoundingLoopWithoutACameraHasNoFrustum)
{
    TQ3ViewObject bare = Q3View_New();
    ASSERT_EQ(Q3View_StartBoundingBox(bare, kQ3ComputeBoundsExact), kQ3Success);
    TQ3Matrix4x4 m{};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_GetWorldToFrustumMatrixState(bare, &m), kQ3Failure), kQ3ErrorCameraNotSet);
    const TQ3BoundingBox box{{100, 100, 100}, {101, 101, 101}, kQ3False};
    // Without a frustum every box may be seen.
    EXPECT_EQ(Q3View_IsBoundingBoxVisible(bare, &box), kQ3True);
    TQ3BoundingBox result{};
    EXPECT_EQ(Q3View_EndBoundingBox(bare, &result), kQ3ViewStatusDone);
    Q3Object_Dispose(bare);
}

} // namespace
