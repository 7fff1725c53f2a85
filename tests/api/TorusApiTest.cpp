// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QuadricApiTestSupport.h"

namespace {

using namespace q3test;

struct TorusTraits {
    using Data = TQ3TorusData;
    static Shape<Data> shape()
    {
        Shape<Data> s;
        s.name = "torus";
        s.type = kQ3GeometryTypeTorus;
        s.create = Q3Torus_New;
        s.submit = Q3Torus_Submit;
        s.setData = Q3Torus_SetData;
        s.getData = Q3Torus_GetData;
        s.emptyData = Q3Torus_EmptyData;
        s.setOrigin = Q3Torus_SetOrigin;
        s.getOrigin = Q3Torus_GetOrigin;
        s.origin = &Data::origin;
        s.vectors = {{"orientation", &Data::orientation, Q3Torus_SetOrientation, Q3Torus_GetOrientation},
                     {"majorRadius", &Data::majorRadius, Q3Torus_SetMajorRadius, Q3Torus_GetMajorRadius},
                     {"minorRadius", &Data::minorRadius, Q3Torus_SetMinorRadius, Q3Torus_GetMinorRadius}};
        s.sets = {{"interiorAttributeSet", &Data::interiorAttributeSet, nullptr, nullptr},
                  {"torusAttributeSet", &Data::torusAttributeSet, nullptr, nullptr}};
        s.own = &Data::torusAttributeSet;
        s.parameters = {{"uMin", &Data::uMin}, {"uMax", &Data::uMax}, {"vMin", &Data::vMin}, {"vMax", &Data::vMax}};
        s.extraFloats = {{"ratio", [](Data& d) -> float& { return d.ratio; }}};
        s.sample =
            Data{{0, 0, 0}, {0, 0, 0.3f}, {1, 0, 0}, {0, 1.5f, 0}, 1, 0, 1, 0, 1, kQ3EndCapNone, nullptr, nullptr};
        return s;
    }
};

using TorusApiTest = QuadricApiTest<TorusTraits>;
Q3_QUADRIC_API_TESTS(TorusApiTest)

TEST_F(TorusApiTest, RatioReadsBackAndMustBeFiniteAndNotNegative)
{
    TQ3GeometryObject torus = make(shape().sample);
    float ratio = 0;
    ASSERT_EQ(Q3Torus_GetRatio(torus, &ratio), kQ3Success);
    EXPECT_EQ(ratio, 1.0f);
    const unsigned long before = Q3Shared_GetEditIndex(torus);
    ASSERT_EQ(Q3Torus_SetRatio(torus, 0.5f), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(torus), before);
    ASSERT_EQ(Q3Torus_GetRatio(torus, &ratio), kQ3Success);
    EXPECT_EQ(ratio, 0.5f);
    State state = stateOf(torus);
    for (float bad : {-1.0f, -0.0001f, kNaN, kInf, -kInf})
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Torus_SetRatio(torus, bad), kQ3Failure), kQ3ErrorInvalidData);
    // Zero is degenerate, not malformed: taken with the warning, read back.
    TQ3GeometryObject ring = make(shape().sample);
    EXPECT_Q3_WARNING(EXPECT_EQ(Q3Torus_SetRatio(ring, 0), kQ3Success), kQ3WarningInconsistentData);
    float zero = 1;
    ASSERT_EQ(Q3Torus_GetRatio(ring, &zero), kQ3Success);
    EXPECT_EQ(zero, 0.0f);
    expectDrawsNothing(ring, "SetRatio 0");
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Torus_SetRatio(nullptr, 1), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Torus_SetRatio(wrongClass(), 1), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Torus_SetRatio(disposed(), 1), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Torus_GetRatio(nullptr, &ratio), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Torus_GetRatio(torus, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Torus_GetRatio(wrongClass(), &ratio), kQ3Failure), kQ3ErrorInvalidObjectType);
    expectUnchanged(torus, state, "SetRatio");
    Q3Torus_EmptyData(&state.data);
    Data data = shape().sample;
    data.ratio = -0.5f;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Torus_New(&data), nullptr), kQ3ErrorInvalidData);
    // A ratio of 0 (a tube with no thickness) is kept with the warning and
    // draws nothing (docs/3dmf.md, Tolerances).
    data.ratio = 0;
    TQ3GeometryObject thin = nullptr;
    EXPECT_Q3_WARNING(thin = make(data), kQ3WarningInconsistentData);
    ASSERT_NE(thin, nullptr);
    expectDrawsNothing(thin, "ratio 0");
}

TEST_F(TorusApiTest, BothRangesAreAnglesThatMayWrap)
{
    Data data = shape().sample;
    data.vMin = 0.8f;
    data.vMax = 0.2f;
    data.uMin = 0.9f;
    data.uMax = 0.1f;
    data.caps = kQ3EndCapMaskInterior;
    TQ3GeometryObject torus = make(data);
    ASSERT_NE(torus, nullptr);
    TQ3BoundingBox box{};
    EXPECT_FALSE(decomposedPoints(torus, box).empty());
    data.vMin = 1;
    data.vMax = 0;
    // No angle: kept with the warning (docs/3dmf.md, Tolerances).
    EXPECT_Q3_WARNING(EXPECT_NE(make(data), nullptr), kQ3WarningInconsistentData);
}

} // namespace
