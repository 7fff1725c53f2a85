// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The API fuzzer's session (ApiFuzzer.cpp says what it checks): the
// contract checks every family shares, the bounds on one input's work,
// and the Session class, whose operations are defined per family in
// Fuzz<Family>.cpp.

#include "CCaller.h"
#include "FuzzData.h"
#include "FuzzInput.h"

#include "Q3NURBCurveTools.h"
#include "QD3D.h"
#include "QD3DCamera.h"
#include "QD3DController.h"
#include "QD3DCustomElements.h"
#include "QD3DDrawContext.h"
#include "QD3DErrors.h"
#include "QD3DExtension.h"
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

// Bounds on the work one input may ask for.
constexpr unsigned long kPointBudget = 4096;    // control points over all curve data built
constexpr int kMaxCurveDraws = 12;              // curve and polyline submits and decompositions
constexpr double kDrawSeconds = 2.0;            // then no more of them (one may take far longer: run.sh)
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
inline Posts g_posts;
// Q3_FUZZ_TRACE=1 prints each operation, for checking what a seed decodes to.
inline bool g_trace = false;
// How many times a controller notify function ran (they only count).
inline unsigned long g_controllerNotifications = 0;

inline void onError(TQ3Error, TQ3Error, long) { ++g_posts.errors; }
inline void onWarning(TQ3Warning, TQ3Warning last, long)
{
    ++g_posts.warnings;
    g_posts.lastWarning = last;
}
inline void onNotice(TQ3Notice, TQ3Notice, long) { ++g_posts.notices; }

[[noreturn]] inline void die(const char* call, const char* why)
{
    std::fprintf(stderr, "q3 fuzz: %s: %s (Q3Error_Get %d, message \"%s\")\n", call, why,
                 int(Q3Error_Get(nullptr)), Q3Error_GetMessage());
    std::abort();
}

inline void require(bool condition, const char* call, const char* why)
{
    if (!condition)
        die(call, why);
}

// Call before each API call (the macros below do).
inline void begin() { g_posts = Posts{}; }

// The error contract, read right after the call.
inline void checkPosted(const char* call, bool failed)
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

inline TQ3Status checkStatus(const char* call, TQ3Status status)
{
    checkPosted(call, status == kQ3Failure);
    return status;
}

inline TQ3Object checkObject(const char* call, TQ3Object object)
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

inline TQ3ViewStatus checkViewStatus(const char* call, TQ3ViewStatus status)
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
inline void setRaw(E& field, std::int32_t raw)
{
    static_assert(sizeof(E) == sizeof(raw), "Q3's enums are int-sized");
    std::memcpy(&field, &raw, sizeof raw);
}

template <class T>
inline bool sameBytes(const T& a, const T& b)
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
inline float expectedParameter(std::int32_t method, float value, bool& replaced)
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

inline bool allFinite(std::initializer_list<float> values)
{
    return std::all_of(values.begin(), values.end(), [](float v) { return std::isfinite(v); });
}

// QD3DLight.h's rules for the light's kind, written from the header.
inline bool lightObeysRules(const AnyLight& l)
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

inline LightStructures lightStructures(const AnyLight& l, bool stored)
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
inline std::vector<unsigned char> lightBytes(const AnyLight& l)
{
    const LightStructures s = lightStructures(l, true);
    const void* kinds[] = {&s.common, &s.directional, &s.point, &s.spot};
    const std::size_t sizes[] = {sizeof s.common, sizeof s.directional, sizeof s.point, sizeof s.spot};
    const unsigned char* p = static_cast<const unsigned char*>(kinds[l.kind]);
    return std::vector<unsigned char>(p, p + sizes[l.kind]);
}

// A stored light (valid values) of the given kind as an AnyLight.
inline AnyLight anyLight(int kind, const LightStructures& h)
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

    void run();

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

    // Hand-written, not from the description (FuzzData.h): the NURB rules
    // that make a curve drawable (order <= numPoints, knots nondecreasing
    // and clamped) are in no description, and only valid curves reach the
    // tessellator; the generated modes build them and then patch values.
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

    // Fills a geometry's data struct from the input by walking the library's
    // description of it (FuzzData.h): first the palette (one picked
    // attribute set the struct's handle fields mostly share), then the
    // fields. The arrays live in `arena`, and the storage objects made for
    // the struct are disposed of when it goes. Returns the palette.
    template <class S>
    TQ3AttributeSet readDescribed(S& data, DataArena& arena)
    {
        const TQ3AttributeSet palette = pick(Kind::kAttributeSet);
        HandleSource source;
        source.pick = [this](TQ3ObjectType type) {
            return pick(type == kQ3ShaderTypeSurface ? Kind::kShader : Kind::kAttributeSet);
        };
        source.storage = [&arena](const std::vector<unsigned char>& bytes) {
            const TQ3Object made = OBJECT(
                Q3MemoryStorage_New(bytes.empty() ? nullptr : bytes.data(), static_cast<unsigned long>(bytes.size())));
            if (made != nullptr)
                arena.atEnd([made] { STATUS(Q3Object_Dispose(made)); });
            return made;
        };
        DataGenerator generator(m_in, arena, std::move(source), palette);
        generator.fill(data);
        return palette;
    }

    // New for a described type, checked to read back; the kind it is held as.
    template <class S>
    void newDescribed(Kind kind, TQ3GeometryObject (*create)(const S*), TQ3Status (*getData)(TQ3GeometryObject, S*),
                      TQ3Status (*emptyData)(S*), TQ3Status (*submit)(const S*, TQ3ViewObject))
    {
        DataArena arena;
        S data{};
        readDescribed(data, arena);
        surfaceAction<S>(0, kind, &data, create, nullptr, getData, emptyData, submit,
                         [](const S& a, const S& b) { return sameData(a, b); });
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

    void step(Op op);

    void newCurve();

    void curveSetData();

    void curveGetData();

    unsigned long knotCount(TQ3Object curve) const;

    unsigned long pointCount(TQ3Object curve) const;

    bool inRangeOfHeldCurve(TQ3Object curve, unsigned long index, unsigned long count) const;

    void setKnot();

    void getKnot();

    void setControlPoint();

    void getControlPoint();

    void duplicate();

    void dispose();

    void getReference();

    TQ3SubdivisionStyleData readStyle(bool& replaced);

    void checkStyle(const char* call, TQ3Status status, bool replaced);

    void newStyle();

    void styleSetGet();

    TQ3Matrix4x4 readMatrix();

    void newTransform();

    void attributeSet();

    void otherGeometry();

    // Get, Set and Empty of points, lines and polylines; a successful Get is
    // always emptied, and emptying twice must succeed.
    // Apple's single-field accessors: positions and attribute sets of points,
    // lines and polylines by index, a geometry's own set, transform and
    // camera fields. A successful Get of a set hands over a reference.
    void accessors();

    void transformField(bool set, bool nullArg);

    void cameraField(bool set, bool nullArg);

    void otherGeometryEdit();

    // Triangles, polygons and trimeshes: New, SetData, GetData with
    // EmptyData (twice), immediate Submit and the per-vertex calls, with data
    // that may break any rule (non-finite coordinates and attribute values,
    // indices out of range, unknown attribute types, NULL arrays, counts no
    // array could hold, dead or foreign attribute sets). A failed SetData
    // must leave the edit index alone; a successful one must read back.
    void surfaces();

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

    void readTriMesh(TriMeshBuffers& m, TQ3AttributeSet set);

    template <class Data, class Same>
    void surfaceAction(std::uint8_t action, Kind kind, Data* data, TQ3GeometryObject (*create)(const Data*),
                       TQ3Status (*setData)(TQ3GeometryObject, const Data*),
                       TQ3Status (*getData)(TQ3GeometryObject, Data*), TQ3Status (*emptyData)(Data*),
                       TQ3Status (*submit)(const Data*, TQ3ViewObject), Same same)
    {
        switch (action) {
        case 0: {
            const TQ3Object geometry = OBJECT(create(data));
            if (geometry == nullptr)
                break;
            hold(geometry, kind);
            require(data != nullptr, "New", "accepted NULL data");
            Data got{};
            if (STATUS(getData(geometry, &got)) == kQ3Success) {
                require(same(got, *data), "GetData", "the data read back differs from what New was given");
                STATUS(emptyData(&got));
            }
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
                     TQ3Status (*setSet)(TQ3GeometryObject, unsigned long, TQ3AttributeSet));

    // Styles other than subdivision, illumination shaders and lights
    // (QD3DStyle.h, QD3DShader.h, QD3DLight.h), with values that may break
    // any rule: New, the setters, Get, immediate and retained Submit, the
    // shaders' uv calls, lights' single-field setters. Where the handle is a
    // held object of the call's kind, a call must succeed exactly when the
    // values obey the header's rules (TQ3Booleans: any int, stored as 0 or
    // 1); a failed edit must leave the object's state and edit index alone,
    // a successful one must change the edit index and read back.
    void stylesShadersLights();

    // Boxes, cones, cylinders, disks, ellipses, ellipsoids and tori: New,
    // SetData, GetData with EmptyData (twice), immediate Submit, every
    // per-field call and the decomposition. The data comes from the input
    // through the type's description (readDescribed): any floats (NaN,
    // infinities, zero or parallel axes, ranges outside [0, 1], a ratio <=
    // 0), any caps bits, attribute sets (dead, foreign, a box's six face sets).
    template <class Data>
    void quadricData(std::uint8_t action, Kind kind, bool nullData, TQ3GeometryObject (*create)(const Data*),
                     TQ3Status (*setData)(TQ3GeometryObject, const Data*),
                     TQ3Status (*getData)(TQ3GeometryObject, Data*), TQ3Status (*emptyData)(Data*),
                     TQ3Status (*submit)(const Data*, TQ3ViewObject))
    {
        describedAction(action, kind, nullData, create, setData, getData, emptyData, submit);
    }

    // Whether GetData read back what was set, field by field as described.
    struct SameDescribed {
        template <class Data>
        bool operator()(const Data& got, const Data& set) const
        {
            return sameData(got, set);
        }
    };

    // One surfaceAction (0 New, 1 SetData, 2 GetData and EmptyData twice,
    // 3 immediate Submit) with data read through the type's description
    // (readDescribed); `same` compares what GetData gives with what was set.
    template <class Data, class Same = SameDescribed>
    void describedAction(std::uint8_t action, Kind kind, bool nullData, TQ3GeometryObject (*create)(const Data*),
                         TQ3Status (*setData)(TQ3GeometryObject, const Data*),
                         TQ3Status (*getData)(TQ3GeometryObject, Data*), TQ3Status (*emptyData)(Data*),
                         TQ3Status (*submit)(const Data*, TQ3ViewObject), Same same = {})
    {
        DataArena arena;
        Data data{};
        readDescribed(data, arena);
        if (action == 3 && !drawAllowed())
            return;
        surfaceAction<Data>(action, kind, nullData ? nullptr : &data, create, setData, getData, emptyData, submit,
                            same);
    }

    // The types whose descriptions are not driven by another operation
    // (general polygons, markers, pixmap markers, NURB curves and patches,
    // polyhedra, triangle grids, TriMeshes): the type byte, the action byte
    // (describedAction's), the non-null byte, the described data.
    void described();

    // After a described curve was made or set: every held curve's order and
    // point count, as the curve operations expect to find them.
    void refreshCurveShapes();

    void quadrics();

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

    // Hand-written besides described() (which generates these types from
    // their descriptions): what reaches the triangulators most often is data
    // the descriptions cannot state (indices below the counts they index,
    // contours that share the vertex budget, a bitmap's width that fits its
    // rowBytes).
    void polygons2();

    void polygons2Field(std::uint8_t type, Kind kind);

    // Pixmap markers: a TQ3StoragePixmap of any pixel type (or a raw one),
    // sizes small or raw, enumerations raw now and then, and an image that
    // is a fresh memory storage (sometimes a byte short), NULL, or another
    // kind of object. The storage made here is given back once the call is
    // done (a marker keeps its own reference).
    struct StoragePixmapArgs {
        TQ3StoragePixmap pixmap{};
        TQ3Object made = nullptr;
    };

    // Hand-written besides described(): an image in a storage object of the
    // pixmap's byte size, or a byte short, which no description says.
    StoragePixmapArgs storagePixmap();

    void releaseStorage(StoragePixmapArgs& a);

    static bool samePixmap(const TQ3StoragePixmap& a, const TQ3StoragePixmap& b)
    {
        return a.image == b.image && a.width == b.width && a.height == b.height && a.rowBytes == b.rowBytes &&
               a.pixelSize == b.pixelSize && sameBytes(a.pixelType, b.pixelType) &&
               sameBytes(a.bitOrder, b.bitOrder) && sameBytes(a.byteOrder, b.byteOrder);
    }

    void pixmapMarkers();

    // QD3DShader.h's textures made from the same storage pixmap, reading no
    // input of their own (so the seeds keep their meaning): a pixmap texture
    // and a two-image mipmap texture go through the data rules; what is made
    // is read back, set again (which must succeed), wrapped in a texture
    // shader and disposed of; a colour routine runs on the pixmap's sizes.
    void texturesFrom(const StoragePixmapArgs& args);

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
    void elements();
    // The rest of the portable API (FuzzPortable.cpp).
    void portable();

    void picking();

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

    void controllers();

    void viewHints();

    void pixmapMarkerField();

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

    void quadricField(std::uint8_t type, Kind kind);

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

    // Hand-written, as readCurve is (the NURB rules are in no description,
    // and the trim loops nest three arrays deep). The patch flag byte: bit 0 raw uOrder, bit 1 raw vOrder, bit 2 a huge
    // numTrimLoops, bit 3 a huge numRows, bit 4 a huge numColumns, bit 5 an
    // attribute set, bit 6 NULL control points, bit 7 NULL knots. Then a
    // shape byte, the scale, value overwrites, the trim loops.
    void readPatch(PatchBuffers& p);

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
    void patches();

    // One per-field call: Set or Get of a control point (row, column), a u
    // knot or a v knot, at an index biased to the edges, NULL or not. A Set
    // that fails changes nothing; one that succeeds reads back.
    void patchField();

    // A patch gives a TriMesh of finite points within the triangle cap (or
    // two per pair of spans, when that is more), with indices in range.
    void checkPatchDecomposed(TQ3Object patch, TQ3Object result);

    void quadricDecompose(Kind kind);

    // A shape gives a trimesh within kQ3SubdivisionMaxTrianglesPerSurface,
    // an ellipse a closed or open polyline within the curve cap; finite. A
    // degenerate shape (the new generator makes them) gives a TriMesh of no
    // points, and only a shape that may be degenerate gives none.
    void checkQuadricDecomposed(Kind kind, TQ3Object geometry, TQ3Object result);

    // Whether the held quadric is clearly not degenerate (FuzzCurves.cpp).
    bool quadricClearlyDrawable(TQ3Object geometry, Kind kind);
    template <class Data>
    bool quadricClearlyDrawable(TQ3Object geometry, TQ3Status (*getData)(TQ3GeometryObject, Data*),
                                TQ3Status (*emptyData)(Data*));

    // The math helpers with arbitrary values, results aliasing inputs. Cases
    // 9 and up are QuickDraw 3D 1.6's other QD3DMath.h calls, by family.
    void math();

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
    TQ3Vector2D vector2();
    TQ3RationalPoint4D point4();
    TQ3Quaternion quaternion();

    TQ3Matrix3x3 readMatrix3x3();

    void mathPoints(bool nullArg);

    void mathVectors(const TQ3Matrix4x4& m4, bool nullArg);

    void mathMatrices(TQ3Matrix4x4& a, const TQ3Matrix4x4& b, const TQ3Vector3D& v1, const TQ3Vector3D& v2,
                      const TQ3Point3D& p, bool nullArg);

    void mathQuaternions(const TQ3Matrix4x4& m, const TQ3Vector3D& v1, const TQ3Vector3D& v2, TQ3Point3D& p,
                         bool nullArg);

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
    void requireHolds(const char* call, const TQ3BoundingBox& box, const Exact& p);

    // The distance is measured in double here and there; a few double ulps
    // of slack keep a point exactly on a float radius from failing.
    void requireHolds(const char* call, const TQ3BoundingSphere& sphere, const Exact& p);

    // isEmpty 0, 1 or any int a C caller may store.
    template <class Bound>
    void setIsEmpty(Bound& bound)
    {
        const std::uint8_t mode = m_in.u8();
        setRaw(bound.isEmpty, mode < 160 ? 0 : mode < 230 ? 1 : static_cast<std::int32_t>(m_in.u32()));
    }

    void mathBounds(bool nullArg);

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

    TQ3Point3D transformedOnce(const TQ3Point3D& p, const TQ3Matrix4x4& m);

    TQ3RationalPoint4D transformedOnce(const TQ3RationalPoint4D& p, const TQ3Matrix4x4& m);

    void mathArrays(const TQ3Matrix4x4& m, bool nullArg);
    static constexpr unsigned long kLongMax = static_cast<unsigned long>(std::numeric_limits<long>::max());

    // The curve tools of Q3NURBCurveTools.h, in the object form on a picked handle
    // or the data form on curve data from the input: parameters, tolerances,
    // indices and counts from the input (NaN, infinities, the ends and beyond), a
    // NULL output now and then. A success hands out curves that Q3NURBCurve_New
    // accepts (then released); a failure writes nothing; a retained curve keeps its
    // edit index. Measuring, inversion and fitting share the curve-draw budget.
    void curveTools();

    TQ3CameraData readCameraData();

    void newCamera();

    void cameraEdit();

    // A pixmap over memory that lives until the end of the input and is as
    // large as the pixmap claims.
    TQ3Pixmap readPixmap();

    TQ3DrawContextData readDrawContextData();

    void newDrawContext();

    void drawContextEdit();

    TQ3ObjectType rendererType();

    void renderer();

    void newView();

    void viewSet();

    void viewGet();

    void startRendering();

    void startBounding();

    void endBounding();

    void submitRetained();

    void submitCurveImmediate();

    void submitStyleImmediate();

    void submitImmediate();

    void pushPop();

    void decompose();

    // Q3Geometry_GetDecomposed of any held object (or a bad handle): NULL
    // with an error, NULL silently for a primitive, or the right geometry of
    // the right size for each type.
    void checkDecomposition(TQ3Object geometry, TQ3Object view);

    // Whether mesh's first count points are vertices' points, in order.
    static bool startsWithVertices(const TQ3TriMeshData& mesh, const TQ3Vertex3D* vertices, unsigned long count)
    {
        if (mesh.numPoints < count)
            return false;
        for (unsigned long i = 0; i < count; ++i) {
            const TQ3Point3D& a = mesh.points[i];
            const TQ3Point3D& b = vertices[i].point;
            if (std::memcmp(&a, &b, sizeof a) != 0)
                return false;
        }
        return true;
    }

    // The size an even-odd fill of `vertices` points in `contours` contours
    // may have. Without added points: a triangulation of the contours joined
    // by bridges, vertices + 2 contours - 2 triangles at most. With points
    // added where the vertices edges cross: at most one slab per vertex and
    // crossing (e (e - 1) / 2 of them), each holding at most e / 2 inside
    // trapezoids of two triangles over four added points.
    static bool boundsEvenOdd(const TQ3TriMeshData& mesh, unsigned long vertices, unsigned long contours)
    {
        if (mesh.numPoints == vertices)
            return mesh.numTriangles + 2 <= vertices + 2 * contours;
        const double edges = double(vertices);
        const double slabs = edges + edges * (edges - 1.0) / 2.0;
        const double trapezoids = slabs * (edges / 2.0);
        return double(mesh.numTriangles) <= 2.0 * trapezoids && double(mesh.numPoints - vertices) <= 4.0 * trapezoids;
    }

    // A general polygon gives a trimesh over its own vertices with at most
    // vertices + 2 contours - 2 triangles (more over added points where
    // contours cross: boundsEvenOdd); a grid one of three vertices per
    // facet; a polyhedron three per triangle and two per listed edge.
    void checkPolygons2Decomposed(TQ3Object geometry, Kind kind, bool posted, TQ3Object result);

    void viewState();

    void cancelSync();

    void objectQueries();

    void initializeExit();

    // ---- Groups -----------------------------------------------------------

    // Reads a group without the checking macros (for the fuzzer's own
    // bookkeeping); the posts it causes are forgotten.
    std::vector<TQ3Object> objectsOf(TQ3Object group);

    // Whether a traversal of the group meets at most kMaxGroupReach objects,
    // and at most one curve or polyline (each may draw 2^20 segments).
    bool groupIsSmall(TQ3Object group);

    // A position of the group (one of its own, walked to), or a bad one.
    TQ3GroupPosition positionIn(TQ3Object group);

    TQ3ObjectType typeToCount();

    // The group's invariants seen through the API: walking forwards and
    // backwards meets the same objects, as many as Q3Group_CountObjects says.
    void checkGroup(TQ3Object group);

    void groups();

    void finish();

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

    bool meshCounts(TQ3Object mesh, MeshCounts& c);

    // A part handle: one this fuzzer saw (maybe deleted since, maybe of
    // another mesh), or a made-up value.
    void* meshPart();

    void rememberPart(void* part);

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

    void meshes();

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

} // namespace q3fuzz
