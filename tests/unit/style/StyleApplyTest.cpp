// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// What each style and shader puts into a DrawState (apply), checked on a
// state of its own: every style changes its own field and nothing else, and
// the checks of the value rules run in the core too.

#include "core/AttributeSet.h"
#include "core/Error.h"
#include "shader/IlluminationShaders.h"
#include "style/HighlightStyle.h"
#include "style/SubdivisionStyle.h"
#include "style/ValueStyles.h"

#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <string>

namespace q3 {
namespace {

bool sameAntiAlias(const TQ3AntiAliasStyleData& a, const TQ3AntiAliasStyleData& b)
{
    return a.state == b.state && a.mode == b.mode && a.quality == b.quality; // it has padding
}

// The fields as bytes, except `highlight` (a reference) compared by pointer
// and the anti-alias data field by field.
bool sameState(const DrawState& a, const DrawState& b, const char* except = "")
{
    auto same = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof x) == 0; };
    const std::string skip = except;
    return (skip == "subdivision" || same(a.subdivision, b.subdivision)) &&
           (skip == "backfacing" || same(a.backfacing, b.backfacing)) &&
           (skip == "interpolation" || same(a.interpolation, b.interpolation)) &&
           (skip == "fill" || same(a.fill, b.fill)) && (skip == "orientation" || same(a.orientation, b.orientation)) &&
           (skip == "highlight" || a.highlight.get() == b.highlight.get()) &&
           (skip == "antiAlias" || sameAntiAlias(a.antiAlias, b.antiAlias)) && (skip == "fog" || same(a.fog, b.fog)) &&
           (skip == "receiveShadows" || same(a.receiveShadows, b.receiveShadows)) &&
           (skip == "castShadows" || same(a.castShadows, b.castShadows)) &&
           (skip == "pickID" || same(a.pickID, b.pickID)) && (skip == "pickParts" || same(a.pickParts, b.pickParts)) &&
           (skip == "illumination" || same(a.illumination, b.illumination));
}

// Applies `style` to a default state and checks that only `field` changed.
DrawState applied(const Style& style, const char* field)
{
    const DrawState before;
    DrawState state;
    style.apply(state);
    EXPECT_TRUE(sameState(state, before, field)) << "applying changed more than " << field;
    return state;
}

TEST(StyleApply, EachValueStyleSetsItsOwnField)
{
    EXPECT_EQ(applied(PickIDStyle(77), "pickID").pickID, 77ul);
    EXPECT_EQ(applied(PickPartsStyle(kQ3PickPartsMaskEdge | kQ3PickPartsMaskVertex), "pickParts").pickParts, 6ul);
    EXPECT_EQ(applied(CastShadowsStyle(kQ3False), "castShadows").castShadows, kQ3False);
    EXPECT_EQ(applied(ReceiveShadowsStyle(kQ3False), "receiveShadows").receiveShadows, kQ3False);
    EXPECT_EQ(applied(FillStyle(kQ3FillStylePoints), "fill").fill, kQ3FillStylePoints);
    EXPECT_EQ(applied(BackfacingStyle(kQ3BackfacingStyleFlip), "backfacing").backfacing, kQ3BackfacingStyleFlip);
    EXPECT_EQ(applied(InterpolationStyle(kQ3InterpolationStylePixel), "interpolation").interpolation,
              kQ3InterpolationStylePixel);
    EXPECT_EQ(applied(OrientationStyle(kQ3OrientationStyleClockwise), "orientation").orientation,
              kQ3OrientationStyleClockwise);
    const TQ3AntiAliasStyleData antiAlias{kQ3On, kQ3AntiAliasModeMaskFilled, 0.5f};
    const DrawState aa = applied(AntiAliasStyle(antiAlias), "antiAlias");
    EXPECT_TRUE(sameAntiAlias(aa.antiAlias, antiAlias));
    const TQ3FogStyleData fog{kQ3On, kQ3FogModeExponential, 0, 0, 2.0f, {1, 0.5f, 0.5f, 0.5f}};
    const DrawState fogged = applied(FogStyle(fog), "fog");
    EXPECT_EQ(std::memcmp(&fogged.fog, &fog, sizeof fog), 0);
    const TQ3SubdivisionStyleData subdivision{kQ3SubdivisionMethodConstant, 7, 9};
    EXPECT_EQ(applied(SubdivisionStyle(subdivision), "subdivision").subdivision.c2, 9.0f);
}

TEST(StyleApply, TheLastStyleAppliedWins)
{
    DrawState state;
    FillStyle(kQ3FillStyleEdges).apply(state);
    FillStyle(kQ3FillStylePoints).apply(state);
    EXPECT_EQ(state.fill, kQ3FillStylePoints);
}

TEST(StyleApply, BooleanStylesStoreNonzeroAsTrue)
{
    TQ3Boolean raw;
    const int two = 2;
    std::memcpy(&raw, &two, sizeof raw);
    EXPECT_EQ(CastShadowsStyle(raw).value(), kQ3True);
    EXPECT_EQ(ReceiveShadowsStyle(raw).value(), kQ3True);
}

TEST(StyleApply, TheCoreRejectsWhatTheRulesReject)
{
    auto rejects = [](const std::function<void()>& make) {
        try {
            make();
        } catch (const Error& error) {
            return error.code() == kQ3ErrorInvalidParameter;
        }
        return false;
    };
    TQ3FillStyle badFill;
    const int three = 3;
    std::memcpy(&badFill, &three, sizeof badFill);
    EXPECT_TRUE(rejects([&] { FillStyle style(badFill); }));
    EXPECT_TRUE(rejects([] { PickPartsStyle style(8); }));
    EXPECT_TRUE(rejects([] { AntiAliasStyle style(TQ3AntiAliasStyleData{kQ3On, 4, 0.5f}); }));
    EXPECT_TRUE(rejects([] {
        FogStyle style(TQ3FogStyleData{kQ3On, kQ3FogModeLinear, 5, 5, 1, {1, 1, 1, 1}});
    }));
    FillStyle style(kQ3FillStyleEdges);
    EXPECT_TRUE(rejects([&] { style.setValue(badFill); }));
    EXPECT_EQ(style.value(), kQ3FillStyleEdges);
}

TEST(StyleApply, HighlightStyleSetsTheStateSetOrClearsIt)
{
    Ref<AttributeSet> set = makeShared<AttributeSet>();
    const DrawState state = applied(HighlightStyle(set), "highlight");
    EXPECT_EQ(state.highlight.get(), set.get());
    EXPECT_EQ(set->referenceCount(), 2u); // the state's copy holds one
    DrawState cleared = state;
    HighlightStyle(nullptr).apply(cleared);
    EXPECT_EQ(cleared.highlight.get(), nullptr);
}

TEST(ShaderApply, EachIlluminationShaderSetsTheIlluminationAndNothingElse)
{
    const DrawState before;
    EXPECT_EQ(before.illumination, 0u); // unlit until one is submitted
    const std::pair<const IlluminationShader*, TQ3ObjectType> shaders[] = {
        {new PhongIllumination, kQ3IlluminationTypePhong},
        {new LambertIllumination, kQ3IlluminationTypeLambert},
        {new NULLIllumination, kQ3IlluminationTypeNULL},
    };
    for (const auto& [shader, type] : shaders) {
        DrawState state;
        shader->apply(state);
        EXPECT_EQ(state.illumination, type);
        EXPECT_TRUE(sameState(state, before, "illumination"));
        delete shader;
    }
}

} // namespace
} // namespace q3
