// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// What a lit render of a patch at fine screen-space subdivision (c1 = 6
// pixels) depends on besides the bound: vertex normals that agree with the
// triangles around them (a normal from degenerate partials at a pole or a
// collapsed edge, or a zero one, would light a spike), and a mesh without
// cracks (an edge with a triangle on one side only is on the domain's
// boundary, never a T-junction between rows). Patches: the samples' hill
// (samples/scenes/scenes.c), its half cylinder, and a whole sphere as one
// rational biquadratic patch (both v ends collapse to the poles, u closes
// on a seam). Normals are compared with the faces computed here from the
// drawn points.

#include "PatchReference.h"
#include "PixmapViewTest.h"
#include "Q3ApiTest.h"

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGeometry.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DView.h"

#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace q3test::patches;
using q3test::subdivision::cross;
using q3test::subdivision::dot;
using q3test::subdivision::norm;

constexpr unsigned long kWidth = 160;
constexpr unsigned long kHeight = 120;
constexpr float kC1 = 6.0f;
// Largest angle between a vertex normal and the face of a triangle at it.
const Real kMaxAngle = 0.5L; // radians, about 29 degrees
// Triangles checked: those whose face is within acos(kFacing) of the eye.
const Real kFacing = 0.5L;

TQ3RationalPoint4D point(float x, float y, float z, float w)
{
    return {x * w, y * w, z * w, w};
}

Patch hill()
{
    static const float heights[5][5] = {{0.0f, 0.1f, 0.2f, 0.1f, 0.0f},
                                        {0.1f, 0.5f, 0.7f, 0.4f, 0.0f},
                                        {0.2f, 0.7f, 1.3f, 0.6f, -0.1f},
                                        {0.1f, 0.4f, 0.6f, 0.2f, -0.4f},
                                        {0.0f, 0.0f, -0.1f, -0.4f, -0.8f}};
    Patch p;
    p.uOrder = p.vOrder = 4;
    p.numRows = p.numColumns = 5;
    for (int row = 0; row < 5; ++row)
        for (int column = 0; column < 5; ++column)
            p.points.push_back(
                point(-1.6f + 0.8f * float(column), heights[row][column] - 0.3f, 1.6f - 0.8f * float(row), 1.0f));
    p.uKnots = p.vKnots = {0, 0, 0, 0, 1, 2, 2, 2, 2};
    return p;
}

Patch halfCylinder()
{
    static const float arc[5][3] = {{1, 0, 1}, {1, 1, 0.70710678f}, {0, 1, 1}, {-1, 1, 0.70710678f}, {-1, 0, 1}};
    Patch p;
    p.uOrder = 3;
    p.vOrder = 2;
    p.numColumns = 5;
    p.numRows = 2;
    for (int row = 0; row < 2; ++row)
        for (int column = 0; column < 5; ++column)
            p.points.push_back(point(arc[column][0], arc[column][1] - 0.5f, row == 0 ? -1.4f : 1.4f, arc[column][2]));
    p.uKnots = {0, 0, 0, 1, 1, 2, 2, 2};
    p.vKnots = {0, 0, 1, 1};
    return p;
}

// The unit sphere: u a full circle around z (9 points), v a half circle
// from the south pole to the north pole (5 points), weights multiplied.
Patch sphere()
{
    const float s = 0.70710678f;
    const float circle[9][3] = {{1, 0, 1}, {1, 1, s},   {0, 1, 1},  {-1, 1, s}, {-1, 0, 1},
                                {-1, -1, s}, {0, -1, 1}, {1, -1, s}, {1, 0, 1}};
    const float meridian[5][3] = {{0, -1, 1}, {1, -1, s}, {1, 0, 1}, {1, 1, s}, {0, 1, 1}}; // radius, z, w
    Patch p;
    p.uOrder = p.vOrder = 3;
    p.numColumns = 9;
    p.numRows = 5;
    for (int row = 0; row < 5; ++row)
        for (int column = 0; column < 9; ++column)
            p.points.push_back(point(circle[column][0] * meridian[row][0], circle[column][1] * meridian[row][0],
                                     meridian[row][1], circle[column][2] * meridian[row][2]));
    p.uKnots = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    p.vKnots = {0, 0, 0, 1, 1, 2, 2, 2};
    return p;
}

class NURBPatchLitRegressionTest : public q3test::PixmapViewTest {
protected:
    NURBPatchLitRegressionTest() : PixmapViewTest(kWidth, kHeight) {}

    void setCamera(const TQ3Point3D& eye)
    {
        TQ3ViewAngleAspectCameraData& camera = m_camera;
        camera = TQ3ViewAngleAspectCameraData{};
        camera.cameraData.placement = {eye, {0, 0, 0}, {0, 1, 0}};
        camera.cameraData.range = {0.5f, 100.0f};
        camera.cameraData.viewPort = {{-1, 1}, 2, 2};
        camera.fov = 0.75f;
        camera.aspectRatioXToY = float(kWidth) / float(kHeight);
        TQ3CameraObject object = Q3ViewAngleAspectCamera_New(&camera);
        ASSERT_EQ(Q3View_SetCamera(m_view, object), kQ3Success);
        Q3Object_Dispose(object);
    }

    // Decomposes the patch in a rendering loop under screen-space c1 = kC1
    // and checks its normals and its edges.
    void check(Patch& p, const std::string& what)
    {
        const Vec3 eye = q3test::subdivision::toVec(m_camera.cameraData.placement.cameraLocation);
        const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodScreenSpace, kC1, kC1};
        TQ3NURBPatchData data = p.data();
        TQ3GeometryObject object = Q3NURBPatch_New(&data);
        ASSERT_NE(object, nullptr) << what;
        ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        ASSERT_EQ(Q3SubdivisionStyle_Submit(&style, m_view), kQ3Success);
        EXPECT_EQ(Q3Geometry_Submit(object, m_view), kQ3Success);
        TQ3GeometryObject mesh = Q3Geometry_GetDecomposed(object, m_view);
        EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
        Q3Object_Dispose(object);
        EXPECT_EQ(Q3Warning_Get(nullptr), kQ3WarningNone) << what;
        ASSERT_NE(mesh, nullptr) << what;
        TQ3TriMeshData out{};
        ASSERT_EQ(Q3TriMesh_GetData(mesh, &out), kQ3Success);
        Q3Object_Dispose(mesh);
        std::vector<Vec3> points, normals;
        std::vector<std::pair<Real, Real>> uvs;
        for (unsigned long i = 0; i < out.numPoints; ++i)
            points.push_back(q3test::subdivision::toVec(out.points[i]));
        for (unsigned long a = 0; a < out.numVertexAttributeTypes; ++a) {
            const TQ3TriMeshAttributeData& attribute = out.vertexAttributeTypes[a];
            for (unsigned long i = 0; i < out.numPoints; ++i)
                if (attribute.attributeType == kQ3AttributeTypeNormal) {
                    const TQ3Vector3D n = static_cast<const TQ3Vector3D*>(attribute.data)[i];
                    normals.push_back({n.x, n.y, n.z});
                } else if (attribute.attributeType == kQ3AttributeTypeSurfaceUV) {
                    const TQ3Param2D uv = static_cast<const TQ3Param2D*>(attribute.data)[i];
                    uvs.emplace_back(uv.u, uv.v);
                }
        }
        ASSERT_EQ(normals.size(), points.size()) << what;
        ASSERT_EQ(uvs.size(), points.size()) << what;
        for (std::size_t i = 0; i < normals.size(); ++i) {
            const Real length = norm(normals[i]);
            ASSERT_TRUE(std::isfinite(double(length)) && std::fabs(double(length) - 1.0) < 1e-4)
                << what << " vertex " << i << " has a normal of length " << double(length);
        }
        const Real size = p.size();
        // Triangles off the pane are not refined (and not seen): only those
        // with a vertex on it are checked.
        const q3test::subdivision::ScreenMap map(m_camera, {{0, 0}, {float(kWidth), float(kHeight)}});
        std::vector<bool> seen(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            Real x, y;
            seen[i] = map.map(points[i], x, y) && x >= 0 && x <= Real(kWidth) && y >= 0 && y <= Real(kHeight);
        }
        std::size_t checked = 0;
        std::map<std::pair<unsigned long, unsigned long>, int> edges;
        Real worst = 0;
        for (unsigned long t = 0; t < out.numTriangles; ++t) {
            const unsigned long* v = out.triangles[t].pointIndices;
            for (int k = 0; k < 3; ++k)
                ++edges[{std::min(v[k], v[(k + 1) % 3]), std::max(v[k], v[(k + 1) % 3])}];
            if (!seen[v[0]] && !seen[v[1]] && !seen[v[2]])
                continue;
            const Vec3 face = cross(points[v[1]] - points[v[0]], points[v[2]] - points[v[0]]);
            const Real area = norm(face);
            if (!(area > 1e-6L * size * size))
                continue; // no direction to speak of (a sliver, or at a pole)
            // Only triangles that face the eye: one seen edge-on or from
            // behind spans much of the surface in few pixels, and its face
            // can differ from the normals at its corners without a spike.
            const Vec3 toEye = eye - Real(1) / 3 * (points[v[0]] + points[v[1]] + points[v[2]]);
            if (dot(face, toEye) < kFacing * area * norm(toEye))
                continue;
            ++checked;
            for (int k = 0; k < 3; ++k) {
                const Real c = dot(face, normals[v[k]]) / area;
                const Real angle = std::acos(std::max(Real(-1), std::min(Real(1), c)));
                worst = std::max(worst, angle);
                EXPECT_LE(angle, kMaxAngle) << what << ": triangle " << t << ", vertex " << v[k] << " at (u, v) = ("
                                            << double(uvs[v[k]].first) << ", " << double(uvs[v[k]].second) << ")";
            }
        }
        // An edge with a triangle on one side only runs along the domain's
        // boundary (both ends on one side of it).
        const Real u0 = p.u0(), u1 = p.u1(), v0 = p.v0(), v1 = p.v1();
        const Real tolerance = 1e-6L * std::max(u1 - u0, v1 - v0) + 1e-6L * std::max({std::fabs(u0), std::fabs(u1),
                                                                                         std::fabs(v0), std::fabs(v1)});
        auto on = [&](unsigned long i, int side) {
            const Real value = side < 2 ? uvs[i].first : uvs[i].second;
            const Real edge = side == 0 ? u0 : side == 1 ? u1 : side == 2 ? v0 : v1;
            return std::fabs(value - edge) <= tolerance;
        };
        std::size_t open = 0;
        for (const auto& edge : edges) {
            EXPECT_LE(edge.second, 2) << what << ": an edge with more than two triangles";
            if (edge.second != 1)
                continue;
            ++open;
            bool boundary = false;
            for (int side = 0; side < 4; ++side)
                boundary = boundary || (on(edge.first.first, side) && on(edge.first.second, side));
            EXPECT_TRUE(boundary) << what << ": a crack between vertices " << edge.first.first << " and "
                                  << edge.first.second;
        }
        EXPECT_GT(checked, out.numTriangles / 5) << what << " should be mostly in view and facing the eye";
        std::printf("[ patches ] %s: %lu triangles at c1 = %g pixels (%zu with a vertex on the pane), vertex "
                    "normals within %.3f rad of their faces, %zu boundary edges\n",
                    what.c_str(), out.numTriangles, double(kC1), checked, double(worst), open);
        Q3TriMesh_EmptyData(&out);
    }

    TQ3ViewAngleAspectCameraData m_camera{};
};

TEST_F(NURBPatchLitRegressionTest, AtSixPixelsNormalsFollowTheFacesAndNothingCracks)
{
    Patch a = hill();
    setCamera({0.0f, 3.8f, 5.4f});
    check(a, "the samples' hill");
    Patch b = halfCylinder();
    setCamera({4.2f, 3.0f, 1.8f});
    check(b, "the half cylinder");
    Patch c = sphere();
    setCamera({2.4f, 1.8f, 2.6f});
    check(c, "the sphere with its poles");
    // From above a pole.
    setCamera({0.3f, 0.2f, 3.2f});
    check(c, "the sphere seen from above its north pole");
}

} // namespace
