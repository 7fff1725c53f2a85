// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The article's three subdivision methods ("CONTROLLING SUBDIVISION") checked
// end to end through the public API on a few hundred random curves. Each curve
// is given a random stack of transforms (translate, rotate, non-uniform scale,
// general matrix) and a random orthographic or perspective camera, view port
// and pane, and is decomposed with Q3Geometry_GetDecomposed inside a rendering
// loop of a 128 x 96 pixmap view under each method. Every polyline is then
// compared with SubdivisionReference.h (its own Cox-de Boor evaluator in long
// double, its own transform and camera matrices), which shares no code with Q3.
//
// Tolerances, with u = 2^-24 (float's unit roundoff):
//  - A vertex Q3 places at a known parameter (the domain ends, and every
//    vertex of the constant method) is the curve point computed in double and
//    rounded to float once, so each coordinate c may be off by u * |c|; on top
//    of that kEvaluationSlack * size covers double-precision error in Q3's
//    evaluation (Bezier conversion of order-16 spans) and in the parameter
//    itself. The largest error seen is printed in units of u.
//  - Any other vertex must lie within kOnCurve * size of the curve, size being
//    the control points' extent (Curve::scale, which bounds every coordinate of
//    the curve): rounding to float moves a vertex by at most sqrt(3) u size,
//    about 1.03e-7 size, so 1e-6 leaves ten times that for double error.
//  - Q3 measures a segment between its end points in double, before they are
//    rounded, through matrices it builds from the same float data (rotations
//    rounded to float entries); the test measures between the float vertices
//    through exact matrices. For each end point p, the world image can differ
//    by at most (steps + 2) u |A| (|p|, 1), where |A| is the product of the
//    steps' entrywise absolute matrices: one u for rounding the vertex, one per
//    step whose entries were rounded, one to spare. In pixels that difference
//    is scaled by the camera's Jacobian at the point (ScreenMap::pixelError),
//    plus 1e-9 px for double rounding in Q3's camera matrix. A segment may
//    exceed c1 by the sum of the two end points' bounds and no more.
//  - "Near minimal": segments <= 1.2 * L / c1 + spans, L the curve's length
//    in the measuring space from 128 samples per span (a chord sum, so a lower
//    bound: the check can only get stricter).

#include "PixmapViewTest.h"
#include "Q3ApiTest.h"
#include "SubdivisionReference.h"

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGeometry.h"
#include "QD3DRenderer.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace q3test::subdivision;

constexpr unsigned long kWidth = 128;
constexpr unsigned long kHeight = 96;
constexpr int kCurves = 300;
constexpr int kDefaultStyleCurves = 40;
constexpr unsigned kDefaultSeed = 20260413u;
constexpr int kSamplesPerSpan = 128;
constexpr Real kEvaluationSlack = 1e-12L;
constexpr Real kOnCurve = 1e-6L;
constexpr Real kCameraSlackPixels = 1e-9L;
constexpr Real kNearMinimalFactor = 1.2L;

/// The seed of the random curves: Q3_SUBDIVISION_SEED if set, so that a
/// failure seen elsewhere can be replayed, else a fixed one.
unsigned seed()
{
    if (const char* text = std::getenv("Q3_SUBDIVISION_SEED"))
        return unsigned(std::strtoul(text, nullptr, 10));
    return kDefaultSeed;
}

/// One random curve with everything it is drawn under.
struct Scene : SceneCamera {
    Curve curve;
    TransformStack transforms;
    bool paneOn = false;
};

/// Curve `index` of a run: orders cycle through 2..16, ends alternate
/// between clamped and not every 15 curves, knot repetition rises every 30,
/// the first transform kind cycles, and every other curve gets a perspective
/// camera, the parity flipping every 30 so that each order, clamped or not,
/// is seen through both kinds of camera.
Scene makeScene(std::mt19937& rng, int index)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Scene scene;
    RandomCurveOptions options;
    options.order = 2 + unsigned(index % 15);
    options.clamped = (index / 15) % 2 == 0;
    const Real repeats[3] = {0.0L, 0.3L, 0.7L};
    options.repeatProbability = repeats[(index / 30) % 3];
    scene.curve = randomCurve(rng, options);
    scene.transforms = randomTransforms(rng, index % 4);
    scene.perspective = (index + index / 30) % 2 == 1;

    // The world-space bounding sphere of the control points holds the curve.
    const ControlBox box(scene.curve.points, scene.transforms.localToWorld());
    const Vec3 centre = box.centre();
    const Real radius = box.radius();

    const Vec3 direction = randomDirection(rng);
    Vec3 up = randomDirection(rng);
    while (norm(cross(up, direction)) < 0.3L)
        up = randomDirection(rng);
    TQ3CameraViewPort viewPort = {{-1.0f, 1.0f}, 2.0f, 2.0f};
    if (u(rng) < 0.5) {
        viewPort.width = float(0.6 + 1.4 * u(rng));
        viewPort.height = float(0.6 + 1.4 * u(rng));
        viewPort.origin = {float(-1.2 + 1.2 * u(rng)), float(1.2 * u(rng))};
    }
    if (scene.perspective) {
        // Every curve point is at least 1.5 radii in front of the eye.
        const Real away = radius * (2.5L + 2.5L * Real(u(rng)));
        TQ3CameraData camera = lookAt(centre + away * direction, centre, up, 0.05L * radius, 100 * radius);
        camera.viewPort = viewPort;
        const Real fov = 0.4 + 1.0 * u(rng);
        const Real aspect = 0.7 + 0.9 * u(rng);
        scene.setPerspective(camera, fov, aspect);
    } else {
        TQ3CameraData camera = lookAt(centre + 3 * radius * direction, centre, up, 0.1L * radius, 100 * radius);
        camera.viewPort = viewPort;
        const Real halfWidth = radius * (0.6L + 0.9L * Real(u(rng)));
        const Real halfHeight = halfWidth * (0.6L + 0.6L * Real(u(rng)));
        const Real shiftX = radius * (0.6L * Real(u(rng)) - 0.3L);
        const Real shiftY = radius * (0.6L * Real(u(rng)) - 0.3L);
        scene.setOrthographic(camera, halfWidth, halfHeight, shiftX, shiftY);
    }
    // Whole-pixel edges: Q3 rounds a pane to pixels, so this is the pane it uses.
    scene.pane = {{0, 0}, {float(kWidth), float(kHeight)}};
    if (u(rng) < 1.0 / 3.0) {
        const float x = float(int(40 * u(rng))), y = float(int(30 * u(rng)));
        scene.pane = {{x, y}, {x + float(32 + int(56 * u(rng))), y + float(24 + int(42 * u(rng)))}};
        scene.paneOn = true;
    }
    return scene;
}

/// The reference's view of a scene: dense samples in local, world and pixel
/// space, and the lengths they give.
struct Reference {
    DenseSamples samples;
    Matrix4 toWorld;
    Matrix4 absoluteToWorld;
    Real errorFactor = 0;
    Real worldLength = 0;
    Real pixelLength = 0;
    Real size = 0;
    std::size_t spans = 0;

    Reference(const Scene& scene, const ScreenMap& screen)
        : samples(denseSamples(scene.curve, kSamplesPerSpan)), toWorld(scene.transforms.localToWorld()),
          absoluteToWorld(scene.transforms.absoluteLocalToWorld()),
          errorFactor(Real(scene.transforms.steps.size() + 2) * kFloatRoundoff), size(scene.curve.scale()),
          spans(scene.curve.spans().size())
    {
        Vec3 previousWorld;
        Real previousX = 0, previousY = 0;
        for (std::size_t i = 0; i < samples.local.size(); ++i) {
            const Vec3 world = toWorld.point(samples.local[i]);
            Real x = 0, y = 0;
            screen.map(world, x, y);
            if (i > 0) {
                worldLength += distance(previousWorld, world);
                pixelLength += std::hypot(x - previousX, y - previousY);
            }
            previousWorld = world;
            previousX = x;
            previousY = y;
        }
    }

    /// How far Q3's world image of the vertex at local point p can be from
    /// the test's (see the file comment).
    Real worldError(const Vec3& p) const
    {
        const Real a[3] = {std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)};
        Real sum2 = 0;
        for (int j = 0; j < 3; ++j) {
            const Real v = a[0] * absoluteToWorld.m[0][j] + a[1] * absoluteToWorld.m[1][j] +
                           a[2] * absoluteToWorld.m[2][j] + absoluteToWorld.m[3][j];
            sum2 += v * v;
        }
        return errorFactor * std::sqrt(sum2);
    }
};

/// Running figures for one method, printed at the end.
struct Efficiency {
    std::string name;
    bool adaptive = true;
    int polylines = 0;
    double sum = 0;
    double max = 0;
    double worstOvershoot = 0;   ///< largest segment / c1 seen
    double worstVertexError = 0; ///< largest distance from the curve / size

    /// ratio: segments / (L / c1 + spans); for the constant method, with c1
    /// its longest world segment.
    void add(double ratio)
    {
        ++polylines;
        sum += ratio;
        max = std::max(max, ratio);
    }
    std::string report() const
    {
        const double mean = polylines ? sum / polylines : 0.0;
        char text[320];
        if (adaptive)
            std::snprintf(text, sizeof text,
                          "%s: %d polylines; segments / (L / c1 + spans): mean %.4f, max %.4f; "
                          "longest segment / c1: %.9f; vertex distance from the curve / size: max %.3g",
                          name.c_str(), polylines, mean, max, worstOvershoot, worstVertexError);
        else
            std::snprintf(text, sizeof text,
                          "%s: %d polylines, each trunc(c1) * spans segments; against an adaptive "
                          "subdivision to its longest world segment it uses (segments / (L / longest + "
                          "spans)) mean %.4f, max %.4f times as many; vertex error / size: max %.3g",
                          name.c_str(), polylines, mean, max, worstVertexError);
        return text;
    }
};

std::vector<Vec3> toVecs(const std::vector<TQ3Point3D>& points)
{
    std::vector<Vec3> out;
    for (const TQ3Point3D& p : points)
        out.push_back(toVec(p));
    return out;
}

class SubdivisionPropertyRegressionTest : public q3test::PixmapViewTest {
protected:
    SubdivisionPropertyRegressionTest() : PixmapViewTest(kWidth, kHeight) {}

    void SetUp() override
    {
        PixmapViewTest::SetUp();
        m_seed = seed();
        std::printf("[ subdivision ] random curves from seed %u (set Q3_SUBDIVISION_SEED to replay another)\n",
                    m_seed);
        RecordProperty("seed", std::to_string(m_seed));
    }

    /// Points the view at a scene: its camera and pane.
    void aim(const Scene& scene)
    {
        useCamera(scene.newObject());
        if (scene.paneOn)
            ASSERT_EQ(Q3DrawContext_SetPane(m_context, &scene.pane), kQ3Success);
        ASSERT_EQ(Q3DrawContext_SetPaneState(m_context, scene.paneOn ? kQ3True : kQ3False), kQ3Success);
    }

    /// One rendering loop: for each entry of `styles` (null: submit none),
    /// the style and the scene's transforms are submitted inside a
    /// Push/Pop, the curve is decomposed and then drawn. `inside` runs after
    /// the transforms, before the decomposition.
    std::vector<std::vector<TQ3Point3D>> decompose(const Scene& scene, TQ3GeometryObject curve,
                                                   const std::vector<const TQ3SubdivisionStyleData*>& styles,
                                                   const std::function<void()>& inside = {})
    {
        std::vector<std::vector<TQ3Point3D>> result(styles.size());
        EXPECT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        TQ3ViewStatus status;
        do {
            for (std::size_t i = 0; i < styles.size(); ++i) {
                EXPECT_EQ(Q3Push_Submit(m_view), kQ3Success);
                if (styles[i] != nullptr)
                    EXPECT_EQ(Q3SubdivisionStyle_Submit(styles[i], m_view), kQ3Success);
                scene.transforms.submit(m_view);
                if (inside)
                    inside();
                TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(curve, m_view);
                EXPECT_NE(polyLine, nullptr);
                result[i].clear();
                if (polyLine != nullptr) {
                    TQ3PolyLineData data{};
                    EXPECT_EQ(Q3PolyLine_GetData(polyLine, &data), kQ3Success);
                    for (unsigned long v = 0; v < data.numVertices; ++v)
                        result[i].push_back(data.vertices[v].point);
                    Q3PolyLine_EmptyData(&data);
                    Q3Object_Dispose(polyLine);
                }
                EXPECT_EQ(Q3Geometry_Submit(curve, m_view), kQ3Success);
                EXPECT_EQ(Q3Pop_Submit(m_view), kQ3Success);
            }
            status = Q3View_EndRendering(m_view);
        } while (status == kQ3ViewStatusRetraverse);
        EXPECT_EQ(status, kQ3ViewStatusDone);
        return result;
    }

    /// Checks vertex v against the curve point c at a known parameter: each
    /// coordinate within float rounding of it. Returns the error / size.
    static double expectAt(const Vec3& v, const Vec3& c, Real size, const std::string& what)
    {
        const Real slack = kEvaluationSlack * size;
        const Real dx = std::fabs(v.x - c.x), dy = std::fabs(v.y - c.y), dz = std::fabs(v.z - c.z);
        EXPECT_LE(dx, kFloatRoundoff * std::fabs(c.x) + slack) << what << " x";
        EXPECT_LE(dy, kFloatRoundoff * std::fabs(c.y) + slack) << what << " y";
        EXPECT_LE(dz, kFloatRoundoff * std::fabs(c.z) + slack) << what << " z";
        return double(std::max({dx, dy, dz}) / size);
    }

    /// What every polyline promises: at least two vertices, the domain ends
    /// first and last, no vertex equal to the one before.
    static void expectEndsAndNoRepeats(const Curve& curve, const std::vector<Vec3>& v, Real size,
                                       const std::string& what)
    {
        ASSERT_GE(v.size(), 2u) << what;
        expectAt(v.front(), evaluate(curve, curve.domainStart()), size, what + " first vertex");
        expectAt(v.back(), evaluate(curve, curve.domainEnd()), size, what + " last vertex");
        for (std::size_t i = 1; i < v.size(); ++i) {
            const bool same = v[i].x == v[i - 1].x && v[i].y == v[i - 1].y && v[i].z == v[i - 1].z;
            EXPECT_FALSE(same) << what << " vertex " << i << " repeats vertex " << i - 1;
        }
    }

    /// Every vertex within kOnCurve * size of the curve.
    static void expectOnCurve(const Curve& curve, const Reference& ref, const std::vector<Vec3>& v,
                              Efficiency& figures, const std::string& what)
    {
        const Real tolerance = kOnCurve * ref.size;
        CurveLocator locator(curve, ref.samples, tolerance);
        for (std::size_t i = 0; i < v.size(); ++i) {
            const Real d = locator.distanceOf(v[i]);
            figures.worstVertexError = std::max(figures.worstVertexError, double(d / ref.size));
            EXPECT_LE(d, tolerance) << what << " vertex " << i << " is off the curve";
        }
    }

    /// Whether the test's dense samples of span number `index` all lie
    /// outside one plane of the view volume (margin 0): a span Q3 may draw
    /// as one segment (docs/subdivision.md, "What a view can show").
    static bool spanOutside(const Scene& scene, const Reference& ref, const ScreenMap& map, std::size_t index)
    {
        bool outside[5] = {true, true, true, true, true};
        for (int k = 0; k <= kSamplesPerSpan; ++k) {
            Real f[5];
            map.planes(ref.toWorld.point(ref.samples.local[index * kSamplesPerSpan + std::size_t(k)]), scene.hither(),
                       0, f);
            for (int p = 0; p < 5; ++p)
                outside[p] = outside[p] && f[p] > 0;
        }
        return outside[0] || outside[1] || outside[2] || outside[3] || outside[4];
    }

    /// The constant method: m = trunc(c1) segments per non-empty span at
    /// uniform parameters, span ends once; in a rendering loop a span that
    /// cannot be seen may be one segment (then all its samples are outside
    /// one plane of the view volume).
    static void checkConstant(const Scene& scene, const Reference& ref, const ScreenMap& map, float c1,
                              const std::vector<Vec3>& v, Efficiency& figures, const std::string& what)
    {
        const Curve& curve = scene.curve;
        const std::size_t m = std::size_t(c1);
        ASSERT_LE(v.size(), m * ref.spans + 1) << what << " m " << m << " spans " << ref.spans;
        std::size_t i = 0;
        std::size_t index = 0;
        for (std::size_t s : curve.spans()) {
            const Real a = curve.knots[s], b = curve.knots[s + 1];
            const Vec3 second = evaluate(curve, a + (b - a) / Real(m));
            const Vec3 end = evaluate(curve, b);
            ASSERT_LT(i + 1, v.size()) << what;
            const bool culled = m > 1 && maxAbs(v[i + 1] - second) > maxAbs(v[i + 1] - end);
            if (culled) {
                EXPECT_TRUE(spanOutside(scene, ref, map, index)) << what << " span " << s << " has one segment";
                expectAt(v[i], evaluate(curve, a), ref.size, what + " culled span start");
                ++i;
                ++index;
                continue;
            }
            ++index;
            for (std::size_t j = 0; j < m; ++j, ++i) {
                const Real t = a + (b - a) * Real(j) / Real(m);
                const double e = expectAt(v[i], evaluate(curve, t), ref.size,
                                          what + " vertex " + std::to_string(i) + " (span " + std::to_string(s) +
                                              ", j " + std::to_string(j) + ")");
                figures.worstVertexError = std::max(figures.worstVertexError, e);
            }
        }
        expectAt(v[i], evaluate(curve, curve.domainEnd()), ref.size, what + " last vertex");
        ASSERT_EQ(i + 1, v.size()) << what;
        // For comparison with the adaptive methods: how many segments an
        // adaptive subdivision with the same longest visible world segment
        // would use.
        Real longest = 0;
        for (std::size_t k = 1; k < v.size(); ++k)
            if (map.segmentVisible(ref.toWorld.point(v[k - 1]), ref.toWorld.point(v[k]), scene.hither(), 1e-5L))
                longest = std::max(longest, distance(ref.toWorld.point(v[k - 1]), ref.toWorld.point(v[k])));
        if (!(longest > 0))
            return;
        figures.add(double((v.size() - 1) / (ref.worldLength / longest + ref.spans)));
    }

    /// World or screen space: every segment with a part in the view (more
    /// than 1e-5 view-port units inside: float rounding of Q3's proof that a
    /// span is outside is far smaller) at most c1, and close to the fewest.
    static void checkAdaptive(const Scene& scene, const Reference& ref, const ScreenMap& map, float c1,
                              Real length, const std::vector<Vec3>& v,
                              const std::function<Real(const Vec3&, const Vec3&)>& measure,
                              const std::function<Real(const Vec3&)>& error, Efficiency& figures,
                              const std::string& what)
    {
        for (std::size_t i = 1; i < v.size(); ++i) {
            if (!map.segmentVisible(ref.toWorld.point(v[i - 1]), ref.toWorld.point(v[i]), scene.hither(), 1e-5L))
                continue;
            const Real segment = measure(v[i - 1], v[i]);
            const Real allowed = Real(c1) + error(v[i - 1]) + error(v[i]);
            figures.worstOvershoot = std::max(figures.worstOvershoot, double(segment / c1));
            EXPECT_LE(segment, allowed) << what << " segment " << i - 1 << " of " << v.size() - 1
                                        << " is longer than c1 " << c1;
        }
        const Real segments = Real(v.size() - 1);
        EXPECT_LE(segments, kNearMinimalFactor * length / c1 + ref.spans)
            << what << " length " << double(length) << " c1 " << c1 << " spans " << ref.spans;
        figures.add(double(segments / (length / c1 + ref.spans)));
    }

    unsigned m_seed = 0;
};

void report(const char* key, const Efficiency& figures, ::testing::Test& test)
{
    const std::string text = figures.report();
    std::printf("[ subdivision ] %s\n", text.c_str());
    test.RecordProperty(key, text);
}

TEST_F(SubdivisionPropertyRegressionTest, RandomCurvesObeyEveryMethodUnderRandomTransformsAndCameras)
{
    std::mt19937 rng(m_seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Efficiency constant{"constant", false}, world{"world space"}, screen{"screen space"};
    for (int index = 0; index < kCurves && !HasFatalFailure(); ++index) {
        Scene scene = makeScene(rng, index);
        const ScreenMap map = scene.screen();
        const Reference ref(scene, map);
        const std::string what = "curve " + std::to_string(index) + " (order " +
                                 std::to_string(scene.curve.order) + (scene.curve.clamped ? ", clamped" : "") +
                                 (scene.perspective ? ", perspective" : ", orthographic") + ")";

        // c1 for the adaptive methods: the curve's own length over 3 to 150.
        auto lengthOver = [&](Real length) {
            return float(length / std::exp(std::log(3.0L) + Real(u(rng)) * std::log(50.0L)));
        };
        const float constantC1 = float(u(rng) < 0.8 ? 1 + 12 * u(rng) : 13 + 50 * u(rng));
        const TQ3SubdivisionStyleData styles[3] = {
            {kQ3SubdivisionMethodConstant, constantC1, constantC1},
            {kQ3SubdivisionMethodWorldSpace, lengthOver(ref.worldLength), 1.0f},
            // Not below the floor, which would be replaced with a warning.
            {kQ3SubdivisionMethodScreenSpace, std::max(lengthOver(ref.pixelLength), kQ3SubdivisionMinScreenSpaceC1),
             1.0f}};

        TQ3NURBCurveData data = scene.curve.data();
        TQ3GeometryObject curve = Q3NURBCurve_New(&data);
        ASSERT_NE(curve, nullptr) << what;
        aim(scene);
        const auto polylines = decompose(scene, curve, {&styles[0], &styles[1], &styles[2]});
        Q3Object_Dispose(curve);

        const std::vector<Vec3> byConstant = toVecs(polylines[0]);
        const std::vector<Vec3> byWorld = toVecs(polylines[1]);
        const std::vector<Vec3> byScreen = toVecs(polylines[2]);
        expectEndsAndNoRepeats(scene.curve, byConstant, ref.size, what + " constant");
        expectEndsAndNoRepeats(scene.curve, byWorld, ref.size, what + " world");
        expectEndsAndNoRepeats(scene.curve, byScreen, ref.size, what + " screen");
        if (HasFailure())
            break;

        checkConstant(scene, ref, map, styles[0].c1, byConstant, constant, what + " constant");

        const auto worldLength = [&](const Vec3& a, const Vec3& b) {
            return distance(ref.toWorld.point(a), ref.toWorld.point(b));
        };
        const auto worldError = [&](const Vec3& p) { return ref.worldError(p); };
        expectOnCurve(scene.curve, ref, byWorld, world, what + " world");
        checkAdaptive(scene, ref, map, styles[1].c1, ref.worldLength, byWorld, worldLength, worldError, world,
                      what + " world");

        const auto pixelLength = [&](const Vec3& a, const Vec3& b) {
            Real ax = 0, ay = 0, bx = 0, by = 0;
            EXPECT_TRUE(map.map(ref.toWorld.point(a), ax, ay));
            EXPECT_TRUE(map.map(ref.toWorld.point(b), bx, by));
            return std::hypot(bx - ax, by - ay);
        };
        const auto pixelError = [&](const Vec3& p) {
            return map.pixelError(ref.toWorld.point(p), ref.worldError(p)) + kCameraSlackPixels;
        };
        expectOnCurve(scene.curve, ref, byScreen, screen, what + " screen");
        checkAdaptive(scene, ref, map, styles[2].c1, ref.pixelLength, byScreen, pixelLength, pixelError, screen,
                      what + " screen");
        if (HasFailure()) {
            std::printf("[ subdivision ] first failing curve: %s, seed %u\n", what.c_str(), m_seed);
            break;
        }
    }
    report("constant", constant, *this);
    report("world", world, *this);
    report("screen", screen, *this);
}

// Without a subdivision style the view subdivides in screen space with
// c1 = c2 = 20 pixels (QD3DView.h's kQ3ViewDefaultSubdivision*): the state
// says so, every segment is at most 20 pixels, the count is near minimal, and
// the polyline is the very one an explicit {screen space, 20, 20} gives.
TEST_F(SubdivisionPropertyRegressionTest, WithoutAStyleTheViewUsesScreenSpaceTwentyPixels)
{
    std::mt19937 rng(m_seed + 1);
    std::printf("[ subdivision ] default-style curves from seed %u + 1\n", m_seed);
    Efficiency byDefault{"default (screen space, 20 px)"};
    const TQ3SubdivisionStyleData explicitDefault = {kQ3SubdivisionMethodScreenSpace, 20.0f, 20.0f};
    for (int index = 0; index < kDefaultStyleCurves && !HasFatalFailure(); ++index) {
        Scene scene = makeScene(rng, index);
        const ScreenMap map = scene.screen();
        const Reference ref(scene, map);
        const std::string what = "curve " + std::to_string(index);
        TQ3NURBCurveData data = scene.curve.data();
        TQ3GeometryObject curve = Q3NURBCurve_New(&data);
        ASSERT_NE(curve, nullptr);
        aim(scene);
        TQ3SubdivisionStyleData state{};
        const auto polylines = decompose(scene, curve, {nullptr, &explicitDefault}, [&] {
            if (state.c1 == 0.0f)
                EXPECT_EQ(Q3View_GetSubdivisionStyleState(m_view, &state), kQ3Success);
        });
        Q3Object_Dispose(curve);
        EXPECT_EQ(state.method, kQ3SubdivisionMethodScreenSpace);
        EXPECT_EQ(state.c1, 20.0f);
        EXPECT_EQ(state.c2, 20.0f);

        const std::vector<Vec3> v = toVecs(polylines[0]);
        expectEndsAndNoRepeats(scene.curve, v, ref.size, what);
        ASSERT_EQ(polylines[0].size(), polylines[1].size()) << what;
        for (std::size_t i = 0; i < v.size(); ++i) {
            EXPECT_EQ(polylines[0][i].x, polylines[1][i].x) << what << " vertex " << i;
            EXPECT_EQ(polylines[0][i].y, polylines[1][i].y) << what << " vertex " << i;
            EXPECT_EQ(polylines[0][i].z, polylines[1][i].z) << what << " vertex " << i;
        }
        expectOnCurve(scene.curve, ref, v, byDefault, what);
        checkAdaptive(
            scene, ref, map, 20.0f, ref.pixelLength, v,
            [&](const Vec3& a, const Vec3& b) {
                Real ax = 0, ay = 0, bx = 0, by = 0;
                map.map(ref.toWorld.point(a), ax, ay);
                map.map(ref.toWorld.point(b), bx, by);
                return std::hypot(bx - ax, by - ay);
            },
            [&](const Vec3& p) {
                return map.pixelError(ref.toWorld.point(p), ref.worldError(p)) + kCameraSlackPixels;
            },
            byDefault, what);
    }
    report("default", byDefault, *this);
}

} // namespace
