// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/View.h"

#include "QD3DExtension.h"
#include "core/CustomObject.h"
#include "core/EnumValue.h"

#include "geometry/Geometry.h"
#include "geometry/nurbs/Tessellate.h"
#include "group/Group.h"
#include "light/Light.h"
#include "base/GlFramebuffer.h"
#include "base/RenderTarget.h"
#include "render/Renderer.h"
#include "view/BoundsPass.h"
#include "view/Camera.h"
#include "view/DrawContext.h"
#include "view/GLDrawContext.h"
#include "view/Pick.h"
#include "view/PickPass.h"
#include "view/RenderPass.h"
#include "view/WindowDrawContext.h"

#include <algorithm>
#include <optional>
#include <string>

namespace q3 {

const ClassInfo kViewClass{kQ3ObjectTypeView, &kRootClass, "view"};

namespace {

// What a cancelled loop submits to: everything is ignored until its end.
class IgnoringVisitor final : public ShapeVisitor {
public:
    void visitGeometry(const Geometry&) override {}
    void visitAttributeSet(const AttributeSet&) override {}
    void visitStyle(const Style&) override {}
    void visitShader(const Shader&) override {}
    bool beginGroup(const DisplayGroup&) override { return false; }
    void endGroup(const DisplayGroup&) override {}
    void visitTransform(const Transform&) override {}
    void pushState() override {}
    void popState() override {}
};

float clampUnit(float value)
{
    return std::clamp(value, 0.0f, 1.0f);
}

bool isComputeBounds(const TQ3ComputeBounds& value)
{
    const long v = enumValue(value);
    return v == kQ3ComputeBoundsExact || v == kQ3ComputeBoundsApproximate;
}

// The part of rect inside a width x height image (possibly empty).
PixelRect clipToImage(const PixelRect& rect, std::uint32_t width, std::uint32_t height)
{
    const long long x0 = std::max<long long>(rect.x, 0);
    const long long y0 = std::max<long long>(rect.y, 0);
    const long long x1 = std::min<long long>((long long)rect.x + rect.width, width);
    const long long y1 = std::min<long long>((long long)rect.y + rect.height, height);
    if (x0 >= x1 || y0 >= y1)
        return PixelRect{};
    return PixelRect{int(x0), int(y0), int(x1 - x0), int(y1 - y0)};
}

// Whether the mask selects pixel (x, y) of the pixmap: its bit is set
// (QD3DDrawContext.h); pixels beyond the mask are not selected.
bool maskSelects(const TQ3Bitmap& mask, int x, int y)
{
    if (static_cast<unsigned long>(x) >= mask.width || static_cast<unsigned long>(y) >= mask.height)
        return false;
    const unsigned char byte = mask.image[std::size_t(y) * mask.rowBytes + std::size_t(x) / 8];
    const unsigned bit = mask.bitOrder == kQ3EndianLittle ? 1u << (x % 8) : 0x80u >> (x % 8);
    return (byte & bit) != 0;
}

PixmapDrawContext& pixmapContext(DrawContext& context)
{
    // The pixmap and X11 draw contexts are the kinds Q3 draws into.
    if (!context.isType(kQ3DrawContextTypePixmap))
        fail(kQ3ErrorInvalidObjectType, std::string("the view's draw context is a ") +
                                            context.classInfo().name + ", which Q3 cannot render into");
    return static_cast<PixmapDrawContext&>(context);
}

// The size of the image a draw context holds: the pixmap's, the X
// window's as the server reports it now (kQ3ErrorX11Error when it cannot),
// or the GL framebuffer's the application set.
std::pair<std::uint32_t, std::uint32_t> imageSize(DrawContext& context)
{
    if (context.isType(kQ3DrawContextTypeGL)) {
        const GLDrawContext& gl = static_cast<GLDrawContext&>(context);
        return {gl.width(), gl.height()};
    }
    if (context.isType(kQ3DrawContextTypeX11)) {
        std::uint32_t width = 0, height = 0;
        const RenderResult result = windowSize(static_cast<WindowDrawContext&>(context).window(), width, height);
        if (!result)
            fail(kQ3ErrorX11Error, "the X11 draw context's window: " + result.message);
        return {width, height};
    }
    const PixmapLayout layout = layoutOf(pixmapContext(context).pixmap());
    return {layout.width, layout.height};
}

// The pixels of the window a bounding or picking loop subdivides curves
// for: none for a window the server no longer knows, which only a
// rendering loop or a window pick must report.
std::optional<PixelRect> subdivisionRect(DrawContext& context)
{
    if (context.isType(kQ3DrawContextTypeX11)) {
        std::uint32_t width = 0, height = 0;
        if (!windowSize(static_cast<WindowDrawContext&>(context).window(), width, height))
            return std::nullopt;
        return context.drawRect(width, height);
    }
    if (!context.isType(kQ3DrawContextTypePixmap) && !context.isType(kQ3DrawContextTypeGL))
        return std::nullopt;
    const auto [width, height] = imageSize(context);
    return context.drawRect(width, height);
}

// The layout of m_windowPixels for writeRgba8ToPixmap: one 32-bit
// 0xAARRGGBB value per pixel in the host's byte order.
PixmapLayout windowLayout(std::uint32_t width, std::uint32_t height)
{
    PixmapLayout layout;
    layout.width = width;
    layout.height = height;
    layout.rowBytes = width * 4;
    layout.pixelType = PixelType::kARGB32;
    layout.byteOrder = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ ? ByteOrder::kLittle : ByteOrder::kBig;
    return layout;
}

// The lights of a light group and the camera's eye, in world coordinates.
SceneLighting lightingOf(const Group* lights, const Camera& camera)
{
    SceneLighting lighting;
    if (lights != nullptr)
        for (const Group::Node& node : lights->nodes())
            if (node.object->isType(kQ3ShapeTypeLight)) {
                // Lights that are off take no place among the lights drawn.
                LightSource source = static_cast<const Light&>(*node.object).source();
                if (source.on)
                    lighting.lights.push_back(source);
            }
    const TQ3CameraPlacement& placement = camera.data().placement;
    lighting.eye = glm::dvec3(placement.cameraLocation.x, placement.cameraLocation.y, placement.cameraLocation.z);
    lighting.orthographic = !camera.isPerspective();
    lighting.viewDirection = glm::dvec3(placement.pointOfInterest.x, placement.pointOfInterest.y,
                                        placement.pointOfInterest.z) -
                             lighting.eye;
    return lighting;
}

} // namespace

View::View() = default;

std::size_t View::curveScratchBytes() const
{
    if (!m_curveScratch)
        return 0;
    return m_curveScratch->vertices.capacity() * sizeof(float) +
           m_curveScratch->parameters.capacity() * sizeof(double);
}

nurbs::TessellatedCurve* View::curveScratch()
{
    if (!m_curveScratch)
        m_curveScratch = std::make_unique<nurbs::TessellatedCurve>();
    return m_curveScratch.get();
}

View::~View()
{
    if (m_loop == Loop::kRendering)
        m_offscreen->cancelFrame();
}

void View::requireNoLoop() const
{
    if (m_loop != Loop::kNone)
        fail(kQ3ErrorViewIsStarted, "the view is inside a rendering or bounding loop");
}

Pass& View::activePass()
{
    if (m_loop == Loop::kNone || !m_pass)
        fail(kQ3ErrorViewNotStarted, "the view is not inside a rendering or bounding loop");
    return *m_pass;
}

void View::setRenderer(Ref<Renderer> renderer)
{
    requireNoLoop();
    m_renderer = std::move(renderer);
}

void View::setRendererByType(TQ3ObjectType type)
{
    requireNoLoop();
    m_renderer = Renderer::newFromType(type);
}

void View::setCamera(Ref<Camera> camera)
{
    requireNoLoop();
    m_camera = std::move(camera);
}

void View::setDrawContext(Ref<DrawContext> drawContext)
{
    requireNoLoop();
    m_drawContext = std::move(drawContext);
}

void View::setLightGroup(Ref<Group> lights)
{
    requireNoLoop();
    if (lights && !lights->isType(kQ3GroupTypeLight))
        fail(kQ3ErrorInvalidObjectType, std::string("the group is a ") + lights->classInfo().name +
                                            ", not a light group (Q3LightGroup_New)");
    m_lightGroup = std::move(lights);
}

void View::setDefaultAttributeSet(Ref<AttributeSet> attributes)
{
    requireNoLoop();
    m_defaultAttributes = std::move(attributes);
}

Ref<AttributeSet> View::defaultAttributeSet() const
{
    if (m_defaultAttributes)
        return m_defaultAttributes;
    return AttributeSet::fromValues(defaultAttributes(nullptr));
}

TQ3BoundingBox View::boundingBoxOf(const DisplayGroup& group, const TQ3ComputeBounds& computeBounds)
{
    startBoundingBox(computeBounds);
    TQ3BoundingBox box{};
    try {
        // The group's objects, whatever its state and box say.
        group.submitContents(*m_pass);
    } catch (...) {
        endLoop();
        throw;
    }
    endBoundingBox(box);
    return box;
}

bool View::isBoundingBoxVisible(const TQ3BoundingBox& box)
{
    return activePass().boxVisible(box);
}

void View::startRendering()
{
    requireNoLoop();
    if (!m_drawContext)
        fail(kQ3ErrorDrawContextNotSet, "the view has no draw context (Q3View_SetDrawContext)");
    if (!m_camera)
        fail(kQ3ErrorCameraNotSet, "the view has no camera (Q3View_SetCamera)");
    if (!m_renderer)
        fail(kQ3ErrorRendererNotSet, "the view has no renderer (Q3View_SetRenderer)");

    const DrawContext& context = *m_drawContext;
    const TQ3DrawContextData& settings = context.data();
    Destination destination;
    if (context.isType(kQ3DrawContextTypeX11)) {
        // The frame is drawn as into a pixmap of the window's size, which
        // starts as the window's pixels where the frame may leave them.
        const auto [width, height] = imageSize(*m_drawContext);
        destination.window = true;
        destination.nativeWindow = static_cast<const WindowDrawContext&>(context).window();
        destination.layout = windowLayout(width, height);
        m_windowPixels.assign(std::size_t(width) * height, 0);
        destination.image = m_windowPixels.data();
    } else if (context.isType(kQ3DrawContextTypeGL)) {
        // Likewise for the application's framebuffer, through its context.
        const RenderResult current = checkCurrentGlContext();
        if (!current)
            fail(kQ3ErrorBadDrawContext, "the GL draw context: " + current.message);
        const auto [width, height] = imageSize(*m_drawContext);
        destination.appGl = true;
        destination.layout = windowLayout(width, height);
        m_windowPixels.assign(std::size_t(width) * height, 0);
        destination.image = m_windowPixels.data();
    } else {
        const PixmapDrawContext& pixmap = pixmapContext(*m_drawContext);
        destination.image = pixmap.pixmap().image;
        destination.layout = layoutOf(pixmap.pixmap());
    }
    destination.pane = context.drawRect(destination.layout.width, destination.layout.height);
    destination.cleared = settings.clearImageMethod == kQ3ClearMethodWithColor;
    if (settings.maskState == kQ3True)
        destination.mask = settings.mask;
    if (destination.window && (!destination.cleared || destination.mask.image != nullptr)) {
        const PixelRect area = clipToImage(destination.pane, destination.layout.width, destination.layout.height);
        const RenderResult read = readWindow(destination.nativeWindow, area, m_windowPixels.data(),
                                             destination.layout.width);
        if (!read)
            fail(kQ3ErrorX11Error, "reading the window the frame is drawn over: " + read.message);
    }
    if (destination.appGl && (!destination.cleared || destination.mask.image != nullptr)) {
        const PixelRect area = clipToImage(destination.pane, destination.layout.width, destination.layout.height);
        const RenderResult read = readGlFramebuffer(area, destination.layout.height, m_windowPixels.data(),
                                                    destination.layout.width);
        if (!read)
            fail(kQ3ErrorBadDrawContext, "reading the framebuffer the frame is drawn over: " + read.message);
    }
    // Without a clear, the frame starts transparent so that writeImage can
    // tell drawn pixels (alpha 1) from untouched ones.
    RgbaColor clear;
    if (destination.cleared) {
        const TQ3ColorARGB& color = settings.clearImageColor;
        clear = RgbaColor{clampUnit(color.r), clampUnit(color.g), clampUnit(color.b), clampUnit(color.a)};
    }

    // The interactive renderer fills surfaces and removes hidden ones with a
    // depth buffer; the wireframe renderer draws edges in submission order.
    const bool fills = m_renderer->fillsSurfaces();
    RenderStyle style;
    style.fillTriangles = fills;
    style.textureFilter = m_renderer->textureFilter();
    FrameOptions options;
    options.depthTest = fills;
    // A little-endian ARGB32 pixmap the frame replaces (cleared, no mask)
    // is offered to the backend to draw in place of its own image, saving
    // the copy into it (writeImage); the backend takes it only when the
    // pane is the whole image.
    const PixmapLayout& layout = destination.layout;
    if (!destination.window && !destination.appGl && destination.image != nullptr && destination.cleared &&
        destination.mask.image == nullptr && layout.pixelType == PixelType::kARGB32 &&
        layout.byteOrder == ByteOrder::kLittle && validatePixmapLayout(layout)) {
        options.bgraImage = static_cast<std::uint8_t*>(destination.image);
        options.bgraRowBytes = layout.rowBytes;
    }

    if (!m_offscreen)
        m_offscreen = makeRenderTarget();
    style.lighting = lightingOf(m_lightGroup.get(), *m_camera);
    auto pass = std::make_unique<RenderPass>(*m_offscreen, Window{m_camera->worldToFrustum(), destination.pane},
                                             defaultAttributes(m_defaultAttributes.get()), style);
    pass->allowGroupCulling(m_cullGroups);
    pass->allowCurveCulling(true);
    pass->useCurveScratch(curveScratch());
    throwIfFailed(m_offscreen->beginFrame(destination.layout.width, destination.layout.height, clear,
                                          destination.pane, options),
                  "starting the image");
    m_destination = destination;
    m_pass = std::move(pass);
    m_loop = Loop::kRendering;
    m_cancelled = false;
}

TQ3ViewStatus View::endRendering()
{
    if (m_loop != Loop::kRendering)
        fail(kQ3ErrorRenderingNotStarted, "no rendering loop is running in the view");
    const bool cancelled = m_cancelled;
    endLoop();
    const RenderResult finished = m_offscreen->endFrame();
    if (!finished)
        fail(kQ3ErrorRenderingLoopFailed, "the image could not be finished: " + finished.message);
    const RenderResult written = m_offscreen->drewInPlace() ? RenderResult::success() : writeImage();
    if (!written)
        fail(kQ3ErrorRenderingLoopFailed, "the image could not be written: " + written.message);
    if (m_destination.window) {
        const Destination& to = m_destination;
        const PixelRect area = clipToImage(to.pane, to.layout.width, to.layout.height);
        const RenderResult shown = writeWindow(to.nativeWindow, area, m_windowPixels.data(), to.layout.width);
        if (!shown)
            fail(kQ3ErrorX11Error, "the frame could not be put into the window: " + shown.message);
    }
    if (m_destination.appGl) {
        const Destination& to = m_destination;
        const PixelRect area = clipToImage(to.pane, to.layout.width, to.layout.height);
        const RenderResult shown = writeGlFramebuffer(area, to.layout.height, m_windowPixels.data(), to.layout.width);
        if (!shown)
            fail(kQ3ErrorBadDrawContext, "the frame could not be put into the GL framebuffer: " + shown.message);
    }
    if (cancelled)
        return kQ3ViewStatusCancelled;
    if (m_endFrameMethod != nullptr)
        m_endFrameMethod(this, m_endFrameData);
    return kQ3ViewStatusDone;
}

RenderResult View::writeImage() const
{
    const Destination& to = m_destination;
    const Rgba8ImageView frame{m_offscreen->pixels(), m_offscreen->width(), m_offscreen->height(),
                               m_offscreen->rowBytes()};
    const PixelRect area = clipToImage(to.pane, to.layout.width, to.layout.height);
    if (area.width == 0)
        return RenderResult::success();
    const bool masked = to.mask.image != nullptr;
    if (to.cleared && !masked)
        return writeRgba8ToPixmap(frame, area, to.image, to.layout, area.x, area.y);
    // Write only the runs of pixels to be written: those geometry covered
    // (kQ3ClearMethodNone) and those the mask selects (mask state on).
    for (int y = area.y; y < area.y + area.height; ++y) {
        const std::uint8_t* row = frame.pixels + std::size_t(y) * frame.rowBytes;
        const auto writes = [&](int x) {
            return (to.cleared || row[4 * x + 3] != 0) && (!masked || maskSelects(to.mask, x, y));
        };
        int x = area.x;
        while (x < area.x + area.width) {
            if (!writes(x)) {
                ++x;
                continue;
            }
            const int start = x;
            while (x < area.x + area.width && writes(x))
                ++x;
            const PixelRect run{start, y, x - start, 1};
            RenderResult result = writeRgba8ToPixmap(frame, run, to.image, to.layout, start, y);
            if (!result)
                return result;
        }
    }
    return RenderResult::success();
}

void View::startBounding(Loop loop, const TQ3ComputeBounds& computeBounds)
{
    requireNoLoop();
    if (!isComputeBounds(computeBounds))
        fail(kQ3ErrorInvalidParameter, "computeBounds " + std::to_string(enumValue(computeBounds)) +
                                           " is neither kQ3ComputeBoundsExact nor Approximate");
    // Screen-space subdivision (for Q3Geometry_GetDecomposed) needs a window.
    std::optional<Window> window;
    if (m_camera && m_drawContext)
        if (const std::optional<PixelRect> rect = subdivisionRect(*m_drawContext))
            window = Window{m_camera->worldToFrustum(), *rect};
    auto pass = std::make_unique<BoundsPass>(computeBounds, window, defaultAttributes(m_defaultAttributes.get()));
    pass->allowGroupCulling(m_cullGroups);
    pass->useCurveScratch(curveScratch());
    m_pass = std::move(pass);
    m_loop = loop;
    m_cancelled = false;
}

void View::startBoundingBox(const TQ3ComputeBounds& computeBounds)
{
    startBounding(Loop::kBoundingBox, computeBounds);
}

void View::startBoundingSphere(const TQ3ComputeBounds& computeBounds)
{
    startBounding(Loop::kBoundingSphere, computeBounds);
}

TQ3ViewStatus View::endBoundingBox(TQ3BoundingBox& result)
{
    if (m_loop != Loop::kBoundingBox)
        fail(kQ3ErrorBoundsNotStarted, "no bounding-box loop is running in the view");
    const TQ3BoundingBox box = static_cast<const BoundsPass&>(*m_pass).box();
    const bool cancelled = m_cancelled;
    endLoop();
    if (cancelled)
        return kQ3ViewStatusCancelled;
    result = box;
    return kQ3ViewStatusDone;
}

TQ3ViewStatus View::endBoundingSphere(TQ3BoundingSphere& result)
{
    if (m_loop != Loop::kBoundingSphere)
        fail(kQ3ErrorBoundsNotStarted, "no bounding-sphere loop is running in the view");
    const TQ3BoundingSphere sphere = static_cast<const BoundsPass&>(*m_pass).sphere();
    const bool cancelled = m_cancelled;
    endLoop();
    if (cancelled)
        return kQ3ViewStatusCancelled;
    result = sphere;
    return kQ3ViewStatusDone;
}

void View::startWriting(std::shared_ptr<WriteTarget> target)
{
    requireNoLoop();
    m_writeTarget = std::move(target);
    m_loop = Loop::kWriting;
    m_cancelled = false;
}

TQ3ViewStatus View::endWriting()
{
    if (m_loop != Loop::kWriting)
        fail(kQ3ErrorWriteStateInactive, "no writing loop is running in the view");
    const bool cancelled = m_cancelled || m_writeTarget->cancelled();
    endLoop();
    return cancelled ? kQ3ViewStatusCancelled : kQ3ViewStatusDone;
}

void View::startPicking(Pick& pick)
{
    requireNoLoop();
    std::optional<Window> window;
    if (pick.kind() != Pick::Kind::kWorldRay) {
        if (!m_drawContext)
            fail(kQ3ErrorDrawContextNotSet, "a window pick needs the view's draw context (Q3View_SetDrawContext)");
        if (!m_camera)
            fail(kQ3ErrorCameraNotSet, "a window pick needs the view's camera (Q3View_SetCamera)");
        const auto [width, height] = imageSize(*m_drawContext);
        window = Window{m_camera->worldToFrustum(), m_drawContext->drawRect(width, height)};
    } else if (m_camera && m_drawContext) {
        // Screen-space subdivision needs a window when there is one.
        if (const std::optional<PixelRect> rect = subdivisionRect(*m_drawContext))
            window = Window{m_camera->worldToFrustum(), *rect};
    }
    auto pass = std::make_unique<PickPass>(pick, window, defaultAttributes(m_defaultAttributes.get()));
    pass->allowGroupCulling(m_cullGroups);
    pass->useCurveScratch(curveScratch());
    pick.emptyHits();
    m_pass = std::move(pass);
    m_pick = pick.handle();
    m_loop = Loop::kPicking;
    m_cancelled = false;
}

TQ3ViewStatus View::endPicking()
{
    if (m_loop != Loop::kPicking)
        fail(kQ3ErrorPickingNotStarted, "no picking loop is running in the view");
    std::vector<PickHit> hits = std::move(static_cast<PickPass&>(*m_pass).hits());
    const bool cancelled = m_cancelled;
    const TQ3Object handle = m_pick;
    endLoop();
    Pick* pick = nullptr;
    try {
        pick = &lookup<Pick>(handle, "pick");
    } catch (const Error&) {
        fail(kQ3ErrorPickingLoopFailed, "the pick was disposed during the picking loop");
    }
    if (cancelled)
        return kQ3ViewStatusCancelled;
    pick->setHits(std::move(hits));
    return kQ3ViewStatusDone;
}

void View::endLoop()
{
    m_pass.reset();
    m_writeTarget.reset();
    m_pick = nullptr;
    m_loop = Loop::kNone;
    m_cancelled = false;
}

void View::cancel()
{
    if (m_loop != Loop::kNone)
        m_cancelled = true;
}

void View::sync() const
{
    if (m_loop == Loop::kRendering)
        fail(kQ3ErrorRenderingIsActive, "a rendering loop is running in the view");
}

void View::flush() const
{
    if (m_loop != Loop::kRendering)
        fail(kQ3ErrorRenderingNotStarted, "no rendering loop is running in the view");
}

void View::setIdleMethod(TQ3ViewIdleMethod method, const void* data)
{
    m_idleMethod = method;
    m_idleData = data;
}

void View::setIdleProgressMethod(TQ3ViewIdleProgressMethod method, const void* data)
{
    m_idleProgressMethod = method;
    m_idleProgressData = data;
}

void View::setEndFrameMethod(TQ3ViewEndFrameMethod method, void* data)
{
    m_endFrameMethod = method;
    m_endFrameData = data;
}

bool View::idle()
{
    // Q3 cannot tell how much of a frame is left: progress is (0, 0), what
    // QuickDraw 3D reports for a renderer without progress information.
    if (m_idleProgressMethod != nullptr)
        return m_idleProgressMethod(this, m_idleProgressData, 0, 0) != kQ3Failure;
    if (m_idleMethod != nullptr)
        return m_idleMethod(this, m_idleData) != kQ3Failure;
    return true;
}

bool View::idleProgress(unsigned long current, unsigned long completed)
{
    if (m_loop != Loop::kRendering)
        fail(kQ3ErrorRenderingNotStarted, "Q3XView_IdleProgress is for a rendering loop");
    bool goOn = true;
    if (m_idleProgressMethod != nullptr)
        goOn = m_idleProgressMethod(this, m_idleProgressData, current, completed) != kQ3Failure;
    else if (m_idleMethod != nullptr)
        goOn = m_idleMethod(this, m_idleData) != kQ3Failure;
    if (!goOn)
        m_cancelled = true;
    return goOn;
}

void View::endFrame()
{
    if (m_loop == Loop::kRendering)
        fail(kQ3ErrorRenderingIsActive, "the frame is still being rendered");
    if (m_endFrameMethod != nullptr)
        m_endFrameMethod(this, m_endFrameData);
}

ShapeVisitor& View::submitTarget()
{
    static IgnoringVisitor ignoring;
    if (m_loop == Loop::kWriting)
        return m_cancelled ? static_cast<ShapeVisitor&>(ignoring) : *m_writeTarget;
    Pass& pass = activePass();
    if (!m_cancelled && m_loop == Loop::kRendering && !idle())
        m_cancelled = true;
    if (m_cancelled)
        return ignoring;
    return pass;
}

void View::submit(const Object& object)
{
    if (m_loop == Loop::kWriting) {
        // Writing takes every shared object: lights, light groups and
        // unknown objects too, which drawing has no use for.
        if (!object.isType(kQ3ObjectTypeShared))
            fail(kQ3ErrorInvalidObjectType,
                 std::string("object is a ") + object.classInfo().name + ", which cannot be written");
        if (!m_cancelled)
            m_writeTarget->write(object);
        return;
    }
    if (!object.isDrawable())
        fail(kQ3ErrorInvalidObjectType,
             std::string("object is a ") + object.classInfo().name + ", which cannot be submitted");
    // Custom objects (here or in a group) draw through their class's submit
    // method for this loop (QD3DExtension.h).
    const TQ3XMethodType method = m_loop == Loop::kRendering ? kQ3XMethodTypeObjectSubmitRender
                                  : m_loop == Loop::kPicking ? kQ3XMethodTypeObjectSubmitPick
                                  : (m_loop == Loop::kBoundingBox || m_loop == Loop::kBoundingSphere)
                                      ? kQ3XMethodTypeObjectSubmitBounds
                                      : 0;
    CustomSubmitScope scope(this, method);
    object.accept(submitTarget());
}

void View::push()
{
    activePass().push();
}

void View::pop()
{
    activePass().pop();
}

TQ3Matrix4x4 View::localToWorldState()
{
    return toQ3(activePass().state().localToWorld);
}

TQ3SubdivisionStyleData View::subdivisionStyleState()
{
    return activePass().state().draw.subdivision;
}

const GraphicsState& View::graphicsState()
{
    return activePass().state();
}

TQ3Matrix4x4 View::worldToFrustumState()
{
    const Pass& pass = activePass();
    if (!pass.window())
        fail(kQ3ErrorCameraNotSet, "the bounding loop has no camera and draw context, so no frustum");
    return toQ3(pass.window()->worldToFrustum);
}

TQ3Matrix4x4 View::frustumToWindowState()
{
    const Pass& pass = activePass();
    if (!pass.window())
        fail(kQ3ErrorCameraNotSet, "the bounding loop has no camera and draw context, so no window");
    // Frustum x, y in -1..1 to the pane's pixels (y down); z kept.
    const PixelRect& pane = pass.window()->pane;
    Matrix m(1.0);
    m[0][0] = 0.5 * pane.width;
    m[1][1] = -0.5 * pane.height;
    m[3][0] = pane.x + 0.5 * pane.width;
    m[3][1] = pane.y + 0.5 * pane.height;
    return toQ3(m);
}

Ref<Geometry> View::decompose(const Geometry& geometry)
{
    return activePass().decomposed(geometry);
}

} // namespace q3
