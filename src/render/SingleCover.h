// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Whether a mesh's triangles, as the rasterizer places them, can cover no
// sample twice; if so, blending them in any order gives the same pixels,
// and a translucent mesh need not be sorted back to front (the QD3D Book's
// order, OffscreenRenderer.cpp, drawTranslucent) to be drawn as if it were.
//
// The argument is the degree of a map (the winding number of its
// boundary). Give every triangle the orientation of its corners on the
// screen. For a point p on no edge, the number of triangles covering p,
// each counted +1 if it turns counter-clockwise and -1 if clockwise, equals
// the winding number around p of the mesh's boundary: the sum of the
// triangles' edges, where an edge used once in each direction cancels.
// So if every triangle turns the same way, the count of triangles over p
// is that winding number's magnitude; and if the boundary is one simple
// closed polygon, it winds around any point at most once. Points on edges
// follow: near such a point at most one triangle covers each point off the
// edges, so the triangles meeting there only touch, and the rasterizer's
// fill rule, exact on snapped coordinates, gives a sample there to at
// most one of them. Multisampling changes where samples are, not this.
//
// The rasterizer computes window coordinates in float and snaps them to a
// subpixel grid, so the two conditions are checked with slack: each must
// still hold with every point moved by up to `slack` pixels in x and in y.
// Moved so, a triangle's doubled signed area changes by at most
// 2 slack (|e1|_1 + |e2|_1) + 8 slack^2 (e1, e2 two of its edges, |.|_1
// the sum of the components' magnitudes), and a point of a segment by at
// most sqrt(2) slack; two segments of the loop that share no end must be
// more than 3 slack apart, and two that share one must each keep its other
// end more than 3 slack from the other (else the two could come to lie on
// one another).

#ifndef Q3_RENDER_SINGLECOVER_H
#define Q3_RENDER_SINGLECOVER_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace q3 {

using WindowPoint = std::array<double, 2>;

/// The boundary of `triangleCount` triangles (three corner indices each,
/// below `vertexCount`) when it is one closed loop: the edges that the
/// triangles do not cancel (an edge cancels when as many triangles use it
/// from a to b as from b to a), each used once, joined end to start with no
/// vertex twice. `loop` gets its vertices in order, each followed by the
/// one its edge goes to; true. False, `loop` empty: there is no such loop
/// (no triangle, a corner index out of range, a triangle with two equal
/// corners, an edge left over twice in one direction, several loops, or
/// loops that share a vertex).
bool boundaryLoop(const std::uint32_t* corners, std::size_t triangleCount, std::size_t vertexCount,
                  std::vector<std::uint32_t>& loop);

/// The way the triangle a, b, c turns with each corner moved by up to
/// `slack` in x and in y: +1 counter-clockwise (x right, y up), -1
/// clockwise, 0 when a move that small could make it flat or turn it over.
/// (Inline: it runs once per triangle of every mesh tested.)
inline int turnWithSlack(const WindowPoint& a, const WindowPoint& b, const WindowPoint& c, double slack)
{
    const double e1x = b[0] - a[0], e1y = b[1] - a[1], e2x = c[0] - a[0], e2y = c[1] - a[1];
    const double doubledArea = e1x * e2y - e1y * e2x;
    const double abs1 = (e1x < 0.0 ? -e1x : e1x) + (e1y < 0.0 ? -e1y : e1y);
    const double abs2 = (e2x < 0.0 ? -e2x : e2x) + (e2y < 0.0 ? -e2y : e2y);
    const double change = 2.0 * slack * (abs1 + abs2) + 8.0 * slack * slack;
    // (The products' own rounding is far below `change` for any slack worth
    // asking for; a NaN or an infinity compares false both ways.)
    return (doubledArea > change) - (doubledArea < -change);
}

/// What simpleWithSlack works in, kept from call to call.
struct LoopScratch {
    struct Side {
        double x0, x1, y0, y1; // its corners' range, widened
        std::uint32_t index;   // side i runs from corner i to corner i + 1
    };
    std::vector<Side> sides;
    std::vector<const Side*> open;
};

/// Whether the closed polygon through points[offset + loop[i]], i in order,
/// stays simple (no two of its sides meet except consecutive ones at their
/// shared corner) with each point moved by up to `slack` in x and in y.
/// Fewer than three corners: false.
bool simpleWithSlack(const WindowPoint* points, std::uint32_t offset, const std::vector<std::uint32_t>& loop,
                     double slack, LoopScratch& scratch);

} // namespace q3

#endif
