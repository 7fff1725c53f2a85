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

// The Get calls of what a view computes as it runs: the view, then the output
// pointer, then *out = read(view), which may refuse a view outside a loop.
// Nothing is written on failure.
template <class Value, class Read>
TQ3Status readView(const char* function, TQ3ViewObject view, Value* out, const char* outName, Read read)
{
    return guardStatus(function, [&] {
        View& source = lookup<View>(view, "view");
        requireNonNull(out, outName);
        *out = std::invoke(read, source);
    });
}

// The graphics state Get calls: readView of the state (the view must run a
// loop).
template <class Value, class Read>
TQ3Status readState(const char* function, TQ3ViewObject view, Value* out, const char* outName, Read read)
{
    return readView(function, view, out, outName, [&](View& source) { return read(source.graphicsState()); });
}

// A bounding loop's end: the view, then the result pointer, then end(view,
// *result).
template <class Bounds>
TQ3ViewStatus endBounds(const char* function, TQ3ViewObject view, Bounds* result,
                        TQ3ViewStatus (View::*end)(Bounds&))
{
    return guard(function, kQ3ViewStatusError, [&] {
        View& target = lookup<View>(view, "view");
        requireNonNull(result, "result");
        return (target.*end)(*result);
    });
}

} // namespace

// A C entry point cannot come from a template, so the Get calls of the style
// states are written once as a macro that defines them through readState:
// Q3View_Get<Style>StyleState of the DrawState member `member`, a Type called
// `param` in QD3DView.h (the error messages name it as every other call does).
#define Q3_VIEW_STYLE_STATE_ENTRY_POINT(Style, Type, param, member)                                             \
    TQ3Status Q3View_Get##Style##StyleState(TQ3ViewObject view, Type* param)                                    \
    {                                                                                                           \
        return readState(__func__, view, param, #param,                                                         \
                         [](const GraphicsState& state) { return state.draw.member; });                         \
    }

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

Q3_HELD_ENTRY_POINTS(Q3View, View, TQ3ViewObject, view, Renderer, TQ3RendererObject, renderer, setHeld)

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
    return setDirect<View>(__func__, view, "view", computeBounds, &View::startBoundingBox);
}

TQ3ViewStatus Q3View_EndBoundingBox(TQ3ViewObject view, TQ3BoundingBox* result)
{
    return endBounds(__func__, view, result, &View::endBoundingBox);
}

TQ3Status Q3View_StartBoundingSphere(TQ3ViewObject view, TQ3ComputeBounds computeBounds)
{
    return setDirect<View>(__func__, view, "view", computeBounds, &View::startBoundingSphere);
}

TQ3ViewStatus Q3View_EndBoundingSphere(TQ3ViewObject view, TQ3BoundingSphere* result)
{
    return endBounds(__func__, view, result, &View::endBoundingSphere);
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

Q3_HELD_ENTRY_POINTS(Q3View, View, TQ3ViewObject, view, Camera, TQ3CameraObject, camera, setHeld)

Q3_HELD_ENTRY_POINTS(Q3View, View, TQ3ViewObject, view, DrawContext, TQ3DrawContextObject, drawContext, setHeld)

TQ3Status Q3View_GetLocalToWorldMatrixState(TQ3ViewObject view, TQ3Matrix4x4* matrix)
{
    return readView(__func__, view, matrix, "matrix", &View::localToWorldState);
}

TQ3Status Q3View_GetSubdivisionStyleState(TQ3ViewObject view, TQ3SubdivisionStyleData* subdivisionStyle)
{
    return readView(__func__, view, subdivisionStyle, "subdivisionStyle", &View::subdivisionStyleState);
}

TQ3Status Q3Push_Submit(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").push(); });
}

TQ3Status Q3Pop_Submit(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").pop(); });
}

Q3_HELD_ENTRY_POINTS(Q3View, View, TQ3ViewObject, view, LightGroup, TQ3GroupObject, lightGroup, setHeldOptional)

TQ3Status Q3View_Flush(TQ3ViewObject view)
{
    return guardStatus(__func__, [&] { lookup<View>(view, "view").flush(); });
}

TQ3Status Q3View_GetWorldToFrustumMatrixState(TQ3ViewObject view, TQ3Matrix4x4* matrix)
{
    return readView(__func__, view, matrix, "matrix", &View::worldToFrustumState);
}

TQ3Status Q3View_GetFrustumToWindowMatrixState(TQ3ViewObject view, TQ3Matrix4x4* matrix)
{
    return readView(__func__, view, matrix, "matrix", &View::frustumToWindowState);
}

Q3_VIEW_STYLE_STATE_ENTRY_POINT(Backfacing, TQ3BackfacingStyle, backfacingStyle, backfacing)

Q3_VIEW_STYLE_STATE_ENTRY_POINT(Interpolation, TQ3InterpolationStyle, interpolationType, interpolation)

Q3_VIEW_STYLE_STATE_ENTRY_POINT(Fill, TQ3FillStyle, fillStyle, fill)

TQ3Status Q3View_GetHighlightStyleState(TQ3ViewObject view, TQ3AttributeSet* highlightStyle)
{
    return readState(__func__, view, highlightStyle, "highlightStyle", [](const GraphicsState& state) {
        return static_cast<TQ3AttributeSet>(handOut(state.draw.highlight));
    });
}

Q3_VIEW_STYLE_STATE_ENTRY_POINT(Orientation, TQ3OrientationStyle, fontFacingDirectionStyle, orientation)

Q3_VIEW_STYLE_STATE_ENTRY_POINT(ReceiveShadows, TQ3Boolean, receives, receiveShadows)

Q3_VIEW_STYLE_STATE_ENTRY_POINT(PickID, unsigned long, pickIDStyle, pickID)

Q3_VIEW_STYLE_STATE_ENTRY_POINT(PickParts, TQ3PickParts, pickPartsStyle, pickParts)

Q3_VIEW_STYLE_STATE_ENTRY_POINT(AntiAlias, TQ3AntiAliasStyleData, antiAliasData, antiAlias)

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

#undef Q3_VIEW_STYLE_STATE_ENTRY_POINT
