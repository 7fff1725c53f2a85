// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QuadricApiTestSupport.h"

namespace {

using namespace q3test;

struct ConeTraits {
    using Data = TQ3ConeData;
    static Shape<Data> shape()
    {
        Shape<Data> s;
        s.name = "cone";
        s.type = kQ3GeometryTypeCone;
        s.create = Q3Cone_New;
        s.submit = Q3Cone_Submit;
        s.setData = Q3Cone_SetData;
        s.getData = Q3Cone_GetData;
        s.emptyData = Q3Cone_EmptyData;
        s.setOrigin = Q3Cone_SetOrigin;
        s.getOrigin = Q3Cone_GetOrigin;
        s.origin = &Data::origin;
        s.vectors = {{"orientation", &Data::orientation, Q3Cone_SetOrientation, Q3Cone_GetOrientation},
                     {"majorRadius", &Data::majorRadius, Q3Cone_SetMajorRadius, Q3Cone_GetMajorRadius},
                     {"minorRadius", &Data::minorRadius, Q3Cone_SetMinorRadius, Q3Cone_GetMinorRadius}};
        s.sets = {{"interiorAttributeSet", &Data::interiorAttributeSet, nullptr, nullptr},
                  {"faceAttributeSet", &Data::faceAttributeSet, Q3Cone_SetFaceAttributeSet, Q3Cone_GetFaceAttributeSet},
                  {"bottomAttributeSet", &Data::bottomAttributeSet, Q3Cone_SetBottomAttributeSet,
                   Q3Cone_GetBottomAttributeSet},
                  {"coneAttributeSet", &Data::coneAttributeSet, nullptr, nullptr}};
        s.own = &Data::coneAttributeSet;
        s.parameters = {{"uMin", &Data::uMin}, {"uMax", &Data::uMax}, {"vMin", &Data::vMin}, {"vMax", &Data::vMax}};
        s.sample = Data{{1, 2, 3}, {0, 0, 2},           {1, 0, 0}, {0, 0.5f, 0}, 0,       1,      0,
                        1,         kQ3EndCapMaskBottom, nullptr,   nullptr,      nullptr, nullptr};
        return s;
    }
};

using ConeApiTest = QuadricApiTest<ConeTraits>;
Q3_QUADRIC_API_TESTS(ConeApiTest)

TEST_F(ConeApiTest, CapsReadBackAndOnlyEndCapMasksAreAccepted)
{
    TQ3GeometryObject cone = make(shape().sample);
    TQ3EndCap caps = 99;
    ASSERT_EQ(Q3Cone_GetCaps(cone, &caps), kQ3Success);
    EXPECT_EQ(caps, TQ3EndCap(kQ3EndCapMaskBottom));
    const unsigned long before = Q3Shared_GetEditIndex(cone);
    // kQ3EndCapMaskTop is accepted (and ignored: a cone has no top).
    ASSERT_EQ(Q3Cone_SetCaps(cone, kQ3EndCapMaskTop | kQ3EndCapMaskInterior), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(cone), before);
    ASSERT_EQ(Q3Cone_GetCaps(cone, &caps), kQ3Success);
    EXPECT_EQ(caps, TQ3EndCap(kQ3EndCapMaskTop | kQ3EndCapMaskInterior));

    State state = stateOf(cone);
    for (TQ3EndCap bad : {TQ3EndCap(8), TQ3EndCap(15), ~TQ3EndCap(0)})
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Cone_SetCaps(cone, bad), kQ3Failure), kQ3ErrorInvalidData);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Cone_SetCaps(nullptr, 0), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Cone_SetCaps(wrongClass(), 0), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Cone_SetCaps(disposed(), 0), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Cone_GetCaps(nullptr, &caps), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Cone_GetCaps(cone, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Cone_GetCaps(wrongClass(), &caps), kQ3Failure), kQ3ErrorInvalidObjectType);
    expectUnchanged(cone, state, "SetCaps");
    Q3Cone_EmptyData(&state.data);

    Data data = shape().sample;
    data.caps = 16;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Cone_New(&data), nullptr), kQ3ErrorInvalidData);
}

TEST_F(ConeApiTest, PartialRangesWrapAroundAngleZeroButVMustIncrease)
{
    Data data = shape().sample;
    data.uMin = 0.75f;
    data.uMax = 0.25f;
    EXPECT_NE(make(data), nullptr);
    data.uMin = 1;
    data.uMax = 0;
    // No angle: kept with the warning (docs/3dmf.md, Tolerances).
    EXPECT_Q3_WARNING(EXPECT_NE(make(data), nullptr), kQ3WarningInconsistentData);
    data = shape().sample;
    data.vMin = 0.6f;
    data.vMax = 0.4f;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Cone_New(&data), nullptr), kQ3ErrorInvalidData);
}

} // namespace
