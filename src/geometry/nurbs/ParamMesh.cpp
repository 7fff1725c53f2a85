// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The planar mesh surface tessellation works on (ParamMesh.h).
//
// Every change of the mesh goes through one routine, `replace`, which swaps
// a set of triangles for another set covering the same region and re-links
// neighbours by matching directed edges: a split, a flip and the removal of a
// vertex are each a few lines on top of it.
//
// Point location is the stochastic visibility walk (O. Devillers, S. Pion,
// M. Teillaud, "Walking in a triangulation", 2002): from a triangle, step
// across an edge that has the target strictly on its far side, trying the
// edges from a random one; it cannot cycle forever in any triangulation.
//
// Constraint segments are inserted by Sloan's method (S. W. Sloan, "A fast
// algorithm for generating constrained Delaunay triangulations", 1993, the
// edge-swapping step): collect the edges the segment crosses, then flip each
// whose quadrilateral is convex, putting back those that still cross, until
// the segment is an edge. It terminates when no vertex lies on the segment's
// interior; a vertex that does is either made part of the segment or
// removed from the mesh first. A crossed edge that is already constrained
// means two trim loops (or one with itself) cross.
//
// Vertex removal triangulates the polygon around the vertex by ear clipping
// (an ear: a strictly convex corner whose closed triangle holds no other
// corner of the polygon).

#include "geometry/nurbs/ParamMesh.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace q3::nurbs {

namespace {

int next3(int i)
{
    return i == 2 ? 0 : i + 1;
}
int prev3(int i)
{
    return i == 0 ? 2 : i - 1;
}

struct OuterEdge {
    std::uint32_t a, b;
    std::uint32_t neighbour;
    bool constrained;
    bool fixed;
};

} // namespace

void ParamMesh::setDomain(double u0, double u1, double v0, double v1)
{
    m_u0 = u0;
    m_u1 = u1;
    m_v0 = v0;
    m_v1 = v1;
}

std::int64_t ParamMesh::keyX(double u) const
{
    const double f = (u - m_u0) / (m_u1 - m_u0);
    if (!(f > 0.0))
        return 0;
    if (!(f < 1.0))
        return kGrid;
    return std::int64_t(std::llround(f * double(kGrid)));
}

std::int64_t ParamMesh::keyY(double v) const
{
    const double f = (v - m_v0) / (m_v1 - m_v0);
    if (!(f > 0.0))
        return 0;
    if (!(f < 1.0))
        return kGrid;
    return std::int64_t(std::llround(f * double(kGrid)));
}

std::uint32_t ParamMesh::addVertex(double u, double v, std::int64_t x, std::int64_t y)
{
    Vertex vertex;
    vertex.u = u;
    vertex.v = v;
    vertex.x = x;
    vertex.y = y;
    vertices.push_back(vertex);
    return std::uint32_t(vertices.size() - 1);
}

std::int64_t ParamMesh::orient(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t cx,
                               std::int64_t cy)
{
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

std::int64_t ParamMesh::orient(std::uint32_t a, std::uint32_t b, std::uint32_t c) const
{
    const Vertex& p = vertices[a];
    const Vertex& q = vertices[b];
    const Vertex& r = vertices[c];
    return orient(p.x, p.y, q.x, q.y, r.x, r.y);
}

void ParamMesh::link(std::uint32_t t, int e, std::uint32_t other)
{
    Triangle& tri = triangles[t];
    tri.neighbour[e] = other;
    if (other == kNone)
        return;
    const std::uint32_t a = tri.v[next3(e)];
    const std::uint32_t b = tri.v[prev3(e)];
    Triangle& o = triangles[other];
    for (int f = 0; f < 3; ++f)
        if (o.v[next3(f)] == b && o.v[prev3(f)] == a) {
            o.neighbour[f] = t;
            return;
        }
}

void ParamMesh::touchVertices(std::uint32_t t)
{
    for (std::uint32_t v : triangles[t].v)
        vertices[v].triangle = t;
}

std::uint32_t ParamMesh::newTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c)
{
    Triangle tri;
    tri.v = {a, b, c};
    std::uint32_t t;
    if (!m_free.empty()) {
        t = m_free.back();
        m_free.pop_back();
        triangles[t] = tri;
    } else {
        triangles.push_back(tri);
        t = std::uint32_t(triangles.size() - 1);
    }
    ++m_alive;
    return t;
}

void ParamMesh::kill(std::uint32_t t)
{
    Triangle& tri = triangles[t];
    if (!tri.alive)
        return;
    for (int e = 0; e < 3; ++e) {
        const std::uint32_t n = tri.neighbour[e];
        if (n == kNone)
            continue;
        for (std::uint32_t& back : triangles[n].neighbour)
            if (back == t)
                back = kNone;
    }
    tri.alive = false;
    tri.neighbour = {kNone, kNone, kNone};
    m_free.push_back(t);
    --m_alive;
}

void ParamMesh::refreshVertexTriangles()
{
    for (Vertex& vertex : vertices)
        vertex.triangle = kNone;
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
        if (triangles[t].alive)
            touchVertices(t);
}

void ParamMesh::build(const std::vector<std::array<std::uint32_t, 3>>& corners)
{
    triangles.clear();
    m_free.clear();
    triangles.reserve(corners.size());
    for (const auto& c : corners) {
        Triangle tri;
        tri.v = c;
        triangles.push_back(tri);
    }
    m_alive = triangles.size();
    // The two halves of an interior edge are found in the bucket of the
    // edge's smaller vertex (buckets hold a vertex's few edges).
    const std::size_t n = vertices.size();
    std::vector<std::uint32_t> start(n + 1, 0);
    for (const Triangle& tri : triangles)
        for (int e = 0; e < 3; ++e)
            ++start[std::min(tri.v[next3(e)], tri.v[prev3(e)]) + 1];
    for (std::size_t i = 0; i < n; ++i)
        start[i + 1] += start[i];
    struct Half {
        std::uint32_t other;
        std::uint32_t t;
        int e;
    };
    std::vector<Half> halves(3 * triangles.size());
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = triangles[t].v[next3(e)];
            const std::uint32_t b = triangles[t].v[prev3(e)];
            halves[fill[std::min(a, b)]++] = Half{std::max(a, b), t, e};
        }
    for (std::size_t v = 0; v < n; ++v)
        for (std::uint32_t i = start[v]; i < start[v + 1]; ++i)
            for (std::uint32_t j = i + 1; j < start[v + 1]; ++j)
                if (halves[i].other == halves[j].other) {
                    triangles[halves[i].t].neighbour[halves[i].e] = halves[j].t;
                    triangles[halves[j].t].neighbour[halves[j].e] = halves[i].t;
                }
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
        touchVertices(t);
}

void ParamMesh::markFixed(std::uint32_t a, std::uint32_t b)
{
    std::uint32_t t;
    int e;
    if (findEdge(a, b, t, e)) {
        triangles[t].fixed |= std::uint8_t(1u << e);
        const std::uint32_t n = triangles[t].neighbour[e];
        int f;
        if (n != kNone && findEdge(b, a, t, f))
            triangles[t].fixed |= std::uint8_t(1u << f);
    } else if (findEdge(b, a, t, e)) {
        triangles[t].fixed |= std::uint8_t(1u << e);
    }
}

ParamMesh::Location ParamMesh::locate(std::int64_t x, std::int64_t y, std::uint32_t hint) const
{
    auto classify = [&](std::uint32_t t, Location& out) {
        const Triangle& tri = triangles[t];
        std::int64_t o[3];
        for (int i = 0; i < 3; ++i) {
            const Vertex& a = vertices[tri.v[next3(i)]];
            const Vertex& b = vertices[tri.v[prev3(i)]];
            o[i] = orient(a.x, a.y, b.x, b.y, x, y);
            if (o[i] < 0)
                return false;
        }
        out.triangle = t;
        const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
        if (zeros == 0) {
            out.kind = Location::kInside;
        } else if (zeros == 1) {
            out.kind = Location::kOnEdge;
            out.index = o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2;
        } else {
            out.kind = Location::kOnVertex;
            out.index = o[0] != 0 ? 0 : o[1] != 0 ? 1 : 2;
        }
        return true;
    };
    Location result;
    std::uint32_t t = hint;
    if (t >= triangles.size() || !triangles[t].alive) {
        t = kNone;
        for (std::uint32_t i = 0; i < triangles.size(); ++i)
            if (triangles[i].alive) {
                t = i;
                break;
            }
        if (t == kNone)
            return result;
    }
    const std::size_t limit = 4 * std::size_t(std::sqrt(double(triangles.size()))) + 4096;
    for (std::size_t step = 0; step < limit; ++step) {
        const Triangle& tri = triangles[t];
        m_random ^= m_random << 13;
        m_random ^= m_random >> 7;
        m_random ^= m_random << 17;
        const int start = int(m_random % 3);
        bool moved = false;
        for (int k = 0; k < 3; ++k) {
            const int i = (start + k) % 3;
            const Vertex& a = vertices[tri.v[next3(i)]];
            const Vertex& b = vertices[tri.v[prev3(i)]];
            if (orient(a.x, a.y, b.x, b.y, x, y) < 0) {
                if (tri.neighbour[i] == kNone)
                    return result; // outside the mesh
                t = tri.neighbour[i];
                moved = true;
                break;
            }
        }
        if (!moved) {
            classify(t, result);
            return result;
        }
    }
    for (std::uint32_t i = 0; i < triangles.size(); ++i)
        if (triangles[i].alive && classify(i, result))
            return result;
    return Location{};
}

std::uint32_t ParamMesh::insertVertex(double u, double v, std::int64_t x, std::int64_t y, std::uint32_t hint,
                                      bool& existed)
{
    existed = false;
    const Location where = locate(x, y, hint);
    if (where.kind == Location::kOutside)
        return kNone;
    const Triangle tri = triangles[where.triangle];
    if (where.kind == Location::kOnVertex) {
        existed = true;
        return tri.v[where.index];
    }
    const std::uint32_t m = addVertex(u, v, x, y);
    if (where.kind == Location::kOnEdge) {
        if (!splitEdge(where.triangle, where.index, m)) {
            vertices.pop_back();
            return kNone;
        }
        return m;
    }
    const std::uint32_t a = tri.v[0], b = tri.v[1], c = tri.v[2];
    const std::array<std::uint32_t, 3> fresh[3] = {{a, b, m}, {b, c, m}, {c, a, m}};
    const std::uint32_t old[1] = {where.triangle};
    replace(old, 1, fresh, 3, nullptr, 0);
    return m;
}

void ParamMesh::replace(const std::uint32_t* old, std::size_t oldCount, const std::array<std::uint32_t, 3>* fresh,
                        std::size_t freshCount, const std::array<std::uint32_t, 2>* inherit, std::size_t inheritCount,
                        bool inheritConstrained, bool inheritFixed)
{
    std::vector<OuterEdge> outer;
    outer.reserve(3 * oldCount);
    auto isOld = [&](std::uint32_t t) { return std::find(old, old + oldCount, t) != old + oldCount; };
    for (std::size_t i = 0; i < oldCount; ++i) {
        const Triangle& tri = triangles[old[i]];
        for (int e = 0; e < 3; ++e) {
            if (tri.neighbour[e] != kNone && isOld(tri.neighbour[e]))
                continue;
            outer.push_back(OuterEdge{tri.v[next3(e)], tri.v[prev3(e)], tri.neighbour[e],
                                      ((tri.constrained >> e) & 1u) != 0, ((tri.fixed >> e) & 1u) != 0});
        }
    }
    for (std::size_t i = 0; i < oldCount; ++i)
        kill(old[i]);
    std::vector<std::uint32_t> made(freshCount);
    for (std::size_t i = 0; i < freshCount; ++i)
        made[i] = newTriangle(fresh[i][0], fresh[i][1], fresh[i][2]);
    for (std::size_t i = 0; i < freshCount; ++i) {
        Triangle& tri = triangles[made[i]];
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = tri.v[next3(e)];
            const std::uint32_t b = tri.v[prev3(e)];
            bool done = false;
            for (std::size_t j = 0; j < freshCount && !done; ++j) {
                if (j == i)
                    continue;
                const Triangle& o = triangles[made[j]];
                for (int f = 0; f < 3; ++f)
                    if (o.v[next3(f)] == b && o.v[prev3(f)] == a) {
                        tri.neighbour[e] = made[j];
                        for (std::size_t k = 0; k < inheritCount; ++k) {
                            const auto& edge = inherit[k];
                            if ((edge[0] == a && edge[1] == b) || (edge[0] == b && edge[1] == a)) {
                                if (inheritConstrained)
                                    tri.constrained |= std::uint8_t(1u << e);
                                if (inheritFixed)
                                    tri.fixed |= std::uint8_t(1u << e);
                            }
                        }
                        done = true;
                        break;
                    }
            }
            if (done)
                continue;
            for (const OuterEdge& edge : outer)
                if (edge.a == a && edge.b == b) {
                    if (edge.constrained)
                        tri.constrained |= std::uint8_t(1u << e);
                    if (edge.fixed)
                        tri.fixed |= std::uint8_t(1u << e);
                    link(made[i], e, edge.neighbour);
                    break;
                }
        }
    }
    for (std::uint32_t t : made)
        touchVertices(t);
}

bool ParamMesh::findEdge(std::uint32_t a, std::uint32_t b, std::uint32_t& triangle, int& edge) const
{
    bool found = false;
    forEachAround(a, [&](std::uint32_t t, int corner) {
        if (triangles[t].v[next3(corner)] != b)
            return true;
        triangle = t;
        edge = prev3(corner);
        found = true;
        return false;
    });
    return found;
}

bool ParamMesh::flip(std::uint32_t t, int e)
{
    const Triangle tri = triangles[t];
    const std::uint32_t u = tri.neighbour[e];
    if (u == kNone)
        return false;
    const std::uint32_t p = tri.v[e], q = tri.v[next3(e)], r = tri.v[prev3(e)];
    const Triangle& other = triangles[u];
    std::uint32_t s = kNone;
    for (int f = 0; f < 3; ++f)
        if (other.v[f] != q && other.v[f] != r)
            s = other.v[f];
    if (s == kNone || orient(p, q, s) <= 0 || orient(p, s, r) <= 0)
        return false;
    const std::uint32_t old[2] = {t, u};
    const std::array<std::uint32_t, 3> fresh[2] = {{p, q, s}, {p, s, r}};
    replace(old, 2, fresh, 2, nullptr, 0, false, false);
    return true;
}

bool ParamMesh::splitEdge(std::uint32_t t, int e, std::uint32_t m)
{
    const Triangle tri = triangles[t];
    const std::uint32_t p = tri.v[e], q = tri.v[next3(e)], r = tri.v[prev3(e)];
    if (orient(p, q, m) <= 0 || orient(p, m, r) <= 0)
        return false;
    const std::uint32_t u = tri.neighbour[e];
    const bool constrained = ((tri.constrained >> e) & 1u) != 0;
    const bool fixed = ((tri.fixed >> e) & 1u) != 0;
    const std::array<std::uint32_t, 2> halves[2] = {{q, m}, {m, r}};
    if (u == kNone) {
        const std::uint32_t old[1] = {t};
        const std::array<std::uint32_t, 3> fresh[2] = {{p, q, m}, {p, m, r}};
        replace(old, 1, fresh, 2, nullptr, 0, false, false);
        // The halves are boundary edges: set their flags directly.
        if (constrained || fixed)
            for (const auto& h : halves) {
                std::uint32_t ht;
                int he;
                if (findEdge(h[0], h[1], ht, he)) {
                    if (constrained)
                        triangles[ht].constrained |= std::uint8_t(1u << he);
                    if (fixed)
                        triangles[ht].fixed |= std::uint8_t(1u << he);
                }
            }
        return true;
    }
    const Triangle& other = triangles[u];
    std::uint32_t s = kNone;
    for (int f = 0; f < 3; ++f)
        if (other.v[f] != q && other.v[f] != r)
            s = other.v[f];
    if (s == kNone || orient(s, r, m) <= 0 || orient(s, m, q) <= 0)
        return false;
    const std::uint32_t old[2] = {t, u};
    const std::array<std::uint32_t, 3> fresh[4] = {{p, q, m}, {p, m, r}, {s, r, m}, {s, m, q}};
    replace(old, 2, fresh, 4, halves, 2, constrained, fixed);
    return true;
}

bool ParamMesh::triangulatePolygon(const std::vector<std::uint32_t>& polygon,
                                   std::vector<std::array<std::uint32_t, 3>>& out) const
{
    std::vector<std::uint32_t> ring = polygon;
    std::size_t guard = 0;
    while (ring.size() > 3) {
        const std::size_t n = ring.size();
        bool cut = false;
        for (std::size_t i = 0; i < n && !cut; ++i) {
            const std::uint32_t a = ring[(i + n - 1) % n], b = ring[i], c = ring[(i + 1) % n];
            if (orient(a, b, c) <= 0)
                continue;
            bool empty = true;
            for (std::size_t j = 0; j < n && empty; ++j) {
                const std::uint32_t w = ring[j];
                if (w == a || w == b || w == c)
                    continue;
                if (orient(a, b, w) >= 0 && orient(b, c, w) >= 0 && orient(c, a, w) >= 0)
                    empty = false;
            }
            if (!empty)
                continue;
            out.push_back({a, b, c});
            ring.erase(ring.begin() + std::ptrdiff_t(i));
            cut = true;
        }
        if (!cut || ++guard > 4 * polygon.size())
            return false;
    }
    if (ring.size() == 3) {
        if (orient(ring[0], ring[1], ring[2]) <= 0)
            return false;
        out.push_back({ring[0], ring[1], ring[2]});
    }
    return true;
}

bool ParamMesh::removeVertex(std::uint32_t a)
{
    std::vector<std::uint32_t> fan;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> linkEdges;
    bool blocked = false;
    forEachAround(a, [&](std::uint32_t t, int c) {
        const Triangle& tri = triangles[t];
        // The two edges at a: opposite corners c + 1 and c + 2.
        if (((tri.constrained >> next3(c)) & 1u) || ((tri.constrained >> prev3(c)) & 1u))
            blocked = true;
        fan.push_back(t);
        linkEdges.emplace_back(tri.v[next3(c)], tri.v[prev3(c)]);
        return true;
    });
    if (blocked || fan.size() < 2)
        return false;
    // Chain the link edges p -> q into a polygon.
    std::vector<std::uint32_t> polygon;
    std::uint32_t first = kNone;
    for (const auto& edge : linkEdges) {
        bool hasIncoming = false;
        for (const auto& other : linkEdges)
            if (other.second == edge.first)
                hasIncoming = true;
        if (!hasIncoming)
            first = edge.first;
    }
    const bool open = first != kNone;
    if (!open)
        first = linkEdges.front().first;
    std::uint32_t current = first;
    for (std::size_t step = 0; step <= linkEdges.size(); ++step) {
        polygon.push_back(current);
        std::uint32_t next = kNone;
        for (const auto& edge : linkEdges)
            if (edge.first == current)
                next = edge.second;
        if (next == kNone || next == first)
            break;
        current = next;
    }
    if (open) {
        // Closing edge from the last back to the first: a must lie on it.
        if (polygon.size() != linkEdges.size() + 1 || orient(polygon.back(), polygon.front(), a) != 0)
            return false;
    } else if (polygon.size() != linkEdges.size()) {
        return false;
    }
    std::vector<std::array<std::uint32_t, 3>> fresh;
    if (!triangulatePolygon(polygon, fresh))
        return false;
    replace(fan.data(), fan.size(), fresh.data(), fresh.size(), nullptr, 0, false, false);
    vertices[a].triangle = kNone;
    return true;
}

bool ParamMesh::collapsible(std::uint32_t v, std::uint32_t w, std::vector<std::uint32_t>& link) const
{
    link.clear();
    bool blocked = false, touchesW = false, boundary = false;
    std::uint32_t boundaryOther = kNone;
    std::size_t fan = 0;
    forEachAround(v, [&](std::uint32_t t, int c) {
        const Triangle& tri = triangles[t];
        const int ex = prev3(c), ey = next3(c); // edges v -> x (opposite y) and y -> v (opposite x)
        if (((tri.constrained | tri.fixed) >> ex) & 1u || ((tri.constrained | tri.fixed) >> ey) & 1u)
            blocked = true;
        const std::uint32_t x = tri.v[next3(c)], y = tri.v[prev3(c)];
        if (tri.neighbour[ex] == kNone) {
            boundary = true;
            if (x != w)
                boundaryOther = x;
        }
        if (tri.neighbour[ey] == kNone) {
            boundary = true;
            if (y != w)
                boundaryOther = y;
        }
        if (x == w || y == w) {
            touchesW = true;
        } else if (orient(w, x, y) <= 0) {
            blocked = true;
        }
        for (std::uint32_t z : {x, y})
            if (z != w && std::find(link.begin(), link.end(), z) == link.end())
                link.push_back(z);
        ++fan;
        return !blocked;
    });
    if (blocked || !touchesW || fan < 2)
        return false;
    if (boundary) {
        // w must be a boundary neighbour, in line with v and the other one.
        std::uint32_t t;
        int e;
        const bool vw = findEdge(v, w, t, e), wv = findEdge(w, v, t, e);
        if (vw == wv || boundaryOther == kNone || orient(w, v, boundaryOther) != 0)
            return false;
    }
    // Link condition: the only neighbours v and w share are the third
    // vertices of the triangles on edge (v, w) (else an edge would double).
    std::vector<std::uint32_t> wings;
    forEachAround(v, [&](std::uint32_t t, int c) {
        const Triangle& tri = triangles[t];
        const std::uint32_t x = tri.v[next3(c)], y = tri.v[prev3(c)];
        if (x == w)
            wings.push_back(y);
        if (y == w)
            wings.push_back(x);
        return true;
    });
    bool doubled = false;
    forEachAround(w, [&](std::uint32_t t, int c) {
        const Triangle& tri = triangles[t];
        for (std::uint32_t z : {tri.v[next3(c)], tri.v[prev3(c)]})
            if (z != v && std::find(link.begin(), link.end(), z) != link.end() &&
                std::find(wings.begin(), wings.end(), z) == wings.end())
                doubled = true;
        return !doubled;
    });
    return !doubled;
}

void ParamMesh::collapse(std::uint32_t v, std::uint32_t w)
{
    std::vector<std::uint32_t> fan;
    std::vector<std::array<std::uint32_t, 3>> fresh;
    forEachAround(v, [&](std::uint32_t t, int c) {
        const Triangle& tri = triangles[t];
        fan.push_back(t);
        const std::uint32_t x = tri.v[next3(c)], y = tri.v[prev3(c)];
        if (x != w && y != w)
            fresh.push_back({w, x, y});
        return true;
    });
    replace(fan.data(), fan.size(), fresh.data(), fresh.size(), nullptr, 0);
    vertices[v].triangle = kNone;
}

bool ParamMesh::firstCrossing(std::uint32_t a, std::uint32_t b, std::uint32_t& through,
                              std::vector<std::pair<std::uint32_t, std::uint32_t>>& crossed, bool& hitsConstraint)
{
    through = kNone;
    hitsConstraint = false;
    crossed.clear();
    const Vertex& va = vertices[a];
    const Vertex& vb = vertices[b];
    auto ahead = [&](std::uint32_t p) {
        const Vertex& vp = vertices[p];
        return (vp.x - va.x) * (vb.x - va.x) + (vp.y - va.y) * (vb.y - va.y) > 0;
    };
    std::uint32_t t = kNone, p = kNone, q = kNone;
    bool stop = false;
    forEachAround(a, [&](std::uint32_t tri, int c) {
        if (stop)
            return false;
        const std::uint32_t x = triangles[tri].v[next3(c)];
        const std::uint32_t y = triangles[tri].v[prev3(c)];
        const std::int64_t ox = orient(a, b, x);
        const std::int64_t oy = orient(a, b, y);
        if (ox == 0 && ahead(x)) {
            through = x;
            stop = true;
        } else if (oy == 0 && ahead(y)) {
            through = y;
            stop = true;
        } else if (ox < 0 && oy > 0) {
            t = tri;
            p = x;
            q = y;
            stop = true;
        }
        return !stop;
    });
    if (through != kNone)
        return true;
    if (t == kNone)
        return false;
    for (std::size_t guard = 0; guard <= triangles.size(); ++guard) {
        // Edge p -> q of t is crossed, p on the right of a -> b, q on the left.
        int e = 0;
        const Triangle& tri = triangles[t];
        for (int i = 0; i < 3; ++i)
            if (tri.v[next3(i)] == p && tri.v[prev3(i)] == q)
                e = i;
        if ((tri.constrained >> e) & 1u) {
            hitsConstraint = true;
            // Where a -> b meets p -> q, in parameters.
            const Vertex& vp = vertices[p];
            const Vertex& vq = vertices[q];
            const double d1 = double(orient(a, b, p)), d2 = double(orient(a, b, q));
            const double s = d1 / (d1 - d2);
            crossU = vp.u + s * (vq.u - vp.u);
            crossV = vp.v + s * (vq.v - vp.v);
            crossA = p;
            crossB = q;
            return true;
        }
        crossed.emplace_back(p, q);
        const std::uint32_t u = tri.neighbour[e];
        if (u == kNone)
            return false;
        std::uint32_t s = kNone;
        for (std::uint32_t w : triangles[u].v)
            if (w != p && w != q)
                s = w;
        if (s == b)
            return true;
        const std::int64_t o = orient(a, b, s);
        if (o == 0) {
            through = s;
            return true;
        }
        if (o > 0)
            q = s;
        else
            p = s;
        t = u;
    }
    return false;
}

ParamMesh::SegmentResult ParamMesh::insertSegment(std::uint32_t a, std::uint32_t b, const PassThrough& passThrough)
{
    pieces.clear();
    touchVertex = kNone;
    std::uint32_t start = a;
    std::size_t restarts = 0;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> crossed;
    while (start != b) {
        std::uint32_t t;
        int e;
        std::uint32_t end = b;
        bool have = findEdge(start, b, t, e) || findEdge(b, start, t, e);
        if (!have) {
            std::uint32_t through = kNone;
            bool hits = false;
            if (!firstCrossing(start, b, through, crossed, hits))
                return SegmentResult::kStuck;
            if (hits)
                return SegmentResult::kCrossesConstraint;
            if (through != kNone) {
                if (vertices[through].loop >= 0) {
                    touchVertex = through;
                    return SegmentResult::kTouchesVertex;
                }
                if (!passThrough(through)) {
                    if (removeVertex(through)) {
                        if (++restarts > vertices.size())
                            return SegmentResult::kStuck;
                        continue;
                    }
                }
                vertices[through].loop = vertices[a].loop;
                end = through;
            }
            // Sloan's flips until start -> end is an edge.
            std::deque<std::pair<std::uint32_t, std::uint32_t>> queue(crossed.begin(), crossed.end());
            const std::size_t limit = 64 * queue.size() * queue.size() + 1024;
            for (std::size_t guard = 0; !queue.empty(); ++guard) {
                if (guard > limit)
                    return SegmentResult::kStuck;
                const auto edge = queue.front();
                queue.pop_front();
                std::uint32_t et;
                int ee;
                if (!findEdge(edge.first, edge.second, et, ee) && !findEdge(edge.second, edge.first, et, ee))
                    continue;
                const std::uint32_t r = triangles[et].v[ee];
                const std::uint32_t other = triangles[et].neighbour[ee];
                if (other == kNone)
                    return SegmentResult::kStuck;
                std::uint32_t s = kNone;
                for (std::uint32_t w : triangles[other].v)
                    if (w != edge.first && w != edge.second)
                        s = w;
                if (flip(et, ee)) {
                    const std::int64_t orr = orient(start, end, r);
                    const std::int64_t os = orient(start, end, s);
                    if ((orr > 0 && os < 0) || (orr < 0 && os > 0))
                        queue.emplace_back(orr < 0 ? r : s, orr < 0 ? s : r);
                } else {
                    queue.push_back(edge);
                }
            }
            if (!findEdge(start, end, t, e) && !findEdge(end, start, t, e))
                return SegmentResult::kStuck;
        }
        // Mark both sides constrained.
        std::uint32_t t1;
        int e1;
        if (findEdge(start, end, t1, e1))
            triangles[t1].constrained |= std::uint8_t(1u << e1);
        if (findEdge(end, start, t1, e1))
            triangles[t1].constrained |= std::uint8_t(1u << e1);
        pieces.emplace_back(start, end);
        start = end;
    }
    return SegmentResult::kInserted;
}

std::string ParamMesh::check() const
{
    for (std::uint32_t t = 0; t < triangles.size(); ++t) {
        const Triangle& tri = triangles[t];
        if (!tri.alive)
            continue;
        if (orient(tri.v[0], tri.v[1], tri.v[2]) <= 0)
            return "triangle " + std::to_string(t) + " not ccw";
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t n = tri.neighbour[e];
            if (n == kNone)
                continue;
            if (!triangles[n].alive)
                return "triangle " + std::to_string(t) + " links a dead one";
            const std::uint32_t a = tri.v[next3(e)], b = tri.v[prev3(e)];
            bool back = false;
            for (int f = 0; f < 3; ++f)
                if (triangles[n].neighbour[f] == t && triangles[n].v[next3(f)] == b && triangles[n].v[prev3(f)] == a)
                    back = true;
            if (!back)
                return "triangle " + std::to_string(t) + " edge " + std::to_string(e) + " not linked back";
        }
        for (std::uint32_t v : tri.v) {
            const std::uint32_t vt = vertices[v].triangle;
            if (vt == kNone || !triangles[vt].alive)
                return "vertex " + std::to_string(v) + " has no alive triangle but triangle " + std::to_string(t) +
                       " uses it";
            const Triangle& o = triangles[vt];
            if (o.v[0] != v && o.v[1] != v && o.v[2] != v)
                return "vertex " + std::to_string(v) + " points at triangle " + std::to_string(vt) +
                       " which does not hold it";
            bool found = false;
            forEachAround(v, [&](std::uint32_t u, int) {
                found = found || u == t;
                return !found;
            });
            if (!found)
                return "vertex " + std::to_string(v) + "'s fan misses triangle " + std::to_string(t);
        }
    }
    return {};
}

} // namespace q3::nurbs
