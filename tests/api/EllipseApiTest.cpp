// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QuadricApiTestSupport.h"

namespace {

using namespace q3test;

struct EllipseTraits {
    using Data = TQ3EllipseData;
    static Shape<Data> shape()
    {
        Shape<Data> s;
        s.name = "ellipse";
        s.type = kQ3GeometryTypeEllipse;
        s.create = Q3Ellipse_New;
        s.submit = Q3Ellipse_Submit;
        s.setData = Q3Ellipse_SetData;
        s.getData = Q3Ellipse_GetData;
        s.emptyData = Q3Ellipse_EmptyData;
        s.setOrigin = Q3Ellipse_SetOrigin;
        s.getOrigin = Q3Ellipse_GetOrigin;
        s.origin = &Data::origin;
        s.vectors = {{"majorRadius", &Data::majorRadius, Q3Ellipse_SetMajorRadius, Q3Ellipse_GetMajorRadius},
                     {"minorRadius", &Data::minorRadius, Q3Ellipse_SetMinorRadius, Q3Ellipse_GetMinorRadius}};
        s.sets = {{"ellipseAttributeSet", &Data::ellipseAttributeSet, nullptr, nullptr}};
        s.own = &Data::ellipseAttributeSet;
        s.parameters = {{"uMin", &Data::uMin}, {"uMax", &Data::uMax}};
        s.sample = Data{{1, 1, 0}, {3, 0, 0}, {0, 1, 0}, 0, 1, nullptr};
        s.curve = true;
        return s;
    }
};

using EllipseApiTest = QuadricApiTest<EllipseTraits>;
Q3_QUADRIC_API_TESTS(EllipseApiTest)

TEST_F(EllipseApiTest, ConstantSubdivisionGivesC1SegmentsPerTurn)
{
    Data data = shape().sample;
    data.uMin = 0.75f;
    data.uMax = 0.25f; // half a turn through u = 0
    TQ3GeometryObject ellipse = make(data);
    const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodConstant, 12, 1};
    ASSERT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
    EXPECT_EQ(Q3SubdivisionStyle_Submit(&style, view()), kQ3Success);
    TQ3GeometryObject line = Q3Geometry_GetDecomposed(ellipse, view());
    TQ3BoundingBox box;
    EXPECT_EQ(Q3View_EndBoundingBox(view(), &box), kQ3ViewStatusDone);
    ASSERT_NE(line, nullptr);
    TQ3PolyLineData out{};
    ASSERT_EQ(Q3PolyLine_GetData(line, &out), kQ3Success);
    ASSERT_EQ(out.numVertices, 7u);
    for (unsigned long i = 0; i < out.numVertices; ++i) {
        const double angle = 2 * 3.14159265358979 * (0.75 + 0.5 * double(i) / 6);
        EXPECT_NEAR(out.vertices[i].point.x, 1 + 3 * std::cos(angle), 1e-5);
        EXPECT_NEAR(out.vertices[i].point.y, 1 + std::sin(angle), 1e-5);
    }
    Q3PolyLine_EmptyData(&out);
    Q3Object_Dispose(line);
}

} // namespace
