// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// What the wireframe renderer draws of a general polygon, a polyhedron and a
// triangle grid: the edges of their decompositions. A general polygon's are
// its contours' outlines (no diagonal of the triangulation); a polyhedron's
// the sides its edge flags name plus its listed edges; a grid's every side
// of every facet. Compared as sets of segments between positions, written
// out here from the data.

#include "QD3D.h"
#include "geometry/Decompose.h"
#include "geometry/GeneralPolygon.h"
#include "geometry/Polyhedron.h"
#include "geometry/TriGrid.h"

#include <gtest/gtest.h>

#include <array>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace q3 {
namespace {

using Point = std::array<float, 3>;
using Segment = std::pair<Point, Point>;

Segment segment(const TQ3Point3D& a, const TQ3Point3D& b)
{
    const Point p{a.x, a.y, a.z}, q{b.x, b.y, b.z};
    return p < q ? Segment{p, q} : Segment{q, p};
}

class EdgeCollector final : public PrimitiveSink {
public:
    void draw(const MeshView& mesh, const AttributeSet*) override
    {
        auto at = [&](std::uint32_t i) {
            return TQ3Point3D{mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2]};
        };
        for (std::size_t e = 0; e < mesh.edgeCount; ++e)
            edges.insert(segment(at(mesh.edges[2 * e]), at(mesh.edges[2 * e + 1])));
        triangles += mesh.triangleCount;
    }
    std::set<Segment> edges;
    std::size_t triangles = 0;
};

// Immediate-mode geometries decompose without asking for subdivision.
class NoSubdivision final : public DecomposeContext {
public:
    SubdivisionMeasure subdivisionMeasure() const override { return SubdivisionMeasure{}; }
};

template <class G>
EdgeCollector decompose(const typename G::DataType& data)
{
    G::validate(&data);
    const G geometry(BorrowData{}, data);
    EdgeCollector collector;
    geometry.decompose(NoSubdivision{}, collector);
    return collector;
}

TEST(PolygonsWireframe, AGeneralPolygonShowsItsContoursAndNoDiagonal)
{
    TQ3Vertex3D outer[5] = {{{0, 0, 0}, nullptr}, {{6, 0, 0}, nullptr}, {{6, 6, 0}, nullptr},
                            {{3, 2, 0}, nullptr}, {{0, 6, 0}, nullptr}};
    TQ3Vertex3D hole[3] = {{{2, 0.5f, 0}, nullptr}, {{4, 0.5f, 0}, nullptr}, {{3, 1.5f, 0}, nullptr}};
    TQ3GeneralPolygonContourData contours[2] = {{5, outer}, {3, hole}};
    const TQ3GeneralPolygonData data{2, contours, kQ3GeneralPolygonShapeHintComplex, nullptr};
    const EdgeCollector got = decompose<GeneralPolygon>(data);
    std::set<Segment> expected;
    for (int i = 0; i < 5; ++i)
        expected.insert(segment(outer[i].point, outer[(i + 1) % 5].point));
    for (int i = 0; i < 3; ++i)
        expected.insert(segment(hole[i].point, hole[(i + 1) % 3].point));
    EXPECT_EQ(got.edges, expected);
    EXPECT_EQ(got.triangles, 8u - 2u + 2u); // n - 2 + 2 * holes for a bridged ear clipping
}

TEST(PolygonsWireframe, APolyhedronShowsTheFlaggedSidesAndItsListedEdges)
{
    TQ3Vertex3D v[4] = {{{0, 0, 0}, nullptr}, {{2, 0, 0}, nullptr}, {{0, 2, 0}, nullptr}, {{0, 0, 2}, nullptr}};
    TQ3PolyhedronTriangleData triangles[4] = {{{0, 2, 1}, kQ3PolyhedronEdge01, nullptr},
                                              {{0, 1, 3}, kQ3PolyhedronEdge12 | kQ3PolyhedronEdge20, nullptr},
                                              {{1, 2, 3}, kQ3PolyhedronEdgeNone, nullptr},
                                              {{2, 0, 3}, kQ3PolyhedronEdgeNone, nullptr}};
    TQ3PolyhedronEdgeData edges[1] = {{{2, 3}, {2, 3}, nullptr}};
    const TQ3PolyhedronData data{4, v, 1, edges, 4, triangles, nullptr};
    const EdgeCollector got = decompose<Polyhedron>(data);
    const std::set<Segment> expected = {segment(v[0].point, v[2].point), segment(v[1].point, v[3].point),
                                        segment(v[3].point, v[0].point), segment(v[2].point, v[3].point)};
    EXPECT_EQ(got.edges, expected);
    EXPECT_EQ(got.triangles, 4u);
}

TEST(PolygonsWireframe, ATriangleGridShowsEverySideOfEveryFacet)
{
    constexpr unsigned long kRows = 3, kColumns = 4;
    std::vector<TQ3Vertex3D> v;
    for (unsigned long r = 0; r < kRows; ++r)
        for (unsigned long c = 0; c < kColumns; ++c)
            v.push_back({{float(c), float(r), 0}, nullptr});
    const TQ3TriGridData data{kRows, kColumns, v.data(), nullptr, nullptr};
    const EdgeCollector got = decompose<TriGrid>(data);
    std::set<Segment> expected;
    for (unsigned long r = 0; r < kRows; ++r)
        for (unsigned long c = 0; c < kColumns; ++c) {
            const TQ3Point3D& p = v[r * kColumns + c].point;
            if (c + 1 < kColumns)
                expected.insert(segment(p, v[r * kColumns + c + 1].point));
            if (r + 1 < kRows)
                expected.insert(segment(p, v[(r + 1) * kColumns + c].point));
            if (r + 1 < kRows && c + 1 < kColumns) // the diagonal alternates by column
                expected.insert(c % 2 == 0 ? segment(v[r * kColumns + c + 1].point, v[(r + 1) * kColumns + c].point)
                                           : segment(p, v[(r + 1) * kColumns + c + 1].point));
        }
    EXPECT_EQ(got.edges, expected);
    EXPECT_EQ(got.triangles, 2 * (kRows - 1) * (kColumns - 1));
}

} // namespace
} // namespace q3
