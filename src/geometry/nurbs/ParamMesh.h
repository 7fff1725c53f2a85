// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

// A triangulation of a rectangle of parameters (a patch's (u, v) domain) that
// can take constraint segments (trim loops), lose vertices, split edges and
// flip them: the planar half of surface tessellation. Plain values in, plain
// values out.
//
// Robustness: every vertex has an integer key (x, y) on a grid of kGrid x
// kGrid cells over the domain besides its exact parameters, and every
// decision about the plane (which side of a line, which triangle holds a
// point, whether a quadrilateral is convex) is an orientation test on the
// keys, computed exactly in 64-bit integers. So the mesh stays a valid
// triangulation of the keys whatever the input: no two vertices share a key,
// and every alive triangle is counterclockwise on the keys. The exact
// parameters, which are what the surface is evaluated at, differ from the
// keys by at most half a cell (1 / 2^29 of the domain).
namespace q3::nurbs {

class ParamMesh {
public:
    /// Cells per side of the key grid. Keys are in [0, kGrid]; differences of
    /// keys fit 30 bits and their products 61, so orientation tests are exact.
    static constexpr std::int64_t kGrid = std::int64_t{1} << 28;
    static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

    struct Vertex {
        std::int64_t x = 0;
        std::int64_t y = 0;
        double u = 0.0;
        double v = 0.0;
        std::uint32_t triangle = kNone; ///< an alive triangle using it, or kNone
        std::int32_t loop = -1;         ///< the trim loop it lies on, or -1
    };

    /// Edge i of a triangle runs from corner i + 1 to corner i + 2 (mod 3),
    /// opposite corner i; neighbour[i] is the triangle across it (kNone on
    /// the boundary). Corners are counterclockwise on the keys.
    struct Triangle {
        std::array<std::uint32_t, 3> v{};
        std::array<std::uint32_t, 3> neighbour{kNone, kNone, kNone};
        std::uint8_t constrained = 0; ///< bit i: edge i is part of a trim loop
        std::uint8_t fixed = 0;       ///< bit i: edge i may not be flipped (a knot line)
        bool alive = true;
    };

    /// Where a point fell.
    struct Location {
        enum Kind { kOutside, kInside, kOnEdge, kOnVertex } kind = kOutside;
        std::uint32_t triangle = kNone;
        int index = 0; ///< kOnEdge: the edge; kOnVertex: the corner
    };

    std::vector<Vertex> vertices;
    std::vector<Triangle> triangles;

    /// The key of parameters inside [u0, u1] x [v0, v1] (clamped).
    void setDomain(double u0, double u1, double v0, double v1);
    std::int64_t keyX(double u) const;
    std::int64_t keyY(double v) const;

    std::uint32_t addVertex(double u, double v, std::int64_t x, std::int64_t y);
    /// Replaces the triangles by `corners` (each counterclockwise on the
    /// keys) and links neighbours. fixedEdges lists vertex pairs whose edge
    /// may not be flipped.
    void build(const std::vector<std::array<std::uint32_t, 3>>& corners);
    void markFixed(std::uint32_t a, std::uint32_t b);

    /// 2 x the signed area of (a, b, c) on the keys: > 0 counterclockwise.
    std::int64_t orient(std::uint32_t a, std::uint32_t b, std::uint32_t c) const;
    static std::int64_t orient(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by,
                               std::int64_t cx, std::int64_t cy);

    /// Finds the triangle holding key (x, y) by walking from `hint` (any
    /// alive triangle; a stochastic walk, with a scan of every triangle as
    /// a fallback, so it always ends).
    Location locate(std::int64_t x, std::int64_t y, std::uint32_t hint) const;

    /// Inserts a vertex at key (x, y) (parameters u, v). When a vertex already
    /// has that key it is returned and `existed` set. Returns kNone for a key
    /// outside the mesh.
    std::uint32_t insertVertex(double u, double v, std::int64_t x, std::int64_t y, std::uint32_t hint,
                               bool& existed);

    /// The alive triangle holding the directed edge a -> b, and the edge's
    /// index in it; false when there is none.
    bool findEdge(std::uint32_t a, std::uint32_t b, std::uint32_t& triangle, int& edge) const;

    /// Calls f(triangle, corner) for every alive triangle around vertex a,
    /// counterclockwise, until f returns false.
    template <class F>
    void forEachAround(std::uint32_t a, F&& f) const;

    /// Flips edge `edge` of `triangle` when the quadrilateral of its two
    /// triangles is strictly convex; false (nothing changed) otherwise.
    bool flip(std::uint32_t triangle, int edge);

    /// Splits edge `edge` of `triangle` at a new vertex m (already added);
    /// false (nothing changed) when a new triangle would not be strictly
    /// counterclockwise. The halves inherit the edge's flags.
    bool splitEdge(std::uint32_t triangle, int edge, std::uint32_t m);

    /// Removes a vertex that is not on a constrained edge: its triangles are
    /// replaced by a triangulation of the polygon around it (for a vertex on
    /// the boundary, closed by the straight line between its two boundary
    /// neighbours). False, nothing changed, when that is impossible.
    bool removeVertex(std::uint32_t a);

    /// Whether vertex v can be merged into its neighbour w (edge collapse):
    /// v is on no constrained or fixed edge; on the boundary, w is a boundary
    /// neighbour in line with v and v's other boundary neighbour (so the
    /// boundary keeps its shape); every triangle that replaces one of v's is
    /// strictly counterclockwise; no edge would be doubled. `link` receives
    /// the vertices the new edges from w go to.
    bool collapsible(std::uint32_t v, std::uint32_t w, std::vector<std::uint32_t>& link) const;
    /// Merges v into w (collapsible(v, w) must hold): v's triangles become
    /// w's, those on edge (v, w) go.
    void collapse(std::uint32_t v, std::uint32_t w);

    /// What insertSegment met.
    enum class SegmentResult {
        kInserted,
        kCrossesConstraint, ///< it crosses a constrained edge at (crossU, crossV)
        kTouchesVertex,     ///< it runs through a vertex of a trim loop (touchVertex)
        kStuck,             ///< the flips did not converge (not expected)
    };
    /// What to do with a vertex the segment runs exactly through (a vertex
    /// not on a trim loop): true keeps it as a vertex of the segment, false
    /// removes it from the mesh first.
    using PassThrough = std::function<bool(std::uint32_t vertex)>;

    /// Makes a -> b an edge of the mesh (by Sloan's flips) and marks it
    /// constrained; a vertex it runs through is kept (splitting the segment)
    /// or removed as passThrough says.
    SegmentResult insertSegment(std::uint32_t a, std::uint32_t b, const PassThrough& passThrough);
    double crossU = 0.0;
    double crossV = 0.0;
    std::uint32_t crossA = kNone; ///< kCrossesConstraint: the constrained edge met
    std::uint32_t crossB = kNone;
    std::uint32_t touchVertex = kNone;
    /// The constrained pieces insertSegment made, in order (a segment split
    /// at kept vertices gives several).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pieces;

    /// Kills triangles and unlinks them from their neighbours.
    void kill(std::uint32_t triangle);
    /// Points every vertex at an alive triangle using it, or kNone when none
    /// does (after killing triangles in bulk).
    void refreshVertexTriangles();

    std::size_t aliveCount() const { return m_alive; }
    /// Debug: the first inconsistency found (neighbour links, orientation,
    /// vertex triangles), or an empty string.
    std::string check() const;

private:
    /// Swaps the alive triangles `old` for `fresh` covering the same region:
    /// edges between fresh triangles are linked (and get the constrained and
    /// fixed flags when listed in `inherit`), the others take the neighbour
    /// and flags of the old edge with the same direction, or none.
    void replace(const std::uint32_t* old, std::size_t oldCount, const std::array<std::uint32_t, 3>* fresh,
                 std::size_t freshCount, const std::array<std::uint32_t, 2>* inherit, std::size_t inheritCount,
                 bool inheritConstrained = false, bool inheritFixed = false);
    void link(std::uint32_t t, int e, std::uint32_t other);
    void touchVertices(std::uint32_t t);
    std::uint32_t newTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c);
    bool triangulatePolygon(const std::vector<std::uint32_t>& polygon,
                            std::vector<std::array<std::uint32_t, 3>>& out) const;
    bool firstCrossing(std::uint32_t a, std::uint32_t b, std::uint32_t& through,
                       std::vector<std::pair<std::uint32_t, std::uint32_t>>& crossed, bool& hitsConstraint);

    double m_u0 = 0.0, m_u1 = 1.0, m_v0 = 0.0, m_v1 = 1.0;
    std::size_t m_alive = 0;
    mutable std::uint64_t m_random = 0x9E3779B97F4A7C15ull;
    std::vector<std::uint32_t> m_free;
};

template <class F>
void ParamMesh::forEachAround(std::uint32_t a, F&& f) const
{
    const std::uint32_t start = vertices[a].triangle;
    if (start == kNone || start >= triangles.size() || !triangles[start].alive)
        return;
    {
        const Triangle& first = triangles[start];
        if (first.v[0] != a && first.v[1] != a && first.v[2] != a)
            return;
    }
    auto cornerOf = [&](std::uint32_t t) {
        const Triangle& tri = triangles[t];
        return tri.v[0] == a ? 0 : tri.v[1] == a ? 1 : 2;
    };
    // Counterclockwise first (across the edge opposite corner + 1), then,
    // if the fan is open, clockwise from the start (opposite corner + 2).
    std::uint32_t t = start;
    std::size_t guard = 0;
    do {
        const int c = cornerOf(t);
        if (!f(t, c))
            return;
        t = triangles[t].neighbour[c == 2 ? 0 : c + 1];
        if (++guard > triangles.size())
            return;
    } while (t != kNone && t != start);
    if (t == start)
        return;
    const int c0 = cornerOf(start);
    t = triangles[start].neighbour[c0 == 0 ? 2 : c0 - 1];
    while (t != kNone && t != start) {
        const int c = cornerOf(t);
        if (!f(t, c))
            return;
        t = triangles[t].neighbour[c == 0 ? 2 : c - 1];
        if (++guard > triangles.size())
            return;
    }
}

} // namespace q3::nurbs
