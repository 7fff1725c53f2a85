// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Renderer objects and the interactive renderer's recorded settings.

#include "Q3ApiTest.h"

#include "QD3DRenderer.h"
#include "QD3DSet.h"

#include <climits>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace {

using q3test::Q3ApiTest;
using RendererApiTest = Q3ApiTest;

TEST_F(RendererApiTest, NewFromTypeMakesTheTwoRenderersQ3Provides)
{
    for (TQ3ObjectType type : {kQ3RendererTypeWireFrame, kQ3RendererTypeInteractive}) {
        TQ3RendererObject renderer = Q3Renderer_NewFromType(type);
        ASSERT_NE(renderer, nullptr);
        EXPECT_EQ(Q3Renderer_GetType(renderer), type);
        EXPECT_EQ(Q3Object_GetLeafType(renderer), type);
        EXPECT_EQ(Q3Shared_GetType(renderer), kQ3SharedTypeRenderer);
        EXPECT_EQ(Q3Object_IsDrawable(renderer), kQ3False);
        Q3Object_Dispose(renderer);
    }
}

TEST_F(RendererApiTest, NewFromTypeRejectsOtherTypes)
{
    for (TQ3ObjectType type : {kQ3RendererTypeGeneric, kQ3SharedTypeRenderer, kQ3ObjectTypeInvalid,
                               kQ3GeometryTypeNURBCurve, TQ3ObjectType(-1)}) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Renderer_NewFromType(type), nullptr), kQ3ErrorInvalidObjectType);
    }
}

TEST_F(RendererApiTest, GetTypeRejectsBadHandles)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    TQ3RendererObject dead = Q3Renderer_NewFromType(kQ3RendererTypeWireFrame);
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Renderer_GetType(nullptr), kQ3ObjectTypeInvalid), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Renderer_GetType(dead), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3Renderer_GetType(set), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(set);
}

TEST_F(RendererApiTest, InteractiveSettingsStartAtTheirDefaults)
{
    TQ3RendererObject renderer = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
    TQ3CSGEquation equation = kQ3CSGEquationAandnotB;
    EXPECT_EQ(Q3InteractiveRenderer_GetCSGEquation(renderer, &equation), kQ3Success);
    EXPECT_EQ(equation, kQ3CSGEquationAandB);
    long vendor = 7, engine = 7;
    EXPECT_EQ(Q3InteractiveRenderer_GetPreferences(renderer, &vendor, &engine), kQ3Success);
    EXPECT_EQ(vendor, -1);
    EXPECT_EQ(engine, 0);
    TQ3Boolean bypass = kQ3True;
    EXPECT_EQ(Q3InteractiveRenderer_GetDoubleBufferBypass(renderer, &bypass), kQ3Success);
    EXPECT_EQ(bypass, kQ3False);
    unsigned long hints = 7, filter = 7;
    EXPECT_EQ(Q3InteractiveRenderer_GetRAVEContextHints(renderer, &hints), kQ3Success);
    EXPECT_EQ(hints, 0u);
    EXPECT_EQ(Q3InteractiveRenderer_GetRAVETextureFilter(renderer, &filter), kQ3Success);
    EXPECT_EQ(filter, 0u);
    Q3Object_Dispose(renderer);
}

TEST_F(RendererApiTest, InteractiveSettingsAreStoredAndReturned)
{
    TQ3RendererObject renderer = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
    const unsigned long edit = Q3Shared_GetEditIndex(renderer);
    EXPECT_EQ(Q3InteractiveRenderer_SetCSGEquation(renderer, TQ3CSGEquation(0x12345678)), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(renderer), edit);
    TQ3CSGEquation equation{};
    Q3InteractiveRenderer_GetCSGEquation(renderer, &equation);
    EXPECT_EQ(equation, TQ3CSGEquation(0x12345678));
    EXPECT_EQ(Q3InteractiveRenderer_SetCSGEquation(renderer, kQ3CSGEquationnAaBorCanB), kQ3Success);
    Q3InteractiveRenderer_GetCSGEquation(renderer, &equation);
    EXPECT_EQ(equation, kQ3CSGEquationnAaBorCanB);

    EXPECT_EQ(Q3InteractiveRenderer_SetPreferences(renderer, LONG_MIN, LONG_MAX), kQ3Success);
    long vendor = 0, engine = 0;
    Q3InteractiveRenderer_GetPreferences(renderer, &vendor, &engine);
    EXPECT_EQ(vendor, LONG_MIN);
    EXPECT_EQ(engine, LONG_MAX);

    EXPECT_EQ(Q3InteractiveRenderer_SetDoubleBufferBypass(renderer, TQ3Boolean(42)), kQ3Success);
    TQ3Boolean bypass = kQ3False;
    Q3InteractiveRenderer_GetDoubleBufferBypass(renderer, &bypass);
    EXPECT_EQ(bypass, kQ3True);
    EXPECT_EQ(Q3InteractiveRenderer_SetDoubleBufferBypass(renderer, kQ3False), kQ3Success);
    Q3InteractiveRenderer_GetDoubleBufferBypass(renderer, &bypass);
    EXPECT_EQ(bypass, kQ3False);

    EXPECT_EQ(Q3InteractiveRenderer_SetRAVEContextHints(renderer, ULONG_MAX), kQ3Success);
    unsigned long hints = 0;
    Q3InteractiveRenderer_GetRAVEContextHints(renderer, &hints);
    EXPECT_EQ(hints, ULONG_MAX);
    EXPECT_EQ(Q3InteractiveRenderer_SetRAVETextureFilter(renderer, 2), kQ3Success);
    unsigned long filter = 0;
    Q3InteractiveRenderer_GetRAVETextureFilter(renderer, &filter);
    EXPECT_EQ(filter, 2u);

    // A duplicate carries the settings.
    TQ3RendererObject copy = Q3Object_Duplicate(renderer);
    ASSERT_NE(copy, nullptr);
    Q3InteractiveRenderer_GetRAVETextureFilter(copy, &filter);
    EXPECT_EQ(filter, 2u);
    Q3Object_Dispose(copy);
    Q3Object_Dispose(renderer);
}

TEST_F(RendererApiTest, InteractiveCallsRejectOtherObjectsAndNullPointers)
{
    TQ3RendererObject interactive = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
    TQ3RendererObject wireFrame = Q3Renderer_NewFromType(kQ3RendererTypeWireFrame);
    TQ3AttributeSet set = Q3AttributeSet_New();
    TQ3RendererObject dead = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
    Q3Object_Dispose(dead);
    TQ3CSGEquation equation;
    long vendor, engine;
    TQ3Boolean bypass;
    unsigned long value;
    // Each call with the pointer or (for setters) nothing to check.
    const std::vector<std::function<TQ3Status(TQ3RendererObject, bool)>> calls = {
        [&](TQ3RendererObject r, bool) { return Q3InteractiveRenderer_SetCSGEquation(r, kQ3CSGEquationAandB); },
        [&](TQ3RendererObject r, bool p) { return Q3InteractiveRenderer_GetCSGEquation(r, p ? &equation : nullptr); },
        [&](TQ3RendererObject r, bool) { return Q3InteractiveRenderer_SetPreferences(r, 1, 2); },
        [&](TQ3RendererObject r, bool p) {
            return Q3InteractiveRenderer_GetPreferences(r, p ? &vendor : nullptr, &engine);
        },
        [&](TQ3RendererObject r, bool p) {
            return Q3InteractiveRenderer_GetPreferences(r, &vendor, p ? &engine : nullptr);
        },
        [&](TQ3RendererObject r, bool) { return Q3InteractiveRenderer_SetDoubleBufferBypass(r, kQ3True); },
        [&](TQ3RendererObject r, bool p) {
            return Q3InteractiveRenderer_GetDoubleBufferBypass(r, p ? &bypass : nullptr);
        },
        [&](TQ3RendererObject r, bool) { return Q3InteractiveRenderer_SetRAVEContextHints(r, 1); },
        [&](TQ3RendererObject r, bool p) {
            return Q3InteractiveRenderer_GetRAVEContextHints(r, p ? &value : nullptr);
        },
        [&](TQ3RendererObject r, bool) { return Q3InteractiveRenderer_SetRAVETextureFilter(r, 1); },
        [&](TQ3RendererObject r, bool p) {
            return Q3InteractiveRenderer_GetRAVETextureFilter(r, p ? &value : nullptr);
        },
    };
    const bool hasPointer[] = {false, true, false, true, true, false, true, false, true, false, true};
    for (std::size_t i = 0; i < calls.size(); ++i) {
        SCOPED_TRACE("call " + std::to_string(i));
        EXPECT_Q3_ERROR(EXPECT_EQ(calls[i](nullptr, true), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(calls[i](dead, true), kQ3ErrorInvalidObject);
        EXPECT_Q3_ERROR(calls[i](wireFrame, true), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(calls[i](set, true), kQ3ErrorInvalidObjectType);
        if (hasPointer[i])
            EXPECT_Q3_ERROR(calls[i](interactive, false), kQ3ErrorNULLParameter);
        EXPECT_EQ(calls[i](interactive, true), kQ3Success);
    }
    for (TQ3Object object : {interactive, wireFrame, set})
        Q3Object_Dispose(object);
}

TEST_F(RendererApiTest, BothRenderersAreInteractive)
{
    for (TQ3ObjectType type : {kQ3RendererTypeInteractive, kQ3RendererTypeWireFrame}) {
        TQ3RendererObject renderer = Q3Renderer_NewFromType(type);
        EXPECT_EQ(Q3Renderer_IsInteractive(renderer), kQ3True);
        Q3Object_Dispose(renderer);
    }
    TQ3AttributeSet set = Q3AttributeSet_New();
    TQ3RendererObject dead = Q3Renderer_NewFromType(kQ3RendererTypeWireFrame);
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Renderer_IsInteractive(nullptr), kQ3False), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Renderer_IsInteractive(dead), kQ3False), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Renderer_IsInteractive(set), kQ3False), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(set);
}

TEST_F(RendererApiTest, NickNamesAreGivenForTheRenderersQ3Provides)
{
    TQ3ObjectClassNameString name = "";
    ASSERT_EQ(Q3RendererClass_GetNickNameString(kQ3RendererTypeInteractive, name), kQ3Success);
    EXPECT_STREQ(name, "Interactive");
    ASSERT_EQ(Q3RendererClass_GetNickNameString(kQ3RendererTypeWireFrame, name), kQ3Success);
    EXPECT_STREQ(name, "Wireframe");
    for (TQ3ObjectType other : {TQ3ObjectType(kQ3SharedTypeRenderer), TQ3ObjectType(kQ3RendererTypeGeneric),
                                TQ3ObjectType(kQ3GeometryTypeBox), TQ3ObjectType(0), TQ3ObjectType(-1)}) {
        std::strcpy(name, "left");
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3RendererClass_GetNickNameString(other, name), kQ3Failure),
                        kQ3ErrorInvalidParameter);
        EXPECT_STREQ(name, "left");
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3RendererClass_GetNickNameString(kQ3RendererTypeInteractive, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
}

TEST_F(RendererApiTest, ThereAreNoRAVEDrawContexts)
{
    TQ3RendererObject interactive = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
    unsigned long count = 99;
    ASSERT_EQ(Q3InteractiveRenderer_CountRAVEDrawContexts(interactive, &count), kQ3Success);
    EXPECT_EQ(count, 0u);
    TQADrawContext* contexts[2] = {nullptr, nullptr};
    TQAEngine* engines[2] = {nullptr, nullptr};
    count = 2;
    ASSERT_EQ(Q3InteractiveRenderer_GetRAVEDrawContexts(interactive, contexts, engines, &count, nullptr), kQ3Success);
    EXPECT_EQ(count, 0u);
    EXPECT_EQ(contexts[0], nullptr);
    EXPECT_EQ(engines[0], nullptr);
    count = 2;
    ASSERT_EQ(Q3InteractiveRenderer_GetRAVEDrawContexts(interactive, nullptr, nullptr, &count, nullptr), kQ3Success);
    EXPECT_EQ(count, 0u);

    TQ3RendererObject wireFrame = Q3Renderer_NewFromType(kQ3RendererTypeWireFrame);
    TQ3RendererObject dead = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
    Q3Object_Dispose(dead);
    count = 7;
    const struct {
        TQ3RendererObject renderer;
        TQ3Error code;
    } bad[] = {{nullptr, kQ3ErrorNULLParameter}, {dead, kQ3ErrorInvalidObject}, {wireFrame, kQ3ErrorInvalidObjectType}};
    for (const auto& b : bad) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3InteractiveRenderer_CountRAVEDrawContexts(b.renderer, &count), kQ3Failure), b.code);
        EXPECT_Q3_ERROR(
            EXPECT_EQ(Q3InteractiveRenderer_GetRAVEDrawContexts(b.renderer, contexts, engines, &count, nullptr),
                      kQ3Failure),
            b.code);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3InteractiveRenderer_CountRAVEDrawContexts(interactive, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(
        EXPECT_EQ(Q3InteractiveRenderer_GetRAVEDrawContexts(interactive, contexts, engines, nullptr, nullptr),
                  kQ3Failure),
        kQ3ErrorNULLParameter);
    EXPECT_EQ(count, 7u);
    Q3Object_Dispose(interactive);
    Q3Object_Dispose(wireFrame);
}

} // namespace
