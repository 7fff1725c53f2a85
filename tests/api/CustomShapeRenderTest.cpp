// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// QD3DExtension.h's submit methods (Q3 extension, Quesa's names): a custom
// shape whose class submits two triangles draws, bounds and picks exactly
// as the same triangles submitted directly, alone and inside a group; its
// pick hits name it, with the path to it, not what it submits; a failing
// submit method fails the submit; a class without the loop's method adds
// nothing.

#include "Q3ApiTest.h"
#include "RenderTestSupport.h"

#include "QD3DExtension.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DPick.h"
#include "QD3DSet.h"
#include "QD3DTransform.h"

#include <array>
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
    TQ3Object submits = nullptr; // submitted in place of the square's triangles when set
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
    if (g_quad.submits != nullptr)
        return Q3Object_Submit(g_quad.submits, view);
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

    /// Runs a picking loop of `pick` around `submit`; the pick keeps the hits.
    void pickWith(TQ3PickObject pick, const std::function<void(TQ3ViewObject)>& submit)
    {
        Pixmap pixels(kWidth, kHeight);
        TestView view(pixels.pixmap());
        ASSERT_EQ(Q3View_StartPicking(view.view(), pick), kQ3Success);
        do
            submit(view.view());
        while (Q3View_EndPicking(view.view()) == kQ3ViewStatusRetraverse);
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
    EXPECT_EQ(hits(1.3f, 0.8f, direct), 1u);
    EXPECT_EQ(hits(1.3f, 0.8f, custom), 1u);
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

TEST_F(CustomShapeRenderTest, APickHitNamesTheCustomObjectNotWhatItSubmits)
{
    // The class submits a group of its own holding two retained triangles
    // that cover the square; the application submits a group holding the
    // custom object.
    TQ3GroupObject inner = own(Q3DisplayGroup_New());
    const TQ3Point3D c[4] = {{1.0f, 0.0f, 0}, {2.0f, 0.0f, 0}, {2.0f, 1.0f, 0}, {1.0f, 1.0f, 0}};
    for (const auto& t : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
        TQ3TriangleData data{};
        for (int k = 0; k < 3; ++k)
            data.vertices[k].point = c[t[k]];
        TQ3GeometryObject triangle = Q3Triangle_New(&data);
        ASSERT_NE(triangle, nullptr);
        ASSERT_NE(Q3Group_AddObject(inner, triangle), nullptr);
        Q3Object_Dispose(triangle);
    }
    g_quad.submits = inner;
    TQ3Object quad = newQuad(kQuad);
    TQ3GroupObject outer = own(Q3DisplayGroup_New());
    TQ3StyleObject faces = own(Q3PickPartsStyle_New(kQ3PickPartsMaskFace));
    ASSERT_NE(Q3Group_AddObject(outer, faces), nullptr);
    const TQ3GroupPosition quadAt = Q3Group_AddObject(outer, quad);
    ASSERT_NE(quadAt, nullptr);

    const TQ3PickDetail mask = kQ3PickDetailMaskObject | kQ3PickDetailMaskPath | kQ3PickDetailMaskXYZ |
                               kQ3PickDetailMaskPickPart | kQ3PickDetailMaskShapePart;
    TQ3WindowPointPickData point{};
    point.data = {kQ3PickSortNearToFar, mask, kQ3ReturnAllHits};
    // World (1.3, 0.8) in the 80 x 60 pane of the listing's camera.
    point.point = {float((1.3 - 1.5 + 2.0) / 4.0 * kWidth), float((1.5 - (0.8 - 0.5)) / 3.0 * kHeight)};
    TQ3WorldRayPickData ray{};
    ray.data = point.data;
    ray.ray = {{1.3f, 0.8f, 5.0f}, {0.0f, 0.0f, -1.0f}};
    for (TQ3PickObject pick : {Q3WindowPointPick_New(&point), Q3WorldRayPick_New(&ray)}) {
        ASSERT_NE(pick, nullptr);
        pickWith(pick, [&](TQ3ViewObject v) { EXPECT_EQ(Q3Object_Submit(outer, v), kQ3Success); });
        unsigned long count = 0;
        ASSERT_EQ(Q3Pick_GetNumHits(pick, &count), kQ3Success);
        ASSERT_EQ(count, 1u); // one submission, one face hit
        TQ3PickDetail valid = 0;
        ASSERT_EQ(Q3Pick_GetPickDetailValidMask(pick, 0, &valid), kQ3Success);
        EXPECT_EQ(valid & kQ3PickDetailMaskShapePart, 0u); // a custom object has no mesh parts
        TQ3Object object = nullptr;
        ASSERT_EQ(Q3Pick_GetPickDetailData(pick, 0, kQ3PickDetailMaskObject, &object), kQ3Success);
        EXPECT_EQ(object, quad);
        if (object != nullptr)
            Q3Object_Dispose(object);
        TQ3HitPath path{};
        ASSERT_EQ(Q3Pick_GetPickDetailData(pick, 0, kQ3PickDetailMaskPath, &path), kQ3Success);
        EXPECT_EQ(path.rootGroup, outer);
        ASSERT_EQ(path.depth, 1u); // the class's own group is no part of the path
        EXPECT_EQ(path.positions[0], quadAt);
        EXPECT_EQ(Q3HitPath_EmptyData(&path), kQ3Success);
        TQ3PickParts part = 0;
        ASSERT_EQ(Q3Pick_GetPickDetailData(pick, 0, kQ3PickDetailMaskPickPart, &part), kQ3Success);
        EXPECT_EQ(part, kQ3PickPartsMaskFace);
        TQ3Point3D xyz{};
        ASSERT_EQ(Q3Pick_GetPickDetailData(pick, 0, kQ3PickDetailMaskXYZ, &xyz), kQ3Success);
        EXPECT_NEAR(xyz.x, 1.3f, 0.03f); // a window point is a pixel centre
        EXPECT_NEAR(xyz.y, 0.8f, 0.03f);
        EXPECT_NEAR(xyz.z, 0.0f, 1e-5f);
        Q3Object_Dispose(pick);
    }

    // Submitted directly, the same group's triangles are the hits' objects.
    TQ3PickObject pick = Q3WorldRayPick_New(&ray);
    pickWith(pick, [&](TQ3ViewObject v) { EXPECT_EQ(Q3Object_Submit(inner, v), kQ3Success); });
    unsigned long count = 0;
    ASSERT_EQ(Q3Pick_GetNumHits(pick, &count), kQ3Success);
    ASSERT_EQ(count, 1u);
    TQ3Object object = nullptr;
    ASSERT_EQ(Q3Pick_GetPickDetailData(pick, 0, kQ3PickDetailMaskObject, &object), kQ3Success);
    ASSERT_NE(object, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(object), kQ3GeometryTypeTriangle);
    Q3Object_Dispose(object);
    Q3Object_Dispose(pick);
    g_quad.submits = nullptr;
}

} // namespace
