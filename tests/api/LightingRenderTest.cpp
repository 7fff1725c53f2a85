// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Lit pixels against the QD3D Book's illumination equations, evaluated here
// (not by Q3): a square facing an orthographic camera, lit at every pixel
// (kQ3InterpolationStylePixel), each sampled pixel's colour compared with
//
//   Lambert:  I = ka Ia Od + sum f_i Ii Od max(0, N . L_i)
//   Phong:    I = Lambert + sum f_i Ii Os max(0, R_i . V)^n   (only where N . L_i > 0)
//
// with Ia the ambient lights' colours times brightness, Ii a light's colour
// times brightness, f_i its attenuation (1, 1/d, 1/d^2) times a spot light's
// fall-off between its hot angle (full) and its outer angle (none), and the
// result clamped to [0, 1] and stored in 8 bits.

#include "OwningApiTest.h"
#include "RenderTestSupport.h"

#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace {

using q3test::Pixmap;
using q3test::Rgba;
using q3test::TestView;

constexpr unsigned long kSize = 64;   // pixels each way
constexpr double kHalf = 2.0;         // the camera shows x and y in [-2, 2]
constexpr double kPi = 3.14159265358979323846;

struct Vec {
    double x, y, z;
};
Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec operator*(double k, Vec a) { return {k * a.x, k * a.y, k * a.z}; }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double length(Vec a) { return std::sqrt(dot(a, a)); }
Vec unit(Vec a) { return (1.0 / length(a)) * a; }

// A light as the test's evaluator sees it.
struct Light {
    enum Kind { kAmbient, kDirectional, kPoint, kSpot } kind = kAmbient;
    Vec color{1, 1, 1};
    double brightness = 1;
    Vec direction{0, 0, -1};
    Vec location{0, 0, 0};
    int attenuation = 0;  // 0 none, 1 1/d, 2 1/d^2
    double hot = 0, outer = 0;
    int fallOff = 0;      // 0 none, 1 linear, 2 exponential, 3 cosine
};

struct Surface {
    Vec diffuse{1, 1, 1};
    Vec specular{1, 1, 1};
    double control = 4;
    double ambientCoefficient = 1;
    bool phong = false;
};

// The spot light's fall-off factor at angle from its axis; -1 outside.
double fallOffFactor(const Light& light, double angle)
{
    if (angle > light.outer)
        return -1;
    if (angle <= light.hot)
        return 1;
    const double t = (angle - light.hot) / (light.outer - light.hot);
    switch (light.fallOff) {
    case 1: return 1 - t;
    case 2: return (std::exp(1 - t) - 1) / (std::exp(1.0) - 1);
    case 3: return std::cos(t * kPi / 2);
    default: return 1;
    }
}

// The book's equations at point p with normal n, seen along -z (the
// orthographic camera's direction), one channel at a time.
Vec shade(const std::vector<Light>& lights, const Surface& s, Vec p, Vec n)
{
    const Vec toEye{0, 0, 1};
    Vec ambient{0, 0, 0};
    Vec sum{0, 0, 0};
    for (const Light& light : lights) {
        const Vec li = light.brightness * light.color;
        if (light.kind == Light::kAmbient) {
            ambient = {ambient.x + li.x, ambient.y + li.y, ambient.z + li.z};
            continue;
        }
        Vec l;
        double f = 1;
        if (light.kind == Light::kDirectional) {
            l = unit(-1.0 * light.direction);
        } else {
            const Vec d = light.location - p;
            const double distance = length(d);
            l = (1.0 / distance) * d;
            f = light.attenuation == 1 ? 1 / distance : light.attenuation == 2 ? 1 / (distance * distance) : 1;
            if (light.kind == Light::kSpot) {
                const double angle = std::acos(std::clamp(dot(-1.0 * l, unit(light.direction)), -1.0, 1.0));
                const double factor = fallOffFactor(light, angle);
                if (factor < 0)
                    continue;
                f *= factor;
            }
        }
        const double nl = dot(n, l);
        if (nl <= 0)
            continue;
        double term[3] = {f * nl * li.x * s.diffuse.x, f * nl * li.y * s.diffuse.y, f * nl * li.z * s.diffuse.z};
        if (s.phong) {
            const Vec r = (2 * nl) * n - l;
            const double rv = dot(r, toEye);
            if (rv > 0) {
                const double k = f * std::pow(rv, s.control);
                term[0] += k * li.x * s.specular.x;
                term[1] += k * li.y * s.specular.y;
                term[2] += k * li.z * s.specular.z;
            }
        }
        sum = {sum.x + term[0], sum.y + term[1], sum.z + term[2]};
    }
    const double ka = s.ambientCoefficient;
    return {ka * ambient.x * s.diffuse.x + sum.x, ka * ambient.y * s.diffuse.y + sum.y,
            ka * ambient.z * s.diffuse.z + sum.z};
}

int toByte(double v)
{
    return int(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

// The world point at the centre of pixel (i, j) on the plane z = 0.
Vec worldAt(unsigned long i, unsigned long j)
{
    return {q3test::pixelCentre(i, kSize, kHalf), -q3test::pixelCentre(j, kSize, kHalf), 0};
}

class LightingRenderTest : public q3test::OwningApiTest {
protected:
    TQ3CameraObject camera()
    {
        const TQ3OrthographicCameraData data = q3test::orthographicCameraAt(0, 0, float(kHalf), float(kHalf));
        return own(Q3OrthographicCamera_New(&data));
    }

    // The back-face tests' scene: a directional light along `direction`,
    // a Lambert shader and a surface of diffuse colour (0.9, 0.5, 0.2).
    struct BackFaceScene {
        Light light;
        Surface surface;
        TQ3LightObject object;
        TQ3ShaderObject lambert;
        TQ3AttributeSet set;
    };
    BackFaceScene backFaceScene(const Vec& direction)
    {
        BackFaceScene scene;
        scene.light.kind = Light::kDirectional;
        scene.light.direction = direction;
        scene.surface.diffuse = {0.9, 0.5, 0.2};
        scene.object = newLight(scene.light);
        scene.lambert = own(Q3LambertIllumination_New());
        scene.set = surfaceSet(scene.surface);
        return scene;
    }

    TQ3LightObject newLight(const Light& light)
    {
        TQ3LightData base{kQ3True, float(light.brightness),
                          {float(light.color.x), float(light.color.y), float(light.color.z)}};
        const TQ3Vector3D direction{float(light.direction.x), float(light.direction.y), float(light.direction.z)};
        const TQ3Point3D location{float(light.location.x), float(light.location.y), float(light.location.z)};
        switch (light.kind) {
        case Light::kAmbient:
            return own(Q3AmbientLight_New(&base));
        case Light::kDirectional: {
            const TQ3DirectionalLightData data{base, kQ3False, direction};
            return own(Q3DirectionalLight_New(&data));
        }
        case Light::kPoint: {
            const TQ3PointLightData data{base, kQ3False, TQ3AttenuationType(light.attenuation), location};
            return own(Q3PointLight_New(&data));
        }
        default: {
            const TQ3SpotLightData data{base,        kQ3False,           TQ3AttenuationType(light.attenuation),
                                        location,    direction,          float(light.hot),
                                        float(light.outer), TQ3FallOffType(light.fallOff)};
            return own(Q3SpotLight_New(&data));
        }
        }
    }

    TQ3AttributeSet surfaceSet(const Surface& s)
    {
        TQ3AttributeSet set = own(Q3AttributeSet_New());
        const TQ3ColorRGB diffuse{float(s.diffuse.x), float(s.diffuse.y), float(s.diffuse.z)};
        const TQ3ColorRGB specular{float(s.specular.x), float(s.specular.y), float(s.specular.z)};
        const float control = float(s.control), ka = float(s.ambientCoefficient);
        EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &diffuse), kQ3Success);
        EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeSpecularColor, &specular), kQ3Success);
        EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeSpecularControl, &control), kQ3Success);
        EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeAmbientCoefficient, &ka), kQ3Success);
        return set;
    }

    // The square z = 0 over the whole view, counterclockwise from +z (facing
    // the camera) unless facingAway.
    TQ3GeometryObject square(TQ3AttributeSet set, bool facingAway = false)
    {
        const float h = float(kHalf) + 0.5f;
        std::vector<TQ3Vertex3D> v{{{-h, -h, 0}, nullptr}, {{h, -h, 0}, nullptr}, {{h, h, 0}, nullptr},
                                   {{-h, h, 0}, nullptr}};
        if (facingAway)
            std::reverse(v.begin(), v.end());
        const TQ3PolygonData data{4, v.data(), set};
        return own(Q3Polygon_New(&data));
    }

    // Renders the square lit by lights (the light objects given, so that a
    // test may edit them first) through the shader. With `placement`, the
    // square is drawn through that transform from `modelled` instead.
    Pixmap render(const std::vector<TQ3LightObject>& lights, TQ3ShaderObject shader, TQ3AttributeSet set,
                  TQ3BackfacingStyle backfacing = kQ3BackfacingStyleBoth, bool facingAway = false,
                  TQ3InterpolationStyle interpolation = kQ3InterpolationStylePixel,
                  const TQ3Matrix4x4* placement = nullptr, TQ3GeometryObject modelled = nullptr)
    {
        Pixmap image(kSize, kSize);
        TestView view(image.pixmap(), kQ3RendererTypeInteractive, camera());
        TQ3GroupObject group = own(Q3LightGroup_New());
        for (TQ3LightObject light : lights)
            EXPECT_NE(Q3Group_AddObject(group, light), nullptr);
        EXPECT_EQ(Q3View_SetLightGroup(view.view(), group), kQ3Success);
        TQ3GeometryObject geometry = placement != nullptr ? modelled : square(set, facingAway);
        EXPECT_EQ(view.render([&](TQ3ViewObject v) {
            Q3InterpolationStyle_Submit(interpolation, v);
            Q3BackfacingStyle_Submit(backfacing, v);
            if (shader != nullptr)
                Q3Shader_Submit(shader, v);
            if (placement != nullptr)
                Q3MatrixTransform_Submit(placement, v);
            Q3Geometry_Submit(geometry, v);
        }),
                  kQ3ViewStatusDone);
        return image;
    }

    // Compares every fourth pixel each way with the evaluator; skip() names
    // pixels too near a discontinuity (a spot light's cone) to sample.
    void expectLit(const Pixmap& image, const std::vector<Light>& lights, const Surface& s, Vec normal,
                   const std::string& what, const std::function<bool(Vec)>& skip = nullptr)
    {
        int checked = 0, wrong = 0;
        std::string first;
        for (unsigned long j = 2; j < kSize; j += 4)
            for (unsigned long i = 2; i < kSize; i += 4) {
                const Vec p = worldAt(i, j);
                if (skip && skip(p))
                    continue;
                const Vec expected = shade(lights, s, p, normal);
                const Rgba got = image.at(i, j);
                ++checked;
                const int tolerance = 2;
                if (std::abs(got.r - toByte(expected.x)) > tolerance ||
                    std::abs(got.g - toByte(expected.y)) > tolerance ||
                    std::abs(got.b - toByte(expected.z)) > tolerance) {
                    if (wrong++ == 0)
                        first = "pixel (" + std::to_string(i) + ", " + std::to_string(j) + "): got " +
                                std::to_string(got.r) + " " + std::to_string(got.g) + " " + std::to_string(got.b) +
                                ", expected " + std::to_string(toByte(expected.x)) + " " +
                                std::to_string(toByte(expected.y)) + " " + std::to_string(toByte(expected.z));
                }
            }
        EXPECT_GT(checked, 100) << what;
        EXPECT_EQ(wrong, 0) << what << ": " << first;
    }

    // A dim ambient light (brightness 0.1), a white point light, and a
    // Phong surface.
    struct PhongScene {
        Light ambient;
        Light point;
        Surface surface;
    };
    static PhongScene phongScene(Vec location, double brightness, int attenuation, Vec diffuse, Vec specular,
                                 double control)
    {
        PhongScene scene;
        scene.ambient.brightness = 0.1;
        scene.point.kind = Light::kPoint;
        scene.point.location = location;
        scene.point.brightness = brightness;
        scene.point.attenuation = attenuation;
        scene.surface.diffuse = diffuse;
        scene.surface.specular = specular;
        scene.surface.control = control;
        scene.surface.phong = true;
        return scene;
    }

    const Vec m_up{0, 0, 1}; // the square's normal, towards the camera
};

TEST_F(LightingRenderTest, AnAmbientLightScalesTheDiffuseColourByTheAmbientCoefficient)
{
    Light ambient;
    ambient.color = {1.0, 0.8, 0.6};
    ambient.brightness = 0.5;
    Surface s;
    s.diffuse = {0.9, 0.6, 0.3};
    s.ambientCoefficient = 0.8;
    const Pixmap image = render({newLight(ambient)}, own(Q3LambertIllumination_New()), surfaceSet(s));
    expectLit(image, {ambient}, s, m_up, "ambient");
}

TEST_F(LightingRenderTest, ADirectionalLightAddsTheCosineOfItsAngle)
{
    Light ambient;
    ambient.brightness = 0.1;
    Light directional;
    directional.kind = Light::kDirectional;
    directional.direction = {1, 0.5, -1};
    directional.brightness = 0.8;
    directional.color = {0.9, 1.0, 0.7};
    Surface s;
    s.diffuse = {0.7, 0.5, 0.9};
    const std::vector<Light> lights{ambient, directional};
    const Pixmap image =
        render({newLight(ambient), newLight(directional)}, own(Q3LambertIllumination_New()), surfaceSet(s));
    expectLit(image, lights, s, m_up, "directional");
}

TEST_F(LightingRenderTest, PointLightsFadeAsTheirAttenuationSays)
{
    for (int attenuation = 0; attenuation <= 2; ++attenuation) {
        Light point;
        point.kind = Light::kPoint;
        point.location = {0.5, -0.3, 1.5};
        point.attenuation = attenuation;
        point.brightness = attenuation == 2 ? 2.0 : 1.2;
        Surface s;
        s.diffuse = {0.8, 0.7, 0.6};
        const Pixmap image = render({newLight(point)}, own(Q3LambertIllumination_New()), surfaceSet(s));
        expectLit(image, {point}, s, m_up, "attenuation " + std::to_string(attenuation));
    }
}

TEST_F(LightingRenderTest, SpotLightsFallOffBetweenTheirHotAndOuterAngles)
{
    for (int fallOff = 0; fallOff <= 3; ++fallOff) {
        Light spot;
        spot.kind = Light::kSpot;
        spot.location = {0.2, 0.1, 3};
        spot.direction = {0, 0, -1};
        spot.hot = 0.25;
        spot.outer = 0.55;
        spot.fallOff = fallOff;
        Light ambient;
        ambient.brightness = 0.05;
        Surface s;
        s.diffuse = {0.9, 0.9, 0.8};
        const Pixmap image =
            render({newLight(ambient), newLight(spot)}, own(Q3LambertIllumination_New()), surfaceSet(s));
        // Pixels whose angle is within 0.02 rad of the outer angle (where a
        // light without fall-off stops at once) are not sampled.
        const auto nearEdge = [&](Vec p) {
            const double angle = std::atan2(std::hypot(p.x - spot.location.x, p.y - spot.location.y), 3.0);
            return std::abs(angle - spot.outer) < 0.02;
        };
        expectLit(image, {ambient, spot}, s, m_up, "fall-off " + std::to_string(fallOff), nearEdge);
        // The cone shows: the middle is lit far above the corners.
        EXPECT_GT(image.at(kSize / 2, kSize / 2).r, image.at(1, 1).r + 100) << fallOff;
    }
}

TEST_F(LightingRenderTest, PhongAddsTheSpecularTermToLambert)
{
    auto [ambient, point, s] = phongScene({-0.4, 0.6, 2.5}, 0.7, 0, {0.5, 0.2, 0.1}, {0.9, 0.9, 1.0}, 12);
    const std::vector<Light> lights{ambient, point};
    const Pixmap phong = render({newLight(ambient), newLight(point)}, own(Q3PhongIllumination_New()), surfaceSet(s));
    expectLit(phong, lights, s, m_up, "phong");
    s.phong = false;
    const Pixmap lambert =
        render({newLight(ambient), newLight(point)}, own(Q3LambertIllumination_New()), surfaceSet(s));
    expectLit(lambert, lights, s, m_up, "lambert");
}

// A geometry drawn through a transform is lit where the transform puts it,
// with its normals by the transform's inverse transpose; one drawn without
// is lit where it was modelled (the renderer lights the two by different
// program variants, LitProgram.h's LOCAL_IS_WORLD).
TEST_F(LightingRenderTest, ASquarePutInPlaceByATransformIsLitWhereItIsDrawn)
{
    const auto [ambient, point, s] = phongScene({0.5, -0.3, 1.5}, 1.3, 1, {0.8, 0.6, 0.4}, {0.9, 0.8, 1.0}, 10);
    const std::vector<Light> lights{ambient, point};
    // Modelled at half its width, tilted back and one unit behind z = 0:
    // the transform (row vectors, p' = p M) doubles x, turns z' = z - y,
    // and adds 1 to z, so that it lands on z = 0 with the normal (0, 0, 1)
    // only by the inverse transpose (the local normal is (0, -1, 1) / sqrt 2).
    const float h = float(kHalf) + 0.5f;
    std::vector<TQ3Vertex3D> v{{{-h / 2, -h, -1 - h}, nullptr},
                               {{h / 2, -h, -1 - h}, nullptr},
                               {{h / 2, h, -1 + h}, nullptr},
                               {{-h / 2, h, -1 + h}, nullptr}};
    const TQ3PolygonData data{4, v.data(), surfaceSet(s)};
    TQ3GeometryObject modelled = own(Q3Polygon_New(&data));
    TQ3Matrix4x4 placement{};
    placement.value[0][0] = 2;
    placement.value[1][1] = 1;
    placement.value[1][2] = -1;
    placement.value[2][2] = 1;
    placement.value[3][2] = 1;
    placement.value[3][3] = 1;
    const auto drawn = [&](TQ3InterpolationStyle interpolation, const TQ3Matrix4x4* through) {
        return render({newLight(ambient), newLight(point)}, own(Q3PhongIllumination_New()), surfaceSet(s),
                      kQ3BackfacingStyleBoth, false, interpolation, through, modelled);
    };
    expectLit(drawn(kQ3InterpolationStylePixel, &placement), lights, s, m_up, "through the transform");
    // Lit at the corners and interpolated: the same pixels as the square
    // modelled in place.
    const Pixmap moved = drawn(kQ3InterpolationStyleVertex, &placement);
    const Pixmap inPlace = drawn(kQ3InterpolationStyleVertex, nullptr);
    int differing = 0;
    for (unsigned long j = 0; j < kSize; ++j)
        for (unsigned long i = 0; i < kSize; ++i) {
            const Rgba a = moved.at(i, j), b = inPlace.at(i, j);
            differing += std::abs(a.r - b.r) > 1 || std::abs(a.g - b.g) > 1 || std::abs(a.b - b.b) > 1;
        }
    EXPECT_EQ(differing, 0) << "lit at the vertices";
}

TEST_F(LightingRenderTest, WithoutAnIlluminationShaderOrWithTheNullOneSurfacesShowTheirDiffuseColour)
{
    Light directional;
    directional.kind = Light::kDirectional;
    directional.direction = {0, 0, -1};
    Surface s;
    s.diffuse = {0.3, 0.6, 0.9};
    for (const bool null : {false, true}) {
        const Pixmap image = render({newLight(directional)}, null ? own(Q3NULLIllumination_New()) : nullptr,
                                    surfaceSet(s));
        const Rgba c = image.at(kSize / 3, kSize / 2);
        // Within one step: 0.3 * 255 = 76.5 rounds either way in float.
        EXPECT_NEAR(c.r, toByte(0.3), 1) << null;
        EXPECT_NEAR(c.g, toByte(0.6), 1) << null;
        EXPECT_NEAR(c.b, toByte(0.9), 1) << null;
    }
}

TEST_F(LightingRenderTest, ALightThatIsOffOrDimmedLightsAccordingly)
{
    Light ambient;
    ambient.brightness = 0.2;
    Light directional;
    directional.kind = Light::kDirectional;
    directional.direction = {-1, 0, -2};
    directional.brightness = 0.9;
    Surface s;
    s.diffuse = {0.8, 0.8, 0.8};
    TQ3LightObject a = newLight(ambient);
    TQ3LightObject d = newLight(directional);
    TQ3ShaderObject lambert = own(Q3LambertIllumination_New());
    TQ3AttributeSet set = surfaceSet(s);

    ASSERT_EQ(Q3Light_SetState(d, kQ3False), kQ3Success);
    expectLit(render({a, d}, lambert, set), {ambient}, s, m_up, "directional off");

    ASSERT_EQ(Q3Light_SetState(d, kQ3True), kQ3Success);
    ASSERT_EQ(Q3Light_SetBrightness(d, 0.4f), kQ3Success);
    const TQ3ColorRGB green{0.2f, 1.0f, 0.4f};
    ASSERT_EQ(Q3Light_SetColor(d, &green), kQ3Success);
    directional.brightness = 0.4;
    directional.color = {0.2, 1.0, 0.4};
    expectLit(render({a, d}, lambert, set), {ambient, directional}, s, m_up, "dimmed and green");
}

TEST_F(LightingRenderTest, FlippedBackFacesAreLitWithTheReversedNormal)
{
    // Towards the square, from the camera's side.
    const auto [directional, s, d, lambert, set] = backFaceScene({0.5, 0, -1});
    // Facing away, its normal is -z: the light is behind it, nothing lights it.
    expectLit(render({d}, lambert, set, kQ3BackfacingStyleBoth, true), {directional}, s, {0, 0, -1},
              "back face, both");
    // Flipped, it is lit as a front face would be.
    expectLit(render({d}, lambert, set, kQ3BackfacingStyleFlip, true), {directional}, s, m_up, "back face, flip");
    // Removed, nothing is drawn: the clear colour (opaque black) stays.
    const Pixmap removed = render({d}, lambert, set, kQ3BackfacingStyleRemove, true);
    const Rgba c = removed.at(kSize / 2, kSize / 2);
    EXPECT_EQ(c.r + c.g + c.b, 0);
}

// The QD3D Book ("Backfacing Styles"): under kQ3BackfacingStyleBoth back faces
// are drawn with their own normals, "illuminated only dimly or not at all,
// because their face normals point away from the camera"; only the flip
// style inverts them. So a light on the side a back face's normal points to
// (behind it, seen from the camera) lights it, and flipping turns it away.
TEST_F(LightingRenderTest, BackFacesUnderBothKeepTheirNormalAsTheBookSays)
{
    // From behind the square, towards the camera.
    const auto [directional, s, d, lambert, set] = backFaceScene({0.5, 0, 1});
    // Facing away, its normal -z points at the light: lit by it.
    expectLit(render({d}, lambert, set, kQ3BackfacingStyleBoth, true), {directional}, s, {0, 0, -1},
              "back face lit from behind, both");
    const Pixmap both = render({d}, lambert, set, kQ3BackfacingStyleBoth, true);
    const Rgba lit = both.at(kSize / 2, kSize / 2);
    EXPECT_GT(lit.r, 100) << "the light behind the back face lights it";
    // Flipped, its normal +z points away from the light: unlit.
    expectLit(render({d}, lambert, set, kQ3BackfacingStyleFlip, true), {directional}, s, m_up,
              "back face lit from behind, flip");
}

} // namespace
