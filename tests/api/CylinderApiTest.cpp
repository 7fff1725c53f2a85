// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QuadricApiTestSupport.h"

#include "RenderTestSupport.h"

namespace {

using namespace q3test;

struct CylinderTraits {
    using Data = TQ3CylinderData;
    static Shape<Data> shape()
    {
        Shape<Data> s;
        s.name = "cylinder";
        s.type = kQ3GeometryTypeCylinder;
        s.create = Q3Cylinder_New;
        s.submit = Q3Cylinder_Submit;
        s.setData = Q3Cylinder_SetData;
        s.getData = Q3Cylinder_GetData;
        s.emptyData = Q3Cylinder_EmptyData;
        s.setOrigin = Q3Cylinder_SetOrigin;
        s.getOrigin = Q3Cylinder_GetOrigin;
        s.origin = &Data::origin;
        s.vectors = {{"orientation", &Data::orientation, Q3Cylinder_SetOrientation, Q3Cylinder_GetOrientation},
                     {"majorRadius", &Data::majorRadius, Q3Cylinder_SetMajorRadius, Q3Cylinder_GetMajorRadius},
                     {"minorRadius", &Data::minorRadius, Q3Cylinder_SetMinorRadius, Q3Cylinder_GetMinorRadius}};
        s.sets = {
            {"interiorAttributeSet", &Data::interiorAttributeSet, nullptr, nullptr},
            {"topAttributeSet", &Data::topAttributeSet, Q3Cylinder_SetTopAttributeSet, Q3Cylinder_GetTopAttributeSet},
            {"faceAttributeSet", &Data::faceAttributeSet, Q3Cylinder_SetFaceAttributeSet,
             Q3Cylinder_GetFaceAttributeSet},
            {"bottomAttributeSet", &Data::bottomAttributeSet, Q3Cylinder_SetBottomAttributeSet,
             Q3Cylinder_GetBottomAttributeSet},
            {"cylinderAttributeSet", &Data::cylinderAttributeSet, nullptr, nullptr}};
        s.own = &Data::cylinderAttributeSet;
        s.parameters = {{"uMin", &Data::uMin}, {"uMax", &Data::uMax}, {"vMin", &Data::vMin}, {"vMax", &Data::vMax}};
        s.sample =
            Data{{0, -1, 0}, {0, 2, 0}, {1, 0, 0}, {0, 0, 1}, 0,      1, 0, 1, kQ3EndCapMaskTop | kQ3EndCapMaskBottom,
                 nullptr,    nullptr,   nullptr,   nullptr,   nullptr};
        return s;
    }
};

using CylinderApiTest = QuadricApiTest<CylinderTraits>;
Q3_QUADRIC_API_TESTS(CylinderApiTest)

TEST_F(CylinderApiTest, CapsReadBackAndOnlyEndCapMasksAreAccepted)
{
    TQ3GeometryObject cylinder = make(shape().sample);
    TQ3EndCap caps = 0;
    ASSERT_EQ(Q3Cylinder_GetCaps(cylinder, &caps), kQ3Success);
    EXPECT_EQ(caps, TQ3EndCap(kQ3EndCapMaskTop | kQ3EndCapMaskBottom));
    ASSERT_EQ(Q3Cylinder_SetCaps(cylinder, kQ3EndCapNone), kQ3Success);
    ASSERT_EQ(Q3Cylinder_GetCaps(cylinder, &caps), kQ3Success);
    EXPECT_EQ(caps, TQ3EndCap(kQ3EndCapNone));
    State state = stateOf(cylinder);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Cylinder_SetCaps(cylinder, 8), kQ3Failure), kQ3ErrorInvalidData);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Cylinder_SetCaps(nullptr, 0), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Cylinder_SetCaps(wrongClass(), 0), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Cylinder_GetCaps(cylinder, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Cylinder_GetCaps(disposed(), &caps), kQ3Failure), kQ3ErrorInvalidObject);
    expectUnchanged(cylinder, state, "SetCaps");
    Q3Cylinder_EmptyData(&state.data);
}

// Top, bottom and side in their own sets' colours, the side's set over the
// cylinder's: seen from above at an angle, the top and the side show.
TEST_F(CylinderApiTest, EachPartIsDrawnInItsOwnSetsColour)
{
    auto colorSet = [&](float r, float g, float b) {
        TQ3AttributeSet set = own(Q3AttributeSet_New());
        const TQ3ColorRGB color{r, g, b};
        Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color);
        return set;
    };
    Data data = shape().sample;
    data.origin = {1.5f, 0.5f, -1.0f};
    data.orientation = {0, 0, 1.0f};
    data.majorRadius = {0.8f, 0, 0};
    data.minorRadius = {0, 0.8f, 0};
    data.topAttributeSet = colorSet(1, 0, 0);
    data.faceAttributeSet = colorSet(0, 1, 0);
    data.bottomAttributeSet = colorSet(0, 0, 1);
    data.cylinderAttributeSet = colorSet(1, 1, 1);
    Pixmap image(200, 150);
    TestView view(image.pixmap());
    ASSERT_EQ(view.render([&](TQ3ViewObject v) { EXPECT_EQ(Q3Cylinder_Submit(&data, v), kQ3Success); }),
              kQ3ViewStatusDone);
    // The listing camera looks down -z at (1.5, 0.5): the top cap (z = 0)
    // covers the middle; the side is hidden below it.
    const Rgba centre = image.at(100, 75);
    EXPECT_EQ(centre.r, 255);
    EXPECT_EQ(centre.g, 0);
    EXPECT_EQ(centre.b, 0);
}

TEST_F(CylinderApiTest, AStyleAskingForTooManyTrianglesIsCappedWithAWarning)
{
    TQ3GeometryObject cylinder = make(shape().sample);
    const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodConstant, 1024, 1024};
    ASSERT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsApproximate), kQ3Success);
    TQ3GeometryObject mesh = nullptr;
    EXPECT_EQ(Q3SubdivisionStyle_Submit(&style, view()), kQ3Success);
    EXPECT_Q3_WARNING(mesh = Q3Geometry_GetDecomposed(cylinder, view()), kQ3WarningParameterOutOfRange);
    EXPECT_NE(std::string(Q3Warning_GetMessage()).find("kQ3SubdivisionMaxTrianglesPerSurface"), std::string::npos);
    TQ3BoundingBox box;
    EXPECT_EQ(Q3View_EndBoundingBox(view(), &box), kQ3ViewStatusDone);
    ASSERT_NE(mesh, nullptr);
    TQ3TriMeshData data{};
    ASSERT_EQ(Q3TriMesh_GetData(mesh, &data), kQ3Success);
    EXPECT_LE(data.numTriangles, (unsigned long)kQ3SubdivisionMaxTrianglesPerSurface);
    EXPECT_GT(data.numTriangles, (unsigned long)kQ3SubdivisionMaxTrianglesPerSurface / 2);
    Q3TriMesh_EmptyData(&data);
    Q3Object_Dispose(mesh);
}

} // namespace
