// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DView.h"
#include "api/Entry.h"
#include "api/SetEntry.h"
#include "core/AttributeSet.h"
#include "core/EnumValue.h"
#include "group/Group.h"
#include "render/Renderer.h"
#include "view/Camera.h"
#include "view/DrawContext.h"
#include "view/Pick.h"
#include "view/Pass.h"
#include "view/StateOperator.h"
#include "view/View.h"

using namespace q3;
using namespace q3::api;

namespace {

// The graphics state Get calls: the view (which must run a loop), then the
// output pointer, then *out = read(state). Nothing is written on failure.
template <class Value, class Read>
TQ3Status readState(const char* function, TQ3ViewObject view, Value* out, const char* outName, Read read)
{
    return guardStatus(function, [&] {
        View& source = lookup<View>(view, "view");
        requireNonNull(out, outName);
        *out = read(source.graphicsState());
    });
}

} // namespace

extern "C" {

TQ3ViewObject Q3View_New(void)
{
    return guard(__func__, TQ3ViewObject{nullptr},
                 []() -> TQ3ViewObject { return makeObject<View>(); });
}

TQ3Status Q3View_Cancel(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").cancel(); });
}

TQ3Status Q3View_SetIdleMethod(TQ3ViewObject view, TQ3ViewIdleMethod idleMethod, const void* idleData)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").setIdleMethod(idleMethod, idleData); });
}

TQ3Status Q3View_SetIdleProgressMethod(TQ3ViewObject view, TQ3ViewIdleProgressMethod idleMethod,
                                       const void* idleData)
{
    return guardStatus(__func__,
                       [&] { lookup<View>(view, "view").setIdleProgressMethod(idleMethod, idleData); });
}

TQ3Status Q3View_SetEndFrameMethod(TQ3ViewObject view, TQ3ViewEndFrameMethod endFrame, void* endFrameData)
{
    return guardStatus(__func__,
                       [&] { lookup<View>(view, "view").setEndFrameMethod(endFrame, endFrameData); });
}

TQ3Status Q3View_SetRendererByType(TQ3ViewObject view, TQ3ObjectType theType)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").setRendererByType(theType); });
}

TQ3Status Q3View_SetRenderer(TQ3ViewObject view, TQ3RendererObject renderer)
{
    return setHeld(__func__, view, "view", renderer, "renderer", &View::setRenderer);
}

TQ3Status Q3View_GetRenderer(TQ3ViewObject view, TQ3RendererObject* renderer)
{
    return getHeld(__func__, view, "view", renderer, "renderer", &View::renderer);
}

TQ3Status Q3View_StartRendering(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").startRendering(); });
}

TQ3ViewStatus Q3View_EndRendering(TQ3ViewObject view)
{
    return guard(__func__, kQ3ViewStatusError, [&] { return lookup<View>(view, "view").endRendering(); });
}

TQ3Status Q3View_Sync(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").sync(); });
}

TQ3Status Q3View_StartBoundingBox(TQ3ViewObject view, TQ3ComputeBounds computeBounds)
{
    return guardStatus(__func__,
                       [&] { lookup<View>(view, "view").startBoundingBox(computeBounds); });
}

TQ3ViewStatus Q3View_EndBoundingBox(TQ3ViewObject view, TQ3BoundingBox* result)
{
    return guard(__func__, kQ3ViewStatusError, [&] {
        View& target = lookup<View>(view, "view");
        requireNonNull(result, "result");
        return target.endBoundingBox(*result);
    });
}

TQ3Status Q3View_StartBoundingSphere(TQ3ViewObject view, TQ3ComputeBounds computeBounds)
{
    return guardStatus(__func__,
                       [&] { lookup<View>(view, "view").startBoundingSphere(computeBounds); });
}

TQ3ViewStatus Q3View_EndBoundingSphere(TQ3ViewObject view, TQ3BoundingSphere* result)
{
    return guard(__func__, kQ3ViewStatusError, [&] {
        View& target = lookup<View>(view, "view");
        requireNonNull(result, "result");
        return target.endBoundingSphere(*result);
    });
}

TQ3Status Q3View_StartPicking(TQ3ViewObject view, TQ3PickObject pick)
{
    return guardStatus(__func__, [&] {
        View& target = lookup<View>(view, "view");
        target.startPicking(lookup<Pick>(pick, "pick"));
    });
}

TQ3ViewStatus Q3View_EndPicking(TQ3ViewObject view)
{
    return guard(__func__, kQ3ViewStatusError, [&] { return lookup<View>(view, "view").endPicking(); });
}

TQ3Status Q3View_GetCamera(TQ3ViewObject view, TQ3CameraObject* camera)
{
    return getHeld(__func__, view, "view", camera, "camera", &View::camera);
}

TQ3Status Q3View_SetCamera(TQ3ViewObject view, TQ3CameraObject camera)
{
    return setHeld(__func__, view, "view", camera, "camera", &View::setCamera);
}

TQ3Status Q3View_SetDrawContext(TQ3ViewObject view, TQ3DrawContextObject drawContext)
{
    return setHeld(__func__, view, "view", drawContext, "drawContext", &View::setDrawContext);
}

TQ3Status Q3View_GetDrawContext(TQ3ViewObject view, TQ3DrawContextObject* drawContext)
{
    return getHeld(__func__, view, "view", drawContext, "drawContext", &View::drawContext);
}

TQ3Status Q3View_GetLocalToWorldMatrixState(TQ3ViewObject view, TQ3Matrix4x4* matrix)
{
    return guardStatus(__func__, [&] {
        View& source = lookup<View>(view, "view");
        requireNonNull(matrix, "matrix");
        *matrix = source.localToWorldState();
    });
}

TQ3Status Q3View_GetSubdivisionStyleState(TQ3ViewObject view,
                                          TQ3SubdivisionStyleData* subdivisionStyle)
{
    return guardStatus(__func__, [&] {
        View& source = lookup<View>(view, "view");
        requireNonNull(subdivisionStyle, "subdivisionStyle");
        *subdivisionStyle = source.subdivisionStyleState();
    });
}

TQ3Status Q3Push_Submit(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").push(); });
}

TQ3Status Q3Pop_Submit(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").pop(); });
}

TQ3Status Q3View_SetLightGroup(TQ3ViewObject view, TQ3GroupObject lightGroup)
{
    return setHeldOptional(__func__, view, "view", lightGroup, "lightGroup", &View::setLightGroup);
}

TQ3Status Q3View_GetLightGroup(TQ3ViewObject view, TQ3GroupObject* lightGroup)
{
    return getHeld(__func__, view, "view", lightGroup, "lightGroup", &View::lightGroup);
}

TQ3Status Q3View_Flush(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").flush(); });
}

TQ3Status Q3View_GetWorldToFrustumMatrixState(TQ3ViewObject view, TQ3Matrix4x4* matrix)
{
    return guardStatus(__func__, [&] {
        View& source = lookup<View>(view, "view");
        requireNonNull(matrix, "matrix");
        *matrix = source.worldToFrustumState();
    });
}

TQ3Status Q3View_GetFrustumToWindowMatrixState(TQ3ViewObject view, TQ3Matrix4x4* matrix)
{
    return guardStatus(__func__, [&] {
        View& source = lookup<View>(view, "view");
        requireNonNull(matrix, "matrix");
        *matrix = source.frustumToWindowState();
    });
}

TQ3Status Q3View_GetBackfacingStyleState(TQ3ViewObject view, TQ3BackfacingStyle* backfacingStyle)
{
    return readState(__func__, view, backfacingStyle, "backfacingStyle",
                     [](const GraphicsState& state) { return state.draw.backfacing; });
}

TQ3Status Q3View_GetInterpolationStyleState(TQ3ViewObject view, TQ3InterpolationStyle* interpolationType)
{
    return readState(__func__, view, interpolationType, "interpolationType",
                     [](const GraphicsState& state) { return state.draw.interpolation; });
}

TQ3Status Q3View_GetFillStyleState(TQ3ViewObject view, TQ3FillStyle* fillStyle)
{
    return readState(__func__, view, fillStyle, "fillStyle",
                     [](const GraphicsState& state) { return state.draw.fill; });
}

TQ3Status Q3View_GetHighlightStyleState(TQ3ViewObject view, TQ3AttributeSet* highlightStyle)
{
    return readState(__func__, view, highlightStyle, "highlightStyle", [](const GraphicsState& state) {
        return static_cast<TQ3AttributeSet>(handOut(state.draw.highlight));
    });
}

TQ3Status Q3View_GetOrientationStyleState(TQ3ViewObject view, TQ3OrientationStyle* fontFacingDirectionStyle)
{
    return readState(__func__, view, fontFacingDirectionStyle, "fontFacingDirectionStyle",
                     [](const GraphicsState& state) { return state.draw.orientation; });
}

TQ3Status Q3View_GetReceiveShadowsStyleState(TQ3ViewObject view, TQ3Boolean* receives)
{
    return readState(__func__, view, receives, "receives",
                     [](const GraphicsState& state) { return state.draw.receiveShadows; });
}

TQ3Status Q3View_GetPickIDStyleState(TQ3ViewObject view, unsigned long* pickIDStyle)
{
    return readState(__func__, view, pickIDStyle, "pickIDStyle",
                     [](const GraphicsState& state) { return state.draw.pickID; });
}

TQ3Status Q3View_GetPickPartsStyleState(TQ3ViewObject view, TQ3PickParts* pickPartsStyle)
{
    return readState(__func__, view, pickPartsStyle, "pickPartsStyle",
                     [](const GraphicsState& state) { return state.draw.pickParts; });
}

TQ3Status Q3View_GetAntiAliasStyleState(TQ3ViewObject view, TQ3AntiAliasStyleData* antiAliasData)
{
    return readState(__func__, view, antiAliasData, "antiAliasData",
                     [](const GraphicsState& state) { return state.draw.antiAlias; });
}

TQ3Status Q3View_GetDefaultAttributeSet(TQ3ViewObject view, TQ3AttributeSet* attributeSet)
{
    return getValue<View>(__func__, view, "view", attributeSet, "attributeSet",
                          [&](const View& source) { return source.defaultAttributeSet().detach(); });
}

TQ3Status Q3View_SetDefaultAttributeSet(TQ3ViewObject view, TQ3AttributeSet attributeSet)
{
    return setHeldOptional(__func__, view, "view", attributeSet, "attributeSet", &View::setDefaultAttributeSet);
}

TQ3Status Q3View_GetAttributeSetState(TQ3ViewObject view, TQ3AttributeSet* attributeSet)
{
    return readState(__func__, view, attributeSet, "attributeSet", [](const GraphicsState& state) {
        return static_cast<TQ3AttributeSet>(AttributeSet::fromValues(state.attributes).detach());
    });
}

TQ3Status Q3View_GetAttributeState(TQ3ViewObject view, TQ3AttributeType attributeType, void* data)
{
    return guardStatus(__func__, [&] {
        View& source = lookup<View>(view, "view");
        requireNonNull(data, "data");
        const GraphicsState& state = source.graphicsState();
        api::getElement(*AttributeSet::fromValues(state.attributes), attributeType, data);
    });
}

TQ3Boolean Q3View_IsBoundingBoxVisible(TQ3ViewObject view, const TQ3BoundingBox* bbox)
{
    return guard(__func__, kQ3False, [&] {
        View& source = lookup<View>(view, "view");
        requireNonNull(bbox, "bbox");
        return source.isBoundingBoxVisible(*bbox) ? kQ3True : kQ3False;
    });
}

TQ3Status Q3View_AllowAllGroupCulling(TQ3ViewObject view, TQ3Boolean allowCulling)
{
    return guardStatus(__func__, [&] {
        View& target = lookup<View>(view, "view");
        const long allow = enumValue(allowCulling);
        if (allow != kQ3True && allow != kQ3False)
            fail(kQ3ErrorInvalidParameter,
                 "allowCulling " + std::to_string(allow) + " is neither kQ3True nor kQ3False");
        target.allowGroupCulling(allow == kQ3True);
    });
}

TQ3StateOperatorObject Q3Push_New(void)
{
    return guard(__func__, TQ3StateOperatorObject{nullptr},
                 []() -> TQ3StateOperatorObject { return makeShared<StateOperator>(true).detach(); });
}

TQ3StateOperatorObject Q3Pop_New(void)
{
    return guard(__func__, TQ3StateOperatorObject{nullptr},
                 []() -> TQ3StateOperatorObject { return makeShared<StateOperator>(false).detach(); });
}

TQ3Status Q3StateOperator_Submit(TQ3StateOperatorObject stateOperator, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        const StateOperator& op = lookup<StateOperator>(stateOperator, "stateOperator");
        lookup<View>(view, "view").submit(op);
    });
}

} // extern "C"
