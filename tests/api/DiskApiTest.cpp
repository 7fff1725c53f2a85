// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QuadricApiTestSupport.h"

namespace {

using namespace q3test;

struct DiskTraits {
    using Data = TQ3DiskData;
    static Shape<Data> shape()
    {
        Shape<Data> s;
        s.name = "disk";
        s.type = kQ3GeometryTypeDisk;
        s.create = Q3Disk_New;
        s.submit = Q3Disk_Submit;
        s.setData = Q3Disk_SetData;
        s.getData = Q3Disk_GetData;
        s.emptyData = Q3Disk_EmptyData;
        s.setOrigin = Q3Disk_SetOrigin;
        s.getOrigin = Q3Disk_GetOrigin;
        s.origin = &Data::origin;
        s.vectors = {{"majorRadius", &Data::majorRadius, Q3Disk_SetMajorRadius, Q3Disk_GetMajorRadius},
                     {"minorRadius", &Data::minorRadius, Q3Disk_SetMinorRadius, Q3Disk_GetMinorRadius}};
        s.sets = {{"diskAttributeSet", &Data::diskAttributeSet, nullptr, nullptr}};
        s.own = &Data::diskAttributeSet;
        s.parameters = {{"uMin", &Data::uMin}, {"uMax", &Data::uMax}, {"vMin", &Data::vMin}, {"vMax", &Data::vMax}};
        s.sample = Data{{0, 0, 1}, {2, 0, 0}, {0, 1, 0}, 0, 1, 0, 1, nullptr};
        return s;
    }
};

using DiskApiTest = QuadricApiTest<DiskTraits>;
Q3_QUADRIC_API_TESTS(DiskApiTest)

TEST_F(DiskApiTest, AHoleAndASectorAreDrawn)
{
    Data data = shape().sample;
    data.vMin = 0.5f;
    data.uMin = 0.25f;
    data.uMax = 0.75f;
    TQ3GeometryObject disk = make(data);
    TQ3BoundingBox box{};
    const std::vector<TQ3Point3D> points = decomposedPoints(disk, box);
    ASSERT_FALSE(points.empty());
    for (const TQ3Point3D& p : points) {
        const double r = std::hypot(p.x / 2.0, p.y);
        EXPECT_GE(r, 0.5 - 1e-5);
        EXPECT_LE(r, 1 + 1e-5);
        EXPECT_LE(p.x, 1e-5f) << "u from 1/4 to 3/4 turn keeps the half where x <= 0";
        EXPECT_FLOAT_EQ(p.z, 1);
    }
}

} // namespace
