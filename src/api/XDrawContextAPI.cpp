// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/X11DrawContext.h" // first: it turns on Apple's X11 declarations
#include "api/Entry.h"

#include <map>
#include <memory>
#include <mutex>
#include <utility>

// Apple's X11 calls: Q3XDrawContext_*, Q3XBuffers_* and Q3X_GetVisualInfo.

// Q3XBuffers_New's record (QD3DDrawContext.h).
struct OpaqueTQ3XBufferObject {
    Display* display = nullptr;
    Window window = 0;
    unsigned long numBuffers = 0;
};

using namespace q3;
using namespace q3::api;

namespace {

// Every record made, one per display and window, for the process's life
// (Apple declares no dispose); Swap accepts only these.
struct BufferRegistry {
    std::mutex mutex;
    std::map<std::pair<Display*, Window>, std::unique_ptr<OpaqueTQ3XBufferObject>> records;
};

BufferRegistry& bufferRegistry()
{
    static BufferRegistry* registry = new BufferRegistry;
    return *registry;
}

void throwIfX11Failed(const RenderResult& result)
{
    if (!result)
        fail(kQ3ErrorX11Error, result.message);
}

} // namespace

extern "C" {

TQ3XBufferObject Q3XBuffers_New(Display* dpy, unsigned long numBuffers, Window window)
{
    return guard(__func__, TQ3XBufferObject{nullptr}, [&] {
        requireNonNull(dpy, "dpy");
        if (numBuffers != 1 && numBuffers != 2)
            fail(kQ3ErrorInvalidParameter, "numBuffers is " + std::to_string(numBuffers) + ", not 1 or 2");
        std::uint32_t width = 0, height = 0;
        throwIfX11Failed(windowSize(NativeWindow{dpy, window}, width, height));
        BufferRegistry& registry = bufferRegistry();
        std::lock_guard<std::mutex> lock(registry.mutex);
        auto& record = registry.records[{dpy, window}];
        if (!record)
            record = std::make_unique<OpaqueTQ3XBufferObject>();
        *record = OpaqueTQ3XBufferObject{dpy, window, numBuffers};
        return record.get();
    });
}

void Q3XBuffers_Swap(Display* dpy, TQ3XBufferObject buffers)
{
    guardStatus(__func__, [&] {
        requireNonNull(dpy, "dpy");
        requireNonNull(buffers, "buffers");
        {
            BufferRegistry& registry = bufferRegistry();
            std::lock_guard<std::mutex> lock(registry.mutex);
            auto found = registry.records.find({buffers->display, buffers->window});
            if (found == registry.records.end() || found->second.get() != buffers)
                fail(kQ3ErrorInvalidParameter, "buffers did not come from Q3XBuffers_New");
        }
        if (buffers->display != dpy)
            fail(kQ3ErrorInvalidParameter, "buffers were made for another display");
        throwIfX11Failed(flushDisplay(dpy));
    });
}

XVisualInfo* Q3X_GetVisualInfo(Display* dpy, Screen* screen)
{
    return guard(__func__, static_cast<XVisualInfo*>(nullptr), [&] {
        requireNonNull(dpy, "dpy");
        requireNonNull(screen, "screen");
        void* visuals = nullptr;
        throwIfX11Failed(trueColorVisuals(dpy, screen, visuals));
        return static_cast<XVisualInfo*>(visuals);
    });
}

TQ3DrawContextObject Q3XDrawContext_New(const TQ3XDrawContextData* xContextData)
{
    return guard(__func__, TQ3DrawContextObject{nullptr}, [&] {
        requireNonNull(xContextData, "xContextData");
        X11DrawContext::validate(*xContextData);
        return makeShared<X11DrawContext>(*xContextData).detach();
    });
}

TQ3Status Q3XDrawContext_SetDisplay(TQ3DrawContextObject drawContext, const Display* display)
{
    return guardStatus(__func__, [&] {
        X11DrawContext& target = lookup<X11DrawContext>(drawContext, "drawContext");
        target.setDisplay(const_cast<Display*>(display));
    });
}

TQ3Status Q3XDrawContext_GetDisplay(TQ3DrawContextObject drawContext, Display** display)
{
    return getValue<X11DrawContext>(__func__, drawContext, "drawContext", display, "display", &X11DrawContext::display);
}

Q3_DIRECT_VALUE_ENTRY_POINTS(Q3XDrawContext, X11DrawContext, TQ3DrawContextObject, drawContext, Drawable, Drawable,
                             drawable)

TQ3Status Q3XDrawContext_SetVisual(TQ3DrawContextObject drawContext, const Visual* visual)
{
    return guardStatus(__func__, [&] {
        X11DrawContext& target = lookup<X11DrawContext>(drawContext, "drawContext");
        requireNonNull(visual, "visual");
        target.setVisual(const_cast<Visual*>(visual));
    });
}

TQ3Status Q3XDrawContext_GetVisual(TQ3DrawContextObject drawContext, Visual** visual)
{
    return getValue<X11DrawContext>(__func__, drawContext, "drawContext", visual, "visual", &X11DrawContext::visual);
}

Q3_DIRECT_VALUE_ENTRY_POINTS(Q3XDrawContext, X11DrawContext, TQ3DrawContextObject, drawContext, Colormap, Colormap,
                             colormap)

Q3_POINTER_VALUE_ENTRY_POINTS(Q3XDrawContext, X11DrawContext, TQ3DrawContextObject, drawContext, ColormapData,
                              TQ3XColormapData, colormapData)

} // extern "C"
