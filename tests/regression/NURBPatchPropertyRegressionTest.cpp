// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// What QD3DGeometry.h promises about a subdivided NURB patch, checked end to
// end through the public API on random patches (orders 2 to 11 in u and v,
// rational weights, clamped and unclamped knots, repeated interior knots),
// trimmed or not (an outer loop with a hole and an island in it, a lone hole,
// an outer loop with two holes; loops of one to three rational curves of
// orders 2-5), each under a random stack of transforms and a random
// orthographic or perspective camera, view port and pane, decomposed with
// Q3Geometry_GetDecomposed under the three methods. Every TriMesh is compared
// with PatchReference.h (its own long-double evaluator, transforms and
// cameras), which shares no code with Q3:
//   - every vertex lies on the surface (Gauss-Newton distance from its
//     surface uv);
//   - world / screen space: every edge is at most c1 long, in world units /
//     pane pixels through the test's own matrices;
//   - constant: 2 c1 c2 triangles per pair of spans, the vertices exactly the
//     surface at the evenly spaced parameters;
//   - every normal agrees with the reference normal at the vertex;
//   - trimmed: every vertex on the edge of the drawn region lies on a trim
//     curve; no triangle's centroid lies inside a hole deeper than the trim
//     polylines' own distance from the curves; the drawn area in (u, v)
//     matches the kept region's;
//   - the triangle count is close to the fewest: it is printed as a ratio to
//     the lower bound A / (sqrt(3)/4 c1^2) (A the mesh's area where lengths
//     are measured; no triangle with sides at most c1 is larger than the
//     equilateral one).
// Tolerances, with u = 2^-24 (float's unit roundoff), size = the control
// points' extent (PatchReference.h, Patch::size):
//   - on the surface: kOnSurface * size = 1e-6 size, ten times the float
//     rounding of a vertex (sqrt(3) u size), as for curves;
//   - edge lengths: c1 plus, for each end point, the bound on how far Q3's
//     image of it can be from the test's (SubdivisionPropertyRegressionTest.cpp
//     explains it: float rounding of the vertex and of each transform's entries);
//   - normals: 1e-4 rad, where the reference's difference partials (relative
//     error about 1e-7) and the float normal (u) both sit far below it;
//     vertices where |du x dv| < 1e-6 |du| |dv| (poles, cusps) and vertices on a
//     crease (an interior knot repeated order - 1 times) are not compared;
//   - on a trim curve: 1e-6 of the domain's larger side in (u, v) plus 2 u
//     times the domain's largest coordinate, for the float surface uv of the
//     vertex and the mesh's parameter grid (2^-29 of the domain);
//   - holes: a centroid may lie in a hole by no more than the largest
//     distance between a boundary edge and the loops (the chords' sagitta,
//     measured at 7 points of each chord, plus 5 %), plus 1e-6 of the
//     domain: between a chord and its curve the polyline region and the
//     curved one differ;
//   - area in (u, v): within that sagitta times the loops' length, plus 1e-4
//     of the domain's area.
// Q3_PATCH_CASES sets how many patches (default 200); Q3_PATCH_SEED the seed.

#include "PatchReference.h"
#include "PixmapViewTest.h"
#include "Q3ApiTest.h"
#include "q3png.h"

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGeometry.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace {

using namespace q3test::patches;
using q3test::subdivision::Matrix4;
using q3test::subdivision::ScreenMap;
using q3test::subdivision::TransformStack;
using q3test::subdivision::kFloatRoundoff;
using q3test::subdivision::lookAt;
using q3test::subdivision::randomDirection;

constexpr unsigned long kWidth = 160;
constexpr unsigned long kHeight = 120;
constexpr unsigned kDefaultSeed = 20261201u;
constexpr int kDefaultCases = 200;
constexpr Real kOnSurface = 1e-6L;
constexpr Real kNormalAngle = 1e-4L;
constexpr Real kCameraSlackPixels = 1e-9L;
constexpr Real kCountFactor = 2.0L;
constexpr Real kCountFactorScreen = 3.0L;

int envInt(const char* name, int fallback)
{
    const char* text = std::getenv(name);
    return text != nullptr ? std::atoi(text) : fallback;
}

struct Scene : q3test::subdivision::SceneCamera {
    Patch patch;
    int trimKind = 0;
    TransformStack transforms;

    Scene() { pane = {{0, 0}, {float(kWidth), float(kHeight)}}; }

};

// Patch `index`: u and v orders cycle through 2..11 (v offset by 3), clamped
// knots except every fourth patch, repeated interior knots in half of them,
// trim kinds cycle 0..3, every other patch seen in perspective.
Scene makeScene(std::mt19937& rng, int index)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Scene scene;
    PatchOptions options;
    options.uOrder = 2 + unsigned(index % 10);
    options.vOrder = 2 + unsigned((index + 3) % 10);
    options.clamped = index % 4 != 3;
    options.repeatProbability = (index / 2) % 2 == 0 ? 0.0L : 0.4L;
    options.extraPoints = 4;
    scene.patch = randomPatch(rng, options);
    scene.trimKind = index % 4;
    addRandomTrims(rng, scene.patch, scene.trimKind);
    scene.transforms = q3test::subdivision::randomTransforms(rng, index % 4);
    scene.perspective = index % 2 == 1;

    const q3test::subdivision::ControlBox box(scene.patch.points, scene.transforms.localToWorld());
    const Vec3 centre = box.centre();
    const Real radius = box.radius();
    const Vec3 direction = randomDirection(rng);
    Vec3 up = randomDirection(rng);
    while (q3test::subdivision::norm(q3test::subdivision::cross(up, direction)) < 0.3L)
        up = randomDirection(rng);
    if (scene.perspective) {
        const Real away = radius * (2.5L + 2.5L * Real(u(rng)));
        const Real fov = 0.4 + 1.0 * u(rng);
        scene.setPerspective(lookAt(centre + away * direction, centre, up, 0.05L * radius, 100 * radius), fov,
                             Real(float(kWidth) / float(kHeight)));
    } else {
        const Real half = radius * (0.8L + 0.6L * Real(u(rng)));
        scene.setOrthographic(lookAt(centre + 3 * radius * direction, centre, up, 0.1L * radius, 100 * radius),
                              half, half * kHeight / kWidth);
    }
    return scene;
}

// The decomposed mesh, read back through the public API.
struct Mesh {
    std::vector<Vec3> points;
    std::vector<Vec3> normals;
    std::vector<std::pair<Real, Real>> uvs;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

Mesh readMesh(TQ3GeometryObject triMesh)
{
    Mesh mesh;
    TQ3TriMeshData data{};
    if (Q3TriMesh_GetData(triMesh, &data) != kQ3Success)
        return mesh;
    for (unsigned long i = 0; i < data.numPoints; ++i)
        mesh.points.push_back(q3test::subdivision::toVec(data.points[i]));
    for (unsigned long t = 0; t < data.numTriangles; ++t)
        mesh.triangles.push_back({std::uint32_t(data.triangles[t].pointIndices[0]),
                                  std::uint32_t(data.triangles[t].pointIndices[1]),
                                  std::uint32_t(data.triangles[t].pointIndices[2])});
    for (unsigned long a = 0; a < data.numVertexAttributeTypes; ++a) {
        const TQ3TriMeshAttributeData& attribute = data.vertexAttributeTypes[a];
        if (attribute.attributeType == kQ3AttributeTypeNormal) {
            const TQ3Vector3D* n = static_cast<const TQ3Vector3D*>(attribute.data);
            for (unsigned long i = 0; i < data.numPoints; ++i)
                mesh.normals.push_back({n[i].x, n[i].y, n[i].z});
        } else if (attribute.attributeType == kQ3AttributeTypeSurfaceUV) {
            const TQ3Param2D* uv = static_cast<const TQ3Param2D*>(attribute.data);
            for (unsigned long i = 0; i < data.numPoints; ++i)
                mesh.uvs.emplace_back(uv[i].u, uv[i].v);
        }
    }
    Q3TriMesh_EmptyData(&data);
    return mesh;
}

struct Figures {
    std::string name;
    int meshes = 0;
    double ratioSum = 0, ratioMax = 0;
    double worstOvershoot = 0;
    double worstSurface = 0;
    double worstNormal = 0;
    double worstTrim = 0;
    long triangles = 0;

    void addRatio(double r)
    {
        ++meshes;
        ratioSum += r;
        ratioMax = std::max(ratioMax, r);
    }
    std::string report() const
    {
        char text[400];
        std::snprintf(text, sizeof text,
                      "%s: %d meshes, %ld triangles; triangles / (A / (sqrt(3)/4 c1^2)): mean %.3f, max %.3f; "
                      "longest edge / c1 %.7f; vertex distance from the surface / size %.3g; normal angle %.3g rad; "
                      "boundary vertex distance from a trim curve / domain %.3g",
                      name.c_str(), meshes, triangles, meshes ? ratioSum / meshes : 0.0, ratioMax, worstOvershoot,
                      worstSurface, worstNormal, worstTrim);
        return text;
    }
};

class NURBPatchPropertyRegressionTest : public q3test::PixmapViewTest {
protected:
    NURBPatchPropertyRegressionTest() : PixmapViewTest(kWidth, kHeight) {}

    void SetUp() override
    {
        PixmapViewTest::SetUp();
        m_seed = unsigned(envInt("Q3_PATCH_SEED", int(kDefaultSeed)));
        m_cases = envInt("Q3_PATCH_CASES", kDefaultCases);
        std::printf("[ patches ] %d random patches from seed %u (Q3_PATCH_CASES, Q3_PATCH_SEED)\n", m_cases, m_seed);
    }

    Mesh decompose(const Scene& scene, TQ3GeometryObject patch, const TQ3SubdivisionStyleData& style)
    {
        Mesh mesh;
        EXPECT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        EXPECT_EQ(Q3SubdivisionStyle_Submit(&style, m_view), kQ3Success);
        scene.transforms.submit(m_view);
        TQ3GeometryObject triMesh = Q3Geometry_GetDecomposed(patch, m_view);
        EXPECT_NE(triMesh, nullptr);
        if (triMesh != nullptr) {
            mesh = readMesh(triMesh);
            Q3Object_Dispose(triMesh);
        }
        Q3View_Cancel(m_view);
        Q3View_EndRendering(m_view);
        return mesh;
    }

    unsigned m_seed = 0;
    int m_cases = 0;
};

// How far Q3's world image of local point p can be from the test's
// (m: the stack's absoluteLocalToWorld()).
Real worldError(const TransformStack& transforms, const Matrix4& m, const Vec3& p)
{
    const Real a[3] = {std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)};
    Real sum2 = 0;
    for (int j = 0; j < 3; ++j) {
        const Real v = a[0] * m.m[0][j] + a[1] * m.m[1][j] + a[2] * m.m[2][j] + m.m[3][j];
        sum2 += v * v;
    }
    return Real(transforms.steps.size() + 2) * kFloatRoundoff * std::sqrt(sum2);
}

bool onCrease(const Patch& p, Real u, Real v)
{
    auto near = [](const std::vector<float>& knots, unsigned long k, unsigned long n, Real t, Real width) {
        for (std::size_t i = k; i < n; ++i) {
            std::size_t run = 1;
            while (i + run < n && knots[i + run] == knots[i])
                ++run;
            if (run >= k - 1 && std::fabs(t - knots[i]) < 1e-5L * width)
                return true;
        }
        return false;
    };
    return near(p.uKnots, p.uOrder, p.numColumns, u, p.u1() - p.u0()) ||
           near(p.vKnots, p.vOrder, p.numRows, v, p.v1() - p.v0());
}

// Vertices on the surface and normals agreeing with the reference.
void checkVertices(const Patch& p, const Mesh& mesh, Figures& figures, const std::string& what)
{
    ASSERT_EQ(mesh.uvs.size(), mesh.points.size()) << what << ": every vertex has a surface uv";
    ASSERT_EQ(mesh.normals.size(), mesh.points.size()) << what << ": every vertex has a normal";
    const Real size = p.size();
    for (std::size_t i = 0; i < mesh.points.size(); ++i) {
        Real u = mesh.uvs[i].first, v = mesh.uvs[i].second;
        const Real d = distanceToSurface(p, mesh.points[i], u, v, kOnSurface * size / 4);
        figures.worstSurface = std::max(figures.worstSurface, double(d / size));
        EXPECT_LE(d, kOnSurface * size) << what << " vertex " << i << " is off the surface";
        if (onCrease(p, u, v))
            continue;
        bool defined = false;
        const Vec3 reference = normal(p, u, v, defined);
        if (!defined)
            continue;
        const Real c = std::clamp(q3test::subdivision::dot(reference, mesh.normals[i]) /
                                      q3test::subdivision::norm(mesh.normals[i]),
                                  Real(-1), Real(1));
        const Real angle = std::acos(c);
        figures.worstNormal = std::max(figures.worstNormal, double(angle));
        EXPECT_LE(angle, kNormalAngle) << what << " vertex " << i << " normal";
    }
}

// Debug: draws a mesh's triangles in (u, v) into a PNG (Q3_PATCH_DUMP=dir).
void dump(const Patch& p, const Mesh& mesh, const std::string& name)
{
    const char* dir = std::getenv("Q3_PATCH_DUMP");
    if (dir == nullptr)
        return;
    const int w = 1000, h = 1000;
    std::vector<unsigned char> rgba(w * h * 4, 255);
    auto plot = [&](Real u, Real v, int r, int g, int b) {
        const int x = int((u - p.u0()) / (p.u1() - p.u0()) * (w - 1));
        const int y = h - 1 - int((v - p.v0()) / (p.v1() - p.v0()) * (h - 1));
        if (x < 0 || y < 0 || x >= w || y >= h)
            return;
        unsigned char* q = &rgba[(y * w + x) * 4];
        q[0] = (unsigned char)r;
        q[1] = (unsigned char)g;
        q[2] = (unsigned char)b;
    };
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const auto& a = mesh.uvs[t[k]];
            const auto& b = mesh.uvs[t[(k + 1) % 3]];
            for (int i = 0; i <= 200; ++i)
                plot(a.first + (b.first - a.first) * i / 200, a.second + (b.second - a.second) * i / 200, 0, 0, 0);
        }
    for (const auto& polygon : densePolygons(p, 64))
        for (const auto& q : polygon)
            plot(q.first, q.second, 255, 0, 0);
    q3png_write_rgba8((std::string(dir) + "/" + name + ".png").c_str(), rgba.data(), w, h, w * 4);
}

// Edges within c1 where measured (screen space: on every triangle that can be
// seen, i.e. whose three vertices are not all outside one plane of the view
// volume, `outside` giving a vertex's planes as a bit mask), and the count
// near the fewest: at most
// kCountFactor times the area bound, plus two triangles per boundary edge and
// four per pair of spans (the rows keep a vertex on every knot and end every
// span with a short step).
void checkEdges(const Patch& p, const Mesh& mesh, Real c1, Real countFactor,
                const std::function<bool(const Vec3&, Vec3&)>& map, const std::function<Real(const Vec3&)>& error,
                Figures& figures, const std::string& what,
                const std::function<unsigned(const Vec3&)>& outside = nullptr)
{
    Real area = 0;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> sides;
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            ++sides[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
    std::size_t boundary = 0;
    for (const auto& side : sides)
        boundary += side.second == 1;
    for (const auto& t : mesh.triangles) {
        Vec3 image[3];
        for (int k = 0; k < 3; ++k)
            ASSERT_TRUE(map(mesh.points[t[k]], image[k])) << what;
        const bool hidden = outside && (outside(mesh.points[t[0]]) & outside(mesh.points[t[1]]) &
                                        outside(mesh.points[t[2]])) != 0;
        for (int k = 0; k < 3 && !hidden; ++k) {
            const std::uint32_t a = t[k], b = t[(k + 1) % 3];
            const Real length = q3test::subdivision::distance(image[k], image[(k + 1) % 3]);
            figures.worstOvershoot = std::max(figures.worstOvershoot, double(length / c1));
            EXPECT_LE(length, c1 + error(mesh.points[a]) + error(mesh.points[b]))
                << what << " an edge is longer than c1 " << double(c1);
        }
        area += q3test::subdivision::norm(
                    q3test::subdivision::cross(image[1] - image[0], image[2] - image[0])) / 2;
    }
    figures.triangles += long(mesh.triangles.size());
    const Real fewest = area / (std::sqrt(3.0L) / 4 * c1 * c1);
    const std::size_t spanPairs = p.uSpans().size() * p.vSpans().size();
    dump(p, mesh, what);
    EXPECT_LE(Real(mesh.triangles.size()), countFactor * fewest + 2 * Real(boundary) + 4 * Real(spanPairs))
        << what << ": " << mesh.triangles.size() << " triangles for an area bound of " << double(fewest) << ", "
        << boundary << " boundary edges, " << spanPairs << " pairs of spans";
    if (area > 0)
        figures.addRatio(double(Real(mesh.triangles.size()) / fewest));
}

// The trimmed region: boundary vertices on the loops, no centroid in a hole,
// the area right.
void checkTrims(const Patch& p, const Region& region, const TrimLocator& locator, const Mesh& mesh, Figures& figures,
                const std::string& what)
{
    const Real side = std::max(p.u1() - p.u0(), p.v1() - p.v0());
    // The float uv of a vertex carries u times its magnitude.
    const Real magnitude = std::max({std::fabs(p.u0()), std::fabs(p.u1()), std::fabs(p.v0()), std::fabs(p.v1())});
    const Real onTrim = 1e-6L * side + 2 * kFloatRoundoff * magnitude;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    Real area = 0;
    for (const auto& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k)
            ++edges[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
        const auto& a = mesh.uvs[t[0]];
        const auto& b = mesh.uvs[t[1]];
        const auto& c = mesh.uvs[t[2]];
        area += ((b.first - a.first) * (c.second - a.second) - (b.second - a.second) * (c.first - a.first)) / 2;
    }
    // Boundary edges: on the domain's edge (lone-hole patches) or on a loop.
    Real sagitta = 0, loopLength = 0;
    std::set<std::uint32_t> checked;
    for (const auto& [edge, count] : edges) {
        if (count != 1)
            continue;
        const auto& a = mesh.uvs[edge.first];
        const auto& b = mesh.uvs[edge.second];
        auto onDomainEdge = [&](const std::pair<Real, Real>& q) {
            const Real e = 1e-6L * side;
            return std::fabs(q.first - p.u0()) < e || std::fabs(q.first - p.u1()) < e ||
                   std::fabs(q.second - p.v0()) < e || std::fabs(q.second - p.v1()) < e;
        };
        if (onDomainEdge(a) && onDomainEdge(b))
            continue;
        for (std::uint32_t vertex : {edge.first, edge.second}) {
            if (!checked.insert(vertex).second)
                continue;
            const auto& q = mesh.uvs[vertex];
            const Real d = locator.distance(q.first, q.second);
            figures.worstTrim = std::max(figures.worstTrim, double(d / side));
            EXPECT_LE(d, onTrim) << what << " boundary vertex " << vertex << " at (" << double(q.first) << ", "
                                       << double(q.second) << ") is not on a trim curve";
            if (d > onTrim && getenv("Q3_PATCH_VERBOSE"))
                std::printf("edge %u-%u (%.9g,%.9g)-(%.9g,%.9g) domain [%g %g]x[%g %g]\n", edge.first, edge.second,
                            double(a.first), double(a.second), double(b.first), double(b.second), double(p.u0()),
                            double(p.u1()), double(p.v0()), double(p.v1()));
        }
        loopLength += std::hypot(b.first - a.first, b.second - a.second);
        for (int s = 1; s < 8; ++s) {
            const Real f = Real(s) / 8;
            sagitta = std::max(sagitta, region.distanceToLoops(a.first + f * (b.first - a.first),
                                                               a.second + f * (b.second - a.second)));
        }
    }
    const Real slack = 1.05L * sagitta + 1e-6L * side;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const auto& t = mesh.triangles[i];
        const Real u = (mesh.uvs[t[0]].first + mesh.uvs[t[1]].first + mesh.uvs[t[2]].first) / 3;
        const Real v = (mesh.uvs[t[0]].second + mesh.uvs[t[1]].second + mesh.uvs[t[2]].second) / 3;
        if (!region.kept(u, v))
            EXPECT_LE(region.distanceToLoops(u, v), slack)
                << what << " triangle " << i << " lies in a hole, centroid (" << double(u) << ", " << double(v) << ")";
    }
    const Real domainArea = (p.u1() - p.u0()) * (p.v1() - p.v0());
    EXPECT_NEAR(double(area), double(region.area(domainArea)), double(sagitta * loopLength + 1e-4L * domainArea))
        << what << " the drawn area in (u, v) differs from the kept region's";
}

TEST_F(NURBPatchPropertyRegressionTest, RandomPatchesKeepEveryPromiseUnderEveryMethod)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Figures constant{"constant"}, world{"world space"}, screen{"screen space"};
    for (int index = 0; index < m_cases && !HasFatalFailure(); ++index) {
        // Each patch from its own seed, so that one can be replayed alone.
        std::mt19937 rng(m_seed + 7919u * unsigned(index));
        Scene scene = makeScene(rng, index);
        if (envInt("Q3_PATCH_ONLY", -1) >= 0 && envInt("Q3_PATCH_ONLY", -1) != index)
            continue;
        Patch& p = scene.patch;
        const ScreenMap map = scene.screen();
        const Matrix4 toWorld = scene.transforms.localToWorld();
        const Matrix4 absolute = scene.transforms.absoluteLocalToWorld();
        const std::string what = "patch " + std::to_string(index) + " (orders " + std::to_string(p.uOrder) + " x " +
                                 std::to_string(p.vOrder) + ", trims " + std::to_string(scene.trimKind) +
                                 (scene.perspective ? ", perspective" : ", orthographic") + ")";
        // Areas for choosing c1: a 24 x 24 grid of the domain.
        Real worldArea = 0, pixelArea = 0;
        {
            const int n = 24;
            std::vector<Vec3> w((n + 1) * (n + 1));
            std::vector<Vec3> s((n + 1) * (n + 1));
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i) {
                    const Vec3 local = evaluate(p, p.u0() + (p.u1() - p.u0()) * i / n, p.v0() + (p.v1() - p.v0()) * j / n);
                    w[j * (n + 1) + i] = toWorld.point(local);
                    Real x = 0, y = 0;
                    map.map(w[j * (n + 1) + i], x, y);
                    s[j * (n + 1) + i] = {x, y, 0};
                }
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
                    for (const auto* g : {&w, &s}) {
                        const Real t = (q3test::subdivision::norm(q3test::subdivision::cross((*g)[b] - (*g)[a], (*g)[c] - (*g)[a])) +
                                        q3test::subdivision::norm(q3test::subdivision::cross((*g)[c] - (*g)[a], (*g)[d] - (*g)[a]))) /
                                       2;
                        (g == &w ? worldArea : pixelArea) += t;
                    }
                }
        }
        // c1 for about 100 to 1000 triangles.
        auto c1For = [&](Real area) {
            const Real target = std::exp(std::log(100.0L) + Real(u(rng)) * std::log(10.0L));
            return float(std::sqrt(area / (0.2165L * target)));
        };
        // Trim loops need enough segments per span that their chords do not
        // cross (QD3DGeometry.h, "Crossing loops").
        const float constantC1 = float((scene.trimKind != 0 ? 6 : 1) + int(5 * u(rng)));
        const float constantC2 = float(1 + int(5 * u(rng)));
        const TQ3SubdivisionStyleData styles[3] = {{kQ3SubdivisionMethodConstant, constantC1, constantC2},
                                                   {kQ3SubdivisionMethodWorldSpace, c1For(worldArea), 1.0f},
                                                   {kQ3SubdivisionMethodScreenSpace, c1For(pixelArea), 1.0f}};
        TQ3NURBPatchData data = p.data();
        TQ3GeometryObject patch = Q3NURBPatch_New(&data);
        ASSERT_NE(patch, nullptr) << what;
        useCamera(scene.newObject());
        const Mesh meshes[3] = {decompose(scene, patch, styles[0]), decompose(scene, patch, styles[1]),
                                decompose(scene, patch, styles[2])};
        Q3Object_Dispose(patch);
        const Region region(p, 32);
        const TrimLocator locator(p, 64);

        // Constant.
        checkVertices(p, meshes[0], constant, what + " constant");
        constant.triangles += long(meshes[0].triangles.size());
        ++constant.meshes;
        if (scene.trimKind == 0) {
            const std::size_t spans = p.uSpans().size() * p.vSpans().size();
            EXPECT_EQ(meshes[0].triangles.size(), std::size_t(2 * constantC1 * constantC2) * spans) << what;
            // The vertices are the surface at the evenly spaced parameters.
            std::set<float> us, vs;
            for (std::size_t s : p.uSpans())
                for (int j = 0; j <= int(constantC1); ++j)
                    us.insert(float(p.uKnots[s] + (Real(p.uKnots[s + 1]) - p.uKnots[s]) * j / Real(constantC1)));
            for (std::size_t s : p.vSpans())
                for (int j = 0; j <= int(constantC2); ++j)
                    vs.insert(float(p.vKnots[s] + (Real(p.vKnots[s + 1]) - p.vKnots[s]) * j / Real(constantC2)));
            EXPECT_EQ(meshes[0].points.size(), us.size() * vs.size()) << what;
            for (const auto& uv : meshes[0].uvs) {
                EXPECT_TRUE(us.count(float(uv.first)) == 1 && vs.count(float(uv.second)) == 1)
                    << what << " a constant vertex at (" << double(uv.first) << ", " << double(uv.second)
                    << ") is not on the grid";
            }
        } else {
            checkTrims(p, region, locator, meshes[0], constant, what + " constant");
        }

        // World space.
        checkVertices(p, meshes[1], world, what + " world");
        checkEdges(
            p, meshes[1], styles[1].c1, kCountFactor,
            [&](const Vec3& a, Vec3& out) {
                out = toWorld.point(a);
                return true;
            },
            [&](const Vec3& a) { return worldError(scene.transforms, absolute, a); }, world, what + " world");
        if (scene.trimKind != 0)
            checkTrims(p, region, locator, meshes[1], world, what + " world");

        // Screen space.
        checkVertices(p, meshes[2], screen, what + " screen");
        checkEdges(
            p, meshes[2], styles[2].c1, kCountFactorScreen,
            [&](const Vec3& a, Vec3& out) {
                Real x = 0, y = 0;
                const bool seen = map.map(toWorld.point(a), x, y);
                out = {x, y, 0};
                return seen;
            },
            [&](const Vec3& a) {
                return map.pixelError(toWorld.point(a), worldError(scene.transforms, absolute, a)) + kCameraSlackPixels;
            },
            screen, what + " screen", [&](const Vec3& a) {
                // Outside the view volume: nearer than hither, or off the pane.
                const Vec3 w = toWorld.point(a);
                const Real hither = scene.hither();
                unsigned mask = map.depth(w) < hither ? 1u : 0u;
                Real x = 0, y = 0;
                if (map.map(w, x, y))
                    mask |= (x < 0 ? 2u : 0u) | (x > Real(kWidth) ? 4u : 0u) | (y < 0 ? 8u : 0u) |
                            (y > Real(kHeight) ? 16u : 0u);
                return mask;
            });
        if (scene.trimKind != 0)
            checkTrims(p, region, locator, meshes[2], screen, what + " screen");
        if (HasFailure()) {
            std::printf("[ patches ] first failing patch: %s, seed %u\n", what.c_str(), m_seed);
            break;
        }
    }
    for (const Figures* f : {&constant, &world, &screen}) {
        std::printf("[ patches ] %s\n", f->report().c_str());
        RecordProperty(f->name, f->report());
    }
}

} // namespace
