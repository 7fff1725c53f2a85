// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Helpers shared by the view, camera, draw context and rendering API tests:
// caller-owned pixmaps of every pixel type read back by a decoder written
// here from QD3DDrawContext.h's table (independent of Q3's PixelConvert), the
// article's Listing 1 curve with its Bezier formula, and checks that an image
// shows a curve and nothing else.

#include "CameraTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGeometry.h"
#include "QD3DRenderer.h"
#include "QD3DView.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace q3test {

struct Rgba {
    int r = 0;
    int g = 0;
    int b = 0;
    int a = 0;
};

inline unsigned bitsOf(TQ3PixelType type)
{
    switch (type) {
    case kQ3PixelTypeRGB32:
    case kQ3PixelTypeARGB32:
        return 32;
    case kQ3PixelTypeRGB24:
        return 24;
    default:
        return 16;
    }
}

inline const char* nameOf(TQ3PixelType type)
{
    switch (type) {
    case kQ3PixelTypeRGB32:
        return "RGB32";
    case kQ3PixelTypeARGB32:
        return "ARGB32";
    case kQ3PixelTypeRGB16:
        return "RGB16";
    case kQ3PixelTypeARGB16:
        return "ARGB16";
    case kQ3PixelTypeRGB16_565:
        return "RGB16_565";
    default:
        return "RGB24";
    }
}

// Widens an n-bit channel to 0..255.
inline int widen(unsigned value, unsigned bits)
{
    const unsigned top = (1u << bits) - 1u;
    return int((value * 255u + top / 2u) / top);
}

/// Caller memory for a TQ3Pixmap, filled with a sentinel byte so that tests
/// can see which bytes Q3 wrote.
class Pixmap {
public:
    static constexpr unsigned char kSentinel = 0x5A;

    Pixmap(unsigned long width, unsigned long height, TQ3PixelType type = kQ3PixelTypeARGB32,
           TQ3Endian byteOrder = kQ3EndianBig, unsigned long padding = 0)
    {
        m_pixmap.width = width;
        m_pixmap.height = height;
        m_pixmap.pixelSize = bitsOf(type);
        m_pixmap.rowBytes = width * (bitsOf(type) / 8) + padding;
        m_pixmap.pixelType = type;
        m_pixmap.bitOrder = kQ3EndianBig;
        m_pixmap.byteOrder = byteOrder;
        m_memory.assign(m_pixmap.rowBytes * height, kSentinel);
        m_pixmap.image = m_memory.data();
    }

    const TQ3Pixmap& pixmap() const { return m_pixmap; }
    unsigned long width() const { return m_pixmap.width; }
    unsigned long height() const { return m_pixmap.height; }
    const std::vector<unsigned char>& bytes() const { return m_memory; }
    void fill(unsigned char value) { std::fill(m_memory.begin(), m_memory.end(), value); }

    /// The pixel's word as QD3DDrawContext.h lays it out.
    std::uint32_t word(unsigned long x, unsigned long y) const
    {
        const unsigned size = bitsOf(m_pixmap.pixelType) / 8;
        const unsigned char* p = m_memory.data() + y * m_pixmap.rowBytes + x * size;
        std::uint32_t value = 0;
        for (unsigned i = 0; i < size; ++i) {
            const unsigned shift =
                m_pixmap.byteOrder == kQ3EndianBig ? 8 * (size - 1 - i) : 8 * i;
            value |= std::uint32_t(p[i]) << shift;
        }
        return value;
    }

    Rgba at(unsigned long x, unsigned long y) const
    {
        const std::uint32_t w = word(x, y);
        switch (m_pixmap.pixelType) {
        case kQ3PixelTypeARGB32:
            return {int((w >> 16) & 255), int((w >> 8) & 255), int(w & 255), int(w >> 24)};
        case kQ3PixelTypeRGB32:
        case kQ3PixelTypeRGB24:
            return {int((w >> 16) & 255), int((w >> 8) & 255), int(w & 255), 255};
        case kQ3PixelTypeARGB16:
            return {widen((w >> 10) & 31, 5), widen((w >> 5) & 31, 5), widen(w & 31, 5),
                    (w & 0x8000) ? 255 : 0};
        case kQ3PixelTypeRGB16:
            return {widen((w >> 10) & 31, 5), widen((w >> 5) & 31, 5), widen(w & 31, 5), 255};
        default:
            return {widen((w >> 11) & 31, 5), widen((w >> 5) & 63, 6), widen(w & 31, 5), 255};
        }
    }

    /// A pixel counts as lit when its red, green or blue is above half.
    bool lit(unsigned long x, unsigned long y) const
    {
        const Rgba c = at(x, y);
        return c.r > 127 || c.g > 127 || c.b > 127;
    }

    /// The first lit pixel (lit()) of the 3 x 3 block around (x, y), row by
    /// row from the top left; all zero when none is (a thin line drawn near
    /// a point may miss its pixel by one).
    Rgba litNear(unsigned long x, unsigned long y) const
    {
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if (lit(x + dx, y + dy))
                    return at(x + dx, y + dy);
        return Rgba{};
    }

    /// The image as 8-bit RGBA, for writing a PNG when a check fails.
    std::vector<unsigned char> rgba() const
    {
        std::vector<unsigned char> out;
        for (unsigned long y = 0; y < height(); ++y)
            for (unsigned long x = 0; x < width(); ++x) {
                const Rgba c = at(x, y);
                out.insert(out.end(), {(unsigned char)c.r, (unsigned char)c.g, (unsigned char)c.b, 255});
            }
        return out;
    }

private:
    std::vector<unsigned char> m_memory;
    TQ3Pixmap m_pixmap{};
};

/// The article's Listing 1 curve: one cubic Bezier span.
struct Listing1 {
    TQ3RationalPoint4D points[4] = {{0, 0, 0, 1}, {1, 1, 0, 1}, {2, 0, 0, 1}, {3, 1, 0, 1}};
    float knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};

    TQ3NURBCurveData data(TQ3AttributeSet attributes = nullptr)
    {
        return TQ3NURBCurveData{4, 4, points, knots, attributes};
    }
};

struct Point3 {
    double x, y, z;
};

/// The cubic Bezier formula B(t) = sum C(3,i) t^i (1-t)^(3-i) P_i for the
/// Listing 1 control points, written out independently of Q3.
inline Point3 listing1At(double t)
{
    const double s = 1.0 - t;
    const double b0 = s * s * s, b1 = 3 * t * s * s, b2 = 3 * t * t * s, b3 = t * t * t;
    return {b0 * 0 + b1 * 1 + b2 * 2 + b3 * 3, b0 * 0 + b1 * 1 + b2 * 0 + b3 * 1, 0.0};
}

/// A world point's position in pixels (x right, y down from the pixmap's top).
using Projection = std::function<Point3(const Point3&)>;

/// The orthographic camera the rendering tests use: looking down -z at the
/// centre (1.5, 0.5) of Listing 1, showing x -0.5..3.5 and y -1..2.
inline TQ3OrthographicCameraData listing1OrthographicCamera()
{
    return orthographicCameraAt(1.5f, 0.5f, 2.0f, 1.5f);
}

/// Where listing1OrthographicCamera puts a world point inside a pane of
/// paneWidth x paneHeight pixels at (paneX, paneY).
inline Projection orthographicProjection(double paneX, double paneY, double paneWidth, double paneHeight)
{
    return [=](const Point3& p) {
        return Point3{paneX + (p.x - 1.5 + 2.0) / 4.0 * paneWidth,
                      paneY + (1.5 - (p.y - 0.5)) / 3.0 * paneHeight, 0.0};
    };
}

/// A view angle aspect camera as the rendering tests use it.
inline TQ3ViewAngleAspectCameraData viewAngleCamera(const Point3& eye, const Point3& target,
                                                    const Point3& up, double fov, double aspect)
{
    TQ3ViewAngleAspectCameraData data{};
    data.cameraData.placement = {{float(eye.x), float(eye.y), float(eye.z)},
                                 {float(target.x), float(target.y), float(target.z)},
                                 {float(up.x), float(up.y), float(up.z)}};
    data.cameraData.range = {0.5f, 50.0f};
    data.cameraData.viewPort = {{-1.0f, 1.0f}, 2.0f, 2.0f};
    data.fov = float(fov);
    data.aspectRatioXToY = float(aspect);
    return data;
}

/// Where that camera puts a world point in a width x height image, written
/// out as a pinhole projection in a look-at frame (fov across y, as
/// aspect >= 1 asks).
inline Projection perspectiveProjection(const Point3& eye, const Point3& target, const Point3& upHint,
                                        double fov, double aspect, double width, double height)
{
    auto sub = [](const Point3& a, const Point3& b) { return Point3{a.x - b.x, a.y - b.y, a.z - b.z}; };
    auto dot = [](const Point3& a, const Point3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
    auto cross = [](const Point3& a, const Point3& b) {
        return Point3{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    };
    auto unit = [&](const Point3& v) {
        const double n = std::sqrt(dot(v, v));
        return Point3{v.x / n, v.y / n, v.z / n};
    };
    const Point3 forward = unit(sub(target, eye));
    const Point3 right = unit(cross(forward, upHint));
    const Point3 up = cross(right, forward);
    const double focal = 1.0 / std::tan(double(float(fov)) / 2.0);
    const double ratio = double(float(aspect));
    return [=](const Point3& p) {
        const Point3 d = sub(p, eye);
        const double depth = dot(d, forward);
        const double ndcX = dot(d, right) / depth * focal / ratio;
        const double ndcY = dot(d, up) / depth * focal;
        return Point3{(ndcX + 1.0) / 2.0 * width, (1.0 - ndcY) / 2.0 * height, 0.0};
    };
}

/// A default draw context for a pixmap: clear to opaque black, no pane.
inline TQ3PixmapDrawContextData pixmapContextData(const TQ3Pixmap& pixmap)
{
    TQ3PixmapDrawContextData data{};
    data.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
    data.drawContextData.clearImageColor = {1.0f, 0.0f, 0.0f, 0.0f};
    data.drawContextData.paneState = kQ3False;
    data.drawContextData.maskState = kQ3False;
    data.drawContextData.doubleBufferState = kQ3False;
    data.pixmap = pixmap;
    return data;
}

/// A view with a renderer, a camera and a pixmap draw context; disposes all
/// of them (its own references) on destruction.
class TestView {
public:
    TestView(const TQ3Pixmap& pixmap, TQ3ObjectType rendererType = kQ3RendererTypeInteractive,
             TQ3CameraObject camera = nullptr)
    {
        m_view = Q3View_New();
        const TQ3PixmapDrawContextData contextData = pixmapContextData(pixmap);
        m_context = Q3PixmapDrawContext_New(&contextData);
        if (camera == nullptr) {
            const TQ3OrthographicCameraData cameraData = listing1OrthographicCamera();
            m_camera = Q3OrthographicCamera_New(&cameraData);
        } else {
            m_camera = Q3Shared_GetReference(camera);
        }
        m_renderer = Q3Renderer_NewFromType(rendererType);
        Q3View_SetDrawContext(m_view, m_context);
        Q3View_SetCamera(m_view, m_camera);
        Q3View_SetRenderer(m_view, m_renderer);
    }
    ~TestView()
    {
        Q3Object_Dispose(m_view);
        Q3Object_Dispose(m_context);
        Q3Object_Dispose(m_camera);
        Q3Object_Dispose(m_renderer);
    }
    TestView(const TestView&) = delete;
    TestView& operator=(const TestView&) = delete;

    TQ3ViewObject view() const { return m_view; }
    TQ3DrawContextObject context() const { return m_context; }
    TQ3CameraObject camera() const { return m_camera; }

    /// Runs the article's loop around submit; returns the final status.
    TQ3ViewStatus render(const std::function<void(TQ3ViewObject)>& submit)
    {
        TQ3ViewStatus status = kQ3ViewStatusError;
        if (Q3View_StartRendering(m_view) != kQ3Success)
            return status;
        do {
            submit(m_view);
            status = Q3View_EndRendering(m_view);
        } while (status == kQ3ViewStatusRetraverse);
        return status;
    }

private:
    TQ3ViewObject m_view = nullptr;
    TQ3DrawContextObject m_context = nullptr;
    TQ3CameraObject m_camera = nullptr;
    TQ3RendererObject m_renderer = nullptr;
};

/// An API test drawing through a TestView into a width x height pixmap of
/// its own, made for each test.
class TestViewApiTest : public Q3ApiTest {
protected:
    TestViewApiTest(unsigned long width, unsigned long height) : m_image(width, height) {}
    void SetUp() override
    {
        Q3ApiTest::SetUp();
        m_view = std::make_unique<TestView>(m_image.pixmap());
    }
    void TearDown() override
    {
        m_view.reset();
        Q3ApiTest::TearDown();
    }

    TQ3ViewObject view() const { return m_view->view(); }

    Pixmap m_image;
    std::unique_ptr<TestView> m_view;
};

/// What checkCurveImage found.
struct CurveImageReport {
    std::size_t litPixels = 0;
    std::size_t strayPixels = 0;    ///< lit pixels farther than the tolerance from the curve
    std::size_t missedSamples = 0;  ///< curve samples with no lit pixel around them
    std::string firstProblem;
};

/// Checks that the lit pixels of `image` inside `area` (x0, y0, x1, y1 in
/// pixels, exclusive ends) are exactly a drawing of Listing 1 under
/// `project`: every lit pixel's centre lies within `tolerance` pixels of the
/// projected curve (sampled densely from the formula, distance to the
/// polyline of 4000 samples, whose own error is far below 0.01 pixel), and
/// every sample's pixel has a lit pixel in its 3x3 neighbourhood, so the
/// curve's whole length is drawn.
inline CurveImageReport checkCurveImage(const Pixmap& image, const Projection& project, int x0, int y0,
                                        int x1, int y1, double tolerance = 1.5)
{
    constexpr int kSamples = 4000;
    std::vector<Point3> samples;
    for (int i = 0; i <= kSamples; ++i)
        samples.push_back(project(listing1At(double(i) / kSamples)));
    CurveImageReport report;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            if (!image.lit(x, y))
                continue;
            ++report.litPixels;
            const double cx = x + 0.5, cy = y + 0.5;
            double best = 1e300;
            for (int i = 0; i < kSamples; ++i) {
                const Point3 a = samples[i], b = samples[i + 1];
                const double dx = b.x - a.x, dy = b.y - a.y;
                const double len2 = dx * dx + dy * dy;
                double t = len2 > 0 ? ((cx - a.x) * dx + (cy - a.y) * dy) / len2 : 0.0;
                t = std::clamp(t, 0.0, 1.0);
                const double ex = a.x + t * dx - cx, ey = a.y + t * dy - cy;
                best = std::min(best, std::sqrt(ex * ex + ey * ey));
            }
            if (best > tolerance) {
                if (report.strayPixels++ == 0)
                    report.firstProblem = "lit pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                          ") is " + std::to_string(best) + " px from the curve";
            }
        }
    for (const Point3& s : samples) {
        const int px = int(std::floor(s.x)), py = int(std::floor(s.y));
        if (px < x0 || py < y0 || px >= x1 || py >= y1)
            continue;
        bool found = false;
        for (int dy = -1; dy <= 1 && !found; ++dy)
            for (int dx = -1; dx <= 1 && !found; ++dx) {
                const int qx = px + dx, qy = py + dy;
                found = qx >= x0 && qy >= y0 && qx < x1 && qy < y1 && image.lit(qx, qy);
            }
        if (!found && report.missedSamples++ == 0 && report.firstProblem.empty())
            report.firstProblem = "no lit pixel near the curve at (" + std::to_string(s.x) + ", " +
                                  std::to_string(s.y) + ")";
    }
    return report;
}

} // namespace q3test
