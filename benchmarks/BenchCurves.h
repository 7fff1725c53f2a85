// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// What the Q3 and GLU benchmark processes share: the same curves, built from a
// fixed seed by code that depends on neither library, a long-double de Boor to
// measure both tessellations against, arc lengths for the adaptive methods,
// and the perspective projection both screen-space measurements use.
//
// The reference evaluation is de Boor's algorithm on homogeneous points
// (Piegl & Tiller, algorithm A4.1 on top of A2.1's span search) in long
// double (64-bit mantissa on x86-64), so its own error is about 2^-11 of the
// float rounding every tessellated vertex carries.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace q3bench {

/// Segments per non-empty span for the constant method, as the issue asks.
constexpr std::uint32_t kSegmentsPerSpan = 64;

/// Interior knot spacing of every test curve. A power of two keeps every knot
/// exact in float, so all spans have the same width for GLU's step rule.
constexpr float kKnotSpacing = 0.125f;

/// The adaptive benchmarks choose c1 so that arc length / c1 is this many
/// segments per span, a quarter of the constant method's count.
constexpr double kAdaptiveSegmentsPerSpan = 16.0;

constexpr double kPi = 3.14159265358979323846;

/// A NURB curve in QuickDraw 3D's (and GLU's GL_MAP1_VERTEX_4) layout:
/// homogeneous control points x*w, y*w, z*w, w, and numPoints + order knots.
struct BenchCurve {
    unsigned order = 0;
    std::vector<float> points;
    std::vector<float> knots;

    std::size_t numPoints() const { return points.size() / 4; }
    /// Clamped with distinct interior knots: every span is non-empty.
    std::size_t spanCount() const { return numPoints() - order + 1; }
    double spanStart(std::size_t s) const { return knots[order - 1 + s]; }
    double spanEnd(std::size_t s) const { return knots[order + s]; }
};

/// splitmix64: a generator whose output is fixed by its definition, so both
/// processes build bit-identical curves whatever the standard library.
class Random {
public:
    explicit Random(std::uint64_t seed) : m_state(seed) {}
    double uniform(double lo, double hi)
    {
        m_state += 0x9E3779B97F4A7C15ull;
        std::uint64_t z = m_state;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        return lo + (hi - lo) * double(z >> 11) * 0x1.0p-53;
    }

private:
    std::uint64_t m_state;
};

/// A rational curve of `order` with numPoints control points that sweeps x
/// from -1 to 1 along three periods of a sine in y (amplitude 0.8) with small
/// random wiggles in y and z, weights in [0.5, 2]; clamped uniform knots
/// kKnotSpacing apart.
inline BenchCurve makeCurve(unsigned order, std::size_t numPoints, std::uint64_t seed)
{
    Random random(seed);
    BenchCurve curve;
    curve.order = order;
    for (std::size_t i = 0; i < numPoints; ++i) {
        const double s = double(i) / double(numPoints - 1);
        const double x = -1.0 + 2.0 * s;
        const double y = 0.8 * std::sin(6.0 * kPi * s) + random.uniform(-0.02, 0.02);
        const double z = random.uniform(-0.3, 0.3);
        const double w = random.uniform(0.5, 2.0);
        curve.points.insert(curve.points.end(), {float(x * w), float(y * w), float(z * w), float(w)});
    }
    const std::size_t spans = numPoints - order + 1;
    for (unsigned i = 0; i < order; ++i)
        curve.knots.push_back(0.0f);
    for (std::size_t i = 1; i < spans; ++i)
        curve.knots.push_back(float(i) * kKnotSpacing);
    for (unsigned i = 0; i < order; ++i)
        curve.knots.push_back(float(spans) * kKnotSpacing);
    return curve;
}

/// The two curves of the tessellation comparison.
inline BenchCurve rationalCubic() { return makeCurve(4, 1000, 1); }
inline BenchCurve orderSixteen() { return makeCurve(16, 1000, 2); }

struct PointL {
    long double x = 0, y = 0, z = 0;
};

inline long double distance(const PointL& a, const PointL& b)
{
    const long double dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

/// The curve at t (clamped to the domain), in long double. At a knot the span
/// to the right is used, at the domain end the last one.
inline PointL evaluateLong(const BenchCurve& curve, long double t)
{
    const unsigned k = curve.order;
    const std::size_t n = curve.numPoints();
    const float* x = curve.knots.data();
    t = std::clamp<long double>(t, x[k - 1], x[n]);
    // Largest l in [k-1, n-1] with x[l] <= t and a non-empty span (A2.1).
    std::size_t lo = k - 1, hi = n - 1;
    while (lo < hi) {
        const std::size_t mid = (lo + hi + 1) / 2;
        if (x[mid] <= t)
            lo = mid;
        else
            hi = mid - 1;
    }
    while (lo > k - 1 && x[lo] == x[lo + 1])
        --lo;
    const std::size_t l = lo;
    long double d[16][4];
    for (unsigned j = 0; j < k; ++j)
        for (int c = 0; c < 4; ++c)
            d[j][c] = curve.points[4 * (l - (k - 1) + j) + c];
    for (unsigned r = 1; r < k; ++r)
        for (unsigned j = k - 1; j >= r; --j) {
            const long double left = x[l - (k - 1) + j];
            const long double right = x[l + 1 + j - r];
            const long double alpha = (t - left) / (right - left);
            for (int c = 0; c < 4; ++c)
                d[j][c] = (1 - alpha) * d[j - 1][c] + alpha * d[j][c];
        }
    const long double* p = d[k - 1];
    return PointL{p[0] / p[3], p[1] / p[3], p[2] / p[3]};
}

/// The parameter the constant method means by sample j of span s: j/m of the
/// way across, exactly.
inline long double sampleParameter(const BenchCurve& curve, std::size_t s, std::uint32_t j, std::uint32_t m)
{
    const long double a = curve.spanStart(s), b = curve.spanEnd(s);
    return j == m ? b : a + (b - a) * (long double)j / (long double)m;
}

/// The largest |coordinate| of the curve's points: the scale relative errors
/// are quoted against (as tests/unit/geometry/nurbs does).
inline double curveScale(const BenchCurve& curve)
{
    double scale = 0.0;
    for (std::size_t i = 0; i < curve.numPoints(); ++i)
        for (int c = 0; c < 3; ++c)
            scale = std::max(scale, std::fabs(double(curve.points[4 * i + c]) / curve.points[4 * i + 3]));
    return scale;
}

/// The largest distance of sample j of span s, held at xyz + 3 * index(s, j),
/// from the reference curve at sampleParameter(s, j).
template <class Index>
double maxSampleError(const BenchCurve& curve, const float* xyz, std::uint32_t m, Index index)
{
    long double worst = 0;
    for (std::size_t s = 0; s < curve.spanCount(); ++s)
        for (std::uint32_t j = 0; j <= m; ++j) {
            const float* v = xyz + 3 * index(s, j);
            const PointL exact = evaluateLong(curve, sampleParameter(curve, s, j, m));
            worst = std::max(worst, distance(PointL{v[0], v[1], v[2]}, exact));
        }
    return double(worst);
}

/// A perspective view of the test curves, as OpenGL column-major float
/// matrices (GLU's gluLoadSamplingMatrices takes exactly these) and a
/// viewport: the eye at (0, 0, 3) looking down -z, 45 degrees across y,
/// near 0.5, far 10, onto 1024 x 1024 pixels.
struct Projection {
    float model[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -3, 1};
    float proj[16] = {};
    int viewport[4] = {0, 0, 1024, 1024};

    Projection()
    {
        const double f = 1.0 / std::tan(kPi / 8.0);
        const double nearPlane = 0.5, farPlane = 10.0;
        proj[0] = float(f);
        proj[5] = float(f);
        proj[10] = float((farPlane + nearPlane) / (nearPlane - farPlane));
        proj[11] = -1.0f;
        proj[14] = float(2.0 * farPlane * nearPlane / (nearPlane - farPlane));
    }

    /// The pixel position (z = 0) of a point; false at or behind the eye.
    bool toPixels(double x, double y, double z, double out[3]) const
    {
        double eye[4], clip[4];
        const double in[4] = {x, y, z, 1.0};
        for (int r = 0; r < 4; ++r)
            eye[r] = model[r] * in[0] + model[4 + r] * in[1] + model[8 + r] * in[2] + model[12 + r] * in[3];
        for (int r = 0; r < 4; ++r)
            clip[r] = proj[r] * eye[0] + proj[4 + r] * eye[1] + proj[8 + r] * eye[2] + proj[12 + r] * eye[3];
        if (!(clip[3] > 0.0))
            return false;
        out[0] = viewport[0] + (clip[0] / clip[3] + 1.0) * 0.5 * viewport[2];
        out[1] = viewport[1] + (clip[1] / clip[3] + 1.0) * 0.5 * viewport[3];
        out[2] = 0.0;
        return true;
    }
};

enum class Space { kWorld, kScreen };

/// Arc length in world units or in pixels, by chords between 256 reference
/// points per span (the chord sum's relative error is far below 1e-6 here).
inline double arcLength(const BenchCurve& curve, Space space)
{
    const Projection projection;
    constexpr std::uint32_t kPerSpan = 256;
    long double length = 0;
    double previous[3] = {0, 0, 0};
    bool first = true;
    for (std::size_t s = 0; s < curve.spanCount(); ++s)
        for (std::uint32_t j = (s == 0 ? 0 : 1); j <= kPerSpan; ++j) {
            const PointL p = evaluateLong(curve, sampleParameter(curve, s, j, kPerSpan));
            double q[3] = {double(p.x), double(p.y), double(p.z)};
            if (space == Space::kScreen)
                projection.toPixels(q[0], q[1], q[2], q);
            if (!first)
                length += std::sqrt((long double)(q[0] - previous[0]) * (q[0] - previous[0]) +
                                    (long double)(q[1] - previous[1]) * (q[1] - previous[1]) +
                                    (long double)(q[2] - previous[2]) * (q[2] - previous[2]));
            std::copy(q, q + 3, previous);
            first = false;
        }
    return double(length);
}

/// The largest chord of a polyline (3 floats per vertex), measured in the space.
inline double longestChord(const float* xyz, std::size_t count, Space space)
{
    const Projection projection;
    double longest = 0.0;
    for (std::size_t i = 0; i + 1 < count; ++i) {
        double a[3] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
        double b[3] = {xyz[3 * i + 3], xyz[3 * i + 4], xyz[3 * i + 5]};
        if (space == Space::kScreen) {
            projection.toPixels(a[0], a[1], a[2], a);
            projection.toPixels(b[0], b[1], b[2], b);
        }
        longest = std::max(longest, std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                                              (a[2] - b[2]) * (a[2] - b[2])));
    }
    return longest;
}

/// c1 for the adaptive benchmarks: arc length / c1 = kAdaptiveSegmentsPerSpan per span.
inline double adaptiveLength(const BenchCurve& curve, double length)
{
    return length / (kAdaptiveSegmentsPerSpan * double(curve.spanCount()));
}

} // namespace q3bench
