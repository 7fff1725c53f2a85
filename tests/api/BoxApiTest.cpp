// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QuadricApiTestSupport.h"

#include "RenderTestSupport.h"

namespace {

using namespace q3test;

bool sameBox(const TQ3BoxData& a, const TQ3BoxData& b)
{
    const std::size_t geometry = offsetof(TQ3BoxData, faceAttributeSet);
    if (std::memcmp(&a, &b, geometry) != 0 || a.boxAttributeSet != b.boxAttributeSet)
        return false;
    if ((a.faceAttributeSet == nullptr) != (b.faceAttributeSet == nullptr))
        return false;
    return a.faceAttributeSet == nullptr ||
           std::memcmp(a.faceAttributeSet, b.faceAttributeSet, 6 * sizeof(TQ3AttributeSet)) == 0;
}

struct BoxTraits {
    using Data = TQ3BoxData;
    static Shape<Data> shape()
    {
        Shape<Data> s;
        s.name = "box";
        s.type = kQ3GeometryTypeBox;
        s.create = Q3Box_New;
        s.submit = Q3Box_Submit;
        s.setData = Q3Box_SetData;
        s.getData = Q3Box_GetData;
        s.emptyData = Q3Box_EmptyData;
        s.setOrigin = Q3Box_SetOrigin;
        s.getOrigin = Q3Box_GetOrigin;
        s.origin = &Data::origin;
        s.vectors = {{"orientation", &Data::orientation, Q3Box_SetOrientation, Q3Box_GetOrientation},
                     {"majorAxis", &Data::majorAxis, Q3Box_SetMajorAxis, Q3Box_GetMajorAxis},
                     {"minorAxis", &Data::minorAxis, Q3Box_SetMinorAxis, Q3Box_GetMinorAxis}};
        s.sets = {{"boxAttributeSet", &Data::boxAttributeSet, nullptr, nullptr}};
        s.own = &Data::boxAttributeSet;
        s.sample = Data{{-1, -1, -1}, {0, 0, 2}, {2, 0, 0}, {0, 2, 0}, nullptr, nullptr};
        s.same = sameBox;
        return s;
    }
};

using BoxApiTest = QuadricApiTest<BoxTraits>;
Q3_QUADRIC_API_TESTS(BoxApiTest)

// Face indices: the last valid one plus one, UINT32_MAX, and the largest
// unsigned long (which a narrowing to int would turn into -1).
const unsigned long kBadFaces[] = {6, std::numeric_limits<std::uint32_t>::max(),
                                   std::numeric_limits<unsigned long>::max()};

TEST_F(BoxApiTest, TheBoxIsTheParallelepipedOfItsEdges)
{
    Data data = shape().sample;
    data.majorAxis = {2, 0.5f, 0};
    TQ3GeometryObject box = make(data);
    const TQ3BoundingBox bounds = boundsOf([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(box, v), kQ3Success); });
    EXPECT_FLOAT_EQ(bounds.min.x, -1);
    EXPECT_FLOAT_EQ(bounds.max.x, 1);
    EXPECT_FLOAT_EQ(bounds.min.y, -1);
    EXPECT_FLOAT_EQ(bounds.max.y, 1.5f);
    EXPECT_FLOAT_EQ(bounds.min.z, -1);
    EXPECT_FLOAT_EQ(bounds.max.z, 1);
}

TEST_F(BoxApiTest, NewTakesSixFaceSetsAndGetDataCopiesThem)
{
    TQ3AttributeSet faces[6] = {own(Q3AttributeSet_New()), nullptr, own(Q3AttributeSet_New()), nullptr, nullptr,
                                own(Q3AttributeSet_New())};
    Data data = shape().sample;
    data.faceAttributeSet = faces;
    TQ3GeometryObject box = Q3Box_New(&data);
    ASSERT_NE(box, nullptr);
    EXPECT_EQ(Q3Shared_IsReferenced(faces[0]), kQ3True);
    Data out = dataOf(box);
    Q3Object_Dispose(box);
    ASSERT_NE(out.faceAttributeSet, nullptr);
    EXPECT_NE(out.faceAttributeSet, faces);
    for (int i = 0; i < 6; ++i)
        EXPECT_EQ(out.faceAttributeSet[i], faces[i]) << "face " << i;
    ASSERT_EQ(Q3Box_EmptyData(&out), kQ3Success);
    EXPECT_EQ(out.faceAttributeSet, nullptr);
    EXPECT_EQ(Q3Shared_IsReferenced(faces[0]), kQ3False);
    EXPECT_EQ(Q3Box_EmptyData(&out), kQ3Success);

    faces[4] = wrongClass();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Box_New(&data), nullptr), kQ3ErrorInvalidObjectType);
    faces[4] = stray();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Box_New(&data), nullptr), kQ3ErrorInvalidObject);
    EXPECT_NE(std::string(Q3Error_GetMessage()).find("faceAttributeSet[4]"), std::string::npos);
}

TEST_F(BoxApiTest, FaceAttributeSetsAreReadAndReplacedByIndex)
{
    TQ3GeometryObject box = make(shape().sample);
    TQ3AttributeSet got = stray();
    for (unsigned long face : {0UL, 5UL}) {
        ASSERT_EQ(Q3Box_GetFaceAttributeSet(box, face, &got), kQ3Success);
        EXPECT_EQ(got, nullptr) << "a box without face sets has none";
    }
    TQ3AttributeSet left = own(Q3AttributeSet_New());
    TQ3AttributeSet bottom = own(Q3AttributeSet_New());
    unsigned long before = Q3Shared_GetEditIndex(box);
    ASSERT_EQ(Q3Box_SetFaceAttributeSet(box, 0, left), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(box), before);
    ASSERT_EQ(Q3Box_SetFaceAttributeSet(box, 5, bottom), kQ3Success);
    ASSERT_EQ(Q3Box_GetFaceAttributeSet(box, 0, &got), kQ3Success);
    EXPECT_EQ(got, left);
    Q3Object_Dispose(got);
    ASSERT_EQ(Q3Box_GetFaceAttributeSet(box, 5, &got), kQ3Success);
    EXPECT_EQ(got, bottom);
    Q3Object_Dispose(got);
    ASSERT_EQ(Q3Box_GetFaceAttributeSet(box, 3, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    Data out = dataOf(box);
    ASSERT_NE(out.faceAttributeSet, nullptr);
    EXPECT_EQ(out.faceAttributeSet[0], left);
    EXPECT_EQ(out.faceAttributeSet[5], bottom);
    Q3Box_EmptyData(&out);

    State state = stateOf(box);
    for (unsigned long face : kBadFaces) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Box_GetFaceAttributeSet(box, face, &got), kQ3Failure), kQ3ErrorParameterOutOfRange);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Box_SetFaceAttributeSet(box, face, left), kQ3Failure), kQ3ErrorParameterOutOfRange);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Box_GetFaceAttributeSet(nullptr, 0, &got), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Box_GetFaceAttributeSet(box, 0, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Box_GetFaceAttributeSet(wrongClass(), 0, &got), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Box_GetFaceAttributeSet(disposed(), 0, &got), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Box_SetFaceAttributeSet(nullptr, 0, left), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Box_SetFaceAttributeSet(wrongClass(), 0, left), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Box_SetFaceAttributeSet(disposed(), 0, left), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Box_SetFaceAttributeSet(box, 2, wrongClass()), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Box_SetFaceAttributeSet(box, 2, stray()), kQ3Failure), kQ3ErrorInvalidObject);
    expectUnchanged(box, state, "SetFaceAttributeSet");
    Q3Box_EmptyData(&state.data);

    ASSERT_EQ(Q3Box_SetFaceAttributeSet(box, 0, nullptr), kQ3Success);
    ASSERT_EQ(Q3Box_SetFaceAttributeSet(box, 5, nullptr), kQ3Success);
    EXPECT_EQ(Q3Shared_IsReferenced(left), kQ3False);
    EXPECT_EQ(Q3Shared_IsReferenced(bottom), kQ3False);
}

TEST_F(BoxApiTest, DuplicateCopiesTheFaceSetsDeeplyKeepingSharing)
{
    TQ3AttributeSet shared = own(Q3AttributeSet_New());
    TQ3AttributeSet single = own(Q3AttributeSet_New());
    TQ3AttributeSet faces[6] = {shared, nullptr, shared, single, nullptr, nullptr};
    Data data = shape().sample;
    data.faceAttributeSet = faces;
    data.boxAttributeSet = shared;
    TQ3GeometryObject box = make(data);
    TQ3GeometryObject copy = own(static_cast<TQ3GeometryObject>(Q3Object_Duplicate(box)));
    ASSERT_NE(copy, nullptr);
    Data out = dataOf(copy);
    ASSERT_NE(out.faceAttributeSet, nullptr);
    EXPECT_NE(out.faceAttributeSet[0], nullptr);
    EXPECT_NE(out.faceAttributeSet[0], shared);
    EXPECT_EQ(out.faceAttributeSet[2], out.faceAttributeSet[0]);
    EXPECT_EQ(out.boxAttributeSet, out.faceAttributeSet[0]);
    EXPECT_NE(out.faceAttributeSet[3], nullptr);
    EXPECT_NE(out.faceAttributeSet[3], single);
    EXPECT_NE(out.faceAttributeSet[3], out.faceAttributeSet[0]);
    EXPECT_EQ(out.faceAttributeSet[1], nullptr);
    // The copy's sets are its own: editing them leaves the original's alone.
    const TQ3ColorRGB red{1, 0, 0};
    Q3AttributeSet_Add(out.faceAttributeSet[3], kQ3AttributeTypeDiffuseColor, &red);
    EXPECT_EQ(Q3AttributeSet_Contains(single, kQ3AttributeTypeDiffuseColor), kQ3False);
    Q3Box_EmptyData(&out);
}

// The six faces in their own colours through the box's: the box seen from
// the front (its orientation up, its major axis towards the camera).
TEST_F(BoxApiTest, EachFaceIsDrawnInItsSetsColour)
{
    auto colorSet = [&](float r, float g, float b) {
        TQ3AttributeSet set = own(Q3AttributeSet_New());
        const TQ3ColorRGB color{r, g, b};
        Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color);
        return set;
    };
    TQ3AttributeSet faces[6] = {colorSet(1, 0, 0), colorSet(0, 1, 0), colorSet(0, 0, 1),
                                colorSet(1, 1, 0), colorSet(1, 0, 1), colorSet(0, 1, 1)};
    // Front (face 2, blue) towards the listing camera at z = 10: the major
    // axis along +z, the minor along -x, orientation along +y.
    Data data{{2.5f, -0.5f, -1.0f}, {0, 2, 0}, {0, 0, 1}, {-2, 0, 0}, faces, colorSet(1, 1, 1)};
    Pixmap image(200, 150);
    TestView view(image.pixmap());
    ASSERT_EQ(view.render([&](TQ3ViewObject v) { EXPECT_EQ(Q3Box_Submit(&data, v), kQ3Success); }), kQ3ViewStatusDone);
    const Rgba centre = image.at(100, 75);
    EXPECT_EQ(centre.r, 0);
    EXPECT_EQ(centre.g, 0);
    EXPECT_EQ(centre.b, 255);
}

} // namespace
