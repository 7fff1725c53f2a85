// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The QD3DRenderer.h calls that complete Apple's portable renderer API in
// Q3: settings dialogs and configuration data (Q3's renderers have neither),
// a renderer's progress and end-of-frame reports to a view
// (Q3XView_IdleProgress, Q3XView_EndFrame) and an attribute set's mask
// (Q3XAttributeSet_GetMask); each with bad input.

#include "RenderTestSupport.h"

#include "QD3DSet.h"

#include <vector>

namespace {

using namespace q3test;

struct Reports {
    std::vector<std::pair<unsigned long, unsigned long>> progress;
    int idle = 0;
    int endFrames = 0;
    bool cancel = false;
};

TQ3Status onProgress(TQ3ViewObject, const void* data, unsigned long current, unsigned long completed)
{
    Reports& r = *static_cast<Reports*>(const_cast<void*>(data));
    r.progress.emplace_back(current, completed);
    return r.cancel && current > 0 ? kQ3Failure : kQ3Success;
}

TQ3Status onIdle(TQ3ViewObject, const void* data)
{
    Reports& r = *static_cast<Reports*>(const_cast<void*>(data));
    ++r.idle;
    return r.cancel ? kQ3Failure : kQ3Success;
}

void onEndFrame(TQ3ViewObject, void* data)
{
    ++static_cast<Reports*>(data)->endFrames;
}

class RendererToolsApiTest : public Q3ApiTest {};

TEST_F(RendererToolsApiTest, RenderersHaveNoSettingsDialog)
{
    for (TQ3ObjectType type : {kQ3RendererTypeInteractive, kQ3RendererTypeWireFrame}) {
        TQ3RendererObject renderer = Q3Renderer_NewFromType(type);
        EXPECT_EQ(Q3Renderer_HasModalConfigure(renderer), kQ3False);
        TQ3DialogAnchor anchor{nullptr};
        TQ3Boolean canceled = kQ3False;
        ASSERT_EQ(Q3Renderer_ModalConfigure(renderer, anchor, &canceled), kQ3Success);
        EXPECT_EQ(canceled, kQ3True) << "as if the user cancelled at once";
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Renderer_ModalConfigure(renderer, anchor, nullptr), kQ3Failure),
                        kQ3ErrorNULLParameter);
        Q3Object_Dispose(renderer);
    }
    TQ3AttributeSet notRenderer = Q3AttributeSet_New();
    TQ3Boolean canceled = kQ3False;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Renderer_HasModalConfigure(nullptr), kQ3False), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Renderer_HasModalConfigure(notRenderer), kQ3False), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Renderer_ModalConfigure(notRenderer, TQ3DialogAnchor{nullptr}, &canceled), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_EQ(canceled, kQ3False);
    Q3Object_Dispose(notRenderer);
}

TEST_F(RendererToolsApiTest, ConfigurationDataIsEmpty)
{
    TQ3RendererObject renderer = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
    unsigned long size = 99;
    ASSERT_EQ(Q3Renderer_GetConfigurationData(renderer, nullptr, 0, &size), kQ3Success);
    EXPECT_EQ(size, 0u) << "the size a buffer needs";
    unsigned char buffer[8] = {7, 7, 7, 7, 7, 7, 7, 7};
    size = 99;
    ASSERT_EQ(Q3Renderer_GetConfigurationData(renderer, buffer, sizeof buffer, &size), kQ3Success);
    EXPECT_EQ(size, 0u);
    EXPECT_EQ(buffer[0], 7) << "nothing written";
    ASSERT_EQ(Q3Renderer_SetConfigurationData(renderer, buffer, 0), kQ3Success) << "what Get gave back";
    ASSERT_EQ(Q3Renderer_SetConfigurationData(renderer, nullptr, 0), kQ3Success);

    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Renderer_GetConfigurationData(renderer, buffer, 8, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Renderer_SetConfigurationData(renderer, nullptr, 4), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Renderer_SetConfigurationData(renderer, buffer, 4), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Renderer_SetConfigurationData(renderer, buffer, UINT32_MAX), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Renderer_GetConfigurationData(nullptr, buffer, 8, &size), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Renderer_SetConfigurationData(nullptr, buffer, 0), kQ3Failure),
                    kQ3ErrorNULLParameter);
    Q3Object_Dispose(renderer);
}

TEST_F(RendererToolsApiTest, IdleProgressReachesTheViewsMethodDuringRendering)
{
    Pixmap image(32, 32);
    TestView view(image.pixmap());
    Reports reports;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XView_IdleProgress(view.view(), 0, 3), kQ3Failure), kQ3ErrorRenderingNotStarted);
    ASSERT_EQ(Q3View_SetIdleProgressMethod(view.view(), onProgress, &reports), kQ3Success);
    const TQ3ViewStatus status = view.render([&](TQ3ViewObject v) {
        for (unsigned long step = 0; step <= 3; ++step)
            EXPECT_EQ(Q3XView_IdleProgress(v, step, 3), kQ3Success);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3XView_IdleProgress(v, 4, 3), kQ3Failure), kQ3ErrorInvalidParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3XView_IdleProgress(v, UINT32_MAX, 0), kQ3Failure), kQ3ErrorInvalidParameter);
    });
    EXPECT_EQ(status, kQ3ViewStatusDone);
    const std::vector<std::pair<unsigned long, unsigned long>> expected{{0, 3}, {1, 3}, {2, 3}, {3, 3}};
    EXPECT_EQ(reports.progress, expected);

    // Without a progress method the idle method is called; a failure from it
    // cancels the loop, and the call says so without an error.
    ASSERT_EQ(Q3View_SetIdleProgressMethod(view.view(), nullptr, nullptr), kQ3Success);
    ASSERT_EQ(Q3View_SetIdleMethod(view.view(), onIdle, &reports), kQ3Success);
    reports.cancel = true;
    TQ3Status reported = kQ3Success;
    const TQ3ViewStatus cancelled = view.render([&](TQ3ViewObject v) { reported = Q3XView_IdleProgress(v, 1, 2); });
    EXPECT_EQ(reported, kQ3Failure);
    EXPECT_EQ(reports.idle, 1);
    EXPECT_EQ(cancelled, kQ3ViewStatusCancelled);

    TQ3AttributeSet notView = Q3AttributeSet_New();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XView_IdleProgress(nullptr, 0, 0), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XView_IdleProgress(notView, 0, 0), kQ3Failure), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(notView);
}

TEST_F(RendererToolsApiTest, EndFrameCallsTheEndFrameMethodOutsideARenderingLoop)
{
    Pixmap image(32, 32);
    TestView view(image.pixmap());
    Reports reports;
    ASSERT_EQ(Q3XView_EndFrame(view.view()), kQ3Success) << "no method: nothing to call";
    ASSERT_EQ(Q3View_SetEndFrameMethod(view.view(), onEndFrame, &reports), kQ3Success);
    ASSERT_EQ(Q3XView_EndFrame(view.view()), kQ3Success);
    EXPECT_EQ(reports.endFrames, 1);
    EXPECT_EQ(view.render([&](TQ3ViewObject v) {
                  EXPECT_Q3_ERROR(EXPECT_EQ(Q3XView_EndFrame(v), kQ3Failure), kQ3ErrorRenderingIsActive);
              }),
              kQ3ViewStatusDone);
    EXPECT_EQ(reports.endFrames, 2) << "the one Q3View_EndRendering called";
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XView_EndFrame(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    TQ3RendererObject notView = Q3Renderer_NewFromType(kQ3RendererTypeWireFrame);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XView_EndFrame(notView), kQ3Failure), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(notView);
}

TEST_F(RendererToolsApiTest, AttributeSetMaskHasOneBitPerAttributeHeld)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    EXPECT_EQ(Q3XAttributeSet_GetMask(set), TQ3XAttributeMask(kQ3XAttributeMaskNone));
    const TQ3ColorRGB red{1, 0, 0};
    const TQ3Vector3D up{0, 1, 0};
    const TQ3Switch on = kQ3On;
    const TQ3Param2D uv{0.5f, 0.5f};
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &red);
    Q3AttributeSet_Add(set, kQ3AttributeTypeNormal, &up);
    EXPECT_EQ(Q3XAttributeSet_GetMask(set), TQ3XAttributeMask((1u << 4) | (1u << 2)));
    Q3AttributeSet_Add(set, kQ3AttributeTypeHighlightState, &on);
    Q3AttributeSet_Add(set, kQ3AttributeTypeShadingUV, &uv);
    EXPECT_EQ(Q3XAttributeSet_GetMask(set),
              TQ3XAttributeMask(kQ3XAttributeMaskDiffuseColor | kQ3XAttributeMaskNormal |
                                kQ3XAttributeMaskHighlightState | kQ3XAttributeMaskShadingUV));
    EXPECT_EQ(Q3XAttributeSet_GetMask(set) & ~kQ3XAttributeMaskAll, 0u);
    Q3AttributeSet_Clear(set, kQ3AttributeTypeNormal);
    EXPECT_EQ(Q3XAttributeSet_GetMask(set) & kQ3XAttributeMaskNormal, 0u);

    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XAttributeSet_GetMask(nullptr), 0u), kQ3ErrorNULLParameter);
    TQ3RendererObject notSet = Q3Renderer_NewFromType(kQ3RendererTypeWireFrame);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XAttributeSet_GetMask(notSet), 0u), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(notSet);
    Q3Object_Dispose(set);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XAttributeSet_GetMask(set), 0u), kQ3ErrorInvalidObject);
}

} // namespace
