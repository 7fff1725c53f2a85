// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

#include "render/SingleCover.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace q3 {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// An edge with its ends in increasing order, and +1 for a use from the
// smaller end to the larger, -1 for the other way.
struct EdgeUse {
    std::uint64_t ends;
    int direction;
};

double distanceSquared(const WindowPoint& a, const WindowPoint& b)
{
    const double dx = a[0] - b[0], dy = a[1] - b[1];
    return dx * dx + dy * dy;
}

// The squared distance from p to the segment a b.
double toSegmentSquared(const WindowPoint& p, const WindowPoint& a, const WindowPoint& b)
{
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double length = dx * dx + dy * dy;
    double t = length > 0.0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length : 0.0;
    t = std::min(1.0, std::max(0.0, t));
    const WindowPoint nearest{a[0] + t * dx, a[1] + t * dy};
    return distanceSquared(p, nearest);
}

// The sign of the turn a, b, c, exactly enough for the crossing test: 0
// on a line.
int sideOf(const WindowPoint& a, const WindowPoint& b, const WindowPoint& c)
{
    const double cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    return (cross > 0.0) - (cross < 0.0);
}

// The squared distance between segments a b and c d: 0 when they cross,
// else the least of their ends' distances to the other.
double betweenSegmentsSquared(const WindowPoint& a, const WindowPoint& b, const WindowPoint& c,
                              const WindowPoint& d)
{
    const int abc = sideOf(a, b, c), abd = sideOf(a, b, d), cda = sideOf(c, d, a), cdb = sideOf(c, d, b);
    if (abc * abd < 0 && cda * cdb < 0)
        return 0.0;
    return std::min(std::min(toSegmentSquared(a, c, d), toSegmentSquared(b, c, d)),
                    std::min(toSegmentSquared(c, a, b), toSegmentSquared(d, a, b)));
}

} // namespace

bool boundaryLoop(const std::uint32_t* corners, std::size_t triangleCount, std::size_t vertexCount,
                  std::vector<std::uint32_t>& loop)
{
    loop.clear();
    if (triangleCount == 0 || corners == nullptr)
        return false;
    std::vector<EdgeUse> uses;
    uses.reserve(3 * triangleCount);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const std::uint32_t* v = corners + 3 * t;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t from = v[k], to = v[(k + 1) % 3];
            if (from >= vertexCount || to >= vertexCount || from == to)
                return false;
            const std::uint64_t low = std::min(from, to), high = std::max(from, to);
            uses.push_back(EdgeUse{low << 32 | high, from < to ? 1 : -1});
        }
    }
    std::sort(uses.begin(), uses.end(), [](const EdgeUse& a, const EdgeUse& b) { return a.ends < b.ends; });
    // Each vertex's one boundary edge out, by the vertex it goes to.
    std::vector<std::uint32_t> next(vertexCount, kNone);
    std::size_t edges = 0;
    std::uint32_t start = kNone;
    for (std::size_t i = 0; i < uses.size();) {
        const std::uint64_t ends = uses[i].ends;
        long net = 0;
        for (; i < uses.size() && uses[i].ends == ends; ++i)
            net += uses[i].direction;
        if (net == 0)
            continue;
        if (net != 1 && net != -1)
            return false;
        const std::uint32_t low = std::uint32_t(ends >> 32), high = std::uint32_t(ends & 0xFFFFFFFFu);
        const std::uint32_t from = net > 0 ? low : high, to = net > 0 ? high : low;
        if (next[from] != kNone)
            return false;
        next[from] = to;
        start = from;
        ++edges;
    }
    if (edges < 3)
        return false;
    // One loop through every boundary edge: back at the start after
    // exactly `edges` steps (an earlier return, or none, leaves edges
    // unvisited or a vertex visited twice).
    std::uint32_t at = start;
    for (std::size_t step = 0; step < edges; ++step) {
        if (at == kNone || (step > 0 && at == start)) {
            loop.clear();
            return false;
        }
        loop.push_back(at);
        at = next[at];
    }
    if (at != start) {
        loop.clear();
        return false;
    }
    return true;
}

bool simpleWithSlack(const WindowPoint* points, std::uint32_t offset, const std::vector<std::uint32_t>& loop,
                     double slack, LoopScratch& scratch)
{
    const std::size_t n = loop.size();
    if (n < 3)
        return false;
    const double apart = 3.0 * slack;
    const double apartSquared = apart * apart;
    const auto corner = [&](std::size_t i) -> const WindowPoint& { return points[std::size_t(offset) + loop[i % n]]; };
    // Side i runs from corner i to corner i + 1. Sides are swept by their
    // least x, each compared with the sides still open (whose x range,
    // widened by `apart`, reaches it).
    using Side = LoopScratch::Side;
    std::vector<Side>& sides = scratch.sides;
    sides.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const WindowPoint& a = corner(i);
        const WindowPoint& b = corner(i + 1);
        if (!std::isfinite(a[0]) || !std::isfinite(a[1]))
            return false;
        sides[i] = Side{std::min(a[0], b[0]) - apart, std::max(a[0], b[0]) + apart, std::min(a[1], b[1]) - apart,
                        std::max(a[1], b[1]) + apart, std::uint32_t(i)};
    }
    std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) { return a.x0 < b.x0; });
    std::vector<const Side*>& open = scratch.open;
    open.clear();
    for (const Side& side : sides) {
        open.erase(std::remove_if(open.begin(), open.end(), [&](const Side* o) { return o->x1 < side.x0; }),
                   open.end());
        for (const Side* other : open) {
            if (other->y1 < side.y0 || side.y1 < other->y0)
                continue;
            const std::size_t i = std::min(side.index, other->index), j = std::max(side.index, other->index);
            const WindowPoint& a = corner(i);
            const WindowPoint& b = corner(i + 1);
            const WindowPoint& c = corner(j);
            const WindowPoint& d = corner(j + 1);
            if (j == i + 1) {
                // Consecutive: they share b (= c); each keeps its other end
                // away from the other side.
                if (toSegmentSquared(a, c, d) <= apartSquared || toSegmentSquared(d, a, b) <= apartSquared)
                    return false;
            } else if (i == 0 && j == n - 1) {
                // The last side and the first share corner 0 (= a = d).
                if (toSegmentSquared(b, c, d) <= apartSquared || toSegmentSquared(c, a, b) <= apartSquared)
                    return false;
            } else if (betweenSegmentsSquared(a, b, c, d) <= apartSquared) {
                return false;
            }
        }
        open.push_back(&side);
    }
    return true;
}

} // namespace q3
