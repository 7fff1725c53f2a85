// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// libFuzzer target: random sequences of Q3's public C API, decoded from the
// fuzzer's bytes (format: FuzzInput.h). It plays a careless C caller that
// never corrupts memory itself: it passes arbitrary values, NULL, disposed
// handles, stray pointers and objects of the wrong class, but every array
// it passes is as long as the counts it claims (Q3 cannot check that), and
// it never releases a reference it does not hold (no reference count can
// survive that).
//
// Besides the sanitizers, it aborts when Q3 breaks the contract its headers
// state:
//   - a call that fails (kQ3Failure, NULL, kQ3ViewStatusError, or a query's
//     fallback) posts exactly one error, readable with Q3Error_Get and with a
//     message; a call that succeeds posts none; kQ3ErrorInternalError (an
//     unexpected exception) is never posted;
//   - a failed edit leaves the object and its edit index unchanged, a failed
//     getter leaves its output unchanged; a successful edit reads back;
//   - a subdivision style is substituted exactly as QD3DStyle.h says, with
//     one warning when anything was replaced;
//   - the other styles, the shaders' uv settings and the lights accept
//     exactly the values their headers' rules allow, on every path;
//   - a decomposed curve has at most kQ3SubdivisionMaxSegmentsPerCurve + 1
//     vertices, a decomposed quadric or solid at most
//     kQ3SubdivisionMaxTrianglesPerSurface triangles, all finite; a bounding
//     box is never NaN;
//   - after every input, once the fuzzer has disposed what it holds,
//     Q3Memory_CountLiveObjects() is 0 and the last Q3Exit warns of nothing.
// Work per input is bounded (control points, curve draws, loops, views) so
// that no input takes more than a fraction of libFuzzer's -timeout.

#include "CCaller.h"
#include "FuzzInput.h"

#include "Q3NURBCurveTools.h"
#include "QD3D.h"
#include "QD3DCamera.h"
#include "QD3DController.h"
#include "QD3DCustomElements.h"
#include "QD3DDrawContext.h"
#include "QD3DErrors.h"
#include "QD3DGeometry.h"
#include "QD3DLight.h"
#include "QD3DMath.h"
#include "QD3DPick.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DGroup.h"
#include "QD3DIO.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <algorithm>
#include <climits>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstddef>
#include <cstring>
#include <deque>
#include <initializer_list>
#include <map>
#include <memory>
#include <set>
#include <vector>

namespace q3fuzz {
namespace {

// Bounds on the work one input may ask for.
constexpr unsigned long kPointBudget = 4096;    // control points over all curve data built
constexpr int kMaxCurveDraws = 12;              // curve and polyline submits and decompositions
constexpr double kDrawSeconds = 2.0;            // then no more of them (one may take 4 s here)
constexpr int kMaxDuplicates = 16;              // a decomposed polyline may have 2^20 vertices
constexpr int kMaxOperations = 400;
constexpr int kMaxViews = 3;
constexpr int kMaxLoops = 24;                   // rendering and bounding loops started
constexpr int kMaxDrawContexts = 6;
constexpr std::size_t kMaxStale = 64;
// Meshes: how many one input may make, their vertices, the part handles kept.
constexpr int kMaxMeshes = 8;
constexpr unsigned long kMaxMeshVertices = 4096;
constexpr std::size_t kMaxMeshParts = 256;
// Groups may share subgroups, so what one submit or duplicate meets can grow
// exponentially with depth: those calls run only on groups that meet at
// most this many objects, and groups take objects only up to kMaxGroupSize.
constexpr unsigned long kMaxGroupReach = 2000;
constexpr unsigned long kMaxGroupSize = 64;

// What the callbacks saw during the current call.
struct Posts {
    int errors = 0;
    int warnings = 0;
    int notices = 0;
    TQ3Warning lastWarning = kQ3WarningNone;
};
Posts g_posts;
// Q3_FUZZ_TRACE=1 prints each operation, for checking what a seed decodes to.
bool g_trace = false;
// How many times a controller notify function ran (they only count).
unsigned long g_controllerNotifications = 0;

void onError(TQ3Error, TQ3Error, long) { ++g_posts.errors; }
void onWarning(TQ3Warning, TQ3Warning last, long)
{
    ++g_posts.warnings;
    g_posts.lastWarning = last;
}
void onNotice(TQ3Notice, TQ3Notice, long) { ++g_posts.notices; }

[[noreturn]] void die(const char* call, const char* why)
{
    std::fprintf(stderr, "q3 fuzz: %s: %s (Q3Error_Get %d, message \"%s\")\n", call, why,
                 int(Q3Error_Get(nullptr)), Q3Error_GetMessage());
    std::abort();
}

void require(bool condition, const char* call, const char* why)
{
    if (!condition)
        die(call, why);
}

// Call before each API call (the macros below do).
void begin() { g_posts = Posts{}; }

// The error contract, read right after the call.
void checkPosted(const char* call, bool failed)
{
    const TQ3Error error = Q3Error_Get(nullptr);
    if (g_trace)
        std::fprintf(stderr, "q3 fuzz:   %s: %s %d\n", call, failed ? "failed" : "ok", int(error));
    require(error != kQ3ErrorInternalError, call, "posted kQ3ErrorInternalError");
    if (failed) {
        require(error != kQ3ErrorNone, call, "failed without posting an error");
        require(g_posts.errors == 1, call, "failed and did not post exactly one error");
        require(Q3Error_GetMessage()[0] != '\0', call, "posted an error without a message");
    } else {
        require(error == kQ3ErrorNone && g_posts.errors == 0, call, "succeeded but posted an error");
    }
}

TQ3Status checkStatus(const char* call, TQ3Status status)
{
    checkPosted(call, status == kQ3Failure);
    return status;
}

TQ3Object checkObject(const char* call, TQ3Object object)
{
    checkPosted(call, object == nullptr);
    return object;
}

template <class T>
T* checkPointer(const char* call, T* result)
{
    checkPosted(call, result == nullptr);
    return result;
}

TQ3ViewStatus checkViewStatus(const char* call, TQ3ViewStatus status)
{
    checkPosted(call, status == kQ3ViewStatusError);
    return status;
}

// For calls whose result cannot say "failed": an error must come with the
// documented fallback result.
template <class T>
T checkQuery(const char* call, T result, T fallback)
{
    const bool failed = Q3Error_Get(nullptr) != kQ3ErrorNone || g_posts.errors != 0;
    checkPosted(call, failed);
    if (failed)
        require(result == fallback, call, "failed but did not return its fallback value");
    return result;
}

#define STATUS(call) checkStatus(#call, (begin(), (call)))
#define OBJECT(call) checkObject(#call, (begin(), (call)))
#define POINTER(call) checkPointer(#call, (begin(), (call)))
#define VIEWSTATUS(call) checkViewStatus(#call, (begin(), (call)))
#define QUERY(call, fallback) checkQuery(#call, (begin(), (call)), (fallback))

// Stores a raw integer in an enum-typed field, as a C caller may.
template <class E>
void setRaw(E& field, std::int32_t raw)
{
    static_assert(sizeof(E) == sizeof(raw), "Q3's enums are int-sized");
    std::memcpy(&field, &raw, sizeof raw);
}

template <class T>
bool sameBytes(const T& a, const T& b)
{
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

enum class Kind { kCurve, kPolyLine, kLine, kPoint, kStyle, kTransform, kAttributeSet, kCamera,
                  kDrawContext, kRenderer, kView, kTriangle, kPolygon, kTriMesh, kOtherStyle, kShader, kLight, kGroup,
                  kBox, kCone, kCylinder, kDisk, kEllipse, kEllipsoid, kTorus, kMesh, kPatch, kGeneralPolygon,
                  kPolyhedron, kTriGrid, kMarker, kPixmapMarker, kViewHints, kPick };
constexpr int kKindCount = 34;
constexpr bool isQuadric(Kind kind) { return kind >= Kind::kBox && kind <= Kind::kTorus; }
// The kinds Q3Geometry_GetDecomposed returns NULL for without an error.
constexpr bool isPrimitiveKind(Kind kind)
{
    return kind == Kind::kPolyLine || kind == Kind::kLine || kind == Kind::kPoint || kind == Kind::kTriangle ||
           kind == Kind::kTriMesh || kind == Kind::kMarker || kind == Kind::kPixmapMarker;
}

struct Held {
    TQ3Object handle;
    Kind kind;
};

// A TQ3NURBCurveData and the arrays it points at. The arrays always hold at
// least what the counts claim, unless numPoints claims more than a size_t can
// address (which Q3 must reject before reading).
struct CurveBuffers {
    std::vector<TQ3RationalPoint4D> points;
    std::vector<float> knots;
    TQ3NURBCurveData data{};
};

// The substitution rule of QD3DStyle.h, written from the header.
float expectedParameter(std::int32_t method, float value, bool& replaced)
{
    float result = value;
    if (!std::isfinite(value))
        result = kQ3SubdivisionDefaultC1;
    else if (method == kQ3SubdivisionMethodConstant)
        result = value < 1.0f ? 1.0f : std::min(value, float(kQ3SubdivisionMaxConstantSegments));
    else if (value <= 0.0f)
        result = kQ3SubdivisionDefaultC1;
    else if (method == kQ3SubdivisionMethodScreenSpace && value < kQ3SubdivisionMinScreenSpaceC1)
        result = kQ3SubdivisionMinScreenSpaceC1;
    if (!sameBytes(result, value))
        replaced = true;
    return result;
}

// A light of any kind as the fields of a spot light (the others use a
// subset), with its enumerations and Booleans as the ints the caller gave.
struct AnyLight {
    int kind = 0; // 0 ambient, 1 directional, 2 point, 3 spot
    TQ3SpotLightData data{};
    std::int32_t isOn = 1, castsShadows = 0, attenuation = 0, fallOff = 0;
};

bool allFinite(std::initializer_list<float> values)
{
    return std::all_of(values.begin(), values.end(), [](float v) { return std::isfinite(v); });
}

// QD3DLight.h's rules for the light's kind, written from the header.
bool lightObeysRules(const AnyLight& l)
{
    const TQ3SpotLightData& d = l.data;
    const TQ3ColorRGB& c = d.lightData.color;
    const bool common = allFinite({d.lightData.brightness, c.r, c.g, c.b});
    const bool direction = allFinite({d.direction.x, d.direction.y, d.direction.z}) &&
                           !(d.direction.x == 0.0f && d.direction.y == 0.0f && d.direction.z == 0.0f);
    const bool located =
        l.attenuation >= 0 && l.attenuation <= 2 && allFinite({d.location.x, d.location.y, d.location.z});
    const bool cone = allFinite({d.hotAngle, d.outerAngle}) && d.hotAngle >= 0.0f && d.outerAngle >= 0.0f &&
                      d.hotAngle <= kQ3PiOver2 && d.outerAngle <= kQ3PiOver2 && d.outerAngle >= d.hotAngle &&
                      l.fallOff >= 0 && l.fallOff <= 3;
    switch (l.kind) {
    case 0: return common;
    case 1: return common && direction;
    case 2: return common && located;
    default: return common && located && direction && cone;
    }
}

// Each kind's data structure, filled from one AnyLight: as a caller passes
// it (stored false: enumerations and Booleans as given) or as Q3 must store
// it (Booleans 0 or 1). Copied as bytes: the fields may hold any int.
struct LightStructures {
    TQ3LightData common;
    TQ3DirectionalLightData directional;
    TQ3PointLightData point;
    TQ3SpotLightData spot;
};

LightStructures lightStructures(const AnyLight& l, bool stored)
{
    LightStructures out{};
    TQ3SpotLightData& s = out.spot;
    std::memcpy(&s, &l.data, sizeof s);
    setRaw(s.lightData.isOn, stored ? std::int32_t(l.isOn != 0) : l.isOn);
    setRaw(s.castsShadows, stored ? std::int32_t(l.castsShadows != 0) : l.castsShadows);
    setRaw(s.attenuation, l.attenuation);
    setRaw(s.fallOff, l.fallOff);
    std::memcpy(&out.common, &s.lightData, sizeof out.common);
    std::memcpy(&out.directional.lightData, &s.lightData, sizeof s.lightData);
    std::memcpy(&out.directional.castsShadows, &s.castsShadows, sizeof s.castsShadows);
    out.directional.direction = s.direction;
    static_assert(sizeof(TQ3PointLightData) == offsetof(TQ3SpotLightData, direction),
                  "a point light's data is a spot light's first fields");
    std::memcpy(&out.point, &s, sizeof out.point);
    return out;
}

// The bytes Q3 must store for the light.
std::vector<unsigned char> lightBytes(const AnyLight& l)
{
    const LightStructures s = lightStructures(l, true);
    const void* kinds[] = {&s.common, &s.directional, &s.point, &s.spot};
    const std::size_t sizes[] = {sizeof s.common, sizeof s.directional, sizeof s.point, sizeof s.spot};
    const unsigned char* p = static_cast<const unsigned char*>(kinds[l.kind]);
    return std::vector<unsigned char>(p, p + sizes[l.kind]);
}

// A stored light (valid values) of the given kind as an AnyLight.
AnyLight anyLight(int kind, const LightStructures& h)
{
    AnyLight l;
    l.kind = kind;
    const TQ3LightData* commons[] = {&h.common, &h.directional.lightData, &h.point.lightData, &h.spot.lightData};
    if (kind == 3)
        l.data = h.spot;
    l.data.lightData = *commons[kind];
    l.isOn = l.data.lightData.isOn;
    if (kind == 1) {
        l.castsShadows = h.directional.castsShadows;
        l.data.direction = h.directional.direction;
    } else if (kind == 2) {
        l.castsShadows = h.point.castsShadows;
        l.attenuation = h.point.attenuation;
        l.data.location = h.point.location;
    } else if (kind == 3) {
        l.castsShadows = h.spot.castsShadows;
        l.attenuation = h.spot.attenuation;
        l.fallOff = h.spot.fallOff;
    }
    return l;
}

class Session {
public:
    explicit Session(Reader& in) : m_in(in) {}

    void run()
    {
        require(Q3Memory_CountLiveObjects() == 0, "start of input", "objects alive from a previous input");
        begin();
        Q3Initialize();
        require(g_posts.notices == 0 && g_posts.errors == 0, "Q3Initialize", "posted something");
        m_initialized = 1;
        for (int n = 0; n < kMaxOperations && !m_in.atEnd(); ++n)
            step(static_cast<Op>(m_in.u8() % kOpCount));
        finish();
    }

private:
    bool holds(TQ3Object handle) const
    {
        return std::any_of(m_held.begin(), m_held.end(), [&](const Held& h) { return h.handle == handle; });
    }

    const Held* heldEntry(TQ3Object handle) const
    {
        for (const Held& h : m_held)
            if (h.handle == handle)
                return &h;
        return nullptr;
    }

    bool holdsKind(TQ3Object handle, Kind kind) const
    {
        const Held* h = heldEntry(handle);
        return h != nullptr && h->kind == kind;
    }

    void hold(TQ3Object handle, Kind kind) { m_held.push_back({handle, kind}); }

    // Gives back one held reference (the caller disposes it); forgets the
    // object once the last one is gone.
    void release(TQ3Object handle)
    {
        for (auto it = m_held.begin(); it != m_held.end(); ++it)
            if (it->handle == handle) {
                m_held.erase(it);
                break;
            }
        if (!holds(handle)) {
            m_curves.erase(handle);
            if (m_stale.size() < kMaxStale)
                m_stale.push_back(handle);
        }
    }

    // A handle Q3 no longer knows: disposed, and its address not reused.
    // pick() calls this while the arguments of a checked call are being
    // evaluated, so the error this posts is kept out of that call's count.
    bool isDead(TQ3Object handle)
    {
        const Posts saved = g_posts;
        const TQ3ObjectType type = Q3Object_GetLeafType(handle);
        const bool dead = type == kQ3ObjectTypeInvalid && Q3Error_Get(nullptr) == kQ3ErrorInvalidObject;
        g_posts = saved;
        return dead;
    }

    TQ3Object pick(Kind wanted)
    {
        const std::uint8_t selector = m_in.u8();
        const std::uint8_t which = m_in.u8();
        if (selector < 200) {
            std::vector<TQ3Object> candidates;
            if (selector < 160)
                for (const Held& h : m_held)
                    if (h.kind == wanted)
                        candidates.push_back(h.handle);
            if (candidates.empty())
                for (const Held& h : m_held)
                    candidates.push_back(h.handle);
            return candidates.empty() ? nullptr : candidates[which % candidates.size()];
        }
        if (selector < 215 || (selector < 235 && m_stale.empty()))
            return nullptr;
        if (selector < 235) {
            const TQ3Object old = m_stale[which % m_stale.size()];
            // A live address (reused, or kept alive by another object) is not
            // ours to use as a dead one.
            return m_initialized > 0 && !holds(old) && isDead(old) ? old : nullptr;
        }
        static unsigned char neverAnObject[64];
        return reinterpret_cast<TQ3Object>(neverAnObject + 8 * (which % 8));
    }

    std::int32_t enumValue(std::int32_t validCount)
    {
        const std::uint8_t tag = m_in.u8();
        if (tag < 224)
            return tag % (validCount + 1);
        return static_cast<std::int32_t>(m_in.u32());
    }

    TQ3Point3D point3() { return TQ3Point3D{m_in.value(), m_in.value(), m_in.value()}; }
    TQ3Vector3D vector3() { return TQ3Vector3D{m_in.value(), m_in.value(), m_in.value()}; }

    unsigned long takePoints(unsigned long wanted, unsigned long minimum)
    {
        const unsigned long granted = std::max(std::min(wanted, m_pointBudget), minimum);
        m_pointBudget -= std::min(granted, m_pointBudget);
        return granted;
    }

    void readCurve(CurveBuffers& c)
    {
        const std::uint8_t flags = m_in.u8();
        const std::uint8_t mode = flags & 3;
        unsigned long order = (flags & kCurveRawOrder) ? m_in.u32() : 1 + m_in.u8() % 18;
        if (mode == kCurveListing1)
            order = 4;
        // Arrays are sized with an order Q3 accepts, whatever the field says.
        const unsigned long arrayOrder = std::clamp<unsigned long>(order, 2, 16);
        unsigned long count = 0;
        if (mode == kCurveListing1) {
            count = takePoints(4, 4);
            const TQ3RationalPoint4D listing[4] = {{0, 0, 0, 1}, {1, 1, 0, 1}, {2, 0, 0, 1}, {3, 1, 0, 1}};
            c.points.assign(listing, listing + 4);
            c.knots = {0, 0, 0, 0, 1, 1, 1, 1};
        } else if (mode == kCurveRaw) {
            // Bounded by the input too: 16 bytes per point at the least.
            const unsigned long fits = m_in.remaining() / 20 + 1;
            count = takePoints(std::min<unsigned long>(m_in.u8(), fits), 0);
            c.points.resize(count);
            for (TQ3RationalPoint4D& p : c.points)
                p = TQ3RationalPoint4D{m_in.value(), m_in.value(), m_in.value(), m_in.value()};
            c.knots.resize(count + arrayOrder);
            float knot = m_in.value();
            for (float& k : c.knots) {
                k = knot;
                knot += float(m_in.u8() % 4);
            }
        } else {
            count = takePoints(arrayOrder + m_in.u16() % kPointBudget, arrayOrder);
            const float scale = m_in.value();
            const std::uint8_t shape = m_in.u8();
            c.points.resize(count);
            for (unsigned long i = 0; i < count; ++i) {
                const float t = float(i);
                const float w = (shape & 1) ? 1.0f + float(i % 3) : 1.0f;
                const float x = (shape & 2) ? std::cos(t) * scale : t * scale / float(count);
                const float y = (shape & 4) ? std::sin(t) * scale : float(i % 2) * scale;
                const float z = (shape & 8) ? t * scale : 0.0f;
                c.points[i] = TQ3RationalPoint4D{x * w, y * w, z * w, w};
            }
            c.knots.resize(count + arrayOrder);
            const unsigned long interior = count - arrayOrder;
            for (unsigned long i = 0; i < c.knots.size(); ++i) {
                const unsigned long clamped = std::min(std::max(i, arrayOrder - 1) - (arrayOrder - 1), interior + 1);
                c.knots[i] = (shape & 16) ? float(i) : float(clamped);
            }
            if (mode == kCurveRawKnots)
                for (float& k : c.knots)
                    if (m_in.u8() & 1)
                        k = m_in.value();
        }
        if (mode != kCurveRaw) {
            // Patches: single values overwritten anywhere.
            for (int n = m_in.u8() % 8; n > 0; --n) {
                const std::uint8_t target = m_in.u8();
                const float v = m_in.value();
                if ((target & 1) && !c.knots.empty())
                    c.knots[m_in.u16() % c.knots.size()] = v;
                else if (!c.points.empty()) {
                    float* p = &c.points[m_in.u16() % c.points.size()].x;
                    p[target >> 6] = v;
                }
            }
        }
        c.data.order = order;
        c.data.numPoints = count;
        if (flags & kCurveShortCount) {
            const std::uint16_t claimed = m_in.u16();
            c.data.numPoints = count == 0 ? 0 : claimed % count;
        }
        if (flags & kCurveHugeCount)
            c.data.numPoints = ~0UL - m_in.u8();
        c.data.controlPoints = (flags & kCurveNullPoints) || c.points.empty() ? nullptr : c.points.data();
        c.data.knots = (flags & kCurveNullKnots) || c.knots.empty() ? nullptr : c.knots.data();
        c.data.curveAttributeSet = (flags & kCurveAttributes) ? pick(Kind::kAttributeSet) : nullptr;
    }

    struct CurveShape {
        unsigned long order;
        unsigned long numPoints;
    };

    // Checks that a held curve reads back as `c` described it.
    void verifyCurve(TQ3Object curve, const TQ3NURBCurveData& expected)
    {
        TQ3NURBCurveData got{};
        if (STATUS(Q3NURBCurve_GetData(curve, &got)) != kQ3Success)
            die("Q3NURBCurve_GetData", "failed on a live curve");
        require(got.order == expected.order && got.numPoints == expected.numPoints, "Q3NURBCurve_GetData",
                "order or numPoints differ from what was set");
        require(std::memcmp(got.controlPoints, expected.controlPoints,
                            expected.numPoints * sizeof(TQ3RationalPoint4D)) == 0,
                "Q3NURBCurve_GetData", "control points differ from what was set");
        require(std::memcmp(got.knots, expected.knots, (expected.numPoints + expected.order) * sizeof(float)) == 0,
                "Q3NURBCurve_GetData", "knots differ from what was set");
        require(got.curveAttributeSet == expected.curveAttributeSet, "Q3NURBCurve_GetData",
                "the attribute set differs from what was set");
        STATUS(Q3NURBCurve_EmptyData(&got));
        require(got.controlPoints == nullptr && got.knots == nullptr && got.curveAttributeSet == nullptr,
                "Q3NURBCurve_EmptyData", "left pointers behind");
    }

    unsigned long editIndex(TQ3Object object) { return QUERY(Q3Shared_GetEditIndex(object), 0UL); }

    // Curve draws are where an input's time goes (up to 2^20 segments each),
    // so they are counted and timed, with the rasterization at the end of
    // the loop; once either budget is spent, further draws are skipped.
    bool drawAllowed()
    {
        if (m_curveDraws >= kMaxCurveDraws || m_drawSeconds >= kDrawSeconds)
            return false;
        ++m_curveDraws;
        return true;
    }

    class DrawTimer {
    public:
        explicit DrawTimer(double& total) : m_total(total), m_start(std::chrono::steady_clock::now()) {}
        ~DrawTimer()
        {
            m_total += std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
        }
        DrawTimer(const DrawTimer&) = delete;
        DrawTimer& operator=(const DrawTimer&) = delete;

    private:
        double& m_total;
        std::chrono::steady_clock::time_point m_start;
    };

    void step(Op op)
    {
        if (g_trace)
            std::fprintf(stderr, "q3 fuzz: op %u\n", unsigned(op));
        switch (op) {
        case Op::kNewCurve: newCurve(); break;
        case Op::kCurveSetData: curveSetData(); break;
        case Op::kCurveGetData: curveGetData(); break;
        case Op::kSetKnot: setKnot(); break;
        case Op::kGetKnot: getKnot(); break;
        case Op::kSetControlPoint: setControlPoint(); break;
        case Op::kGetControlPoint: getControlPoint(); break;
        case Op::kDuplicate: duplicate(); break;
        case Op::kDispose: dispose(); break;
        case Op::kGetReference: getReference(); break;
        case Op::kNewStyle: newStyle(); break;
        case Op::kStyleSetGet: styleSetGet(); break;
        case Op::kNewTransform: newTransform(); break;
        case Op::kNewAttributeSet: attributeSet(); break;
        case Op::kNewOtherGeometry: otherGeometry(); break;
        case Op::kNewCamera: newCamera(); break;
        case Op::kCameraEdit: cameraEdit(); break;
        case Op::kNewDrawContext: newDrawContext(); break;
        case Op::kDrawContextEdit: drawContextEdit(); break;
        case Op::kNewRenderer: renderer(); break;
        case Op::kNewView: newView(); break;
        case Op::kViewSet: viewSet(); break;
        case Op::kViewGet: viewGet(); break;
        case Op::kStartRendering: startRendering(); break;
        case Op::kEndRendering: {
            const TQ3Object view = pick(Kind::kView);
            const DrawTimer timer(m_drawSeconds);
            VIEWSTATUS(Q3View_EndRendering(view));
            break;
        }
        case Op::kStartBounding: startBounding(); break;
        case Op::kEndBounding: endBounding(); break;
        case Op::kSubmitRetained: submitRetained(); break;
        case Op::kSubmitCurveImmediate: submitCurveImmediate(); break;
        case Op::kSubmitStyleImmediate: submitStyleImmediate(); break;
        case Op::kSubmitTransformImmediate: submitImmediate(); break;
        case Op::kPushPop: pushPop(); break;
        case Op::kDecompose: decompose(); break;
        case Op::kViewState: viewState(); break;
        case Op::kCancelSync: cancelSync(); break;
        case Op::kObjectQueries: objectQueries(); break;
        case Op::kInitializeExit: initializeExit(); break;
        case Op::kOtherGeometryEdit: otherGeometryEdit(); break;
        case Op::kMath: math(); break;
        case Op::kAccessors: accessors(); break;
        case Op::kSurfaces: surfaces(); break;
        case Op::kGroups: groups(); break;
        case Op::kStylesShadersLights: stylesShadersLights(); break;
        case Op::kCurveTools: curveTools(); break;
        case Op::kQuadrics: quadrics(); break;
        case Op::kMeshes: meshes(); break;
        case Op::kPatches: patches(); break;
        case Op::kPolygons2: polygons2(); break;
        case Op::kPixmapMarkers: pixmapMarkers(); break;
        case Op::kViewHints: viewHints(); break;
        case Op::kPicking: picking(); break;
        case Op::kControllers: controllers(); break;
        case Op::kElements: elements(); break;
        case Op::kCount: break;
        }
    }

    void newCurve()
    {
        CurveBuffers c;
        readCurve(c);
        const TQ3Object curve = OBJECT(Q3NURBCurve_New(&c.data));
        if (curve == nullptr)
            return;
        hold(curve, Kind::kCurve);
        m_curves[curve] = CurveShape{c.data.order, c.data.numPoints};
        verifyCurve(curve, c.data);
    }

    void curveSetData()
    {
        const TQ3Object curve = pick(Kind::kCurve);
        CurveBuffers c;
        readCurve(c);
        const bool isCurve = holdsKind(curve, Kind::kCurve) && m_initialized > 0;
        const unsigned long before = isCurve ? editIndex(curve) : 0;
        const bool nullData = m_in.u8() == 0;
        if (STATUS(Q3NURBCurve_SetData(curve, nullData ? nullptr : &c.data)) == kQ3Success) {
            require(isCurve, "Q3NURBCurve_SetData", "accepted something that is not a held curve");
            require(editIndex(curve) != before, "Q3NURBCurve_SetData", "did not change the edit index");
            m_curves[curve] = CurveShape{c.data.order, c.data.numPoints};
            verifyCurve(curve, c.data);
        } else if (isCurve) {
            require(editIndex(curve) == before, "Q3NURBCurve_SetData", "failed but changed the edit index");
        }
    }

    void curveGetData()
    {
        const TQ3Object curve = pick(Kind::kCurve);
        const bool nullData = m_in.u8() == 0;
        TQ3NURBCurveData data;
        std::memset(&data, 0xA5, sizeof data);
        TQ3NURBCurveData untouched = data;
        if (STATUS(Q3NURBCurve_GetData(curve, nullData ? nullptr : &data)) == kQ3Success) {
            const auto shape = m_curves.find(curve);
            require(shape != m_curves.end(), "Q3NURBCurve_GetData", "succeeded on something that is not a curve");
            require(data.order == shape->second.order && data.numPoints == shape->second.numPoints,
                    "Q3NURBCurve_GetData", "order or numPoints changed behind the caller's back");
            STATUS(Q3NURBCurve_EmptyData(&data));
            // Emptying again does nothing and succeeds.
            if (STATUS(Q3NURBCurve_EmptyData(&data)) != kQ3Success)
                die("Q3NURBCurve_EmptyData", "failed on emptied data");
        } else {
            require(sameBytes(data, untouched), "Q3NURBCurve_GetData", "failed but wrote its output");
        }
        if (m_in.u8() == 0)
            STATUS(Q3NURBCurve_EmptyData(nullptr));
    }

    unsigned long knotCount(TQ3Object curve) const
    {
        const auto shape = m_curves.find(curve);
        return shape == m_curves.end() ? 8 : shape->second.numPoints + shape->second.order;
    }

    unsigned long pointCount(TQ3Object curve) const
    {
        const auto shape = m_curves.find(curve);
        return shape == m_curves.end() ? 4 : shape->second.numPoints;
    }

    bool inRangeOfHeldCurve(TQ3Object curve, unsigned long index, unsigned long count) const
    {
        return m_initialized > 0 && m_curves.count(curve) != 0 && index < count;
    }

    void setKnot()
    {
        const TQ3Object curve = pick(Kind::kCurve);
        const unsigned long count = knotCount(curve);
        const unsigned long index = m_in.index(count);
        const float value = m_in.value();
        const bool known = inRangeOfHeldCurve(curve, index, count);
        float old = 0.0f;
        unsigned long before = 0;
        if (known) {
            before = editIndex(curve);
            STATUS(Q3NURBCurve_GetKnot(curve, index, &old));
        }
        if (STATUS(Q3NURBCurve_SetKnot(curve, index, value)) == kQ3Success) {
            require(known, "Q3NURBCurve_SetKnot", "succeeded on an index or object it should reject");
            float now = 0.0f;
            STATUS(Q3NURBCurve_GetKnot(curve, index, &now));
            require(sameBytes(now, value), "Q3NURBCurve_SetKnot", "the knot does not read back");
            require(editIndex(curve) != before, "Q3NURBCurve_SetKnot", "did not change the edit index");
        } else if (known) {
            float now = 0.0f;
            STATUS(Q3NURBCurve_GetKnot(curve, index, &now));
            require(sameBytes(now, old), "Q3NURBCurve_SetKnot", "failed but changed the knot");
            require(editIndex(curve) == before, "Q3NURBCurve_SetKnot", "failed but changed the edit index");
        }
    }

    void getKnot()
    {
        const TQ3Object curve = pick(Kind::kCurve);
        const unsigned long count = knotCount(curve);
        const unsigned long index = m_in.index(count);
        const bool nullOut = m_in.u8() == 0;
        float value = -12345.0f;
        const TQ3Status status = STATUS(Q3NURBCurve_GetKnot(curve, index, nullOut ? nullptr : &value));
        if (inRangeOfHeldCurve(curve, index, count) && !nullOut)
            require(status == kQ3Success, "Q3NURBCurve_GetKnot", "failed on a valid index");
        if (status == kQ3Failure)
            require(value == -12345.0f, "Q3NURBCurve_GetKnot", "failed but wrote its output");
    }

    void setControlPoint()
    {
        const TQ3Object curve = pick(Kind::kCurve);
        const unsigned long count = pointCount(curve);
        const unsigned long index = m_in.index(count);
        const TQ3RationalPoint4D point{m_in.value(), m_in.value(), m_in.value(), m_in.value()};
        const bool nullPoint = m_in.u8() == 0;
        const bool known = inRangeOfHeldCurve(curve, index, count);
        TQ3RationalPoint4D old{};
        unsigned long before = 0;
        if (known) {
            before = editIndex(curve);
            STATUS(Q3NURBCurve_GetControlPoint(curve, index, &old));
        }
        if (STATUS(Q3NURBCurve_SetControlPoint(curve, index, nullPoint ? nullptr : &point)) == kQ3Success) {
            require(known, "Q3NURBCurve_SetControlPoint", "succeeded on an index or object it should reject");
            TQ3RationalPoint4D now{};
            STATUS(Q3NURBCurve_GetControlPoint(curve, index, &now));
            require(sameBytes(now, point), "Q3NURBCurve_SetControlPoint", "the point does not read back");
            require(editIndex(curve) != before, "Q3NURBCurve_SetControlPoint", "did not change the edit index");
        } else if (known) {
            TQ3RationalPoint4D now{};
            STATUS(Q3NURBCurve_GetControlPoint(curve, index, &now));
            require(sameBytes(now, old), "Q3NURBCurve_SetControlPoint", "failed but changed the point");
            require(editIndex(curve) == before, "Q3NURBCurve_SetControlPoint", "failed but changed the edit index");
        }
    }

    void getControlPoint()
    {
        const TQ3Object curve = pick(Kind::kCurve);
        const unsigned long count = pointCount(curve);
        const unsigned long index = m_in.index(count);
        const bool nullOut = m_in.u8() == 0;
        TQ3RationalPoint4D point{-1, -2, -3, -4};
        const TQ3RationalPoint4D untouched = point;
        const TQ3Status status =
            STATUS(Q3NURBCurve_GetControlPoint(curve, index, nullOut ? nullptr : &point));
        if (inRangeOfHeldCurve(curve, index, count) && !nullOut)
            require(status == kQ3Success, "Q3NURBCurve_GetControlPoint", "failed on a valid index");
        if (status == kQ3Failure)
            require(sameBytes(point, untouched), "Q3NURBCurve_GetControlPoint", "failed but wrote its output");
    }

    void duplicate()
    {
        const TQ3Object original = pick(Kind(m_in.u8() % kKindCount));
        if (++m_duplicates > kMaxDuplicates)
            return;
        if (holdsKind(original, Kind::kGroup) && !groupIsSmall(original))
            return;
        const TQ3Object copy = OBJECT(Q3Object_Duplicate(original));
        if (copy == nullptr)
            return;
        const Held* entry = heldEntry(original);
        require(entry != nullptr && copy != original, "Q3Object_Duplicate", "copied something it should reject");
        hold(copy, entry->kind);
        const auto shape = m_curves.find(original);
        if (shape != m_curves.end()) {
            const CurveShape copied = shape->second;
            m_curves[copy] = copied;
            TQ3NURBCurveData data{};
            STATUS(Q3NURBCurve_GetData(original, &data));
            TQ3AttributeSet originalSet = data.curveAttributeSet;
            // The copy has a copy of the attribute set, not the same one.
            TQ3NURBCurveData copyData{};
            STATUS(Q3NURBCurve_GetData(copy, &copyData));
            require(copyData.order == data.order && copyData.numPoints == data.numPoints &&
                        std::memcmp(copyData.controlPoints, data.controlPoints,
                                    data.numPoints * sizeof(TQ3RationalPoint4D)) == 0 &&
                        std::memcmp(copyData.knots, data.knots, (data.numPoints + data.order) * sizeof(float)) == 0,
                    "Q3Object_Duplicate", "the copy of a curve differs from it");
            require((originalSet == nullptr) == (copyData.curveAttributeSet == nullptr) &&
                        (originalSet == nullptr || originalSet != copyData.curveAttributeSet),
                    "Q3Object_Duplicate", "the copy does not have its own attribute set");
            STATUS(Q3NURBCurve_EmptyData(&data));
            STATUS(Q3NURBCurve_EmptyData(&copyData));
        }
    }

    void dispose()
    {
        const TQ3Object object = pick(Kind(m_in.u8() % kKindCount));
        for (int times = 1 + m_in.u8() % 2; times > 0; --times) {
            const bool held = holds(object);
            // Disposing again after the last held reference went is a double
            // dispose only if the object is gone; if another object still
            // holds it, it would release a reference that is not ours.
            if (!held && object != nullptr && m_initialized > 0 && !isDead(object))
                break;
            const TQ3Status status = STATUS(Q3Object_Dispose(object));
            if (m_initialized == 0)
                continue;
            if (held) {
                require(status == kQ3Success, "Q3Object_Dispose", "failed on a held reference");
                release(object);
            } else {
                require(status == kQ3Failure, "Q3Object_Dispose", "disposed something nobody held");
                const TQ3Error expected = object == nullptr ? kQ3ErrorNULLParameter : kQ3ErrorInvalidObject;
                require(Q3Error_Get(nullptr) == expected, "Q3Object_Dispose", "posted the wrong error");
            }
        }
    }

    void getReference()
    {
        const TQ3Object object = pick(Kind(m_in.u8() % kKindCount));
        const TQ3Object reference = OBJECT(Q3Shared_GetReference(object));
        if (reference == nullptr)
            return;
        const Held* entry = heldEntry(object);
        require(entry != nullptr && reference == object, "Q3Shared_GetReference", "referenced something odd");
        hold(reference, entry->kind);
        begin();
        require(Q3Shared_IsReferenced(object) == kQ3True, "Q3Shared_IsReferenced", "missed a second reference");
    }

    TQ3SubdivisionStyleData readStyle(bool& replaced)
    {
        TQ3SubdivisionStyleData data{};
        const std::int32_t method = enumValue(3);
        setRaw(data.method, method);
        data.c1 = m_in.value();
        data.c2 = m_in.value();
        replaced = false;
        m_expectedStyle = data;
        m_expectedStyle.c1 = expectedParameter(method, data.c1, replaced);
        m_expectedStyle.c2 = expectedParameter(method, data.c2, replaced);
        m_styleValid = method >= 0 && method <= 2;
        return data;
    }

    void checkStyle(const char* call, TQ3Status status, bool replaced)
    {
        if (status == kQ3Success) {
            require(m_styleValid, call, "accepted a method outside the enumeration");
            require((g_posts.warnings == 1 && g_posts.lastWarning == kQ3WarningParameterOutOfRange) == replaced,
                    call, "the substitution warning does not match QD3DStyle.h's rule");
        }
    }

    void newStyle()
    {
        bool replaced = false;
        const TQ3SubdivisionStyleData data = readStyle(replaced);
        const TQ3Object style = OBJECT(Q3SubdivisionStyle_New(&data));
        checkStyle("Q3SubdivisionStyle_New", style != nullptr ? kQ3Success : kQ3Failure, replaced);
        if (style == nullptr)
            return;
        hold(style, Kind::kStyle);
        TQ3SubdivisionStyleData got{};
        STATUS(Q3SubdivisionStyle_GetData(style, &got));
        require(sameBytes(got, m_expectedStyle), "Q3SubdivisionStyle_GetData",
                "does not read back as QD3DStyle.h's substitution rule says");
    }

    void styleSetGet()
    {
        const TQ3Object style = pick(Kind::kStyle);
        bool replaced = false;
        const TQ3SubdivisionStyleData data = readStyle(replaced);
        const bool nullData = m_in.u8() == 0;
        const bool isStyle = holdsKind(style, Kind::kStyle) && m_initialized > 0;
        TQ3SubdivisionStyleData before{};
        unsigned long beforeIndex = 0;
        if (isStyle) {
            STATUS(Q3SubdivisionStyle_GetData(style, &before));
            beforeIndex = editIndex(style);
        }
        const TQ3Status status = STATUS(Q3SubdivisionStyle_SetData(style, nullData ? nullptr : &data));
        checkStyle("Q3SubdivisionStyle_SetData", status, replaced);
        TQ3SubdivisionStyleData got;
        std::memset(&got, 0x5A, sizeof got);
        const TQ3SubdivisionStyleData untouched = got;
        const TQ3Status read = STATUS(Q3SubdivisionStyle_GetData(style, m_in.u8() == 0 ? nullptr : &got));
        if (read == kQ3Failure)
            require(sameBytes(got, untouched), "Q3SubdivisionStyle_GetData", "failed but wrote its output");
        else if (status == kQ3Success)
            require(sameBytes(got, m_expectedStyle), "Q3SubdivisionStyle_SetData", "does not read back");
        else if (isStyle) {
            require(sameBytes(got, before), "Q3SubdivisionStyle_SetData", "failed but changed the style");
            require(editIndex(style) == beforeIndex, "Q3SubdivisionStyle_SetData", "failed but changed the edit index");
        }
    }

    TQ3Matrix4x4 readMatrix()
    {
        TQ3Matrix4x4 m{};
        const std::uint8_t mode = m_in.u8();
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                m.value[r][c] = (mode & 1) ? m_in.value() : (r == c ? 1.0f : 0.0f);
        if (!(mode & 1))
            for (int n = mode >> 5; n > 0; --n)
                m.value[m_in.u8() % 4][m_in.u8() % 4] = m_in.value();
        return m;
    }

    void newTransform()
    {
        TQ3Object transform = nullptr;
        switch (m_in.u8() % 6) {
        case 0: {
            const TQ3Matrix4x4 m = readMatrix();
            transform = OBJECT(Q3MatrixTransform_New(m_in.u8() == 0 ? nullptr : &m));
            break;
        }
        case 1: {
            const TQ3Vector3D v = vector3();
            transform = OBJECT(Q3TranslateTransform_New(m_in.u8() == 0 ? nullptr : &v));
            break;
        }
        case 2: {
            const TQ3Vector3D v = vector3();
            transform = OBJECT(Q3ScaleTransform_New(m_in.u8() == 0 ? nullptr : &v));
            break;
        }
        case 3: {
            TQ3RotateTransformData data{};
            setRaw(data.axis, enumValue(3));
            data.radians = m_in.value();
            transform = OBJECT(Q3RotateTransform_New(m_in.u8() == 0 ? nullptr : &data));
            break;
        }
        case 4:
            transform = OBJECT(Q3ResetTransform_New());
            break;
        default: {
            // Q3's matrix helpers feed the transform, as an application's would.
            TQ3Matrix4x4 m{};
            const TQ3Point3D origin = point3();
            const TQ3Vector3D axis = vector3();
            const float angle = m_in.value();
            begin();
            const TQ3Matrix4x4* set = Q3Matrix4x4_SetRotateAboutAxis(&m, &origin, &axis, angle);
            checkPosted("Q3Matrix4x4_SetRotateAboutAxis", set == nullptr);
            transform = OBJECT(Q3MatrixTransform_New(&m));
            break;
        }
        }
        if (transform != nullptr)
            hold(transform, Kind::kTransform);
    }

    void attributeSet()
    {
        TQ3Object set = nullptr;
        if (m_in.u8() < 64) {
            set = OBJECT(Q3AttributeSet_New());
            if (set == nullptr)
                return;
            hold(set, Kind::kAttributeSet);
        } else {
            set = pick(Kind::kAttributeSet);
        }
        for (int n = 1 + m_in.u8() % 4; n > 0; --n) {
            const std::uint8_t which = m_in.u8();
            const TQ3AttributeType type = which < 240 ? TQ3AttributeType(which % 14) : TQ3AttributeType(m_in.u32());
            // Large enough for any attribute's C type (TQ3Tangent2D is 24 bytes).
            float data[8];
            for (float& f : data)
                f = m_in.value();
            if (type == kQ3AttributeTypeHighlightState) {
                const std::int32_t raw = enumValue(2);
                std::memcpy(data, &raw, sizeof raw);
            }
            const bool nullData = m_in.u8() == 0;
            // A surface shader is passed as a handle, read back as a new one.
            const auto releaseShader = [&](TQ3Status status, const float* out) {
                if (status == kQ3Success && type == kQ3AttributeTypeSurfaceShader && !nullData) {
                    TQ3Object shader;
                    std::memcpy(&shader, out, sizeof shader);
                    Q3Object_Dispose(shader);
                }
            };
            switch (m_in.u8() % 10) {
            case 0:
                STATUS(Q3AttributeSet_Add(set, type, nullData ? nullptr : data));
                break;
            case 1: {
                float out[8];
                releaseShader(STATUS(Q3AttributeSet_Get(set, type, nullData ? nullptr : out)), out);
                break;
            }
            case 2:
                QUERY(Q3AttributeSet_Contains(set, type), kQ3False);
                break;
            case 3:
                STATUS(Q3AttributeSet_Clear(set, type));
                break;
            case 4: {
                TQ3AttributeType next = type;
                STATUS(Q3AttributeSet_GetNextAttributeType(set, nullData ? nullptr : &next));
                break;
            }
            case 5:
                STATUS(Q3AttributeSet_Inherit(pick(Kind::kAttributeSet), pick(Kind::kAttributeSet), set));
                break;
            case 6: {
                // The surface shader attribute: a texture shader is not among
                // the fuzzer's objects, so this tries what must be refused.
                TQ3Object shader = pick(Kind::kShader);
                STATUS(Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceShader, nullData ? nullptr : &shader));
                break;
            }
            case 7: {
                // The generic set calls on the same set (an attribute set is a set).
                float out[8];
                STATUS(Q3Set_Add(set, type, nullData ? nullptr : data));
                releaseShader(STATUS(Q3Set_Get(set, type, nullData ? nullptr : out)), out);
                QUERY(Q3Set_Contains(set, type), kQ3False);
                TQ3ElementType next = type;
                STATUS(Q3Set_GetNextElementType(set, nullData ? nullptr : &next));
                break;
            }
            case 8:
                STATUS(Q3Set_Clear(set, type));
                break;
            default:
                STATUS(Q3AttributeSet_Empty(set));
                break;
            }
        }
    }

    void otherGeometry()
    {
        const std::uint8_t which = m_in.u8() % 3;
        TQ3AttributeSet sets[3] = {nullptr, nullptr, nullptr};
        const std::uint8_t withSets = m_in.u8();
        for (int i = 0; i < 3; ++i)
            if (withSets & (1 << i))
                sets[i] = pick(Kind::kAttributeSet);
        TQ3Object geometry = nullptr;
        Kind kind = Kind::kPoint;
        if (which == 0) {
            const TQ3PointData data{point3(), sets[0]};
            geometry = OBJECT(Q3Point_New(&data));
        } else if (which == 1) {
            const TQ3LineData data{{{point3(), sets[0]}, {point3(), sets[1]}}, sets[2]};
            geometry = OBJECT(Q3Line_New(&data));
            kind = Kind::kLine;
        } else {
            std::vector<TQ3Vertex3D> vertices(m_in.u8() % 17);
            for (TQ3Vertex3D& v : vertices)
                v = TQ3Vertex3D{point3(), nullptr};
            std::vector<TQ3AttributeSet> segmentSets(vertices.empty() ? 0 : vertices.size() - 1, sets[0]);
            TQ3PolyLineData data{};
            data.numVertices = vertices.size();
            data.vertices = vertices.empty() ? nullptr : vertices.data();
            data.segmentAttributeSet = (withSets & 8) && !segmentSets.empty() ? segmentSets.data() : nullptr;
            data.polyLineAttributeSet = sets[1];
            geometry = OBJECT(Q3PolyLine_New(&data));
            kind = Kind::kPolyLine;
        }
        if (geometry != nullptr)
            hold(geometry, kind);
    }

    // Get, Set and Empty of points, lines and polylines; a successful Get is
    // always emptied, and emptying twice must succeed.
    // Apple's single-field accessors: positions and attribute sets of points,
    // lines and polylines by index, a geometry's own set, transform and
    // camera fields. A successful Get of a set hands over a reference.
    void accessors()
    {
        const bool nullArg = m_in.u8() == 0;
        const bool set = m_in.u8() & 1;
        const TQ3AttributeSet attributes = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
        TQ3AttributeSet got = nullptr;
        TQ3AttributeSet* out = nullArg ? nullptr : &got;
        TQ3Point3D position = point3();
        TQ3Point3D* where = nullArg ? nullptr : &position;
        switch (m_in.u8() % 8) {
        case 0: {
            const TQ3Object point = pick(Kind::kPoint);
            set ? STATUS(Q3Point_SetPosition(point, where)) : STATUS(Q3Point_GetPosition(point, where));
            break;
        }
        case 1: {
            const TQ3Object line = pick(Kind::kLine);
            const unsigned long index = m_in.index(2);
            set ? STATUS(Q3Line_SetVertexPosition(line, index, where))
                : STATUS(Q3Line_GetVertexPosition(line, index, where));
            break;
        }
        case 2: {
            const TQ3Object line = pick(Kind::kLine);
            const unsigned long index = m_in.index(2);
            set ? STATUS(Q3Line_SetVertexAttributeSet(line, index, attributes))
                : STATUS(Q3Line_GetVertexAttributeSet(line, index, out));
            break;
        }
        case 3: {
            const TQ3Object polyLine = pick(Kind::kPolyLine);
            const unsigned long index = m_in.index(8);
            set ? STATUS(Q3PolyLine_SetVertexPosition(polyLine, index, where))
                : STATUS(Q3PolyLine_GetVertexPosition(polyLine, index, where));
            break;
        }
        case 4: {
            const TQ3Object polyLine = pick(Kind::kPolyLine);
            const unsigned long index = m_in.index(8);
            if (m_in.u8() & 1)
                set ? STATUS(Q3PolyLine_SetSegmentAttributeSet(polyLine, index, attributes))
                    : STATUS(Q3PolyLine_GetSegmentAttributeSet(polyLine, index, out));
            else
                set ? STATUS(Q3PolyLine_SetVertexAttributeSet(polyLine, index, attributes))
                    : STATUS(Q3PolyLine_GetVertexAttributeSet(polyLine, index, out));
            break;
        }
        case 5: {
            static const Kind kGeometries[] = {Kind::kCurve,    Kind::kPolyLine, Kind::kLine,   Kind::kPoint,
                                               Kind::kTriangle, Kind::kPolygon,  Kind::kTriMesh};
            const TQ3Object geometry = pick(kGeometries[m_in.u8() % 7]);
            set ? STATUS(Q3Geometry_SetAttributeSet(geometry, attributes))
                : STATUS(Q3Geometry_GetAttributeSet(geometry, out));
            break;
        }
        case 6:
            transformField(set, nullArg);
            break;
        default:
            cameraField(set, nullArg);
            break;
        }
        if (got != nullptr)
            hold(got, Kind::kAttributeSet);
    }

    void transformField(bool set, bool nullArg)
    {
        const TQ3Object transform = pick(Kind::kTransform);
        TQ3Matrix4x4 matrix = readMatrix();
        TQ3Vector3D vector = vector3();
        TQ3RotateTransformData rotate{};
        const std::int32_t rawAxis = enumValue(3);
        setRaw(rotate.axis, rawAxis);
        rotate.radians = m_in.value();
        TQ3Axis axisOut{};
        float radians = rotate.radians;
        switch (m_in.u8() % 7) {
        case 0:
            set ? STATUS(Q3MatrixTransform_Set(transform, nullArg ? nullptr : &matrix))
                : STATUS(Q3MatrixTransform_Get(transform, nullArg ? nullptr : &matrix));
            break;
        case 1:
            set ? STATUS(Q3TranslateTransform_Set(transform, nullArg ? nullptr : &vector))
                : STATUS(Q3TranslateTransform_Get(transform, nullArg ? nullptr : &vector));
            break;
        case 2:
            set ? STATUS(Q3ScaleTransform_Set(transform, nullArg ? nullptr : &vector))
                : STATUS(Q3ScaleTransform_Get(transform, nullArg ? nullptr : &vector));
            break;
        case 3:
            set ? STATUS(Q3RotateTransform_SetData(transform, nullArg ? nullptr : &rotate))
                : STATUS(Q3RotateTransform_GetData(transform, nullArg ? nullptr : &rotate));
            break;
        case 4:
            set ? STATUS(q3fuzz_RotateTransform_SetAxis(transform, rawAxis))
                : STATUS(Q3RotateTransform_GetAxis(transform, nullArg ? nullptr : &axisOut));
            break;
        case 5:
            set ? STATUS(Q3RotateTransform_SetAngle(transform, radians))
                : STATUS(Q3RotateTransform_GetAngle(transform, nullArg ? nullptr : &radians));
            break;
        default:
            if (set)
                QUERY(Q3Transform_GetType(transform), TQ3ObjectType{kQ3ObjectTypeInvalid});
            else
                POINTER(Q3Transform_GetMatrix(transform, nullArg ? nullptr : &matrix));
            break;
        }
    }

    void cameraField(bool set, bool nullArg)
    {
        using Setter = TQ3Status (*)(TQ3CameraObject, float);
        using Getter = TQ3Status (*)(TQ3CameraObject, float*);
        struct Field {
            const char* name;
            Setter setter;
            Getter getter;
        };
        static const Field kFields[] = {
            {"Q3OrthographicCamera_Left", Q3OrthographicCamera_SetLeft, Q3OrthographicCamera_GetLeft},
            {"Q3OrthographicCamera_Top", Q3OrthographicCamera_SetTop, Q3OrthographicCamera_GetTop},
            {"Q3OrthographicCamera_Right", Q3OrthographicCamera_SetRight, Q3OrthographicCamera_GetRight},
            {"Q3OrthographicCamera_Bottom", Q3OrthographicCamera_SetBottom, Q3OrthographicCamera_GetBottom},
            {"Q3ViewPlaneCamera_ViewPlane", Q3ViewPlaneCamera_SetViewPlane, Q3ViewPlaneCamera_GetViewPlane},
            {"Q3ViewPlaneCamera_HalfWidth", Q3ViewPlaneCamera_SetHalfWidth, Q3ViewPlaneCamera_GetHalfWidth},
            {"Q3ViewPlaneCamera_HalfHeight", Q3ViewPlaneCamera_SetHalfHeight, Q3ViewPlaneCamera_GetHalfHeight},
            {"Q3ViewPlaneCamera_CenterX", Q3ViewPlaneCamera_SetCenterX, Q3ViewPlaneCamera_GetCenterX},
            {"Q3ViewPlaneCamera_CenterY", Q3ViewPlaneCamera_SetCenterY, Q3ViewPlaneCamera_GetCenterY},
            {"Q3ViewAngleAspectCamera_FOV", Q3ViewAngleAspectCamera_SetFOV, Q3ViewAngleAspectCamera_GetFOV},
            {"Q3ViewAngleAspectCamera_AspectRatio", Q3ViewAngleAspectCamera_SetAspectRatio,
             Q3ViewAngleAspectCamera_GetAspectRatio},
        };
        const Field& field = kFields[m_in.u8() % (sizeof kFields / sizeof kFields[0])];
        const TQ3Object camera = pick(Kind::kCamera);
        float value = m_in.value();
        begin();
        const TQ3Status status = set ? field.setter(camera, value) : field.getter(camera, nullArg ? nullptr : &value);
        checkStatus(field.name, status);
    }

    void otherGeometryEdit()
    {
        const std::uint8_t family = m_in.u8() % 3;
        const TQ3Object geometry = pick(family == 0 ? Kind::kPoint : family == 1 ? Kind::kLine : Kind::kPolyLine);
        const std::uint8_t action = m_in.u8() % 3;
        const TQ3AttributeSet set = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
        const bool nullData = m_in.u8() == 0;
        if (family == 0) {
            TQ3PointData data{point3(), set};
            if (action == 0) {
                if (STATUS(Q3Point_GetData(geometry, nullData ? nullptr : &data)) == kQ3Success) {
                    STATUS(Q3Point_EmptyData(&data));
                    STATUS(Q3Point_EmptyData(&data));
                }
            } else if (action == 1) {
                STATUS(Q3Point_SetData(geometry, nullData ? nullptr : &data));
            } else {
                STATUS(Q3Point_EmptyData(nullptr));
            }
        } else if (family == 1) {
            TQ3LineData data{{{point3(), nullptr}, {point3(), set}}, set};
            if (action == 0) {
                if (STATUS(Q3Line_GetData(geometry, nullData ? nullptr : &data)) == kQ3Success) {
                    STATUS(Q3Line_EmptyData(&data));
                    STATUS(Q3Line_EmptyData(&data));
                }
            } else if (action == 1) {
                STATUS(Q3Line_SetData(geometry, nullData ? nullptr : &data));
            } else {
                STATUS(Q3Line_EmptyData(nullptr));
            }
        } else {
            std::vector<TQ3Vertex3D> vertices(m_in.u8() % 9);
            for (TQ3Vertex3D& v : vertices)
                v = TQ3Vertex3D{point3(), (m_in.u8() & 1) ? set : nullptr};
            std::vector<TQ3AttributeSet> segmentSets(vertices.empty() ? 0 : vertices.size() - 1, set);
            TQ3PolyLineData data{vertices.size(), vertices.empty() ? nullptr : vertices.data(),
                                 segmentSets.empty() ? nullptr : segmentSets.data(), set};
            if (action == 0) {
                if (STATUS(Q3PolyLine_GetData(geometry, nullData ? nullptr : &data)) == kQ3Success) {
                    STATUS(Q3PolyLine_EmptyData(&data));
                    STATUS(Q3PolyLine_EmptyData(&data));
                }
            } else if (action == 1) {
                if (drawAllowed())
                    STATUS(Q3PolyLine_SetData(geometry, nullData ? nullptr : &data));
            } else {
                STATUS(Q3PolyLine_EmptyData(nullptr));
            }
        }
    }

    // Triangles, polygons and trimeshes: New, SetData, GetData with
    // EmptyData (twice), immediate Submit and the per-vertex calls, with data
    // that may break any rule (non-finite coordinates and attribute values,
    // indices out of range, unknown attribute types, NULL arrays, counts no
    // array could hold, dead or foreign attribute sets). A failed SetData
    // must leave the edit index alone; a successful one must read back.
    void surfaces()
    {
        const std::uint8_t family = m_in.u8() % 3;
        const std::uint8_t action = m_in.u8() % 5;
        const Kind kind = family == 0 ? Kind::kTriangle : family == 1 ? Kind::kPolygon : Kind::kTriMesh;
        const TQ3AttributeSet set = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
        const bool nullData = m_in.u8() == 0;
        if (family == 0) {
            TQ3TriangleData data{};
            for (TQ3Vertex3D& v : data.vertices)
                v = TQ3Vertex3D{point3(), (m_in.u8() & 1) ? set : nullptr};
            data.triangleAttributeSet = set;
            surfaceAction<TQ3TriangleData>(action, kind, nullData ? nullptr : &data, Q3Triangle_New, Q3Triangle_SetData,
                                           Q3Triangle_GetData, Q3Triangle_EmptyData, Q3Triangle_Submit,
                                           [&](const TQ3TriangleData& a, const TQ3TriangleData& b) {
                                               for (int i = 0; i < 3; ++i)
                                                   if (!sameBytes(a.vertices[i], b.vertices[i]))
                                                       return false;
                                               return a.triangleAttributeSet == b.triangleAttributeSet;
                                           });
            if (action == 4)
                vertexCalls(kind, 3, set, Q3Triangle_GetVertexPosition, Q3Triangle_SetVertexPosition,
                            Q3Triangle_GetVertexAttributeSet, Q3Triangle_SetVertexAttributeSet);
        } else if (family == 1) {
            std::vector<TQ3Vertex3D> vertices(m_in.u8() % 12);
            for (TQ3Vertex3D& v : vertices)
                v = TQ3Vertex3D{point3(), (m_in.u8() & 1) ? set : nullptr};
            TQ3PolygonData data{vertices.size(), vertices.empty() ? nullptr : vertices.data(), set};
            if (m_in.u8() == 0) {
                data.numVertices = ~0UL - m_in.u8();
                data.vertices = nullptr;
            }
            surfaceAction<TQ3PolygonData>(action, kind, nullData ? nullptr : &data, Q3Polygon_New, Q3Polygon_SetData,
                                          Q3Polygon_GetData, Q3Polygon_EmptyData, Q3Polygon_Submit,
                                          [&](const TQ3PolygonData& a, const TQ3PolygonData& b) {
                                              if (a.numVertices != b.numVertices)
                                                  return false;
                                              for (unsigned long i = 0; i < a.numVertices; ++i)
                                                  if (!sameBytes(a.vertices[i], b.vertices[i]))
                                                      return false;
                                              return a.polygonAttributeSet == b.polygonAttributeSet;
                                          });
            if (action == 4)
                vertexCalls(kind, 12, set, Q3Polygon_GetVertexPosition, Q3Polygon_SetVertexPosition,
                            Q3Polygon_GetVertexAttributeSet, Q3Polygon_SetVertexAttributeSet);
        } else {
            TriMeshBuffers mesh;
            readTriMesh(mesh, set);
            surfaceAction<TQ3TriMeshData>(action, kind, nullData ? nullptr : &mesh.data, Q3TriMesh_New,
                                          Q3TriMesh_SetData, Q3TriMesh_GetData, Q3TriMesh_EmptyData,
                                          Q3TriMesh_Submit, [&](const TQ3TriMeshData& a, const TQ3TriMeshData& b) {
                                              return a.numPoints == b.numPoints && a.numTriangles == b.numTriangles &&
                                                     (a.numPoints == 0 ||
                                                      std::memcmp(a.points, b.points,
                                                                  a.numPoints * sizeof(TQ3Point3D)) == 0) &&
                                                     a.triMeshAttributeSet == b.triMeshAttributeSet;
                                          });
        }
    }

    // A TriMesh whose arrays hold what its counts claim (unless a count is
    // one no array could hold, with the array NULL).
    struct TriMeshBuffers {
        std::vector<TQ3Point3D> points;
        std::vector<TQ3TriMeshTriangleData> triangles;
        std::vector<TQ3TriMeshEdgeData> edges;
        std::vector<TQ3TriMeshAttributeData> vertexAttributes;
        std::vector<TQ3TriMeshAttributeData> triangleAttributes;
        std::deque<std::vector<float>> values; // a deque: growing it moves no array
        std::deque<std::vector<char>> uses;
        TQ3TriMeshData data{};
    };

    void readTriMesh(TriMeshBuffers& m, TQ3AttributeSet set)
    {
        m.points.resize(m_in.u8() % 10);
        for (TQ3Point3D& p : m.points)
            p = point3();
        const unsigned long points = m.points.size();
        m.triangles.resize(m_in.u8() % 10);
        for (TQ3TriMeshTriangleData& t : m.triangles)
            for (unsigned long& i : t.pointIndices)
                i = m_in.index(points);
        m.edges.resize(m_in.u8() % 4);
        for (TQ3TriMeshEdgeData& e : m.edges) {
            e.pointIndices[0] = m_in.index(points);
            e.pointIndices[1] = m_in.index(points);
            e.triangleIndices[0] = (m_in.u8() & 1) ? (unsigned long)kQ3ArrayIndexNULL : m_in.index(m.triangles.size());
            e.triangleIndices[1] = 0xFFFFFFFFUL;
        }
        // Attribute arrays per vertex and per triangle: the standard types
        // (1..10) and some that are not; values with NaN and Inf possible.
        for (int a = m_in.u8() % 3; a > 0; --a) {
            const bool onVertices = m_in.u8() & 1;
            const std::size_t count = onVertices ? points : m.triangles.size();
            const std::uint8_t raw = m_in.u8();
            const TQ3AttributeType type = raw < 200 ? 1 + raw % 10 : TQ3AttributeType(std::int8_t(raw));
            m.values.emplace_back(count * 6 + 1);
            for (float& v : m.values.back())
                v = (m_in.u8() % 8 == 0) ? m_in.value() : float(m_in.u8() % 2);
            m.uses.emplace_back();
            if (m_in.u8() & 1) {
                m.uses.back().resize(count + 1);
                for (char& u : m.uses.back())
                    u = char(m_in.u8() & 1);
            }
            (onVertices ? m.vertexAttributes : m.triangleAttributes)
                .push_back(TQ3TriMeshAttributeData{type, m.values.back().data(),
                                                   m.uses.back().empty() ? nullptr : m.uses.back().data()});
        }
        TQ3TriMeshData& d = m.data;
        d.triMeshAttributeSet = set;
        d.numTriangles = m.triangles.size();
        d.triangles = m.triangles.empty() ? nullptr : m.triangles.data();
        d.numEdges = m.edges.size();
        d.edges = m.edges.empty() ? nullptr : m.edges.data();
        d.numPoints = points;
        d.points = m.points.empty() ? nullptr : m.points.data();
        d.numVertexAttributeTypes = m.vertexAttributes.size();
        d.vertexAttributeTypes = m.vertexAttributes.empty() ? nullptr : m.vertexAttributes.data();
        d.numTriangleAttributeTypes = m.triangleAttributes.size();
        d.triangleAttributeTypes = m.triangleAttributes.empty() ? nullptr : m.triangleAttributes.data();
        if (m_in.u8() == 0) {
            d.numTriangles = ~0UL - m_in.u8();
            d.triangles = nullptr;
        }
    }

    template <class Data, class Same>
    void surfaceAction(std::uint8_t action, Kind kind, Data* data, TQ3GeometryObject (*create)(const Data*),
                       TQ3Status (*setData)(TQ3GeometryObject, const Data*),
                       TQ3Status (*getData)(TQ3GeometryObject, Data*), TQ3Status (*emptyData)(Data*),
                       TQ3Status (*submit)(const Data*, TQ3ViewObject), Same same)
    {
        switch (action) {
        case 0: {
            const TQ3Object geometry = OBJECT(create(data));
            if (geometry != nullptr)
                hold(geometry, kind);
            break;
        }
        case 1: {
            const TQ3Object geometry = pick(kind);
            const bool ours = holdsKind(geometry, kind) && m_initialized > 0;
            const unsigned long before = ours ? editIndex(geometry) : 0;
            const TQ3Status status = STATUS(setData(geometry, data));
            if (!ours)
                break;
            if (status != kQ3Success) {
                require(editIndex(geometry) == before, "SetData", "a failed SetData changed the edit index");
                break;
            }
            Data got{};
            if (STATUS(getData(geometry, &got)) == kQ3Success) {
                require(same(got, *data), "GetData", "the data read back differs from what was set");
                STATUS(emptyData(&got));
            }
            break;
        }
        case 2: {
            Data got{};
            if (STATUS(getData(pick(kind), data == nullptr ? nullptr : &got)) == kQ3Success) {
                STATUS(emptyData(&got));
                STATUS(emptyData(&got));
            }
            break;
        }
        case 3: {
            const TQ3Object view = pick(Kind::kView);
            const DrawTimer timer(m_drawSeconds);
            STATUS(submit(data, view));
            break;
        }
        default:
            break;
        }
    }

    void vertexCalls(Kind kind, unsigned long count, TQ3AttributeSet set,
                     TQ3Status (*getPosition)(TQ3GeometryObject, unsigned long, TQ3Point3D*),
                     TQ3Status (*setPosition)(TQ3GeometryObject, unsigned long, const TQ3Point3D*),
                     TQ3Status (*getSet)(TQ3GeometryObject, unsigned long, TQ3AttributeSet*),
                     TQ3Status (*setSet)(TQ3GeometryObject, unsigned long, TQ3AttributeSet))
    {
        const TQ3Object geometry = pick(kind);
        const unsigned long index = m_in.index(count);
        const bool nullArg = m_in.u8() == 0;
        TQ3Point3D position = point3();
        TQ3AttributeSet got = nullptr;
        switch (m_in.u8() % 4) {
        case 0: STATUS(getPosition(geometry, index, nullArg ? nullptr : &position)); break;
        case 1: STATUS(setPosition(geometry, index, nullArg ? nullptr : &position)); break;
        case 2: STATUS(getSet(geometry, index, nullArg ? nullptr : &got)); break;
        default: STATUS(setSet(geometry, index, set)); break;
        }
        if (got != nullptr)
            hold(got, Kind::kAttributeSet);
    }

    // Styles other than subdivision, illumination shaders and lights
    // (QD3DStyle.h, QD3DShader.h, QD3DLight.h), with values that may break
    // any rule: New, the setters, Get, immediate and retained Submit, the
    // shaders' uv calls, lights' single-field setters. Where the handle is a
    // held object of the call's kind, a call must succeed exactly when the
    // values obey the header's rules (TQ3Booleans: any int, stored as 0 or
    // 1); a failed edit must leave the object's state and edit index alone,
    // a successful one must change the edit index and read back.
    void stylesShadersLights()
    {
        // A held style, shader or light's state through its getters, as
        // bytes (field by field: TQ3AntiAliasStyleData has padding); empty
        // for anything else.
        auto snapshot = [&](TQ3Object object) {
            std::vector<unsigned char> bytes;
            auto add = [&](const auto& value) {
                const auto* p = reinterpret_cast<const unsigned char*>(&value);
                bytes.insert(bytes.end(), p, p + sizeof value);
            };
            const bool ours = holdsKind(object, Kind::kOtherStyle) || holdsKind(object, Kind::kShader) ||
                              holdsKind(object, Kind::kLight);
            if (!ours || m_initialized == 0)
                return bytes;
            auto read = [&](auto get, auto value) {
                if (STATUS(get(object, &value)) != kQ3Success)
                    die("snapshot", "a getter failed on a held object of its kind");
                add(value);
            };
            switch (QUERY(Q3Object_GetLeafType(object), TQ3ObjectType{kQ3ObjectTypeInvalid})) {
            case kQ3StyleTypePickID: read(Q3PickIDStyle_Get, 0UL); break;
            case kQ3StyleTypePickParts: read(Q3PickPartsStyle_Get, TQ3PickParts{}); break;
            case kQ3StyleTypeCastShadows: read(Q3CastShadowsStyle_Get, kQ3False); break;
            case kQ3StyleTypeReceiveShadows: read(Q3ReceiveShadowsStyle_Get, kQ3False); break;
            case kQ3StyleTypeFill: read(Q3FillStyle_Get, kQ3FillStyleFilled); break;
            case kQ3StyleTypeBackfacing: read(Q3BackfacingStyle_Get, kQ3BackfacingStyleBoth); break;
            case kQ3StyleTypeInterpolation: read(Q3InterpolationStyle_Get, kQ3InterpolationStyleNone); break;
            case kQ3StyleTypeOrientation: read(Q3OrientationStyle_Get, kQ3OrientationStyleClockwise); break;
            case kQ3StyleTypeFog: read(Q3FogStyle_GetData, TQ3FogStyleData{}); break;
            case kQ3StyleTypeAntiAlias: {
                TQ3AntiAliasStyleData data{};
                STATUS(Q3AntiAliasStyle_GetData(object, &data));
                add(data.state), add(data.mode), add(data.quality);
                break;
            }
            case kQ3StyleTypeHighlight: {
                TQ3AttributeSet set = nullptr;
                STATUS(Q3HighlightStyle_Get(object, &set));
                add(set);
                if (set != nullptr)
                    STATUS(Q3Object_Dispose(set));
                break;
            }
            case kQ3LightTypeAmbient: read(Q3AmbientLight_GetData, TQ3LightData{}); break;
            case kQ3LightTypeDirectional: read(Q3DirectionalLight_GetData, TQ3DirectionalLightData{}); break;
            case kQ3LightTypePoint: read(Q3PointLight_GetData, TQ3PointLightData{}); break;
            case kQ3LightTypeSpot: read(Q3SpotLight_GetData, TQ3SpotLightData{}); break;
            default: // an illumination shader
                read(Q3Shader_GetUVTransform, TQ3Matrix3x3{});
                read(Q3Shader_GetUBoundary, kQ3ShaderUVBoundaryWrap);
                read(Q3Shader_GetVBoundary, kQ3ShaderUVBoundaryWrap);
                break;
            }
            return bytes;
        };
        // Runs one edit. `valid`: 1 or 0 when the handle is known to be of the
        // call's kind and the values do or do not obey the rules, -1 when the
        // outcome is not predicted. `expected`: the state a success must leave
        // (empty: not checked).
        auto edit = [&](const char* call, TQ3Object object, int valid, const std::vector<unsigned char>& expected,
                        auto run) {
            const std::vector<unsigned char> before = snapshot(object);
            const unsigned long index = before.empty() ? 0 : editIndex(object);
            begin();
            const TQ3Status status = checkStatus(call, run());
            if (valid >= 0 && m_initialized > 0)
                require((status == kQ3Success) == (valid == 1), call, "disagrees with the header's rules");
            if (before.empty())
                return status;
            if (status == kQ3Success) {
                require(editIndex(object) != index, call, "succeeded without changing the edit index");
                require(expected.empty() || snapshot(object) == expected, call, "does not read back");
            } else {
                require(editIndex(object) == index, call, "failed but changed the edit index");
                require(snapshot(object) == before, call, "failed but changed the object");
            }
            return status;
        };
        auto bytesOf = [](const auto& value) {
            const auto* p = reinterpret_cast<const unsigned char*>(&value);
            return std::vector<unsigned char>(p, p + sizeof value);
        };
        const std::uint8_t action = m_in.u8() % 5;
        if (action == 0) {
            // A style: New, immediate Submit or Set, with one value.
            static const TQ3ObjectType kTypes[] = {kQ3StyleTypeFill,        kQ3StyleTypeBackfacing,
                                                   kQ3StyleTypeInterpolation, kQ3StyleTypeOrientation,
                                                   kQ3StyleTypeCastShadows, kQ3StyleTypeReceiveShadows,
                                                   kQ3StyleTypePickID,      kQ3StyleTypePickParts,
                                                   kQ3StyleTypeAntiAlias,   kQ3StyleTypeFog,
                                                   kQ3StyleTypeHighlight};
            const int which = m_in.u8() % 11;
            static const int kLast[] = {2, 2, 2, 1, 1, 1};
            const std::int32_t raw = which < 6 ? enumValue(kLast[which] + 1) : 0;
            const unsigned long word = which == 6 ? m_in.u32() : which == 7 ? (unsigned long)enumValue(8) : 0;
            TQ3AntiAliasStyleData antiAlias{};
            TQ3FogStyleData fog{};
            std::int32_t state = enumValue(2), mode = 0;
            if (which == 8) {
                setRaw(antiAlias.state, state);
                antiAlias.mode = (unsigned long)enumValue(4);
                antiAlias.quality = m_in.value();
            } else if (which == 9) {
                mode = enumValue(4);
                setRaw(fog.state, state);
                setRaw(fog.mode, mode);
                fog.fogStart = m_in.value();
                fog.fogEnd = m_in.value();
                fog.density = m_in.value();
                fog.color = {m_in.value(), m_in.value(), m_in.value(), m_in.value()};
            }
            const TQ3Object set = which == 10 ? pick(Kind::kAttributeSet) : nullptr;
            const bool nullData = m_in.u8() == 0;
            bool obeys = true;
            std::vector<unsigned char> expected;
            if (which < 4)
                obeys = raw >= 0 && raw <= kLast[which], expected = bytesOf(raw);
            else if (which < 6)
                expected = bytesOf(std::int32_t(raw != 0));
            else if (which == 6)
                expected = bytesOf(word);
            else if (which == 7)
                obeys = (word & ~7UL) == 0, expected = bytesOf(word);
            else if (which == 8) {
                obeys = (state == 0 || state == 1) && (antiAlias.mode & ~3UL) == 0 &&
                        std::isfinite(antiAlias.quality) && antiAlias.quality >= 0.0f && antiAlias.quality <= 1.0f;
                expected = bytesOf(antiAlias.state);
                for (const auto& part : {bytesOf(antiAlias.mode), bytesOf(antiAlias.quality)})
                    expected.insert(expected.end(), part.begin(), part.end());
            } else if (which == 9) {
                obeys = (state == 0 || state == 1) && mode >= 0 && mode <= 3 &&
                        allFinite({fog.fogStart, fog.fogEnd, fog.density, fog.color.a, fog.color.r, fog.color.g,
                                   fog.color.b}) &&
                        fog.density >= 0.0f && !(state == 1 && mode == 0 && !(fog.fogStart < fog.fogEnd));
                expected = bytesOf(fog);
            } else {
                obeys = set == nullptr || holdsKind(set, Kind::kAttributeSet), expected = bytesOf(set);
            }
            auto create = [&]() -> TQ3Object {
                switch (which) {
                case 6: return Q3PickIDStyle_New(word);
                case 7: return Q3PickPartsStyle_New(word);
                case 8: return Q3AntiAliasStyle_New(nullData ? nullptr : &antiAlias);
                case 9: return Q3FogStyle_New(nullData ? nullptr : &fog);
                case 10: return Q3HighlightStyle_New(set);
                default: return q3fuzz_EnumStyle_New(which, raw);
                }
            };
            const std::uint8_t path = m_in.u8() % 3;
            if (path == 0) {
                begin();
                const TQ3Object style = checkObject("a style's _New", create());
                if (m_initialized > 0)
                    require((style != nullptr) == (obeys && !(nullData && (which == 8 || which == 9))),
                            "a style's _New", "disagrees with QD3DStyle.h's rules");
                if (style == nullptr)
                    return;
                hold(style, Kind::kOtherStyle);
                require(snapshot(style) == expected, "a style's _New", "does not read back");
            } else if (path == 1) {
                const TQ3Object view = pick(Kind::kView);
                begin();
                switch (which) {
                case 6: checkStatus("Q3PickIDStyle_Submit", Q3PickIDStyle_Submit(word, view)); break;
                case 7: checkStatus("Q3PickPartsStyle_Submit", Q3PickPartsStyle_Submit(word, view)); break;
                case 8: checkStatus("Q3AntiAliasStyle_Submit", Q3AntiAliasStyle_Submit(&antiAlias, view)); break;
                case 9: checkStatus("Q3FogStyle_Submit", Q3FogStyle_Submit(&fog, view)); break;
                case 10: checkStatus("Q3HighlightStyle_Submit", Q3HighlightStyle_Submit(set, view)); break;
                default: checkStatus("a style's _Submit", q3fuzz_EnumStyle_Submit(which, raw, view)); break;
                }
            } else {
                const TQ3Object style = pick(Kind::kOtherStyle);
                const bool sameKind = holdsKind(style, Kind::kOtherStyle) && m_initialized > 0 &&
                                      QUERY(Q3Style_GetType(style), TQ3ObjectType{0}) == kTypes[which];
                const int valid = sameKind ? int(obeys && !(nullData && (which == 8 || which == 9))) : -1;
                edit("a style's _Set", style, valid, expected, [&] {
                    switch (which) {
                    case 6: return Q3PickIDStyle_Set(style, word);
                    case 7: return Q3PickPartsStyle_Set(style, word);
                    case 8: return Q3AntiAliasStyle_SetData(style, nullData ? nullptr : &antiAlias);
                    case 9: return Q3FogStyle_SetData(style, nullData ? nullptr : &fog);
                    case 10: return Q3HighlightStyle_Set(style, set);
                    default: return q3fuzz_EnumStyle_Set(which, style, raw);
                    }
                });
            }
        } else if (action == 1) {
            // Calls on any style, shader or light: types, retained submit,
            // highlight Get, a light's single getters.
            static const Kind kKinds[] = {Kind::kOtherStyle, Kind::kShader, Kind::kLight};
            const TQ3Object object = pick(kKinds[m_in.u8() % 3]);
            const TQ3Object view = pick(Kind::kView);
            TQ3AttributeSet set = nullptr;
            const bool nullOut = m_in.u8() == 0;
            float value = 0.5f;
            switch (m_in.u8() % 9) {
            case 6: QUERY(Q3Light_GetType(object), TQ3ObjectType{kQ3ObjectTypeInvalid}); break;
            case 7:
                if (STATUS(Q3SpotLight_GetOuterAngle(object, nullOut ? nullptr : &value)) != kQ3Success)
                    require(value == 0.5f, "Q3SpotLight_GetOuterAngle", "failed but wrote its output");
                break;
            case 8:
                if (STATUS(Q3Light_GetBrightness(object, nullOut ? nullptr : &value)) != kQ3Success)
                    require(value == 0.5f, "Q3Light_GetBrightness", "failed but wrote its output");
                break;
            case 0: QUERY(Q3Style_GetType(object), TQ3ObjectType{kQ3ObjectTypeInvalid}); break;
            case 1: QUERY(Q3Shader_GetType(object), TQ3ObjectType{kQ3ObjectTypeInvalid}); break;
            case 2: QUERY(Q3IlluminationShader_GetType(object), TQ3ObjectType{kQ3ObjectTypeInvalid}); break;
            case 3: STATUS(Q3Style_Submit(object, view)); break;
            case 4: STATUS(Q3Shader_Submit(object, view)); break;
            default:
                STATUS(Q3HighlightStyle_Get(object, nullOut ? nullptr : &set));
                if (set != nullptr)
                    hold(set, Kind::kAttributeSet);
                break;
            }
        } else if (action == 2) {
            // Illumination shaders and the uv calls every shader has.
            const std::uint8_t call = m_in.u8() % 4;
            if (call == 0) {
                static TQ3ShaderObject (*const kNew[])() = {Q3PhongIllumination_New, Q3LambertIllumination_New,
                                                            Q3NULLIllumination_New};
                const TQ3Object shader = OBJECT(kNew[m_in.u8() % 3]());
                if (shader != nullptr)
                    hold(shader, Kind::kShader);
                return;
            }
            const TQ3Object shader = pick(Kind::kShader);
            const bool ours = holdsKind(shader, Kind::kShader) && m_initialized > 0;
            const bool nullArg = m_in.u8() == 0;
            if (call == 1) {
                TQ3Matrix3x3 m{};
                for (auto& row : m.value)
                    for (float& v : row)
                        v = (m_in.u8() & 1) ? m_in.value() : 0.0f;
                bool finite = true;
                for (auto& row : m.value)
                    for (float v : row)
                        finite = finite && std::isfinite(v);
                std::vector<unsigned char> expected = bytesOf(m);
                if (ours) {
                    const std::vector<unsigned char> now = snapshot(shader);
                    expected.insert(expected.end(), now.end() - 2 * sizeof(TQ3ShaderUVBoundary), now.end());
                }
                edit("Q3Shader_SetUVTransform", shader, ours ? int(finite && !nullArg) : -1, expected,
                     [&] { return Q3Shader_SetUVTransform(shader, nullArg ? nullptr : &m); });
                TQ3Matrix3x3 out = m;
                if (STATUS(Q3Shader_GetUVTransform(shader, m_in.u8() == 0 ? nullptr : &out)) != kQ3Success)
                    require(sameBytes(out, m), "Q3Shader_GetUVTransform", "failed but wrote its output");
            } else if (call == 2) {
                const bool v = m_in.u8() & 1;
                const std::int32_t raw = enumValue(2);
                edit(v ? "Q3Shader_SetVBoundary" : "Q3Shader_SetUBoundary", shader,
                     ours ? int(raw == 0 || raw == 1) : -1, {},
                     [&] { return q3fuzz_SetEnumField(v ? 8 : 7, shader, raw); });
            } else {
                TQ3ShaderUVBoundary out = kQ3ShaderUVBoundaryClamp;
                TQ3ShaderUVBoundary* where = nullArg ? nullptr : &out;
                const TQ3Status status = (m_in.u8() & 1) ? STATUS(Q3Shader_GetUBoundary(shader, where))
                                                         : STATUS(Q3Shader_GetVBoundary(shader, where));
                if (status != kQ3Success)
                    require(out == kQ3ShaderUVBoundaryClamp, "Q3Shader_GetUBoundary", "failed but wrote its output");
            }
        } else {
            // Lights: New or SetData of a kind with any values (action 3), or
            // one value through its own setter (action 4).
            AnyLight l;
            l.kind = m_in.u8() % 4;
            TQ3SpotLightData& d = l.data;
            l.isOn = enumValue(1);
            d.lightData.brightness = m_in.value();
            d.lightData.color = {m_in.value(), m_in.value(), m_in.value()};
            l.castsShadows = enumValue(1);
            l.attenuation = enumValue(3);
            d.location = point3();
            d.direction = vector3();
            d.hotAngle = m_in.value();
            d.outerAngle = m_in.value();
            l.fallOff = enumValue(4);
            const bool nullData = m_in.u8() == 0;
            const LightStructures given = lightStructures(l, false);
            static const TQ3ObjectType kKinds[] = {kQ3LightTypeAmbient, kQ3LightTypeDirectional, kQ3LightTypePoint,
                                                   kQ3LightTypeSpot};
            const TQ3Object light = pick(Kind::kLight);
            const bool ours = holdsKind(light, Kind::kLight) && m_initialized > 0;
            // The held light's current values.
            AnyLight now;
            if (ours) {
                const TQ3ObjectType type = QUERY(Q3Light_GetType(light), TQ3ObjectType{0});
                now.kind = int(std::find(kKinds, kKinds + 4, type) - kKinds);
                const std::vector<unsigned char> bytes = snapshot(light);
                LightStructures held{};
                void* into[] = {&held.common, &held.directional, &held.point, &held.spot};
                std::memcpy(into[now.kind], bytes.data(), bytes.size());
                now = anyLight(now.kind, held);
            }
            if (action == 3 && (m_in.u8() & 1)) {
                begin();
                TQ3Object created = nullptr;
                switch (l.kind) {
                case 0: created = Q3AmbientLight_New(nullData ? nullptr : &given.common); break;
                case 1: created = Q3DirectionalLight_New(nullData ? nullptr : &given.directional); break;
                case 2: created = Q3PointLight_New(nullData ? nullptr : &given.point); break;
                default: created = Q3SpotLight_New(nullData ? nullptr : &given.spot); break;
                }
                checkObject("a light's _New", created);
                if (m_initialized > 0)
                    require((created != nullptr) == (!nullData && lightObeysRules(l)), "a light's _New",
                            "disagrees with QD3DLight.h's rules");
                if (created != nullptr) {
                    hold(created, Kind::kLight);
                    require(snapshot(created) == lightBytes(l), "a light's _New", "does not read back");
                }
            } else if (action == 3) {
                const int valid = ours && now.kind == l.kind ? int(!nullData && lightObeysRules(l)) : -1;
                edit("a light's _SetData", light, valid, lightBytes(l), [&] {
                    switch (l.kind) {
                    case 0: return Q3AmbientLight_SetData(light, nullData ? nullptr : &given.common);
                    case 1: return Q3DirectionalLight_SetData(light, nullData ? nullptr : &given.directional);
                    case 2: return Q3PointLight_SetData(light, nullData ? nullptr : &given.point);
                    default: return Q3SpotLight_SetData(light, nullData ? nullptr : &given.spot);
                    }
                });
            } else {
                // One setter, the kind it takes (-1: any light), and what it
                // does to the light's values.
                const int call = m_in.u8() % 16;
                static const int kTakes[] = {-1, -1, -1, -1, 1, 1, 2, 2, 2, 3, 3, 3, 3, 3, 3, 3};
                static const bool kPointer[] = {false, false, true, true, false, true, false, false,
                                                true,  false, false, true, true, false, false, false};
                AnyLight next = now;
                switch (call) {
                case 0: next.isOn = l.isOn; break;
                case 1: next.data.lightData.brightness = d.lightData.brightness; break;
                case 2: next.data.lightData.color = d.lightData.color; break;
                case 3: next.data.lightData = d.lightData, next.isOn = l.isOn; break;
                case 4: case 6: case 9: next.castsShadows = l.castsShadows; break;
                case 5: case 12: next.data.direction = d.direction; break;
                case 7: case 10: next.attenuation = l.attenuation; break;
                case 8: case 11: next.data.location = d.location; break;
                case 13: next.data.hotAngle = d.hotAngle; break;
                case 14: next.data.outerAngle = d.outerAngle; break;
                default: next.fallOff = l.fallOff; break;
                }
                const bool nullArg = nullData && kPointer[call];
                const bool fits = ours && (kTakes[call] < 0 || kTakes[call] == now.kind);
                edit("a light's setter", light, fits ? int(!nullArg && lightObeysRules(next)) : -1,
                     fits ? lightBytes(next) : std::vector<unsigned char>{}, [&] {
                         const TQ3ColorRGB* color = nullArg ? nullptr : &d.lightData.color;
                         const TQ3Vector3D* direction = nullArg ? nullptr : &d.direction;
                         const TQ3Point3D* location = nullArg ? nullptr : &d.location;
                         switch (call) {
                         case 0: return q3fuzz_SetEnumField(0, light, l.isOn);
                         case 1: return Q3Light_SetBrightness(light, d.lightData.brightness);
                         case 2: return Q3Light_SetColor(light, color);
                         case 3: return Q3Light_SetData(light, nullArg ? nullptr : &given.common);
                         case 4: return q3fuzz_SetEnumField(1, light, l.castsShadows);
                         case 5: return Q3DirectionalLight_SetDirection(light, direction);
                         case 6: return q3fuzz_SetEnumField(2, light, l.castsShadows);
                         case 7: return q3fuzz_SetEnumField(3, light, l.attenuation);
                         case 8: return Q3PointLight_SetLocation(light, location);
                         case 9: return q3fuzz_SetEnumField(4, light, l.castsShadows);
                         case 10: return q3fuzz_SetEnumField(5, light, l.attenuation);
                         case 11: return Q3SpotLight_SetLocation(light, location);
                         case 12: return Q3SpotLight_SetDirection(light, direction);
                         case 13: return Q3SpotLight_SetHotAngle(light, d.hotAngle);
                         case 14: return Q3SpotLight_SetOuterAngle(light, d.outerAngle);
                         default: return q3fuzz_SetEnumField(6, light, l.fallOff);
                         }
                     });
            }
        }
    }

    // Boxes, cones, cylinders, disks, ellipses, ellipsoids and tori: New,
    // SetData, GetData with EmptyData (twice), immediate Submit, every
    // per-field call and the decomposition. The data starts as a valid shape
    // whose floats an input may overwrite with anything (NaN, infinities,
    // zero or parallel axes, ranges outside [0, 1], a ratio <= 0), with any
    // caps bits and attribute sets (dead, foreign, a box's six face sets).
    struct QuadricFields {
        float* floats; // origin, then the vectors, the torus's ratio, the ranges
        int floatCount;
        TQ3EndCap* caps;       // NULL if the type has none
        TQ3AttributeSet* sets; // the part sets and then the geometry's, consecutive
        int setCount;
    };
    static QuadricFields fieldsOf(TQ3BoxData& d) { return {&d.origin.x, 12, nullptr, &d.boxAttributeSet, 1}; }
    static QuadricFields fieldsOf(TQ3ConeData& d) { return {&d.origin.x, 16, &d.caps, &d.interiorAttributeSet, 4}; }
    static QuadricFields fieldsOf(TQ3CylinderData& d) { return {&d.origin.x, 16, &d.caps, &d.interiorAttributeSet, 5}; }
    static QuadricFields fieldsOf(TQ3DiskData& d) { return {&d.origin.x, 13, nullptr, &d.diskAttributeSet, 1}; }
    static QuadricFields fieldsOf(TQ3EllipseData& d) { return {&d.origin.x, 11, nullptr, &d.ellipseAttributeSet, 1}; }
    static QuadricFields fieldsOf(TQ3EllipsoidData& d)
    {
        return {&d.origin.x, 16, &d.caps, &d.interiorAttributeSet, 2};
    }
    static QuadricFields fieldsOf(TQ3TorusData& d) { return {&d.origin.x, 17, &d.caps, &d.interiorAttributeSet, 2}; }

    template <class Data>
    static bool sameQuadric(const Data& a, const Data& b)
    {
        const QuadricFields x = fieldsOf(const_cast<Data&>(a));
        const QuadricFields y = fieldsOf(const_cast<Data&>(b));
        return std::memcmp(x.floats, y.floats, std::size_t(x.floatCount) * sizeof(float)) == 0 &&
               (x.caps == nullptr || *x.caps == *y.caps) &&
               std::memcmp(x.sets, y.sets, std::size_t(x.setCount) * sizeof(TQ3AttributeSet)) == 0;
    }
    static bool sameQuadric(const TQ3BoxData& a, const TQ3BoxData& b)
    {
        const bool faces = a.faceAttributeSet == nullptr || b.faceAttributeSet == nullptr
                               ? a.faceAttributeSet == b.faceAttributeSet
                               : std::memcmp(a.faceAttributeSet, b.faceAttributeSet, 6 * sizeof(TQ3AttributeSet)) == 0;
        return faces && sameQuadric<TQ3BoxData>(a, b);
    }

    template <class Data>
    void quadricData(std::uint8_t action, Kind kind, Data& data, bool nullData,
                     TQ3GeometryObject (*create)(const Data*),
                     TQ3Status (*setData)(TQ3GeometryObject, const Data*),
                     TQ3Status (*getData)(TQ3GeometryObject, Data*), TQ3Status (*emptyData)(Data*),
                     TQ3Status (*submit)(const Data*, TQ3ViewObject))
    {
        // A valid shape: unit axes along y, z and x (a torus's tube half as
        // thick), full ranges; disks and ellipses take the last two axes.
        static const float kShape[] = {0, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 0, 1, 0, 1};
        static const float kTorus[] = {0, 0, 0, 0, 0.5f, 0, 0, 0, 1, 1, 0, 0, 0.5f, 0, 1, 0, 1};
        const QuadricFields f = fieldsOf(data);
        if (f.floatCount == 17)
            std::copy(kTorus, kTorus + 17, f.floats);
        else if (f.floatCount == 12 || f.floatCount == 16)
            std::copy(kShape, kShape + f.floatCount, f.floats);
        else
            std::copy(kShape + 6, kShape + 3 + f.floatCount, f.floats + 3);
        for (int n = m_in.u8() % 4; n > 0; --n)
            f.floats[m_in.u8() % f.floatCount] = m_in.value();
        if (f.caps != nullptr)
            *f.caps = TQ3EndCap(enumValue(7));
        const std::uint8_t withSets = m_in.u8();
        for (int i = 0; i < f.setCount; ++i)
            if (withSets & (1 << i))
                f.sets[i] = pick(Kind::kAttributeSet);
        if (action == 3 && !drawAllowed())
            return;
        surfaceAction<Data>(action, kind, nullData ? nullptr : &data, create, setData, getData, emptyData, submit,
                            [](const Data& a, const Data& b) { return sameQuadric(a, b); });
    }

    void quadrics()
    {
        const std::uint8_t type = m_in.u8() % 7;
        const std::uint8_t action = m_in.u8() % 6;
        const Kind kind = Kind(int(Kind::kBox) + type);
        const bool nullData = m_in.u8() == 0;
        if (action == 4)
            return quadricField(type, kind);
        if (action == 5)
            return quadricDecompose(kind);
        switch (type) {
        case 0: {
            TQ3BoxData data{};
            TQ3AttributeSet faces[6] = {};
            if (m_in.u8() & 1) {
                for (TQ3AttributeSet& face : faces)
                    face = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
                data.faceAttributeSet = faces;
            }
            quadricData(action, kind, data, nullData, Q3Box_New, Q3Box_SetData, Q3Box_GetData, Q3Box_EmptyData,
                        Q3Box_Submit);
            break;
        }
        case 1: {
            TQ3ConeData data{};
            quadricData(action, kind, data, nullData, Q3Cone_New, Q3Cone_SetData, Q3Cone_GetData,
                        Q3Cone_EmptyData, Q3Cone_Submit);
            break;
        }
        case 2: {
            TQ3CylinderData data{};
            quadricData(action, kind, data, nullData, Q3Cylinder_New, Q3Cylinder_SetData, Q3Cylinder_GetData,
                        Q3Cylinder_EmptyData, Q3Cylinder_Submit);
            break;
        }
        case 3: {
            TQ3DiskData data{};
            quadricData(action, kind, data, nullData, Q3Disk_New, Q3Disk_SetData, Q3Disk_GetData,
                        Q3Disk_EmptyData, Q3Disk_Submit);
            break;
        }
        case 4: {
            TQ3EllipseData data{};
            quadricData(action, kind, data, nullData, Q3Ellipse_New, Q3Ellipse_SetData, Q3Ellipse_GetData,
                        Q3Ellipse_EmptyData, Q3Ellipse_Submit);
            break;
        }
        case 5: {
            TQ3EllipsoidData data{};
            quadricData(action, kind, data, nullData, Q3Ellipsoid_New, Q3Ellipsoid_SetData, Q3Ellipsoid_GetData,
                        Q3Ellipsoid_EmptyData, Q3Ellipsoid_Submit);
            break;
        }
        default: {
            TQ3TorusData data{};
            quadricData(action, kind, data, nullData, Q3Torus_New, Q3Torus_SetData, Q3Torus_GetData,
                        Q3Torus_EmptyData, Q3Torus_Submit);
            break;
        }
        }
    }

    // General polygons, polyhedra, triangle grids and markers: data with
    // a few vertices (coordinates from the input, NaN and infinities
    // included), raw counts and indices now and then, and every per-field
    // call, each edit checked as surfaceAction checks SetData.
    static bool samePoints(const TQ3Vertex3D* a, const TQ3Vertex3D* b, unsigned long n)
    {
        for (unsigned long i = 0; i < n; ++i)
            if (!sameBytes(a[i].point, b[i].point) || a[i].attributeSet != b[i].attributeSet)
                return false;
        return true;
    }

    void polygons2()
    {
        const std::uint8_t type = m_in.u8() % 4;
        const std::uint8_t action = m_in.u8() % 5;
        const Kind kind = Kind(int(Kind::kGeneralPolygon) + type);
        const bool nullData = m_in.u8() == 0;
        if (action == 4)
            return polygons2Field(type, kind);
        if (action == 3 && !drawAllowed())
            return;
        std::vector<TQ3Vertex3D> vertices(2 + m_in.u8() % 10);
        for (TQ3Vertex3D& v : vertices) {
            v.point = TQ3Point3D{float(m_in.u8() % 7), float(m_in.u8() % 7), 0.0f};
            v.attributeSet = (m_in.u8() % 8 == 0) ? pick(Kind::kAttributeSet) : nullptr;
        }
        for (int n = m_in.u8() % 3; n > 0; --n)
            vertices[m_in.u8() % vertices.size()].point.z = m_in.value();
        const unsigned long count = static_cast<unsigned long>(vertices.size());
        // Now and then a count no array could hold, which must be refused
        // before any array is read (a smaller lie would make the fuzzer, not
        // Q3, read past its own arrays).
        const bool rawCount = m_in.u8() % 16 == 0;
        const unsigned long hugeCount =
            !rawCount ? 0 : m_in.u8() % 2 ? ~0UL : static_cast<unsigned long>(kQ3GeometryMaxArrayCount) + 1 + m_in.u8();
        switch (type) {
        case 0: {
            std::vector<TQ3GeneralPolygonContourData> contours;
            for (unsigned long first = 0; first < count;) {
                const unsigned long n = std::min<unsigned long>(count - first, 1 + m_in.u8() % 6);
                contours.push_back({n, vertices.data() + first});
                first += n;
            }
            TQ3GeneralPolygonData data{static_cast<unsigned long>(contours.size()), contours.data(),
                                       kQ3GeneralPolygonShapeHintComplex, nullptr};
            setRaw(data.shapeHint, enumValue(3));
            if (rawCount)
                data.numContours = hugeCount;
            surfaceAction<TQ3GeneralPolygonData>(
                action, kind, nullData ? nullptr : &data, Q3GeneralPolygon_New, Q3GeneralPolygon_SetData,
                Q3GeneralPolygon_GetData, Q3GeneralPolygon_EmptyData, Q3GeneralPolygon_Submit,
                [](const TQ3GeneralPolygonData& a, const TQ3GeneralPolygonData& b) {
                    if (a.numContours != b.numContours || a.shapeHint != b.shapeHint)
                        return false;
                    for (unsigned long c = 0; c < a.numContours; ++c)
                        if (a.contours[c].numVertices != b.contours[c].numVertices ||
                            !samePoints(a.contours[c].vertices, b.contours[c].vertices, a.contours[c].numVertices))
                            return false;
                    return true;
                });
            break;
        }
        case 1: {
            std::vector<TQ3PolyhedronTriangleData> triangles(1 + m_in.u8() % 6);
            for (TQ3PolyhedronTriangleData& t : triangles) {
                for (unsigned long& index : t.vertexIndices)
                    index = m_in.u8() % 32 == 0 ? m_in.u32() : m_in.index(count);
                t.edgeFlag = m_in.u8() % 9;
                t.triangleAttributeSet = (m_in.u8() % 4 == 0) ? pick(Kind::kAttributeSet) : nullptr;
            }
            std::vector<TQ3PolyhedronEdgeData> edges(m_in.u8() % 4);
            for (TQ3PolyhedronEdgeData& e : edges) {
                e.vertexIndices[0] = m_in.index(count + 1);
                e.vertexIndices[1] = m_in.index(count);
                e.triangleIndices[0] = m_in.index(triangles.size() + 1);
                e.triangleIndices[1] = m_in.u8() % 2 ? ~0UL : m_in.index(triangles.size());
                e.edgeAttributeSet = (m_in.u8() % 4 == 0) ? pick(Kind::kAttributeSet) : nullptr;
            }
            TQ3PolyhedronData data{count, vertices.data(), static_cast<unsigned long>(edges.size()),
                                   edges.empty() ? nullptr : edges.data(),
                                   static_cast<unsigned long>(triangles.size()), triangles.data(), nullptr};
            if (rawCount)
                data.numTriangles = hugeCount;
            surfaceAction<TQ3PolyhedronData>(
                action, kind, nullData ? nullptr : &data, Q3Polyhedron_New, Q3Polyhedron_SetData,
                Q3Polyhedron_GetData, Q3Polyhedron_EmptyData, Q3Polyhedron_Submit,
                [](const TQ3PolyhedronData& a, const TQ3PolyhedronData& b) {
                    return a.numVertices == b.numVertices && a.numEdges == b.numEdges &&
                           a.numTriangles == b.numTriangles && samePoints(a.vertices, b.vertices, a.numVertices);
                });
            break;
        }
        case 2: {
            const unsigned long columns = 1 + m_in.u8() % 4;
            const unsigned long rows = count / columns;
            std::vector<TQ3AttributeSet> facets(2 * count, nullptr);
            for (TQ3AttributeSet& f : facets)
                f = (m_in.u8() % 8 == 0) ? pick(Kind::kAttributeSet) : nullptr;
            TQ3TriGridData data{rows, columns, vertices.data(), (m_in.u8() & 1) ? facets.data() : nullptr, nullptr};
            if (rawCount)
                data.numRows = hugeCount;
            surfaceAction<TQ3TriGridData>(action, kind, nullData ? nullptr : &data, Q3TriGrid_New, Q3TriGrid_SetData,
                                          Q3TriGrid_GetData, Q3TriGrid_EmptyData, Q3TriGrid_Submit,
                                          [](const TQ3TriGridData& a, const TQ3TriGridData& b) {
                                              return a.numRows == b.numRows && a.numColumns == b.numColumns &&
                                                     samePoints(a.vertices, b.vertices, a.numRows * a.numColumns);
                                          });
            break;
        }
        default: {
            std::vector<unsigned char> bits(1 + m_in.u8() % 16);
            for (unsigned char& b : bits)
                b = m_in.u8();
            TQ3MarkerData data{};
            data.location = TQ3Point3D{vertices[0].point.z, 0.0f, 0.0f};
            data.xOffset = static_cast<long>(static_cast<std::int32_t>(m_in.u32()));
            data.yOffset = static_cast<long>(static_cast<std::int8_t>(m_in.u8()));
            data.bitmap.image = bits.data();
            data.bitmap.rowBytes = 1 + m_in.u8() % 2;
            data.bitmap.height = bits.size() / data.bitmap.rowBytes;
            data.bitmap.width = m_in.u8() % 20;
            setRaw(data.bitmap.bitOrder, enumValue(2));
            if (rawCount)
                data.bitmap.height = hugeCount;
            surfaceAction<TQ3MarkerData>(action, kind, nullData ? nullptr : &data, Q3Marker_New, Q3Marker_SetData,
                                         Q3Marker_GetData, Q3Marker_EmptyData, Q3Marker_Submit,
                                         [](const TQ3MarkerData& a, const TQ3MarkerData& b) {
                                             return sameBytes(a.location, b.location) && a.xOffset == b.xOffset &&
                                                    a.yOffset == b.yOffset && a.bitmap.width == b.bitmap.width &&
                                                    a.bitmap.height == b.bitmap.height &&
                                                    std::memcmp(a.bitmap.image, b.bitmap.image,
                                                                a.bitmap.rowBytes * a.bitmap.height) == 0;
                                         });
            break;
        }
        }
    }

    void polygons2Field(std::uint8_t type, Kind kind)
    {
        const TQ3Object geometry = pick(kind);
        const bool ours = holdsKind(geometry, kind) && m_initialized > 0;
        const bool nullArg = m_in.u8() == 0;
        const std::uint8_t call = m_in.u8();
        const unsigned long i = m_in.u8() % 8 == 0 ? m_in.u32() : m_in.u8() % 8;
        const unsigned long j = m_in.u8() % 8 == 0 ? m_in.u32() : m_in.u8() % 8;
        const TQ3Point3D point = point3();
        const TQ3AttributeSet attributes = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
        const unsigned long before = ours ? editIndex(geometry) : 0;
        TQ3Point3D pointOut{};
        TQ3AttributeSet got = nullptr;
        TQ3Status status = kQ3Success;
        bool edit = false;
        switch (type) {
        case 0:
            switch (call % 6) {
            case 0: STATUS(Q3GeneralPolygon_GetVertexPosition(geometry, i, j, nullArg ? nullptr : &pointOut)); break;
            case 1:
                edit = true;
                status = STATUS(Q3GeneralPolygon_SetVertexPosition(geometry, i, j, nullArg ? nullptr : &point));
                break;
            case 2: STATUS(Q3GeneralPolygon_GetVertexAttributeSet(geometry, i, j, nullArg ? nullptr : &got)); break;
            case 3:
                edit = true;
                status = STATUS(Q3GeneralPolygon_SetVertexAttributeSet(geometry, i, j, attributes));
                break;
            case 4: {
                TQ3GeneralPolygonShapeHint hint{};
                STATUS(Q3GeneralPolygon_GetShapeHint(geometry, nullArg ? nullptr : &hint));
                break;
            }
            default: {
                TQ3GeneralPolygonShapeHint hint = kQ3GeneralPolygonShapeHintComplex;
                setRaw(hint, enumValue(3));
                edit = true;
                status = STATUS(Q3GeneralPolygon_SetShapeHint(geometry, hint));
                break;
            }
            }
            break;
        case 1:
            switch (call % 8) {
            case 0: STATUS(Q3Polyhedron_GetVertexPosition(geometry, i, nullArg ? nullptr : &pointOut)); break;
            case 1:
                edit = true;
                status = STATUS(Q3Polyhedron_SetVertexPosition(geometry, i, nullArg ? nullptr : &point));
                break;
            case 2: STATUS(Q3Polyhedron_GetVertexAttributeSet(geometry, i, nullArg ? nullptr : &got)); break;
            case 3:
                edit = true;
                status = STATUS(Q3Polyhedron_SetVertexAttributeSet(geometry, i, attributes));
                break;
            case 4: {
                TQ3PolyhedronTriangleData t{};
                if (STATUS(Q3Polyhedron_GetTriangleData(geometry, i, nullArg ? nullptr : &t)) == kQ3Success)
                    got = t.triangleAttributeSet;
                break;
            }
            case 5: {
                const TQ3PolyhedronTriangleData t{{j, j % 4, i % 4}, j % 9, attributes};
                edit = true;
                status = STATUS(Q3Polyhedron_SetTriangleData(geometry, i, nullArg ? nullptr : &t));
                break;
            }
            case 6: {
                TQ3PolyhedronEdgeData e{};
                if (STATUS(Q3Polyhedron_GetEdgeData(geometry, i, nullArg ? nullptr : &e)) == kQ3Success)
                    got = e.edgeAttributeSet;
                break;
            }
            default: {
                const TQ3PolyhedronEdgeData e{{j % 4, j}, {i % 2, ~0UL}, attributes};
                edit = true;
                status = STATUS(Q3Polyhedron_SetEdgeData(geometry, i, nullArg ? nullptr : &e));
                break;
            }
            }
            break;
        case 2:
            switch (call % 6) {
            case 0: STATUS(Q3TriGrid_GetVertexPosition(geometry, i, j, nullArg ? nullptr : &pointOut)); break;
            case 1:
                edit = true;
                status = STATUS(Q3TriGrid_SetVertexPosition(geometry, i, j, nullArg ? nullptr : &point));
                break;
            case 2: STATUS(Q3TriGrid_GetVertexAttributeSet(geometry, i, j, nullArg ? nullptr : &got)); break;
            case 3:
                edit = true;
                status = STATUS(Q3TriGrid_SetVertexAttributeSet(geometry, i, j, attributes));
                break;
            case 4: STATUS(Q3TriGrid_GetFacetAttributeSet(geometry, i, nullArg ? nullptr : &got)); break;
            default:
                edit = true;
                status = STATUS(Q3TriGrid_SetFacetAttributeSet(geometry, i, attributes));
                break;
            }
            break;
        default:
            switch (call % 8) {
            case 0: STATUS(Q3Marker_GetPosition(geometry, nullArg ? nullptr : &pointOut)); break;
            case 1:
                edit = true;
                status = STATUS(Q3Marker_SetPosition(geometry, nullArg ? nullptr : &point));
                break;
            case 2: {
                long offset = 0;
                STATUS(Q3Marker_GetXOffset(geometry, nullArg ? nullptr : &offset));
                STATUS(Q3Marker_GetYOffset(geometry, nullArg ? nullptr : &offset));
                break;
            }
            case 3:
                edit = true;
                status = STATUS(Q3Marker_SetXOffset(geometry, static_cast<long>(j)));
                break;
            case 4:
                edit = true;
                status = STATUS(Q3Marker_SetYOffset(geometry, -static_cast<long>(i)));
                break;
            case 5: {
                TQ3Bitmap bitmap{};
                if (STATUS(Q3Marker_GetBitmap(geometry, nullArg ? nullptr : &bitmap)) == kQ3Success)
                    STATUS(Q3Bitmap_Empty(&bitmap));
                break;
            }
            case 6: {
                unsigned char bits[8] = {static_cast<unsigned char>(i), static_cast<unsigned char>(j), 0xFF, 0x81, 0x18};
                TQ3Bitmap bitmap{bits, j % 20, 1 + i % 4, 1 + i % 2, kQ3EndianBig};
                setRaw(bitmap.bitOrder, std::int32_t(j % 3));
                edit = true;
                status = STATUS(Q3Marker_SetBitmap(geometry, nullArg ? nullptr : &bitmap));
                break;
            }
            default:
                QUERY(Q3Bitmap_GetImageSize(i, j), 0UL);
                break;
            }
            break;
        }
        if (edit && ours && status != kQ3Success)
            require(editIndex(geometry) == before, "polygons2", "a failed edit changed the edit index");
        if (edit)
            require(status == kQ3Failure || ours, "polygons2", "an edit succeeded on something not held");
        if (got != nullptr)
            hold(got, Kind::kAttributeSet);
    }

    // Pixmap markers: a TQ3StoragePixmap of any pixel type (or a raw one),
    // sizes small or raw, enumerations raw now and then, and an image that
    // is a fresh memory storage (sometimes a byte short), NULL, or another
    // kind of object. The storage made here is given back once the call is
    // done (a marker keeps its own reference).
    struct StoragePixmapArgs {
        TQ3StoragePixmap pixmap{};
        TQ3Object made = nullptr;
    };

    StoragePixmapArgs storagePixmap()
    {
        StoragePixmapArgs a;
        const std::uint8_t flags = m_in.u8();
        const std::int32_t type = enumValue(6);
        const unsigned long bits = type == 5 ? 24 : (type >= 2 && type <= 4) ? 16 : 32;
        const unsigned long width = (flags & 1) ? m_in.u32() : m_in.u8() % 9;
        const unsigned long height = (flags & 2) ? m_in.u32() : m_in.u8() % 9;
        a.pixmap.width = width;
        a.pixmap.height = height;
        a.pixmap.rowBytes = (flags & 4) ? m_in.u32() : width * (bits / 8) + m_in.u8() % 4;
        a.pixmap.pixelSize = (flags & 8) ? m_in.u8() : bits;
        setRaw(a.pixmap.pixelType, type);
        setRaw(a.pixmap.byteOrder, enumValue(2));
        setRaw(a.pixmap.bitOrder, enumValue(2));
        switch ((flags >> 4) & 3) {
        case 0: {
            // As many bytes as the pixmap needs (at most 4096), one fewer
            // when flag 0x40 says so; the first 16 from the input.
            const unsigned long long need =
                std::min<unsigned long long>((unsigned long long)a.pixmap.rowBytes * height, 4096ULL);
            std::vector<unsigned char> bytes(need);
            for (std::size_t i = 0; i < bytes.size(); ++i)
                bytes[i] = i < 16 ? m_in.u8() : static_cast<unsigned char>(i * 37);
            const unsigned long size = static_cast<unsigned long>(bytes.size()) - ((flags & 0x40) && need > 0 ? 1 : 0);
            a.made = OBJECT(Q3MemoryStorage_New(bytes.empty() ? nullptr : bytes.data(), size));
            a.pixmap.image = a.made;
            break;
        }
        case 1: a.pixmap.image = pick(Kind::kAttributeSet); break;
        case 2: a.pixmap.image = nullptr; break;
        default: a.pixmap.image = pick(Kind::kPixmapMarker); break;
        }
        return a;
    }

    void releaseStorage(StoragePixmapArgs& a)
    {
        if (a.made != nullptr)
            STATUS(Q3Object_Dispose(a.made));
        a.made = nullptr;
    }

    static bool samePixmap(const TQ3StoragePixmap& a, const TQ3StoragePixmap& b)
    {
        return a.image == b.image && a.width == b.width && a.height == b.height && a.rowBytes == b.rowBytes &&
               a.pixelSize == b.pixelSize && sameBytes(a.pixelType, b.pixelType) &&
               sameBytes(a.bitOrder, b.bitOrder) && sameBytes(a.byteOrder, b.byteOrder);
    }

    void pixmapMarkers()
    {
        const std::uint8_t action = m_in.u8() % 5;
        const bool nullData = m_in.u8() == 0;
        if (action == 4)
            return pixmapMarkerField();
        if (action == 3 && !drawAllowed())
            return;
        StoragePixmapArgs args = storagePixmap();
        TQ3PixmapMarkerData data{};
        data.position = point3();
        data.xOffset = static_cast<long>(static_cast<std::int32_t>(m_in.u32()));
        data.yOffset = static_cast<long>(static_cast<std::int8_t>(m_in.u8()));
        data.pixmap = args.pixmap;
        data.pixmapMarkerAttributeSet = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
        surfaceAction<TQ3PixmapMarkerData>(action, Kind::kPixmapMarker, nullData ? nullptr : &data,
                                           Q3PixmapMarker_New, Q3PixmapMarker_SetData, Q3PixmapMarker_GetData,
                                           Q3PixmapMarker_EmptyData, Q3PixmapMarker_Submit,
                                           [](const TQ3PixmapMarkerData& a, const TQ3PixmapMarkerData& b) {
                                               return sameBytes(a.position, b.position) && a.xOffset == b.xOffset &&
                                                      a.yOffset == b.yOffset && samePixmap(a.pixmap, b.pixmap) &&
                                                      a.pixmapMarkerAttributeSet == b.pixmapMarkerAttributeSet;
                                           });
        texturesFrom(args);
        releaseStorage(args);
    }

    // QD3DShader.h's textures made from the same storage pixmap, reading no
    // input of their own (so the seeds keep their meaning): a pixmap texture
    // and a two-image mipmap texture go through the data rules; what is made
    // is read back, set again (which must succeed), wrapped in a texture
    // shader and disposed of; a colour routine runs on the pixmap's sizes.
    void texturesFrom(const StoragePixmapArgs& args)
    {
        const TQ3StoragePixmap& p = args.pixmap;
        TQ3Mipmap mipmap{};
        mipmap.image = p.image;
        setRaw(mipmap.useMipmapping, static_cast<std::int32_t>(p.width & 1) == 0 ? 1 : 0);
        std::memcpy(&mipmap.pixelType, &p.pixelType, sizeof mipmap.pixelType);
        std::memcpy(&mipmap.bitOrder, &p.bitOrder, sizeof mipmap.bitOrder);
        std::memcpy(&mipmap.byteOrder, &p.byteOrder, sizeof mipmap.byteOrder);
        mipmap.mipmaps[0] = TQ3MipmapImage{p.width, p.height, p.rowBytes, 0};
        mipmap.mipmaps[1] = TQ3MipmapImage{p.width / 2, p.height / 2, p.rowBytes / 2, p.rowBytes * p.height};
        const TQ3Object textures[2] = {OBJECT(Q3PixmapTexture_New(&p)), OBJECT(Q3MipmapTexture_New(&mipmap))};
        for (TQ3Object texture : textures) {
            if (texture == nullptr)
                continue;
            unsigned long size = 0;
            STATUS(Q3Texture_GetWidth(texture, &size));
            STATUS(Q3Texture_GetHeight(texture, &size));
            if (Q3Texture_GetType(texture) == kQ3TextureTypePixmap) {
                TQ3StoragePixmap got{};
                if (STATUS(Q3PixmapTexture_GetPixmap(texture, &got)) == kQ3Success) {
                    require(STATUS(Q3PixmapTexture_SetPixmap(texture, &got)) == kQ3Success,
                            "Q3PixmapTexture_SetPixmap", "refused what Q3PixmapTexture_GetPixmap gave");
                    STATUS(Q3Object_Dispose(got.image));
                }
            } else {
                TQ3Mipmap got{};
                if (STATUS(Q3MipmapTexture_GetMipmap(texture, &got)) == kQ3Success) {
                    require(STATUS(Q3MipmapTexture_SetMipmap(texture, &got)) == kQ3Success,
                            "Q3MipmapTexture_SetMipmap", "refused what Q3MipmapTexture_GetMipmap gave");
                    STATUS(Q3Object_Dispose(got.image));
                }
            }
        }
        const TQ3Object shader = OBJECT(Q3TextureShader_New(textures[0] != nullptr ? textures[0] : textures[1]));
        if (shader != nullptr) {
            STATUS(Q3TextureShader_SetTexture(shader, textures[1] != nullptr ? textures[1] : textures[0]));
            TQ3TextureObject got = nullptr;
            if (STATUS(Q3TextureShader_GetTexture(shader, &got)) == kQ3Success)
                STATUS(Q3Object_Dispose(got));
            QUERY(Q3SurfaceShader_GetType(shader), kQ3ObjectTypeInvalid);
            STATUS(Q3Object_Dispose(shader));
        }
        for (TQ3Object texture : textures)
            if (texture != nullptr)
                STATUS(Q3Object_Dispose(texture));
        TQ3ColorRGB color{float(p.width), float(p.height), float(p.rowBytes)};
        float luminance = 0.0f;
        POINTER(Q3ColorRGB_Clamp(&color, &color));
        POINTER(Q3ColorRGB_Luminance(&color, &luminance));
    }

    // QD3DIO.h's view hints: New from a view, then one Set or Get call with
    // picked objects and input values; a Set that fails must leave the edit
    // index as it was, and every Get's objects are released.
    // QD3DPick.h: picks made from raw data, every setter and getter (a
    // failed Set leaves the data as it was), picking loops around the other
    // ops' submits, and every hit's details read back (the valid mask never
    // exceeds the pick's mask; references returned are given back).
    // The element calls on any held object (QD3D.h's Q3Shape_ family,
    // Quesa's Q3Object_ family) and Apple's name element: random element
    // types (attribute types, the unknown and set elements, any long) and
    // data, each call checked against the error contract; a handle a Get
    // returns is disposed.
    void elements()
    {
        const TQ3Object target = pick(static_cast<Kind>(m_in.u8() % kKindCount));
        const std::uint8_t which = m_in.u8();
        const TQ3ElementType type = which < 200 ? TQ3ElementType(which % 40) : TQ3ElementType(std::int32_t(m_in.u32()));
        // Large enough for any element's C type; a handle read from it is
        // checked by Q3 before use.
        float data[8];
        for (float& f : data)
            f = m_in.value();
        const bool handleType = type == kQ3AttributeTypeSurfaceShader || type == kQ3ElementTypeSet;
        switch (m_in.u8() % 9) {
        case 0:
            STATUS(Q3Object_AddElement(target, type, m_in.u8() == 0 ? nullptr : data));
            break;
        case 1:
            STATUS(Q3Shape_AddElement(target, type, data));
            break;
        case 2: {
            float out[8] = {};
            if (STATUS(Q3Object_GetElement(target, type, out)) == kQ3Success && handleType) {
                TQ3Object got;
                std::memcpy(&got, out, sizeof got);
                Q3Object_Dispose(got);
            }
            break;
        }
        case 3:
            QUERY(Q3Shape_ContainsElement(target, type), kQ3False);
            break;
        case 4: {
            TQ3ElementType next = m_in.u8() < 200 ? TQ3ElementType(kQ3ElementTypeNone) : type;
            for (int i = 0; i < 40; ++i)
                if (STATUS(Q3Object_GetNextElementType(target, &next)) != kQ3Success || next == kQ3ElementTypeNone)
                    break;
            break;
        }
        case 5:
            STATUS(Q3Shape_ClearElement(target, type));
            break;
        case 6:
            STATUS(m_in.u8() < 128 ? Q3Object_EmptyElements(target) : Q3Shape_EmptyElements(target));
            break;
        case 7: {
            char name[12];
            for (char& c : name)
                c = static_cast<char>(1 + m_in.u8() % 255);
            name[sizeof name - 1] = '\0';
            STATUS(CENameElement_SetData(target, m_in.u8() < 32 ? nullptr : name));
            break;
        }
        case 8: {
            char* got = nullptr;
            if (STATUS(CENameElement_GetData(target, &got)) == kQ3Success)
                STATUS(CENameElement_EmptyData(&got));
            break;
        }
        }
    }

    void picking()
    {
        const std::uint8_t call = m_in.u8() % 8;
        const bool nullArg = m_in.u8() == 0;
        if (call == 0) {
            TQ3PickData common{};
            setRaw(common.sort, enumValue(3));
            common.mask = m_in.u8() < 200 ? (m_in.u32() & 0x3FF) : m_in.u32();
            common.numHitsToReturn = m_in.u8() % 4;
            TQ3Object made = nullptr;
            switch (m_in.u8() % 3) {
            case 0: {
                TQ3WindowPointPickData d{common, {m_in.value(), m_in.value()}, m_in.value(), m_in.value()};
                made = OBJECT(Q3WindowPointPick_New(nullArg ? nullptr : &d));
                break;
            }
            case 1: {
                TQ3WindowRectPickData d{common, {{m_in.value(), m_in.value()}, {m_in.value(), m_in.value()}}};
                made = OBJECT(Q3WindowRectPick_New(nullArg ? nullptr : &d));
                break;
            }
            default: {
                TQ3WorldRayPickData d{common,
                                      {{m_in.value(), m_in.value(), m_in.value()},
                                       {m_in.value(), m_in.value(), m_in.value()}},
                                      m_in.value(),
                                      m_in.value()};
                made = OBJECT(Q3WorldRayPick_New(nullArg ? nullptr : &d));
                break;
            }
            }
            if (made != nullptr) {
                hold(made, Kind::kPick);
                TQ3PickData got{};
                STATUS(Q3Pick_GetData(made, &got));
                require(got.mask == common.mask && got.numHitsToReturn == common.numHitsToReturn, "Q3Pick_GetData",
                        "differs from what the pick was made with");
            }
            return;
        }
        const TQ3Object pick = this->pick(Kind::kPick);
        switch (call) {
        case 1: {
            TQ3WindowPointPickData point;
            TQ3WindowRectPickData rect;
            TQ3WorldRayPickData ray;
            std::memset(&point, 0xA5, sizeof point);
            std::memset(&rect, 0xA5, sizeof rect);
            std::memset(&ray, 0xA5, sizeof ray);
            const bool gotPoint = STATUS(Q3WindowPointPick_GetData(pick, &point)) == kQ3Success;
            const bool gotRect = STATUS(Q3WindowRectPick_GetData(pick, &rect)) == kQ3Success;
            const bool gotRay = STATUS(Q3WorldRayPick_GetData(pick, &ray)) == kQ3Success;
            const float value = m_in.value();
            TQ3Status status = kQ3Success;
            switch (m_in.u8() % 6) {
            case 0: status = STATUS(Q3Pick_SetVertexTolerance(pick, value)); break;
            case 1: status = STATUS(Q3Pick_SetEdgeTolerance(pick, value)); break;
            case 2: {
                const TQ3Point2D p{value, m_in.value()};
                status = STATUS(Q3WindowPointPick_SetPoint(pick, nullArg ? nullptr : &p));
                break;
            }
            case 3: {
                const TQ3Area a{{value, m_in.value()}, {m_in.value(), m_in.value()}};
                status = STATUS(Q3WindowRectPick_SetRect(pick, nullArg ? nullptr : &a));
                break;
            }
            case 4: {
                const TQ3Ray3D r{{value, m_in.value(), m_in.value()}, {m_in.value(), m_in.value(), m_in.value()}};
                status = STATUS(Q3WorldRayPick_SetRay(pick, nullArg ? nullptr : &r));
                break;
            }
            default: {
                TQ3PickData d{};
                setRaw(d.sort, enumValue(3));
                d.mask = m_in.u8() < 200 ? (m_in.u32() & 0x3FF) : m_in.u32();
                d.numHitsToReturn = m_in.u8() % 4;
                status = STATUS(Q3Pick_SetData(pick, nullArg ? nullptr : &d));
                break;
            }
            }
            if (status != kQ3Success) {
                TQ3WindowPointPickData point2;
                TQ3WindowRectPickData rect2;
                TQ3WorldRayPickData ray2;
                std::memset(&point2, 0xA5, sizeof point2);
                std::memset(&rect2, 0xA5, sizeof rect2);
                std::memset(&ray2, 0xA5, sizeof ray2);
                if (gotPoint && STATUS(Q3WindowPointPick_GetData(pick, &point2)) == kQ3Success)
                    require(sameBytes(point, point2), "Q3WindowPointPick_Set*", "failed but changed the pick");
                if (gotRect && STATUS(Q3WindowRectPick_GetData(pick, &rect2)) == kQ3Success)
                    require(sameBytes(rect, rect2), "Q3WindowRectPick_Set*", "failed but changed the pick");
                if (gotRay && STATUS(Q3WorldRayPick_GetData(pick, &ray2)) == kQ3Success)
                    require(sameBytes(ray, ray2), "Q3WorldRayPick_Set*", "failed but changed the pick");
            }
            return;
        }
        case 2: {
            float tolerance = 0.0f;
            TQ3Point2D point{};
            TQ3Area area{};
            TQ3Ray3D ray{};
            TQ3PickData data{};
            QUERY(Q3Pick_GetType(pick), TQ3ObjectType{kQ3ObjectTypeInvalid});
            STATUS(Q3Pick_GetVertexTolerance(pick, nullArg ? nullptr : &tolerance));
            STATUS(Q3Pick_GetEdgeTolerance(pick, nullArg ? nullptr : &tolerance));
            STATUS(Q3WindowPointPick_GetPoint(pick, nullArg ? nullptr : &point));
            STATUS(Q3WindowRectPick_GetRect(pick, nullArg ? nullptr : &area));
            STATUS(Q3WorldRayPick_GetRay(pick, nullArg ? nullptr : &ray));
            STATUS(Q3Pick_GetData(pick, nullArg ? nullptr : &data));
            return;
        }
        case 3: {
            const TQ3Object view = this->pick(Kind::kView);
            if (m_loops >= kMaxLoops)
                return;
            ++m_loops;
            STATUS(Q3View_StartPicking(view, pick));
            return;
        }
        case 4:
            VIEWSTATUS(Q3View_EndPicking(this->pick(Kind::kView)));
            return;
        case 5: {
            // Every byte is read before the calls, so a failing one leaves
            // the rest of the input decoding as written.
            const std::uint32_t raw = m_in.u32();
            const bool inRange = m_in.u8() < 200;
            const TQ3PickDetail asked = m_in.u8() < 200 ? (1ul << (m_in.u8() % 10)) : m_in.u32();
            unsigned long count = 0;
            TQ3PickData data{};
            if (STATUS(Q3Pick_GetNumHits(pick, &count)) != kQ3Success ||
                STATUS(Q3Pick_GetData(pick, &data)) != kQ3Success)
                return;
            require(data.numHitsToReturn == 0 || count <= data.numHitsToReturn, "Q3Pick_GetNumHits",
                    "more hits than numHitsToReturn");
            const unsigned long index = inRange && count != 0 ? raw % count : raw;
            TQ3PickDetail valid = 0;
            if (STATUS(Q3Pick_GetPickDetailValidMask(pick, index, nullArg ? nullptr : &valid)) != kQ3Success)
                return;
            require((valid & ~data.mask) == 0, "Q3Pick_GetPickDetailValidMask",
                    "reports a detail the pick did not ask for");
            union {
                unsigned long id;
                TQ3HitPath path;
                TQ3Object object;
                TQ3Matrix4x4 matrix;
                TQ3Point3D xyz;
                float distance;
                TQ3Vector3D normal;
                TQ3PickParts part;
                TQ3Param2D uv;
            } out;
            std::memset(&out, 0, sizeof out);
            if (STATUS(Q3Pick_GetPickDetailData(pick, index, asked, &out)) != kQ3Success)
                return;
            require((valid & asked) == asked, "Q3Pick_GetPickDetailData", "gave a detail that is not valid");
            if (asked == kQ3PickDetailMaskObject)
                STATUS(Q3Object_Dispose(out.object));
            if (asked == kQ3PickDetailMaskShapePart) {
                // A mesh part: every shape part call, the right one succeeding.
                TQ3ShapeObject shape = nullptr;
                if (STATUS(Q3ShapePart_GetShape(out.object, &shape)) == kQ3Success)
                    STATUS(Q3Object_Dispose(shape));
                require(QUERY(Q3ShapePart_GetType(out.object), TQ3ObjectType{kQ3ObjectTypeInvalid}) ==
                            kQ3ShapePartTypeMeshPart,
                        "Q3ShapePart_GetType", "a part that is not a mesh part");
                TQ3MeshComponent component = nullptr;
                TQ3MeshFace face = nullptr;
                TQ3MeshEdge edge = nullptr;
                TQ3MeshVertex vertex = nullptr;
                STATUS(Q3MeshPart_GetComponent(out.object, &component));
                STATUS(Q3MeshFacePart_GetFace(out.object, &face));
                STATUS(Q3MeshEdgePart_GetEdge(out.object, &edge));
                STATUS(Q3MeshVertexPart_GetVertex(out.object, &vertex));
                STATUS(Q3Object_Dispose(out.object));
            }
            if (asked == kQ3PickDetailMaskPath) {
                require(out.path.rootGroup != nullptr && out.path.depth != 0, "Q3Pick_GetPickDetailData",
                        "gave an empty path");
                STATUS(Q3HitPath_EmptyData(&out.path));
            }
            return;
        }
        case 6: {
            STATUS(Q3Pick_EmptyHitList(pick));
            TQ3HitPath empty{nullptr, 0, nullptr};
            STATUS(Q3HitPath_EmptyData(nullArg ? nullptr : &empty));
            return;
        }
        default:
            QUERY(Q3Pick_GetType(pick), TQ3ObjectType{kQ3ObjectTypeInvalid});
            return;
        }
    }

    // QD3DController.h: every call on a controller this input made (or an
    // unknown pointer), a tracker made for the step and disposed at its end
    // (which detaches the controllers attached to it), the cursor tracker.
    // Notify functions only count: they must not post errors of their own.
    static TQ3Status fuzzGetChannel(TQ3ControllerRef, unsigned long channel, void* data, unsigned long* size)
    {
        if (channel % 3 == 2)
            return kQ3Failure;
        const unsigned long n = std::min<unsigned long>(*size, channel % 5);
        std::memset(data, 0x5A, n);
        *size = n;
        return kQ3Success;
    }
    static TQ3Status fuzzSetChannel(TQ3ControllerRef, unsigned long channel, const void*, unsigned long)
    {
        return channel % 4 == 3 ? kQ3Failure : kQ3Success;
    }
    static TQ3Status fuzzTrackerNotify(TQ3TrackerObject, TQ3ControllerRef)
    {
        ++g_controllerNotifications;
        return kQ3Success;
    }
    static void fuzzCursorNotify() { ++g_controllerNotifications; }

    void controllers()
    {
        const std::uint8_t call = m_in.u8() % 14;
        const bool nullArg = m_in.u8() == 0;
        TQ3ControllerRef ref = &m_notAController;
        if (!m_controllers.empty() && m_in.u8() != 0)
            ref = m_controllers[m_in.u8() % m_controllers.size()];
        TQ3TrackerObject tracker = OBJECT(Q3Tracker_New((m_in.u8() & 1) ? fuzzTrackerNotify : nullptr));
        const TQ3Point3D point{m_in.value(), m_in.value(), m_in.value()};
        const TQ3Vector3D vector{m_in.value(), m_in.value(), m_in.value()};
        const TQ3Quaternion turn{m_in.value(), m_in.value(), m_in.value(), m_in.value()};
        TQ3Boolean b = kQ3False;
        unsigned long n = m_in.u32();
        switch (call) {
        case 0: {
            char signature[] = "dev?";
            signature[3] = char('a' + m_in.u8() % 4);
            const unsigned long counts[] = {0, 3, 1024, 1025, 0xFFFFFFFFul};
            TQ3ControllerData data{signature, counts[m_in.u8() % 5], counts[m_in.u8() % 5] % 1100, fuzzGetChannel,
                                   fuzzSetChannel};
            if (m_in.u8() == 0)
                data.signature = nullptr;
            if (TQ3ControllerRef made = POINTER(Q3Controller_New(nullArg ? nullptr : &data)))
                if (std::find(m_controllers.begin(), m_controllers.end(), made) == m_controllers.end())
                    m_controllers.push_back(made);
            break;
        }
        case 1: {
            TQ3ControllerRef next = nullptr;
            STATUS(Q3Controller_GetListChanged(nullArg ? nullptr : &b, &n));
            const bool fromStart = m_in.u8() & 1;
            STATUS(Q3Controller_Next(fromStart ? nullptr : ref, nullArg ? nullptr : &next));
            STATUS(Q3Controller_GetActivation(ref, nullArg ? nullptr : &b));
            STATUS(Q3Controller_GetValueCount(ref, nullArg ? nullptr : &n));
            STATUS(Q3Controller_HasTracker(ref, nullArg ? nullptr : &b));
            STATUS(Q3Controller_Track2DCursor(ref, nullArg ? nullptr : &b));
            STATUS(Q3Controller_Track3DCursor(ref, nullArg ? nullptr : &b));
            STATUS(Q3Controller_GetButtons(ref, nullArg ? nullptr : &n));
            break;
        }
        case 2:
            STATUS(Q3Controller_SetActivation(ref, static_cast<TQ3Boolean>(m_in.u8() % 3)));
            if (m_in.u8() % 8 == 0)
                STATUS(Q3Controller_Decommission(ref));
            break;
        case 3: {
            char text[16];
            const unsigned long numChars = m_in.u8() % 17;
            STATUS(Q3Controller_GetSignature(ref, nullArg ? nullptr : text, numChars));
            unsigned char bytes[300] = {};
            unsigned long size = m_in.u32() % 300;
            const unsigned long setChannel = m_in.u8() % 6;
            const unsigned long getChannel = m_in.u8() % 6;
            STATUS(Q3Controller_SetChannel(ref, setChannel, nullArg ? nullptr : bytes, size));
            STATUS(Q3Controller_GetChannel(ref, getChannel, nullArg ? nullptr : bytes, &size));
            break;
        }
        case 4: {
            const bool toCursor = m_in.u8() & 1;
            STATUS(Q3Controller_SetTracker(ref, toCursor ? nullptr : tracker));
            const unsigned long buttons = m_in.u32();
            STATUS(Q3Controller_SetButtons(ref, buttons));
            break;
        }
        case 5: {
            TQ3Point3D p{};
            TQ3Quaternion q{};
            STATUS(Q3Controller_SetTrackerPosition(ref, nullArg ? nullptr : &point));
            STATUS(Q3Controller_MoveTrackerPosition(ref, &vector));
            STATUS(Q3Controller_SetTrackerOrientation(ref, &turn));
            STATUS(Q3Controller_MoveTrackerOrientation(ref, &turn));
            STATUS(Q3Controller_GetTrackerPosition(ref, nullArg ? nullptr : &p));
            STATUS(Q3Controller_GetTrackerOrientation(ref, nullArg ? nullptr : &q));
            break;
        }
        case 6: {
            float values[8] = {m_in.value(), m_in.value(), m_in.value()};
            const unsigned long setCount = m_in.u8() % 9;
            STATUS(Q3Controller_SetValues(ref, nullArg ? nullptr : values, setCount));
            unsigned long serial = m_in.u8();
            const unsigned long getCount = m_in.u8() % 9;
            const bool noSerial = m_in.u8() & 1;
            STATUS(Q3Controller_GetValues(ref, getCount, values, nullArg ? nullptr : &b, noSerial ? nullptr : &serial));
            break;
        }
        case 7: {
            const TQ3Object state = OBJECT(Q3ControllerState_New(ref));
            STATUS(Q3ControllerState_Restore(state));
            STATUS(Q3ControllerState_SaveAndReset(nullArg ? tracker : state));
            STATUS(Q3ControllerState_Restore(state));
            if (state != nullptr)
                STATUS(Q3Object_Dispose(state));
            break;
        }
        case 8: {
            float p = 0, o = 0;
            const float positionThresh = m_in.value();
            const float orientationThresh = m_in.value();
            STATUS(Q3Tracker_SetNotifyThresholds(tracker, positionThresh, orientationThresh));
            STATUS(Q3Tracker_GetNotifyThresholds(tracker, nullArg ? nullptr : &p, &o));
            STATUS(Q3Tracker_SetActivation(tracker, static_cast<TQ3Boolean>(m_in.u8() % 3)));
            STATUS(Q3Tracker_GetActivation(tracker, nullArg ? nullptr : &b));
            const bool byApplication = m_in.u8() & 1;
            const unsigned long buttons = m_in.u32();
            const unsigned long mask = m_in.u32();
            STATUS(Q3Tracker_ChangeButtons(tracker, byApplication ? nullptr : ref, buttons, mask));
            STATUS(Q3Tracker_GetButtons(tracker, nullArg ? nullptr : &n));
            break;
        }
        case 9: {
            const TQ3ControllerRef by = m_in.u8() & 1 ? nullptr : ref;
            TQ3Point3D p{};
            TQ3Vector3D d{};
            TQ3Quaternion q{}, dq{};
            unsigned long serial = m_in.u8();
            STATUS(Q3Tracker_SetPosition(tracker, by, nullArg ? nullptr : &point));
            STATUS(Q3Tracker_MovePosition(tracker, by, &vector));
            STATUS(Q3Tracker_SetOrientation(tracker, by, &turn));
            STATUS(Q3Tracker_MoveOrientation(tracker, by, &turn));
            const std::uint8_t outs = m_in.u8();
            STATUS(Q3Tracker_GetPosition(tracker, nullArg ? nullptr : &p, outs & 1 ? nullptr : &d, &b,
                                         outs & 2 ? nullptr : &serial));
            STATUS(Q3Tracker_GetOrientation(tracker, &q, outs & 4 ? nullptr : &dq, nullArg ? nullptr : &b,
                                            outs & 8 ? nullptr : &serial));
            break;
        }
        case 10: {
            const std::uint8_t events = m_in.u8() % 20;
            for (std::uint8_t i = 0; i < events; ++i) {
                const unsigned long time = m_in.u32();
                const unsigned long buttons = m_in.u32();
                const std::uint8_t given = m_in.u8();
                STATUS(Q3Tracker_SetEventCoordinates(tracker, time, buttons, given & 1 ? nullptr : &point,
                                                     given & 2 ? nullptr : &turn));
            }
            TQ3Point3D p{};
            TQ3Quaternion q{};
            const unsigned long time = m_in.u32();
            STATUS(Q3Tracker_GetEventCoordinates(tracker, time, nullArg ? nullptr : &n, &p, &q));
            break;
        }
        case 11: {
            float depth = 0;
            TQ3Quaternion q{};
            TQ3Boolean has = kQ3False;
            unsigned long serial = m_in.u8();
            STATUS(Q3CursorTracker_PrepareTracking());
            STATUS(Q3CursorTracker_SetTrackDeltas(static_cast<TQ3Boolean>(m_in.u8() % 3)));
            const bool noSerial = m_in.u8() & 1;
            STATUS(Q3CursorTracker_GetAndClearDeltas(nullArg ? nullptr : &depth, &q, &has, &b,
                                                     noSerial ? nullptr : &serial));
            break;
        }
        case 12: {
            TQ3CursorTrackerNotifyFunc f = nullptr;
            STATUS(Q3CursorTracker_SetNotifyFunc(m_in.u8() & 1 ? fuzzCursorNotify : nullptr));
            STATUS(Q3CursorTracker_GetNotifyFunc(nullArg ? nullptr : &f));
            break;
        }
        default:
            // The same calls on a tracker handle that is something else.
            STATUS(Q3Tracker_GetButtons(pick(Kind::kView), &n));
            STATUS(Q3Controller_SetTracker(ref, pick(Kind::kAttributeSet)));
            break;
        }
        if (tracker != nullptr)
            STATUS(Q3Object_Dispose(tracker));
    }

    void viewHints()
    {
        const std::uint8_t call = m_in.u8() % 12;
        if (call == 0) {
            const TQ3Object hints = OBJECT(Q3ViewHints_New(pick(Kind::kView)));
            if (hints != nullptr)
                hold(hints, Kind::kViewHints);
            return;
        }
        const TQ3Object hints = pick(Kind::kViewHints);
        const bool ours = holdsKind(hints, Kind::kViewHints) && m_initialized > 0;
        const bool nullArg = m_in.u8() == 0;
        const unsigned long before = ours ? editIndex(hints) : 0;
        TQ3Status status = kQ3Success;
        bool edit = true;
        switch (call) {
        case 1: status = STATUS(Q3ViewHints_SetCamera(hints, pick(Kind::kCamera))); break;
        case 2: status = STATUS(Q3ViewHints_SetRenderer(hints, pick(Kind::kRenderer))); break;
        case 3: status = STATUS(Q3ViewHints_SetLightGroup(hints, pick(Kind::kGroup))); break;
        case 4: status = STATUS(Q3ViewHints_SetAttributeSet(hints, pick(Kind::kAttributeSet))); break;
        case 5: {
            edit = false;
            TQ3Object got[4] = {};
            STATUS(Q3ViewHints_GetCamera(hints, nullArg ? nullptr : &got[0]));
            STATUS(Q3ViewHints_GetRenderer(hints, nullArg ? nullptr : &got[1]));
            STATUS(Q3ViewHints_GetLightGroup(hints, nullArg ? nullptr : &got[2]));
            STATUS(Q3ViewHints_GetAttributeSet(hints, nullArg ? nullptr : &got[3]));
            for (TQ3Object object : got)
                if (object != nullptr)
                    STATUS(Q3Object_Dispose(object));
            break;
        }
        case 6: {
            // Widths past 32 bits where unsigned long has them.
            const std::uint8_t shift = m_in.u8() % 40;
            const unsigned long width = static_cast<unsigned long>(std::uint64_t{m_in.u32()} << (shift % 33));
            status = STATUS(Q3ViewHints_SetDimensions(hints, width, m_in.u32()));
            break;
        }
        case 7:
            status = STATUS(Q3ViewHints_SetDimensionsState(hints, (m_in.u8() & 1) ? kQ3True : kQ3False));
            if (status == kQ3Success)
                status = STATUS(Q3ViewHints_SetMaskState(hints, (m_in.u8() & 1) ? kQ3True : kQ3False));
            break;
        case 8: {
            edit = false;
            TQ3Boolean state = kQ3False;
            unsigned long width = 0, height = 0;
            STATUS(Q3ViewHints_GetDimensionsState(hints, nullArg ? nullptr : &state));
            STATUS(Q3ViewHints_GetMaskState(hints, nullArg ? nullptr : &state));
            STATUS(Q3ViewHints_GetDimensions(hints, nullArg ? nullptr : &width, &height));
            TQ3Bitmap mask;
            std::memset(&mask, 0xA5, sizeof mask);
            const TQ3Bitmap untouched = mask;
            if (STATUS(Q3ViewHints_GetMask(hints, nullArg ? nullptr : &mask)) == kQ3Success)
                STATUS(Q3Bitmap_Empty(&mask));
            else
                require(sameBytes(mask, untouched), "Q3ViewHints_GetMask", "failed but wrote its output");
            break;
        }
        case 9: {
            // A bitmap whose image holds every byte it claims (or NULL):
            // 0..63 x 0..63 pixels, rows of the bytes the width needs plus
            // 0..2, a bit order from the input.
            const unsigned long width = m_in.u8() % 64, height = m_in.u8() % 64;
            const unsigned long rowBytes = (width + 7) / 8 + m_in.u8() % 3;
            std::vector<unsigned char> image(rowBytes * height + 1, 0x3C);
            TQ3Bitmap mask{nullArg ? nullptr : image.data(), width, height, rowBytes, kQ3EndianBig};
            setRaw(mask.bitOrder, enumValue(1));
            status = STATUS(Q3ViewHints_SetMask(hints, &mask));
            break;
        }
        case 10: {
            status = STATUS(q3fuzz_ViewHints_SetClearImageMethod(hints, enumValue(1)));
            TQ3DrawContextClearImageMethod method;
            STATUS(Q3ViewHints_GetClearImageMethod(hints, nullArg ? nullptr : &method));
            break;
        }
        default: {
            const TQ3ColorARGB color{m_in.value(), m_in.value(), m_in.value(), m_in.value()};
            status = STATUS(Q3ViewHints_SetClearImageColor(hints, nullArg ? nullptr : &color));
            TQ3ColorARGB got;
            STATUS(Q3ViewHints_GetClearImageColor(hints, &got));
            break;
        }
        }
        if (ours && edit && status == kQ3Failure)
            require(editIndex(hints) == before, "Q3ViewHints_Set...", "failed but changed the hints");
    }

    void pixmapMarkerField()
    {
        const TQ3Object geometry = pick(Kind::kPixmapMarker);
        const bool ours = holdsKind(geometry, Kind::kPixmapMarker) && m_initialized > 0;
        const bool nullArg = m_in.u8() == 0;
        const std::uint8_t call = m_in.u8() % 8;
        const unsigned long before = ours ? editIndex(geometry) : 0;
        TQ3Status status = kQ3Success;
        bool edit = false;
        switch (call) {
        case 0: {
            TQ3Point3D p{};
            STATUS(Q3PixmapMarker_GetPosition(geometry, nullArg ? nullptr : &p));
            break;
        }
        case 1: {
            const TQ3Point3D p = point3();
            edit = true;
            status = STATUS(Q3PixmapMarker_SetPosition(geometry, nullArg ? nullptr : &p));
            break;
        }
        case 2: {
            long offset = 0;
            STATUS(Q3PixmapMarker_GetXOffset(geometry, nullArg ? nullptr : &offset));
            STATUS(Q3PixmapMarker_GetYOffset(geometry, nullArg ? nullptr : &offset));
            break;
        }
        case 3:
            edit = true;
            status = STATUS(Q3PixmapMarker_SetXOffset(geometry, static_cast<long>(static_cast<std::int32_t>(m_in.u32()))));
            break;
        case 4:
            edit = true;
            status = STATUS(Q3PixmapMarker_SetYOffset(geometry, (m_in.u8() & 1) ? LONG_MIN : LONG_MAX));
            break;
        case 5: {
            TQ3StoragePixmap pixmap;
            std::memset(&pixmap, 0xA5, sizeof pixmap);
            const TQ3StoragePixmap untouched = pixmap;
            if (STATUS(Q3PixmapMarker_GetPixmap(geometry, nullArg ? nullptr : &pixmap)) == kQ3Success) {
                require(Q3Object_IsType(pixmap.image, kQ3SharedTypeStorage) == kQ3True,
                        "Q3PixmapMarker_GetPixmap", "gave no storage");
                STATUS(Q3Object_Dispose(pixmap.image));
            } else {
                require(sameBytes(pixmap, untouched), "Q3PixmapMarker_GetPixmap", "failed but wrote its output");
            }
            break;
        }
        case 6: {
            StoragePixmapArgs args = storagePixmap();
            edit = true;
            status = STATUS(Q3PixmapMarker_SetPixmap(geometry, nullArg ? nullptr : &args.pixmap));
            if (status == kQ3Success) {
                TQ3StoragePixmap got{};
                STATUS(Q3PixmapMarker_GetPixmap(geometry, &got));
                require(samePixmap(got, args.pixmap), "Q3PixmapMarker_SetPixmap", "the pixmap read back differs");
                STATUS(Q3Object_Dispose(got.image));
            }
            releaseStorage(args);
            break;
        }
        default: {
            TQ3PixmapMarkerData got{};
            if (STATUS(Q3PixmapMarker_GetData(geometry, nullArg ? nullptr : &got)) == kQ3Success) {
                STATUS(Q3PixmapMarker_EmptyData(&got));
                require(got.pixmap.image == nullptr && got.pixmapMarkerAttributeSet == nullptr,
                        "Q3PixmapMarker_EmptyData", "left handles behind");
            }
            break;
        }
        }
        if (edit && ours && status != kQ3Success)
            require(editIndex(geometry) == before, "pixmapMarkers", "a failed edit changed the edit index");
        if (edit)
            require(status == kQ3Failure || ours, "pixmapMarkers", "an edit succeeded on something not held");
    }

    // Apple's per-field calls of each type: the vectors are orientation
    // (or none), major and minor; the sets are the part sets by name; the
    // scalar is the caps (cones, cylinders) or the ratio (tori).
    struct QuadricCalls {
        TQ3Status (*setOrigin)(TQ3GeometryObject, const TQ3Point3D*);
        TQ3Status (*getOrigin)(TQ3GeometryObject, TQ3Point3D*);
        TQ3Status (*setVector[3])(TQ3GeometryObject, const TQ3Vector3D*);
        TQ3Status (*getVector[3])(TQ3GeometryObject, TQ3Vector3D*);
        TQ3Status (*setSet[3])(TQ3GeometryObject, TQ3AttributeSet);
        TQ3Status (*getSet[3])(TQ3GeometryObject, TQ3AttributeSet*);
        TQ3Status (*setCaps)(TQ3GeometryObject, TQ3EndCap);
        TQ3Status (*getCaps)(TQ3GeometryObject, TQ3EndCap*);
    };

    void quadricField(std::uint8_t type, Kind kind)
    {
        static const QuadricCalls kCalls[] = {
            {Q3Box_SetOrigin, Q3Box_GetOrigin, {Q3Box_SetOrientation, Q3Box_SetMajorAxis, Q3Box_SetMinorAxis},
             {Q3Box_GetOrientation, Q3Box_GetMajorAxis, Q3Box_GetMinorAxis}, {}, {}, nullptr, nullptr},
            {Q3Cone_SetOrigin, Q3Cone_GetOrigin, {Q3Cone_SetOrientation, Q3Cone_SetMajorRadius, Q3Cone_SetMinorRadius},
             {Q3Cone_GetOrientation, Q3Cone_GetMajorRadius, Q3Cone_GetMinorRadius},
             {Q3Cone_SetBottomAttributeSet, Q3Cone_SetFaceAttributeSet},
             {Q3Cone_GetBottomAttributeSet, Q3Cone_GetFaceAttributeSet}, Q3Cone_SetCaps, Q3Cone_GetCaps},
            {Q3Cylinder_SetOrigin, Q3Cylinder_GetOrigin,
             {Q3Cylinder_SetOrientation, Q3Cylinder_SetMajorRadius, Q3Cylinder_SetMinorRadius},
             {Q3Cylinder_GetOrientation, Q3Cylinder_GetMajorRadius, Q3Cylinder_GetMinorRadius},
             {Q3Cylinder_SetTopAttributeSet, Q3Cylinder_SetBottomAttributeSet, Q3Cylinder_SetFaceAttributeSet},
             {Q3Cylinder_GetTopAttributeSet, Q3Cylinder_GetBottomAttributeSet, Q3Cylinder_GetFaceAttributeSet},
             Q3Cylinder_SetCaps, Q3Cylinder_GetCaps},
            {Q3Disk_SetOrigin, Q3Disk_GetOrigin, {nullptr, Q3Disk_SetMajorRadius, Q3Disk_SetMinorRadius},
             {nullptr, Q3Disk_GetMajorRadius, Q3Disk_GetMinorRadius}, {}, {}, nullptr, nullptr},
            {Q3Ellipse_SetOrigin, Q3Ellipse_GetOrigin, {nullptr, Q3Ellipse_SetMajorRadius, Q3Ellipse_SetMinorRadius},
             {nullptr, Q3Ellipse_GetMajorRadius, Q3Ellipse_GetMinorRadius}, {}, {}, nullptr, nullptr},
            {Q3Ellipsoid_SetOrigin, Q3Ellipsoid_GetOrigin,
             {Q3Ellipsoid_SetOrientation, Q3Ellipsoid_SetMajorRadius, Q3Ellipsoid_SetMinorRadius},
             {Q3Ellipsoid_GetOrientation, Q3Ellipsoid_GetMajorRadius, Q3Ellipsoid_GetMinorRadius}, {}, {}, nullptr,
             nullptr},
            {Q3Torus_SetOrigin, Q3Torus_GetOrigin,
             {Q3Torus_SetOrientation, Q3Torus_SetMajorRadius, Q3Torus_SetMinorRadius},
             {Q3Torus_GetOrientation, Q3Torus_GetMajorRadius, Q3Torus_GetMinorRadius}, {}, {}, nullptr, nullptr},
        };
        const QuadricCalls& c = kCalls[type];
        const TQ3Object geometry = pick(kind);
        const bool ours = holdsKind(geometry, kind) && m_initialized > 0;
        const bool nullArg = m_in.u8() == 0;
        const bool set = m_in.u8() & 1;
        const std::uint8_t field = m_in.u8();
        const std::uint8_t slot = m_in.u8() % 3;
        const TQ3Point3D point = point3();
        const TQ3Vector3D vector{point.x, point.y, point.z};
        const float ratio = m_in.value();
        const TQ3EndCap caps = TQ3EndCap(enumValue(7));
        const TQ3AttributeSet attributes = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
        const unsigned long face = m_in.index(6);
        // A Set: a success reads back with its Get, a failure changes
        // neither the field nor the edit index.
        auto edit = [&](const char* name, auto get, auto wanted, auto call) {
            decltype(wanted) old{}, now{};
            const unsigned long before = ours ? editIndex(geometry) : 0;
            if (ours)
                STATUS(get(geometry, &old));
            const TQ3Status status = STATUS(call());
            require(status == kQ3Failure || ours, name, "succeeded on something that is not a held shape");
            if (!ours)
                return;
            STATUS(get(geometry, &now));
            if (status == kQ3Success)
                require(sameBytes(now, wanted), name, "does not read back");
            else
                require(sameBytes(now, old) && editIndex(geometry) == before, name, "failed but changed the shape");
        };
        TQ3Point3D pointOut{};
        TQ3Vector3D vectorOut{};
        TQ3AttributeSet got = nullptr;
        switch (field % 5) {
        case 0:
            if (set)
                edit("SetOrigin", c.getOrigin, point,
                     [&] { return c.setOrigin(geometry, nullArg ? nullptr : &point); });
            else
                STATUS(c.getOrigin(geometry, nullArg ? nullptr : &pointOut));
            break;
        case 1:
            if (c.setVector[slot] == nullptr)
                break;
            if (set)
                edit("SetVector", c.getVector[slot], vector,
                     [&] { return c.setVector[slot](geometry, nullArg ? nullptr : &vector); });
            else
                STATUS(c.getVector[slot](geometry, nullArg ? nullptr : &vectorOut));
            break;
        case 2:
            if (type == 0) {
                const unsigned long before = ours ? editIndex(geometry) : 0;
                if (!set)
                    STATUS(Q3Box_GetFaceAttributeSet(geometry, face, nullArg ? nullptr : &got));
                else if (STATUS(Q3Box_SetFaceAttributeSet(geometry, face, attributes)) == kQ3Failure && ours)
                    require(editIndex(geometry) == before, "Q3Box_SetFaceAttributeSet", "failed but changed the box");
            } else if (c.setSet[slot] != nullptr) {
                const unsigned long before = ours ? editIndex(geometry) : 0;
                if (!set)
                    STATUS(c.getSet[slot](geometry, nullArg ? nullptr : &got));
                else if (STATUS(c.setSet[slot](geometry, attributes)) == kQ3Failure && ours)
                    require(editIndex(geometry) == before, "SetAttributeSet", "failed but changed the shape");
            }
            break;
        case 3:
            if (type == 6) {
                float out = 0.0f;
                if (set)
                    edit("Q3Torus_SetRatio", Q3Torus_GetRatio, ratio,
                         [&] { return Q3Torus_SetRatio(geometry, ratio); });
                else
                    STATUS(Q3Torus_GetRatio(geometry, nullArg ? nullptr : &out));
            } else if (c.setCaps != nullptr) {
                TQ3EndCap out = 0;
                if (set)
                    edit("SetCaps", c.getCaps, caps, [&] { return c.setCaps(geometry, caps); });
                else
                    STATUS(c.getCaps(geometry, nullArg ? nullptr : &out));
            }
            break;
        default:
            QUERY(Q3Geometry_GetType(geometry), TQ3ObjectType{kQ3ObjectTypeInvalid});
            break;
        }
        if (got != nullptr)
            hold(got, Kind::kAttributeSet);
    }

    // ---- NURB patches ------------------------------------------------------

    // A TQ3NURBPatchData and every array it points at. As for curves, the
    // arrays hold at least what the counts claim, unless a count claims more
    // than kQ3GeometryMaxArrayCount (which Q3 must reject before reading).
    struct PatchBuffers {
        std::vector<TQ3RationalPoint4D> points;
        std::vector<float> uKnots, vKnots;
        std::vector<std::vector<TQ3RationalPoint3D>> trimPoints;
        std::vector<std::vector<float>> trimKnots;
        std::vector<std::vector<TQ3NURBPatchTrimCurveData>> curves;
        std::vector<TQ3NURBPatchTrimLoopData> loops;
        TQ3NURBPatchData data{};
    };

    // Clamped uniform knots for `count` points of order `order` (ends
    // repeated order times, interior steps of 1); with `repeat`, one interior
    // knot doubled.
    static std::vector<float> clampedKnots(unsigned long count, unsigned long order, bool repeat)
    {
        std::vector<float> knots(count + order);
        const unsigned long interior = count - order;
        for (unsigned long i = 0; i < knots.size(); ++i)
            knots[i] = float(std::min(std::max(i, order - 1) - (order - 1), interior + 1));
        if (repeat && interior >= 2)
            knots[order + 1] = knots[order];
        return knots;
    }

    // The patch flag byte: bit 0 raw uOrder, bit 1 raw vOrder, bit 2 a huge
    // numTrimLoops, bit 3 a huge numRows, bit 4 a huge numColumns, bit 5 an
    // attribute set, bit 6 NULL control points, bit 7 NULL knots. Then a
    // shape byte, the scale, value overwrites, the trim loops.
    void readPatch(PatchBuffers& p)
    {
        const std::uint8_t flags = m_in.u8();
        const unsigned long uOrder = (flags & 1) ? m_in.u32() : 1 + m_in.u8() % 12;
        const unsigned long vOrder = (flags & 2) ? m_in.u32() : 1 + m_in.u8() % 12;
        // Arrays are sized with orders Q3 accepts, whatever the fields say.
        const unsigned long au = std::clamp<unsigned long>(uOrder, 2, kQ3NURBPatchMaxOrder);
        const unsigned long av = std::clamp<unsigned long>(vOrder, 2, kQ3NURBPatchMaxOrder);
        const unsigned long columns = au + m_in.u8() % 6, rows = av + m_in.u8() % 6;
        takePoints(rows * columns, rows * columns);
        const std::uint8_t shape = m_in.u8();
        const float scale = m_in.value();
        p.points.resize(rows * columns);
        for (unsigned long r = 0; r < rows; ++r)
            for (unsigned long c = 0; c < columns; ++c) {
                const float w = (shape & 1) ? 1.0f + float((r + c) % 3) : 1.0f;
                const float x = float(c) / float(columns - 1) * scale, y = float(r) / float(rows - 1) * scale;
                const float z = (shape & 2) ? std::sin(float(r + 2 * c)) * scale : 0.25f * float((r + c) % 2);
                p.points[r * columns + c] = TQ3RationalPoint4D{x * w, y * w, z * w, w};
            }
        p.uKnots = clampedKnots(columns, au, shape & 4);
        p.vKnots = clampedKnots(rows, av, shape & 8);
        for (int n = m_in.u8() % 8; n > 0; --n) {
            const std::uint8_t target = m_in.u8();
            const float v = m_in.value();
            if ((target & 3) == 1)
                p.uKnots[m_in.u16() % p.uKnots.size()] = v;
            else if ((target & 3) == 2)
                p.vKnots[m_in.u16() % p.vKnots.size()] = v;
            else
                (&p.points[m_in.u16() % p.points.size()].x)[target >> 6] = v;
        }
        // Trim loops: each a circle (or, reversed, a hole) around a point of
        // the domain, cut into curves that join end to end; optionally left
        // open, or with values overwritten.
        const float width = float(columns - au + 1), height = float(rows - av + 1);
        const unsigned long loopCount = m_in.u8() % 5;
        p.trimPoints.clear();
        p.curves.resize(loopCount);
        for (unsigned long l = 0; l < loopCount; ++l) {
            const std::uint8_t loopFlags = m_in.u8();
            const unsigned long curveCount = m_in.u8() % 4;
            const float cu = float(m_in.u8()) / 255.0f * width, cv = float(m_in.u8()) / 255.0f * height;
            const float radius = float(1 + m_in.u8()) / 512.0f * std::min(width, height);
            const float turn = (loopFlags & 1) ? -1.0f : 1.0f;
            for (unsigned long k = 0; k < curveCount; ++k) {
                const unsigned long order = (loopFlags & 2) ? m_in.u32() : 1 + m_in.u8() % 6;
                const unsigned long arrayOrder = std::clamp<unsigned long>(order, 2, 16);
                const unsigned long count = arrayOrder + m_in.u8() % 4;
                takePoints(count, count);
                std::vector<TQ3RationalPoint3D> points(count);
                for (unsigned long i = 0; i < count; ++i) {
                    const float a = 6.2831853f * turn * (float(k) + float(i) / float(count - 1)) / float(curveCount);
                    const float w = (loopFlags & 4) ? 1.0f + 0.5f * float(i % 2) : 1.0f;
                    points[i] = {(cu + radius * std::cos(a)) * w, (cv + radius * std::sin(a)) * w, w};
                }
                if (k + 1 == curveCount) // exactly where the first curve starts
                    points[count - 1] = {cu + radius, cv, 1.0f};
                p.trimPoints.push_back(std::move(points));
                p.trimKnots.push_back(clampedKnots(count, arrayOrder, loopFlags & 8));
                TQ3NURBPatchTrimCurveData curve{};
                curve.order = order;
                curve.numPoints = count;
                p.curves[l].push_back(curve);
            }
            if ((loopFlags & 16) && curveCount > 0) // open
                p.trimPoints.back().back().x += 0.25f * radius;
            if (loopFlags & 32)
                for (int n = m_in.u8() % 4; n > 0; --n) {
                    const float v = m_in.value();
                    if (p.trimPoints.empty())
                        break;
                    std::vector<TQ3RationalPoint3D>& points = p.trimPoints[m_in.u8() % p.trimPoints.size()];
                    (&points[m_in.u8() % points.size()].x)[m_in.u8() % 3] = v;
                }
            if ((loopFlags & 64) && !p.trimKnots.empty())
                p.trimKnots.back()[m_in.u8() % p.trimKnots.back().size()] = m_in.value();
        }
        // Pointers, once every array is in place.
        std::size_t next = 0;
        p.loops.resize(loopCount);
        for (unsigned long l = 0; l < loopCount; ++l) {
            for (TQ3NURBPatchTrimCurveData& curve : p.curves[l]) {
                curve.controlPoints = p.trimPoints[next].data();
                curve.knots = p.trimKnots[next].data();
                ++next;
            }
            p.loops[l].numTrimCurves = p.curves[l].size();
            p.loops[l].trimCurves = p.curves[l].empty() ? nullptr : p.curves[l].data();
            if (m_in.u8() == 0xFF)
                p.loops[l].numTrimCurves = ~0UL - m_in.u8();
        }
        p.data.uOrder = uOrder;
        p.data.vOrder = vOrder;
        p.data.numRows = (flags & 8) ? ~0UL - m_in.u8() : rows;
        p.data.numColumns = (flags & 16) ? (m_in.u8() & 1 ? ~0UL : 1UL << 32) : columns;
        p.data.controlPoints = (flags & 64) ? nullptr : p.points.data();
        p.data.uKnots = (flags & 128) ? nullptr : p.uKnots.data();
        p.data.vKnots = (flags & 128) ? nullptr : p.vKnots.data();
        p.data.numTrimLoops = (flags & 4) ? ~0UL - m_in.u8() : loopCount;
        p.data.trimLoops = p.loops.empty() ? nullptr : p.loops.data();
        p.data.patchAttributeSet = (flags & 32) ? pick(Kind::kAttributeSet) : nullptr;
    }

    // Whether two valid descriptions are the same, value for value.
    static bool samePatch(const TQ3NURBPatchData& a, const TQ3NURBPatchData& b)
    {
        if (a.uOrder != b.uOrder || a.vOrder != b.vOrder || a.numRows != b.numRows ||
            a.numColumns != b.numColumns || a.numTrimLoops != b.numTrimLoops ||
            a.patchAttributeSet != b.patchAttributeSet)
            return false;
        if (std::memcmp(a.controlPoints, b.controlPoints, a.numRows * a.numColumns * sizeof *a.controlPoints) != 0 ||
            std::memcmp(a.uKnots, b.uKnots, (a.uOrder + a.numColumns) * sizeof(float)) != 0 ||
            std::memcmp(a.vKnots, b.vKnots, (a.vOrder + a.numRows) * sizeof(float)) != 0)
            return false;
        for (unsigned long l = 0; l < a.numTrimLoops; ++l) {
            const TQ3NURBPatchTrimLoopData &la = a.trimLoops[l], &lb = b.trimLoops[l];
            if (la.numTrimCurves != lb.numTrimCurves)
                return false;
            for (unsigned long k = 0; k < la.numTrimCurves; ++k) {
                const TQ3NURBPatchTrimCurveData &ca = la.trimCurves[k], &cb = lb.trimCurves[k];
                if (ca.order != cb.order || ca.numPoints != cb.numPoints ||
                    std::memcmp(ca.controlPoints, cb.controlPoints, ca.numPoints * sizeof *ca.controlPoints) != 0 ||
                    std::memcmp(ca.knots, cb.knots, (ca.order + ca.numPoints) * sizeof(float)) != 0)
                    return false;
            }
        }
        return true;
    }

    // patches(): the action byte, then what it reads. 0 New, 1 SetData,
    // 2 GetData and EmptyData (twice), 3 immediate Submit (0-3 share
    // surfaceAction with the quadrics), 4 one control point or knot Set or
    // Get, 5 decomposition, 6 retained submit (bounds and the generic ops
    // reach patches through Kind::kPatch).
    void patches()
    {
        const std::uint8_t action = m_in.u8() % 7;
        if (action <= 3) {
            PatchBuffers p;
            readPatch(p);
            const bool nullData = m_in.u8() == 0;
            if (action == 3 && !drawAllowed())
                return;
            surfaceAction<TQ3NURBPatchData>(action, Kind::kPatch, nullData ? nullptr : &p.data, Q3NURBPatch_New,
                                            Q3NURBPatch_SetData, Q3NURBPatch_GetData, Q3NURBPatch_EmptyData,
                                            Q3NURBPatch_Submit, samePatch);
            return;
        }
        if (action == 4)
            return patchField();
        const TQ3Object patch = pick(Kind::kPatch);
        const TQ3Object view = pick(Kind::kView);
        if (!drawAllowed())
            return;
        const DrawTimer timer(m_drawSeconds);
        if (action == 5) {
            // pick may give another kind: a primitive decomposes to NULL silently.
            const Held* picked = heldEntry(patch);
            if (picked != nullptr && isPrimitiveKind(picked->kind)) {
                checkDecomposition(patch, view);
                return;
            }
            const TQ3Object result = OBJECT(Q3Geometry_GetDecomposed(patch, view));
            if (result == nullptr)
                return;
            const Held* entry = heldEntry(patch);
            require(entry != nullptr, "Q3Geometry_GetDecomposed", "decomposed something nobody holds");
            if (entry->kind == Kind::kPatch)
                checkPatchDecomposed(patch, result);
            else // another geometry, picked when no patch is held
                hold(result, Q3Geometry_GetType(result) == kQ3GeometryTypeTriMesh ? Kind::kTriMesh : Kind::kPolyLine);
        } else {
            STATUS(Q3Geometry_Submit(patch, view));
        }
    }

    // One per-field call: Set or Get of a control point (row, column), a u
    // knot or a v knot, at an index biased to the edges, NULL or not. A Set
    // that fails changes nothing; one that succeeds reads back.
    void patchField()
    {
        const TQ3Object patch = pick(Kind::kPatch);
        const bool ours = holdsKind(patch, Kind::kPatch) && m_initialized > 0;
        TQ3NURBPatchData shape{};
        if (ours && STATUS(Q3NURBPatch_GetData(patch, &shape)) != kQ3Success)
            die("Q3NURBPatch_GetData", "failed on a live patch");
        const std::uint8_t field = m_in.u8();
        const bool set = field & 1, nullArg = m_in.u8() == 0;
        const unsigned long row = m_in.index(shape.numRows), column = m_in.index(shape.numColumns);
        const unsigned long uKnot = m_in.index(shape.uOrder + shape.numColumns);
        const unsigned long vKnot = m_in.index(shape.vOrder + shape.numRows);
        const TQ3RationalPoint4D point{m_in.value(), m_in.value(), m_in.value(), m_in.value()};
        const float knot = m_in.value();
        const unsigned long before = ours ? editIndex(patch) : 0;
        TQ3Status status = kQ3Failure;
        switch ((field >> 1) % 3) {
        case 0:
            if (set) {
                status = STATUS(Q3NURBPatch_SetControlPoint(patch, row, column, nullArg ? nullptr : &point));
                TQ3RationalPoint4D got{};
                if (status == kQ3Success && ours &&
                    STATUS(Q3NURBPatch_GetControlPoint(patch, row, column, &got)) == kQ3Success)
                    require(sameBytes(got, point), "Q3NURBPatch_SetControlPoint", "does not read back");
            } else {
                TQ3RationalPoint4D got{};
                status = STATUS(Q3NURBPatch_GetControlPoint(patch, row, column, nullArg ? nullptr : &got));
                if (ours && !nullArg && row < shape.numRows && column < shape.numColumns)
                    require(status == kQ3Success && sameBytes(got, shape.controlPoints[row * shape.numColumns + column]),
                            "Q3NURBPatch_GetControlPoint", "failed or differs from GetData on a valid index");
            }
            break;
        case 1:
        case 2: {
            const bool inU = (field >> 1) % 3 == 1;
            const unsigned long index = inU ? uKnot : vKnot;
            auto setKnot = inU ? Q3NURBPatch_SetUKnot : Q3NURBPatch_SetVKnot;
            auto getKnot = inU ? Q3NURBPatch_GetUKnot : Q3NURBPatch_GetVKnot;
            const unsigned long count = inU ? shape.uOrder + shape.numColumns : shape.vOrder + shape.numRows;
            float got = 0.0f;
            if (set) {
                status = STATUS(setKnot(patch, index, knot));
                if (status == kQ3Success && ours && STATUS(getKnot(patch, index, &got)) == kQ3Success)
                    require(sameBytes(got, knot), "Q3NURBPatch_SetKnot", "does not read back");
            } else {
                status = STATUS(getKnot(patch, index, nullArg ? nullptr : &got));
                if (ours && !nullArg && index < count)
                    require(status == kQ3Success && sameBytes(got, (inU ? shape.uKnots : shape.vKnots)[index]),
                            "Q3NURBPatch_GetKnot", "failed or differs from GetData on a valid index");
            }
            break;
        }
        }
        require(status == kQ3Failure || ours, "Q3NURBPatch_*", "succeeded on something that is not a patch");
        if (ours) {
            if (set && status == kQ3Failure) {
                TQ3NURBPatchData now{};
                STATUS(Q3NURBPatch_GetData(patch, &now));
                require(editIndex(patch) == before && samePatch(now, shape), "Q3NURBPatch_Set",
                        "failed but changed the patch");
                STATUS(Q3NURBPatch_EmptyData(&now));
            }
            STATUS(Q3NURBPatch_EmptyData(&shape));
        }
    }

    // A patch gives a TriMesh of finite points within the triangle cap (or
    // two per pair of spans, when that is more), with indices in range.
    void checkPatchDecomposed(TQ3Object patch, TQ3Object result)
    {
        const char* call = "Q3Geometry_GetDecomposed";
        require(Q3Geometry_GetType(result) == kQ3GeometryTypeTriMesh, call, "a patch gave no trimesh");
        hold(result, Kind::kTriMesh);
        TQ3NURBPatchData data{};
        STATUS(Q3NURBPatch_GetData(patch, &data));
        const unsigned long spans = (data.numColumns - data.uOrder + 1) * (data.numRows - data.vOrder + 1);
        STATUS(Q3NURBPatch_EmptyData(&data));
        TQ3TriMeshData mesh{};
        STATUS(Q3TriMesh_GetData(result, &mesh));
        require(mesh.numTriangles <= std::max<unsigned long>(kQ3SubdivisionMaxTrianglesPerPatch, 2 * spans), call,
                "a patch's trimesh has more triangles than the cap");
        for (unsigned long i = 0; i < mesh.numPoints; ++i)
            require(std::isfinite(mesh.points[i].x) && std::isfinite(mesh.points[i].y) &&
                        std::isfinite(mesh.points[i].z),
                    call, "a patch's trimesh has a point that is not finite");
        for (unsigned long t = 0; t < mesh.numTriangles; ++t)
            for (unsigned long k : mesh.triangles[t].pointIndices)
                require(k < mesh.numPoints, call, "a patch's trimesh has an index out of range");
        STATUS(Q3TriMesh_EmptyData(&mesh));
    }

    void quadricDecompose(Kind kind)
    {
        const TQ3Object geometry = pick(kind);
        const TQ3Object view = pick(Kind::kView);
        if (!drawAllowed())
            return;
        checkDecomposition(geometry, view);
    }

    // A shape gives a trimesh within kQ3SubdivisionMaxTrianglesPerSurface,
    // an ellipse a closed or open polyline within the curve cap; finite.
    void checkQuadricDecomposed(Kind kind, TQ3Object result)
    {
        const char* call = "Q3Geometry_GetDecomposed";
        if (kind == Kind::kEllipse) {
            require(Q3Geometry_GetType(result) == kQ3GeometryTypePolyLine, call, "an ellipse gave no polyline");
            hold(result, Kind::kPolyLine);
            TQ3PolyLineData line{};
            STATUS(Q3PolyLine_GetData(result, &line));
            require(line.numVertices >= 2 && line.numVertices <= (unsigned long)kQ3SubdivisionMaxSegmentsPerCurve + 1,
                    call, "an ellipse's polyline has the wrong size");
            STATUS(Q3PolyLine_EmptyData(&line));
            return;
        }
        require(Q3Geometry_GetType(result) == kQ3GeometryTypeTriMesh, call, "a shape gave no trimesh");
        hold(result, Kind::kTriMesh);
        TQ3TriMeshData mesh{};
        STATUS(Q3TriMesh_GetData(result, &mesh));
        require(mesh.numTriangles >= 1 && mesh.numTriangles <= (unsigned long)kQ3SubdivisionMaxTrianglesPerSurface,
                call, "a shape's trimesh has no triangles or more than the cap");
        for (unsigned long i = 0; i < mesh.numPoints; ++i)
            require(std::isfinite(mesh.points[i].x) && std::isfinite(mesh.points[i].y) &&
                        std::isfinite(mesh.points[i].z),
                    call, "a shape's trimesh has a point that is not finite");
        STATUS(Q3TriMesh_EmptyData(&mesh));
    }

    // The math helpers with arbitrary values, results aliasing inputs. Cases
    // 9 and up are QuickDraw 3D 1.6's other QD3DMath.h calls, by family.
    void math()
    {
        TQ3Matrix4x4 a = readMatrix();
        const TQ3Matrix4x4 b = readMatrix();
        TQ3Vector3D v1 = vector3();
        const TQ3Vector3D v2 = vector3();
        TQ3Point3D p = point3();
        const bool nullArg = m_in.u8() == 0;
        TQ3Matrix4x4 r{};
        switch (m_in.u8() % 15) {
        case 0: POINTER(Q3Matrix4x4_Invert(&a, nullArg ? nullptr : &r)); break;
        case 1: POINTER(Q3Matrix4x4_Invert(&a, &a)); break;
        case 2: POINTER(Q3Matrix4x4_Multiply(&a, nullArg ? nullptr : &b, &a)); break;
        case 3: POINTER(Q3Matrix4x4_Transpose(&a, &a)); break;
        case 4: POINTER(Q3Point3D_Transform(&p, nullArg ? nullptr : &a, &p)); break;
        case 5: POINTER(Q3Vector3D_Normalize(&v1, nullArg ? nullptr : &v1)); break;
        case 6: POINTER(Q3Vector3D_Cross(&v1, &v2, &v1)); break;
        case 7: QUERY(Q3Vector3D_Dot(&v1, nullArg ? nullptr : &v2), 0.0f); break;
        case 9: mathPoints(nullArg); break;
        case 10: mathVectors(a, nullArg); break;
        case 11: mathMatrices(a, b, v1, v2, p, nullArg); break;
        case 12: mathQuaternions(a, v1, v2, p, nullArg); break;
        case 13: mathBounds(nullArg); break;
        case 14: mathArrays(a, nullArg); break;
        default: QUERY(Q3Point3D_Distance(&p, nullArg ? nullptr : &p), 0.0f); break;
        }
    }

    // A QD3DMath.h call that writes *out: it returns out on success; on
    // failure (exactly one error, as POINTER checks) *out is as it was.
    // Tells whether the call succeeded.
    template <class T, class Call>
    bool mathInto(const char* call, T* out, Call&& compute)
    {
        T before{};
        if (out != nullptr)
            before = *out;
        T* const result = checkPointer(call, (begin(), compute()));
        if (out != nullptr && result == nullptr)
            require(sameBytes(*out, before), call, "failed but changed its result");
        if (result != nullptr)
            require(result == out, call, "returned a pointer other than its result");
        return result != nullptr;
    }
#define MATH_INTO(out, call) mathInto(#call, (out), [&] { return (call); })

    TQ3Point2D point2() { return TQ3Point2D{m_in.value(), m_in.value()}; }
    TQ3Vector2D vector2() { return TQ3Vector2D{m_in.value(), m_in.value()}; }
    TQ3RationalPoint4D point4() { return TQ3RationalPoint4D{m_in.value(), m_in.value(), m_in.value(), m_in.value()}; }
    TQ3Quaternion quaternion() { return TQ3Quaternion{m_in.value(), m_in.value(), m_in.value(), m_in.value()}; }

    TQ3Matrix3x3 readMatrix3x3()
    {
        TQ3Matrix3x3 m{};
        const std::uint8_t mode = m_in.u8();
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                m.value[i][j] = (mode & 1) ? m_in.value() : (i == j ? 1.0f : 0.0f);
        if (!(mode & 1))
            for (int n = mode >> 5; n > 0; --n)
                m.value[m_in.u8() % 3][m_in.u8() % 3] = m_in.value();
        return m;
    }

    void mathPoints(bool nullArg)
    {
        TQ3Point2D p2 = point2();
        const TQ3Point2D q2 = point2();
        TQ3Param2D u{m_in.value(), m_in.value()};
        TQ3Point3D p3 = point3();
        const TQ3Point3D q3 = point3();
        TQ3RationalPoint3D r3{m_in.value(), m_in.value(), m_in.value()};
        TQ3RationalPoint4D r4 = point4();
        const TQ3RationalPoint4D s4 = point4();
        const TQ3Vector2D v2 = vector2();
        const TQ3Vector3D v3 = vector3();
        const float r1 = m_in.value(), rr2 = m_in.value();
        TQ3PolarPoint polar{m_in.value(), m_in.value()};
        TQ3SphericalPoint sphere{m_in.value(), m_in.value(), m_in.value()};
        const TQ3Matrix3x3 m = readMatrix3x3();
        TQ3Vector2D ov2{};
        TQ3Vector3D ov3{};
        switch (m_in.u8() % 24) {
        case 0: MATH_INTO(&p2, Q3Point2D_Set(nullArg ? nullptr : &p2, r1, rr2)); break;
        case 1: MATH_INTO(&r3, Q3RationalPoint3D_Set(&r3, r1, rr2, q2.x)); break;
        case 2: MATH_INTO(&sphere, Q3SphericalPoint_Set(&sphere, r1, rr2, q2.y)); break;
        case 3: MATH_INTO(&p3, Q3Point2D_To3D(nullArg ? nullptr : &p2, &p3)); break;
        case 4: MATH_INTO(&p2, Q3RationalPoint3D_To2D(&r3, &p2)); break;
        case 5: MATH_INTO(&p3, Q3RationalPoint4D_To3D(&r4, &p3)); break;
        case 6: MATH_INTO(&ov2, Q3Param2D_Subtract(&u, nullArg ? nullptr : &u, &ov2)); break;
        case 7: MATH_INTO(&ov3, Q3Point3D_Subtract(&p3, &q3, &ov3)); break;
        case 8: QUERY(Q3RationalPoint3D_Distance(&r3, nullArg ? nullptr : &r3), 0.0f); break;
        case 9: QUERY(Q3RationalPoint4D_DistanceSquared(&r4, &s4), 0.0f); break;
        case 10: QUERY(Q3Point2D_Distance(&p2, &q2), 0.0f); break;
        case 11: MATH_INTO(&p2, Q3Point2D_RRatio(&p2, &q2, r1, rr2, &p2)); break;
        case 12: MATH_INTO(&r4, Q3RationalPoint4D_RRatio(&s4, &r4, r1, rr2, nullArg ? nullptr : &r4)); break;
        case 13: MATH_INTO(&u, Q3Param2D_RRatio(&u, &u, r1, rr2, &u)); break;
        case 14: MATH_INTO(&p3, Q3Point3D_Vector3D_Add(&p3, nullArg ? nullptr : &v3, &p3)); break;
        case 15: MATH_INTO(&u, Q3Param2D_Vector2D_Subtract(&u, &v2, &u)); break;
        case 16: MATH_INTO(&ov3, Q3Point3D_CrossProductTri(&p3, &q3, &p3, &ov3)); break;
        case 17: MATH_INTO(&p2, Q3Point2D_Transform(&p2, nullArg ? nullptr : &m, &p2)); break;
        case 18: MATH_INTO(&u, Q3Param2D_Transform(&u, &m, &u)); break;
        case 19: MATH_INTO(&polar, Q3Point2D_ToPolar(&p2, &polar)); break;
        case 20: MATH_INTO(&p2, Q3PolarPoint_ToPoint2D(&polar, nullArg ? nullptr : &p2)); break;
        case 21: MATH_INTO(&sphere, Q3Point3D_ToSpherical(&p3, &sphere)); break;
        case 22: MATH_INTO(&p3, Q3SphericalPoint_ToPoint3D(&sphere, &p3)); break;
        default: MATH_INTO(&r4, Q3Point3D_To4D(&p3, &r4)); break;
        }
    }

    void mathVectors(const TQ3Matrix4x4& m4, bool nullArg)
    {
        TQ3Vector2D a = vector2();
        const TQ3Vector2D b = vector2();
        TQ3Vector3D c = vector3();
        const TQ3Vector3D d = vector3();
        const float scalar = m_in.value();
        const TQ3Matrix3x3 m3 = readMatrix3x3();
        switch (m_in.u8() % 14) {
        case 0: MATH_INTO(&a, Q3Vector2D_Set(&a, scalar, b.y)); break;
        case 1: MATH_INTO(&c, Q3Vector2D_To3D(nullArg ? nullptr : &a, &c)); break;
        case 2: MATH_INTO(&a, Q3Vector3D_To2D(&c, &a)); break;
        case 3: MATH_INTO(&a, Q3Vector2D_Scale(&a, scalar, nullArg ? nullptr : &a)); break;
        case 4: MATH_INTO(&c, Q3Vector3D_Scale(&c, scalar, &c)); break;
        case 5: QUERY(Q3Vector2D_Length(nullArg ? nullptr : &a), 0.0f); break;
        case 6: MATH_INTO(&a, Q3Vector2D_Normalize(&a, &a)); break;
        case 7: MATH_INTO(&a, Q3Vector2D_Add(&a, nullArg ? nullptr : &b, &a)); break;
        case 8: MATH_INTO(&c, Q3Vector3D_Subtract(&d, &c, &c)); break;
        case 9: QUERY(Q3Vector2D_Cross(&a, nullArg ? nullptr : &b), 0.0f); break;
        case 10: QUERY(Q3Vector2D_Dot(&a, &b), 0.0f); break;
        case 11: MATH_INTO(&a, Q3Vector2D_Transform(&a, nullArg ? nullptr : &m3, &a)); break;
        case 12: MATH_INTO(&c, Q3Vector3D_Transform(&c, &m4, &c)); break;
        default: MATH_INTO(&c, Q3Vector3D_Negate(nullArg ? nullptr : &d, &c)); break;
        }
    }

    void mathMatrices(TQ3Matrix4x4& a, const TQ3Matrix4x4& b, const TQ3Vector3D& v1, const TQ3Vector3D& v2,
                      const TQ3Point3D& p, bool nullArg)
    {
        TQ3Matrix3x3 m = readMatrix3x3();
        const TQ3Matrix3x3 n = readMatrix3x3();
        const TQ3Point2D origin = point2();
        const TQ3Quaternion q = quaternion();
        const float x = m_in.value(), y = m_in.value(), z = m_in.value();
        switch (m_in.u8() % 16) {
        case 0: MATH_INTO(&m, Q3Matrix3x3_Copy(&n, nullArg ? nullptr : &m)); break;
        case 1: MATH_INTO(&m, Q3Matrix3x3_SetIdentity(&m)); break;
        case 2: MATH_INTO(&m, Q3Matrix3x3_Transpose(&m, &m)); break;
        case 3: MATH_INTO(&m, Q3Matrix3x3_Invert(&m, nullArg ? nullptr : &m)); break;
        case 4: MATH_INTO(&m, Q3Matrix3x3_Adjoint(&m, &m)); break;
        case 5: MATH_INTO(&m, Q3Matrix3x3_Multiply(&m, nullArg ? nullptr : &n, &m)); break;
        case 6: MATH_INTO(&m, Q3Matrix3x3_SetTranslate(&m, x, y)); break;
        case 7: MATH_INTO(&m, Q3Matrix3x3_SetScale(nullArg ? nullptr : &m, x, y)); break;
        case 8: MATH_INTO(&m, Q3Matrix3x3_SetRotateAboutPoint(&m, nullArg ? nullptr : &origin, x)); break;
        case 9: MATH_INTO(&a, Q3Matrix4x4_SetRotateAboutPoint(&a, nullArg ? nullptr : &p, x, y, z)); break;
        case 10: MATH_INTO(&a, Q3Matrix4x4_SetRotate_XYZ(&a, x, y, z)); break;
        case 11: MATH_INTO(&a, Q3Matrix4x4_SetRotateVectorToVector(&a, &v1, nullArg ? nullptr : &v2)); break;
        case 12: MATH_INTO(&a, Q3Matrix4x4_SetQuaternion(&a, nullArg ? nullptr : &q)); break;
        case 13: QUERY(Q3Matrix3x3_Determinant(nullArg ? nullptr : &m), 0.0f); break;
        case 14: QUERY(Q3Matrix4x4_Determinant(&b), 0.0f); break;
        default: MATH_INTO(&a, Q3Matrix4x4_Copy(&b, &a)); break;
        }
    }

    void mathQuaternions(const TQ3Matrix4x4& m, const TQ3Vector3D& v1, const TQ3Vector3D& v2, TQ3Point3D& p,
                         bool nullArg)
    {
        TQ3Quaternion q1 = quaternion();
        const TQ3Quaternion q2 = quaternion();
        TQ3Vector3D v = v1;
        const float t = m_in.value(), x = m_in.value(), y = m_in.value(), z = m_in.value();
        switch (m_in.u8() % 20) {
        case 0: MATH_INTO(&q1, Q3Quaternion_Set(&q1, t, x, y, z)); break;
        case 1: MATH_INTO(&q1, Q3Quaternion_SetIdentity(nullArg ? nullptr : &q1)); break;
        case 2: MATH_INTO(&q1, Q3Quaternion_Copy(&q2, &q1)); break;
        case 3: QUERY(Q3Quaternion_IsIdentity(nullArg ? nullptr : &q1), kQ3False); break;
        case 4: MATH_INTO(&q1, Q3Quaternion_Invert(&q1, &q1)); break;
        case 5: MATH_INTO(&q1, Q3Quaternion_Normalize(&q1, nullArg ? nullptr : &q1)); break;
        case 6: QUERY(Q3Quaternion_Dot(&q1, nullArg ? nullptr : &q2), 0.0f); break;
        case 7: MATH_INTO(&q1, Q3Quaternion_Multiply(&q1, &q2, &q1)); break;
        case 8: MATH_INTO(&q1, Q3Quaternion_SetRotateAboutAxis(&q1, nullArg ? nullptr : &v2, t)); break;
        case 9: MATH_INTO(&q1, Q3Quaternion_SetRotate_XYZ(&q1, x, y, z)); break;
        case 10: MATH_INTO(&q1, Q3Quaternion_SetRotate_X(&q1, t)); break;
        case 11: MATH_INTO(&q1, Q3Quaternion_SetRotate_Z(&q1, t)); break;
        case 12: MATH_INTO(&q1, Q3Quaternion_SetMatrix(&q1, nullArg ? nullptr : &m)); break;
        case 13: MATH_INTO(&q1, Q3Quaternion_SetRotateVectorToVector(&q1, &v1, &v2)); break;
        case 14: MATH_INTO(&q1, Q3Quaternion_MatchReflection(&q1, &q2, &q1)); break;
        case 15: MATH_INTO(&q1, Q3Quaternion_InterpolateFast(&q1, &q2, t, nullArg ? nullptr : &q1)); break;
        case 16: MATH_INTO(&q1, Q3Quaternion_InterpolateLinear(&q2, &q1, t, &q1)); break;
        case 17: MATH_INTO(&v, Q3Vector3D_TransformQuaternion(&v, nullArg ? nullptr : &q1, &v)); break;
        case 18: MATH_INTO(&p, Q3Point3D_TransformQuaternion(&p, &q2, &p)); break;
        default: MATH_INTO(&q1, Q3Quaternion_SetRotate_Y(&q1, t)); break;
        }
    }

    struct Exact {
        double x, y, z;
    };

    // The point a point stands for, exactly (in double).
    static Exact exactPoint(const TQ3Point3D& p) { return Exact{p.x, p.y, p.z}; }
    static Exact exactPoint(const TQ3RationalPoint4D& p)
    {
        const double w = p.w == 0.0f ? 1.0 : p.w;
        return Exact{p.x / w, p.y / w, p.z / w};
    }

    static bool finite(const Exact& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

    static std::int32_t enumInt(const TQ3Boolean& value)
    {
        std::int32_t raw;
        std::memcpy(&raw, &value, sizeof raw);
        return raw;
    }

    // A bound made of points holds each of them exactly (QD3DMath.h rounds
    // outwards); checked where the bound and the point are finite.
    void requireHolds(const char* call, const TQ3BoundingBox& box, const Exact& p)
    {
        const Exact low = exactPoint(box.min), high = exactPoint(box.max);
        if (finite(low) && finite(high) && finite(p))
            require(low.x <= p.x && p.x <= high.x && low.y <= p.y && p.y <= high.y && low.z <= p.z && p.z <= high.z,
                    call, "the box does not hold a point it was made of");
    }

    // The distance is measured in double here and there; a few double ulps
    // of slack keep a point exactly on a float radius from failing.
    void requireHolds(const char* call, const TQ3BoundingSphere& sphere, const Exact& p)
    {
        const double dx = p.x - sphere.origin.x, dy = p.y - sphere.origin.y, dz = p.z - sphere.origin.z;
        const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
        if (std::isfinite(d) && std::isfinite(sphere.radius))
            require(d <= double(sphere.radius) * (1.0 + 1e-12), call,
                    "the sphere does not hold a point it was made of");
    }

    // isEmpty 0, 1 or any int a C caller may store.
    template <class Bound>
    void setIsEmpty(Bound& bound)
    {
        const std::uint8_t mode = m_in.u8();
        setRaw(bound.isEmpty, mode < 160 ? 0 : mode < 230 ? 1 : static_cast<std::int32_t>(m_in.u32()));
    }

    void mathBounds(bool nullArg)
    {
        TQ3BoundingBox box1{point3(), point3(), kQ3False}, box2{point3(), point3(), kQ3False};
        TQ3BoundingSphere s1{point3(), m_in.value(), kQ3False}, s2{point3(), m_in.value(), kQ3False};
        setIsEmpty(box1);
        setIsEmpty(box2);
        setIsEmpty(s1);
        setIsEmpty(s2);
        const TQ3Point3D point = point3();
        const TQ3RationalPoint4D point4D = point4();
        // Passed from C (CCaller.c): C++ cannot hold an int outside the enum.
        const int isEmpty = m_in.u8() % 4 == 0 ? static_cast<int>(m_in.u32()) : m_in.u8() % 2;
        const bool box1Empty = enumInt(box1.isEmpty) != 0;
        // A sphere with a negative radius holds nothing the union could keep.
        const bool s1Sane = enumInt(s1.isEmpty) != 0 || s1.radius >= 0.0f;
        const TQ3BoundingBox box1Before = box1;
        switch (m_in.u8() % 12) {
        case 0: MATH_INTO(&box2, Q3BoundingBox_Copy(&box1, nullArg ? nullptr : &box2)); break;
        case 1: MATH_INTO(&box1, Q3BoundingBox_Union(&box1, nullArg ? nullptr : &box2, &box1)); break;
        case 2: MATH_INTO(&box1, q3fuzz_BoundingBox_Set(&box1, &point, nullArg ? nullptr : &point, isEmpty)); break;
        case 3:
            if (MATH_INTO(&box1, Q3BoundingBox_UnionPoint3D(&box1, &point, &box1)))
                requireHolds("Q3BoundingBox_UnionPoint3D", box1, exactPoint(point));
            break;
        case 4:
            if (MATH_INTO(&box1, Q3BoundingBox_UnionRationalPoint4D(&box1, &point4D, &box1)))
                requireHolds("Q3BoundingBox_UnionRationalPoint4D", box1, exactPoint(point4D));
            break;
        case 5: MATH_INTO(&s2, Q3BoundingSphere_Copy(&s1, &s2)); break;
        case 6: MATH_INTO(&s1, Q3BoundingSphere_Union(&s1, nullArg ? nullptr : &s2, &s1)); break;
        case 7:
            MATH_INTO(&s1, q3fuzz_BoundingSphere_Set(&s1, nullArg ? nullptr : &point, m_in.value(), isEmpty));
            break;
        case 8:
            if (MATH_INTO(&s1, Q3BoundingSphere_UnionPoint3D(&s1, &point, nullArg ? nullptr : &s1)) && s1Sane)
                requireHolds("Q3BoundingSphere_UnionPoint3D", s1, exactPoint(point));
            break;
        case 9:
            if (MATH_INTO(&s1, Q3BoundingSphere_UnionRationalPoint4D(&s1, &point4D, &s1)) && s1Sane)
                requireHolds("Q3BoundingSphere_UnionRationalPoint4D", s1, exactPoint(point4D));
            break;
        case 10:
            // A box that is not empty (nor inside out) still holds its
            // corners after a union.
            if (MATH_INTO(&box2, Q3BoundingBox_Union(&box2, &box1, &box2)) && !box1Empty &&
                box1Before.min.x <= box1Before.max.x && box1Before.min.y <= box1Before.max.y &&
                box1Before.min.z <= box1Before.max.z) {
                requireHolds("Q3BoundingBox_Union", box2, exactPoint(box1Before.min));
                requireHolds("Q3BoundingBox_Union", box2, exactPoint(box1Before.max));
            }
            break;
        default: MATH_INTO(&box2, Q3BoundingBox_Copy(&box2, &box2)); break;
        }
    }

    // An array of count elements of T at a stride, in bytes that hold all
    // of them (one spare byte in front puts them off alignment); or a count
    // or a stride Q3 must reject before reading; or NULL.
    template <class T>
    struct MathArray {
        std::vector<unsigned char> bytes;
        unsigned long count = 0;
        unsigned long stride = sizeof(T);
        bool null = false;
        bool badStride = false;
        bool badCount = false;
        T* data() { return null ? nullptr : reinterpret_cast<T*>(bytes.data() + 1); }
        T at(unsigned long i) const
        {
            T value;
            std::memcpy(&value, bytes.data() + 1 + i * stride, sizeof value);
            return value;
        }
        // Room for n elements at this stride.
        void reserveFor(unsigned long n)
        {
            const std::size_t need = 1 + n * stride + sizeof(T);
            if (bytes.size() < need)
                bytes.resize(need, 0);
        }
    };

    template <class T, class Fill>
    MathArray<T> readMathArray(Fill fill)
    {
        MathArray<T> array;
        const std::uint8_t shape = m_in.u8();
        array.count = m_in.u8() % 9;
        array.stride = sizeof(T) + ((shape & 1) ? m_in.u8() % 9 : 0);
        if ((shape >> 1) % 8 == 0) {
            array.stride = m_in.u8() % sizeof(T); // smaller than an element
            array.badStride = true;
        }
        array.reserveFor(array.count);
        for (unsigned long i = 0; i < array.count; ++i) {
            const T value = fill();
            std::memcpy(array.bytes.data() + 1 + i * array.stride, &value, sizeof value);
        }
        if ((shape >> 4) % 8 == 0) {
            // More than any array could hold at a stride of 12 bytes or more.
            array.count = kLongMax - m_in.u8();
            array.badCount = true;
        }
        array.null = (shape & 0x80) && m_in.u8() % 4 == 0;
        return array;
    }

    // A transform-array call: on failure the output bytes are unchanged, on
    // success each output element is the single-point call's result.
    template <class In, class Out, class Call, class Single>
    void transformArray(const char* call, const MathArray<In>& in, MathArray<Out>& out, long count, Call&& compute,
                        Single single)
    {
        const std::vector<unsigned char> before = out.bytes;
        const MathArray<In> input = in; // the output may be the input
        const TQ3Status status = checkStatus(call, (begin(), compute()));
        if (status == kQ3Failure) {
            require(out.bytes == before, call, "failed but wrote its output array");
            return;
        }
        require(m_initialized > 0 && count >= 0 && !input.badCount && !input.badStride && !out.badStride &&
                    !(count > 0 && (input.null || out.null)),
                call, "accepted a bad count, stride or array");
        for (long i = 0; i < count; ++i)
            require(sameBytes(out.at(static_cast<unsigned long>(i)), single(input.at(static_cast<unsigned long>(i)))),
                    call, "an element differs from the single-point call");
    }

    // A bound of a point array succeeds exactly when nothing it was given
    // is bad; then it is empty for no points and holds every point.
    template <class Bound, class T>
    void boundOfArray(const char* call, Bound* out, MathArray<T>& in,
                      Bound* (*function)(Bound*, const T*, unsigned long, unsigned long))
    {
        Bound before{};
        if (out != nullptr)
            before = *out;
        Bound* const result = checkPointer(call, (begin(), function(out, in.data(), in.count, in.stride)));
        const bool bad = m_initialized == 0 || out == nullptr || in.badStride || in.badCount ||
                         (in.null && in.count != 0);
        require((result == nullptr) == bad, call, bad ? "accepted a bad argument" : "failed on good arguments");
        if (result == nullptr) {
            if (out != nullptr)
                require(sameBytes(*out, before), call, "failed but changed its result");
            return;
        }
        require(enumInt(out->isEmpty) == (in.count == 0 ? 1 : 0), call, "isEmpty does not match the count");
        for (unsigned long i = 0; i < in.count; ++i)
            requireHolds(call, *out, exactPoint(in.at(i)));
    }

    TQ3Point3D transformedOnce(const TQ3Point3D& p, const TQ3Matrix4x4& m)
    {
        TQ3Point3D r{};
        POINTER(Q3Point3D_Transform(&p, &m, &r));
        return r;
    }

    TQ3RationalPoint4D transformedOnce(const TQ3RationalPoint4D& p, const TQ3Matrix4x4& m)
    {
        TQ3RationalPoint4D r{};
        POINTER(Q3RationalPoint4D_Transform(&p, &m, &r));
        return r;
    }

    void mathArrays(const TQ3Matrix4x4& m, bool nullArg)
    {
        const std::uint8_t which = m_in.u8() % 9;
        MathArray<TQ3Point3D> in3 = readMathArray<TQ3Point3D>([&] { return point3(); });
        MathArray<TQ3RationalPoint4D> in4 = readMathArray<TQ3RationalPoint4D>([&] { return point4(); });
        MathArray<TQ3Point3D> out3 = readMathArray<TQ3Point3D>([&] { return point3(); });
        MathArray<TQ3RationalPoint4D> out4 = readMathArray<TQ3RationalPoint4D>([&] { return point4(); });
        // The outputs hold as many elements as the inputs claim (a claim
        // no array could hold is rejected before anything is written).
        for (const unsigned long n : {in3.badCount ? 0 : in3.count, in4.badCount ? 0 : in4.count}) {
            out3.reserveFor(n);
            out4.reserveFor(n);
        }
        out3.count = out4.count = 0;
        const bool negative = m_in.u8() == 255;
        auto countOf = [&](const auto& in) {
            return negative ? -1 - long(m_in.u8()) : long(std::min(in.count, kLongMax));
        };
        const TQ3Matrix4x4* matrix = nullArg ? nullptr : &m;
        auto transformOf = [&](const auto& p) { return transformedOnce(p, m); };
        auto rationalOf = [&](const TQ3Point3D& p) {
            const TQ3RationalPoint4D r{p.x, p.y, p.z, 1.0f};
            return transformedOnce(r, m);
        };
        TQ3BoundingBox box{};
        TQ3BoundingSphere sphere{};
        switch (which) {
        case 0: {
            const long count = countOf(in3);
            transformArray("Q3Point3D_To3DTransformArray", in3, out3, count, [&] {
                return Q3Point3D_To3DTransformArray(in3.data(), matrix, out3.data(), count, in3.stride, out3.stride);
            }, transformOf);
            break;
        }
        case 1: {
            const long count = countOf(in3);
            transformArray("Q3Point3D_To4DTransformArray", in3, out4, count, [&] {
                return Q3Point3D_To4DTransformArray(in3.data(), matrix, out4.data(), count, in3.stride, out4.stride);
            }, rationalOf);
            break;
        }
        case 2: {
            const long count = countOf(in4);
            transformArray("Q3RationalPoint4D_To4DTransformArray", in4, out4, count, [&] {
                return Q3RationalPoint4D_To4DTransformArray(in4.data(), matrix, out4.data(), count, in4.stride,
                                                            out4.stride);
            }, transformOf);
            break;
        }
        case 3: {
            // In place: the input array is the output array.
            const long count = countOf(in3);
            transformArray("Q3Point3D_To3DTransformArray", in3, in3, count, [&] {
                return Q3Point3D_To3DTransformArray(in3.data(), matrix, in3.data(), count, in3.stride, in3.stride);
            }, transformOf);
            break;
        }
        case 4:
            boundOfArray("Q3BoundingBox_SetFromPoints3D", nullArg ? nullptr : &box, in3,
                         &Q3BoundingBox_SetFromPoints3D);
            break;
        case 5:
            boundOfArray("Q3BoundingBox_SetFromRationalPoints4D", nullArg ? nullptr : &box, in4,
                         &Q3BoundingBox_SetFromRationalPoints4D);
            break;
        case 6:
            boundOfArray("Q3BoundingSphere_SetFromPoints3D", nullArg ? nullptr : &sphere, in3,
                         &Q3BoundingSphere_SetFromPoints3D);
            break;
        case 7:
            boundOfArray("Q3BoundingSphere_SetFromRationalPoints4D", nullArg ? nullptr : &sphere, in4,
                         &Q3BoundingSphere_SetFromRationalPoints4D);
            break;
        default: {
            // Contiguous points and weights, as many as claimed, or a count
            // no array could hold.
            std::vector<TQ3Point3D> points(m_in.u8() % 6);
            std::vector<float> weights(points.size());
            for (std::size_t i = 0; i < points.size(); ++i) {
                points[i] = point3();
                weights[i] = m_in.value();
            }
            unsigned long n = points.size();
            if (m_in.u8() == 255)
                n = std::numeric_limits<unsigned long>::max() - m_in.u8();
            TQ3Point3D result = point3();
            MATH_INTO(&result, Q3Point3D_AffineComb(points.empty() ? nullptr : points.data(),
                                                    weights.empty() ? nullptr : weights.data(), n,
                                                    nullArg ? nullptr : &result));
            break;
        }
        }
    }
    static constexpr unsigned long kLongMax = static_cast<unsigned long>(std::numeric_limits<long>::max());

    // The curve tools of Q3NURBCurveTools.h, in the object form on a picked handle
    // or the data form on curve data from the input: parameters, tolerances,
    // indices and counts from the input (NaN, infinities, the ends and beyond), a
    // NULL output now and then. A success hands out curves that Q3NURBCurve_New
    // accepts (then released); a failure writes nothing; a retained curve keeps its
    // edit index. Measuring, inversion and fitting share the curve-draw budget.
    void curveTools()
    {
        const bool object = m_in.u8() & 1;
        const TQ3Object curve = object ? pick(Kind::kCurve) : nullptr;
        CurveBuffers c;
        if (!object)
            readCurve(c);
        const TQ3NURBCurveData* data = m_in.u8() == 0 ? nullptr : &c.data;
        const bool nullOut = m_in.u8() == 0;
        const float a = m_in.value();
        const float b = m_in.value();
        const float tolerance = m_in.value();
        const unsigned long index = m_in.index(object ? knotCount(curve) : c.knots.size());
        const unsigned long times = m_in.index(16);
        const std::uint8_t which = m_in.u8() % 17;
        // Up to 31 knots or 63 points, claimed as they are or as a count past the
        // limit (which Q3 must refuse before reading).
        std::vector<float> knots(m_in.u8() % 32);
        for (float& k : knots)
            k = m_in.value();
        std::vector<TQ3Point3D> points(std::min<std::size_t>(m_in.u8() % 64, m_in.remaining() / 3 + 1));
        for (TQ3Point3D& p : points)
            p = point3();
        const bool hugeCount = m_in.u8() == 0;
        const unsigned long claimedKnots = hugeCount ? kQ3NURBCurveToolsMaxPoints + 1 : knots.size();
        const unsigned long claimedPoints = hugeCount ? ~0UL : points.size();
        const unsigned long order = 1 + m_in.u8() % 17;
        const TQ3NURBCurveParameterization how = (m_in.u8() & 1) ? kQ3NURBCurveParameterizationCentripetal
                                                                   : kQ3NURBCurveParameterizationChordLength;
        const TQ3Point3D target = point3();
        if (which >= 12 && !drawAllowed())
            return;
        const DrawTimer timer(m_drawSeconds);
        const bool held = object && holdsKind(curve, Kind::kCurve) && m_initialized > 0;
        const unsigned long before = held ? editIndex(curve) : 0;

        struct Outputs {
            float f[2];
            TQ3Point3D p;
            TQ3Vector3D v[2];
            TQ3NURBCurveData curves[2];
            unsigned long n;
        } out, untouched;
        std::memset(&out, 0x5A, sizeof out);
        untouched = out;
        float* f0 = nullOut ? nullptr : &out.f[0];
        TQ3NURBCurveData* c0 = nullOut ? nullptr : &out.curves[0];
        TQ3NURBCurveData* c1 = (m_in.u8() & 7) == 0 ? c0 : &out.curves[1];
#define Q3_FUZZ_TOOL(name, ...)                                                                     \
    (object ? STATUS(Q3NURBCurve_##name(curve, __VA_ARGS__)) : STATUS(Q3NURBCurveData_##name(data, __VA_ARGS__)))
        TQ3Status status = kQ3Failure;
        switch (which) {
        case 0: status = Q3_FUZZ_TOOL(GetDomain, f0, &out.f[1]); break;
        case 1: status = Q3_FUZZ_TOOL(Evaluate, a, nullOut ? nullptr : &out.p); break;
        case 2: status = Q3_FUZZ_TOOL(EvaluateDerivatives, a, &out.p, nullOut ? nullptr : &out.v[0], &out.v[1]); break;
        case 3: status = Q3_FUZZ_TOOL(GetTangent, a, nullOut ? nullptr : &out.v[0]); break;
        case 4: status = Q3_FUZZ_TOOL(GetCurvature, a, f0); break;
        case 5: status = Q3_FUZZ_TOOL(InsertKnot, a, times, c0); break;
        case 6: status = Q3_FUZZ_TOOL(RefineKnots, claimedKnots, knots.empty() ? nullptr : knots.data(), c0); break;
        case 7: status = Q3_FUZZ_TOOL(RemoveKnot, index, times, tolerance, c0, &out.n); break;
        case 8: status = Q3_FUZZ_TOOL(ElevateDegree, times, c0); break;
        case 9: status = Q3_FUZZ_TOOL(CountBezierPieces, nullOut ? nullptr : &out.n); break;
        case 10: status = Q3_FUZZ_TOOL(GetBezierPiece, index, c0); break;
        case 11: status = Q3_FUZZ_TOOL(Split, a, c0, c1); break;
        case 12: status = Q3_FUZZ_TOOL(GetArcLength, a, b, tolerance, f0); break;
        case 13: status = Q3_FUZZ_TOOL(GetParameterAtLength, a, b, tolerance, f0); break;
        case 14: status = Q3_FUZZ_TOOL(GetClosestPoint, &target, f0, &out.p); break;
        case 15:
            status = STATUS(Q3NURBCurveData_Interpolate(order, claimedPoints, points.empty() ? nullptr : points.data(),
                                                         how, c0));
            break;
        default:
            status = STATUS(Q3NURBCurveData_Approximate(order, claimedPoints, points.empty() ? nullptr : points.data(),
                                                         times, how, c0));
            break;
        }
#undef Q3_FUZZ_TOOL
        if (status == kQ3Failure) {
            require(sameBytes(out, untouched), "a curve tool", "failed but wrote its output");
        } else {
            for (TQ3NURBCurveData& made : out.curves) {
                if (sameBytes(made, untouched.curves[0]))
                    continue;
                require(made.curveAttributeSet == nullptr, "a curve tool", "handed out an attribute set");
                const TQ3Object check = OBJECT(Q3NURBCurve_New(&made));
                require(check != nullptr, "a curve tool", "handed out a curve Q3NURBCurve_New rejects");
                STATUS(Q3Object_Dispose(check));
                STATUS(Q3NURBCurve_EmptyData(&made));
            }
        }
        if (held)
            require(editIndex(curve) == before, "a curve tool", "changed the retained curve's edit index");
    }

    TQ3CameraData readCameraData()
    {
        TQ3CameraData data{};
        data.placement = {{1.5f, 0.5f, 10.0f}, {1.5f, 0.5f, 0.0f}, {0.0f, 1.0f, 0.0f}};
        data.range = {1.0f, 100.0f};
        data.viewPort = {{-1.0f, 1.0f}, 2.0f, 2.0f};
        const std::uint8_t mode = m_in.u8();
        if (mode & 1) {
            data.placement = {point3(), point3(), vector3()};
            data.range = {m_in.value(), m_in.value()};
            data.viewPort = {{m_in.value(), m_in.value()}, m_in.value(), m_in.value()};
        } else {
            float* values = &data.placement.cameraLocation.x;
            constexpr int kFloats = sizeof(TQ3CameraData) / sizeof(float);
            for (int n = (mode >> 1) % 4; n > 0; --n)
                values[m_in.u8() % kFloats] = m_in.value();
        }
        return data;
    }

    void newCamera()
    {
        TQ3Object camera = nullptr;
        const bool nullData = m_in.u8() == 0;
        switch (m_in.u8() % 3) {
        case 0: {
            TQ3OrthographicCameraData data{readCameraData(), -2.0f, 1.5f, 2.0f, -1.5f};
            if (m_in.u8() & 1) {
                data.left = m_in.value();
                data.top = m_in.value();
                data.right = m_in.value();
                data.bottom = m_in.value();
            }
            camera = OBJECT(Q3OrthographicCamera_New(nullData ? nullptr : &data));
            break;
        }
        case 1: {
            TQ3ViewPlaneCameraData data{readCameraData(), 10.0f, 2.0f, 1.5f, 0.0f, 0.0f};
            if (m_in.u8() & 1) {
                data.viewPlane = m_in.value();
                data.halfWidthAtViewPlane = m_in.value();
                data.halfHeightAtViewPlane = m_in.value();
                data.centerXOnViewPlane = m_in.value();
                data.centerYOnViewPlane = m_in.value();
            }
            camera = OBJECT(Q3ViewPlaneCamera_New(nullData ? nullptr : &data));
            break;
        }
        default: {
            TQ3ViewAngleAspectCameraData data{readCameraData(), 0.8f, 1.0f};
            if (m_in.u8() & 1) {
                data.fov = m_in.value();
                data.aspectRatioXToY = m_in.value();
            }
            camera = OBJECT(Q3ViewAngleAspectCamera_New(nullData ? nullptr : &data));
            break;
        }
        }
        if (camera != nullptr)
            hold(camera, Kind::kCamera);
    }

    void cameraEdit()
    {
        const TQ3Object camera = pick(Kind::kCamera);
        const bool nullArg = m_in.u8() == 0;
        TQ3CameraData data = readCameraData();
        TQ3Matrix4x4 matrix;
        switch (m_in.u8() % 10) {
        case 0: STATUS(Q3Camera_SetData(camera, nullArg ? nullptr : &data)); break;
        case 1: STATUS(Q3Camera_GetData(camera, nullArg ? nullptr : &data)); break;
        case 2: STATUS(Q3Camera_SetPlacement(camera, nullArg ? nullptr : &data.placement)); break;
        case 3: STATUS(Q3Camera_SetRange(camera, nullArg ? nullptr : &data.range)); break;
        case 4: STATUS(Q3Camera_SetViewPort(camera, nullArg ? nullptr : &data.viewPort)); break;
        case 5: STATUS(Q3Camera_GetWorldToFrustum(camera, nullArg ? nullptr : &matrix)); break;
        case 6: STATUS(Q3Camera_GetViewToFrustum(camera, nullArg ? nullptr : &matrix)); break;
        case 7: STATUS(Q3Camera_GetWorldToView(camera, nullArg ? nullptr : &matrix)); break;
        case 8: QUERY(Q3Camera_GetType(camera), TQ3ObjectType{kQ3ObjectTypeInvalid}); break;
        default: {
            TQ3ViewAngleAspectCameraData angle{data, m_in.value(), m_in.value()};
            STATUS(Q3ViewAngleAspectCamera_SetData(camera, nullArg ? nullptr : &angle));
            break;
        }
        }
    }

    // A pixmap over memory that lives until the end of the input and is as
    // large as the pixmap claims.
    TQ3Pixmap readPixmap()
    {
        TQ3Pixmap pixmap{};
        const std::uint8_t shape = m_in.u8();
        static const unsigned long kSizes[] = {32, 32, 16, 16, 16, 24};
        const std::int32_t type = enumValue(6);
        setRaw(pixmap.pixelType, type);
        const unsigned long bits = type >= 0 && type < 6 ? kSizes[type] : 32;
        pixmap.pixelSize = (shape & 1) ? m_in.u8() : bits;
        if (shape & 2) {
            // A wide strip, up to beyond what the renderer supports.
            pixmap.width = m_in.u16();
            pixmap.height = m_in.u8() % 3;
        } else {
            pixmap.width = m_in.u8() % 70;
            pixmap.height = m_in.u8() % 70;
        }
        pixmap.rowBytes = pixmap.width * ((bits + 7) / 8) + m_in.u8() % 8;
        if (shape & 4)
            pixmap.rowBytes = m_in.u16() % (pixmap.rowBytes + 1);
        setRaw(pixmap.byteOrder, enumValue(2));
        setRaw(pixmap.bitOrder, enumValue(2));
        const std::size_t bytes = std::max<std::size_t>(pixmap.rowBytes, pixmap.width * 4) *
                                      std::max<std::size_t>(pixmap.height, 1) + 8;
        m_images.push_back(std::make_unique<std::vector<unsigned char>>(bytes, 0x5A));
        pixmap.image = (shape & 8) ? nullptr : m_images.back()->data();
        return pixmap;
    }

    TQ3DrawContextData readDrawContextData()
    {
        TQ3DrawContextData data{};
        setRaw(data.clearImageMethod, enumValue(2));
        data.clearImageColor = {m_in.value(), m_in.value(), m_in.value(), m_in.value()};
        data.pane = {{m_in.value(), m_in.value()}, {m_in.value(), m_in.value()}};
        setRaw(data.paneState, enumValue(2));
        setRaw(data.maskState, enumValue(2));
        setRaw(data.doubleBufferState, enumValue(2));
        return data;
    }

    void newDrawContext()
    {
        if (m_drawContexts >= kMaxDrawContexts)
            return;
        ++m_drawContexts;
        TQ3PixmapDrawContextData data{};
        data.drawContextData = readDrawContextData();
        data.pixmap = readPixmap();
        const TQ3Object context = OBJECT(Q3PixmapDrawContext_New(m_in.u8() == 0 ? nullptr : &data));
        if (context != nullptr)
            hold(context, Kind::kDrawContext);
    }

    void drawContextEdit()
    {
        const TQ3Object context = pick(Kind::kDrawContext);
        const bool nullArg = m_in.u8() == 0;
        TQ3DrawContextData data = readDrawContextData();
        switch (m_in.u8() % 12) {
        case 0: STATUS(Q3DrawContext_SetData(context, nullArg ? nullptr : &data)); break;
        case 1: STATUS(Q3DrawContext_GetData(context, nullArg ? nullptr : &data)); break;
        case 2: STATUS(Q3DrawContext_SetClearImageColor(context, nullArg ? nullptr : &data.clearImageColor)); break;
        case 3: STATUS(Q3DrawContext_GetClearImageColor(context, nullArg ? nullptr : &data.clearImageColor)); break;
        case 4: STATUS(Q3DrawContext_SetPane(context, nullArg ? nullptr : &data.pane)); break;
        case 5: STATUS(Q3DrawContext_GetPane(context, nullArg ? nullptr : &data.pane)); break;
        case 6: STATUS(q3fuzz_SetPaneState(context, enumValue(2))); break;
        case 7: STATUS(Q3DrawContext_GetPaneState(context, nullArg ? nullptr : &data.paneState)); break;
        case 8: STATUS(q3fuzz_SetClearImageMethod(context, enumValue(2))); break;
        case 9: STATUS(Q3DrawContext_GetClearImageMethod(context, nullArg ? nullptr : &data.clearImageMethod)); break;
        case 10: {
            if (m_drawContexts >= kMaxDrawContexts)
                break;
            ++m_drawContexts;
            const TQ3Pixmap pixmap = readPixmap();
            STATUS(Q3PixmapDrawContext_SetPixmap(context, nullArg ? nullptr : &pixmap));
            break;
        }
        default: {
            TQ3Pixmap pixmap{};
            STATUS(Q3PixmapDrawContext_GetPixmap(context, nullArg ? nullptr : &pixmap));
            QUERY(Q3DrawContext_GetType(context), TQ3ObjectType{kQ3ObjectTypeInvalid});
            break;
        }
        }
    }

    TQ3ObjectType rendererType()
    {
        static const TQ3ObjectType kTypes[] = {kQ3RendererTypeInteractive, kQ3RendererTypeWireFrame,
                                               kQ3RendererTypeGeneric, kQ3ObjectTypeView, 0};
        const std::uint8_t which = m_in.u8();
        return which < 250 ? kTypes[which % 5] : TQ3ObjectType(static_cast<std::int32_t>(m_in.u32()));
    }

    void renderer()
    {
        if (m_in.u8() < 128) {
            const TQ3Object renderer = OBJECT(Q3Renderer_NewFromType(rendererType()));
            if (renderer != nullptr)
                hold(renderer, Kind::kRenderer);
            return;
        }
        const TQ3Object renderer = pick(Kind::kRenderer);
        const bool nullArg = m_in.u8() == 0;
        TQ3CSGEquation equation{};
        setRaw(equation, static_cast<std::int32_t>(m_in.u32()));
        long vendor = 0, engine = 0;
        TQ3Boolean bypass{};
        unsigned long value = 0;
        switch (m_in.u8() % 10) {
        case 0: STATUS(Q3InteractiveRenderer_SetCSGEquation(renderer, equation)); break;
        case 1: STATUS(Q3InteractiveRenderer_GetCSGEquation(renderer, nullArg ? nullptr : &equation)); break;
        case 2: STATUS(Q3InteractiveRenderer_SetPreferences(renderer, long(m_in.u32()), long(m_in.u32()))); break;
        case 3: STATUS(Q3InteractiveRenderer_GetPreferences(renderer, nullArg ? nullptr : &vendor, &engine)); break;
        case 4: STATUS(q3fuzz_SetDoubleBufferBypass(renderer, enumValue(2))); break;
        case 5: STATUS(Q3InteractiveRenderer_GetDoubleBufferBypass(renderer, nullArg ? nullptr : &bypass)); break;
        case 6: STATUS(Q3InteractiveRenderer_SetRAVEContextHints(renderer, m_in.u32())); break;
        case 7: STATUS(Q3InteractiveRenderer_GetRAVETextureFilter(renderer, nullArg ? nullptr : &value)); break;
        case 8: STATUS(Q3InteractiveRenderer_SetRAVETextureFilter(renderer, m_in.u32())); break;
        default: QUERY(Q3Renderer_GetType(renderer), TQ3ObjectType{kQ3ObjectTypeInvalid}); break;
        }
    }

    void newView()
    {
        if (m_views >= kMaxViews)
            return;
        ++m_views;
        const TQ3Object view = OBJECT(Q3View_New());
        if (view == nullptr)
            return;
        hold(view, Kind::kView);
        // Most views get everything they need at once.
        if (m_in.u8() < 200) {
            STATUS(Q3View_SetCamera(view, pick(Kind::kCamera)));
            STATUS(Q3View_SetDrawContext(view, pick(Kind::kDrawContext)));
            STATUS(Q3View_SetRendererByType(view, rendererType()));
        }
    }

    void viewSet()
    {
        const TQ3Object view = pick(Kind::kView);
        switch (m_in.u8() % 4) {
        case 0: STATUS(Q3View_SetCamera(view, pick(Kind::kCamera))); break;
        case 1: STATUS(Q3View_SetDrawContext(view, pick(Kind::kDrawContext))); break;
        case 2: STATUS(Q3View_SetRenderer(view, pick(Kind::kRenderer))); break;
        default: STATUS(Q3View_SetRendererByType(view, rendererType())); break;
        }
    }

    void viewGet()
    {
        const TQ3Object view = pick(Kind::kView);
        const bool nullOut = m_in.u8() == 0;
        TQ3Object got = nullptr;
        Kind kind = Kind::kCamera;
        TQ3Status status = kQ3Failure;
        switch (m_in.u8() % 3) {
        case 0:
            status = STATUS(Q3View_GetCamera(view, nullOut ? nullptr : &got));
            break;
        case 1:
            status = STATUS(Q3View_GetDrawContext(view, nullOut ? nullptr : &got));
            kind = Kind::kDrawContext;
            break;
        default:
            status = STATUS(Q3View_GetRenderer(view, nullOut ? nullptr : &got));
            kind = Kind::kRenderer;
            break;
        }
        if (status == kQ3Success && got != nullptr)
            hold(got, kind);
    }

    void startRendering()
    {
        const TQ3Object view = pick(Kind::kView);
        if (m_loops >= kMaxLoops)
            return;
        ++m_loops;
        STATUS(Q3View_StartRendering(view));
    }

    void startBounding()
    {
        const TQ3Object view = pick(Kind::kView);
        const int mode = enumValue(2);
        if (m_loops >= kMaxLoops)
            return;
        ++m_loops;
        if (m_in.u8() & 1)
            STATUS(q3fuzz_StartBoundingBox(view, mode));
        else
            STATUS(q3fuzz_StartBoundingSphere(view, mode));
    }

    void endBounding()
    {
        const TQ3Object view = pick(Kind::kView);
        const bool nullOut = m_in.u8() == 0;
        if (m_in.u8() & 1) {
            TQ3BoundingBox box;
            std::memset(&box, 0x5A, sizeof box);
            const TQ3BoundingBox untouched = box;
            const TQ3ViewStatus status = VIEWSTATUS(Q3View_EndBoundingBox(view, nullOut ? nullptr : &box));
            if (status == kQ3ViewStatusDone && !box.isEmpty) {
                const float* low = &box.min.x;
                const float* high = &box.max.x;
                for (int i = 0; i < 3; ++i)
                    require(low[i] <= high[i], "Q3View_EndBoundingBox", "gave a NaN or inverted box");
            } else if (status != kQ3ViewStatusDone) {
                require(sameBytes(box, untouched), "Q3View_EndBoundingBox", "wrote its result without finishing");
            }
        } else {
            TQ3BoundingSphere sphere;
            std::memset(&sphere, 0x5A, sizeof sphere);
            const TQ3ViewStatus status = VIEWSTATUS(Q3View_EndBoundingSphere(view, nullOut ? nullptr : &sphere));
            if (status == kQ3ViewStatusDone && !sphere.isEmpty)
                require(sphere.radius >= 0.0f, "Q3View_EndBoundingSphere", "gave a NaN or negative radius");
        }
    }

    void submitRetained()
    {
        const TQ3Object object = pick(Kind(m_in.u8() % kKindCount));
        const TQ3Object view = pick(Kind::kView);
        const Held* entry = heldEntry(object);
        if (entry != nullptr &&
            (entry->kind == Kind::kCurve || entry->kind == Kind::kPolyLine || isQuadric(entry->kind) ||
             entry->kind == Kind::kPatch) &&
            !drawAllowed())
            return;
        if (entry != nullptr && entry->kind == Kind::kGroup && (!drawAllowed() || !groupIsSmall(object)))
            return;
        const DrawTimer timer(m_drawSeconds);
        switch (m_in.u8() % 3) {
        case 0: STATUS(Q3Geometry_Submit(object, view)); break;
        case 1: STATUS(Q3Object_Submit(object, view)); break;
        default: STATUS(Q3AttributeSet_Submit(object, view)); break;
        }
    }

    void submitCurveImmediate()
    {
        CurveBuffers c;
        readCurve(c);
        const TQ3Object view = pick(Kind::kView);
        if (!drawAllowed())
            return;
        const DrawTimer timer(m_drawSeconds);
        STATUS(Q3NURBCurve_Submit(m_in.u8() == 0 ? nullptr : &c.data, view));
    }

    void submitStyleImmediate()
    {
        bool replaced = false;
        const TQ3SubdivisionStyleData data = readStyle(replaced);
        const TQ3Object view = pick(Kind::kView);
        const TQ3Status status = STATUS(Q3SubdivisionStyle_Submit(m_in.u8() == 0 ? nullptr : &data, view));
        checkStyle("Q3SubdivisionStyle_Submit", status, replaced);
        if (status == kQ3Success) {
            // Unless the loop was cancelled (then the style is ignored), the
            // view's state is now the substituted style.
            TQ3SubdivisionStyleData state{};
            STATUS(Q3View_GetSubdivisionStyleState(view, &state));
        }
    }

    void submitImmediate()
    {
        const TQ3Object view = pick(Kind::kView);
        const bool nullData = m_in.u8() == 0;
        switch (m_in.u8() % 8) {
        case 0: {
            const TQ3Matrix4x4 m = readMatrix();
            STATUS(Q3MatrixTransform_Submit(nullData ? nullptr : &m, view));
            break;
        }
        case 1: {
            const TQ3Vector3D v = vector3();
            STATUS(Q3TranslateTransform_Submit(nullData ? nullptr : &v, view));
            break;
        }
        case 2: {
            const TQ3Vector3D v = vector3();
            STATUS(Q3ScaleTransform_Submit(nullData ? nullptr : &v, view));
            break;
        }
        case 3: {
            TQ3RotateTransformData data{};
            setRaw(data.axis, enumValue(3));
            data.radians = m_in.value();
            STATUS(Q3RotateTransform_Submit(nullData ? nullptr : &data, view));
            break;
        }
        case 4:
            STATUS(Q3ResetTransform_Submit(view));
            break;
        case 5: {
            const TQ3PointData data{point3(), nullptr};
            STATUS(Q3Point_Submit(nullData ? nullptr : &data, view));
            break;
        }
        case 6: {
            const TQ3LineData data{{{point3(), nullptr}, {point3(), nullptr}}, nullptr};
            STATUS(Q3Line_Submit(nullData ? nullptr : &data, view));
            break;
        }
        default: {
            TQ3Vertex3D vertices[4] = {{point3(), nullptr}, {point3(), nullptr}, {point3(), nullptr},
                                       {point3(), nullptr}};
            TQ3PolyLineData data{1u + m_in.u8() % 4, vertices, nullptr, nullptr};
            STATUS(Q3PolyLine_Submit(nullData ? nullptr : &data, view));
            break;
        }
        }
    }

    void pushPop()
    {
        const TQ3Object view = pick(Kind::kView);
        if (m_in.u8() & 1)
            STATUS(Q3Push_Submit(view));
        else
            STATUS(Q3Pop_Submit(view));
    }

    void decompose()
    {
        const TQ3Object geometry = pick(Kind::kCurve);
        const TQ3Object view = pick(Kind::kView);
        if (!drawAllowed())
            return;
        checkDecomposition(geometry, view);
    }

    // Q3Geometry_GetDecomposed of any held object (or a bad handle): NULL
    // with an error, NULL silently for a primitive, or the right geometry of
    // the right size for each type.
    void checkDecomposition(TQ3Object geometry, TQ3Object view)
    {
        const DrawTimer timer(m_drawSeconds);
        begin();
        const TQ3Object polyline = Q3Geometry_GetDecomposed(geometry, view);
        const bool posted = Q3Error_Get(nullptr) != kQ3ErrorNone;
        checkPosted("Q3Geometry_GetDecomposed", posted);
        if (polyline == nullptr) {
            if (!posted) {
                const Held* entry = heldEntry(geometry);
                require(entry != nullptr && isPrimitiveKind(entry->kind),
                        "Q3Geometry_GetDecomposed", "returned NULL silently for something other than a primitive");
            }
            return;
        }
        const Held* entry = heldEntry(geometry);
        if (entry != nullptr && isQuadric(entry->kind)) {
            require(!posted, "Q3Geometry_GetDecomposed", "posted an error but decomposed");
            checkQuadricDecomposed(entry->kind, polyline);
            return;
        }
        if (entry != nullptr && entry->kind == Kind::kPatch) {
            require(!posted, "Q3Geometry_GetDecomposed", "posted an error but decomposed");
            checkPatchDecomposed(geometry, polyline);
            return;
        }
        if (holdsKind(geometry, Kind::kPolygon)) {
            // A polygon gives a TriMesh of at most numVertices - 2 triangles
            // over its own vertices.
            require(!posted && Q3Geometry_GetType(polyline) == kQ3GeometryTypeTriMesh, "Q3Geometry_GetDecomposed",
                    "a polygon did not give a trimesh");
            hold(polyline, Kind::kTriMesh);
            TQ3PolygonData polygon{};
            TQ3TriMeshData mesh{};
            STATUS(Q3Polygon_GetData(geometry, &polygon));
            STATUS(Q3TriMesh_GetData(polyline, &mesh));
            require(mesh.numPoints == polygon.numVertices && mesh.numTriangles + 2 <= polygon.numVertices,
                    "Q3Geometry_GetDecomposed", "a polygon's trimesh has the wrong size");
            STATUS(Q3Polygon_EmptyData(&polygon));
            STATUS(Q3TriMesh_EmptyData(&mesh));
            return;
        }
        if (holdsKind(geometry, Kind::kMesh)) {
            // A mesh gives a TriMesh (empty for a mesh without faces).
            require(!posted && Q3Geometry_GetType(polyline) == kQ3GeometryTypeTriMesh, "Q3Geometry_GetDecomposed",
                    "a mesh did not give a trimesh");
            hold(polyline, Kind::kTriMesh);
            return;
        }
        if (entry != nullptr && (entry->kind == Kind::kGeneralPolygon || entry->kind == Kind::kPolyhedron ||
                                 entry->kind == Kind::kTriGrid)) {
            checkPolygons2Decomposed(geometry, entry->kind, posted, polyline);
            return;
        }
        require(!posted && holdsKind(geometry, Kind::kCurve), "Q3Geometry_GetDecomposed",
                "decomposed something that is not a curve");
        hold(polyline, Kind::kPolyLine);
        TQ3PolyLineData data{};
        STATUS(Q3PolyLine_GetData(polyline, &data));
        require(data.numVertices >= 2 && data.numVertices <= (unsigned long)kQ3SubdivisionMaxSegmentsPerCurve + 1,
                "Q3Geometry_GetDecomposed", "the polyline's vertex count is outside 2 .. cap + 1");
        STATUS(Q3PolyLine_EmptyData(&data));
    }

    // A general polygon gives a trimesh over its own vertices with at most
    // vertices + 2 contours - 2 triangles; a grid one of three vertices per
    // facet; a polyhedron three per triangle and two per listed edge.
    void checkPolygons2Decomposed(TQ3Object geometry, Kind kind, bool posted, TQ3Object result)
    {
        const char* call = "Q3Geometry_GetDecomposed";
        require(!posted && Q3Geometry_GetType(result) == kQ3GeometryTypeTriMesh, call, "gave no trimesh");
        hold(result, Kind::kTriMesh);
        TQ3TriMeshData mesh{};
        STATUS(Q3TriMesh_GetData(result, &mesh));
        if (kind == Kind::kGeneralPolygon) {
            TQ3GeneralPolygonData data{};
            STATUS(Q3GeneralPolygon_GetData(geometry, &data));
            unsigned long total = 0;
            for (unsigned long c = 0; c < data.numContours; ++c)
                total += data.contours[c].numVertices;
            require(mesh.numPoints == total && mesh.numTriangles + 2 <= total + 2 * data.numContours, call,
                    "a general polygon's trimesh has the wrong size");
            STATUS(Q3GeneralPolygon_EmptyData(&data));
        } else if (kind == Kind::kTriGrid) {
            TQ3TriGridData data{};
            STATUS(Q3TriGrid_GetData(geometry, &data));
            const unsigned long facets = 2 * (data.numRows - 1) * (data.numColumns - 1);
            require(mesh.numTriangles == facets && mesh.numPoints == 3 * facets, call,
                    "a grid's trimesh has the wrong size");
            STATUS(Q3TriGrid_EmptyData(&data));
        } else {
            TQ3PolyhedronData data{};
            STATUS(Q3Polyhedron_GetData(geometry, &data));
            require(mesh.numTriangles == data.numTriangles &&
                        mesh.numPoints == 3 * data.numTriangles + 2 * data.numEdges,
                    call, "a polyhedron's trimesh has the wrong size");
            STATUS(Q3Polyhedron_EmptyData(&data));
        }
        STATUS(Q3TriMesh_EmptyData(&mesh));
    }

    void viewState()
    {
        const TQ3Object view = pick(Kind::kView);
        const bool nullOut = m_in.u8() == 0;
        if (m_in.u8() & 1) {
            TQ3Matrix4x4 m;
            STATUS(Q3View_GetLocalToWorldMatrixState(view, nullOut ? nullptr : &m));
        } else {
            TQ3SubdivisionStyleData style;
            STATUS(Q3View_GetSubdivisionStyleState(view, nullOut ? nullptr : &style));
        }
    }

    void cancelSync()
    {
        const TQ3Object view = pick(Kind::kView);
        if (m_in.u8() & 1)
            STATUS(Q3View_Cancel(view));
        else
            STATUS(Q3View_Sync(view));
    }

    void objectQueries()
    {
        const TQ3Object object = pick(Kind(m_in.u8() % kKindCount));
        constexpr TQ3ObjectType kInvalid = kQ3ObjectTypeInvalid;
        switch (m_in.u8() % 11) {
        case 0: QUERY(Q3Object_GetType(object), kInvalid); break;
        case 1: QUERY(Q3Object_GetLeafType(object), kInvalid); break;
        case 2: QUERY(Q3Object_IsType(object, TQ3ObjectType(static_cast<std::int32_t>(m_in.u32()))), kQ3False); break;
        case 3: QUERY(Q3Object_IsDrawable(object), kQ3False); break;
        case 4: QUERY(Q3Shared_GetType(object), kInvalid); break;
        case 5: QUERY(Q3Shared_IsReferenced(object), kQ3False); break;
        case 6: QUERY(Q3Shared_GetEditIndex(object), 0UL); break;
        case 7: STATUS(Q3Shared_Edited(object)); break;
        case 8: QUERY(Q3Shape_GetType(object), kInvalid); break;
        case 9: QUERY(Q3Geometry_GetType(object), kInvalid); break;
        default: QUERY(Q3Camera_GetType(object), kInvalid); break;
        }
    }

    void initializeExit()
    {
        if (m_in.u8() & 1) {
            if (m_initialized >= 3)
                return;
            begin();
            Q3Initialize();
            require(g_posts.errors == 0, "Q3Initialize", "posted an error");
            require((g_posts.notices == 1) == (m_initialized > 0), "Q3Initialize", "the nesting notice is wrong");
            ++m_initialized;
            return;
        }
        const TQ3Status status = STATUS(Q3Exit());
        require((status == kQ3Success) == (m_initialized > 0), "Q3Exit", "disagrees about being initialized");
        if (m_initialized > 0)
            --m_initialized;
    }

    // ---- Groups -----------------------------------------------------------

    // Reads a group without the checking macros (for the fuzzer's own
    // bookkeeping); the posts it causes are forgotten.
    std::vector<TQ3Object> objectsOf(TQ3Object group)
    {
        const Posts saved = g_posts;
        std::vector<TQ3Object> objects;
        TQ3GroupPosition position = nullptr;
        if (Q3Object_IsType(group, kQ3ShapeTypeGroup) == kQ3True)
            Q3Group_GetFirstPosition(group, &position);
        while (position != nullptr && objects.size() <= kMaxGroupReach) {
            TQ3Object object = nullptr;
            if (Q3Group_GetPositionObject(group, position, &object) != kQ3Success)
                break;
            objects.push_back(object);
            Q3Object_Dispose(object);
            if (Q3Group_GetNextPosition(group, &position) != kQ3Success)
                break;
        }
        g_posts = saved;
        return objects;
    }

    // Whether a traversal of the group meets at most kMaxGroupReach objects,
    // and at most one curve or polyline (each may draw 2^20 segments).
    bool groupIsSmall(TQ3Object group)
    {
        unsigned long met = 0, lines = 0;
        std::vector<TQ3Object> pending{group};
        while (!pending.empty()) {
            const TQ3Object current = pending.back();
            pending.pop_back();
            for (TQ3Object object : objectsOf(current)) {
                if (++met > kMaxGroupReach)
                    return false;
                const Posts saved = g_posts;
                if (Q3Object_IsType(object, kQ3ShapeTypeGroup) == kQ3True)
                    pending.push_back(object);
                else if (Q3Object_IsType(object, kQ3GeometryTypeNURBCurve) == kQ3True ||
                         Q3Object_IsType(object, kQ3GeometryTypePolyLine) == kQ3True)
                    ++lines;
                g_posts = saved;
                if (lines > 1)
                    return false;
            }
        }
        return true;
    }

    // A position of the group (one of its own, walked to), or a bad one.
    TQ3GroupPosition positionIn(TQ3Object group)
    {
        const std::uint8_t how = m_in.u8();
        if (how < 200 && holdsKind(group, Kind::kGroup)) {
            TQ3GroupPosition position = nullptr;
            const Posts saved = g_posts;
            Q3Group_GetFirstPosition(group, &position);
            for (int steps = m_in.u8() % 16; steps > 0 && position != nullptr; --steps) {
                TQ3GroupPosition next = position;
                Q3Group_GetNextPosition(group, &next);
                if (next == nullptr)
                    break;
                position = next;
            }
            g_posts = saved;
            if (position != nullptr && m_positions.size() < 64)
                m_positions.push_back(position);
            return position;
        }
        if (how < 230 && !m_positions.empty())
            return m_positions[m_in.u8() % m_positions.size()]; // perhaps removed, perhaps another group's
        if (how < 245)
            return nullptr;
        static unsigned char neverAPosition[32];
        return reinterpret_cast<TQ3GroupPosition>(neverAPosition + 8 * (m_in.u8() % 4));
    }

    TQ3ObjectType typeToCount()
    {
        static const TQ3ObjectType kTypes[] = {kQ3ObjectTypeInvalid,  kQ3ShapeTypeGeometry,    kQ3GeometryTypePoint,
                                               kQ3ShapeTypeTransform, kQ3ShapeTypeStyle,       kQ3SetTypeAttribute,
                                               kQ3ShapeTypeGroup,     kQ3GroupTypeDisplay,     kQ3SharedTypeShape,
                                               kQ3ShapeTypeLight,     kQ3ShapeTypeStateOperator};
        const std::uint8_t which = m_in.u8();
        return which < 250 ? kTypes[which % 11] : TQ3ObjectType(m_in.u32());
    }

    // The group's invariants seen through the API: walking forwards and
    // backwards meets the same objects, as many as Q3Group_CountObjects says.
    void checkGroup(TQ3Object group)
    {
        if (!holdsKind(group, Kind::kGroup) || Q3Object_IsType(group, kQ3ShapeTypeGroup) != kQ3True)
            return;
        const std::vector<TQ3Object> forward = objectsOf(group);
        if (forward.size() > kMaxGroupReach)
            return;
        std::vector<TQ3Object> backward;
        TQ3GroupPosition position = nullptr;
        STATUS(Q3Group_GetLastPosition(group, &position));
        while (position != nullptr) {
            TQ3Object object = nullptr;
            STATUS(Q3Group_GetPositionObject(group, position, &object));
            backward.insert(backward.begin(), object);
            STATUS(Q3Object_Dispose(object));
            STATUS(Q3Group_GetPreviousPosition(group, &position));
        }
        unsigned long count = 0;
        STATUS(Q3Group_CountObjects(group, &count));
        require(forward == backward && count == forward.size(), "Q3Group_GetNextPosition",
                "walking forwards and backwards and counting disagree");
        const TQ3ObjectType type = typeToCount();
        unsigned long ofType = 0, walked = 0;
        if (STATUS(Q3Group_CountObjectsOfType(group, type, &ofType)) == kQ3Success) {
            STATUS(Q3Group_GetFirstPositionOfType(group, type, &position));
            while (position != nullptr && walked <= count) {
                ++walked;
                STATUS(Q3Group_GetNextPositionOfType(group, type, &position));
            }
            require(walked == ofType, "Q3Group_CountObjectsOfType", "disagrees with walking that type");
        }
    }

    void groups()
    {
        const std::uint8_t action = m_in.u8() % 10;
        const TQ3Object group = pick(Kind::kGroup);
        switch (action) {
        case 0: {
            TQ3Object made = nullptr;
            switch (m_in.u8() % 8) {
            case 0: made = OBJECT(Q3Group_New()); break;
            case 1: made = OBJECT(Q3DisplayGroup_New()); break;
            case 2: made = OBJECT(Q3OrderedDisplayGroup_New()); break;
            case 3: made = OBJECT(Q3IOProxyDisplayGroup_New()); break;
            case 4: made = OBJECT(Q3LightGroup_New()); break;
            case 5: made = OBJECT(Q3InfoGroup_New()); break;
            case 6: made = OBJECT(Q3Push_New()); break;
            default: made = OBJECT(Q3Pop_New()); break;
            }
            if (made != nullptr)
                hold(made, Kind::kGroup);
            break;
        }
        case 1: {
            const TQ3Object object = pick(Kind(m_in.u8() % kKindCount));
            const std::uint8_t where = m_in.u8() % 3;
            const TQ3GroupPosition position = where == 0 ? nullptr : positionIn(group);
            if (holdsKind(group, Kind::kGroup) && objectsOf(group).size() >= kMaxGroupSize)
                return;
            TQ3GroupPosition added = nullptr;
            if (where == 0)
                added = POINTER(Q3Group_AddObject(group, object));
            else if (where == 1)
                added = POINTER(Q3Group_AddObjectBefore(group, position, object));
            else
                added = POINTER(Q3Group_AddObjectAfter(group, position, object));
            require(added == nullptr || object != group, "Q3Group_AddObject", "a group took itself");
            checkGroup(group);
            break;
        }
        case 2: {
            const TQ3GroupPosition position = positionIn(group);
            const TQ3Object object = pick(Kind(m_in.u8() % kKindCount));
            const TQ3Status status = STATUS(Q3Group_SetPositionObject(group, position, object));
            require(status == kQ3Failure || object != group, "Q3Group_SetPositionObject", "a group took itself");
            checkGroup(group);
            break;
        }
        case 3: {
            // Remove positions while walking: every `stride`-th, taking the
            // next position first (as the header says to).
            const unsigned stride = 1 + m_in.u8() % 4;
            if (!holdsKind(group, Kind::kGroup)) {
                const TQ3Object removed = OBJECT(Q3Group_RemovePosition(group, positionIn(group)));
                if (removed != nullptr)
                    STATUS(Q3Object_Dispose(removed));
            }
            TQ3GroupPosition position = nullptr;
            if (holdsKind(group, Kind::kGroup) && STATUS(Q3Group_GetFirstPosition(group, &position)) == kQ3Success)
                for (unsigned index = 0; position != nullptr; ++index) {
                    TQ3GroupPosition next = position;
                    STATUS(Q3Group_GetNextPosition(group, &next));
                    if (index % stride == 0) {
                        const TQ3Object removed = OBJECT(Q3Group_RemovePosition(group, position));
                        if (removed != nullptr)
                            STATUS(Q3Object_Dispose(removed));
                    }
                    position = next;
                }
            checkGroup(group);
            break;
        }
        case 4: checkGroup(group); break;
        case 5: {
            const TQ3ObjectType type = typeToCount();
            if (m_in.u8() & 1)
                STATUS(Q3Group_EmptyObjectsOfType(group, type));
            else
                STATUS(Q3Group_EmptyObjects(group));
            checkGroup(group);
            break;
        }
        case 6: {
            TQ3DisplayGroupState state = 0;
            const std::uint8_t which = m_in.u8() % 5;
            TQ3BoundingBox box{point3(), point3(), (m_in.u8() & 1) ? kQ3True : kQ3False};
            if (which == 0)
                STATUS(Q3DisplayGroup_SetState(group, m_in.u8()));
            else if (which == 1)
                STATUS(Q3DisplayGroup_GetState(group, &state));
            else if (which == 2)
                STATUS(Q3DisplayGroup_SetAndUseBoundingBox(group, &box));
            else if (which == 3)
                STATUS(Q3DisplayGroup_GetBoundingBox(group, &box));
            else
                STATUS(Q3DisplayGroup_RemoveBoundingBox(group));
            break;
        }
        case 7: {
            const TQ3Object view = pick(Kind::kView);
            if (!groupIsSmall(group) || !drawAllowed())
                return;
            const DrawTimer timer(m_drawSeconds);
            if (m_in.u8() & 1)
                STATUS(Q3DisplayGroup_Submit(group, view));
            else
                STATUS(Q3StateOperator_Submit(group, view));
            break;
        }
        case 8: {
            const TQ3Object view = pick(Kind::kView);
            // Through C: any int, a value outside TQ3ComputeBounds included
            // (which C++ may not even hold in the enum).
            const int bounds = enumValue(2);
            if (!groupIsSmall(group) || !drawAllowed())
                return;
            const DrawTimer timer(m_drawSeconds);
            STATUS(q3fuzz_CalcAndUseBoundingBox(group, bounds, view));
            break;
        }
        default: {
            // Every position of one object, forwards or backwards.
            const TQ3Object object = pick(Kind(m_in.u8() % kKindCount));
            const bool forwards = m_in.u8() & 1;
            TQ3GroupPosition position = nullptr;
            TQ3Status status = forwards ? STATUS(Q3Group_GetFirstObjectPosition(group, object, &position))
                                        : STATUS(Q3Group_GetLastObjectPosition(group, object, &position));
            for (unsigned long n = 0; status == kQ3Success && position != nullptr; ++n) {
                require(n <= kMaxGroupReach, "Q3Group_GetNextObjectPosition", "walked more positions than objects");
                TQ3Object there = nullptr;
                STATUS(Q3Group_GetPositionObject(group, position, &there));
                require(there == object, "Q3Group_GetFirstObjectPosition", "a position of another object");
                STATUS(Q3Object_Dispose(there));
                status = forwards ? STATUS(Q3Group_GetNextObjectPosition(group, object, &position))
                                  : STATUS(Q3Group_GetPreviousObjectPosition(group, object, &position));
            }
            break;
        }
        }
    }

    void finish()
    {
        while (m_initialized == 0) {
            begin();
            Q3Initialize();
            ++m_initialized;
        }
        while (!m_held.empty()) {
            const TQ3Object object = m_held.back().handle;
            if (STATUS(Q3Object_Dispose(object)) != kQ3Success)
                die("Q3Object_Dispose", "failed to release a held reference at the end");
            m_held.pop_back();
        }
        require(Q3Memory_CountLiveObjects() == 0, "end of input", "objects are still alive: a leak");
        for (; m_initialized > 0; --m_initialized) {
            if (STATUS(Q3Exit()) != kQ3Success)
                die("Q3Exit", "failed");
            require(g_posts.warnings == 0, "Q3Exit", "warned at the end of a leak-free input");
        }
    }

    // ---- Meshes ------------------------------------------------------------
    //
    // Builds, edits and walks meshes with parts of this mesh, of other
    // meshes, deleted ones and made-up handle values. Besides the error
    // contract: a failed edit changes neither the counts nor the edit index;
    // a successful one changes the counts as QD3DGeometry.h says; the mesh
    // walks give each part once and as many as the counts; the components'
    // vertices never outnumber the mesh's.

    struct MeshCounts {
        unsigned long vertices = 0, faces = 0, edges = 0, components = 0, corners = 0;
        bool operator==(const MeshCounts& o) const
        {
            return vertices == o.vertices && faces == o.faces && edges == o.edges && components == o.components &&
                   corners == o.corners;
        }
    };

    bool meshCounts(TQ3Object mesh, MeshCounts& c)
    {
        return STATUS(Q3Mesh_GetNumVertices(mesh, &c.vertices)) == kQ3Success &&
               STATUS(Q3Mesh_GetNumFaces(mesh, &c.faces)) == kQ3Success &&
               STATUS(Q3Mesh_GetNumEdges(mesh, &c.edges)) == kQ3Success &&
               STATUS(Q3Mesh_GetNumComponents(mesh, &c.components)) == kQ3Success &&
               STATUS(Q3Mesh_GetNumCorners(mesh, &c.corners)) == kQ3Success;
    }

    // A part handle: one this fuzzer saw (maybe deleted since, maybe of
    // another mesh), or a made-up value.
    void* meshPart()
    {
        const std::uint8_t how = m_in.u8();
        if (how < 200 && !m_meshParts.empty())
            return m_meshParts[m_in.u8() % m_meshParts.size()];
        if (how < 220)
            return nullptr;
        return reinterpret_cast<void*>(static_cast<std::uintptr_t>(m_in.u32()));
    }

    void rememberPart(void* part)
    {
        if (part == nullptr)
            return;
        if (m_meshParts.size() < kMaxMeshParts)
            m_meshParts.push_back(part);
        else
            m_meshParts[m_in.u8() % kMaxMeshParts] = part;
    }

    // Every part of the mesh of one kind through its walk: each once, as
    // many as counted.
    template <class Handle>
    void checkMeshWalk(TQ3Object mesh, Handle (*first)(TQ3GeometryObject, TQ3MeshIterator*),
                       Handle (*next)(TQ3MeshIterator*), unsigned long expected, const char* call)
    {
        std::set<Handle> seen;
        TQ3MeshIterator it;
        for (Handle h = QUERY(first(mesh, &it), Handle(nullptr)); h != nullptr; h = QUERY(next(&it), Handle(nullptr))) {
            require(seen.insert(h).second, call, "gave a part twice");
            require(seen.size() <= expected, call, "gave more parts than the mesh has");
            rememberPart(h);
        }
        require(seen.size() == expected, call, "gave fewer parts than the mesh has");
    }

    void meshes()
    {
        const std::uint8_t action = m_in.u8() % 8;
        if (action == 0) {
            if (m_meshes < kMaxMeshes) {
                ++m_meshes;
                if (const TQ3Object mesh = OBJECT(Q3Mesh_New()))
                    hold(mesh, Kind::kMesh);
            }
            return;
        }
        const TQ3Object mesh = pick(Kind::kMesh);
        const bool ours = holdsKind(mesh, Kind::kMesh) && m_initialized > 0;
        MeshCounts before;
        const bool counted = ours && meshCounts(mesh, before);
        const unsigned long edit = ours ? editIndex(mesh) : 0;
        bool failed = true;
        const char* call = "Q3Mesh edit";
        switch (action) {
        case 1: {
            call = "Q3Mesh_VertexNew";
            TQ3Vertex3D v{{m_in.value(), m_in.value(), m_in.value()}, nullptr};
            if (m_in.u8() & 1)
                v.attributeSet = pick(Kind::kAttributeSet);
            const bool vertexNull = m_in.u8() == 0;
            if (before.vertices >= kMaxMeshVertices)
                return;
            void* made = POINTER(Q3Mesh_VertexNew(mesh, vertexNull ? nullptr : &v));
            failed = made == nullptr;
            rememberPart(made);
            if (!failed) {
                before.vertices++;
                require(std::isfinite(v.point.x) && std::isfinite(v.point.y) && std::isfinite(v.point.z), call,
                        "accepted a point that is not finite");
            }
            break;
        }
        case 2: {
            call = "Q3Mesh_FaceNew";
            std::vector<TQ3MeshVertex> ring(3 + m_in.u8() % 6);
            const std::uint8_t source = m_in.u8();
            // Mostly the mesh's own vertices, walked; else remembered parts.
            std::vector<TQ3MeshVertex> own;
            if (ours) {
                TQ3MeshIterator it;
                for (TQ3MeshVertex v = QUERY(Q3Mesh_FirstMeshVertex(mesh, &it), TQ3MeshVertex(nullptr));
                     v != nullptr && own.size() < 64; v = QUERY(Q3Mesh_NextMeshVertex(&it), TQ3MeshVertex(nullptr)))
                    own.push_back(v);
            }
            for (TQ3MeshVertex& v : ring)
                v = source < 200 && !own.empty() ? own[m_in.u8() % own.size()]
                                                 : static_cast<TQ3MeshVertex>(meshPart());
            const unsigned long claimed = (m_in.u8() == 0) ? 2 : static_cast<unsigned long>(ring.size());
            TQ3AttributeSet set = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
            void* made = POINTER(Q3Mesh_FaceNew(mesh, claimed, ring.data(), set));
            failed = made == nullptr;
            rememberPart(made);
            if (!failed) {
                // A ring that names a vertex twice is kept, as QuickDraw 3D
                // and Quesa keep it (docs/3dmf.md, "Tolerances"); fewer
                // than three vertices is refused.
                before.faces++;
                require(claimed >= 3, call, "accepted a bad vertex list");
            }
            break;
        }
        case 3: {
            void* part = meshPart();
            if (m_in.u8() & 1) {
                call = "Q3Mesh_VertexDelete";
                failed = STATUS(Q3Mesh_VertexDelete(mesh, static_cast<TQ3MeshVertex>(part))) == kQ3Failure;
            } else {
                call = "Q3Mesh_FaceDelete";
                failed = STATUS(Q3Mesh_FaceDelete(mesh, static_cast<TQ3MeshFace>(part))) == kQ3Failure;
                if (!failed)
                    before.faces--;
            }
            break;
        }
        case 4: {
            void* a = meshPart();
            void* b = meshPart();
            void* made = nullptr;
            if (m_in.u8() & 1) {
                call = "Q3Mesh_FaceToContour";
                made = POINTER(Q3Mesh_FaceToContour(mesh, static_cast<TQ3MeshFace>(a), static_cast<TQ3MeshFace>(b)));
                if (made != nullptr) {
                    require(a != b, call, "made a face a contour of itself");
                    before.faces--;
                }
            } else {
                call = "Q3Mesh_ContourToFace";
                made = POINTER(Q3Mesh_ContourToFace(mesh, static_cast<TQ3MeshContour>(a)));
            }
            failed = made == nullptr;
            rememberPart(made);
            break;
        }
        case 5: {
            void* part = meshPart();
            TQ3AttributeSet set = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
            switch (m_in.u8() % 5) {
            case 0:
                call = "Q3Mesh_SetVertexAttributeSet";
                failed = STATUS(Q3Mesh_SetVertexAttributeSet(mesh, static_cast<TQ3MeshVertex>(part), set)) ==
                         kQ3Failure;
                break;
            case 1:
                call = "Q3Mesh_SetFaceAttributeSet";
                failed = STATUS(Q3Mesh_SetFaceAttributeSet(mesh, static_cast<TQ3MeshFace>(part), set)) == kQ3Failure;
                break;
            case 2:
                call = "Q3Mesh_SetEdgeAttributeSet";
                failed = STATUS(Q3Mesh_SetEdgeAttributeSet(mesh, static_cast<TQ3MeshEdge>(part), set)) == kQ3Failure;
                break;
            case 3: {
                call = "Q3Mesh_SetCornerAttributeSet";
                void* face = meshPart();
                failed = STATUS(Q3Mesh_SetCornerAttributeSet(mesh, static_cast<TQ3MeshVertex>(part),
                                                             static_cast<TQ3MeshFace>(face), set)) == kQ3Failure;
                break;
            }
            default: {
                call = "Q3Mesh_SetVertexCoordinates";
                const TQ3Point3D p{m_in.value(), m_in.value(), m_in.value()};
                failed = STATUS(Q3Mesh_SetVertexCoordinates(mesh, static_cast<TQ3MeshVertex>(part), &p)) ==
                         kQ3Failure;
                if (!failed)
                    require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), call,
                            "accepted a point that is not finite");
            }
            }
            break;
        }
        case 6: {
            // A walk around a part, bounded: each Next obeys the contract.
            void* part = meshPart();
            TQ3MeshIterator it;
            void* h = nullptr;
            const std::uint8_t which = m_in.u8() % 13;
            switch (which) {
            case 0: h = QUERY(Q3Mesh_FirstComponentVertex(static_cast<TQ3MeshComponent>(part), &it), TQ3MeshVertex(nullptr)); break;
            case 1: h = QUERY(Q3Mesh_FirstComponentEdge(static_cast<TQ3MeshComponent>(part), &it), TQ3MeshEdge(nullptr)); break;
            case 2: h = QUERY(Q3Mesh_FirstVertexEdge(static_cast<TQ3MeshVertex>(part), &it), TQ3MeshEdge(nullptr)); break;
            case 3: h = QUERY(Q3Mesh_FirstVertexVertex(static_cast<TQ3MeshVertex>(part), &it), TQ3MeshVertex(nullptr)); break;
            case 4: h = QUERY(Q3Mesh_FirstVertexFace(static_cast<TQ3MeshVertex>(part), &it), TQ3MeshFace(nullptr)); break;
            case 5: h = QUERY(Q3Mesh_FirstFaceEdge(static_cast<TQ3MeshFace>(part), &it), TQ3MeshEdge(nullptr)); break;
            case 6: h = QUERY(Q3Mesh_FirstFaceVertex(static_cast<TQ3MeshFace>(part), &it), TQ3MeshVertex(nullptr)); break;
            case 7: h = QUERY(Q3Mesh_FirstFaceFace(static_cast<TQ3MeshFace>(part), &it), TQ3MeshFace(nullptr)); break;
            case 8: h = QUERY(Q3Mesh_FirstFaceContour(static_cast<TQ3MeshFace>(part), &it), TQ3MeshContour(nullptr)); break;
            case 9: h = QUERY(Q3Mesh_FirstContourEdge(static_cast<TQ3MeshContour>(part), &it), TQ3MeshEdge(nullptr)); break;
            case 10: h = QUERY(Q3Mesh_FirstContourVertex(static_cast<TQ3MeshContour>(part), &it), TQ3MeshVertex(nullptr)); break;
            case 11: h = QUERY(Q3Mesh_FirstContourFace(static_cast<TQ3MeshContour>(part), &it), TQ3MeshFace(nullptr)); break;
            default: h = QUERY(Q3Mesh_FirstMeshComponent(mesh, &it), TQ3MeshComponent(nullptr)); break;
            }
            for (int step = 0; h != nullptr && step < 4096; ++step) {
                rememberPart(h);
                switch (which) {
                case 0: h = QUERY(Q3Mesh_NextComponentVertex(&it), TQ3MeshVertex(nullptr)); break;
                case 1: h = QUERY(Q3Mesh_NextComponentEdge(&it), TQ3MeshEdge(nullptr)); break;
                case 2: h = QUERY(Q3Mesh_NextVertexEdge(&it), TQ3MeshEdge(nullptr)); break;
                case 3: h = QUERY(Q3Mesh_NextVertexVertex(&it), TQ3MeshVertex(nullptr)); break;
                case 4: h = QUERY(Q3Mesh_NextVertexFace(&it), TQ3MeshFace(nullptr)); break;
                case 5: h = QUERY(Q3Mesh_NextFaceEdge(&it), TQ3MeshEdge(nullptr)); break;
                case 6: h = QUERY(Q3Mesh_NextFaceVertex(&it), TQ3MeshVertex(nullptr)); break;
                case 7: h = QUERY(Q3Mesh_NextFaceFace(&it), TQ3MeshFace(nullptr)); break;
                case 8: h = QUERY(Q3Mesh_NextFaceContour(&it), TQ3MeshContour(nullptr)); break;
                case 9: h = QUERY(Q3Mesh_NextContourEdge(&it), TQ3MeshEdge(nullptr)); break;
                case 10: h = QUERY(Q3Mesh_NextContourVertex(&it), TQ3MeshVertex(nullptr)); break;
                case 11: h = QUERY(Q3Mesh_NextContourFace(&it), TQ3MeshFace(nullptr)); break;
                default: h = QUERY(Q3Mesh_NextMeshComponent(&it), TQ3MeshComponent(nullptr)); break;
                }
            }
            return;
        }
        default: {
            // The walks against the counts; the components' vertices.
            if (!counted)
                return;
            checkMeshWalk(mesh, Q3Mesh_FirstMeshVertex, Q3Mesh_NextMeshVertex, before.vertices, "Q3Mesh_NextMeshVertex");
            checkMeshWalk(mesh, Q3Mesh_FirstMeshFace, Q3Mesh_NextMeshFace, before.faces, "Q3Mesh_NextMeshFace");
            checkMeshWalk(mesh, Q3Mesh_FirstMeshEdge, Q3Mesh_NextMeshEdge, before.edges, "Q3Mesh_NextMeshEdge");
            checkMeshWalk(mesh, Q3Mesh_FirstMeshComponent, Q3Mesh_NextMeshComponent, before.components,
                          "Q3Mesh_NextMeshComponent");
            unsigned long inComponents = 0;
            TQ3MeshIterator it;
            for (TQ3MeshComponent c = QUERY(Q3Mesh_FirstMeshComponent(mesh, &it), TQ3MeshComponent(nullptr));
                 c != nullptr; c = QUERY(Q3Mesh_NextMeshComponent(&it), TQ3MeshComponent(nullptr))) {
                unsigned long n = 0;
                STATUS(Q3Mesh_GetComponentNumVertices(mesh, c, &n));
                inComponents += n;
            }
            require(inComponents <= before.vertices, "Q3Mesh_GetComponentNumVertices",
                    "components hold more vertices than the mesh");
            return;
        }
        }
        if (!counted)
            return;
        MeshCounts after;
        require(meshCounts(mesh, after), call, "a mesh's counts could not be read");
        if (failed) {
            require(after == before && editIndex(mesh) == edit, call, "failed but changed the mesh");
        } else if (action == 1 || action == 2) {
            require(after.vertices == before.vertices && after.faces == before.faces, call,
                    "did not add exactly one part");
        } else if (action == 3 || action == 4) {
            require(after.faces <= before.faces + 1, call, "deleted or moved but gained faces");
        }
    }

    Reader& m_in;
    int m_initialized = 0;
    std::vector<Held> m_held;
    std::vector<TQ3Object> m_stale;
    std::vector<void*> m_meshParts;
    std::vector<TQ3ControllerRef> m_controllers;
    int m_notAController = 0;
    int m_meshes = 0;
    std::vector<TQ3GroupPosition> m_positions;
    std::map<TQ3Object, CurveShape> m_curves;
    std::vector<std::unique_ptr<std::vector<unsigned char>>> m_images;
    unsigned long m_pointBudget = kPointBudget;
    int m_curveDraws = 0;
    double m_drawSeconds = 0.0;
    int m_duplicates = 0;
    int m_views = 0;
    int m_loops = 0;
    int m_drawContexts = 0;
    TQ3SubdivisionStyleData m_expectedStyle{};
    bool m_styleValid = false;
};

} // namespace
} // namespace q3fuzz

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    q3fuzz::g_trace = std::getenv("Q3_FUZZ_TRACE") != nullptr;
    Q3Error_Register(&q3fuzz::onError, 0);
    Q3Warning_Register(&q3fuzz::onWarning, 0);
    Q3Notice_Register(&q3fuzz::onNotice, 0);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    q3fuzz::Reader in(data, size);
    q3fuzz::Session(in).run();
    return 0;
}
