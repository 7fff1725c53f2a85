// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "base/WindowSystem.h"

#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>
#include <string>

// base/WindowSystem.h for X11. libX11.so.6 is opened with dlopen the first
// time a call needs it (a program that shows an X window has it loaded
// already, so this finds the same copy), and libq3.so imports no X symbol.
//
// Xlib reports protocol errors (BadWindow for a drawable that is no window,
// BadMatch for reading outside the screen) asynchronously, through one
// process-wide handler whose default prints and exits. Each call here
// syncs first (so errors of the application's earlier requests still go to
// its own handler), installs a handler that records the error, makes its
// requests, syncs again and puts the application's handler back. The handler
// is process-wide, so the calls are serialized by one mutex.

namespace q3 {
namespace {

// Every Xlib function Q3 calls, named once: `member` is XlibApi's pointer to
// `function`, which xlib() looks up by its name.
#define Q3_XLIB_CALLS(X)                                                                                        \
    X(setErrorHandler, XSetErrorHandler) X(sync, XSync) X(flush, XFlush)                                        \
    X(getWindowAttributes, XGetWindowAttributes) X(createImage, XCreateImage) X(getImage, XGetImage)            \
    X(putImage, XPutImage) X(createGC, XCreateGC) X(freeGC, XFreeGC) X(getVisualInfo, XGetVisualInfo)           \
    X(screenNumberOfScreen, XScreenNumberOfScreen) X(getErrorText, XGetErrorText)

struct XlibApi {
#define Q3_XLIB_MEMBER(member, function) decltype(&function) member = nullptr;
    Q3_XLIB_CALLS(Q3_XLIB_MEMBER)
#undef Q3_XLIB_MEMBER
};

template <class F>
bool load(void* library, const char* name, F& function)
{
    function = reinterpret_cast<F>(dlsym(library, name));
    return function != nullptr;
}

// Loaded once; null when libX11 or one of its functions is missing.
const XlibApi* xlib()
{
    static const XlibApi* api = [] () -> const XlibApi* {
        void* library = dlopen("libX11.so.6", RTLD_NOW | RTLD_LOCAL);
        if (library == nullptr)
            return nullptr;
        static XlibApi loaded;
        bool complete = true;
#define Q3_XLIB_LOAD(member, function) complete = complete && load(library, #function, loaded.member);
        Q3_XLIB_CALLS(Q3_XLIB_LOAD)
#undef Q3_XLIB_LOAD
        return complete ? &loaded : nullptr;
    }();
    return api;
}

#undef Q3_XLIB_CALLS

std::mutex& trapMutex()
{
    static std::mutex mutex;
    return mutex;
}

// The first error seen while a trap is set (guarded by trapMutex()).
int g_errorCode = 0;
int g_errorRequest = 0;

int recordError(Display*, XErrorEvent* event)
{
    if (g_errorCode == 0) {
        g_errorCode = event->error_code;
        g_errorRequest = event->request_code;
    }
    return 0;
}

// Catches the X errors of the requests made while it lives.
class ErrorTrap {
public:
    ErrorTrap(const XlibApi& api, Display* display) : m_api(api), m_display(display), m_lock(trapMutex())
    {
        m_api.sync(m_display, False);
        g_errorCode = 0;
        m_previous = m_api.setErrorHandler(recordError);
    }
    ~ErrorTrap()
    {
        m_api.sync(m_display, False);
        m_api.setErrorHandler(m_previous);
    }
    ErrorTrap(const ErrorTrap&) = delete;
    ErrorTrap& operator=(const ErrorTrap&) = delete;

    /// Waits for the server's answer to every request so far; the failure
    /// naming the first error since the last check, or success.
    RenderResult check(const char* what)
    {
        m_api.sync(m_display, False);
        if (g_errorCode == 0)
            return RenderResult::success();
        const int code = g_errorCode;
        g_errorCode = 0;
        char text[256] = {};
        m_api.getErrorText(m_display, code, text, sizeof text);
        return RenderResult::failure(RenderStatus::kContextFailure,
                                     std::string(what) + " failed with X error " + std::to_string(code) +
                                         " (" + text + ", request code " + std::to_string(g_errorRequest) + ")");
    }

private:
    const XlibApi& m_api;
    Display* m_display;
    std::lock_guard<std::mutex> m_lock;
    XErrorHandler m_previous = nullptr;
};

RenderResult missingLibrary()
{
    return RenderResult::failure(RenderStatus::kContextFailure,
                                 "libX11.so.6 (or one of its functions) could not be loaded: " +
                                     std::string(dlerror() ? dlerror() : "not found"));
}

// One colour channel of a TrueColor pixel: its mask's shift and width.
struct Channel {
    unsigned shift = 0;
    unsigned bits = 0;
    explicit Channel(unsigned long mask)
    {
        while (mask != 0 && (mask & 1u) == 0) {
            mask >>= 1;
            ++shift;
        }
        while ((mask & 1u) != 0) {
            mask >>= 1;
            ++bits;
        }
    }
    unsigned long encode(std::uint32_t value8) const
    {
        const unsigned long max = (1ul << bits) - 1;
        return ((value8 * max + 127) / 255) << shift;
    }
    std::uint32_t decode(unsigned long pixel) const
    {
        const unsigned long max = (1ul << bits) - 1;
        return std::uint32_t((((pixel >> shift) & max) * 255 + max / 2) / max);
    }
};

// Xlib's name for the host's byte order, which a client's XImage has.
constexpr int kHostByteOrder = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ ? LSBFirst : MSBFirst;

// Whether a window of this visual and depth takes the frame's 0xAARRGGBB
// words unchanged: 8 bits a channel in the usual places, depth 24 (at depth
// 32 the top byte would be the window's alpha).
bool holdsHostPixels(const Visual& visual, int depth)
{
    return depth == 24 && visual.red_mask == 0xFF0000ul && visual.green_mask == 0x00FF00ul &&
           visual.blue_mask == 0x0000FFul;
}

// The attributes of a window Q3 can draw into, with the trap set.
RenderResult windowAttributes(const XlibApi& api, Display* display, Window window, XWindowAttributes& attributes,
                              ErrorTrap& trap)
{
    const Status got = api.getWindowAttributes(display, window, &attributes);
    RenderResult result = trap.check("XGetWindowAttributes");
    if (!result)
        return RenderResult::failure(result.status, "the drawable is not a window of the display: " + result.message);
    if (got == 0)
        return RenderResult::failure(RenderStatus::kContextFailure, "the drawable is not a window of the display");
    if (attributes.c_class == InputOnly)
        return RenderResult::failure(RenderStatus::kContextFailure, "the window is InputOnly: it has no pixels");
    if (attributes.visual == nullptr || attributes.visual->c_class != TrueColor)
        return RenderResult::failure(RenderStatus::kContextFailure,
                                     "the window's visual is not TrueColor, which Q3 needs");
    return RenderResult::success();
}

// A window opened for one request: its display, the attributes Q3 checked,
// and the red, green and blue channels of its visual.
struct OpenWindow {
    const XlibApi& api;
    Display* display;
    Window drawable;
    const XWindowAttributes& attributes;
    ErrorTrap& trap;

    Channel red() const { return Channel(attributes.visual->red_mask); }
    Channel green() const { return Channel(attributes.visual->green_mask); }
    Channel blue() const { return Channel(attributes.visual->blue_mask); }
};

// Opens the window the way every request does: the library, then (when a
// rect is given) nothing to do for an empty one, then the error trap and
// the window's attributes; runs use(OpenWindow&) while the trap is set.
template <class Use>
RenderResult withWindow(const NativeWindow& window, const PixelRect* rect, Use&& use)
{
    const XlibApi* api = xlib();
    if (api == nullptr)
        return missingLibrary();
    if (rect != nullptr && (rect->width <= 0 || rect->height <= 0))
        return RenderResult::success();
    Display* display = static_cast<Display*>(window.display);
    ErrorTrap trap(*api, display);
    XWindowAttributes attributes{};
    const RenderResult result = windowAttributes(*api, display, window.drawable, attributes, trap);
    if (!result)
        return result;
    OpenWindow open{*api, display, window.drawable, attributes, trap};
    return use(open);
}

} // namespace

RenderResult windowSize(const NativeWindow& window, std::uint32_t& width, std::uint32_t& height)
{
    return withWindow(window, nullptr, [&](OpenWindow& open) {
        width = std::uint32_t(open.attributes.width);
        height = std::uint32_t(open.attributes.height);
        return RenderResult::success();
    });
}

RenderResult readWindow(const NativeWindow& window, const PixelRect& rect, std::uint32_t* pixels,
                        std::size_t rowPixels)
{
    return withWindow(window, &rect, [&](OpenWindow& open) {
        XImage* image = open.api.getImage(open.display, open.drawable, rect.x, rect.y, unsigned(rect.width),
                                          unsigned(rect.height), AllPlanes, ZPixmap);
        const RenderResult result = open.trap.check("XGetImage");
        if (!result || image == nullptr) {
            if (image != nullptr)
                XDestroyImage(image);
            return result ? RenderResult::failure(RenderStatus::kContextFailure, "XGetImage returned nothing")
                          : result;
        }
        const Channel red = open.red(), green = open.green(), blue = open.blue();
        for (int y = 0; y < rect.height; ++y)
            for (int x = 0; x < rect.width; ++x) {
                const unsigned long pixel = XGetPixel(image, x, y);
                pixels[std::size_t(rect.y + y) * rowPixels + std::size_t(rect.x + x)] =
                    red.decode(pixel) << 16 | green.decode(pixel) << 8 | blue.decode(pixel);
            }
        XDestroyImage(image);
        return RenderResult::success();
    });
}

namespace {

// Sends `image` to the rect's place in the window.
void sendImage(OpenWindow& open, XImage* image, const PixelRect& rect)
{
    GC gc = open.api.createGC(open.display, open.drawable, 0, nullptr);
    open.api.putImage(open.display, open.drawable, gc, image, 0, 0, rect.x, rect.y, unsigned(rect.width),
                      unsigned(rect.height));
    open.api.freeGC(open.display, gc);
}

} // namespace

RenderResult writeWindow(const NativeWindow& window, const PixelRect& rect, const std::uint32_t* pixels,
                         std::size_t rowPixels)
{
    return withWindow(window, &rect, [&](OpenWindow& open) {
        const XWindowAttributes& attributes = open.attributes;
        if (holdsHostPixels(*attributes.visual, attributes.depth)) {
            // The frame's 0xAARRGGBB words are the window's pixels as they are
            // (the server ignores the top byte at depth 24): XPutImage sends
            // them from where they lie, with no copy or conversion (a copy
            // through XPutPixel took a third of an 800 x 600 frame's time).
            const std::uint32_t* first = pixels + std::size_t(rect.y) * rowPixels + std::size_t(rect.x);
            XImage* direct = open.api.createImage(open.display, attributes.visual, unsigned(attributes.depth),
                                                  ZPixmap, 0, reinterpret_cast<char*>(const_cast<std::uint32_t*>(first)),
                                                  unsigned(rect.width), unsigned(rect.height), 32, int(rowPixels * 4));
            if (direct == nullptr)
                return RenderResult::failure(RenderStatus::kOutOfMemory, "XCreateImage failed");
            const bool sendable = direct->bits_per_pixel == 32 && direct->byte_order == kHostByteOrder;
            if (sendable)
                sendImage(open, direct, rect);
            direct->data = nullptr; // the caller's pixels: not XDestroyImage's to free
            XDestroyImage(direct);
            if (sendable)
                return open.trap.check("XPutImage");
        }
        XImage* image = open.api.createImage(open.display, attributes.visual, unsigned(attributes.depth), ZPixmap, 0,
                                             nullptr, unsigned(rect.width), unsigned(rect.height), 32, 0);
        if (image == nullptr)
            return RenderResult::failure(RenderStatus::kOutOfMemory, "XCreateImage failed");
        // XDestroyImage frees the data with free().
        image->data = static_cast<char*>(std::malloc(std::size_t(image->bytes_per_line) * std::size_t(rect.height)));
        if (image->data == nullptr) {
            XDestroyImage(image);
            return RenderResult::failure(RenderStatus::kOutOfMemory, "no memory for the window's image");
        }
        const Channel red = open.red(), green = open.green(), blue = open.blue();
        for (int y = 0; y < rect.height; ++y)
            for (int x = 0; x < rect.width; ++x) {
                const std::uint32_t rgb = pixels[std::size_t(rect.y + y) * rowPixels + std::size_t(rect.x + x)];
                XPutPixel(image, x, y,
                          red.encode(rgb >> 16 & 0xFF) | green.encode(rgb >> 8 & 0xFF) | blue.encode(rgb & 0xFF));
            }
        sendImage(open, image, rect);
        XDestroyImage(image);
        return open.trap.check("XPutImage");
    });
}

RenderResult flushDisplay(void* display)
{
    const XlibApi* api = xlib();
    if (api == nullptr)
        return missingLibrary();
    api->flush(static_cast<Display*>(display));
    return RenderResult::success();
}

RenderResult trueColorVisuals(void* display, void* screen, void*& visuals)
{
    const XlibApi* api = xlib();
    if (api == nullptr)
        return missingLibrary();
    XVisualInfo wanted{};
    wanted.screen = api->screenNumberOfScreen(static_cast<Screen*>(screen));
    wanted.c_class = TrueColor;
    wanted.depth = 24;
    int count = 0;
    XVisualInfo* list = api->getVisualInfo(static_cast<Display*>(display),
                                           VisualScreenMask | VisualClassMask | VisualDepthMask, &wanted, &count);
    if (list == nullptr || count == 0)
        return RenderResult::failure(RenderStatus::kContextFailure, "the screen has no TrueColor visual of depth 24");
    visuals = list;
    return RenderResult::success();
}

} // namespace q3
