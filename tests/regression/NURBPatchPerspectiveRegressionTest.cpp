// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Screen-space subdivision of patches that reach the eye of a perspective
// camera (behind it, through it, across its hither plane), the surface
// version of SubdivisionPerspectiveRegressionTest.cpp: the part of every
// triangle edge that is drawn (beyond the hither plane) is at most c1 pixels
// long on every triangle that can be seen (not all three vertices outside one
// plane of the view volume, computed here from the camera), triangles that
// cannot be seen are not held to it, and no patch gives in to the triangle
// cap (each ends far below it). Which vertices are beyond the hither plane and which triangles are
// outside the view is judged on the surface as PatchReference.h's evaluator
// computes it at each vertex's (u, v), not on the library's float vertices
// (which must lie there too); lengths are measured between the drawn
// vertices with SubdivisionReference.h's projection.
// (Vertices on the surface are checked by NURBPatchPropertyRegressionTest.)

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

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace q3test::patches;
using q3test::subdivision::ScreenMap;

constexpr unsigned long kWidth = 128;
constexpr unsigned long kHeight = 96;
constexpr float kHither = 0.5f;
constexpr unsigned kSeed = 20261202u;
constexpr int kPatches = 24;

class NURBPatchPerspectiveRegressionTest : public q3test::PixmapViewTest {
protected:
    NURBPatchPerspectiveRegressionTest() : PixmapViewTest(kWidth, kHeight) {}

    void SetUp() override
    {
        PixmapViewTest::SetUp();
        m_camera = eyeAtOrigin(kHither);
        useCamera(Q3ViewAngleAspectCamera_New(&m_camera));
    }

    // Draws the patch (retained and immediate) and decomposes it, in one
    // rendering loop under screen-space subdivision with c1; returns the
    // TriMesh's points and triangles.
    void render(Patch& patch, float c1, std::vector<Vec3>& points, std::vector<std::pair<Real, Real>>& uvs,
                std::vector<std::array<unsigned long, 3>>& triangles, bool& capped)
    {
        const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodScreenSpace, c1, c1};
        TQ3NURBPatchData data = patch.data();
        TQ3GeometryObject object = Q3NURBPatch_New(&data);
        ASSERT_NE(object, nullptr);
        EXPECT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        EXPECT_EQ(Q3SubdivisionStyle_Submit(&style, m_view), kQ3Success);
        EXPECT_EQ(Q3Geometry_Submit(object, m_view), kQ3Success);
        EXPECT_EQ(Q3NURBPatch_Submit(&data, m_view), kQ3Success);
        TQ3GeometryObject mesh = Q3Geometry_GetDecomposed(object, m_view);
        capped = Q3Warning_Get(nullptr) == kQ3WarningParameterOutOfRange;
        EXPECT_NE(mesh, nullptr);
        if (mesh != nullptr) {
            TQ3TriMeshData out{};
            EXPECT_EQ(Q3TriMesh_GetData(mesh, &out), kQ3Success);
            for (unsigned long i = 0; i < out.numPoints; ++i)
                points.push_back(q3test::subdivision::toVec(out.points[i]));
            for (unsigned long a = 0; a < out.numVertexAttributeTypes; ++a)
                if (out.vertexAttributeTypes[a].attributeType == kQ3AttributeTypeSurfaceUV) {
                    const TQ3Param2D* uv = static_cast<const TQ3Param2D*>(out.vertexAttributeTypes[a].data);
                    for (unsigned long i = 0; i < out.numPoints; ++i)
                        uvs.emplace_back(uv[i].u, uv[i].v);
                }
            for (unsigned long t = 0; t < out.numTriangles; ++t)
                triangles.push_back({out.triangles[t].pointIndices[0], out.triangles[t].pointIndices[1],
                                     out.triangles[t].pointIndices[2]});
            Q3TriMesh_EmptyData(&out);
            Q3Object_Dispose(mesh);
        }
        EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
        Q3Object_Dispose(object);
    }

    // The view volume of m_camera (eye at the origin looking down -z, y up,
    // view port [-1, 1]^2) as five plane values, each >= 0 inside: beyond
    // the hither plane, and within the four sides of the pyramid.
    void planeValues(const Vec3& p, Real out[5]) const
    {
        const Real across = 1 / std::tan(Real(m_camera.fov) / 2);
        const Real aspect = m_camera.aspectRatioXToY;
        const Real fx = aspect >= 1 ? across / aspect : across;
        const Real fy = aspect >= 1 ? across : across * aspect;
        const Real depth = -p.z;
        out[0] = depth - kHither;
        out[1] = depth - fx * p.x;
        out[2] = depth + fx * p.x;
        out[3] = depth - fy * p.y;
        out[4] = depth + fy * p.y;
    }

    bool outsideOnePlane(const Vec3& a, const Vec3& b, const Vec3& c) const
    {
        Real va[5], vb[5], vc[5];
        planeValues(a, va);
        planeValues(b, vb);
        planeValues(c, vc);
        for (int k = 0; k < 5; ++k)
            if (va[k] < 0 && vb[k] < 0 && vc[k] < 0)
                return true;
        return false;
    }

    TQ3ViewAngleAspectCameraData m_camera{};
};

TEST_F(NURBPatchPerspectiveRegressionTest, TheDrawnPieceOfEveryEdgeIsAtMostC1)
{
    std::mt19937 rng(kSeed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const ScreenMap map(m_camera, {{0, 0}, {float(kWidth), float(kHeight)}});
    std::size_t crossing = 0, largest = 0, cappedPatches = 0, hidden = 0;
    for (int index = 0; index < kPatches && !HasFatalFailure(); ++index) {
        PatchOptions options;
        options.uOrder = 2 + unsigned(index % 6);
        options.vOrder = 2 + unsigned((index + 2) % 6);
        options.repeatProbability = 0.3L;
        options.extraPoints = 3;
        Patch p = randomPatch(rng, options);
        // Around the eye: x, y over [-1.5, 1.5], z from about 1 (behind) to -3.
        const float sx = float(3.0 / double(p.numColumns - 1)), sy = float(3.0 / double(p.numRows - 1));
        const float dz = float(2.0 * unit(rng) - 1.0);
        for (unsigned long r = 0; r < p.numRows; ++r)
            for (unsigned long c = 0; c < p.numColumns; ++c) {
                TQ3RationalPoint4D& q = p.points[r * p.numColumns + c];
                const float x = -1.5f + sx * float(c), y = -1.5f + sy * float(r);
                const float z = q.z / q.w * 2.0f - 1.0f + dz - 1.5f * float(r) / float(p.numRows);
                q = {x * q.w, y * q.w, z * q.w, q.w};
            }
        if (index % 3 == 1)
            addRandomTrims(rng, p, 1 + index % 3);
        const float c1 = index % 2 == 0 ? 16.0f : 32.0f;
        std::vector<Vec3> points;
        std::vector<std::pair<Real, Real>> uvs;
        std::vector<std::array<unsigned long, 3>> triangles;
        bool capped = false;
        render(p, c1, points, uvs, triangles, capped);
        forgetPosted();
        const std::string what = "patch " + std::to_string(index);
        if (capped) {
            // Gave in (posting kQ3WarningParameterOutOfRange).
            std::printf("[ patches ] %s gave in\n", what.c_str());
            ++cappedPatches;
        }
        largest = std::max(largest, triangles.size());
        EXPECT_LE(triangles.size(), std::size_t(kQ3SubdivisionMaxTrianglesPerPatch));
        ASSERT_EQ(uvs.size(), points.size()) << what << ": every vertex has a surface uv";
        const Real size = p.size();
        // The surface at each vertex's (u, v) by the test's evaluator; the
        // drawn vertex must be that point (up to the float rounding of u, v
        // and of the point).
        std::vector<Vec3> surface(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            surface[i] = evaluate(p, uvs[i].first, uvs[i].second);
            ASSERT_LE(q3test::subdivision::norm(surface[i] - points[i]), 1e-4L * size)
                << what << " vertex " << i << " is not the surface at its (u, v)";
        }
        for (const auto& t : triangles) {
            // A triangle whose three vertices are outside one plane of the
            // view volume cannot be seen: it need not keep the bound.
            if (outsideOnePlane(surface[t[0]], surface[t[1]], surface[t[2]])) {
                ++hidden;
                continue;
            }
            for (int k = 0; k < 3; ++k) {
                Vec3 a = points[t[k]], b = points[t[(k + 1) % 3]];
                const Real da = map.depth(surface[t[k]]), db = map.depth(surface[t[(k + 1) % 3]]);
                if (da < kHither && db < kHither)
                    continue;
                if (da < kHither || db < kHither) {
                    ++crossing;
                    const Real s = (kHither - da) / (db - da);
                    const Vec3 onPlane = a + s * (b - a);
                    (da < kHither ? a : b) = onPlane;
                }
                Real ax, ay, bx, by;
                ASSERT_TRUE(map.map(a, ax, ay) && map.map(b, bx, by)) << what;
                const Real slack = map.pixelError(a, 1e-6L * size) + map.pixelError(b, 1e-6L * size) + 1e-3L;
                EXPECT_LE(std::hypot(bx - ax, by - ay), c1 + slack)
                    << what << ", depths " << double(da) << " and " << double(db);
            }
        }
        if (HasFailure()) {
            std::printf("[ patches ] first failing patch around the eye: %s\n", what.c_str());
            break;
        }
    }
    std::printf("[ patches ] around the eye: %zu edges cross the hither plane; at most %zu triangles; %zu hidden "
                "triangles; %zu of %d patches gave in to the triangle cap\n",
                crossing, largest, hidden, cappedPatches, kPatches);
    // No patch gives in: next to the hither plane, where it cuts a patch
    // along a straight line in (u, v), the vertices left there by splits at
    // the last visible point are nearly collinear, and the thin triangles
    // between them are flipped away before an edge they hold is split (3 of
    // these 24 patches used to give in there, leaving edges up to 4 c1 long).
    EXPECT_EQ(cappedPatches, 0u);
    EXPECT_LT(largest, std::size_t(kQ3SubdivisionMaxTrianglesPerPatch) / 100);
    EXPECT_GT(crossing, 20u) << "the patches should cross the hither plane";
    EXPECT_GT(hidden, 0u) << "some triangles should be out of view";
}

} // namespace
