// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Classes of bad input from docs/robustness.md that cut across the families
// and had no test of their own: stray pointers and disposed handles given to
// every kind of call, double disposes of shared and non-shared objects, and
// a NURB curve whose point count no array could hold. Each must fail with
// the documented error and without reading memory that is not there
// (AddressSanitizer runs these in CI).

#include "RenderTestSupport.h"

#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"

#include <climits>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace {

using namespace q3test;

class RobustnessApiTest : public Q3ApiTest {};

/// One call of each family that takes a handle of its own kind, run with
/// `handle` in that place.
std::vector<std::pair<std::string, std::function<void(TQ3Object)>>> callsTaking()
{
    return {
        {"Q3Object_GetType", [](TQ3Object h) { Q3Object_GetType(h); }},
        {"Q3Shared_GetReference", [](TQ3Object h) { Q3Shared_GetReference(h); }},
        {"Q3Object_Duplicate", [](TQ3Object h) { Q3Object_Duplicate(h); }},
        {"Q3NURBCurve_SetKnot", [](TQ3Object h) { Q3NURBCurve_SetKnot(h, 0, 0.0f); }},
        {"Q3SubdivisionStyle_GetData",
         [](TQ3Object h) {
             TQ3SubdivisionStyleData data{};
             Q3SubdivisionStyle_GetData(h, &data);
         }},
        {"Q3AttributeSet_Empty", [](TQ3Object h) { Q3AttributeSet_Empty(h); }},
        {"Q3Camera_GetType", [](TQ3Object h) { Q3Camera_GetType(h); }},
        {"Q3DrawContext_SetPaneState", [](TQ3Object h) { Q3DrawContext_SetPaneState(h, kQ3False); }},
        {"Q3Renderer_GetType", [](TQ3Object h) { Q3Renderer_GetType(h); }},
        {"Q3View_StartRendering", [](TQ3Object h) { Q3View_StartRendering(h); }},
        {"Q3View_StartBoundingBox", [](TQ3Object h) { Q3View_StartBoundingBox(h, kQ3ComputeBoundsExact); }},
        {"Q3Push_Submit", [](TQ3Object h) { Q3Push_Submit(h); }},
        {"Q3Object_Dispose", [](TQ3Object h) { Q3Object_Dispose(h); }},
    };
}

// Pointers Q3 never handed out: into the caller's stack, into a caller's data
// structure, into the middle of a live object. The registry compares
// addresses without reading through them.
TEST_F(RobustnessApiTest, StrayPointersAreRejectedByEveryKindOfCall)
{
    Listing1 listing;
    TQ3NURBCurveData data = listing.data();
    TQ3GeometryObject curve = Q3NURBCurve_New(&data);
    int local[4] = {0, 0, 0, 0};
    const std::vector<TQ3Object> strays = {
        reinterpret_cast<TQ3Object>(local),
        reinterpret_cast<TQ3Object>(&data),
        reinterpret_cast<TQ3Object>(reinterpret_cast<char*>(curve) + 8),
        reinterpret_cast<TQ3Object>(std::uintptr_t{0x1000}),
    };
    for (const auto& [name, call] : callsTaking())
        for (TQ3Object stray : strays)
            EXPECT_Q3_ERROR(call(stray), kQ3ErrorInvalidObject);
    EXPECT_EQ(local[0], 0);
    EXPECT_EQ(data.order, 4u);
    Q3Object_Dispose(curve);
}

// A disposed handle of each kind, given to calls of every family.
TEST_F(RobustnessApiTest, DisposedHandlesAreRejectedByEveryKindOfCall)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    const TQ3SubdivisionStyleData style{kQ3SubdivisionMethodConstant, 4.0f, 4.0f};
    const TQ3OrthographicCameraData camera = listing1OrthographicCamera();
    Pixmap image(8, 8);
    const TQ3PixmapDrawContextData context = pixmapContextData(image.pixmap());
    const TQ3Vector3D offset{1.0f, 0.0f, 0.0f};
    std::vector<TQ3Object> dead = {
        Q3NURBCurve_New(&data),
        Q3SubdivisionStyle_New(&style),
        Q3TranslateTransform_New(&offset),
        Q3AttributeSet_New(),
        Q3OrthographicCamera_New(&camera),
        Q3PixmapDrawContext_New(&context),
        Q3Renderer_NewFromType(kQ3RendererTypeInteractive),
        Q3View_New(),
    };
    // Made before the others are disposed, so that it cannot take the
    // address of one of them; it keeps the registry from being empty.
    TQ3GeometryObject live = Q3NURBCurve_New(&data);
    for (TQ3Object object : dead) {
        ASSERT_NE(object, nullptr);
        ASSERT_EQ(Q3Object_Dispose(object), kQ3Success);
    }
    for (const auto& [name, call] : callsTaking())
        for (TQ3Object object : dead)
            EXPECT_Q3_ERROR(call(object), kQ3ErrorInvalidObject);
    Q3Object_Dispose(live);
}

// The second dispose of a handle whose last reference is gone fails, for a
// shared object and for a view (which is not shared: disposed at once); a
// shared object with a second reference survives the first dispose.
TEST_F(RobustnessApiTest, DisposingTwiceFailsOnlyOnceTheLastReferenceIsGone)
{
    Listing1 listing;
    const TQ3NURBCurveData data = listing.data();
    TQ3GeometryObject curve = Q3NURBCurve_New(&data);
    EXPECT_EQ(Q3Shared_GetReference(curve), curve);
    EXPECT_EQ(Q3Object_Dispose(curve), kQ3Success);
    EXPECT_EQ(Q3Object_Dispose(curve), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_Dispose(curve), kQ3Failure), kQ3ErrorInvalidObject);

    TQ3ViewObject view = Q3View_New();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shared_GetReference(view), nullptr), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(Q3Object_Dispose(view), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_Dispose(view), kQ3Failure), kQ3ErrorInvalidObject);

    // An object a view holds outlives the caller's reference; disposing the
    // view then releases it, and the caller's old handle is dead.
    TQ3CameraObject camera = nullptr;
    {
        const TQ3OrthographicCameraData cameraData = listing1OrthographicCamera();
        camera = Q3OrthographicCamera_New(&cameraData);
    }
    view = Q3View_New();
    EXPECT_EQ(Q3View_SetCamera(view, camera), kQ3Success);
    EXPECT_EQ(Q3Object_Dispose(camera), kQ3Success);
    EXPECT_EQ(Q3Camera_GetType(camera), kQ3CameraTypeOrthographic);
    EXPECT_EQ(Q3Object_Dispose(view), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_Dispose(camera), kQ3Failure), kQ3ErrorInvalidObject);
}

// QD3DGeometry.h: numPoints + order and the byte size of each array must fit
// in a size_t (kQ3ErrorParameterOutOfRange), checked before the arrays are
// read: the arrays here hold four points, so any read past them is caught by
// AddressSanitizer.
TEST_F(RobustnessApiTest, APointCountNoArrayCouldHoldIsRejectedBeforeTheArraysAreRead)
{
    Listing1 listing;
    Pixmap image(8, 8);
    TestView view(image.pixmap());
    TQ3GeometryObject curve = nullptr;
    {
        const TQ3NURBCurveData good = listing.data();
        curve = Q3NURBCurve_New(&good);
    }
    for (unsigned long count : {ULONG_MAX, ULONG_MAX - 3, ULONG_MAX / 16 + 1, 1UL << 62}) {
        TQ3NURBCurveData data = listing.data();
        data.numPoints = count;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_New(&data), nullptr), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_SetData(curve, &data), kQ3Failure), kQ3ErrorParameterOutOfRange);
        ASSERT_EQ(Q3View_StartBoundingBox(view.view(), kQ3ComputeBoundsExact), kQ3Success);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3NURBCurve_Submit(&data, view.view()), kQ3Failure),
                        kQ3ErrorParameterOutOfRange);
        TQ3BoundingBox box{};
        EXPECT_EQ(Q3View_EndBoundingBox(view.view(), &box), kQ3ViewStatusDone);
        EXPECT_EQ(box.isEmpty, kQ3True);
    }
    float knot = 0.0f;
    EXPECT_EQ(Q3NURBCurve_GetKnot(curve, 7, &knot), kQ3Success);
    EXPECT_EQ(knot, 1.0f);
    Q3Object_Dispose(curve);
}

} // namespace
