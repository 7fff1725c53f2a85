// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Styles, illumination shaders, lights and transforms written and read back
// in every encoding and mode, compared through their Get calls; and a light
// group and a group of them together.

#include "FileTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"

#include <cstring>
#include <functional>
#include <string>

using namespace q3test;

namespace {

const TQ3FileMode kModes[] = {kQ3FileModeNormal, kQ3FileModeText, kQ3FileModeStream | kQ3FileModeText,
                              kQ3FileModeDatabase};

struct StateCase {
    std::string name;
    std::function<TQ3Object()> make;
    std::function<bool(TQ3Object, TQ3Object)> same;
};

// Compares what one Get call gives for both objects, byte for byte.
template <class V, class Get>
std::function<bool(TQ3Object, TQ3Object)> sameBy(Get get)
{
    return [get](TQ3Object a, TQ3Object b) {
        V va, vb;
        std::memset(&va, 0, sizeof va);
        std::memset(&vb, 0, sizeof vb);
        return get(a, &va) == kQ3Success && get(b, &vb) == kQ3Success && std::memcmp(&va, &vb, sizeof va) == 0;
    };
}

bool sameType(TQ3Object a, TQ3Object b)
{
    return Q3Object_GetLeafType(a) == Q3Object_GetLeafType(b);
}

std::vector<StateCase> stateCases()
{
    std::vector<StateCase> all;
    all.push_back({"SubdivisionConstant",
                   [] {
                       TQ3SubdivisionStyleData d = {kQ3SubdivisionMethodConstant, 12, 7};
                       return Q3SubdivisionStyle_New(&d);
                   },
                   sameBy<TQ3SubdivisionStyleData>(Q3SubdivisionStyle_GetData)});
    all.push_back({"SubdivisionScreen",
                   [] {
                       TQ3SubdivisionStyleData d = {kQ3SubdivisionMethodScreenSpace, 3.5f, 3.5f};
                       return Q3SubdivisionStyle_New(&d);
                   },
                   sameBy<TQ3SubdivisionStyleData>(Q3SubdivisionStyle_GetData)});
    all.push_back({"AntiAlias",
                   [] {
                       TQ3AntiAliasStyleData d = {kQ3On, kQ3AntiAliasModeMaskEdges | kQ3AntiAliasModeMaskFilled, 0.5f};
                       return Q3AntiAliasStyle_New(&d);
                   },
                   sameBy<TQ3AntiAliasStyleData>(Q3AntiAliasStyle_GetData)});
    all.push_back({"Fog",
                   [] {
                       TQ3FogStyleData d = {kQ3On, kQ3FogModeExponential, 1, 10, 0.25f, {1, 0.5f, 0.25f, 0.75f}};
                       return Q3FogStyle_New(&d);
                   },
                   sameBy<TQ3FogStyleData>(Q3FogStyle_GetData)});
    all.push_back({"Highlight",
                   [] {
                       TQ3AttributeSet set = Q3AttributeSet_New();
                       const TQ3ColorRGB yellow = {1, 1, 0};
                       Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &yellow);
                       TQ3Object style = Q3HighlightStyle_New(set);
                       Q3Object_Dispose(set);
                       return style;
                   },
                   [](TQ3Object a, TQ3Object b) {
                       TQ3AttributeSet sa = nullptr, sb = nullptr;
                       Q3HighlightStyle_Get(a, &sa);
                       Q3HighlightStyle_Get(b, &sb);
                       TQ3ColorRGB ca = {}, cb = {};
                       const bool same = sa != nullptr && sb != nullptr &&
                                         Q3AttributeSet_Get(sa, kQ3AttributeTypeDiffuseColor, &ca) == kQ3Success &&
                                         Q3AttributeSet_Get(sb, kQ3AttributeTypeDiffuseColor, &cb) == kQ3Success &&
                                         std::memcmp(&ca, &cb, sizeof ca) == 0;
                       if (sa != nullptr)
                           Q3Object_Dispose(sa);
                       if (sb != nullptr)
                           Q3Object_Dispose(sb);
                       return same;
                   }});
    all.push_back({"Backfacing", [] { return Q3BackfacingStyle_New(kQ3BackfacingStyleFlip); },
                   sameBy<TQ3BackfacingStyle>(Q3BackfacingStyle_Get)});
    all.push_back({"Interpolation", [] { return Q3InterpolationStyle_New(kQ3InterpolationStylePixel); },
                   sameBy<TQ3InterpolationStyle>(Q3InterpolationStyle_Get)});
    all.push_back({"Fill", [] { return Q3FillStyle_New(kQ3FillStyleEdges); }, sameBy<TQ3FillStyle>(Q3FillStyle_Get)});
    all.push_back({"Orientation", [] { return Q3OrientationStyle_New(kQ3OrientationStyleClockwise); },
                   sameBy<TQ3OrientationStyle>(Q3OrientationStyle_Get)});
    all.push_back({"PickID", [] { return Q3PickIDStyle_New(123456); }, sameBy<unsigned long>(Q3PickIDStyle_Get)});
    all.push_back({"PickParts", [] { return Q3PickPartsStyle_New(kQ3PickPartsMaskFace | kQ3PickPartsMaskVertex); },
                   sameBy<TQ3PickParts>(Q3PickPartsStyle_Get)});
    all.push_back({"CastShadows", [] { return Q3CastShadowsStyle_New(kQ3False); },
                   sameBy<TQ3Boolean>(Q3CastShadowsStyle_Get)});
    all.push_back({"ReceiveShadows", [] { return Q3ReceiveShadowsStyle_New(kQ3True); },
                   sameBy<TQ3Boolean>(Q3ReceiveShadowsStyle_Get)});
    all.push_back({"Phong", [] { return Q3PhongIllumination_New(); }, sameType});
    all.push_back({"Lambert", [] { return Q3LambertIllumination_New(); }, sameType});
    all.push_back({"NULLIllumination", [] { return Q3NULLIllumination_New(); }, sameType});
    all.push_back({"AmbientLight",
                   [] {
                       TQ3LightData d = {kQ3True, 0.25f, {1, 0.5f, 0.25f}};
                       return Q3AmbientLight_New(&d);
                   },
                   sameBy<TQ3LightData>(Q3AmbientLight_GetData)});
    all.push_back({"DirectionalLight",
                   [] {
                       TQ3DirectionalLightData d = {{kQ3False, 0.75f, {0.5f, 1, 1}}, kQ3True, {0, -1, 0}};
                       return Q3DirectionalLight_New(&d);
                   },
                   sameBy<TQ3DirectionalLightData>(Q3DirectionalLight_GetData)});
    all.push_back({"PointLight",
                   [] {
                       TQ3PointLightData d = {{kQ3True, 1, {1, 1, 1}}, kQ3False, kQ3AttenuationTypeInverseDistance,
                                              {1, 2, 3}};
                       return Q3PointLight_New(&d);
                   },
                   sameBy<TQ3PointLightData>(Q3PointLight_GetData)});
    all.push_back({"SpotLight",
                   [] {
                       TQ3SpotLightData d = {{kQ3True, 0.5f, {1, 1, 0}}, kQ3True,
                                             kQ3AttenuationTypeInverseDistanceSquared,
                                             {0, 5, 0}, {0, -1, 0}, 0.25f, 0.5f, kQ3FallOffTypeCosine};
                       return Q3SpotLight_New(&d);
                   },
                   sameBy<TQ3SpotLightData>(Q3SpotLight_GetData)});
    all.push_back({"Matrix",
                   [] {
                       TQ3Matrix4x4 m = {{{1, 2, 3, 0}, {0, 1, 0, 0}, {0, 0.5f, 1, 0}, {4, 5, 6, 1}}};
                       return Q3MatrixTransform_New(&m);
                   },
                   sameBy<TQ3Matrix4x4>(Q3MatrixTransform_Get)});
    all.push_back({"Translate",
                   [] {
                       TQ3Vector3D v = {1, -2, 3.5f};
                       return Q3TranslateTransform_New(&v);
                   },
                   sameBy<TQ3Vector3D>(Q3TranslateTransform_Get)});
    all.push_back({"Scale",
                   [] {
                       TQ3Vector3D v = {2, 0.5f, 1};
                       return Q3ScaleTransform_New(&v);
                   },
                   sameBy<TQ3Vector3D>(Q3ScaleTransform_Get)});
    all.push_back({"Rotate",
                   [] {
                       TQ3RotateTransformData d = {kQ3AxisY, 0.75f};
                       return Q3RotateTransform_New(&d);
                   },
                   sameBy<TQ3RotateTransformData>(Q3RotateTransform_GetData)});
    all.push_back({"Quaternion",
                   [] {
                       TQ3Quaternion q = {0.5f, -0.5f, 0.25f, 2.0f}; // kept as given, not normalized
                       return Q3QuaternionTransform_New(&q);
                   },
                   sameBy<TQ3Quaternion>(Q3QuaternionTransform_Get)});
    all.push_back({"RotateAboutPoint",
                   [] {
                       TQ3RotateAboutPointTransformData d = {kQ3AxisZ, -1.25f, {1.0f, 2.0f, -3.0f}};
                       return Q3RotateAboutPointTransform_New(&d);
                   },
                   sameBy<TQ3RotateAboutPointTransformData>(Q3RotateAboutPointTransform_GetData)});
    all.push_back({"RotateAboutAxis",
                   [] {
                       TQ3RotateAboutAxisTransformData d = {{0.5f, 0.0f, 1.0f}, {0.0f, 3.0f, 4.0f}, 2.5f};
                       return Q3RotateAboutAxisTransform_New(&d);
                   },
                   sameBy<TQ3RotateAboutAxisTransformData>(Q3RotateAboutAxisTransform_GetData)});
    all.push_back({"Reset", [] { return Q3ResetTransform_New(); }, sameType});
    return all;
}

class FileStateRoundTripTest : public Q3ApiTest, public ::testing::WithParamInterface<std::size_t> {};
class FileLightGroupTest : public Q3ApiTest {};

} // namespace

TEST_P(FileStateRoundTripTest, WrittenAndReadBackInEveryModeIsTheSame)
{
    const StateCase c = stateCases()[GetParam()];
    TQ3Object original = c.make();
    ASSERT_NE(original, nullptr);
    for (TQ3FileMode mode : kModes) {
        SCOPED_TRACE(mode);
        const auto objects = readAll(writeObjects({original}, mode));
        ASSERT_EQ(objects.size(), 1u);
        EXPECT_EQ(Q3Object_GetLeafType(objects[0]), Q3Object_GetLeafType(original));
        EXPECT_TRUE(c.same(original, objects[0]));
        disposeAll(objects);
    }
    Q3Object_Dispose(original);
}

INSTANTIATE_TEST_SUITE_P(EveryClass, FileStateRoundTripTest, ::testing::Range<std::size_t>(0, 28),
                         [](const ::testing::TestParamInfo<std::size_t>& info) {
                             return stateCases()[info.param].name;
                         });

TEST_F(FileLightGroupTest, LightGroupsRoundTripWithTheirLights)
{
    TQ3GroupObject lights = Q3LightGroup_New();
    TQ3LightData ambient = {kQ3True, 0.3f, {1, 1, 1}};
    TQ3LightObject a = Q3AmbientLight_New(&ambient);
    Q3Group_AddObject(lights, a);
    Q3Group_AddObject(lights, a); // twice: written once, referred to
    for (TQ3FileMode mode : {TQ3FileMode(kQ3FileModeNormal), TQ3FileMode(kQ3FileModeText)}) {
        const auto objects = readAll(writeObjects({lights}, mode));
        ASSERT_EQ(objects.size(), 1u);
        EXPECT_EQ(Q3Object_GetLeafType(objects[0]), kQ3GroupTypeLight);
        unsigned long n = 0;
        Q3Group_CountObjectsOfType(objects[0], kQ3LightTypeAmbient, &n);
        EXPECT_EQ(n, 2u);
        disposeAll(objects);
    }
    Q3Object_Dispose(a);
    Q3Object_Dispose(lights);
}
