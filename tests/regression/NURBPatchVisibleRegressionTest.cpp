// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Screen-space subdivision of patches mostly outside the view: the layout
// does not refine what the view cannot show. Each random patch is drawn
// twice under the same c1, first with a camera that sees all of it, then
// with one zoomed in four times, which sees about a sixteenth of it at the
// same size in pixels. In the zoomed view every triangle that can be seen
// (not all three vertices outside one plane of the view volume, judged on
// the surface as PatchReference.h's evaluator computes it at each vertex's
// (u, v)) keeps every edge within c1 pixels, no patch gives in to the
// triangle cap, and the whole mesh has at most kMaxRatio times as many
// triangles as the fully visible one (subdividing all of it to c1 would
// take about 16 times as many).

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
constexpr unsigned kSeed = 20261125u;
constexpr int kPatches = 6;
constexpr float kC1 = 6.0f;
constexpr double kMaxRatio = 5.0;
constexpr float kDepth = 4.0f;

struct Mesh {
    std::vector<Vec3> points;
    std::vector<std::pair<Real, Real>> uvs;
    std::vector<std::array<unsigned long, 3>> triangles;
    bool capped = false;
};

class NURBPatchVisibleRegressionTest : public q3test::PixmapViewTest {
protected:
    NURBPatchVisibleRegressionTest() : PixmapViewTest(kWidth, kHeight) {}

    // The eye at the origin looking down -z; the field of view sees
    // [-halfWidth, halfWidth] across at depth kDepth.
    void setCamera(float halfWidth)
    {
        m_camera.cameraData.placement = {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}};
        m_camera.cameraData.range = {0.5f, 100.0f};
        m_camera.cameraData.viewPort = {{-1, 1}, 2, 2};
        m_camera.aspectRatioXToY = float(kWidth) / float(kHeight);
        // The field of view is the smaller of the two (vertical here).
        m_camera.fov = 2.0f * std::atan(halfWidth / m_camera.aspectRatioXToY / kDepth);
        TQ3CameraObject camera = Q3ViewAngleAspectCamera_New(&m_camera);
        ASSERT_EQ(Q3View_SetCamera(m_view, camera), kQ3Success);
        Q3Object_Dispose(camera);
    }

    Mesh render(Patch& patch)
    {
        Mesh mesh;
        const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodScreenSpace, kC1, kC1};
        TQ3NURBPatchData data = patch.data();
        TQ3GeometryObject object = Q3NURBPatch_New(&data);
        EXPECT_NE(object, nullptr);
        if (object == nullptr)
            return mesh;
        EXPECT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        EXPECT_EQ(Q3SubdivisionStyle_Submit(&style, m_view), kQ3Success);
        TQ3GeometryObject decomposed = Q3Geometry_GetDecomposed(object, m_view);
        mesh.capped = Q3Warning_Get(nullptr) == kQ3WarningParameterOutOfRange;
        EXPECT_NE(decomposed, nullptr);
        if (decomposed != nullptr) {
            TQ3TriMeshData out{};
            EXPECT_EQ(Q3TriMesh_GetData(decomposed, &out), kQ3Success);
            for (unsigned long i = 0; i < out.numPoints; ++i)
                mesh.points.push_back(q3test::subdivision::toVec(out.points[i]));
            for (unsigned long a = 0; a < out.numVertexAttributeTypes; ++a)
                if (out.vertexAttributeTypes[a].attributeType == kQ3AttributeTypeSurfaceUV) {
                    const TQ3Param2D* uv = static_cast<const TQ3Param2D*>(out.vertexAttributeTypes[a].data);
                    for (unsigned long i = 0; i < out.numPoints; ++i)
                        mesh.uvs.emplace_back(uv[i].u, uv[i].v);
                }
            for (unsigned long t = 0; t < out.numTriangles; ++t)
                mesh.triangles.push_back({out.triangles[t].pointIndices[0], out.triangles[t].pointIndices[1],
                                          out.triangles[t].pointIndices[2]});
            Q3TriMesh_EmptyData(&out);
            Q3Object_Dispose(decomposed);
        }
        EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
        Q3Object_Dispose(object);
        forgetPosted();
        return mesh;
    }

    // Whether all three points are outside one plane of m_camera's view
    // volume (beyond the hither plane, or outside one side of the pyramid).
    bool outsideOnePlane(const Vec3* p) const
    {
        const Real across = 1 / std::tan(Real(m_camera.fov) / 2);
        const Real aspect = m_camera.aspectRatioXToY;
        const Real fx = aspect >= 1 ? across / aspect : across;
        const Real fy = aspect >= 1 ? across : across * aspect;
        for (int plane = 0; plane < 5; ++plane) {
            bool all = true;
            for (int k = 0; k < 3 && all; ++k) {
                const Real depth = -p[k].z;
                const Real values[5] = {depth - Real(m_camera.cameraData.range.hither), depth - fx * p[k].x,
                                        depth + fx * p[k].x, depth - fy * p[k].y, depth + fy * p[k].y};
                all = values[plane] < 0;
            }
            if (all)
                return true;
        }
        return false;
    }

    TQ3ViewAngleAspectCameraData m_camera{};
};

TEST_F(NURBPatchVisibleRegressionTest, ZoomedInTheSeenPartKeepsC1AndTheRestCostsLittle)
{
    std::mt19937 rng(kSeed);
    double worstRatio = 0;
    std::size_t hidden = 0;
    for (int index = 0; index < kPatches && !HasFatalFailure(); ++index) {
        PatchOptions options;
        options.uOrder = 2 + unsigned(index % 4);
        options.vOrder = 2 + unsigned((index + 1) % 4);
        options.extraPoints = 3;
        Patch p = randomPatch(rng, options);
        // Spread over [-2, 2] x [-1.5, 1.5] at depth kDepth, slightly wavy.
        for (unsigned long r = 0; r < p.numRows; ++r)
            for (unsigned long c = 0; c < p.numColumns; ++c) {
                TQ3RationalPoint4D& q = p.points[r * p.numColumns + c];
                const float x = -2.0f + 4.0f * float(c) / float(p.numColumns - 1);
                const float y = -1.5f + 3.0f * float(r) / float(p.numRows - 1);
                const float z = -kDepth + 0.2f * q.z / q.w;
                q = {x * q.w, y * q.w, z * q.w, q.w};
            }
        const std::string what = "patch " + std::to_string(index);
        setCamera(2.2f);
        const Mesh full = render(p);
        EXPECT_FALSE(full.capped) << what;
        setCamera(2.2f / 4.0f);
        const Mesh zoomed = render(p);
        EXPECT_FALSE(zoomed.capped) << what << " gave in to the triangle cap";
        ASSERT_EQ(zoomed.uvs.size(), zoomed.points.size()) << what;
        ASSERT_FALSE(full.triangles.empty()) << what;
        const ScreenMap map(m_camera, {{0, 0}, {float(kWidth), float(kHeight)}});
        const Real size = p.size();
        std::vector<Vec3> surface(zoomed.points.size());
        for (std::size_t i = 0; i < surface.size(); ++i) {
            surface[i] = evaluate(p, zoomed.uvs[i].first, zoomed.uvs[i].second);
            ASSERT_LE(q3test::subdivision::norm(surface[i] - zoomed.points[i]), 1e-4L * size)
                << what << " vertex " << i << " is not the surface at its (u, v)";
        }
        for (const auto& t : zoomed.triangles) {
            const Vec3 corners[3] = {surface[t[0]], surface[t[1]], surface[t[2]]};
            if (outsideOnePlane(corners)) {
                ++hidden;
                continue;
            }
            for (int k = 0; k < 3; ++k) {
                const Vec3& a = zoomed.points[t[k]];
                const Vec3& b = zoomed.points[t[(k + 1) % 3]];
                Real ax, ay, bx, by;
                ASSERT_TRUE(map.map(a, ax, ay) && map.map(b, bx, by)) << what;
                const Real slack = map.pixelError(a, 1e-6L * size) + map.pixelError(b, 1e-6L * size) + 1e-3L;
                EXPECT_LE(std::hypot(bx - ax, by - ay), kC1 + slack) << what << ": a visible edge is too long";
            }
        }
        const double ratio = double(zoomed.triangles.size()) / double(full.triangles.size());
        worstRatio = std::max(worstRatio, ratio);
        std::printf("[ patches ] %s: %zu triangles fully seen, %zu zoomed in (x%.2f)\n", what.c_str(),
                    full.triangles.size(), zoomed.triangles.size(), ratio);
        EXPECT_LE(ratio, kMaxRatio) << what << ": the part out of view was refined";
    }
    std::printf("[ patches ] zoomed in four times: at most %.2f times the triangles of the whole patch in view\n",
                worstRatio);
    EXPECT_GT(hidden, 0u) << "some triangles should be out of view";
}

} // namespace
