// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QuadricApiTestSupport.h"

namespace {

using namespace q3test;

struct EllipsoidTraits {
    using Data = TQ3EllipsoidData;
    static Shape<Data> shape()
    {
        Shape<Data> s;
        s.name = "ellipsoid";
        s.type = kQ3GeometryTypeEllipsoid;
        s.create = Q3Ellipsoid_New;
        s.submit = Q3Ellipsoid_Submit;
        s.setData = Q3Ellipsoid_SetData;
        s.getData = Q3Ellipsoid_GetData;
        s.emptyData = Q3Ellipsoid_EmptyData;
        s.setOrigin = Q3Ellipsoid_SetOrigin;
        s.getOrigin = Q3Ellipsoid_GetOrigin;
        s.origin = &Data::origin;
        s.vectors = {{"orientation", &Data::orientation, Q3Ellipsoid_SetOrientation, Q3Ellipsoid_GetOrientation},
                     {"majorRadius", &Data::majorRadius, Q3Ellipsoid_SetMajorRadius, Q3Ellipsoid_GetMajorRadius},
                     {"minorRadius", &Data::minorRadius, Q3Ellipsoid_SetMinorRadius, Q3Ellipsoid_GetMinorRadius}};
        s.sets = {{"interiorAttributeSet", &Data::interiorAttributeSet, nullptr, nullptr},
                  {"ellipsoidAttributeSet", &Data::ellipsoidAttributeSet, nullptr, nullptr}};
        s.own = &Data::ellipsoidAttributeSet;
        s.parameters = {{"uMin", &Data::uMin}, {"uMax", &Data::uMax}, {"vMin", &Data::vMin}, {"vMax", &Data::vMax}};
        s.sample = Data{{0, 0, 0}, {0, 0, 1.5f}, {1, 0, 0}, {0, 1.2f, 0}, 0, 1, 0, 1, kQ3EndCapNone, nullptr, nullptr};
        return s;
    }
};

using EllipsoidApiTest = QuadricApiTest<EllipsoidTraits>;
Q3_QUADRIC_API_TESTS(EllipsoidApiTest)

TEST_F(EllipsoidApiTest, TheBoundingBoxIsTheEllipsoidsOwn)
{
    TQ3GeometryObject ellipsoid = make(shape().sample);
    const TQ3BoundingBox box =
        boundsOf([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(ellipsoid, v), kQ3Success); });
    EXPECT_FLOAT_EQ(box.min.x, -1);
    EXPECT_FLOAT_EQ(box.max.x, 1);
    EXPECT_FLOAT_EQ(box.min.y, -1.2f);
    EXPECT_FLOAT_EQ(box.max.y, 1.2f);
    EXPECT_FLOAT_EQ(box.min.z, -1.5f);
    EXPECT_FLOAT_EQ(box.max.z, 1.5f);
}

TEST_F(EllipsoidApiTest, CapsAreSetWithTheDataAndOnlyEndCapMasksAreAccepted)
{
    Data data = shape().sample;
    data.caps = kQ3EndCapMaskTop | kQ3EndCapMaskBottom | kQ3EndCapMaskInterior;
    data.vMin = 0.2f;
    data.vMax = 0.7f;
    data.uMax = 0.5f;
    TQ3GeometryObject ellipsoid = make(data);
    ASSERT_NE(ellipsoid, nullptr);
    Data out = dataOf(ellipsoid);
    EXPECT_EQ(out.caps, data.caps);
    Q3Ellipsoid_EmptyData(&out);
    data.caps = 0x100;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Ellipsoid_New(&data), nullptr), kQ3ErrorInvalidData);
}

} // namespace
