// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QD3DGroup.h as a container: every call, positions and their checks, the
// kinds of group and what each accepts, the ordered group's order, cycles,
// references, duplication and deep nesting. Drawing groups is in
// GroupRenderTest.cpp.

#include "OwningApiTest.h"

#include "QD3DDrawContext.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"

#include <utility>
#include <vector>

namespace {

using namespace q3test;

class GroupApiTest : public OwningApiTest {
protected:
    /// The objects of `type` in `group`, first to last (`forwards`) or last
    /// to first, through the ...PositionOfType calls; the group keeps the
    /// references.
    static std::vector<TQ3Object> walkOfType(TQ3GroupObject group, TQ3ObjectType type, bool forwards)
    {
        std::vector<TQ3Object> objects;
        TQ3GroupPosition position = nullptr;
        if (forwards)
            Q3Group_GetFirstPositionOfType(group, type, &position);
        else
            Q3Group_GetLastPositionOfType(group, type, &position);
        while (position != nullptr) {
            TQ3Object object = nullptr;
            Q3Group_GetPositionObject(group, position, &object);
            objects.push_back(object);
            Q3Object_Dispose(object);
            if (forwards)
                Q3Group_GetNextPositionOfType(group, type, &position);
            else
                Q3Group_GetPreviousPositionOfType(group, type, &position);
        }
        return objects;
    }

    TQ3GeometryObject point(float x)
    {
        const TQ3PointData data{{x, 0.0f, 0.0f}, nullptr};
        return own(Q3Point_New(&data));
    }
    TQ3TransformObject translate(float x)
    {
        const TQ3Vector3D offset{x, 0.0f, 0.0f};
        return own(Q3TranslateTransform_New(&offset));
    }
    TQ3StyleObject fillStyle()
    {
        const TQ3SubdivisionStyleData data{kQ3SubdivisionMethodConstant, 4, 4};
        return own(Q3SubdivisionStyle_New(&data));
    }
    TQ3AttributeSet attributes() { return own(Q3AttributeSet_New()); }

    /// The objects of the group from first to last, through the positions:
    /// walked from the first forwards, or from the last back when `backwards`.
    std::vector<TQ3Object> walk(TQ3GroupObject group, bool backwards = false)
    {
        std::vector<TQ3Object> objects;
        TQ3GroupPosition position = nullptr;
        EXPECT_EQ((backwards ? Q3Group_GetLastPosition : Q3Group_GetFirstPosition)(group, &position), kQ3Success);
        while (position != nullptr) {
            TQ3Object object = nullptr;
            EXPECT_EQ(Q3Group_GetPositionObject(group, position, &object), kQ3Success);
            objects.insert(backwards ? objects.begin() : objects.end(), object);
            Q3Object_Dispose(object);
            EXPECT_EQ((backwards ? Q3Group_GetPreviousPosition : Q3Group_GetNextPosition)(group, &position),
                      kQ3Success);
        }
        return objects;
    }

    /// The positions of `object` in the group in the order the object
    /// position calls give them: from the first on, or from the last back
    /// when `backwards`, until they give NULL (at most 100).
    std::vector<TQ3GroupPosition> objectPositions(TQ3GroupObject group, TQ3Object object, bool backwards)
    {
        std::vector<TQ3GroupPosition> positions;
        TQ3GroupPosition position = nullptr;
        EXPECT_EQ((backwards ? Q3Group_GetLastObjectPosition : Q3Group_GetFirstObjectPosition)(group, object, &position),
                  kQ3Success);
        while (position != nullptr && positions.size() < 100) {
            positions.push_back(position);
            (backwards ? Q3Group_GetPreviousObjectPosition : Q3Group_GetNextObjectPosition)(group, object, &position);
        }
        return positions;
    }

    unsigned long count(TQ3GroupObject group, TQ3ObjectType type = kQ3ObjectTypeInvalid)
    {
        unsigned long n = 12345;
        if (type == kQ3ObjectTypeInvalid)
            EXPECT_EQ(Q3Group_CountObjects(group, &n), kQ3Success);
        else
            EXPECT_EQ(Q3Group_CountObjectsOfType(group, type, &n), kQ3Success);
        return n;
    }
};

TEST_F(GroupApiTest, EachKindHasItsTypes)
{
    struct Kind {
        TQ3GroupObject (*make)(void);
        TQ3ObjectType leaf, group, display;
    };
    const Kind kinds[] = {
        {Q3Group_New, kQ3ShapeTypeGroup, kQ3ObjectTypeInvalid, kQ3ObjectTypeInvalid},
        {Q3LightGroup_New, kQ3GroupTypeLight, kQ3GroupTypeLight, kQ3ObjectTypeInvalid},
        {Q3InfoGroup_New, kQ3GroupTypeInfo, kQ3GroupTypeInfo, kQ3ObjectTypeInvalid},
        {Q3DisplayGroup_New, kQ3GroupTypeDisplay, kQ3GroupTypeDisplay, kQ3ObjectTypeInvalid},
        {Q3OrderedDisplayGroup_New, kQ3DisplayGroupTypeOrdered, kQ3GroupTypeDisplay, kQ3DisplayGroupTypeOrdered},
        {Q3IOProxyDisplayGroup_New, kQ3DisplayGroupTypeIOProxy, kQ3GroupTypeDisplay, kQ3DisplayGroupTypeIOProxy},
    };
    for (const Kind& kind : kinds) {
        TQ3GroupObject group = own(kind.make());
        ASSERT_NE(group, nullptr);
        EXPECT_EQ(Q3Object_GetLeafType(group), kind.leaf);
        EXPECT_EQ(Q3Shared_GetType(group), kQ3SharedTypeShape);
        EXPECT_EQ(Q3Shape_GetType(group), kQ3ShapeTypeGroup);
        EXPECT_EQ(Q3Group_GetType(group), kind.group);
        EXPECT_EQ(Q3Object_IsType(group, kQ3ShapeTypeGroup), kQ3True);
        if (kind.group == kQ3GroupTypeDisplay)
            EXPECT_EQ(Q3DisplayGroup_GetType(group), kind.display);
        else
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3DisplayGroup_GetType(group), kQ3ObjectTypeInvalid),
                            kQ3ErrorInvalidObjectType);
        EXPECT_EQ(count(group), 0u);
        TQ3GroupPosition position = reinterpret_cast<TQ3GroupPosition>(this);
        EXPECT_EQ(Q3Group_GetFirstPosition(group, &position), kQ3Success);
        EXPECT_EQ(position, nullptr);
    }
}

TEST_F(GroupApiTest, AddKeepsTheOrderAndWalksBothWays)
{
    TQ3GroupObject group = own(Q3Group_New());
    TQ3Object a = point(1), b = point(2), c = point(3), d = point(4);
    TQ3GroupPosition pa = Q3Group_AddObject(group, a);
    TQ3GroupPosition pc = Q3Group_AddObject(group, c);
    ASSERT_NE(pa, nullptr);
    ASSERT_NE(pc, nullptr);
    TQ3GroupPosition pb = Q3Group_AddObjectBefore(group, pc, b);
    TQ3GroupPosition pd = Q3Group_AddObjectAfter(group, pc, d);
    ASSERT_NE(pb, nullptr);
    ASSERT_NE(pd, nullptr);
    const std::vector<TQ3Object> expected{a, b, c, d};
    EXPECT_EQ(walk(group), expected);
    EXPECT_EQ(walk(group, true), expected);
    EXPECT_EQ(count(group), 4u);

    TQ3GroupPosition last = nullptr;
    EXPECT_EQ(Q3Group_GetLastPosition(group, &last), kQ3Success);
    EXPECT_EQ(last, pd);
    TQ3GroupPosition position = pa;
    EXPECT_EQ(Q3Group_GetPreviousPosition(group, &position), kQ3Success);
    EXPECT_EQ(position, nullptr);
}

TEST_F(GroupApiTest, TheGroupHoldsOneReferenceAndHandsOutNewOnes)
{
    TQ3GroupObject group = own(Q3Group_New());
    TQ3Object a = point(1);
    EXPECT_EQ(Q3Shared_IsReferenced(a), kQ3False);
    TQ3GroupPosition position = Q3Group_AddObject(group, a);
    EXPECT_EQ(Q3Shared_IsReferenced(a), kQ3True);

    TQ3Object read = nullptr;
    ASSERT_EQ(Q3Group_GetPositionObject(group, position, &read), kQ3Success);
    EXPECT_EQ(read, a);
    Q3Object_Dispose(read); // the caller's reference, not the group's
    EXPECT_EQ(Q3Shared_IsReferenced(a), kQ3True);

    TQ3Object removed = Q3Group_RemovePosition(group, position);
    EXPECT_EQ(removed, a);
    EXPECT_EQ(Q3Shared_IsReferenced(a), kQ3True); // the group's, now ours
    Q3Object_Dispose(removed);
    EXPECT_EQ(Q3Shared_IsReferenced(a), kQ3False);
    EXPECT_EQ(count(group), 0u);

    // Disposing the group releases what it holds.
    TQ3Object b = point(2);
    Q3Group_AddObject(group, b);
    TQ3GroupObject other = Q3Group_New();
    Q3Group_AddObject(other, b);
    Q3Object_Dispose(other);
    EXPECT_EQ(count(group), 1u);
    Q3Group_EmptyObjects(group);
    EXPECT_EQ(Q3Shared_IsReferenced(b), kQ3False);
}

TEST_F(GroupApiTest, SetPositionObjectReplacesInPlace)
{
    TQ3GroupObject group = own(Q3Group_New());
    TQ3Object a = point(1), b = point(2), c = point(3);
    Q3Group_AddObject(group, a);
    TQ3GroupPosition middle = Q3Group_AddObject(group, b);
    Q3Group_AddObject(group, c);
    TQ3Object replacement = point(9);
    ASSERT_EQ(Q3Group_SetPositionObject(group, middle, replacement), kQ3Success);
    EXPECT_EQ(walk(group), (std::vector<TQ3Object>{a, replacement, c}));
    EXPECT_EQ(Q3Shared_IsReferenced(b), kQ3False);
    EXPECT_EQ(Q3Shared_IsReferenced(replacement), kQ3True);
    // Setting the object already there keeps it.
    ASSERT_EQ(Q3Group_SetPositionObject(group, middle, replacement), kQ3Success);
    EXPECT_EQ(Q3Shared_IsReferenced(replacement), kQ3True);
    EXPECT_EQ(walk(group), (std::vector<TQ3Object>{a, replacement, c}));
}

TEST_F(GroupApiTest, PositionsOfOtherGroupsOrRemovedOnesAreRefused)
{
    TQ3GroupObject group = own(Q3Group_New());
    TQ3GroupObject other = own(Q3Group_New());
    TQ3Object a = point(1), b = point(2);
    TQ3GroupPosition kept = Q3Group_AddObject(group, a);
    TQ3GroupPosition foreign = Q3Group_AddObject(other, b);
    TQ3GroupPosition removed = Q3Group_AddObject(group, b);
    Q3Object_Dispose(Q3Group_RemovePosition(group, removed));
    int stray = 0;
    const TQ3GroupPosition bad[] = {foreign, removed, reinterpret_cast<TQ3GroupPosition>(&stray)};
    for (TQ3GroupPosition position : bad) {
        TQ3Object object = a;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_GetPositionObject(group, position, &object), kQ3Failure),
                        kQ3ErrorInvalidPositionForGroup);
        EXPECT_EQ(object, a);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_SetPositionObject(group, position, b), kQ3Failure),
                        kQ3ErrorInvalidPositionForGroup);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_RemovePosition(group, position), nullptr),
                        kQ3ErrorInvalidPositionForGroup);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObjectBefore(group, position, b), nullptr),
                        kQ3ErrorInvalidPositionForGroup);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObjectAfter(group, position, b), nullptr),
                        kQ3ErrorInvalidPositionForGroup);
        TQ3GroupPosition walked = position;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_GetNextPosition(group, &walked), kQ3Failure),
                        kQ3ErrorInvalidPositionForGroup);
        EXPECT_EQ(walked, position);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_GetPreviousPosition(group, &walked), kQ3Failure),
                        kQ3ErrorInvalidPositionForGroup);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_GetNextPositionOfType(group, kQ3ShapeTypeGeometry, &walked),
                                  kQ3Failure),
                        kQ3ErrorInvalidPositionForGroup);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_GetNextObjectPosition(group, a, &walked), kQ3Failure),
                        kQ3ErrorInvalidPositionForGroup);
        EXPECT_EQ(walked, position);
    }
    // Nothing changed.
    EXPECT_EQ(walk(group), std::vector<TQ3Object>{a});
    EXPECT_EQ(walk(other), std::vector<TQ3Object>{b});
    TQ3Object object = nullptr;
    EXPECT_EQ(Q3Group_GetPositionObject(group, kept, &object), kQ3Success);
    Q3Object_Dispose(object);
}

TEST_F(GroupApiTest, RemovingWhileWalkingWorksWhenTheNextIsTakenFirst)
{
    TQ3GroupObject group = own(Q3Group_New());
    std::vector<TQ3Object> points;
    for (int i = 0; i < 10; ++i) {
        points.push_back(point(float(i)));
        Q3Group_AddObject(group, points.back());
    }
    // Remove every other object while walking.
    TQ3GroupPosition position = nullptr;
    Q3Group_GetFirstPosition(group, &position);
    int index = 0;
    while (position != nullptr) {
        TQ3GroupPosition next = position;
        ASSERT_EQ(Q3Group_GetNextPosition(group, &next), kQ3Success);
        if (index % 2 == 1)
            Q3Object_Dispose(Q3Group_RemovePosition(group, position));
        position = next;
        ++index;
    }
    EXPECT_EQ(walk(group), (std::vector<TQ3Object>{points[0], points[2], points[4], points[6], points[8]}));
}

TEST_F(GroupApiTest, OfTypeCallsSeeOnlyThatTypeAndItsSubclasses)
{
    TQ3GroupObject group = own(Q3DisplayGroup_New());
    TQ3Object p1 = point(1), t1 = translate(1), p2 = point(2), s = fillStyle(), t2 = translate(2);
    for (TQ3Object object : {p1, t1, p2, s, t2})
        ASSERT_NE(Q3Group_AddObject(group, object), nullptr);
    // Each type and how many of the five objects are of it.
    const std::pair<TQ3ObjectType, unsigned long> counts[] = {
        {kQ3ShapeTypeGeometry, 2},      {kQ3GeometryTypePoint, 2},  {kQ3ShapeTypeTransform, 2},
        {kQ3TransformTypeTranslate, 2}, {kQ3TransformTypeScale, 0}, {kQ3ShapeTypeStyle, 1},
        {kQ3SharedTypeShape, 5}};
    for (const auto& [type, expected] : counts)
        EXPECT_EQ(count(group, type), expected) << "type " << type;

    EXPECT_EQ(walkOfType(group, kQ3ShapeTypeTransform, true), (std::vector<TQ3Object>{t1, t2}));
    EXPECT_EQ(walkOfType(group, kQ3ShapeTypeGeometry, false), (std::vector<TQ3Object>{p2, p1}));

    TQ3GroupPosition position = nullptr;
    Q3Group_GetFirstPositionOfType(group, kQ3ShapeTypeShader, &position);
    EXPECT_EQ(position, nullptr);

    ASSERT_EQ(Q3Group_EmptyObjectsOfType(group, kQ3ShapeTypeTransform), kQ3Success);
    EXPECT_EQ(walk(group), (std::vector<TQ3Object>{p1, p2, s}));
    ASSERT_EQ(Q3Group_EmptyObjects(group), kQ3Success);
    EXPECT_EQ(count(group), 0u);
}

TEST_F(GroupApiTest, ObjectPositionCallsFindEveryPlaceAnObjectIs)
{
    TQ3GroupObject group = own(Q3Group_New());
    TQ3Object a = point(1), b = point(2);
    TQ3GroupPosition p0 = Q3Group_AddObject(group, a);
    Q3Group_AddObject(group, b);
    TQ3GroupPosition p2 = Q3Group_AddObject(group, a);
    Q3Group_AddObject(group, b);
    TQ3GroupPosition p4 = Q3Group_AddObject(group, a);

    using Positions = std::vector<TQ3GroupPosition>;
    EXPECT_EQ(objectPositions(group, a, false), (Positions{p0, p2, p4}));
    EXPECT_EQ(objectPositions(group, a, true), (Positions{p4, p2, p0}));

    TQ3GroupPosition position = nullptr;
    TQ3Object absent = point(7);
    Q3Group_GetFirstObjectPosition(group, absent, &position);
    EXPECT_EQ(position, nullptr);
    EXPECT_EQ(count(group), 5u);
}

TEST_F(GroupApiTest, EachKindAcceptsOnlyItsObjects)
{
    TQ3GroupObject plain = own(Q3Group_New());
    TQ3GroupObject display = own(Q3DisplayGroup_New());
    TQ3GroupObject lights = own(Q3LightGroup_New());
    TQ3GroupObject info = own(Q3InfoGroup_New());
    TQ3Pixmap pixmap{};
    std::vector<unsigned char> memory(16);
    pixmap.image = memory.data();
    pixmap.width = 2;
    pixmap.height = 2;
    pixmap.rowBytes = 8;
    pixmap.pixelSize = 16;
    pixmap.pixelType = kQ3PixelTypeRGB16;
    TQ3PixmapDrawContextData contextData{};
    contextData.drawContextData.clearImageMethod = kQ3ClearMethodWithColor;
    contextData.pixmap = pixmap;
    TQ3DrawContextObject context = own(Q3PixmapDrawContext_New(&contextData));
    ASSERT_NE(context, nullptr);
    TQ3Object p = point(1);

    // A plain group holds any shared object; a view is not one.
    EXPECT_NE(Q3Group_AddObject(plain, context), nullptr);
    EXPECT_NE(Q3Group_AddObject(plain, p), nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(plain, view()), nullptr), kQ3ErrorInvalidObjectForGroup);
    // A display group holds what can be drawn.
    EXPECT_NE(Q3Group_AddObject(display, p), nullptr);
    EXPECT_NE(Q3Group_AddObject(display, attributes()), nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(display, context), nullptr), kQ3ErrorInvalidObjectForGroup);
    // Light and info groups refuse geometry.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(lights, p), nullptr), kQ3ErrorInvalidObjectForGroup);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(info, p), nullptr), kQ3ErrorInvalidObjectForGroup);
    // Replacing follows the same rules and leaves the old object.
    TQ3GroupPosition position = nullptr;
    Q3Group_GetFirstPosition(display, &position);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_SetPositionObject(display, position, context), kQ3Failure),
                    kQ3ErrorInvalidObjectForGroup);
    EXPECT_EQ(walk(display)[0], p);
    EXPECT_EQ(count(lights), 0u);
    EXPECT_EQ(count(info), 0u);
}

TEST_F(GroupApiTest, AGroupNeverContainsItself)
{
    TQ3GroupObject outer = own(Q3DisplayGroup_New());
    TQ3GroupObject middle = own(Q3DisplayGroup_New());
    TQ3GroupObject inner = own(Q3Group_New());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(outer, outer), nullptr), kQ3ErrorInvalidObjectForGroup);
    ASSERT_NE(Q3Group_AddObject(outer, middle), nullptr);
    ASSERT_NE(Q3Group_AddObject(middle, inner), nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(inner, outer), nullptr), kQ3ErrorInvalidObjectForGroup);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(middle, outer), nullptr), kQ3ErrorInvalidObjectForGroup);
    TQ3GroupPosition position = Q3Group_AddObject(inner, point(1));
    ASSERT_NE(position, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_SetPositionObject(inner, position, outer), kQ3Failure),
                    kQ3ErrorInvalidObjectForGroup);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObjectBefore(inner, position, middle), nullptr),
                    kQ3ErrorInvalidObjectForGroup);
    // The same group may appear twice in one parent, and in two parents.
    EXPECT_NE(Q3Group_AddObject(outer, inner), nullptr);
    EXPECT_NE(Q3Group_AddObject(outer, inner), nullptr);
    EXPECT_EQ(count(outer), 3u);
    EXPECT_EQ(count(inner), 1u);
}

TEST_F(GroupApiTest, TheOrderedGroupSortsByKindAndKeepsEachKindInOrder)
{
    TQ3GroupObject group = own(Q3OrderedDisplayGroup_New());
    TQ3Object g1 = point(1), g2 = point(2), t1 = translate(1), t2 = translate(2), s1 = fillStyle();
    TQ3Object a1 = attributes();
    TQ3GroupObject sub = own(Q3DisplayGroup_New());
    for (TQ3Object object : {g1, sub, a1, t1, g2, s1, t2})
        ASSERT_NE(Q3Group_AddObject(group, object), nullptr);
    // Transforms, styles, attribute sets, (shaders, cameras, lights),
    // geometries, groups.
    EXPECT_EQ(walk(group), (std::vector<TQ3Object>{t1, t2, s1, a1, g1, g2, sub}));

    // Before and after a position of the same kind are allowed; next to
    // another kind only where that keeps the order.
    TQ3GroupPosition first = nullptr;
    Q3Group_GetFirstPositionOfType(group, kQ3ShapeTypeGeometry, &first);
    TQ3Object g0 = point(0);
    ASSERT_NE(Q3Group_AddObjectBefore(group, first, g0), nullptr);
    TQ3GroupPosition style = nullptr;
    Q3Group_GetFirstPositionOfType(group, kQ3ShapeTypeStyle, &style);
    TQ3Object t3 = translate(3);
    ASSERT_NE(Q3Group_AddObjectBefore(group, style, t3), nullptr);
    TQ3Object g9 = point(9);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObjectBefore(group, style, g9), nullptr),
                    kQ3ErrorInvalidObjectForPosition);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_SetPositionObject(group, style, g9), kQ3Failure),
                    kQ3ErrorInvalidObjectForPosition);
    EXPECT_EQ(walk(group), (std::vector<TQ3Object>{t1, t2, t3, s1, a1, g0, g1, g2, sub}));
}

TEST_F(GroupApiTest, DisplayStateAndBoundingBox)
{
    TQ3GroupObject group = own(Q3DisplayGroup_New());
    TQ3DisplayGroupState state = 0;
    ASSERT_EQ(Q3DisplayGroup_GetState(group, &state), kQ3Success);
    EXPECT_EQ(state & kQ3DisplayGroupStateMaskIsDrawn, (TQ3DisplayGroupState)kQ3DisplayGroupStateMaskIsDrawn);
    EXPECT_EQ(state & kQ3DisplayGroupStateMaskIsInline, 0u);
    ASSERT_EQ(Q3DisplayGroup_SetState(group, kQ3DisplayGroupStateMaskIsInline | 0x400), kQ3Success);
    Q3DisplayGroup_GetState(group, &state);
    EXPECT_EQ(state, (TQ3DisplayGroupState)(kQ3DisplayGroupStateMaskIsInline | 0x400));

    TQ3BoundingBox box{{0, 0, 0}, {1, 1, 1}, kQ3True};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DisplayGroup_GetBoundingBox(group, &box), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    TQ3BoundingBox set{{-1, -2, -3}, {1, 2, 3}, kQ3False};
    ASSERT_EQ(Q3DisplayGroup_SetAndUseBoundingBox(group, &set), kQ3Success);
    Q3DisplayGroup_GetState(group, &state);
    EXPECT_NE(state & kQ3DisplayGroupStateMaskUseBoundingBox, 0u);
    ASSERT_EQ(Q3DisplayGroup_GetBoundingBox(group, &box), kQ3Success);
    EXPECT_EQ(box.min.y, -2.0f);
    EXPECT_EQ(box.max.z, 3.0f);
    EXPECT_EQ(box.isEmpty, kQ3False);

    TQ3BoundingBox inverted{{1, 0, 0}, {0, 1, 1}, kQ3False};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DisplayGroup_SetAndUseBoundingBox(group, &inverted), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    TQ3BoundingBox infinite{{0, 0, 0}, {1, 1, 1.0f / 0.0f}, kQ3False};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DisplayGroup_SetAndUseBoundingBox(group, &infinite), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    Q3DisplayGroup_GetBoundingBox(group, &box);
    EXPECT_EQ(box.min.y, -2.0f);

    ASSERT_EQ(Q3DisplayGroup_RemoveBoundingBox(group), kQ3Success);
    EXPECT_Q3_ERROR(Q3DisplayGroup_GetBoundingBox(group, &box), kQ3ErrorInvalidParameter);

    // CalcAndUse bounds the contents with a bounding loop of the view.
    const TQ3Vector3D offset{10, 0, 0};
    Q3Group_AddObject(group, own(Q3TranslateTransform_New(&offset)));
    Q3Group_AddObject(group, point(1));
    Q3Group_AddObject(group, point(-2));
    ASSERT_EQ(Q3DisplayGroup_CalcAndUseBoundingBox(group, kQ3ComputeBoundsExact, view()), kQ3Success);
    ASSERT_EQ(Q3DisplayGroup_GetBoundingBox(group, &box), kQ3Success);
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_FLOAT_EQ(box.min.x, 8.0f);
    EXPECT_FLOAT_EQ(box.max.x, 11.0f);
    // Not inside a loop of that view.
    ASSERT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3DisplayGroup_CalcAndUseBoundingBox(group, kQ3ComputeBoundsExact, view()),
                              kQ3Failure),
                    kQ3ErrorViewIsStarted);
    TQ3BoundingBox ignored{};
    Q3View_EndBoundingBox(view(), &ignored);
    // Display calls refuse other groups.
    TQ3GroupObject plain = own(Q3Group_New());
    EXPECT_Q3_ERROR(Q3DisplayGroup_GetState(plain, &state), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3DisplayGroup_SetAndUseBoundingBox(plain, &set), kQ3ErrorInvalidObjectType);
}

TEST_F(GroupApiTest, DuplicateCopiesTheGroupAndItsObjects)
{
    TQ3GroupObject group = own(Q3OrderedDisplayGroup_New());
    TQ3GroupObject sub = own(Q3DisplayGroup_New());
    Q3Group_AddObject(sub, point(5));
    Q3Group_AddObject(group, point(1));
    Q3Group_AddObject(group, translate(2));
    Q3Group_AddObject(group, sub);
    TQ3GroupObject copy = own(Q3Object_Duplicate(group));
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(copy), kQ3DisplayGroupTypeOrdered);
    const std::vector<TQ3Object> original = walk(group), copied = walk(copy);
    ASSERT_EQ(copied.size(), 3u);
    for (std::size_t i = 0; i < copied.size(); ++i) {
        EXPECT_NE(copied[i], original[i]);
        EXPECT_EQ(Q3Object_GetLeafType(copied[i]), Q3Object_GetLeafType(original[i]));
    }
    // Editing the copy leaves the original alone.
    Q3Group_EmptyObjects(copied[2]);
    EXPECT_EQ(count(sub), 1u);
}

TEST_F(GroupApiTest, DuplicateKeepsSharingAndStaysLinearInDistinctObjects)
{
    // Level k holds level k-1 twice: 2^40 paths to the bottom, 41 groups.
    TQ3GroupObject level = own(Q3DisplayGroup_New());
    Q3Group_AddObject(level, point(1));
    for (int k = 0; k < 40; ++k) {
        TQ3GroupObject next = own(Q3DisplayGroup_New());
        Q3Group_AddObject(next, level);
        Q3Group_AddObject(next, level);
        level = next;
    }
    TQ3GroupObject copy = own(Q3Object_Duplicate(level));
    ASSERT_NE(copy, nullptr);
    const std::vector<TQ3Object> children = walk(copy);
    ASSERT_EQ(children.size(), 2u);
    EXPECT_EQ(children[0], children[1]); // one copy, held twice
    EXPECT_NE(children[0], walk(level)[0]);
}

TEST_F(GroupApiTest, DeepChainsAreDestroyedWithoutRecursionAndRefusedWhereTheyAreTooDeep)
{
    // A chain far deeper than the stack could recurse through.
    TQ3GroupObject top = Q3DisplayGroup_New();
    TQ3GroupObject current = top;
    for (int i = 0; i < 200000; ++i) {
        TQ3GroupObject next = Q3DisplayGroup_New();
        ASSERT_NE(Q3Group_AddObject(current, next), nullptr);
        Q3Object_Dispose(next);
        current = next;
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_Duplicate(top), nullptr), kQ3ErrorInvalidObject);
    Q3Object_Dispose(top);
}

TEST_F(GroupApiTest, BadArgumentsAreErrors)
{
    TQ3GroupObject group = own(Q3Group_New());
    TQ3Object p = point(1);
    unsigned long n = 7;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(nullptr, p), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(group, nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(p, p), nullptr), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_CountObjects(group, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_CountObjects(p, &n), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(n, 7u);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_GetFirstPosition(group, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_GetNextPosition(group, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    TQ3GroupPosition none = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_GetNextPosition(group, &none), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_RemovePosition(group, nullptr), nullptr), kQ3ErrorNULLParameter);
    TQ3Object dead = Q3Group_New();
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(dead, p), nullptr), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(group, dead), nullptr), kQ3ErrorInvalidObject);
    EXPECT_EQ(count(group), 0u);
}

} // namespace
