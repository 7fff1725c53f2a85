// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The styles of QD3DStyle.h other than subdivision (SubdivisionStyleApiTest):
// Q3Style_GetType and Q3Style_Submit, the eight styles whose data is one
// value (driven from one table), the highlight style, and the anti-alias
// and fog styles with their data rules.

#include "DiffuseColor.h"
#include "OwningApiTest.h"
#include "RenderTestSupport.h"
#include "ShapeTypeChain.h"

#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStyle.h"

#include <climits>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace {

using q3test::expectShapeTypeChain;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
const float kNonFinite[] = {kNaN, kInf, -kInf};

// The eight value styles, each seen through an unsigned long (the widest of
// their C types): an enumeration travels as its int, passed on as C passes
// it (an int converted to the enum type, whatever its value).
struct ValueStyleApi {
    const char* name;
    TQ3ObjectType type;
    std::function<TQ3StyleObject(unsigned long)> create;
    std::function<TQ3Status(unsigned long, TQ3ViewObject)> submit;
    /// Reads into *out; with out NULL passes NULL. A failed read leaves *out.
    std::function<TQ3Status(TQ3StyleObject, unsigned long*)> get;
    std::function<TQ3Status(TQ3StyleObject, unsigned long)> set;
    std::vector<unsigned long> valid;                           // read back as given
    std::vector<std::pair<unsigned long, unsigned long>> taken; // given, read back (Booleans)
    std::vector<unsigned long> invalid;                         // kQ3ErrorInvalidParameter
};

constexpr unsigned long asInt(int value)
{
    return static_cast<unsigned long>(static_cast<long>(value));
}

#define Q3TEST_ENUM_STYLE(Prefix, CType, Type)                                                                    \
    #Prefix, Type, [](unsigned long v) { return Q3##Prefix##_New(static_cast<CType>(static_cast<int>(v))); },     \
        [](unsigned long v, TQ3ViewObject view) {                                                                 \
            return Q3##Prefix##_Submit(static_cast<CType>(static_cast<int>(v)), view);                           \
        },                                                                                                        \
        [](TQ3StyleObject s, unsigned long* out) {                                                                \
            CType v = static_cast<CType>(out != nullptr ? static_cast<int>(*out) : 0);                           \
            const TQ3Status status = Q3##Prefix##_Get(s, out != nullptr ? &v : nullptr);                          \
            if (out != nullptr)                                                                                   \
                *out = asInt(static_cast<int>(v));                                                                \
            return status;                                                                                        \
        },                                                                                                        \
        [](TQ3StyleObject s, unsigned long v) { return Q3##Prefix##_Set(s, static_cast<CType>(static_cast<int>(v))); }

#define Q3TEST_WORD_STYLE(Prefix, Type)                                                                           \
    #Prefix, Type, [](unsigned long v) { return Q3##Prefix##_New(v); },                                           \
        [](unsigned long v, TQ3ViewObject view) { return Q3##Prefix##_Submit(v, view); },                         \
        [](TQ3StyleObject s, unsigned long* out) { return Q3##Prefix##_Get(s, out); },                           \
        [](TQ3StyleObject s, unsigned long v) { return Q3##Prefix##_Set(s, v); }

// Values outside a 0..last enumeration: one past, -1, large, the int limits.
std::vector<unsigned long> outside(int last)
{
    return {asInt(last + 1), asInt(-1), asInt(1000000), asInt(INT_MAX), asInt(INT_MIN)};
}

const std::vector<ValueStyleApi>& valueStyles()
{
    static const std::vector<ValueStyleApi> styles = {
        {Q3TEST_WORD_STYLE(PickIDStyle, kQ3StyleTypePickID), {0, 1, 12345, ULONG_MAX}, {}, {}},
        {Q3TEST_WORD_STYLE(PickPartsStyle, kQ3StyleTypePickParts),
         {kQ3PickPartsObject, kQ3PickPartsMaskFace, kQ3PickPartsMaskEdge, kQ3PickPartsMaskVertex, 3, 5, 6, 7},
         {},
         {8, 9, 1ul << 20, ULONG_MAX}},
        {Q3TEST_ENUM_STYLE(CastShadowsStyle, TQ3Boolean, kQ3StyleTypeCastShadows),
         {kQ3False, kQ3True},
         {{2, kQ3True}, {asInt(-1), kQ3True}, {asInt(INT_MAX), kQ3True}},
         {}},
        {Q3TEST_ENUM_STYLE(ReceiveShadowsStyle, TQ3Boolean, kQ3StyleTypeReceiveShadows),
         {kQ3False, kQ3True},
         {{2, kQ3True}, {asInt(-1), kQ3True}, {asInt(INT_MIN), kQ3True}},
         {}},
        {Q3TEST_ENUM_STYLE(FillStyle, TQ3FillStyle, kQ3StyleTypeFill),
         {kQ3FillStyleFilled, kQ3FillStyleEdges, kQ3FillStylePoints},
         {},
         outside(kQ3FillStylePoints)},
        {Q3TEST_ENUM_STYLE(BackfacingStyle, TQ3BackfacingStyle, kQ3StyleTypeBackfacing),
         {kQ3BackfacingStyleBoth, kQ3BackfacingStyleRemove, kQ3BackfacingStyleFlip},
         {},
         outside(kQ3BackfacingStyleFlip)},
        {Q3TEST_ENUM_STYLE(InterpolationStyle, TQ3InterpolationStyle, kQ3StyleTypeInterpolation),
         {kQ3InterpolationStyleNone, kQ3InterpolationStyleVertex, kQ3InterpolationStylePixel},
         {},
         outside(kQ3InterpolationStylePixel)},
        {Q3TEST_ENUM_STYLE(OrientationStyle, TQ3OrientationStyle, kQ3StyleTypeOrientation),
         {kQ3OrientationStyleCounterClockwise, kQ3OrientationStyleClockwise},
         {},
         outside(kQ3OrientationStyleClockwise)},
    };
    return styles;
}

TQ3AntiAliasStyleData goodAntiAlias()
{
    return TQ3AntiAliasStyleData{kQ3On, kQ3AntiAliasModeMaskEdges | kQ3AntiAliasModeMaskFilled, 0.5f};
}

TQ3FogStyleData goodFog()
{
    return TQ3FogStyleData{kQ3On, kQ3FogModeLinear, 2.0f, 20.0f, 0.25f, {1.0f, 0.5f, 0.25f, 0.125f}};
}

// What a C caller can store in an enum field: any int (copied in as bytes,
// since C++ cannot form such an enum value without undefined behaviour).
template <class E>
void storeInt(E& field, int value)
{
    static_assert(sizeof field == sizeof value, "Q3's enums are int-sized");
    std::memcpy(&field, &value, sizeof value);
}

template <class T>
bool sameBytes(const T& a, const T& b)
{
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// TQ3AntiAliasStyleData has padding around its unsigned long, so it is
// compared field by field (the floats by their bits).
bool sameAntiAlias(const TQ3AntiAliasStyleData& a, const TQ3AntiAliasStyleData& b)
{
    return sameBytes(a.state, b.state) && a.mode == b.mode && sameBytes(a.quality, b.quality);
}

class StyleApiTest : public q3test::OwningApiTest {
protected:
    /// The type chain every style has, and that it is drawable.
    void expectStyleOfType(TQ3StyleObject style, TQ3ObjectType type, const std::string& what)
    {
        ASSERT_NE(style, nullptr) << what;
        expectShapeTypeChain(style, kQ3ShapeTypeStyle, type, kQ3True, what);
        EXPECT_EQ(Q3Style_GetType(style), type) << what;
    }

    unsigned long valueOf(const ValueStyleApi& api, TQ3StyleObject style)
    {
        unsigned long value = 0;
        EXPECT_EQ(api.get(style, &value), kQ3Success) << api.name;
        return value;
    }

    /// A style of another class than api's, to pass where api's is expected.
    TQ3StyleObject otherStyle(const ValueStyleApi& api)
    {
        return own(api.type == kQ3StyleTypeFill ? Q3BackfacingStyle_New(kQ3BackfacingStyleBoth)
                                                : Q3FillStyle_New(kQ3FillStyleFilled));
    }

    /// A handle disposed already. Take it after creating the objects a
    /// check needs: a new object may reuse its address.
    TQ3Object disposedStyle()
    {
        TQ3StyleObject style = Q3FillStyle_New(kQ3FillStyleEdges);
        Q3Object_Dispose(style);
        return style;
    }

    /// Runs `scene` in one rendering loop of a small interactive view.
    void inRenderingLoop(const std::function<void(TQ3ViewObject)>& scene)
    {
        q3test::Pixmap pixmap(8, 8);
        q3test::TestView view(pixmap.pixmap());
        EXPECT_EQ(view.render(scene), kQ3ViewStatusDone);
    }
};

// ---- Every style ----------------------------------------------------------

TEST_F(StyleApiTest, StyleGetTypeGivesTheLeafTypeOfEveryStyle)
{
    const TQ3SubdivisionStyleData subdivision{kQ3SubdivisionMethodConstant, 4, 4};
    const TQ3AntiAliasStyleData antiAlias = goodAntiAlias();
    const TQ3FogStyleData fog = goodFog();
    expectStyleOfType(own(Q3SubdivisionStyle_New(&subdivision)), kQ3StyleTypeSubdivision, "subdivision");
    expectStyleOfType(own(Q3HighlightStyle_New(nullptr)), kQ3StyleTypeHighlight, "highlight");
    expectStyleOfType(own(Q3AntiAliasStyle_New(&antiAlias)), kQ3StyleTypeAntiAlias, "anti-alias");
    expectStyleOfType(own(Q3FogStyle_New(&fog)), kQ3StyleTypeFog, "fog");
    for (const ValueStyleApi& api : valueStyles())
        expectStyleOfType(own(api.create(api.valid.front())), api.type, api.name);
}

TEST_F(StyleApiTest, StyleGetTypeRejectsBadHandles)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Style_GetType(nullptr), kQ3ObjectTypeInvalid), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Style_GetType(disposedStyle()), kQ3ObjectTypeInvalid), kQ3ErrorInvalidObject);
    TQ3ShaderObject shader = own(Q3PhongIllumination_New());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Style_GetType(shader), kQ3ObjectTypeInvalid), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Style_GetType(view()), kQ3ObjectTypeInvalid), kQ3ErrorInvalidObjectType);
}

TEST_F(StyleApiTest, StyleSubmitWorksInRenderingAndBoundingLoopsOnly)
{
    TQ3StyleObject fill = own(Q3FillStyle_New(kQ3FillStyleEdges));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Style_Submit(fill, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    boundsOf([&](TQ3ViewObject v) {
        EXPECT_EQ(Q3Style_Submit(fill, v), kQ3Success);
        EXPECT_EQ(Q3Object_Submit(fill, v), kQ3Success);
    });
    inRenderingLoop([&](TQ3ViewObject v) {
        EXPECT_EQ(Q3Style_Submit(fill, v), kQ3Success);
        EXPECT_EQ(Q3Object_Submit(fill, v), kQ3Success);
    });
}

TEST_F(StyleApiTest, StyleSubmitRejectsBadStylesAndViews)
{
    TQ3StyleObject fill = own(Q3FillStyle_New(kQ3FillStyleEdges));
    TQ3ShaderObject shader = own(Q3PhongIllumination_New());
    boundsOf([&](TQ3ViewObject v) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Style_Submit(nullptr, v), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Style_Submit(disposedStyle(), v), kQ3Failure), kQ3ErrorInvalidObject);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Style_Submit(shader, v), kQ3Failure), kQ3ErrorInvalidObjectType);
    });
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Style_Submit(fill, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Style_Submit(fill, fill), kQ3Failure), kQ3ErrorInvalidObjectType);
}

// ---- The value styles -----------------------------------------------------

TEST_F(StyleApiTest, ValueStylesReadBackEveryValidValue)
{
    for (const ValueStyleApi& api : valueStyles())
        for (unsigned long value : api.valid) {
            TQ3StyleObject style = own(api.create(value));
            ASSERT_NE(style, nullptr) << api.name << " " << value;
            EXPECT_EQ(valueOf(api, style), value) << api.name;
        }
}

TEST_F(StyleApiTest, ValueStylesRejectValuesOutsideTheirRuleInNewAndSet)
{
    for (const ValueStyleApi& api : valueStyles()) {
        TQ3StyleObject style = own(api.create(api.valid.back()));
        const unsigned long before = Q3Shared_GetEditIndex(style);
        for (unsigned long value : api.invalid) {
            EXPECT_Q3_ERROR(EXPECT_EQ(api.create(value), nullptr) << api.name << " " << value,
                            kQ3ErrorInvalidParameter);
            EXPECT_STRNE(Q3Error_GetMessage(), "");
            EXPECT_Q3_ERROR(EXPECT_EQ(api.set(style, value), kQ3Failure) << api.name << " " << value,
                            kQ3ErrorInvalidParameter);
        }
        EXPECT_EQ(valueOf(api, style), api.valid.back()) << api.name;
        EXPECT_EQ(Q3Shared_GetEditIndex(style), before) << api.name;
    }
}

TEST_F(StyleApiTest, BooleanStylesStoreAnyNonzeroValueAsTrue)
{
    for (const ValueStyleApi& api : valueStyles())
        for (const auto& [given, stored] : api.taken) {
            TQ3StyleObject style = own(api.create(given));
            ASSERT_NE(style, nullptr) << api.name;
            EXPECT_EQ(valueOf(api, style), stored) << api.name << " " << given;
            ASSERT_EQ(api.set(style, kQ3False), kQ3Success);
            ASSERT_EQ(api.set(style, given), kQ3Success);
            EXPECT_EQ(valueOf(api, style), stored) << api.name << " " << given;
            boundsOf([&](TQ3ViewObject v) { EXPECT_EQ(api.submit(given, v), kQ3Success) << api.name; });
        }
}

TEST_F(StyleApiTest, ValueStyleSetReadsBackAndChangesTheEditIndex)
{
    for (const ValueStyleApi& api : valueStyles()) {
        TQ3StyleObject style = own(api.create(api.valid.front()));
        for (unsigned long value : api.valid) {
            const unsigned long before = Q3Shared_GetEditIndex(style);
            EXPECT_EQ(api.set(style, value), kQ3Success) << api.name;
            EXPECT_EQ(valueOf(api, style), value) << api.name;
            EXPECT_NE(Q3Shared_GetEditIndex(style), before) << api.name;
        }
    }
}

TEST_F(StyleApiTest, ValueStyleDuplicateIsAnIndependentCopy)
{
    for (const ValueStyleApi& api : valueStyles()) {
        TQ3StyleObject style = own(api.create(api.valid.back()));
        TQ3StyleObject copy = own(Q3Object_Duplicate(style));
        ASSERT_NE(copy, nullptr) << api.name;
        EXPECT_NE(copy, style);
        expectStyleOfType(copy, api.type, api.name);
        EXPECT_EQ(valueOf(api, copy), api.valid.back()) << api.name;
        ASSERT_EQ(api.set(copy, api.valid.front()), kQ3Success);
        EXPECT_EQ(valueOf(api, style), api.valid.back()) << api.name;
    }
}

TEST_F(StyleApiTest, ValueStyleGetAndSetRejectBadHandlesAndPointers)
{
    int notAnObject = 0;
    TQ3Object stray = reinterpret_cast<TQ3Object>(&notAnObject);
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    for (const ValueStyleApi& api : valueStyles()) {
        const unsigned long value = api.valid.back();
        TQ3StyleObject wrong = otherStyle(api);
        const std::vector<std::pair<TQ3Object, TQ3Error>> bad = {{nullptr, kQ3ErrorNULLParameter},
                                                                 {disposedStyle(), kQ3ErrorInvalidObject},
                                                                 {stray, kQ3ErrorInvalidObject},
                                                                 {set, kQ3ErrorInvalidObjectType},
                                                                 {wrong, kQ3ErrorInvalidObjectType}};
        for (const auto& [handle, error] : bad) {
            unsigned long out = api.valid.front();
            EXPECT_Q3_ERROR(EXPECT_EQ(api.get(handle, &out), kQ3Failure) << api.name, error);
            EXPECT_EQ(out, api.valid.front()) << api.name;
            EXPECT_Q3_ERROR(EXPECT_EQ(api.set(handle, value), kQ3Failure) << api.name, error);
        }
        // The handle is checked before the value.
        if (!api.invalid.empty())
            EXPECT_Q3_ERROR(api.set(nullptr, api.invalid.front()), kQ3ErrorNULLParameter);
        TQ3StyleObject style = own(api.create(value));
        EXPECT_Q3_ERROR(EXPECT_EQ(api.get(style, nullptr), kQ3Failure) << api.name, kQ3ErrorNULLParameter);
    }
}

TEST_F(StyleApiTest, ValueStyleSubmitOutsideALoopFailsWithViewNotStarted)
{
    for (const ValueStyleApi& api : valueStyles()) {
        EXPECT_Q3_ERROR(EXPECT_EQ(api.submit(api.valid.back(), view()), kQ3Failure) << api.name,
                        kQ3ErrorViewNotStarted);
        // The view's condition comes before the value's rule.
        if (!api.invalid.empty())
            EXPECT_Q3_ERROR(api.submit(api.invalid.front(), view()), kQ3ErrorViewNotStarted);
    }
}

TEST_F(StyleApiTest, ValueStyleSubmitRejectsBadViews)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    for (const ValueStyleApi& api : valueStyles()) {
        EXPECT_Q3_ERROR(EXPECT_EQ(api.submit(api.valid.back(), nullptr), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(api.submit(api.valid.back(), set), kQ3Failure), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(EXPECT_EQ(api.submit(api.valid.back(), disposedStyle()), kQ3Failure),
                        kQ3ErrorInvalidObject);
    }
}

TEST_F(StyleApiTest, ValueStyleSubmitChecksTheValueInsideLoops)
{
    auto scene = [&](TQ3ViewObject v) {
        for (const ValueStyleApi& api : valueStyles()) {
            for (unsigned long value : api.valid)
                EXPECT_EQ(api.submit(value, v), kQ3Success) << api.name << " " << value;
            for (unsigned long value : api.invalid)
                EXPECT_Q3_ERROR(EXPECT_EQ(api.submit(value, v), kQ3Failure) << api.name << " " << value,
                                kQ3ErrorInvalidParameter);
            TQ3StyleObject style = api.create(api.valid.back());
            EXPECT_EQ(Q3Object_Submit(style, v), kQ3Success) << api.name;
            EXPECT_EQ(Q3Style_Submit(style, v), kQ3Success) << api.name;
            Q3Object_Dispose(style);
        }
    };
    boundsOf(scene);
    inRenderingLoop(scene);
}

// ---- Highlight ------------------------------------------------------------

TEST_F(StyleApiTest, HighlightStyleHoldsAReferenceToItsSet)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    TQ3StyleObject style = own(Q3HighlightStyle_New(set));
    ASSERT_NE(style, nullptr);
    EXPECT_EQ(Q3Shared_IsReferenced(set), kQ3True);
    TQ3AttributeSet got = nullptr;
    ASSERT_EQ(Q3HighlightStyle_Get(style, &got), kQ3Success);
    EXPECT_EQ(got, set);
    Q3Object_Dispose(got); // Get handed out a reference of its own
    EXPECT_EQ(Q3Shared_IsReferenced(set), kQ3True);
    // The style keeps the set alive after the caller's reference goes.
    TQ3AttributeSet loose = Q3AttributeSet_New();
    const TQ3ColorRGB red{1, 0, 0};
    ASSERT_EQ(Q3AttributeSet_Add(loose, kQ3AttributeTypeDiffuseColor, &red), kQ3Success);
    TQ3StyleObject holder = own(Q3HighlightStyle_New(loose));
    Q3Object_Dispose(loose);
    ASSERT_EQ(Q3HighlightStyle_Get(holder, &got), kQ3Success);
    EXPECT_EQ(q3test::expectDiffuseColor(got).r, 1.0f);
    Q3Object_Dispose(got);
}

TEST_F(StyleApiTest, HighlightStyleAcceptsNoSet)
{
    TQ3StyleObject style = own(Q3HighlightStyle_New(nullptr));
    ASSERT_NE(style, nullptr);
    TQ3AttributeSet got = reinterpret_cast<TQ3AttributeSet>(&got);
    ASSERT_EQ(Q3HighlightStyle_Get(style, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    ASSERT_EQ(Q3HighlightStyle_Set(style, set), kQ3Success);
    const unsigned long before = Q3Shared_GetEditIndex(style);
    ASSERT_EQ(Q3HighlightStyle_Set(style, nullptr), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(style), before);
    EXPECT_EQ(Q3Shared_IsReferenced(set), kQ3False); // the style let go of it
    ASSERT_EQ(Q3HighlightStyle_Get(style, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
}

TEST_F(StyleApiTest, HighlightStyleSetReplacesTheSetAndChangesTheEditIndex)
{
    TQ3AttributeSet first = own(Q3AttributeSet_New());
    TQ3AttributeSet second = own(Q3AttributeSet_New());
    TQ3StyleObject style = own(Q3HighlightStyle_New(first));
    const unsigned long before = Q3Shared_GetEditIndex(style);
    ASSERT_EQ(Q3HighlightStyle_Set(style, second), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(style), before);
    EXPECT_EQ(Q3Shared_IsReferenced(first), kQ3False);
    EXPECT_EQ(Q3Shared_IsReferenced(second), kQ3True);
    TQ3AttributeSet got = nullptr;
    ASSERT_EQ(Q3HighlightStyle_Get(style, &got), kQ3Success);
    EXPECT_EQ(got, second);
    Q3Object_Dispose(got);
}

TEST_F(StyleApiTest, HighlightStyleRejectsBadHandlesAndChangesNothing)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    TQ3StyleObject style = own(Q3HighlightStyle_New(set));
    TQ3StyleObject fill = own(Q3FillStyle_New(kQ3FillStyleFilled));
    ASSERT_NE(view(), nullptr); // created before any handle is disposed
    int notAnObject = 0;
    TQ3Object stray = reinterpret_cast<TQ3Object>(&notAnObject);
    const unsigned long before = Q3Shared_GetEditIndex(style);
    // Bad sets: New, Set and Submit.
    for (const auto& [handle, error] : std::vector<std::pair<TQ3Object, TQ3Error>>{
             {disposedStyle(), kQ3ErrorInvalidObject},
             {stray, kQ3ErrorInvalidObject},
             {fill, kQ3ErrorInvalidObjectType}}) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3HighlightStyle_New(handle), nullptr), error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3HighlightStyle_Set(style, handle), kQ3Failure), error);
        boundsOf([&](TQ3ViewObject v) {
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3HighlightStyle_Submit(handle, v), kQ3Failure), error);
        });
    }
    EXPECT_EQ(Q3Shared_GetEditIndex(style), before);
    // Bad styles: Get and Set.
    for (const auto& [handle, error] : std::vector<std::pair<TQ3Object, TQ3Error>>{
             {nullptr, kQ3ErrorNULLParameter},
             {disposedStyle(), kQ3ErrorInvalidObject},
             {fill, kQ3ErrorInvalidObjectType},
             {set, kQ3ErrorInvalidObjectType}}) {
        TQ3AttributeSet got = set;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3HighlightStyle_Get(handle, &got), kQ3Failure), error);
        EXPECT_EQ(got, set);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3HighlightStyle_Set(handle, set), kQ3Failure), error);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3HighlightStyle_Get(style, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    TQ3AttributeSet got = nullptr;
    ASSERT_EQ(Q3HighlightStyle_Get(style, &got), kQ3Success);
    EXPECT_EQ(got, set);
    Q3Object_Dispose(got);
}

TEST_F(StyleApiTest, HighlightStyleDuplicateCopiesTheSet)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    const TQ3ColorRGB green{0, 1, 0};
    ASSERT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &green), kQ3Success);
    TQ3StyleObject style = own(Q3HighlightStyle_New(set));
    TQ3StyleObject copy = own(Q3Object_Duplicate(style));
    expectStyleOfType(copy, kQ3StyleTypeHighlight, "copy");
    TQ3AttributeSet copied = nullptr;
    ASSERT_EQ(Q3HighlightStyle_Get(copy, &copied), kQ3Success);
    ASSERT_NE(copied, nullptr);
    EXPECT_NE(copied, set);
    EXPECT_EQ(q3test::expectDiffuseColor(copied).g, 1.0f);
    Q3Object_Dispose(copied);
    TQ3StyleObject empty = own(Q3HighlightStyle_New(nullptr));
    TQ3StyleObject emptyCopy = own(Q3Object_Duplicate(empty));
    ASSERT_EQ(Q3HighlightStyle_Get(emptyCopy, &copied), kQ3Success);
    EXPECT_EQ(copied, nullptr);
}

TEST_F(StyleApiTest, HighlightStyleSubmitWorksInLoopsOnly)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3HighlightStyle_Submit(set, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3HighlightStyle_Submit(nullptr, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3HighlightStyle_Submit(set, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3HighlightStyle_Submit(set, set), kQ3Failure), kQ3ErrorInvalidObjectType);
    TQ3StyleObject style = own(Q3HighlightStyle_New(set));
    auto scene = [&](TQ3ViewObject v) {
        EXPECT_EQ(Q3HighlightStyle_Submit(set, v), kQ3Success);
        EXPECT_EQ(Q3HighlightStyle_Submit(nullptr, v), kQ3Success);
        EXPECT_EQ(Q3Style_Submit(style, v), kQ3Success);
    };
    boundsOf(scene);
    inRenderingLoop(scene);
}

// ---- Anti-alias -----------------------------------------------------------

TEST_F(StyleApiTest, AntiAliasStyleStoresValidDataAsGiven)
{
    for (TQ3Switch state : {kQ3Off, kQ3On})
        for (unsigned long mode : {0ul, 1ul, 2ul, 3ul})
            for (float quality : {0.0f, 0.25f, 1.0f}) {
                const TQ3AntiAliasStyleData data{state, mode, quality};
                TQ3StyleObject style = own(Q3AntiAliasStyle_New(&data));
                ASSERT_NE(style, nullptr);
                TQ3AntiAliasStyleData got{};
                ASSERT_EQ(Q3AntiAliasStyle_GetData(style, &got), kQ3Success);
                EXPECT_TRUE(sameAntiAlias(got, data));
            }
}

// Each way to break the anti-alias rules.
std::vector<std::pair<std::string, TQ3AntiAliasStyleData>> badAntiAlias()
{
    std::vector<std::pair<std::string, TQ3AntiAliasStyleData>> cases;
    for (int state : {2, -1, 1000000}) {
        TQ3AntiAliasStyleData d = goodAntiAlias();
        storeInt(d.state, state);
        cases.push_back({"state " + std::to_string(state), d});
    }
    for (unsigned long mode : {4ul, 7ul, 1ul << 31, ULONG_MAX}) {
        TQ3AntiAliasStyleData d = goodAntiAlias();
        d.mode = mode;
        cases.push_back({"mode " + std::to_string(mode), d});
    }
    for (float quality : {kNaN, kInf, -kInf, -0.001f, 1.001f, 2.0f}) {
        TQ3AntiAliasStyleData d = goodAntiAlias();
        d.quality = quality;
        cases.push_back({"quality " + std::to_string(quality), d});
    }
    return cases;
}

TEST_F(StyleApiTest, AntiAliasStyleRejectsBrokenRulesOnEveryPath)
{
    const TQ3AntiAliasStyleData good = goodAntiAlias();
    TQ3StyleObject style = own(Q3AntiAliasStyle_New(&good));
    const unsigned long before = Q3Shared_GetEditIndex(style);
    for (const auto& [what, data] : badAntiAlias()) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AntiAliasStyle_New(&data), nullptr) << what, kQ3ErrorInvalidParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AntiAliasStyle_SetData(style, &data), kQ3Failure) << what,
                        kQ3ErrorInvalidParameter);
        boundsOf([&](TQ3ViewObject v) {
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3AntiAliasStyle_Submit(&data, v), kQ3Failure) << what,
                            kQ3ErrorInvalidParameter);
        });
    }
    TQ3AntiAliasStyleData got{};
    ASSERT_EQ(Q3AntiAliasStyle_GetData(style, &got), kQ3Success);
    EXPECT_TRUE(sameAntiAlias(got, good));
    EXPECT_EQ(Q3Shared_GetEditIndex(style), before);
}

TEST_F(StyleApiTest, AntiAliasStyleSetDataReadsBackAndDuplicates)
{
    const TQ3AntiAliasStyleData good = goodAntiAlias();
    TQ3StyleObject style = own(Q3AntiAliasStyle_New(&good));
    const TQ3AntiAliasStyleData other{kQ3Off, kQ3AntiAliasModeMaskFilled, 1.0f};
    const unsigned long before = Q3Shared_GetEditIndex(style);
    ASSERT_EQ(Q3AntiAliasStyle_SetData(style, &other), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(style), before);
    TQ3AntiAliasStyleData got{};
    ASSERT_EQ(Q3AntiAliasStyle_GetData(style, &got), kQ3Success);
    EXPECT_TRUE(sameAntiAlias(got, other));
    TQ3StyleObject copy = own(Q3Object_Duplicate(style));
    expectStyleOfType(copy, kQ3StyleTypeAntiAlias, "copy");
    ASSERT_EQ(Q3AntiAliasStyle_GetData(copy, &got), kQ3Success);
    EXPECT_TRUE(sameAntiAlias(got, other));
}

TEST_F(StyleApiTest, AntiAliasStyleCallsRejectBadHandlesAndPointers)
{
    const TQ3AntiAliasStyleData good = goodAntiAlias();
    const TQ3FogStyleData fogData = goodFog();
    TQ3StyleObject style = own(Q3AntiAliasStyle_New(&good));
    TQ3StyleObject fog = own(Q3FogStyle_New(&fogData));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AntiAliasStyle_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3AntiAliasStyle_SetData(style, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3AntiAliasStyle_GetData(style, nullptr), kQ3ErrorNULLParameter);
    for (const auto& [handle, error] : std::vector<std::pair<TQ3Object, TQ3Error>>{
             {nullptr, kQ3ErrorNULLParameter},
             {disposedStyle(), kQ3ErrorInvalidObject},
             {fog, kQ3ErrorInvalidObjectType}}) {
        TQ3AntiAliasStyleData got = good;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AntiAliasStyle_GetData(handle, &got), kQ3Failure), error);
        EXPECT_TRUE(sameAntiAlias(got, good));
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AntiAliasStyle_SetData(handle, &good), kQ3Failure), error);
    }
    // The handle before the pointer, the pointer before the data.
    EXPECT_Q3_ERROR(Q3AntiAliasStyle_SetData(nullptr, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3AntiAliasStyle_SetData(fog, nullptr), kQ3ErrorInvalidObjectType);
}

TEST_F(StyleApiTest, AntiAliasStyleSubmitWorksInLoopsOnly)
{
    const TQ3AntiAliasStyleData good = goodAntiAlias();
    TQ3AntiAliasStyleData bad = good;
    bad.quality = kNaN;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AntiAliasStyle_Submit(&good, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(Q3AntiAliasStyle_Submit(&bad, view()), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(Q3AntiAliasStyle_Submit(nullptr, view()), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3AntiAliasStyle_Submit(&good, nullptr), kQ3ErrorNULLParameter);
    auto scene = [&](TQ3ViewObject v) { EXPECT_EQ(Q3AntiAliasStyle_Submit(&good, v), kQ3Success); };
    boundsOf(scene);
    inRenderingLoop(scene);
}

// ---- Fog ------------------------------------------------------------------

TEST_F(StyleApiTest, FogStyleStoresValidDataAsGiven)
{
    std::vector<TQ3FogStyleData> cases;
    for (int mode = kQ3FogModeLinear; mode <= kQ3FogModeAlpha; ++mode)
        for (TQ3Switch state : {kQ3Off, kQ3On}) {
            TQ3FogStyleData d = goodFog();
            d.state = state;
            storeInt(d.mode, mode);
            cases.push_back(d);
        }
    // Fields a fog does not use may be left zero, or reversed.
    TQ3FogStyleData zeroOff{};
    cases.push_back(zeroOff);
    TQ3FogStyleData exponential{kQ3On, kQ3FogModeExponential, 0.0f, 0.0f, 0.0f, {1, 1, 1, 1}};
    cases.push_back(exponential);
    TQ3FogStyleData reversedOff = goodFog();
    reversedOff.state = kQ3Off;
    std::swap(reversedOff.fogStart, reversedOff.fogEnd);
    cases.push_back(reversedOff);
    // Colours are not clamped; negative distances are allowed.
    TQ3FogStyleData odd{kQ3On, kQ3FogModeLinear, -5.0f, -1.0f, 1e30f, {2.0f, -1.0f, 0.0f, 7.0f}};
    cases.push_back(odd);
    for (const TQ3FogStyleData& data : cases) {
        TQ3StyleObject style = own(Q3FogStyle_New(&data));
        ASSERT_NE(style, nullptr);
        TQ3FogStyleData got{};
        ASSERT_EQ(Q3FogStyle_GetData(style, &got), kQ3Success);
        EXPECT_TRUE(sameBytes(got, data));
    }
}

// Each way to break the fog rules.
std::vector<std::pair<std::string, TQ3FogStyleData>> badFog()
{
    std::vector<std::pair<std::string, TQ3FogStyleData>> cases;
    for (int state : {2, -1, 1000000}) {
        TQ3FogStyleData d = goodFog();
        storeInt(d.state, state);
        cases.push_back({"state " + std::to_string(state), d});
    }
    for (int mode : {4, -1, 1000000, INT_MIN}) {
        TQ3FogStyleData d = goodFog();
        storeInt(d.mode, mode);
        cases.push_back({"mode " + std::to_string(mode), d});
    }
    for (float bad : kNonFinite) {
        for (float TQ3FogStyleData::*field : {&TQ3FogStyleData::fogStart, &TQ3FogStyleData::fogEnd,
                                             &TQ3FogStyleData::density}) {
            TQ3FogStyleData d = goodFog();
            d.*field = bad;
            cases.push_back({"a non-finite distance or density", d});
        }
        for (float TQ3ColorARGB::*component : {&TQ3ColorARGB::a, &TQ3ColorARGB::r, &TQ3ColorARGB::g,
                                               &TQ3ColorARGB::b}) {
            TQ3FogStyleData d = goodFog();
            d.color.*component = bad;
            cases.push_back({"a non-finite colour component", d});
        }
    }
    TQ3FogStyleData negative = goodFog();
    negative.density = -0.5f;
    cases.push_back({"negative density", negative});
    TQ3FogStyleData equal = goodFog();
    equal.fogEnd = equal.fogStart;
    cases.push_back({"linear fog with fogStart == fogEnd", equal});
    TQ3FogStyleData reversed = goodFog();
    std::swap(reversed.fogStart, reversed.fogEnd);
    cases.push_back({"linear fog with fogStart > fogEnd", reversed});
    return cases;
}

TEST_F(StyleApiTest, FogStyleRejectsBrokenRulesOnEveryPath)
{
    const TQ3FogStyleData good = goodFog();
    TQ3StyleObject style = own(Q3FogStyle_New(&good));
    const unsigned long before = Q3Shared_GetEditIndex(style);
    for (const auto& [what, data] : badFog()) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3FogStyle_New(&data), nullptr) << what, kQ3ErrorInvalidParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3FogStyle_SetData(style, &data), kQ3Failure) << what, kQ3ErrorInvalidParameter);
        boundsOf([&](TQ3ViewObject v) {
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3FogStyle_Submit(&data, v), kQ3Failure) << what, kQ3ErrorInvalidParameter);
        });
    }
    TQ3FogStyleData got{};
    ASSERT_EQ(Q3FogStyle_GetData(style, &got), kQ3Success);
    EXPECT_TRUE(sameBytes(got, good));
    EXPECT_EQ(Q3Shared_GetEditIndex(style), before);
}

TEST_F(StyleApiTest, FogStyleSetDataReadsBackAndDuplicates)
{
    const TQ3FogStyleData good = goodFog();
    TQ3StyleObject style = own(Q3FogStyle_New(&good));
    const TQ3FogStyleData other{kQ3On, kQ3FogModeExponentialSquared, 0.0f, 0.0f, 3.0f, {1, 0, 0, 1}};
    const unsigned long before = Q3Shared_GetEditIndex(style);
    ASSERT_EQ(Q3FogStyle_SetData(style, &other), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(style), before);
    TQ3FogStyleData got{};
    ASSERT_EQ(Q3FogStyle_GetData(style, &got), kQ3Success);
    EXPECT_TRUE(sameBytes(got, other));
    TQ3StyleObject copy = own(Q3Object_Duplicate(style));
    expectStyleOfType(copy, kQ3StyleTypeFog, "copy");
    ASSERT_EQ(Q3FogStyle_GetData(copy, &got), kQ3Success);
    EXPECT_TRUE(sameBytes(got, other));
}

TEST_F(StyleApiTest, FogStyleCallsRejectBadHandlesAndPointers)
{
    const TQ3FogStyleData good = goodFog();
    const TQ3AntiAliasStyleData antiAlias = goodAntiAlias();
    TQ3StyleObject style = own(Q3FogStyle_New(&good));
    TQ3StyleObject other = own(Q3AntiAliasStyle_New(&antiAlias));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3FogStyle_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3FogStyle_SetData(style, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3FogStyle_GetData(style, nullptr), kQ3ErrorNULLParameter);
    for (const auto& [handle, error] : std::vector<std::pair<TQ3Object, TQ3Error>>{
             {nullptr, kQ3ErrorNULLParameter},
             {disposedStyle(), kQ3ErrorInvalidObject},
             {other, kQ3ErrorInvalidObjectType}}) {
        TQ3FogStyleData got = good;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3FogStyle_GetData(handle, &got), kQ3Failure), error);
        EXPECT_TRUE(sameBytes(got, good));
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3FogStyle_SetData(handle, &good), kQ3Failure), error);
    }
}

TEST_F(StyleApiTest, FogStyleSubmitWorksInLoopsOnly)
{
    const TQ3FogStyleData good = goodFog();
    TQ3FogStyleData bad = good;
    bad.density = -kInf;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3FogStyle_Submit(&good, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(Q3FogStyle_Submit(&bad, view()), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(Q3FogStyle_Submit(nullptr, view()), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3FogStyle_Submit(&good, nullptr), kQ3ErrorNULLParameter);
    auto scene = [&](TQ3ViewObject v) { EXPECT_EQ(Q3FogStyle_Submit(&good, v), kQ3Success); };
    boundsOf(scene);
    inRenderingLoop(scene);
}

// ---- Before Q3Initialize --------------------------------------------------

TEST(StyleApiUninitialized, EveryFunctionFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    auto failed = [] { return Q3Error_Get(nullptr) == kQ3ErrorNotInitialized; };
    const TQ3AntiAliasStyleData antiAlias = goodAntiAlias();
    const TQ3FogStyleData fog = goodFog();
    TQ3AntiAliasStyleData antiAliasOut{};
    TQ3FogStyleData fogOut{};
    TQ3AttributeSet setOut = nullptr;
    EXPECT_EQ(Q3Style_GetType(nullptr), kQ3ObjectTypeInvalid);
    EXPECT_TRUE(failed());
    for (TQ3StyleObject style :
         {Q3HighlightStyle_New(nullptr), Q3AntiAliasStyle_New(&antiAlias), Q3FogStyle_New(&fog)}) {
        EXPECT_EQ(style, nullptr);
        EXPECT_TRUE(failed());
    }
    const std::vector<std::function<TQ3Status()>> calls = {
        [&] { return Q3Style_Submit(nullptr, nullptr); },
        [&] { return Q3HighlightStyle_Submit(nullptr, nullptr); },
        [&] { return Q3HighlightStyle_Get(nullptr, &setOut); },
        [&] { return Q3HighlightStyle_Set(nullptr, nullptr); },
        [&] { return Q3AntiAliasStyle_Submit(&antiAlias, nullptr); },
        [&] { return Q3AntiAliasStyle_GetData(nullptr, &antiAliasOut); },
        [&] { return Q3AntiAliasStyle_SetData(nullptr, &antiAlias); },
        [&] { return Q3FogStyle_Submit(&fog, nullptr); },
        [&] { return Q3FogStyle_GetData(nullptr, &fogOut); },
        [&] { return Q3FogStyle_SetData(nullptr, &fog); },
    };
    for (std::size_t i = 0; i < calls.size(); ++i) {
        EXPECT_EQ(calls[i](), kQ3Failure) << "call " << i;
        EXPECT_TRUE(failed()) << "call " << i;
    }
    for (const ValueStyleApi& api : valueStyles()) {
        unsigned long out = 0;
        EXPECT_EQ(api.create(api.valid.front()), nullptr) << api.name;
        EXPECT_TRUE(failed()) << api.name;
        EXPECT_EQ(api.submit(api.valid.front(), nullptr), kQ3Failure) << api.name;
        EXPECT_TRUE(failed()) << api.name;
        EXPECT_EQ(api.get(nullptr, &out), kQ3Failure) << api.name;
        EXPECT_TRUE(failed()) << api.name;
        EXPECT_EQ(api.set(nullptr, api.valid.front()), kQ3Failure) << api.name;
        EXPECT_TRUE(failed()) << api.name;
    }
}

} // namespace
