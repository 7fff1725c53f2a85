// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DView.h"
#include "core/Object.h"
#include "core/ShapeVisitor.h"
#include "base/PixelConvert.h"
#include "base/RenderResult.h"
#include "base/WindowSystem.h"

#include <memory>
#include <vector>

namespace q3 {

namespace nurbs {
struct TessellatedCurve;
}

extern const ClassInfo kViewClass;

class AttributeSet;
class Camera;
class DisplayGroup;
class DrawContext;
class Geometry;
class Group;
struct GraphicsState;
class RenderTarget;
class Pass;
class Pick;
class Renderer;

/// What a writing loop (Q3View_StartWriting) sends objects to; io/File
/// implements it, so the view does not depend on the file format. Retained
/// objects arrive through write(), immediate-mode shapes through the
/// ShapeVisitor calls.
class WriteTarget : public ShapeVisitor {
public:
    virtual void write(const Object& object) = 0;
    /// Whether the target itself cancelled the loop (a file's idle method).
    virtual bool cancelled() const { return false; }
};

/// A QuickDraw 3D view: draw context, camera, renderer, and the loop running
/// in it. A loop is a Pass (RenderPass or BoundsPass) that receives every
/// submitted shape and owns the graphics state and its push/pop stack.
///
/// Rendering draws through one RenderTarget per view (base/RenderTarget.h,
/// made by the backend's makeRenderTarget()), created at the
/// first rendering loop and reused by the next ones. The image reaches the
/// caller's pixmap when the loop ends: Q3View_EndRendering converts the
/// finished frame into the pixmap's pixel type (only the pane, when the pane
/// state is on; only the pixels geometry covered, when the clear method is
/// kQ3ClearMethodNone). Q3's renderers finish in one traversal, so
/// EndRendering never asks for a retraversal and the article's
/// do { ... } while (EndRendering == kQ3ViewStatusRetraverse) loop runs once.
///
/// Not shared: disposing it destroys it. Invariant: a pass exists exactly
/// while a loop runs; while a rendering loop runs, the RenderTarget has a
/// frame open on the image and pane snapshotted at its start.
class View final : public Object {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ObjectTypeView;

    View();
    ~View() override;

    const ClassInfo& classInfo() const override { return kViewClass; }

    /// Bytes reserved by the buffer the view's passes subdivide curves into
    /// (0 before the first curve): it grows to the largest curve drawn and is
    /// freed with the view. Benchmarks and tests read it.
    std::size_t curveScratchBytes() const;

    /// The setters throw kQ3ErrorViewIsStarted inside a loop and then change
    /// nothing. The view keeps its own reference to what it is given.
    void setRenderer(Ref<Renderer> renderer);
    /// A new renderer of that type (Renderer::newFromType), checked after
    /// the loop.
    void setRendererByType(TQ3ObjectType type);
    void setCamera(Ref<Camera> camera);
    void setDrawContext(Ref<DrawContext> drawContext);
    const Ref<Renderer>& renderer() const { return m_renderer; }
    const Ref<Camera>& camera() const { return m_camera; }
    const Ref<DrawContext>& drawContext() const { return m_drawContext; }

    /// The lights the view is lit by: a light group (kQ3ErrorInvalidObjectType
    /// for any other group) or null. Read at the start of each rendering
    /// loop. Not allowed inside a loop (kQ3ErrorViewIsStarted).
    void setLightGroup(Ref<Group> lights);
    const Ref<Group>& lightGroup() const { return m_lightGroup; }
    /// The attributes every traversal starts with, over QuickDraw 3D's view
    /// defaults (null: the defaults alone). Not allowed inside a loop.
    void setDefaultAttributeSet(Ref<AttributeSet> attributes);
    /// The set in use: the one given, or a new set holding the defaults.
    Ref<AttributeSet> defaultAttributeSet() const;
    /// Whether display groups with a bounding box may be culled or bounded
    /// by it (Q3View_AllowAllGroupCulling); on by default.
    void allowGroupCulling(bool allow) { m_cullGroups = allow; }

    /// Q3DisplayGroup_CalcAndUseBoundingBox: the box of the group's objects
    /// from a bounding loop of this view (which must not be in a loop).
    TQ3BoundingBox boundingBoxOf(const DisplayGroup& group, const TQ3ComputeBounds& computeBounds);
    /// Q3View_IsBoundingBoxVisible: whether a box in the current local
    /// coordinates may be seen (kQ3ErrorViewNotStarted outside a loop).
    bool isBoundingBoxVisible(const TQ3BoundingBox& box);

    /// Starts a rendering loop. Throws kQ3ErrorViewIsStarted,
    /// kQ3ErrorDrawContextNotSet, kQ3ErrorCameraNotSet,
    /// kQ3ErrorRendererNotSet (in that order), or what the renderer's frame
    /// start reports (throwIfFailed in view/RenderPass.h).
    void startRendering();
    /// Ends it and writes the image: kQ3ViewStatusDone, or
    /// kQ3ViewStatusCancelled after cancel(). Throws
    /// kQ3ErrorRenderingNotStarted outside a rendering loop and
    /// kQ3ErrorRenderingLoopFailed when the image cannot be finished (the
    /// loop is over then too).
    TQ3ViewStatus endRendering();

    /// Start a bounding loop. Throw kQ3ErrorViewIsStarted, then
    /// kQ3ErrorInvalidParameter for a computeBounds that is no
    /// TQ3ComputeBounds value (read through enumValue, so any int is safe).
    void startBoundingBox(const TQ3ComputeBounds& computeBounds);
    void startBoundingSphere(const TQ3ComputeBounds& computeBounds);
    /// End it: kQ3ViewStatusDone with the result set, or
    /// kQ3ViewStatusCancelled with it untouched. Throw
    /// kQ3ErrorBoundsNotStarted unless a loop of that kind runs.
    TQ3ViewStatus endBoundingBox(TQ3BoundingBox& result);
    TQ3ViewStatus endBoundingSphere(TQ3BoundingSphere& result);

    /// Starts a writing loop into `target` (kQ3ErrorViewIsStarted inside a
    /// loop).
    void startWriting(std::shared_ptr<WriteTarget> target);
    /// Ends it: kQ3ViewStatusDone, or kQ3ViewStatusCancelled after cancel().
    /// Throws kQ3ErrorWriteStateInactive outside a writing loop.
    TQ3ViewStatus endWriting();

    /// Starts a picking loop for `pick` (QD3DPick.h): kQ3ErrorViewIsStarted
    /// inside a loop; for window picks kQ3ErrorDrawContextNotSet, then
    /// kQ3ErrorCameraNotSet. Empties the pick's hit list and tests against
    /// a copy of its settings.
    void startPicking(Pick& pick);
    /// Ends it and hands the hits to the pick (looked up again by handle,
    /// since it may have been disposed: kQ3ErrorPickingLoopFailed then):
    /// kQ3ViewStatusDone, or kQ3ViewStatusCancelled after cancel() with the
    /// hit list left empty. Throws kQ3ErrorPickingNotStarted outside a
    /// picking loop.
    TQ3ViewStatus endPicking();

    /// Makes the running loop's end report kQ3ViewStatusCancelled; until then
    /// submitted shapes are ignored. Does nothing outside a loop.
    void cancel();

    /// The application's callbacks (QD3DView.h): null removes one. In a
    /// rendering loop submitTarget() calls the progress method (with 0, 0)
    /// or else the idle method before each object, and cancels the loop
    /// when it returns kQ3Failure; endRendering() calls the end-frame
    /// method after a frame is written. Allowed inside a loop.
    void setIdleMethod(TQ3ViewIdleMethod method, const void* data);
    void setIdleProgressMethod(TQ3ViewIdleProgressMethod method, const void* data);
    void setEndFrameMethod(TQ3ViewEndFrameMethod method, void* data);
    /// Q3XView_IdleProgress: the progress (or idle) method with these
    /// values; false, with the loop cancelled, when it asks to cancel.
    /// Throws kQ3ErrorRenderingNotStarted outside a rendering loop.
    bool idleProgress(unsigned long current, unsigned long completed);
    /// Q3XView_EndFrame: the end-frame method, if any. Throws
    /// kQ3ErrorRenderingIsActive inside a rendering loop.
    void endFrame();
    /// Throws kQ3ErrorRenderingIsActive inside a rendering loop; otherwise
    /// every image is already complete.
    void sync() const;
    /// Q3View_Flush: throws kQ3ErrorRenderingNotStarted outside a rendering
    /// loop; inside one, every shape is already drawn.
    void flush() const;

    /// Where shapes go when submitted: the active pass (or, after cancel(), a
    /// visitor ignoring them). Throws kQ3ErrorViewNotStarted outside a loop.
    ShapeVisitor& submitTarget();
    /// Submits any drawable object; throws kQ3ErrorInvalidObjectType for one
    /// that is not drawable, then as submitTarget().
    void submit(const Object& object);

    /// Graphics state operations; each throws kQ3ErrorViewNotStarted outside
    /// a loop, pop() kQ3ErrorNothingToPop when nothing pushed is left.
    void push();
    void pop();
    TQ3Matrix4x4 localToWorldState();
    TQ3SubdivisionStyleData subdivisionStyleState();
    /// The whole graphics state of the running loop (kQ3ErrorViewNotStarted
    /// outside one).
    const GraphicsState& graphicsState();
    /// The camera's world-to-frustum matrix, and the frustum-to-window matrix
    /// of the pane, for the running loop.
    TQ3Matrix4x4 worldToFrustumState();
    TQ3Matrix4x4 frustumToWindowState();

    /// Q3Geometry_GetDecomposed: what the geometry submitted now would be
    /// drawn as, as a new geometry (Geometry::decomposed); null for a
    /// primitive. Throws kQ3ErrorViewNotStarted outside a loop.
    Ref<Geometry> decompose(const Geometry& geometry);

private:
    enum class Loop { kNone, kRendering, kBoundingBox, kBoundingSphere, kWriting, kPicking };

    /// The rendering loop's destination, read from the draw context at its
    /// start (changes to the draw context affect the next loop).
    struct Destination {
        void* image = nullptr;
        PixmapLayout layout;
        PixelRect pane;
        bool cleared = true;
        /// The draw context's mask while its mask state is on, else null
        /// image (every pixel of the pane is written).
        TQ3Bitmap mask{};
        /// The frame goes to an X window (X11DrawContext): image is
        /// m_windowPixels, shown by endRendering.
        bool window = false;
        NativeWindow nativeWindow;
        /// The frame goes to the application's current OpenGL context
        /// (GLDrawContext): image is m_windowPixels too, put into the
        /// context's framebuffer by endRendering.
        bool appGl = false;
    };

    /// Calls the idle or progress method; false when it asks to cancel.
    bool idle();

    void requireNoLoop() const;
    Pass& activePass();
    /// m_curveScratch, made on first use.
    nurbs::TessellatedCurve* curveScratch();
    void startBounding(Loop loop, const TQ3ComputeBounds& computeBounds);
    /// Closes the loop, whatever state it is in.
    void endLoop();
    RenderResult writeImage() const;

    Ref<Renderer> m_renderer;
    Ref<Camera> m_camera;
    Ref<DrawContext> m_drawContext;
    Ref<Group> m_lightGroup;
    Ref<AttributeSet> m_defaultAttributes;
    bool m_cullGroups = true;

    Loop m_loop = Loop::kNone;
    bool m_cancelled = false;
    TQ3ViewIdleMethod m_idleMethod = nullptr;
    const void* m_idleData = nullptr;
    TQ3ViewIdleProgressMethod m_idleProgressMethod = nullptr;
    const void* m_idleProgressData = nullptr;
    TQ3ViewEndFrameMethod m_endFrameMethod = nullptr;
    void* m_endFrameData = nullptr;
    /// The buffer every pass of this view subdivides curves into (declared
    /// before m_pass, which points to it, so it is destroyed after). Views
    /// are not shared between threads, so neither is it.
    std::unique_ptr<nurbs::TessellatedCurve> m_curveScratch;
    std::unique_ptr<Pass> m_pass;
    std::shared_ptr<WriteTarget> m_writeTarget;
    /// The pick of a picking loop, as a handle: it is not shared, so the
    /// view cannot keep it alive and checks it is still live at the end.
    TQ3Object m_pick = nullptr;
    std::unique_ptr<RenderTarget> m_offscreen;
    Destination m_destination;
    /// A window or GL frame's pixels (0xAARRGGBB, the window's or
    /// framebuffer's size), kept between
    /// frames so that a frame of an unchanged size allocates nothing.
    std::vector<std::uint32_t> m_windowPixels;
};

} // namespace q3
