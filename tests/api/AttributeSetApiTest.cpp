// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "DiffuseColor.h"
#include "GeometryTestSupport.h"
#include "OwningApiTest.h"
#include "SetTestSupport.h"

#include "QD3DSet.h"
#include "QD3DView.h"

#include <cstring>
#include <limits>
#include <vector>

namespace {

using namespace q3test;
using AttributeSetApiTest = SetApiTestBase;

// The types Q3AttributeSet_GetNextAttributeType walks through, in its order.
std::vector<TQ3AttributeType> attributeWalk(TQ3AttributeSet set)
{
    std::vector<TQ3AttributeType> types;
    TQ3AttributeType type = kQ3AttributeTypeNone;
    while (Q3AttributeSet_GetNextAttributeType(set, &type) == kQ3Success && type != kQ3AttributeTypeNone &&
           types.size() <= kQ3AttributeTypeNumTypes)
        types.push_back(type);
    return types;
}

TQ3AttributeSet deadAttributeSet()
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    Q3Object_Dispose(set);
    return set;
}

TEST_F(AttributeSetApiTest, AddGetContainsClearAndEmpty)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    ASSERT_NE(set, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(set), kQ3SetTypeAttribute);
    EXPECT_EQ(Q3Shared_GetType(set), kQ3SharedTypeSet);
    EXPECT_EQ(Q3AttributeSet_Contains(set, kQ3AttributeTypeDiffuseColor), kQ3False);
    const TQ3ColorRGB color{0.25f, 0.5f, 0.75f};
    const unsigned long before = Q3Shared_GetEditIndex(set);
    EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(set), before);
    EXPECT_EQ(Q3AttributeSet_Contains(set, kQ3AttributeTypeDiffuseColor), kQ3True);
    TQ3ColorRGB got{};
    EXPECT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeDiffuseColor, &got), kQ3Success);
    EXPECT_EQ(got.r, 0.25f);
    EXPECT_EQ(got.g, 0.5f);
    EXPECT_EQ(got.b, 0.75f);
    const float coefficient = 0.5f;
    EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeAmbientCoefficient, &coefficient), kQ3Success);
    const TQ3Switch highlight = kQ3On;
    EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeHighlightState, &highlight), kQ3Success);
    EXPECT_EQ(Q3AttributeSet_Clear(set, kQ3AttributeTypeDiffuseColor), kQ3Success);
    EXPECT_EQ(Q3AttributeSet_Contains(set, kQ3AttributeTypeDiffuseColor), kQ3False);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeDiffuseColor, &got), kQ3Failure),
                    kQ3ErrorAttributeNotContained);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Clear(set, kQ3AttributeTypeDiffuseColor), kQ3Failure),
                    kQ3ErrorAttributeNotContained);
    EXPECT_EQ(Q3AttributeSet_Empty(set), kQ3Success);
    EXPECT_EQ(Q3AttributeSet_Contains(set, kQ3AttributeTypeAmbientCoefficient), kQ3False);
    EXPECT_EQ(Q3AttributeSet_Contains(set, kQ3AttributeTypeHighlightState), kQ3False);
}

TEST_F(AttributeSetApiTest, RejectsBadTypesPointersAndValues)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB color{1, 1, 1};
    for (TQ3AttributeType type : {TQ3AttributeType{kQ3AttributeTypeNone},
                                  TQ3AttributeType{kQ3AttributeTypeNumTypes}, TQ3AttributeType{99},
                                  TQ3AttributeType{-1}}) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Add(set, type, &color), kQ3Failure),
                        kQ3ErrorAttributeInvalidType);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Contains(set, type), kQ3False), kQ3ErrorAttributeInvalidType);
    }
    EXPECT_Q3_ERROR(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, nullptr), kQ3ErrorNULLParameter);
    TQ3ColorRGB out{};
    EXPECT_Q3_ERROR(Q3AttributeSet_Get(set, kQ3AttributeTypeDiffuseColor, nullptr), kQ3ErrorNULLParameter);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (TQ3ColorRGB bad : {TQ3ColorRGB{nan, 0, 0}, TQ3ColorRGB{0, inf, 0}, TQ3ColorRGB{0, 0, -inf}})
        EXPECT_Q3_ERROR(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &bad), kQ3ErrorInvalidParameter);
    const int badSwitch = 7;
    EXPECT_Q3_ERROR(Q3AttributeSet_Add(set, kQ3AttributeTypeHighlightState, &badSwitch),
                    kQ3ErrorInvalidParameter);
    EXPECT_EQ(Q3AttributeSet_Contains(set, kQ3AttributeTypeDiffuseColor), kQ3False);
    EXPECT_Q3_ERROR(Q3AttributeSet_Get(nullptr, kQ3AttributeTypeDiffuseColor, &out), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3AttributeSet_Empty(nullptr), kQ3ErrorNULLParameter);
    Q3Object_Dispose(set);
    EXPECT_Q3_ERROR(Q3AttributeSet_Empty(set), kQ3ErrorInvalidObject);
}

TEST_F(AttributeSetApiTest, DuplicateCopiesValuesIndependently)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB red{1, 0, 0};
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &red);
    TQ3AttributeSet copy = Q3Object_Duplicate(set);
    ASSERT_NE(copy, nullptr);
    ASSERT_NE(copy, set);
    Q3AttributeSet_Clear(set, kQ3AttributeTypeDiffuseColor);
    EXPECT_EQ(expectDiffuseColor(copy).r, 1.0f);
    Q3Object_Dispose(copy);
    Q3Object_Dispose(set);
}

TEST_F(AttributeSetApiTest, TheSurfaceShaderAttributeIsHeldByReference)
{
    TQ3ShaderObject shader = own(newTextureShader());
    ASSERT_NE(shader, nullptr);
    TQ3AttributeSet set = Q3AttributeSet_New();
    EXPECT_EQ(referenceCount(shader), 1UL);
    const unsigned long before = Q3Shared_GetEditIndex(set);
    EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(set), before);
    EXPECT_EQ(referenceCount(shader), 2UL);
    EXPECT_EQ(Q3AttributeSet_Contains(set, kQ3AttributeTypeSurfaceShader), kQ3True);
    EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
    EXPECT_EQ(referenceCount(shader), 2UL);
    expectSurfaceShaderHandedOut(Q3AttributeSet_Get, set, shader); // 3 references while handed out, then 2 again

    // Another surface shader replaces it and releases it.
    TQ3ShaderObject other = own(newTextureShader());
    EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceShader, &other), kQ3Success);
    EXPECT_EQ(referenceCount(shader), 1UL);
    EXPECT_EQ(referenceCount(other), 2UL);
    EXPECT_EQ(Q3AttributeSet_Clear(set, kQ3AttributeTypeSurfaceShader), kQ3Success);
    EXPECT_EQ(referenceCount(other), 1UL);
    EXPECT_EQ(Q3AttributeSet_Contains(set, kQ3AttributeTypeSurfaceShader), kQ3False);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Clear(set, kQ3AttributeTypeSurfaceShader), kQ3Failure),
                    kQ3ErrorAttributeNotContained);
    TQ3SurfaceShaderObject got = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Get(set, kQ3AttributeTypeSurfaceShader, &got), kQ3Failure),
                    kQ3ErrorAttributeNotContained);
    EXPECT_EQ(got, nullptr);

    EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
    EXPECT_EQ(Q3AttributeSet_Empty(set), kQ3Success);
    EXPECT_EQ(referenceCount(shader), 1UL);
    EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
    // A duplicate shares the shader.
    TQ3AttributeSet copy = Q3Object_Duplicate(set);
    EXPECT_EQ(referenceCount(shader), 3UL);
    Q3Object_Dispose(copy);
    Q3Object_Dispose(set);
    EXPECT_EQ(referenceCount(shader), 1UL);
}

TEST_F(AttributeSetApiTest, AddRefusesWhatIsNoSurfaceShaderAndChangesNothing)
{
    expectOnlySurfaceShadersTaken(Q3AttributeSet_Add, Q3AttributeSet_Get, own(Q3AttributeSet_New()));
}

TEST_F(AttributeSetApiTest, GetNextAttributeTypeWalksInTypeOrder)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    EXPECT_TRUE(attributeWalk(set).empty());
    TQ3ShaderObject shader = own(newTextureShader());
    const float control = 8.0f;
    const TQ3Vector3D normal{0, 0, 1};
    const TQ3Switch highlight = kQ3On;
    ASSERT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
    ASSERT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeSpecularControl, &control), kQ3Success);
    ASSERT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeHighlightState, &highlight), kQ3Success);
    ASSERT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeNormal, &normal), kQ3Success);
    const std::vector<TQ3AttributeType> expected{kQ3AttributeTypeNormal, kQ3AttributeTypeSpecularControl,
                                                 kQ3AttributeTypeHighlightState, kQ3AttributeTypeSurfaceShader};
    EXPECT_EQ(attributeWalk(set), expected);
    const unsigned long edit = Q3Shared_GetEditIndex(set);

    TQ3AttributeType type = kQ3AttributeTypeSurfaceUV;  // not held: the walk goes on after it
    EXPECT_EQ(Q3AttributeSet_GetNextAttributeType(set, &type), kQ3Success);
    EXPECT_EQ(type, kQ3AttributeTypeNormal);
    type = kQ3AttributeTypeSurfaceShader;
    EXPECT_EQ(Q3AttributeSet_GetNextAttributeType(set, &type), kQ3Success);
    EXPECT_EQ(type, kQ3AttributeTypeNone);

    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_GetNextAttributeType(set, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    for (TQ3AttributeType bad : {TQ3AttributeType{kQ3AttributeTypeNumTypes}, TQ3AttributeType{-1},
                                 TQ3AttributeType{kQ3ElementTypeUnknown}}) {
        type = bad;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_GetNextAttributeType(set, &type), kQ3Failure),
                        kQ3ErrorAttributeInvalidType);
        EXPECT_EQ(type, bad);
    }
    type = kQ3AttributeTypeNone;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_GetNextAttributeType(nullptr, &type), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_GetNextAttributeType(deadAttributeSet(), &type), kQ3Failure),
                    kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_GetNextAttributeType(shader, &type), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    EXPECT_EQ(type, kQ3AttributeTypeNone);
    EXPECT_EQ(Q3Shared_GetEditIndex(set), edit);
}

// Q3AttributeSet_Inherit's result computed here: for each type, the child's
// value if it has one, else the parent's, else none.
SetContents inherited(const SetContents& parent, const SetContents& child)
{
    SetContents result;
    for (std::size_t type = 0; type < result.values.size(); ++type)
        result.values[type] = child.values[type] ? child.values[type] : parent.values[type];
    return result;
}

TEST_F(AttributeSetApiTest, InheritGivesTheChildsAttributesOverTheParents)
{
    TQ3ShaderObject parentShader = own(newTextureShader());
    TQ3ShaderObject childShader = own(newTextureShader());
    // Parent: even types and a shader; child: every third type; result
    // starts with types the other two lack, which the merge drops.
    const auto fill = [&](TQ3AttributeSet set, int first, int step, float seed, TQ3ShaderObject shader) {
        for (TQ3AttributeType type = first; type <= kQ3AttributeTypeHighlightState; type += step) {
            const AttributeBytes value = attributeValue(type, seed);
            EXPECT_EQ(Q3AttributeSet_Add(set, type, value.data()), kQ3Success);
        }
        if (shader != nullptr)
            EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceShader, &shader), kQ3Success);
    };
    for (int childHasShader = 0; childHasShader < 2; ++childHasShader) {
        TQ3AttributeSet parent = own(Q3AttributeSet_New());
        TQ3AttributeSet child = own(Q3AttributeSet_New());
        TQ3AttributeSet result = own(Q3AttributeSet_New());
        fill(parent, 2, 2, 0.25f, parentShader);
        fill(child, 3, 3, 0.5f, childHasShader ? childShader : nullptr);
        const AttributeBytes uv = attributeValue(kQ3AttributeTypeSurfaceUV, 0.75f);
        EXPECT_EQ(Q3AttributeSet_Add(result, kQ3AttributeTypeSurfaceUV, uv.data()), kQ3Success);
        const SetContents expected = inherited(contentsOf(parent), contentsOf(child));
        const SetContents parentBefore = contentsOf(parent), childBefore = contentsOf(child);
        const unsigned long parentEdit = Q3Shared_GetEditIndex(parent), childEdit = Q3Shared_GetEditIndex(child);
        const unsigned long resultEdit = Q3Shared_GetEditIndex(result);
        const unsigned long parentShaderCount = referenceCount(parentShader);

        EXPECT_EQ(Q3AttributeSet_Inherit(parent, child, result), kQ3Success);
        EXPECT_TRUE(contentsOf(result) == expected) << "child has a shader: " << childHasShader;
        EXPECT_EQ(Q3AttributeSet_Contains(result, kQ3AttributeTypeSurfaceUV), kQ3False);
        EXPECT_NE(Q3Shared_GetEditIndex(result), resultEdit);
        EXPECT_TRUE(contentsOf(parent) == parentBefore);
        EXPECT_TRUE(contentsOf(child) == childBefore);
        EXPECT_EQ(Q3Shared_GetEditIndex(parent), parentEdit);
        EXPECT_EQ(Q3Shared_GetEditIndex(child), childEdit);
        TQ3Object got = nullptr;
        ASSERT_EQ(Q3AttributeSet_Get(result, kQ3AttributeTypeSurfaceShader, &got), kQ3Success);
        EXPECT_EQ(got, childHasShader ? childShader : parentShader);
        Q3Object_Dispose(got);
        // result holds one more reference to the shader it inherited.
        EXPECT_EQ(referenceCount(parentShader), parentShaderCount + (childHasShader ? 0 : 1));

        // result may be the child or the parent itself.
        EXPECT_EQ(Q3AttributeSet_Inherit(parent, child, child), kQ3Success);
        EXPECT_TRUE(contentsOf(child) == expected);
        TQ3AttributeSet parentCopy = own(Q3Object_Duplicate(parent));
        EXPECT_TRUE(contentsOf(parentCopy) == parentBefore);
        EXPECT_EQ(Q3AttributeSet_Inherit(parentCopy, child, parentCopy), kQ3Success);
        EXPECT_TRUE(contentsOf(parentCopy) == expected);
        EXPECT_EQ(Q3AttributeSet_Inherit(parent, parent, parent), kQ3Success);
        EXPECT_TRUE(contentsOf(parent) == parentBefore);
    }
    // Every set disposed by TearDown: the shaders are back to the caller's one
    // reference once they are gone, which the leak check confirms.
}

TEST_F(AttributeSetApiTest, InheritRefusesBadSetsAndLeavesTheResultUnchanged)
{
    TQ3AttributeSet parent = own(Q3AttributeSet_New());
    TQ3AttributeSet child = own(Q3AttributeSet_New());
    TQ3AttributeSet result = own(Q3AttributeSet_New());
    const TQ3ColorRGB red{1, 0, 0};
    ASSERT_EQ(Q3AttributeSet_Add(parent, kQ3AttributeTypeDiffuseColor, &red), kQ3Success);
    const float ambient = 0.5f;
    ASSERT_EQ(Q3AttributeSet_Add(result, kQ3AttributeTypeAmbientCoefficient, &ambient), kQ3Success);
    const SetContents before = contentsOf(result);
    const unsigned long edit = Q3Shared_GetEditIndex(result);
    TQ3SetObject plain = own(Q3Set_New());
    const std::pair<TQ3Object, TQ3Error> bads[] = {{nullptr, kQ3ErrorNULLParameter},
                                                   {deadAttributeSet(), kQ3ErrorInvalidObject},
                                                   {plain, kQ3ErrorInvalidObjectType}};
    for (const auto& [bad, error] : bads) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Inherit(bad, child, result), kQ3Failure), error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Inherit(parent, bad, result), kQ3Failure), error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Inherit(parent, child, bad), kQ3Failure), error);
    }
    EXPECT_EQ(Q3Shared_GetEditIndex(result), edit);
    EXPECT_TRUE(contentsOf(result) == before);
}

TEST_F(AttributeSetApiTest, EveryCallRefusesBadSetHandles)
{
    TQ3ShaderObject shader = own(Q3PhongIllumination_New());
    const std::pair<TQ3Object, TQ3Error> bads[] = {{nullptr, kQ3ErrorNULLParameter},
                                                   {deadAttributeSet(), kQ3ErrorInvalidObject},
                                                   {shader, kQ3ErrorInvalidObjectType}};
    const TQ3ColorRGB color{1, 1, 1};
    for (const auto& [bad, error] : bads) {
        TQ3ColorRGB out = color;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Add(bad, kQ3AttributeTypeDiffuseColor, &color), kQ3Failure), error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Get(bad, kQ3AttributeTypeDiffuseColor, &out), kQ3Failure), error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Contains(bad, kQ3AttributeTypeDiffuseColor), kQ3False), error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Clear(bad, kQ3AttributeTypeDiffuseColor), kQ3Failure), error);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Empty(bad), kQ3Failure), error);
        boundsOf([&](TQ3ViewObject v) {
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3AttributeSet_Submit(bad, v), kQ3Failure), error);
        });
        EXPECT_EQ(out.r, 1.0f);
    }
}

TEST_F(AttributeSetApiTest, AttributeSubmitSetsOneAttributeOfTheViewState)
{
    const TQ3ColorRGB green{0, 1, 0};
    TQ3ShaderObject shader = own(newTextureShader());
    boundsOf([&](TQ3ViewObject v) {
        TQ3ColorRGB got{};
        EXPECT_EQ(Q3View_GetAttributeState(v, kQ3AttributeTypeDiffuseColor, &got), kQ3Success);
        EXPECT_EQ(got.g, 1.0f);  // the default: white
        EXPECT_EQ(got.r, 1.0f);
        EXPECT_EQ(Q3Attribute_Submit(kQ3AttributeTypeDiffuseColor, &green, v), kQ3Success);
        EXPECT_EQ(Q3View_GetAttributeState(v, kQ3AttributeTypeDiffuseColor, &got), kQ3Success);
        EXPECT_EQ(got.r, 0.0f);
        EXPECT_EQ(got.g, 1.0f);

        EXPECT_EQ(Q3Attribute_Submit(kQ3AttributeTypeSurfaceShader, &shader, v), kQ3Success);
        TQ3Object inForce = nullptr;
        EXPECT_EQ(Q3View_GetAttributeState(v, kQ3AttributeTypeSurfaceShader, &inForce), kQ3Success);
        EXPECT_EQ(inForce, shader);
        if (inForce != nullptr)
            Q3Object_Dispose(inForce);
    });
    // The pass is over: the view's state no longer holds the shader.
    EXPECT_EQ(referenceCount(shader), 1UL);
}

TEST_F(AttributeSetApiTest, AttributeSubmitRefusesBadArguments)
{
    const TQ3ColorRGB green{0, 1, 0};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Attribute_Submit(kQ3AttributeTypeDiffuseColor, &green, view()), kQ3Failure),
                    kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Attribute_Submit(kQ3AttributeTypeDiffuseColor, &green, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    TQ3ShaderObject illumination = own(Q3PhongIllumination_New());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Attribute_Submit(kQ3AttributeTypeDiffuseColor, &green, illumination), kQ3Failure),
                    kQ3ErrorInvalidObjectType);
    boundsOf([&](TQ3ViewObject v) {
        for (TQ3AttributeType bad : {TQ3AttributeType{kQ3AttributeTypeNone},
                                     TQ3AttributeType{kQ3AttributeTypeNumTypes}, TQ3AttributeType{-1}})
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3Attribute_Submit(bad, &green, v), kQ3Failure),
                            kQ3ErrorAttributeInvalidType);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Attribute_Submit(kQ3AttributeTypeDiffuseColor, nullptr, v), kQ3Failure),
                        kQ3ErrorNULLParameter);
        const TQ3ColorRGB nan{0, std::numeric_limits<float>::quiet_NaN(), 0};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Attribute_Submit(kQ3AttributeTypeDiffuseColor, &nan, v), kQ3Failure),
                        kQ3ErrorInvalidParameter);
        EXPECT_Q3_ERROR(
            EXPECT_EQ(Q3Attribute_Submit(kQ3AttributeTypeSurfaceShader, &illumination, v), kQ3Failure),
            kQ3ErrorInvalidObjectType);
        // The refused submits changed nothing: the default diffuse colour holds.
        TQ3ColorRGB got{};
        EXPECT_EQ(Q3View_GetAttributeState(v, kQ3AttributeTypeDiffuseColor, &got), kQ3Success);
        EXPECT_EQ(got.r, 1.0f);
        EXPECT_EQ(got.g, 1.0f);
        TQ3Object inForce = nullptr;
        EXPECT_Q3_ERROR(
            EXPECT_EQ(Q3View_GetAttributeState(v, kQ3AttributeTypeSurfaceShader, &inForce), kQ3Failure),
            kQ3ErrorAttributeNotContained);
    });
}

} // namespace
