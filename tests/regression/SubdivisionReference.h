// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The second computation the subdivision regression tests compare Q3 with,
// written from the public headers and the article alone and sharing no code
// with src/:
//   - a NURB curve evaluator: the article's basis-function recursion
//     ("DEFINING THE BASIS FUNCTIONS", Cox-de Boor, 0/0 taken as 0) over the
//     one non-empty span that contains t, then the rational sum of
//     "RATIONAL CURVES" on homogeneous control points, in long double;
//   - random valid curves (orders 2-16, clamped or not, interior knots
//     repeated up to order - 1 times, weights 0.25 to 4);
//   - the local-to-world matrix of a stack of submitted transforms, built
//     from QD3DTransform.h's definitions (row vectors; a transform submitted
//     later acts first);
//   - the pixel position of a world point, built from QD3DCamera.h's camera
//     definitions (look-at frame, orthographic window or view angle and
//     aspect ratio, view port) and QD3DDrawContext.h's pane (frustum x and y
//     from -1 to 1 across the pane, y up, pixel rows down). It does not use
//     Q3Camera_GetWorldToFrustum or any other Q3 matrix.
// Plus a locator that finds how far a point is from a curve, used to check
// that the vertices of an adaptive polyline (whose parameters Q3 does not
// return) lie on the curve.

#include "QD3DCamera.h"
#include "QD3DGeometry.h"
#include "QD3DMath.h"
#include "QD3DTransform.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

namespace q3test::subdivision {

using Real = long double;

/// Unit roundoff of float: rounding to nearest moves a value x by at most
/// kFloatRoundoff * |x|.
constexpr Real kFloatRoundoff = 1.0L / 16777216.0L; // 2^-24

struct Vec3 {
    Real x = 0, y = 0, z = 0;
};

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(Real s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline Real dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Real norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Real distance(const Vec3& a, const Vec3& b) { return norm(b - a); }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Vec3 unit(const Vec3& a) { return (1 / norm(a)) * a; }
inline Vec3 toVec(const TQ3Point3D& p) { return {p.x, p.y, p.z}; }
inline Real maxAbs(const Vec3& a) { return std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}); }

/// A curve that owns its arrays.
struct Curve {
    unsigned long order = 0;
    std::vector<TQ3RationalPoint4D> points;
    std::vector<float> knots;
    bool clamped = false;

    TQ3NURBCurveData data() { return {order, points.size(), points.data(), knots.data(), nullptr}; }
    std::size_t numPoints() const { return points.size(); }
    Real domainStart() const { return knots[order - 1]; }
    Real domainEnd() const { return knots[numPoints()]; }

    /// Knot indices s with knots[s] < knots[s + 1] inside the domain.
    std::vector<std::size_t> spans() const
    {
        std::vector<std::size_t> result;
        for (std::size_t s = order - 1; s < numPoints(); ++s)
            if (knots[s] < knots[s + 1])
                result.push_back(s);
        return result;
    }

    /// The larger of the control points' bounding-box diagonal and their
    /// largest coordinate: the curve lies in the hull of its control points,
    /// so no coordinate of a curve point exceeds it.
    Real scale() const;
};

/// The curve point at t by Cox-de Boor. The span is the last non-empty
/// domain span starting at or before t (the first one for t before the
/// domain), so at the domain end the left limit is taken and slightly
/// outside the domain the end spans' polynomials are continued.
inline Vec3 evaluate(const Curve& c, Real t)
{
    const std::size_t k = c.order;
    const std::size_t n = c.numPoints();
    std::size_t s = n;
    for (std::size_t i = k - 1; i < n; ++i) {
        if (c.knots[i] < c.knots[i + 1] && (s == n || Real(c.knots[i]) <= t))
            s = i;
    }
    // N[j] holds N(i, m) for i = s - (k - 1) + j; N[k] stays 0 (N(s + 1, m) is
    // zero on span s). Level 1 is 1 on span s only.
    Real N[kQ3NURBCurveMaxOrder + 1] = {};
    N[k - 1] = 1;
    for (std::size_t m = 2; m <= k; ++m) {
        for (std::size_t j = 0; j < k; ++j) {
            const std::size_t i = s - (k - 1) + j;
            const Real xi = c.knots[i], xim1 = c.knots[i + m - 1], xi1 = c.knots[i + 1], xim = c.knots[i + m];
            Real value = 0;
            if (xim1 != xi)
                value += (t - xi) / (xim1 - xi) * N[j];
            if (xim != xi1)
                value += (xim - t) / (xim - xi1) * N[j + 1];
            N[j] = value;
        }
    }
    Real x = 0, y = 0, z = 0, w = 0;
    for (std::size_t j = 0; j < k; ++j) {
        const TQ3RationalPoint4D& p = c.points[s - (k - 1) + j];
        x += N[j] * p.x;
        y += N[j] * p.y;
        z += N[j] * p.z;
        w += N[j] * p.w;
    }
    return {x / w, y / w, z / w};
}

struct RandomCurveOptions {
    unsigned long order = 4;
    bool clamped = true;
    Real repeatProbability = 0.0; ///< chance that a knot repeats its predecessor (capped at order - 1)
    unsigned long extraPoints = 10; ///< numPoints is order + uniform(0, extraPoints)
    Real extent = 10.0;            ///< positions in [-extent, extent]^3
};

/// A random curve obeying every TQ3NURBCurveData rule with a non-empty domain.
inline Curve randomCurve(std::mt19937& rng, const RandomCurveOptions& options)
{
    std::uniform_real_distribution<double> coordinate(-double(options.extent), double(options.extent));
    std::uniform_real_distribution<double> logWeight(std::log(0.25), std::log(4.0));
    std::uniform_real_distribution<double> unitInterval(0.0, 1.0);
    std::uniform_int_distribution<unsigned long> extra(0, options.extraPoints);
    const unsigned long k = options.order;
    for (;;) {
        Curve c;
        c.order = k;
        c.clamped = options.clamped;
        const unsigned long n = k + extra(rng);
        for (unsigned long i = 0; i < n; ++i) {
            const double w = std::exp(logWeight(rng));
            c.points.push_back({float(coordinate(rng) * w), float(coordinate(rng) * w), float(coordinate(rng) * w),
                                float(w)});
        }
        double value = std::floor(coordinate(rng));
        unsigned long run = 1;
        c.knots.push_back(float(value));
        for (unsigned long i = 1; i < n + k; ++i) {
            const bool endRun = options.clamped && (i < k || i > n);
            const bool firstOfEndRun = options.clamped && i == n;
            const bool repeat = endRun || (!firstOfEndRun && run < k - 1 &&
                                           unitInterval(rng) < double(options.repeatProbability));
            if (repeat) {
                ++run;
            } else {
                value += 0.125 + 1.5 * unitInterval(rng);
                run = 1;
            }
            c.knots.push_back(float(value));
        }
        if (c.domainStart() < c.domainEnd())
            return c;
    }
}

/// A 4x4 matrix acting on row vectors, p' = p * M, as QD3D.h has it.
struct Matrix4 {
    std::array<std::array<Real, 4>, 4> m{};

    static Matrix4 identity()
    {
        Matrix4 r;
        for (int i = 0; i < 4; ++i)
            r.m[i][i] = 1;
        return r;
    }
    static Matrix4 from(const TQ3Matrix4x4& q)
    {
        Matrix4 r;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                r.m[i][j] = q.value[i][j];
        return r;
    }
    /// This matrix, then `next`.
    Matrix4 then(const Matrix4& next) const
    {
        Matrix4 r;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                for (int l = 0; l < 4; ++l)
                    r.m[i][j] += m[i][l] * next.m[l][j];
        return r;
    }
    Matrix4 absolute() const
    {
        Matrix4 r;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                r.m[i][j] = std::fabs(m[i][j]);
        return r;
    }
    /// The image of point p (w = 1 in), divided by its w.
    Vec3 point(const Vec3& p) const
    {
        Real out[4];
        for (int j = 0; j < 4; ++j)
            out[j] = p.x * m[0][j] + p.y * m[1][j] + p.z * m[2][j] + m[3][j];
        return {out[0] / out[3], out[1] / out[3], out[2] / out[3]};
    }
};

/// One transform of a submitted stack, as its data (the test submits the
/// same values with Q3..._Submit).
struct TransformStep {
    enum Kind { kTranslate, kRotate, kScale, kMatrix } kind = kTranslate;
    TQ3Vector3D vector{};         ///< translate, scale
    TQ3RotateTransformData rotate{};
    TQ3Matrix4x4 matrix{};

    /// The matrix QD3DTransform.h defines for it, from the float data, with
    /// the rotation's sine and cosine in long double.
    Matrix4 reference() const
    {
        Matrix4 r = Matrix4::identity();
        switch (kind) {
        case kTranslate:
            r.m[3][0] = vector.x;
            r.m[3][1] = vector.y;
            r.m[3][2] = vector.z;
            break;
        case kScale:
            r.m[0][0] = vector.x;
            r.m[1][1] = vector.y;
            r.m[2][2] = vector.z;
            break;
        case kRotate: {
            // Counterclockwise seen from the axis' positive end: about X y
            // turns towards z, about Y z towards x, about Z x towards y.
            const int from = rotate.axis == kQ3AxisX ? 1 : rotate.axis == kQ3AxisY ? 2 : 0;
            const int to = rotate.axis == kQ3AxisX ? 2 : rotate.axis == kQ3AxisY ? 0 : 1;
            const Real c = std::cos(Real(rotate.radians)), s = std::sin(Real(rotate.radians));
            r.m[from][from] = c;
            r.m[from][to] = s;
            r.m[to][from] = -s;
            r.m[to][to] = c;
            break;
        }
        case kMatrix:
            r = Matrix4::from(matrix);
            break;
        }
        return r;
    }

    TQ3Status submit(TQ3ViewObject view) const
    {
        switch (kind) {
        case kTranslate:
            return Q3TranslateTransform_Submit(&vector, view);
        case kScale:
            return Q3ScaleTransform_Submit(&vector, view);
        case kRotate:
            return Q3RotateTransform_Submit(&rotate, view);
        case kMatrix:
            return Q3MatrixTransform_Submit(&matrix, view);
        }
        return kQ3Failure;
    }
};

/// A stack of transforms submitted in order, and its local-to-world matrix
/// (QD3DTransform.h: submitting T makes L into T * L, so a later transform
/// acts first).
struct TransformStack {
    std::vector<TransformStep> steps;

    Matrix4 localToWorld() const
    {
        Matrix4 l = Matrix4::identity();
        for (const TransformStep& step : steps)
            l = step.reference().then(l);
        return l;
    }
    /// The product of the steps' entrywise absolute values: |M| bound for
    /// how far rounding in the steps' entries can move a point.
    Matrix4 absoluteLocalToWorld() const
    {
        Matrix4 l = Matrix4::identity();
        for (const TransformStep& step : steps)
            l = step.reference().absolute().then(l);
        return l;
    }
    void submit(TQ3ViewObject view) const
    {
        for (const TransformStep& step : steps)
            step.submit(view);
    }
};

/// A random non-identity stack: `first` (a TransformStep::Kind) and then up
/// to three more random steps: translations up to 30, rotations about a
/// random axis, non-uniform scales of 0.25 to 4 (sometimes mirrored), general
/// affine matrices with shear and determinant at least 0.3 in magnitude.
inline TransformStack randomTransforms(std::mt19937& rng, int first)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto step = [&](int kind) {
        TransformStep t;
        t.kind = TransformStep::Kind(kind);
        switch (t.kind) {
        case TransformStep::kTranslate:
            t.vector = {float(60 * u(rng) - 30), float(60 * u(rng) - 30), float(60 * u(rng) - 30)};
            break;
        case TransformStep::kScale: {
            auto factor = [&] {
                const double f = std::exp(std::log(0.25) + u(rng) * std::log(16.0));
                return float(u(rng) < 0.15 ? -f : f);
            };
            t.vector = {factor(), factor(), factor()};
            break;
        }
        case TransformStep::kRotate:
            t.rotate = {TQ3Axis(int(3 * u(rng)) % 3), float(6.2831853 * u(rng) - 3.14159265)};
            break;
        case TransformStep::kMatrix:
            for (;;) {
                Q3Matrix4x4_SetIdentity(&t.matrix);
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j)
                        t.matrix.value[i][j] = float(3 * u(rng) - 1.5);
                for (int j = 0; j < 3; ++j)
                    t.matrix.value[3][j] = float(40 * u(rng) - 20);
                const Matrix4 m = Matrix4::from(t.matrix);
                const Real det = m.m[0][0] * (m.m[1][1] * m.m[2][2] - m.m[1][2] * m.m[2][1]) -
                                 m.m[0][1] * (m.m[1][0] * m.m[2][2] - m.m[1][2] * m.m[2][0]) +
                                 m.m[0][2] * (m.m[1][0] * m.m[2][1] - m.m[1][1] * m.m[2][0]);
                if (std::fabs(det) >= 0.3)
                    break;
            }
            break;
        }
        return t;
    };
    TransformStack stack;
    stack.steps.push_back(step(first));
    const int more = int(4 * u(rng));
    for (int i = 0; i < more; ++i)
        stack.steps.push_back(step(int(4 * u(rng)) % 4));
    return stack;
}

/// Where the camera and pane put a world point, in pixels (x right from the
/// pane's left edge, y down from its top edge), computed from the camera's
/// data as QD3DCamera.h defines it.
class ScreenMap {
public:
    /// An orthographic camera.
    ScreenMap(const TQ3OrthographicCameraData& data, const TQ3Area& pane)
        : ScreenMap(data.cameraData, pane)
    {
        m_perspective = false;
        m_left = data.left;
        m_right = data.right;
        m_top = data.top;
        m_bottom = data.bottom;
    }
    /// A view angle aspect camera: fov spans the narrower dimension, so the
    /// vertical one when aspectRatioXToY >= 1.
    ScreenMap(const TQ3ViewAngleAspectCameraData& data, const TQ3Area& pane)
        : ScreenMap(data.cameraData, pane)
    {
        m_perspective = true;
        const Real across = 1 / std::tan(Real(data.fov) / 2);
        const Real aspect = data.aspectRatioXToY;
        m_focalX = aspect >= 1 ? across / aspect : across;
        m_focalY = aspect >= 1 ? across : across * aspect;
    }

    /// The pixel position of world point p; false when p is at or behind the
    /// eye of a perspective camera (it has no image).
    bool map(const Vec3& p, Real& px, Real& py) const
    {
        Real nx, ny;
        if (!toViewPlane(p, nx, ny))
            return false;
        // The view port rectangle [ox, ox + w] x [oy - h, oy] onto -1..1.
        const Real fx = (nx - (m_viewPortX + m_viewPortWidth / 2)) * 2 / m_viewPortWidth;
        const Real fy = (ny - (m_viewPortY - m_viewPortHeight / 2)) * 2 / m_viewPortHeight;
        px = m_paneX + (fx + 1) / 2 * m_paneWidth;
        py = m_paneY + (1 - fy) / 2 * m_paneHeight;
        return true;
    }

    /// Distance in front of the eye along the viewing direction.
    Real depth(const Vec3& p) const { return dot(p - m_eye, m_forward); }

    /// An upper bound on how far the pixel image of p moves when p moves by
    /// at most `error` (first order: the Frobenius norm of the map's
    /// Jacobian, computed analytically, times the distance).
    Real pixelError(const Vec3& p, Real error) const
    {
        const Vec3 d = p - m_eye;
        const Real x = dot(d, m_xAxis), y = dot(d, m_yAxis);
        const Real sx = m_paneWidth / m_viewPortWidth, sy = m_paneHeight / m_viewPortHeight;
        Vec3 gx, gy; // gradients of the view-plane coordinates
        if (m_perspective) {
            const Real z = dot(d, m_forward);
            gx = m_focalX * ((1 / z) * m_xAxis - (x / (z * z)) * m_forward);
            gy = m_focalY * ((1 / z) * m_yAxis - (y / (z * z)) * m_forward);
        } else {
            gx = (2 / (m_right - m_left)) * m_xAxis;
            gy = (2 / (m_top - m_bottom)) * m_yAxis;
        }
        return std::sqrt(sx * sx * dot(gx, gx) + sy * sy * dot(gy, gy)) * error;
    }

    bool perspective() const { return m_perspective; }

    /// The view volume as five affine functions of a world point, each <= 0
    /// inside: the four sides of the view port (moved inwards by `margin`
    /// view-port units) and the plane `hither` in front of the eye. For a
    /// perspective camera the side functions are multiplied by the depth,
    /// which the hither function keeps positive inside, so all five stay
    /// affine.
    void planes(const Vec3& p, Real hither, Real margin, Real out[5]) const
    {
        const Vec3 d = p - m_eye;
        const Real x = dot(d, m_xAxis), y = dot(d, m_yAxis), z = dot(d, m_forward);
        const Real left = m_viewPortX + margin, right = m_viewPortX + m_viewPortWidth - margin;
        const Real top = m_viewPortY - margin, bottom = m_viewPortY - m_viewPortHeight + margin;
        if (m_perspective) {
            const Real nx = m_focalX * x, ny = m_focalY * y; // view-plane coordinates times z
            out[0] = left * z - nx;
            out[1] = nx - right * z;
            out[2] = bottom * z - ny;
            out[3] = ny - top * z;
        } else {
            const Real nx = (2 * x - (m_right + m_left)) / (m_right - m_left);
            const Real ny = (2 * y - (m_top + m_bottom)) / (m_top - m_bottom);
            out[0] = left - nx;
            out[1] = nx - right;
            out[2] = bottom - ny;
            out[3] = ny - top;
        }
        out[4] = hither - z;
    }

    /// Whether some part of the world segment a-b lies inside the view
    /// volume (planes() with the same hither and margin): the segment is
    /// clipped against each plane in its parameter.
    bool segmentVisible(const Vec3& a, const Vec3& b, Real hither, Real margin) const
    {
        Real fa[5], fb[5];
        planes(a, hither, margin, fa);
        planes(b, hither, margin, fb);
        Real lo = 0, hi = 1;
        for (int k = 0; k < 5; ++k) {
            // f(s) = fa + s (fb - fa) <= 0
            const Real slope = fb[k] - fa[k];
            if (slope == 0) {
                if (fa[k] > 0)
                    return false;
            } else if (slope > 0) {
                hi = std::min(hi, -fa[k] / slope);
            } else {
                lo = std::max(lo, -fa[k] / slope);
            }
        }
        return lo <= hi;
    }

private:
    ScreenMap(const TQ3CameraData& camera, const TQ3Area& pane)
    {
        const TQ3CameraPlacement& placement = camera.placement;
        m_eye = toVec(placement.cameraLocation);
        // View space: the eye at the origin looking down -z, +y towards the
        // up vector made perpendicular, +x to the right (right-handed).
        m_forward = unit(toVec(placement.pointOfInterest) - m_eye);
        m_xAxis = unit(cross(m_forward, Vec3{placement.upVector.x, placement.upVector.y, placement.upVector.z}));
        m_yAxis = cross(m_xAxis, m_forward);
        m_viewPortX = camera.viewPort.origin.x;
        m_viewPortY = camera.viewPort.origin.y;
        m_viewPortWidth = camera.viewPort.width;
        m_viewPortHeight = camera.viewPort.height;
        m_paneX = pane.min.x;
        m_paneY = pane.min.y;
        m_paneWidth = Real(pane.max.x) - pane.min.x;
        m_paneHeight = Real(pane.max.y) - pane.min.y;
    }

    bool toViewPlane(const Vec3& p, Real& nx, Real& ny) const
    {
        const Vec3 d = p - m_eye;
        const Real x = dot(d, m_xAxis), y = dot(d, m_yAxis);
        if (m_perspective) {
            const Real z = dot(d, m_forward);
            if (!(z > 0))
                return false;
            nx = m_focalX * x / z;
            ny = m_focalY * y / z;
        } else {
            nx = (2 * x - (m_right + m_left)) / (m_right - m_left);
            ny = (2 * y - (m_top + m_bottom)) / (m_top - m_bottom);
        }
        return true;
    }

    bool m_perspective = false;
    Vec3 m_eye, m_forward, m_xAxis, m_yAxis;
    Real m_left = 0, m_right = 0, m_top = 0, m_bottom = 0;
    Real m_focalX = 1, m_focalY = 1;
    Real m_viewPortX = -1, m_viewPortY = 1, m_viewPortWidth = 2, m_viewPortHeight = 2;
    Real m_paneX = 0, m_paneY = 0, m_paneWidth = 1, m_paneHeight = 1;

};

/// A point of the long-double reference as the float point the API takes.
inline TQ3Point3D toPoint(const Vec3& v)
{
    return {float(v.x), float(v.y), float(v.z)};
}

/// A random unit vector: three normal deviates, drawn again while their
/// length is below 1e-3, then normalised.
inline Vec3 randomDirection(std::mt19937& rng)
{
    std::normal_distribution<double> normal;
    for (;;) {
        const Vec3 v{normal(rng), normal(rng), normal(rng)};
        if (norm(v) > 1e-3L)
            return unit(v);
    }
}

/// The axis-aligned box of rational control points (each divided by its w),
/// each first mapped by `toWorld`.
struct ControlBox {
    Vec3 lo{1e30L, 1e30L, 1e30L};
    Vec3 hi{-1e30L, -1e30L, -1e30L};
    Real largest = 0; ///< the largest coordinate's magnitude

    ControlBox(const std::vector<TQ3RationalPoint4D>& points, const Matrix4& toWorld = Matrix4::identity())
    {
        for (const TQ3RationalPoint4D& p : points) {
            const Vec3 w = toWorld.point({Real(p.x) / p.w, Real(p.y) / p.w, Real(p.z) / p.w});
            lo = {std::min(lo.x, w.x), std::min(lo.y, w.y), std::min(lo.z, w.z)};
            hi = {std::max(hi.x, w.x), std::max(hi.y, w.y), std::max(hi.z, w.z)};
            largest = std::max(largest, maxAbs(w));
        }
    }
    Vec3 centre() const { return 0.5L * (lo + hi); }
    /// Half the diagonal, at least 1e-3.
    Real radius() const { return std::max(distance(lo, hi) / 2, Real(1e-3)); }
    /// The larger of the diagonal and the largest coordinate: no point of a
    /// curve or surface in the hull of the points has a larger coordinate.
    Real extent() const { return std::max(distance(lo, hi), largest); }
};

/// The camera data of an eye at `eye` looking at `target` with `up`, the
/// view port the whole square, the range hither to yon.
inline TQ3CameraData lookAt(const Vec3& eye, const Vec3& target, const Vec3& up, Real hither, Real yon)
{
    TQ3CameraData camera{};
    camera.placement.cameraLocation = toPoint(eye);
    camera.placement.pointOfInterest = toPoint(target);
    camera.placement.upVector = {float(up.x), float(up.y), float(up.z)};
    camera.range = {float(hither), float(yon)};
    camera.viewPort = {{-1.0f, 1.0f}, 2.0f, 2.0f};
    return camera;
}

/// The camera a random scene is seen through: an orthographic or a view
/// angle aspect one, with the screen map computed from its data.
struct SceneCamera {
    bool perspective = false;
    TQ3OrthographicCameraData orthographic{};
    TQ3ViewAngleAspectCameraData viewAngle{};
    TQ3Area pane{}; ///< the draw context's pane the camera's view port maps to

    void setPerspective(const TQ3CameraData& camera, Real fov, Real aspectRatioXToY)
    {
        perspective = true;
        viewAngle.cameraData = camera;
        viewAngle.fov = float(fov);
        viewAngle.aspectRatioXToY = float(aspectRatioXToY);
    }
    /// An orthographic camera showing halfWidth either side of x = shiftX
    /// and halfHeight above and below y = shiftY (camera coordinates).
    void setOrthographic(const TQ3CameraData& camera, Real halfWidth, Real halfHeight, Real shiftX = 0,
                         Real shiftY = 0)
    {
        perspective = false;
        orthographic.cameraData = camera;
        orthographic.left = float(shiftX - halfWidth);
        orthographic.right = float(shiftX + halfWidth);
        orthographic.top = float(shiftY + halfHeight);
        orthographic.bottom = float(shiftY - halfHeight);
    }
    ScreenMap screen() const { return perspective ? ScreenMap(viewAngle, pane) : ScreenMap(orthographic, pane); }
    Real hither() const
    {
        return perspective ? viewAngle.cameraData.range.hither : orthographic.cameraData.range.hither;
    }
    /// A new camera object (the caller disposes it).
    TQ3CameraObject newObject() const
    {
        return perspective ? Q3ViewAngleAspectCamera_New(&viewAngle) : Q3OrthographicCamera_New(&orthographic);
    }
};

inline Real Curve::scale() const
{
    return ControlBox(points).extent();
}

/// Dense samples of a curve: `perSpan` intervals of equal parameter width
/// in every non-empty span, shared span ends kept once.
struct DenseSamples {
    std::vector<Real> t;
    std::vector<Vec3> local;
};

inline DenseSamples denseSamples(const Curve& c, int perSpan)
{
    DenseSamples out;
    const std::vector<std::size_t> spans = c.spans();
    for (std::size_t s : spans) {
        const Real a = c.knots[s], b = c.knots[s + 1];
        for (int j = 0; j < perSpan; ++j) {
            const Real t = a + (b - a) * j / perSpan;
            out.t.push_back(t);
            out.local.push_back(evaluate(c, t));
        }
    }
    out.t.push_back(c.domainEnd());
    out.local.push_back(evaluate(c, c.domainEnd()));
    return out;
}

/// Finds how far points are from a curve, for points that come in the order
/// of their curve parameters (a polyline's vertices): each search starts
/// where the previous point was found and takes the first place along the
/// curve within `tolerance`; a point with none gets its distance to the
/// nearest dense sample chord instead (which is then above the tolerance).
class CurveLocator {
public:
    CurveLocator(const Curve& curve, const DenseSamples& samples, Real tolerance)
        : m_curve(curve), m_samples(samples), m_tolerance(tolerance)
    {
    }

    Real distanceOf(const Vec3& v)
    {
        const std::size_t last = m_samples.t.size() - 1;
        for (std::size_t j = m_cursor; j < last; ++j) {
            const Vec3& a = m_samples.local[j];
            const Vec3& b = m_samples.local[j + 1];
            // The curve between two dense samples stays close to their chord;
            // a quarter of the chord is far more than its sagitta.
            if (chordDistance(v, a, b) > 0.25L * distance(a, b) + m_tolerance)
                continue;
            const Real d = refine(v, j);
            if (d <= m_tolerance) {
                m_cursor = j;
                return d;
            }
        }
        Real best = std::numeric_limits<Real>::infinity();
        for (std::size_t j = 0; j < last; ++j)
            best = std::min(best, chordDistance(v, m_samples.local[j], m_samples.local[j + 1]));
        return std::max(best, m_tolerance * 2);
    }

private:
    static Real chordDistance(const Vec3& v, const Vec3& a, const Vec3& b)
    {
        const Vec3 ab = b - a;
        const Real len2 = dot(ab, ab);
        Real u = len2 > 0 ? dot(v - a, ab) / len2 : 0;
        u = std::clamp(u, Real(0), Real(1));
        return distance(a + u * ab, v);
    }

    // The distance from v to the curve on the parameters around interval j:
    // Gauss-Newton on |C(t) - v|^2 from the chord's nearest point; if that
    // stalls above a hundredth of the tolerance (it is slow where the curve
    // barely moves), a golden-section search near where it got to, and if
    // that is still not on the curve, over the whole bracket.
    Real refine(const Vec3& v, std::size_t j) const
    {
        const std::vector<Real>& ts = m_samples.t;
        const Real lo = ts[j == 0 ? 0 : j - 1];
        const Real hi = ts[std::min(j + 2, ts.size() - 1)];
        const Vec3 a = m_samples.local[j], b = m_samples.local[j + 1];
        const Vec3 ab = b - a;
        const Real len2 = dot(ab, ab);
        const Real u = len2 > 0 ? std::clamp(dot(v - a, ab) / len2, Real(0), Real(1)) : Real(0);
        Real t = ts[j] + u * (ts[j + 1] - ts[j]);
        const Real h = (hi - lo) * 1e-7L;
        for (int iteration = 0; iteration < 40; ++iteration) {
            const Vec3 c = evaluate(m_curve, t);
            const Vec3 derivative = (1 / (2 * h)) * (evaluate(m_curve, t + h) - evaluate(m_curve, t - h));
            const Real speed2 = dot(derivative, derivative);
            if (!(speed2 > 0))
                break;
            const Real next = std::clamp(t - dot(c - v, derivative) / speed2, lo, hi);
            const bool done = std::fabs(next - t) <= (hi - lo) * 1e-15L;
            t = next;
            if (done)
                break;
        }
        Real best = distance(evaluate(m_curve, t), v);
        if (best > m_tolerance / 100) {
            const Real width = (hi - lo) / 64;
            best = std::min(best, goldenSection(v, std::max(lo, t - width), std::min(hi, t + width)));
        }
        if (best > m_tolerance)
            best = std::min(best, goldenSection(v, lo, hi));
        return best;
    }

    // The smallest distance from v to the curve on [x0, x1] when there is one
    // local minimum there.
    Real goldenSection(const Vec3& v, Real x0, Real x1) const
    {
        const Real g = (std::sqrt(Real(5)) - 1) / 2;
        Real p = x1 - g * (x1 - x0), q = x0 + g * (x1 - x0);
        Real fp = distance(evaluate(m_curve, p), v), fq = distance(evaluate(m_curve, q), v);
        for (int iteration = 0; iteration < 90; ++iteration) {
            if (fp < fq) {
                x1 = q;
                q = p;
                fq = fp;
                p = x1 - g * (x1 - x0);
                fp = distance(evaluate(m_curve, p), v);
            } else {
                x0 = p;
                p = q;
                fp = fq;
                q = x0 + g * (x1 - x0);
                fq = distance(evaluate(m_curve, q), v);
            }
        }
        return std::min(fp, fq);
    }

    const Curve& m_curve;
    const DenseSamples& m_samples;
    Real m_tolerance;
    std::size_t m_cursor = 0;
};

} // namespace q3test::subdivision
