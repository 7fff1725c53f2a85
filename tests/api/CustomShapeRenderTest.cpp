// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// QD3DExtension.h's submit methods (Q3 extension, Quesa's names): a custom
// shape whose class submits two triangles draws, bounds and picks exactly
// as the same triangles submitted directly, alone and inside a group; a
// failing submit method fails the submit; a class without the loop's
// method adds nothing.

#include "Q3ApiTest.h"
#include "RenderTestSupport.h"

#include "QD3DExtension.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DPick.h"
#include "QD3DSet.h"
#include "QD3DTransform.h"

#include <memory>

namespace {

using namespace q3test;

constexpr int kWidth = 80;
constexpr int kHeight = 60;

// A square of half-size h centred on (x, y) in one colour.
struct Quad {
    float x, y, h;
    TQ3ColorRGB color;
};

// The square's two triangles, submitted in immediate mode.
TQ3Status submitQuad(const Quad& quad, TQ3ViewObject view)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &quad.color);
    const float x = quad.x, y = quad.y, h = quad.h;
    const TQ3Point3D corners[4] = {{x - h, y - h, 0}, {x + h, y - h, 0}, {x + h, y + h, 0}, {x - h, y + h, 0}};
    const int triangles[2][3] = {{0, 1, 2}, {0, 2, 3}};
    TQ3Status status = kQ3Success;
    for (const auto& t : triangles) {
        TQ3TriangleData data{};
        for (int k = 0; k < 3; ++k)
            data.vertices[k].point = corners[t[k]];
        data.triangleAttributeSet = set;
        if (Q3Triangle_Submit(&data, view) != kQ3Success)
            status = kQ3Failure;
    }
    Q3Object_Dispose(set);
    return status;
}

struct Behaviour {
    bool fail = false;
    int calls = 0;
    TQ3ObjectType typeSeen = 0;
};
Behaviour g_quad;

TQ3Status quadSubmit(TQ3ViewObject view, TQ3ObjectType objectType, TQ3Object, const void* data)
{
    ++g_quad.calls;
    g_quad.typeSeen = objectType;
    if (g_quad.fail)
        return kQ3Failure;
    return submitQuad(*static_cast<const Quad*>(data), view);
}

TQ3Status quadNew(TQ3Object, void* privateData, void* parameters)
{
    *static_cast<Quad*>(privateData) = *static_cast<const Quad*>(parameters);
    return kQ3Success;
}

TQ3XFunctionPointer quadMetaHandler(TQ3XMethodType type)
{
    switch (type) {
    case kQ3XMethodTypeObjectNew:
        return reinterpret_cast<TQ3XFunctionPointer>(quadNew);
    case kQ3XMethodTypeObjectSubmitRender:
    case kQ3XMethodTypeObjectSubmitPick:
    case kQ3XMethodTypeObjectSubmitBounds:
        return reinterpret_cast<TQ3XFunctionPointer>(quadSubmit);
    default:
        return nullptr;
    }
}

// A class with a render method only: it adds nothing to bounds.
TQ3XFunctionPointer renderOnlyMetaHandler(TQ3XMethodType type)
{
    switch (type) {
    case kQ3XMethodTypeObjectNew:
        return reinterpret_cast<TQ3XFunctionPointer>(quadNew);
    case kQ3XMethodTypeObjectSubmitRender:
        return reinterpret_cast<TQ3XFunctionPointer>(quadSubmit);
    default:
        return nullptr;
    }
}

class CustomShapeRenderTest : public Q3ApiTest {
protected:
    void SetUp() override
    {
        Q3ApiTest::SetUp();
        g_quad = Behaviour{};
        m_class = Q3XObjectHierarchy_RegisterClass(kQ3SharedTypeShape, &m_type, const_cast<char*>("Test:Quad"),
                                                   quadMetaHandler, nullptr, 0, sizeof(Quad));
        ASSERT_NE(m_class, nullptr);
    }
    void TearDown() override
    {
        for (TQ3Object object : m_owned)
            Q3Object_Dispose(object);
        m_owned.clear();
        EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(m_class), kQ3Success);
        Q3ApiTest::TearDown();
    }
    template <class T>
    T own(T object)
    {
        m_owned.push_back(object);
        return object;
    }

    /// The image of what `submit` draws.
    std::vector<unsigned char> image(const std::function<void(TQ3ViewObject)>& submit)
    {
        Pixmap pixels(kWidth, kHeight);
        TestView view(pixels.pixmap());
        EXPECT_EQ(view.render(submit), kQ3ViewStatusDone);
        return pixels.bytes();
    }
    TQ3BoundingBox bounds(const std::function<void(TQ3ViewObject)>& submit)
    {
        Pixmap pixels(kWidth, kHeight);
        TestView view(pixels.pixmap());
        TQ3BoundingBox box{};
        EXPECT_EQ(Q3View_StartBoundingBox(view.view(), kQ3ComputeBoundsExact), kQ3Success);
        do
            submit(view.view());
        while (Q3View_EndBoundingBox(view.view(), &box) == kQ3ViewStatusRetraverse);
        return box;
    }
    unsigned long hits(float x, float y, const std::function<void(TQ3ViewObject)>& submit)
    {
        Pixmap pixels(kWidth, kHeight);
        TestView view(pixels.pixmap());
        TQ3WorldRayPickData data{};
        data.data.sort = kQ3PickSortNone;
        data.data.mask = kQ3PickDetailNone;
        data.data.numHitsToReturn = kQ3ReturnAllHits;
        data.ray.origin = {x, y, 5};
        data.ray.direction = {0, 0, -1};
        TQ3PickObject pick = Q3WorldRayPick_New(&data);
        EXPECT_EQ(Q3View_StartPicking(view.view(), pick), kQ3Success);
        do
            submit(view.view());
        while (Q3View_EndPicking(view.view()) == kQ3ViewStatusRetraverse);
        unsigned long count = 0;
        EXPECT_EQ(Q3Pick_GetNumHits(pick, &count), kQ3Success);
        Q3Object_Dispose(pick);
        return count;
    }

    TQ3Object newQuad(const Quad& quad) { return own(Q3XObjectHierarchy_NewObject(m_class, const_cast<Quad*>(&quad))); }

    TQ3XObjectClass m_class = nullptr;
    TQ3ObjectType m_type = 0;
    std::vector<TQ3Object> m_owned;
};

const Quad kQuad{1.5f, 0.5f, 0.5f, {0, 1, 0}};

TEST_F(CustomShapeRenderTest, ACustomShapeDrawsWhatItsSubmitMethodSubmits)
{
    TQ3Object quad = newQuad(kQuad);
    EXPECT_EQ(Q3Object_IsDrawable(quad), kQ3True);
    const std::vector<unsigned char> direct = image([](TQ3ViewObject v) { submitQuad(kQuad, v); });
    const std::vector<unsigned char> empty = image([](TQ3ViewObject) {});
    ASSERT_NE(direct, empty); // the square is in the picture
    EXPECT_EQ(image([&](TQ3ViewObject v) { EXPECT_EQ(Q3Object_Submit(quad, v), kQ3Success); }), direct);
    EXPECT_EQ(g_quad.typeSeen, m_type);

    // In a group, and after a transform the group applies to it.
    TQ3GroupObject group = own(Q3DisplayGroup_New());
    const TQ3Vector3D offset{-1.0f, 0, 0};
    TQ3TransformObject translate = own(Q3TranslateTransform_New(&offset));
    Q3Group_AddObject(group, translate);
    Q3Group_AddObject(group, quad);
    const Quad moved{0.5f, 0.5f, 0.5f, {0, 1, 0}};
    EXPECT_EQ(image([&](TQ3ViewObject v) { EXPECT_EQ(Q3Object_Submit(group, v), kQ3Success); }),
              image([&](TQ3ViewObject v) { submitQuad(moved, v); }));
}

TEST_F(CustomShapeRenderTest, ACustomShapeBoundsAndPicksAsItsSubmissions)
{
    TQ3Object quad = newQuad(kQuad);
    const TQ3BoundingBox box = bounds([&](TQ3ViewObject v) { EXPECT_EQ(Q3Object_Submit(quad, v), kQ3Success); });
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_FLOAT_EQ(box.min.x, 1.0f);
    EXPECT_FLOAT_EQ(box.max.x, 2.0f);
    EXPECT_FLOAT_EQ(box.min.y, 0.0f);
    EXPECT_FLOAT_EQ(box.max.y, 1.0f);

    const auto custom = [&](TQ3ViewObject v) { EXPECT_EQ(Q3Object_Submit(quad, v), kQ3Success); };
    const auto direct = [](TQ3ViewObject v) { submitQuad(kQuad, v); };
    EXPECT_EQ(hits(1.3f, 0.8f, custom), hits(1.3f, 0.8f, direct));
    EXPECT_GE(hits(1.3f, 0.8f, custom), 1u);
    EXPECT_EQ(hits(3.0f, 0.8f, custom), 0u);
}

TEST_F(CustomShapeRenderTest, AFailingSubmitMethodFailsTheSubmit)
{
    TQ3Object quad = newQuad(kQuad);
    g_quad.fail = true;
    Pixmap pixels(kWidth, kHeight);
    TestView view(pixels.pixmap());
    EXPECT_EQ(view.render([&](TQ3ViewObject v) {
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_Submit(quad, v), kQ3Failure), kQ3ErrorInvalidParameter);
    }),
              kQ3ViewStatusDone);
}

TEST_F(CustomShapeRenderTest, AClassWithoutTheLoopsMethodAddsNothingToIt)
{
    TQ3ObjectType type = 0;
    TQ3XObjectClass renderOnly = Q3XObjectHierarchy_RegisterClass(
        kQ3SharedTypeShape, &type, const_cast<char*>("Test:RenderOnly"), renderOnlyMetaHandler, nullptr, 0, sizeof(Quad));
    ASSERT_NE(renderOnly, nullptr);
    TQ3Object quad = Q3XObjectHierarchy_NewObject(renderOnly, const_cast<Quad*>(&kQuad));
    const TQ3BoundingBox box = bounds([&](TQ3ViewObject v) { EXPECT_EQ(Q3Object_Submit(quad, v), kQ3Success); });
    EXPECT_EQ(box.isEmpty, kQ3True);
    EXPECT_EQ(g_quad.calls, 0);
    EXPECT_NE(image([&](TQ3ViewObject v) { EXPECT_EQ(Q3Object_Submit(quad, v), kQ3Success); }),
              image([](TQ3ViewObject) {}));
    EXPECT_EQ(g_quad.calls, 1);
    Q3Object_Dispose(quad);
    EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(renderOnly), kQ3Success);
}

} // namespace
