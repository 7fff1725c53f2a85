// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Drawing display groups: the state saved around a group and leaked by an
// inline one, IsDrawn, the ordered group's order, the I/O proxy's first
// representation, culling by a group's bounding box, the nesting limit, and
// push / pop state operators met in groups. Each check reads pixels where a
// shape must or must not be, placed by the test's own projection of the
// orthographic camera (RenderTestSupport.h).

#include "RenderTestSupport.h"

#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DSet.h"
#include "QD3DTransform.h"

#include <memory>
#include <vector>

namespace {

using namespace q3test;

constexpr int kWidth = 80;
constexpr int kHeight = 60;

class GroupRenderTest : public Q3ApiTest {
protected:
    void SetUp() override
    {
        Q3ApiTest::SetUp();
        m_view = std::make_unique<TestView>(m_image.pixmap());
    }
    void TearDown() override
    {
        for (TQ3Object object : m_owned)
            Q3Object_Dispose(object);
        m_view.reset();
        Q3ApiTest::TearDown();
    }

    template <class T>
    T own(T object)
    {
        m_owned.push_back(object);
        return object;
    }

    TQ3ViewObject view() const { return m_view->view(); }

    /// A square of side 0.5 centred on (x, y), in one colour, as two
    /// triangles in a display group the caller may add to other groups.
    TQ3GroupObject square(float x, float y, TQ3ColorRGB color)
    {
        TQ3AttributeSet set = own(Q3AttributeSet_New());
        Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color);
        TQ3GroupObject group = own(Q3DisplayGroup_New());
        const float h = 0.25f;
        const TQ3Point3D corners[4] = {{x - h, y - h, 0}, {x + h, y - h, 0}, {x + h, y + h, 0}, {x - h, y + h, 0}};
        const int triangles[2][3] = {{0, 1, 2}, {0, 2, 3}};
        for (const auto& t : triangles) {
            TQ3TriangleData data{};
            for (int k = 0; k < 3; ++k)
                data.vertices[k].point = corners[t[k]];
            data.triangleAttributeSet = set;
            TQ3GeometryObject triangle = own(Q3Triangle_New(&data));
            Q3Group_AddObject(group, triangle);
        }
        return group;
    }

    TQ3TransformObject translate(float x, float y)
    {
        const TQ3Vector3D offset{x, y, 0};
        return own(Q3TranslateTransform_New(&offset));
    }

    /// The colour drawn at world point (x, y).
    Rgba at(float x, float y) const
    {
        const Point3 p = orthographicProjection(0, 0, kWidth, kHeight)(Point3{x, y, 0});
        return m_image.at((unsigned long)p.x, (unsigned long)p.y);
    }
    static bool isColor(const Rgba& c, int r, int g, int b)
    {
        return std::abs(c.r - r) <= 2 && std::abs(c.g - g) <= 2 && std::abs(c.b - b) <= 2;
    }
    bool red(float x, float y) const { return isColor(at(x, y), 255, 0, 0); }
    bool green(float x, float y) const { return isColor(at(x, y), 0, 255, 0); }
    bool blank(float x, float y) const { return isColor(at(x, y), 0, 0, 0); }

    TQ3ViewStatus render(const std::function<void(TQ3ViewObject)>& submit) { return m_view->render(submit); }

    static constexpr TQ3ColorRGB kRed{1, 0, 0};
    static constexpr TQ3ColorRGB kGreen{0, 1, 0};

    Pixmap m_image{kWidth, kHeight};
    std::unique_ptr<TestView> m_view;
    std::vector<TQ3Object> m_owned;
};

TEST_F(GroupRenderTest, AGroupKeepsItsStateToItselfUnlessInline)
{
    // group { translate +1.5 } then a square at x = 0.5: the translation ends
    // with the group, so the square stays at 0.5.
    TQ3GroupObject group = own(Q3DisplayGroup_New());
    Q3Group_AddObject(group, translate(1.5f, 0));
    TQ3GroupObject thing = square(0.5f, 0.5f, kRed);
    ASSERT_EQ(render([&](TQ3ViewObject v) {
                  Q3DisplayGroup_Submit(group, v);
                  Q3DisplayGroup_Submit(thing, v);
              }),
              kQ3ViewStatusDone);
    EXPECT_TRUE(red(0.5f, 0.5f));
    EXPECT_TRUE(blank(2.0f, 0.5f));

    // Inline, the translation stays in force after the group.
    ASSERT_EQ(Q3DisplayGroup_SetState(group, kQ3DisplayGroupStateMaskIsDrawn | kQ3DisplayGroupStateMaskIsInline),
              kQ3Success);
    ASSERT_EQ(render([&](TQ3ViewObject v) {
                  Q3DisplayGroup_Submit(group, v);
                  Q3DisplayGroup_Submit(thing, v);
              }),
              kQ3ViewStatusDone);
    EXPECT_TRUE(blank(0.5f, 0.5f));
    EXPECT_TRUE(red(2.0f, 0.5f));
}

TEST_F(GroupRenderTest, AttributesSetInAGroupEndWithIt)
{
    // A plain square (no colour of its own) drawn in a group that sets green
    // and again after it: green inside, white (the default) after.
    TQ3AttributeSet greenSet = own(Q3AttributeSet_New());
    Q3AttributeSet_Add(greenSet, kQ3AttributeTypeDiffuseColor, &kGreen);
    TQ3TriangleData data{};
    data.vertices[0].point = {0, 0, 0};
    data.vertices[1].point = {1, 0, 0};
    data.vertices[2].point = {0, 1, 0};
    TQ3GeometryObject triangle = own(Q3Triangle_New(&data));
    TQ3GroupObject group = own(Q3DisplayGroup_New());
    Q3Group_AddObject(group, greenSet);
    Q3Group_AddObject(group, triangle);
    const TQ3Vector3D offset{2, 0, 0};
    ASSERT_EQ(render([&](TQ3ViewObject v) {
                  Q3Object_Submit(group, v);
                  Q3TranslateTransform_Submit(&offset, v);
                  Q3Object_Submit(triangle, v);
              }),
              kQ3ViewStatusDone);
    EXPECT_TRUE(green(0.2f, 0.2f));
    EXPECT_TRUE(isColor(at(2.2f, 0.2f), 255, 255, 255));
}

TEST_F(GroupRenderTest, AGroupThatIsNotDrawnDrawsNothing)
{
    TQ3GroupObject group = square(1.5f, 0.5f, kRed);
    ASSERT_EQ(Q3DisplayGroup_SetState(group, kQ3DisplayGroupStateNone), kQ3Success);
    ASSERT_EQ(render([&](TQ3ViewObject v) { Q3DisplayGroup_Submit(group, v); }), kQ3ViewStatusDone);
    EXPECT_TRUE(blank(1.5f, 0.5f));
}

TEST_F(GroupRenderTest, TheOrderedGroupAppliesTransformsBeforeGeometry)
{
    // The same objects, geometry added before the transform: a plain display
    // group draws the square untransformed, an ordered one translated.
    for (bool ordered : {false, true}) {
        TQ3GroupObject group = own(ordered ? Q3OrderedDisplayGroup_New() : Q3DisplayGroup_New());
        Q3Group_AddObject(group, square(0.5f, 0.5f, kRed));
        Q3Group_AddObject(group, translate(2.0f, 0));
        ASSERT_EQ(render([&](TQ3ViewObject v) { Q3Object_Submit(group, v); }), kQ3ViewStatusDone);
        EXPECT_EQ(red(0.5f, 0.5f), !ordered) << ordered;
        EXPECT_EQ(red(2.5f, 0.5f), ordered) << ordered;
    }
}

TEST_F(GroupRenderTest, TheIOProxyDrawsItsFirstRepresentationOnly)
{
    TQ3GroupObject proxy = own(Q3IOProxyDisplayGroup_New());
    Q3Group_AddObject(proxy, square(0.5f, 0.5f, kRed));
    Q3Group_AddObject(proxy, square(2.5f, 0.5f, kGreen));
    ASSERT_EQ(render([&](TQ3ViewObject v) { Q3Object_Submit(proxy, v); }), kQ3ViewStatusDone);
    EXPECT_TRUE(red(0.5f, 0.5f));
    EXPECT_TRUE(blank(2.5f, 0.5f));
}

TEST_F(GroupRenderTest, AGroupOutsideTheViewByItsBoxIsCulledUnlessCullingIsOff)
{
    // The box says "far to the right" although the square is in view: a
    // group that uses its box is judged by it.
    TQ3GroupObject group = square(1.5f, 0.5f, kRed);
    TQ3BoundingBox box{{50, 0, -1}, {51, 1, 1}, kQ3False};
    ASSERT_EQ(Q3DisplayGroup_SetAndUseBoundingBox(group, &box), kQ3Success);
    ASSERT_EQ(render([&](TQ3ViewObject v) { Q3Object_Submit(group, v); }), kQ3ViewStatusDone);
    EXPECT_TRUE(blank(1.5f, 0.5f));

    ASSERT_EQ(Q3View_AllowAllGroupCulling(view(), kQ3False), kQ3Success);
    ASSERT_EQ(render([&](TQ3ViewObject v) { Q3Object_Submit(group, v); }), kQ3ViewStatusDone);
    EXPECT_TRUE(red(1.5f, 0.5f));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_AllowAllGroupCulling(view(), TQ3Boolean(7)), kQ3Failure),
                    kQ3ErrorInvalidParameter);

    // A box in view draws the group; without the UseBoundingBox bit the box
    // is ignored.
    ASSERT_EQ(Q3View_AllowAllGroupCulling(view(), kQ3True), kQ3Success);
    ASSERT_EQ(Q3DisplayGroup_SetState(group, kQ3DisplayGroupStateMaskIsDrawn), kQ3Success);
    ASSERT_EQ(render([&](TQ3ViewObject v) { Q3Object_Submit(group, v); }), kQ3ViewStatusDone);
    EXPECT_TRUE(red(1.5f, 0.5f));
}

TEST_F(GroupRenderTest, BoundingLoopsUseAGroupsBoxAndRestoreItsTransform)
{
    TQ3GroupObject group = own(Q3DisplayGroup_New());
    Q3Group_AddObject(group, translate(10, 0));
    Q3Group_AddObject(group, square(0, 0, kRed));
    TQ3GroupObject after = square(0, 0, kGreen);
    TQ3BoundingBox result{};
    ASSERT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
    Q3Object_Submit(group, view());
    Q3Object_Submit(after, view());
    ASSERT_EQ(Q3View_EndBoundingBox(view(), &result), kQ3ViewStatusDone);
    EXPECT_FLOAT_EQ(result.min.x, -0.25f);
    EXPECT_FLOAT_EQ(result.max.x, 10.25f);

    // With a box it uses, the group counts as its box.
    TQ3BoundingBox box{{-5, -5, -5}, {-4, -4, -4}, kQ3False};
    Q3DisplayGroup_SetAndUseBoundingBox(group, &box);
    ASSERT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
    Q3Object_Submit(group, view());
    ASSERT_EQ(Q3View_EndBoundingBox(view(), &result), kQ3ViewStatusDone);
    EXPECT_FLOAT_EQ(result.min.x, -5.0f);
    EXPECT_FLOAT_EQ(result.max.x, -4.0f);
}

TEST_F(GroupRenderTest, GroupsNestUpToTheLimitAndNoDeeper)
{
    auto chain = [&](int depth) {
        TQ3GroupObject top = own(Q3DisplayGroup_New());
        TQ3GroupObject current = top;
        for (int i = 1; i < depth; ++i) {
            TQ3GroupObject next = own(Q3DisplayGroup_New());
            Q3Group_AddObject(current, next);
            current = next;
        }
        Q3Group_AddObject(current, square(1.5f, 0.5f, kRed));
        return top;
    };
    // The square's own group is one more level.
    TQ3GroupObject deepest = chain(kQ3GroupMaxNesting - 1);
    ASSERT_EQ(render([&](TQ3ViewObject v) { EXPECT_EQ(Q3Object_Submit(deepest, v), kQ3Success); }),
              kQ3ViewStatusDone);
    EXPECT_TRUE(red(1.5f, 0.5f));

    TQ3GroupObject tooDeep = chain(kQ3GroupMaxNesting);
    ASSERT_EQ(render([&](TQ3ViewObject v) {
                  EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_Submit(tooDeep, v), kQ3Failure), kQ3ErrorInvalidObject);
              }),
              kQ3ViewStatusDone);
    EXPECT_TRUE(blank(1.5f, 0.5f));
}

TEST_F(GroupRenderTest, StateOperatorsPushAndPopLikeTheSubmitCalls)
{
    TQ3StateOperatorObject push = own(Q3Push_New());
    TQ3StateOperatorObject pop = own(Q3Pop_New());
    ASSERT_NE(push, nullptr);
    ASSERT_NE(pop, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(push), kQ3StateOperatorTypePush);
    EXPECT_EQ(Q3Object_GetLeafType(pop), kQ3StateOperatorTypePop);
    EXPECT_EQ(Q3Shape_GetType(push), kQ3ShapeTypeStateOperator);

    // Inline group: push, translate, square, pop, square: the second square
    // is back at the origin's place.
    TQ3GroupObject group = own(Q3DisplayGroup_New());
    Q3DisplayGroup_SetState(group, kQ3DisplayGroupStateMaskIsDrawn | kQ3DisplayGroupStateMaskIsInline);
    Q3Group_AddObject(group, push);
    Q3Group_AddObject(group, translate(2, 0));
    Q3Group_AddObject(group, square(0.5f, 0.5f, kRed));
    Q3Group_AddObject(group, pop);
    Q3Group_AddObject(group, square(0.5f, -0.5f, kGreen));
    ASSERT_EQ(render([&](TQ3ViewObject v) { Q3Object_Submit(group, v); }), kQ3ViewStatusDone);
    EXPECT_TRUE(red(2.5f, 0.5f));
    EXPECT_TRUE(blank(0.5f, 0.5f));
    EXPECT_TRUE(green(0.5f, -0.5f));

    // Submitted directly, with the local-to-world matrix read back.
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    ASSERT_EQ(Q3StateOperator_Submit(push, view()), kQ3Success);
    Q3Object_Submit(translate(3, 0), view());
    TQ3Matrix4x4 m{};
    Q3View_GetLocalToWorldMatrixState(view(), &m);
    EXPECT_EQ(m.value[3][0], 3.0f);
    ASSERT_EQ(Q3StateOperator_Submit(pop, view()), kQ3Success);
    Q3View_GetLocalToWorldMatrixState(view(), &m);
    EXPECT_EQ(m.value[3][0], 0.0f);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3StateOperator_Submit(pop, view()), kQ3Failure), kQ3ErrorNothingToPop);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3StateOperator_Submit(group, view()), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3StateOperator_Submit(push, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3StateOperator_Submit(nullptr, view()), kQ3Failure), kQ3ErrorNULLParameter);

    TQ3Object copy = Q3Object_Duplicate(pop);
    EXPECT_EQ(Q3Object_GetLeafType(copy), kQ3StateOperatorTypePop);
    Q3Object_Dispose(copy);
}

TEST_F(GroupRenderTest, AGroupsObjectsCannotPopWhatWasPushedBeforeIt)
{
    // Push outside, then a group that pops twice: the second pop would
    // reach the state pushed before the group, so it fails and the group's
    // submit reports it; the outer push is still there afterwards.
    TQ3GroupObject group = own(Q3DisplayGroup_New());
    TQ3StateOperatorObject push = own(Q3Push_New());
    TQ3StateOperatorObject pop = own(Q3Pop_New());
    Q3Group_AddObject(group, push);
    Q3Group_AddObject(group, pop);
    Q3Group_AddObject(group, pop);
    // Unmatched pushes inside a group end with it.
    TQ3GroupObject leaky = own(Q3DisplayGroup_New());
    Q3Group_AddObject(leaky, push);
    Q3Group_AddObject(leaky, push);
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    ASSERT_EQ(Q3Push_Submit(view()), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_Submit(group, view()), kQ3Failure), kQ3ErrorNothingToPop);
    EXPECT_EQ(Q3Object_Submit(leaky, view()), kQ3Success);
    EXPECT_EQ(Q3Pop_Submit(view()), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Pop_Submit(view()), kQ3Failure), kQ3ErrorNothingToPop);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
}

} // namespace
