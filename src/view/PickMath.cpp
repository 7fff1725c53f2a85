// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/PickMath.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace q3::pickmath {

std::optional<TriangleHit> rayTriangle(const glm::dvec3& origin, const glm::dvec3& direction,
                                       const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
    const glm::dvec3 e1 = b - a;
    const glm::dvec3 e2 = c - a;
    const glm::dvec3 p = glm::cross(direction, e2);
    const double det = glm::dot(e1, p);
    // A ray parallel to the plane (or a degenerate triangle) meets nothing
    // that has an area to be seen.
    const double scale = glm::length(e1) * glm::length(p);
    if (!(std::abs(det) > 1e-12 * scale) || !std::isfinite(det))
        return std::nullopt;
    const double inv = 1.0 / det;
    const glm::dvec3 s = origin - a;
    const double u = glm::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0)
        return std::nullopt;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(direction, q) * inv;
    if (v < 0.0 || u + v > 1.0)
        return std::nullopt;
    const double t = glm::dot(e2, q) * inv;
    if (!(t >= 0.0))
        return std::nullopt;
    return TriangleHit{t, u, v};
}

Approach rayPoint(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& p)
{
    const double dd = glm::dot(direction, direction);
    const double t = dd > 0.0 ? std::max(0.0, glm::dot(p - origin, direction) / dd) : 0.0;
    return Approach{t, 0.0, glm::distance(origin + t * direction, p)};
}

Approach raySegment(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& a,
                    const glm::dvec3& b)
{
    // Minimise |origin + t d - (a + s e)| over t >= 0, s in [0, 1]: solve
    // the unconstrained pair, clamp s, recompute t for it, clamp t and
    // recompute s for that (Ericson 5.1.9's order).
    const glm::dvec3 d = direction;
    const glm::dvec3 e = b - a;
    const glm::dvec3 r = origin - a;
    const double dd = glm::dot(d, d);
    const double ee = glm::dot(e, e);
    const double de = glm::dot(d, e);
    const double dr = glm::dot(d, r);
    const double er = glm::dot(e, r);
    if (ee <= 0.0) {
        Approach point = rayPoint(origin, direction, a);
        return point;
    }
    const double denom = dd * ee - de * de;
    double s = denom > 1e-15 * dd * ee ? std::clamp((dd * er - de * dr) / denom, 0.0, 1.0) : 0.0;
    double t = (de * s - dr) / dd;
    if (t < 0.0) {
        t = 0.0;
        s = std::clamp(er / ee, 0.0, 1.0);
    }
    return Approach{t, s, glm::distance(origin + t * d, a + s * e)};
}

SegmentClosest pointSegment2D(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b)
{
    const glm::dvec2 e = b - a;
    const double ee = glm::dot(e, e);
    const double s = ee > 0.0 ? std::clamp(glm::dot(p - a, e) / ee, 0.0, 1.0) : 0.0;
    return SegmentClosest{s, glm::distance(p, a + s * e)};
}

namespace {

// The signed distances to the two depth planes (inside when >= 0) and to
// w = 0 (inside when > 0, kept with a small margin so that the divide is
// safe).
double plane(const glm::dvec4& v, int which)
{
    switch (which) {
    case 0:
        return -v.z;      // z <= 0: in front of the hither plane
    case 1:
        return v.z + v.w; // z >= -w: before the yon plane
    default:
        return v.w - 1e-12;
    }
}

} // namespace

bool clipSegment(ClipVertex& a, ClipVertex& b)
{
    for (int which = 0; which < 3; ++which) {
        const double da = plane(a.clip, which);
        const double db = plane(b.clip, which);
        if (da < 0.0 && db < 0.0)
            return false;
        if (da < 0.0 || db < 0.0) {
            const double f = da / (da - db);
            const ClipVertex cut{a.clip + f * (b.clip - a.clip), a.s + f * (b.s - a.s)};
            (da < 0.0 ? a : b) = cut;
        }
    }
    return true;
}

void clipPolygon(std::vector<glm::dvec4>& polygon)
{
    std::vector<glm::dvec4> out;
    for (int which = 0; which < 3 && !polygon.empty(); ++which) {
        out.clear();
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const glm::dvec4& p = polygon[i];
            const glm::dvec4& q = polygon[(i + 1) % polygon.size()];
            const double dp = plane(p, which);
            const double dq = plane(q, which);
            if (dp >= 0.0)
                out.push_back(p);
            if ((dp >= 0.0) != (dq >= 0.0))
                out.push_back(p + (dp / (dp - dq)) * (q - p));
        }
        polygon.swap(out);
    }
}

double screenToHomogeneous(double sigma, double wa, double wb)
{
    // The screen point (1 - sigma) A/wa + sigma B/wb is the image of
    // (1 - s) A + s B for s = sigma wa / ((1 - sigma) wb + sigma wa).
    const double denom = (1.0 - sigma) * wb + sigma * wa;
    return denom != 0.0 ? sigma * wa / denom : sigma;
}

bool convexOverlapsRect(const glm::dvec2* points, std::size_t count, const glm::dvec2& lo, const glm::dvec2& hi)
{
    if (count == 0)
        return false;
    // The rectangle's own axes.
    glm::dvec2 pmin = points[0];
    glm::dvec2 pmax = points[0];
    for (std::size_t i = 1; i < count; ++i) {
        pmin = glm::min(pmin, points[i]);
        pmax = glm::max(pmax, points[i]);
    }
    if (pmax.x < lo.x || pmin.x > hi.x || pmax.y < lo.y || pmin.y > hi.y)
        return false;
    // Each edge's normal (one edge for a segment; none for a point).
    const glm::dvec2 corners[4] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
    const std::size_t edges = count == 1 ? 0 : (count == 2 ? 1 : count);
    for (std::size_t i = 0; i < edges; ++i) {
        const glm::dvec2 e = points[(i + 1) % count] - points[i];
        const glm::dvec2 n(-e.y, e.x);
        if (n.x == 0.0 && n.y == 0.0)
            continue;
        double a0 = glm::dot(n, points[0]);
        double a1 = a0;
        for (std::size_t k = 1; k < count; ++k) {
            const double v = glm::dot(n, points[k]);
            a0 = std::min(a0, v);
            a1 = std::max(a1, v);
        }
        double b0 = glm::dot(n, corners[0]);
        double b1 = b0;
        for (const glm::dvec2& c : corners) {
            const double v = glm::dot(n, c);
            b0 = std::min(b0, v);
            b1 = std::max(b1, v);
        }
        if (a1 < b0 || b1 < a0)
            return false;
    }
    return true;
}

} // namespace q3::pickmath
