// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Polygon triangulation by ear clipping, after D. Eberly, "Triangulation by
// Ear Clipping" (Geometric Tools, 2002-2015):
//
//  1. Each contour loses repeated points; contours enclosing no area go.
//  2. The even-odd rule decides what is inside: a contour's depth is the
//     number of other contours around it; even depth outlines a region
//     (made counterclockwise), odd depth cuts a hole in the contour just
//     around it (made clockwise).
//  3. Each hole is joined to its outline by a bridge, a pair of coincident
//     edges from the hole's rightmost vertex M to a vertex P of the outline
//     that M sees (Eberly section 3: cast a ray from M to +x, take the
//     nearest edge hit, its endpoint with the larger x, unless a reflex
//     vertex inside the triangle M, hit point, P sees M at a smaller angle).
//     Holes are bridged from the rightmost one leftwards, so every bridge
//     is made into the outline as it already is; when P is the end of an
//     earlier bridge (and so in the list twice), the copy whose wedge faces
//     M is used.
//  4. The outline, now one simple counterclockwise polygon, is clipped ear
//     by ear: a convex vertex whose triangle holds no reflex vertex (only
//     reflex vertices can lie inside an ear of a simple polygon) is cut off.
//     Reflex vertices sit in a uniform grid, so an ear test looks at the
//     few near the ear. Vertices on straight runs and spike tips are
//     dropped without a triangle, all of them before the first ear. If a whole lap finds no ear (the input was not simple), the
//     first convex vertex is cut anyway, so the loop always ends.

#include "geometry/mesh/Triangulate.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace q3::mesh {

namespace {

double cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

double signedArea(const std::vector<glm::dvec2>& points, const std::vector<std::uint32_t>& ring)
{
    double area = 0.0;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
        const glm::dvec2& a = points[ring[i]];
        const glm::dvec2& b = points[ring[(i + 1) % n]];
        area += a.x * b.y - b.x * a.y;
    }
    return area / 2.0;
}

// Even-odd containment of p in a ring (a point on the boundary may go
// either way).
bool contains(const std::vector<glm::dvec2>& points, const std::vector<std::uint32_t>& ring, const glm::dvec2& p)
{
    bool inside = false;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const glm::dvec2& a = points[ring[i]];
        const glm::dvec2& b = points[ring[j]];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
            inside = !inside;
    }
    return inside;
}

struct Node {
    std::uint32_t point; // index into the caller's points
    std::uint32_t prev;
    std::uint32_t next;
    bool reflex = false;
    bool removed = false;
};

// One outline with its holes bridged in, as a circular list, and the clipper.
class Clipper {
public:
    Clipper(const std::vector<glm::dvec2>& points, std::vector<std::uint32_t>& out) : m_points(points), m_out(out) {}

    // Starts the list with a counterclockwise ring; returns its first node.
    std::uint32_t addRing(const std::vector<std::uint32_t>& ring)
    {
        const std::uint32_t first = std::uint32_t(m_nodes.size());
        const std::uint32_t n = std::uint32_t(ring.size());
        for (std::uint32_t i = 0; i < n; ++i)
            m_nodes.push_back(Node{ring[i], first + (i + n - 1) % n, first + (i + 1) % n});
        return first;
    }

    // Joins a clockwise hole ring to the list holding `outline`.
    void bridge(std::uint32_t outline, const std::vector<std::uint32_t>& hole)
    {
        // M: the hole's rightmost vertex (the lowest of equals, for a
        // deterministic choice).
        std::size_t m = 0;
        for (std::size_t i = 1; i < hole.size(); ++i) {
            const glm::dvec2& a = at(hole[i]);
            const glm::dvec2& b = at(hole[m]);
            if (a.x > b.x || (a.x == b.x && a.y < b.y))
                m = i;
        }
        const glm::dvec2 pm = at(hole[m]);
        const std::uint32_t visible = copyFacing(outline, visibleVertex(outline, pm), pm);
        if (visible == kNone)
            return; // not inside the outline after all: the hole is dropped

        // visible -> M -> the hole from M around to M again -> visible -> on.
        const std::uint32_t after = m_nodes[visible].next;
        const std::uint32_t n = std::uint32_t(hole.size());
        std::uint32_t previous = visible;
        for (std::uint32_t k = 0; k <= n; ++k) {
            const std::uint32_t node = std::uint32_t(m_nodes.size());
            m_nodes.push_back(Node{hole[(m + k) % n], previous, 0});
            m_nodes[previous].next = node;
            previous = node;
        }
        const std::uint32_t back = std::uint32_t(m_nodes.size());
        m_nodes.push_back(Node{m_nodes[visible].point, previous, after});
        m_nodes[previous].next = back;
        m_nodes[after].prev = back;
    }

    void clip(std::uint32_t start)
    {
        std::size_t remaining = 0;
        std::uint32_t node = start;
        do {
            ++remaining;
            node = m_nodes[node].next;
        } while (node != start);
        // Straight runs and spikes (vertices where the outline turns by 0
        // or 180 degrees) go before any ear is cut: a spike's tip left in
        // place can become the corner of an ear outside the polygon.
        for (std::size_t unchanged = 0; remaining > 3 && unchanged < remaining;) {
            const Node& v = m_nodes[node];
            if (cross(at(m_nodes[v.prev].point), at(v.point), at(m_nodes[v.next].point)) != 0.0) {
                node = v.next;
                ++unchanged;
                continue;
            }
            const std::uint32_t prev = v.prev;
            if (node == start)
                start = prev;
            removeNode(node);
            --remaining;
            node = prev;
            unchanged = 0;
        }
        for (std::uint32_t i = start;; i = m_nodes[i].next) {
            updateReflex(i);
            if (m_nodes[i].next == start)
                break;
        }
        buildGrid(start);

        std::uint32_t current = start;
        std::size_t sinceLastCut = 0;
        while (remaining > 3) {
            const Node& v = m_nodes[current];
            const double turn = cross(at(m_nodes[v.prev].point), at(v.point), at(m_nodes[v.next].point));
            const bool flat = turn == 0.0;
            const bool stuck = sinceLastCut > remaining;
            const bool ear = flat || (turn > 0.0 && (stuck || isEar(current)));
            // Past two laps without a cut the polygon is not simple and not a
            // single convex vertex is left: the vertex is cut as it is.
            if (ear || (stuck && sinceLastCut > 2 * remaining)) {
                if (!flat)
                    emit(v.prev, current, v.next);
                const std::uint32_t prev = v.prev;
                removeNode(current);
                --remaining;
                sinceLastCut = 0;
                current = prev;
                continue;
            }
            ++sinceLastCut;
            current = v.next;
        }
        const Node& v = m_nodes[current];
        if (cross(at(m_nodes[v.prev].point), at(v.point), at(m_nodes[v.next].point)) > 0.0)
            emit(v.prev, current, v.next);
    }

private:
    static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

    const glm::dvec2& at(std::uint32_t point) const { return m_points[point]; }

    void emit(std::uint32_t a, std::uint32_t b, std::uint32_t c)
    {
        m_out.push_back(m_nodes[a].point);
        m_out.push_back(m_nodes[b].point);
        m_out.push_back(m_nodes[c].point);
    }

    void updateReflex(std::uint32_t i)
    {
        const Node& v = m_nodes[i];
        m_nodes[i].reflex = cross(at(m_nodes[v.prev].point), at(v.point), at(m_nodes[v.next].point)) < 0.0;
    }

    void removeNode(std::uint32_t i)
    {
        Node& v = m_nodes[i];
        v.removed = true;
        m_nodes[v.prev].next = v.next;
        m_nodes[v.next].prev = v.prev;
        updateReflex(v.prev);
        updateReflex(v.next);
    }

    // Whether p lies in the closed triangle a b c (counterclockwise).
    static bool inTriangle(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& p)
    {
        return cross(a, b, p) >= 0.0 && cross(b, c, p) >= 0.0 && cross(c, a, p) >= 0.0;
    }

    bool isEar(std::uint32_t i) const
    {
        const Node& v = m_nodes[i];
        const glm::dvec2& a = at(m_nodes[v.prev].point);
        const glm::dvec2& b = at(v.point);
        const glm::dvec2& c = at(m_nodes[v.next].point);
        const glm::dvec2 low = glm::min(a, glm::min(b, c));
        const glm::dvec2 high = glm::max(a, glm::max(b, c));
        const int x0 = cellX(low.x), x1 = cellX(high.x), y0 = cellY(low.y), y1 = cellY(high.y);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                for (std::uint32_t r : m_grid[std::size_t(y) * m_gridSize + std::size_t(x)]) {
                    const Node& candidate = m_nodes[r];
                    if (candidate.removed || !candidate.reflex || r == v.prev || r == i || r == v.next)
                        continue;
                    const glm::dvec2& p = at(candidate.point);
                    // Bridge duplicates sit exactly on a corner: they do not block.
                    if (p == a || p == b || p == c)
                        continue;
                    if (inTriangle(a, b, c, p))
                        return false;
                }
        return true;
    }

    void buildGrid(std::uint32_t start)
    {
        std::vector<std::uint32_t> reflex;
        glm::dvec2 low(std::numeric_limits<double>::max()), high(-std::numeric_limits<double>::max());
        for (std::uint32_t i = start;; i = m_nodes[i].next) {
            low = glm::min(low, at(m_nodes[i].point));
            high = glm::max(high, at(m_nodes[i].point));
            if (m_nodes[i].reflex)
                reflex.push_back(i);
            if (m_nodes[i].next == start)
                break;
        }
        m_gridSize = std::max<std::size_t>(1, std::size_t(std::sqrt(double(reflex.size()))));
        m_low = low;
        const glm::dvec2 extent = high - low;
        m_scale = glm::dvec2(extent.x > 0.0 ? double(m_gridSize) / extent.x : 0.0,
                             extent.y > 0.0 ? double(m_gridSize) / extent.y : 0.0);
        m_grid.assign(m_gridSize * m_gridSize, {});
        for (std::uint32_t r : reflex) {
            const glm::dvec2& p = at(m_nodes[r].point);
            m_grid[std::size_t(cellY(p.y)) * m_gridSize + std::size_t(cellX(p.x))].push_back(r);
        }
    }

    int cell(double value, double low, double scale) const
    {
        const double c = std::floor((value - low) * scale);
        return int(std::clamp(c, 0.0, double(m_gridSize - 1)));
    }
    int cellX(double x) const { return cell(x, m_low.x, m_scale.x); }
    int cellY(double y) const { return cell(y, m_low.y, m_scale.y); }

    // Whether the segment from node i towards p starts inside the polygon:
    // p lies in the interior wedge between i's two sides (the left of both
    // at a convex vertex, of either at a reflex one).
    bool locallyInside(std::uint32_t i, const glm::dvec2& p) const
    {
        const glm::dvec2& a = at(m_nodes[m_nodes[i].prev].point);
        const glm::dvec2& v = at(m_nodes[i].point);
        const glm::dvec2& b = at(m_nodes[m_nodes[i].next].point);
        if (cross(a, v, b) >= 0.0)
            return cross(v, b, p) > 0.0 && cross(a, v, p) > 0.0;
        return cross(v, b, p) > 0.0 || cross(a, v, p) > 0.0;
    }

    // A vertex an earlier bridge ended at appears more than once in the
    // list, each copy owning one wedge of the angle there; a new bridge to
    // it must start from the copy whose wedge faces the hole, or it would
    // cross the earlier bridge. Returns that copy of
    // `visible` (itself when it is the only one, or when none faces p).
    std::uint32_t copyFacing(std::uint32_t outline, std::uint32_t visible, const glm::dvec2& p) const
    {
        if (visible == kNone || locallyInside(visible, p))
            return visible;
        const glm::dvec2 point = at(m_nodes[visible].point);
        for (std::uint32_t i = outline;; i = m_nodes[i].next) {
            if (i != visible && at(m_nodes[i].point) == point && locallyInside(i, p))
                return i;
            if (m_nodes[i].next == outline)
                break;
        }
        return visible;
    }

    // The outline vertex that the hole vertex at pm is joined to, or kNone.
    std::uint32_t visibleVertex(std::uint32_t outline, const glm::dvec2& pm) const
    {
        double nearest = std::numeric_limits<double>::infinity();
        std::uint32_t edge = kNone;
        for (std::uint32_t i = outline;; i = m_nodes[i].next) {
            const glm::dvec2& a = at(m_nodes[i].point);
            const glm::dvec2& b = at(m_nodes[m_nodes[i].next].point);
            if ((a.y <= pm.y && pm.y <= b.y) || (b.y <= pm.y && pm.y <= a.y)) {
                const double x = a.y == b.y ? std::max(a.x, b.x) : a.x + (pm.y - a.y) * (b.x - a.x) / (b.y - a.y);
                if (x >= pm.x && x < nearest) {
                    nearest = x;
                    edge = i;
                }
            }
            if (m_nodes[i].next == outline)
                break;
        }
        if (edge == kNone)
            return kNone;
        const std::uint32_t a = edge, b = m_nodes[edge].next;
        std::uint32_t p = at(m_nodes[a].point).x > at(m_nodes[b].point).x ? a : b;
        const glm::dvec2 hit(nearest, pm.y);
        if (at(m_nodes[p].point) == hit)
            return p;
        // A reflex vertex inside (M, hit, P) would block the bridge to P; the
        // one seen at the smallest angle from the ray is visible instead.
        const glm::dvec2 pp = at(m_nodes[p].point);
        const bool upward = pp.y > pm.y;
        const glm::dvec2 t0 = pm, t1 = upward ? hit : pp, t2 = upward ? pp : hit;
        double best = std::numeric_limits<double>::infinity();
        for (std::uint32_t i = outline;; i = m_nodes[i].next) {
            const Node& v = m_nodes[i];
            const glm::dvec2& q = at(v.point);
            const bool isReflex =
                cross(at(m_nodes[v.prev].point), q, at(m_nodes[v.next].point)) < 0.0;
            if (i != p && isReflex && q != pp && inTriangle(t0, t1, t2, q)) {
                const double angle = std::abs(q.y - pm.y) / std::max(q.x - pm.x, 1e-300);
                if (angle < best || (angle == best && glm::distance(q, pm) < glm::distance(at(m_nodes[p].point), pm))) {
                    best = angle;
                    p = i;
                }
            }
            if (v.next == outline)
                break;
        }
        return p;
    }

    const std::vector<glm::dvec2>& m_points;
    std::vector<std::uint32_t>& m_out;
    std::vector<Node> m_nodes;
    std::vector<std::vector<std::uint32_t>> m_grid;
    std::size_t m_gridSize = 1;
    glm::dvec2 m_low{0.0};
    glm::dvec2 m_scale{0.0};
};

} // namespace

glm::dvec3 newellNormal(const glm::dvec3* points, std::size_t count)
{
    glm::dvec3 n(0.0);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3& a = points[i];
        const glm::dvec3& b = points[(i + 1) % count];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    const double length = glm::length(n);
    return length > 0.0 && std::isfinite(length) ? n / length : glm::dvec3(0.0);
}

glm::dvec3 spanNormal(const glm::dvec3* points, std::size_t count)
{
    if (count < 3)
        return glm::dvec3(0.0);
    // The point farthest from the first, then the point farthest from the
    // line through both: the widest triangle of the three spans the plane.
    std::size_t far = 0;
    for (std::size_t i = 1; i < count; ++i)
        if (glm::length(points[i] - points[0]) > glm::length(points[far] - points[0]))
            far = i;
    glm::dvec3 best(0.0);
    for (std::size_t i = 1; i < count; ++i) {
        const glm::dvec3 n = glm::cross(points[far] - points[0], points[i] - points[0]);
        if (glm::length(n) > glm::length(best))
            best = n;
    }
    const double length = glm::length(best);
    return length > 0.0 && std::isfinite(length) ? best / length : glm::dvec3(0.0);
}

std::vector<glm::dvec2> projectToPlane(const glm::dvec3* points, std::size_t count, const glm::dvec3& n)
{
    // u: perpendicular to n, built from the axis n is least aligned with.
    const glm::dvec3 axis = std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z)
                                ? glm::dvec3(1, 0, 0)
                                : (std::abs(n.y) <= std::abs(n.z) ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1));
    const glm::dvec3 u = glm::normalize(glm::cross(axis, n));
    const glm::dvec3 v = glm::cross(n, u);
    std::vector<glm::dvec2> projected(count);
    for (std::size_t i = 0; i < count; ++i)
        projected[i] = glm::dvec2(glm::dot(points[i], u), glm::dot(points[i], v));
    return projected;
}

std::vector<std::uint32_t> triangulate(const std::vector<glm::dvec2>& points,
                                       const std::vector<std::size_t>& contourStarts)
{
    // 1. Rings without repeated points and with area.
    std::vector<std::vector<std::uint32_t>> rings;
    std::vector<double> areas;
    for (std::size_t c = 0; c < contourStarts.size(); ++c) {
        const std::size_t begin = contourStarts[c];
        const std::size_t end = c + 1 < contourStarts.size() ? contourStarts[c + 1] : points.size();
        std::vector<std::uint32_t> ring;
        for (std::size_t i = begin; i < end && i < points.size(); ++i) {
            if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
                continue;
            if (!ring.empty() && points[ring.back()] == points[i])
                continue;
            ring.push_back(std::uint32_t(i));
        }
        while (ring.size() > 1 && points[ring.front()] == points[ring.back()])
            ring.pop_back();
        if (ring.size() < 3)
            continue;
        const double area = signedArea(points, ring);
        if (area == 0.0 || !std::isfinite(area))
            continue;
        rings.push_back(std::move(ring));
        areas.push_back(area);
    }

    // 2. Depth by the even-odd rule, and each hole's parent: the smallest
    // ring around it.
    const std::size_t count = rings.size();
    std::vector<int> depth(count, 0);
    std::vector<std::size_t> parent(count, count);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec2& probe = points[rings[i][0]];
        for (std::size_t j = 0; j < count; ++j) {
            if (i == j || std::abs(areas[j]) <= std::abs(areas[i]) || !contains(points, rings[j], probe))
                continue;
            ++depth[i];
            if (parent[i] == count || std::abs(areas[j]) < std::abs(areas[parent[i]]))
                parent[i] = j;
        }
    }
    for (std::size_t i = 0; i < count; ++i) {
        const bool hole = depth[i] % 2 == 1;
        if ((areas[i] > 0.0) == hole)
            std::reverse(rings[i].begin(), rings[i].end());
    }

    // 3 and 4, outline by outline.
    std::vector<std::uint32_t> triangles;
    for (std::size_t i = 0; i < count; ++i) {
        if (depth[i] % 2 == 1)
            continue;
        std::vector<std::size_t> holes;
        for (std::size_t j = 0; j < count; ++j)
            if (depth[j] % 2 == 1 && parent[j] == i)
                holes.push_back(j);
        auto rightmost = [&](std::size_t ring) {
            double x = -std::numeric_limits<double>::infinity();
            for (std::uint32_t p : rings[ring])
                x = std::max(x, points[p].x);
            return x;
        };
        std::stable_sort(holes.begin(), holes.end(),
                         [&](std::size_t a, std::size_t b) { return rightmost(a) > rightmost(b); });
        Clipper clipper(points, triangles);
        const std::uint32_t start = clipper.addRing(rings[i]);
        for (std::size_t hole : holes)
            clipper.bridge(start, rings[hole]);
        clipper.clip(start);
    }
    return triangles;
}

namespace {

// One side of a contour between two distinct finite points, lower end first
// (y, then x).
struct Side {
    std::uint32_t a; // the caller's index of the lower end
    std::uint32_t b; // of the upper end
};

// True when the open segments p0p1 and q0q1 cross at one point inside both.
bool crosses(const glm::dvec2& p0, const glm::dvec2& p1, const glm::dvec2& q0, const glm::dvec2& q1)
{
    const double d1 = cross(p0, p1, q0), d2 = cross(p0, p1, q1);
    const double d3 = cross(q0, q1, p0), d4 = cross(q0, q1, p1);
    return ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0));
}

} // namespace

Triangulation triangulateEvenOdd(const std::vector<glm::dvec2>& points, const std::vector<std::size_t>& contourStarts)
{
    // The sides of every contour, repeated and non-finite points skipped.
    std::vector<Side> sides;
    for (std::size_t c = 0; c < contourStarts.size(); ++c) {
        const std::size_t begin = contourStarts[c];
        const std::size_t end = c + 1 < contourStarts.size() ? contourStarts[c + 1] : points.size();
        std::vector<std::uint32_t> ring;
        for (std::size_t i = begin; i < end && i < points.size(); ++i)
            if (std::isfinite(points[i].x) && std::isfinite(points[i].y) &&
                (ring.empty() || points[ring.back()] != points[i]))
                ring.push_back(std::uint32_t(i));
        while (ring.size() > 1 && points[ring.front()] == points[ring.back()])
            ring.pop_back();
        if (ring.size() < 2)
            continue;
        for (std::size_t i = 0; i < ring.size(); ++i) {
            std::uint32_t a = ring[i], b = ring[(i + 1) % ring.size()];
            const glm::dvec2 &pa = points[a], &pb = points[b];
            if (pb.y < pa.y || (pb.y == pa.y && pb.x < pa.x))
                std::swap(a, b);
            sides.push_back(Side{a, b});
        }
    }

    // Where sides cross: without a crossing, ear clipping gives the same
    // region with no added points. Sides sorted by their lower end's y are
    // compared only with those that start below the first one's upper end.
    std::sort(sides.begin(), sides.end(), [&](const Side& l, const Side& r) {
        return points[l.a].y < points[r.a].y || (points[l.a].y == points[r.a].y && l.a < r.a) ||
               (points[l.a].y == points[r.a].y && l.a == r.a && l.b < r.b);
    });
    std::vector<double> levels;
    for (std::size_t i = 0; i < sides.size(); ++i)
        for (std::size_t j = i + 1; j < sides.size() && points[sides[j].a].y <= points[sides[i].b].y; ++j) {
            const glm::dvec2 &p0 = points[sides[i].a], &p1 = points[sides[i].b];
            const glm::dvec2 &q0 = points[sides[j].a], &q1 = points[sides[j].b];
            if (!crosses(p0, p1, q0, q1))
                continue;
            const double t = cross(q0, q1, p0) / (cross(q0, q1, p0) - cross(q0, q1, p1));
            levels.push_back(p0.y + (p1.y - p0.y) * t);
        }
    Triangulation result;
    if (levels.empty()) {
        result.triangles = triangulate(points, contourStarts);
        return result;
    }

    // Slabs between consecutive levels: every vertex's y and every crossing's.
    for (const Side& side : sides) {
        levels.push_back(points[side.a].y);
        levels.push_back(points[side.b].y);
    }
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());

    // The point of side `s` at level `k`: an end of it, or a point added
    // once (shared by the slabs above and below).
    std::map<std::pair<std::size_t, std::size_t>, std::uint32_t> added;
    const auto pointAt = [&](std::size_t s, std::size_t k) {
        const Side& side = sides[s];
        const glm::dvec2 &pa = points[side.a], &pb = points[side.b];
        const double y = levels[k];
        if (y == pa.y)
            return side.a;
        if (y == pb.y)
            return side.b;
        const auto [it, inserted] = added.emplace(std::make_pair(s, k), 0u);
        if (inserted) {
            it->second = std::uint32_t(points.size() + result.added.size());
            result.added.push_back(EdgePoint{side.a, side.b, (y - pa.y) / (pb.y - pa.y)});
        }
        return it->second;
    };
    const auto position = [&](std::uint32_t index) {
        if (index < points.size())
            return points[index];
        const EdgePoint& e = result.added[index - points.size()];
        return points[e.a] + (points[e.b] - points[e.a]) * e.t;
    };

    struct Crossing {
        double x;
        std::size_t side;
    };
    std::vector<Crossing> row;
    for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
        const double y0 = levels[k], y1 = levels[k + 1], middle = (y0 + y1) / 2.0;
        row.clear();
        for (std::size_t s = 0; s < sides.size(); ++s) {
            const glm::dvec2 &pa = points[sides[s].a], &pb = points[sides[s].b];
            if (pa.y <= y0 && pb.y >= y1 && pb.y > pa.y)
                row.push_back(Crossing{pa.x + (pb.x - pa.x) * (middle - pa.y) / (pb.y - pa.y), s});
        }
        std::sort(row.begin(), row.end(), [](const Crossing& l, const Crossing& r) {
            return l.x < r.x || (l.x == r.x && l.side < r.side);
        });
        // Inside: between the first and second crossing, the third and
        // fourth, ... (an odd number of sides to the left).
        for (std::size_t i = 0; i + 1 < row.size(); i += 2) {
            const std::uint32_t l0 = pointAt(row[i].side, k), l1 = pointAt(row[i].side, k + 1);
            const std::uint32_t r0 = pointAt(row[i + 1].side, k), r1 = pointAt(row[i + 1].side, k + 1);
            const std::uint32_t quad[2][3] = {{l0, r0, r1}, {l0, r1, l1}};
            for (const auto& triangle : quad)
                if (cross(position(triangle[0]), position(triangle[1]), position(triangle[2])) > 0.0)
                    result.triangles.insert(result.triangles.end(), triangle, triangle + 3);
        }
    }
    return result;
}

} // namespace q3::mesh
