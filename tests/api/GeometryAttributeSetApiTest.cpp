// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Q3Geometry_GetAttributeSet and Q3Geometry_SetAttributeSet on every kind of
// geometry Q3 has, and what a changed attribute set does downstream: the
// decomposed curve carries it, the renderer draws with it.

#include "OwningApiTest.h"
#include "RenderTestSupport.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DTransform.h"

#include <functional>
#include <string>
#include <vector>

namespace {

using namespace q3test;

TQ3AttributeSet colorSet(float r, float g, float b)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB color{r, g, b};
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color);
    return set;
}

class GeometryAttributeSetApiTest : public OwningApiTest {
protected:
    // One geometry of every kind, each made with `attributes` (may be NULL)
    // as its own attribute set, and a way to read that set through GetData.
    struct Kind {
        std::string name;
        std::function<TQ3GeometryObject(TQ3AttributeSet)> make;
        std::function<TQ3AttributeSet(TQ3GeometryObject)> setFromGetData;
    };

    std::vector<Kind> kinds()
    {
        return {
            {"NURB curve",
             [this](TQ3AttributeSet attributes) {
                 const TQ3NURBCurveData data = m_listing.data(attributes);
                 return Q3NURBCurve_New(&data);
             },
             [](TQ3GeometryObject geometry) {
                 TQ3NURBCurveData data{};
                 EXPECT_EQ(Q3NURBCurve_GetData(geometry, &data), kQ3Success);
                 const TQ3AttributeSet set = data.curveAttributeSet;
                 EXPECT_EQ(Q3NURBCurve_EmptyData(&data), kQ3Success);
                 return set;
             }},
            {"polyline",
             [this](TQ3AttributeSet attributes) {
                 const TQ3PolyLineData data{2, m_vertices, nullptr, attributes};
                 return Q3PolyLine_New(&data);
             },
             [](TQ3GeometryObject geometry) {
                 TQ3PolyLineData data{};
                 EXPECT_EQ(Q3PolyLine_GetData(geometry, &data), kQ3Success);
                 const TQ3AttributeSet set = data.polyLineAttributeSet;
                 EXPECT_EQ(Q3PolyLine_EmptyData(&data), kQ3Success);
                 return set;
             }},
            {"line",
             [this](TQ3AttributeSet attributes) {
                 const TQ3LineData data{{m_vertices[0], m_vertices[1]}, attributes};
                 return Q3Line_New(&data);
             },
             [](TQ3GeometryObject geometry) {
                 TQ3LineData data{};
                 EXPECT_EQ(Q3Line_GetData(geometry, &data), kQ3Success);
                 const TQ3AttributeSet set = data.lineAttributeSet;
                 EXPECT_EQ(Q3Line_EmptyData(&data), kQ3Success);
                 return set;
             }},
            {"point",
             [this](TQ3AttributeSet attributes) {
                 const TQ3PointData data{m_vertices[0].point, attributes};
                 return Q3Point_New(&data);
             },
             [](TQ3GeometryObject geometry) {
                 TQ3PointData data{};
                 EXPECT_EQ(Q3Point_GetData(geometry, &data), kQ3Success);
                 const TQ3AttributeSet set = data.pointAttributeSet;
                 EXPECT_EQ(Q3Point_EmptyData(&data), kQ3Success);
                 return set;
             }},
        };
    }

    Listing1 m_listing;
    TQ3Vertex3D m_vertices[2] = {{{0, 0, 0}, nullptr}, {{1, 1, 0}, nullptr}};
};

TEST_F(GeometryAttributeSetApiTest, GetReturnsTheSetTheDataNamedOrNull)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    for (const Kind& kind : kinds()) {
        SCOPED_TRACE(kind.name);
        TQ3GeometryObject with = own(kind.make(set));
        TQ3GeometryObject without = own(kind.make(nullptr));
        ASSERT_NE(with, nullptr);
        ASSERT_NE(without, nullptr);
        TQ3AttributeSet got = set;
        ASSERT_EQ(Q3Geometry_GetAttributeSet(without, &got), kQ3Success);
        EXPECT_EQ(got, nullptr); // none is NULL, and still a success
        ASSERT_EQ(Q3Geometry_GetAttributeSet(with, &got), kQ3Success);
        EXPECT_EQ(got, set);
        Q3Object_Dispose(got); // Get handed out a reference of the caller's own
    }
}

TEST_F(GeometryAttributeSetApiTest, SetReplacesTheSetGetDataSeesAndBumpsTheEditIndex)
{
    for (const Kind& kind : kinds()) {
        SCOPED_TRACE(kind.name);
        TQ3AttributeSet first = colorSet(1, 0, 0);
        TQ3AttributeSet second = colorSet(0, 1, 0);
        TQ3GeometryObject geometry = kind.make(first);
        ASSERT_NE(geometry, nullptr);

        unsigned long edit = Q3Shared_GetEditIndex(geometry);
        EXPECT_EQ(Q3Geometry_SetAttributeSet(geometry, second), kQ3Success);
        EXPECT_NE(Q3Shared_GetEditIndex(geometry), edit);
        EXPECT_EQ(Q3Shared_IsReferenced(first), kQ3False); // the geometry let go of it
        EXPECT_EQ(kind.setFromGetData(geometry), second);
        TQ3AttributeSet got = nullptr;
        ASSERT_EQ(Q3Geometry_GetAttributeSet(geometry, &got), kQ3Success);
        EXPECT_EQ(got, second);
        Q3Object_Dispose(got);
        EXPECT_EQ(Q3Geometry_SetAttributeSet(geometry, second), kQ3Success); // same set again

        edit = Q3Shared_GetEditIndex(geometry);
        EXPECT_EQ(Q3Geometry_SetAttributeSet(geometry, nullptr), kQ3Success);
        EXPECT_NE(Q3Shared_GetEditIndex(geometry), edit);
        EXPECT_EQ(kind.setFromGetData(geometry), nullptr);
        EXPECT_EQ(Q3Shared_IsReferenced(second), kQ3False);

        EXPECT_EQ(Q3Geometry_SetAttributeSet(geometry, second), kQ3Success);
        EXPECT_EQ(Q3Shared_IsReferenced(second), kQ3True);
        Q3Object_Dispose(geometry);
        EXPECT_EQ(Q3Shared_IsReferenced(second), kQ3False); // one reference held, no more
        Q3Object_Dispose(first);
        Q3Object_Dispose(second);
    }
}

TEST_F(GeometryAttributeSetApiTest, FailedSetChangesNothing)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    const TQ3Vector3D offset{1, 1, 1};
    TQ3TransformObject notASet = own(Q3TranslateTransform_New(&offset));
    int notAnObject = 0;
    TQ3AttributeSet stray = reinterpret_cast<TQ3AttributeSet>(&notAnObject);
    for (const Kind& kind : kinds()) {
        SCOPED_TRACE(kind.name);
        TQ3GeometryObject geometry = own(kind.make(set));
        ASSERT_NE(geometry, nullptr);
        const unsigned long edit = Q3Shared_GetEditIndex(geometry);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_SetAttributeSet(geometry, notASet), kQ3Failure),
                        kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_SetAttributeSet(geometry, geometry), kQ3Failure),
                        kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_SetAttributeSet(geometry, stray), kQ3Failure),
                        kQ3ErrorInvalidObject);
        EXPECT_EQ(Q3Shared_GetEditIndex(geometry), edit);
        EXPECT_EQ(kind.setFromGetData(geometry), set);
    }
}

TEST_F(GeometryAttributeSetApiTest, BadGeometriesAndNullOutputsAreReported)
{
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    const TQ3Vector3D offset{1, 1, 1};
    TQ3TransformObject notAGeometry = own(Q3TranslateTransform_New(&offset));
    int notAnObject = 0;
    TQ3GeometryObject stray = reinterpret_cast<TQ3GeometryObject>(&notAnObject);
    TQ3AttributeSet got = set;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_GetAttributeSet(nullptr, &got), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_SetAttributeSet(nullptr, set), kQ3Failure), kQ3ErrorNULLParameter);
    for (TQ3Object wrong : {notAGeometry, static_cast<TQ3Object>(set), view()}) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_GetAttributeSet(wrong, &got), kQ3Failure),
                        kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_SetAttributeSet(wrong, set), kQ3Failure),
                        kQ3ErrorInvalidObjectType);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_GetAttributeSet(stray, &got), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_SetAttributeSet(stray, set), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_EQ(got, set); // unchanged on failure
    TQ3GeometryObject point = own(kinds().back().make(nullptr));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_GetAttributeSet(point, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    // The geometry is checked before the attribute set.
    EXPECT_Q3_ERROR(Q3Geometry_SetAttributeSet(nullptr, reinterpret_cast<TQ3AttributeSet>(&notAnObject)),
                    kQ3ErrorNULLParameter);
    EXPECT_EQ(Q3Shared_IsReferenced(set), kQ3False); // no failed call kept a reference
}

TEST_F(GeometryAttributeSetApiTest, TheDecomposedCurveCarriesTheNewSet)
{
    TQ3AttributeSet set = own(colorSet(0, 0, 1));
    TQ3GeometryObject curve = own(kinds().front().make(nullptr));
    ASSERT_EQ(Q3Geometry_SetAttributeSet(curve, set), kQ3Success);
    TQ3GeometryObject polyLine = nullptr;
    boundsOf([&](TQ3ViewObject v) {
        if (polyLine == nullptr)
            polyLine = Q3Geometry_GetDecomposed(curve, v);
    });
    ASSERT_NE(polyLine, nullptr);
    own(polyLine);
    TQ3AttributeSet got = nullptr;
    ASSERT_EQ(Q3Geometry_GetAttributeSet(polyLine, &got), kQ3Success);
    EXPECT_EQ(got, set);
    Q3Object_Dispose(got);
}

TEST_F(GeometryAttributeSetApiTest, ColorsSetAfterCreationAreDrawn)
{
    // A polyline made without any attribute set, coloured afterwards: red as
    // a whole, green on its first segment only (segment colours win).
    TQ3AttributeSet red = own(colorSet(1, 0, 0));
    TQ3AttributeSet green = own(colorSet(0, 1, 0));
    TQ3Vertex3D vertices[3] = {{{0, 0, 0}, nullptr}, {{1, 1, 0}, nullptr}, {{2, 0, 0}, nullptr}};
    const TQ3PolyLineData data = {3, vertices, nullptr, nullptr};
    TQ3GeometryObject polyLine = own(Q3PolyLine_New(&data));
    ASSERT_EQ(Q3Geometry_SetAttributeSet(polyLine, red), kQ3Success);
    ASSERT_EQ(Q3PolyLine_SetSegmentAttributeSet(polyLine, 0, green), kQ3Success);

    Pixmap image(200, 150);
    {
        TestView testView(image.pixmap());
        const TQ3ViewStatus status =
            testView.render([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(polyLine, v), kQ3Success); });
        EXPECT_EQ(status, kQ3ViewStatusDone);
    }
    const Projection pixelOf = orthographicProjection(0, 0, 200, 150);
    auto colorNear = [&](const Point3& p) { return image.litNear(unsigned(p.x), unsigned(p.y)); };
    const Rgba first = colorNear(pixelOf({0.5, 0.5, 0}));
    const Rgba second = colorNear(pixelOf({1.5, 0.5, 0}));
    EXPECT_EQ(first.g, 255);
    EXPECT_EQ(first.r, 0);
    EXPECT_EQ(second.r, 255);
    EXPECT_EQ(second.g, 0);
}

TEST(GeometryAttributeSetApiUninitialized, BothFunctionsFailWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    TQ3AttributeSet set = nullptr;
    EXPECT_EQ(Q3Geometry_GetAttributeSet(nullptr, &set), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3Geometry_SetAttributeSet(nullptr, nullptr), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
}

} // namespace
