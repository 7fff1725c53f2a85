// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// QD3DShader.h: the three illumination shaders, the calls every shader has
// (type, submit, uv transform and boundaries).

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
#include <utility>
#include <vector>

namespace {

using q3test::expectShapeTypeChain;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

struct IlluminationKind {
    const char* name;
    TQ3ShaderObject (*create)();
    TQ3ObjectType type;
};

const IlluminationKind kIlluminations[] = {
    {"Phong", Q3PhongIllumination_New, kQ3IlluminationTypePhong},
    {"Lambert", Q3LambertIllumination_New, kQ3IlluminationTypeLambert},
    {"NULL", Q3NULLIllumination_New, kQ3IlluminationTypeNULL},
};

TQ3Matrix3x3 identity3()
{
    TQ3Matrix3x3 m{};
    for (int i = 0; i < 3; ++i)
        m.value[i][i] = 1.0f;
    return m;
}

TQ3Matrix3x3 someUVTransform()
{
    TQ3Matrix3x3 m = identity3();
    m.value[0][0] = 2.0f;
    m.value[1][1] = -0.5f;
    m.value[2][0] = 0.25f;
    m.value[2][1] = 0.75f;
    return m;
}

bool sameMatrix(const TQ3Matrix3x3& a, const TQ3Matrix3x3& b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// The u and v boundary calls, seen the same way.
struct BoundaryCalls {
    const char* name;
    TQ3Status (*set)(TQ3ShaderObject, TQ3ShaderUVBoundary);
    TQ3Status (*get)(TQ3ShaderObject, TQ3ShaderUVBoundary*);
};

const BoundaryCalls kBoundaries[] = {
    {"u", Q3Shader_SetUBoundary, Q3Shader_GetUBoundary},
    {"v", Q3Shader_SetVBoundary, Q3Shader_GetVBoundary},
};

TQ3ShaderUVBoundary rawBoundary(int value)
{
    return static_cast<TQ3ShaderUVBoundary>(value); // what a C caller passes
}

class ShaderApiTest : public q3test::OwningApiTest {
protected:
    /// A handle disposed already. Take it after creating the objects a
    /// check needs: a new object may reuse its address.
    TQ3Object disposedShader()
    {
        TQ3ShaderObject shader = Q3PhongIllumination_New();
        Q3Object_Dispose(shader);
        return shader;
    }

    TQ3ShaderUVBoundary boundary(const BoundaryCalls& calls, TQ3ShaderObject shader)
    {
        TQ3ShaderUVBoundary value = kQ3ShaderUVBoundaryWrap;
        EXPECT_EQ(calls.get(shader, &value), kQ3Success) << calls.name;
        return value;
    }

    TQ3Matrix3x3 uvTransform(TQ3ShaderObject shader)
    {
        TQ3Matrix3x3 m{};
        EXPECT_EQ(Q3Shader_GetUVTransform(shader, &m), kQ3Success);
        return m;
    }

    /// Bad shader handles: NULL, stray, objects that are not shaders, and a
    /// disposed one.
    std::vector<std::pair<TQ3Object, TQ3Error>> badShaders()
    {
        std::vector<std::pair<TQ3Object, TQ3Error>> bad = {
            {nullptr, kQ3ErrorNULLParameter},
            {reinterpret_cast<TQ3Object>(&m_stray), kQ3ErrorInvalidObject},
            {own(Q3AttributeSet_New()), kQ3ErrorInvalidObjectType},
            {own(Q3FillStyle_New(kQ3FillStyleEdges)), kQ3ErrorInvalidObjectType},
            {view(), kQ3ErrorInvalidObjectType}};
        bad.push_back({disposedShader(), kQ3ErrorInvalidObject}); // last: see disposedShader
        return bad;
    }

    void inRenderingLoop(const std::function<void(TQ3ViewObject)>& scene)
    {
        q3test::Pixmap pixmap(8, 8);
        q3test::TestView view(pixmap.pixmap());
        EXPECT_EQ(view.render(scene), kQ3ViewStatusDone);
    }

private:
    int m_stray = 0;
};

// ---- Illumination shaders ---------------------------------------------------

TEST_F(ShaderApiTest, EachIlluminationShaderHasItsTypeChain)
{
    for (const IlluminationKind& kind : kIlluminations) {
        TQ3ShaderObject shader = own(kind.create());
        ASSERT_NE(shader, nullptr) << kind.name;
        expectShapeTypeChain(shader, kQ3ShapeTypeShader, kind.type, kQ3True, kind.name);
        EXPECT_EQ(Q3Shader_GetType(shader), kQ3ShaderTypeIllumination) << kind.name;
        EXPECT_EQ(Q3IlluminationShader_GetType(shader), kind.type) << kind.name;
        EXPECT_EQ(Q3Object_IsType(shader, kQ3ShaderTypeIllumination), kQ3True) << kind.name;
    }
}

TEST_F(ShaderApiTest, GetTypeCallsRejectBadHandles)
{
    for (const auto& [handle, error] : badShaders()) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shader_GetType(handle), kQ3ObjectTypeInvalid), error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3IlluminationShader_GetType(handle), kQ3ObjectTypeInvalid), error);
    }
}

TEST_F(ShaderApiTest, DuplicateKeepsTheKindAndTheUVSettings)
{
    const TQ3Matrix3x3 m = someUVTransform();
    for (const IlluminationKind& kind : kIlluminations) {
        TQ3ShaderObject shader = own(kind.create());
        ASSERT_EQ(Q3Shader_SetUVTransform(shader, &m), kQ3Success);
        ASSERT_EQ(Q3Shader_SetVBoundary(shader, kQ3ShaderUVBoundaryClamp), kQ3Success);
        TQ3ShaderObject copy = own(Q3Object_Duplicate(shader));
        ASSERT_NE(copy, nullptr) << kind.name;
        EXPECT_NE(copy, shader);
        EXPECT_EQ(Q3IlluminationShader_GetType(copy), kind.type) << kind.name;
        EXPECT_TRUE(sameMatrix(uvTransform(copy), m)) << kind.name;
        EXPECT_EQ(boundary(kBoundaries[0], copy), kQ3ShaderUVBoundaryWrap) << kind.name;
        EXPECT_EQ(boundary(kBoundaries[1], copy), kQ3ShaderUVBoundaryClamp) << kind.name;
        // Independent: changing the copy leaves the original.
        ASSERT_EQ(Q3Shader_SetVBoundary(copy, kQ3ShaderUVBoundaryWrap), kQ3Success);
        EXPECT_EQ(boundary(kBoundaries[1], shader), kQ3ShaderUVBoundaryClamp) << kind.name;
    }
}

// ---- Submit -----------------------------------------------------------------

TEST_F(ShaderApiTest, SubmitWorksInRenderingAndBoundingLoopsOnly)
{
    for (const IlluminationKind& kind : kIlluminations) {
        TQ3ShaderObject shader = own(kind.create());
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shader_Submit(shader, view()), kQ3Failure), kQ3ErrorViewNotStarted);
        auto scene = [&](TQ3ViewObject v) {
            EXPECT_EQ(Q3Shader_Submit(shader, v), kQ3Success) << kind.name;
            EXPECT_EQ(Q3Object_Submit(shader, v), kQ3Success) << kind.name;
        };
        boundsOf(scene);
        inRenderingLoop(scene);
    }
}

TEST_F(ShaderApiTest, SubmitRejectsBadShadersAndViews)
{
    TQ3ShaderObject shader = own(Q3LambertIllumination_New());
    const auto bad = badShaders();
    boundsOf([&](TQ3ViewObject v) {
        for (const auto& [handle, error] : bad)
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shader_Submit(handle, v), kQ3Failure), error);
    });
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shader_Submit(shader, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shader_Submit(shader, shader), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shader_Submit(shader, disposedShader()), kQ3Failure), kQ3ErrorInvalidObject);
}

// ---- UV transform -------------------------------------------------------------

TEST_F(ShaderApiTest, UVTransformStartsAsTheIdentityAndReadsBack)
{
    for (const IlluminationKind& kind : kIlluminations) {
        TQ3ShaderObject shader = own(kind.create());
        EXPECT_TRUE(sameMatrix(uvTransform(shader), identity3())) << kind.name;
        const TQ3Matrix3x3 m = someUVTransform();
        const unsigned long before = Q3Shared_GetEditIndex(shader);
        ASSERT_EQ(Q3Shader_SetUVTransform(shader, &m), kQ3Success);
        EXPECT_NE(Q3Shared_GetEditIndex(shader), before);
        EXPECT_TRUE(sameMatrix(uvTransform(shader), m)) << kind.name;
        // Singular matrices are allowed (they squash the texture).
        const TQ3Matrix3x3 zero{};
        ASSERT_EQ(Q3Shader_SetUVTransform(shader, &zero), kQ3Success);
        EXPECT_TRUE(sameMatrix(uvTransform(shader), zero)) << kind.name;
    }
}

TEST_F(ShaderApiTest, SetUVTransformRejectsEveryNonFiniteEntryAndChangesNothing)
{
    TQ3ShaderObject shader = own(Q3PhongIllumination_New());
    const TQ3Matrix3x3 good = someUVTransform();
    ASSERT_EQ(Q3Shader_SetUVTransform(shader, &good), kQ3Success);
    const unsigned long before = Q3Shared_GetEditIndex(shader);
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column)
            for (float bad : {kNaN, kInf, -kInf}) {
                TQ3Matrix3x3 m = good;
                m.value[row][column] = bad;
                EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shader_SetUVTransform(shader, &m), kQ3Failure),
                                kQ3ErrorInvalidParameter);
            }
    EXPECT_TRUE(sameMatrix(uvTransform(shader), good));
    EXPECT_EQ(Q3Shared_GetEditIndex(shader), before);
}

TEST_F(ShaderApiTest, UVTransformCallsRejectBadHandlesAndPointers)
{
    const TQ3Matrix3x3 m = someUVTransform();
    for (const auto& [handle, error] : badShaders()) {
        TQ3Matrix3x3 out = m;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shader_GetUVTransform(handle, &out), kQ3Failure), error);
        EXPECT_TRUE(sameMatrix(out, m));
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shader_SetUVTransform(handle, &m), kQ3Failure), error);
    }
    TQ3ShaderObject shader = own(Q3NULLIllumination_New());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shader_SetUVTransform(shader, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shader_GetUVTransform(shader, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    // The handle is checked before the pointer.
    EXPECT_Q3_ERROR(Q3Shader_SetUVTransform(disposedShader(), nullptr), kQ3ErrorInvalidObject);
}

// ---- UV boundaries --------------------------------------------------------------

TEST_F(ShaderApiTest, BoundariesStartWrappedAndReadBackEachValue)
{
    for (const BoundaryCalls& calls : kBoundaries) {
        TQ3ShaderObject shader = own(Q3PhongIllumination_New());
        EXPECT_EQ(boundary(calls, shader), kQ3ShaderUVBoundaryWrap) << calls.name;
        for (TQ3ShaderUVBoundary value : {kQ3ShaderUVBoundaryClamp, kQ3ShaderUVBoundaryWrap}) {
            const unsigned long before = Q3Shared_GetEditIndex(shader);
            ASSERT_EQ(calls.set(shader, value), kQ3Success) << calls.name;
            EXPECT_EQ(boundary(calls, shader), value) << calls.name;
            EXPECT_NE(Q3Shared_GetEditIndex(shader), before) << calls.name;
        }
    }
    // u and v are separate.
    TQ3ShaderObject shader = own(Q3PhongIllumination_New());
    ASSERT_EQ(Q3Shader_SetUBoundary(shader, kQ3ShaderUVBoundaryClamp), kQ3Success);
    EXPECT_EQ(boundary(kBoundaries[1], shader), kQ3ShaderUVBoundaryWrap);
}

TEST_F(ShaderApiTest, SetBoundaryRejectsValuesOutsideTheEnumAndChangesNothing)
{
    for (const BoundaryCalls& calls : kBoundaries) {
        TQ3ShaderObject shader = own(Q3LambertIllumination_New());
        ASSERT_EQ(calls.set(shader, kQ3ShaderUVBoundaryClamp), kQ3Success);
        const unsigned long before = Q3Shared_GetEditIndex(shader);
        for (int bad : {2, -1, 1000000, INT_MAX, INT_MIN})
            EXPECT_Q3_ERROR(EXPECT_EQ(calls.set(shader, rawBoundary(bad)), kQ3Failure) << calls.name << " " << bad,
                            kQ3ErrorInvalidParameter);
        EXPECT_EQ(boundary(calls, shader), kQ3ShaderUVBoundaryClamp) << calls.name;
        EXPECT_EQ(Q3Shared_GetEditIndex(shader), before) << calls.name;
    }
}

TEST_F(ShaderApiTest, BoundaryCallsRejectBadHandlesAndPointers)
{
    for (const BoundaryCalls& calls : kBoundaries) {
        for (const auto& [handle, error] : badShaders()) {
            TQ3ShaderUVBoundary out = kQ3ShaderUVBoundaryClamp;
            EXPECT_Q3_ERROR(EXPECT_EQ(calls.get(handle, &out), kQ3Failure) << calls.name, error);
            EXPECT_EQ(out, kQ3ShaderUVBoundaryClamp);
            EXPECT_Q3_ERROR(EXPECT_EQ(calls.set(handle, kQ3ShaderUVBoundaryWrap), kQ3Failure) << calls.name, error);
        }
        // The handle is checked before the value.
        EXPECT_Q3_ERROR(calls.set(nullptr, rawBoundary(7)), kQ3ErrorNULLParameter);
        TQ3ShaderObject shader = own(Q3PhongIllumination_New());
        EXPECT_Q3_ERROR(EXPECT_EQ(calls.get(shader, nullptr), kQ3Failure) << calls.name, kQ3ErrorNULLParameter);
    }
}

// ---- Before Q3Initialize ----------------------------------------------------------

TEST(ShaderApiUninitialized, EveryFunctionFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    auto failed = [] { return Q3Error_Get(nullptr) == kQ3ErrorNotInitialized; };
    for (const IlluminationKind& kind : kIlluminations) {
        EXPECT_EQ(kind.create(), nullptr) << kind.name;
        EXPECT_TRUE(failed()) << kind.name;
    }
    EXPECT_EQ(Q3Shader_GetType(nullptr), kQ3ObjectTypeInvalid);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3IlluminationShader_GetType(nullptr), kQ3ObjectTypeInvalid);
    EXPECT_TRUE(failed());
    TQ3Matrix3x3 m = identity3();
    TQ3ShaderUVBoundary boundary = kQ3ShaderUVBoundaryWrap;
    const std::vector<std::function<TQ3Status()>> calls = {
        [&] { return Q3Shader_Submit(nullptr, nullptr); },
        [&] { return Q3Shader_SetUVTransform(nullptr, &m); },
        [&] { return Q3Shader_GetUVTransform(nullptr, &m); },
        [&] { return Q3Shader_SetUBoundary(nullptr, kQ3ShaderUVBoundaryClamp); },
        [&] { return Q3Shader_SetVBoundary(nullptr, kQ3ShaderUVBoundaryClamp); },
        [&] { return Q3Shader_GetUBoundary(nullptr, &boundary); },
        [&] { return Q3Shader_GetVBoundary(nullptr, &boundary); },
    };
    for (std::size_t i = 0; i < calls.size(); ++i) {
        EXPECT_EQ(calls[i](), kQ3Failure) << "call " << i;
        EXPECT_TRUE(failed()) << "call " << i;
    }
}

} // namespace
