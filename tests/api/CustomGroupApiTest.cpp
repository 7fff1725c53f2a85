// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Group classes an application registers (QD3DGroup.h, "Group classes"):
// registration under every group class, the accept method, the private
// data of positions, the methods that replace Q3Group_ calls (and reach
// Q3's own behaviour by calling them again), drawing through the iterate
// methods, and 3DMF: written under the class's name, read back as the
// class with its end-read method called, read as a display group with a
// warning when the class is not registered.

#include "FileTestSupport.h"
#include "OwningApiTest.h"

#include "QD3DExtension.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DPick.h"
#include "QD3DString.h"

#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace q3test;

// What the methods saw, reset by each test.
struct Seen {
    int accepted = 0, refused = 0;
    int made = 0, copied = 0, deleted = 0;
    int added = 0, removed = 0, counted = 0, emptied = 0;
    int started = 0, ended = 0, endRead = 0;
    TQ3ObjectType countedType = 0;
    const void* initData = nullptr;
    bool failEndRead = false;
    std::vector<TQ3Object> iterated;
};
Seen g_seen;

// A position's data: a serial number and the type of the object there.
struct PositionRecord {
    int serial;
    TQ3ObjectType type;
};
int g_serial = 0;

void forgetWhatMethodsSaw()
{
    g_seen = Seen{};
    g_serial = 0;
}

// A group's own data.
struct GroupRecord {
    int tag;
};

template <class F>
TQ3XFunctionPointer fn(F method)
{
    return reinterpret_cast<TQ3XFunctionPointer>(method);
}

// Accepts triangles only.
TQ3Boolean acceptTriangles(TQ3GroupObject, TQ3Object object)
{
    const bool yes = Q3Object_IsType(object, kQ3GeometryTypeTriangle) == kQ3True;
    ++(yes ? g_seen.accepted : g_seen.refused);
    return yes ? kQ3True : kQ3False;
}

TQ3Status positionNew(void* gPos, TQ3Object object, const void* initData)
{
    ++g_seen.made;
    g_seen.initData = initData;
    // Refuses points, to show a failing new method leaves the group alone.
    if (Q3Object_IsType(object, kQ3GeometryTypePoint) == kQ3True)
        return kQ3Failure;
    auto* record = static_cast<PositionRecord*>(gPos);
    record->serial = ++g_serial;
    record->type = Q3Object_GetLeafType(object);
    return kQ3Success;
}

TQ3Status positionCopy(void* srcGPos, void* dstGPos)
{
    ++g_seen.copied;
    const auto* from = static_cast<const PositionRecord*>(srcGPos);
    auto* to = static_cast<PositionRecord*>(dstGPos);
    to->serial = from->serial + 100;
    to->type = from->type;
    return kQ3Success;
}

void positionDelete(void* gPos)
{
    ++g_seen.deleted;
    std::memset(gPos, 0xAB, sizeof(PositionRecord));
}

TQ3XFunctionPointer recordingMetaHandler(TQ3XMethodType type)
{
    switch (type) {
    case kQ3XMethodType_GroupPositionSize:
        return reinterpret_cast<TQ3XFunctionPointer>(static_cast<std::uintptr_t>(sizeof(PositionRecord)));
    case kQ3XMethodType_GroupPositionNew:
        return fn(&positionNew);
    case kQ3XMethodType_GroupPositionCopy:
        return fn(&positionCopy);
    case kQ3XMethodType_GroupPositionDelete:
        return fn(&positionDelete);
    default:
        return nullptr;
    }
}

TQ3XFunctionPointer triangleMetaHandler(TQ3XMethodType type)
{
    return type == kQ3XMethodType_GroupAcceptObject ? fn(&acceptTriangles) : nullptr;
}

// A stack: new objects go first. The method calls Q3Group_AddObjectBefore,
// which the class does not replace, and Q3Group_AddObject on an empty group,
// which gets Q3's own behaviour since the method itself is running.
TQ3GroupPosition addFirst(TQ3GroupObject group, TQ3Object object)
{
    ++g_seen.added;
    TQ3GroupPosition first = nullptr;
    if (Q3Group_GetFirstPosition(group, &first) != kQ3Success)
        return nullptr;
    return first == nullptr ? Q3Group_AddObject(group, object) : Q3Group_AddObjectBefore(group, first, object);
}

// Counts 100 more than Q3 does.
TQ3Status countPlus100(TQ3GroupObject group, TQ3ObjectType isType, unsigned long* nObjects)
{
    ++g_seen.counted;
    g_seen.countedType = isType;
    if (Q3Group_CountObjectsOfType(group, isType, nObjects) != kQ3Success)
        return kQ3Failure;
    *nObjects += 100;
    return kQ3Success;
}

// Refuses to be emptied.
TQ3Status refuseEmpty(TQ3GroupObject, TQ3ObjectType)
{
    ++g_seen.emptied;
    Q3XError_Post(kQ3ErrorAccessRestricted);
    return kQ3Failure;
}

TQ3Object removeCounted(TQ3GroupObject group, TQ3GroupPosition position)
{
    ++g_seen.removed;
    return Q3Group_RemovePosition(group, position);
}

TQ3XFunctionPointer stackMetaHandler(TQ3XMethodType type)
{
    switch (type) {
    case kQ3XMethodType_GroupAddObject:
        return fn(&addFirst);
    case kQ3XMethodType_GroupCountObjectsOfType:
        return fn(&countPlus100);
    case kQ3XMethodType_GroupEmptyObjectsOfType:
        return fn(&refuseEmpty);
    case kQ3XMethodType_GroupRemovePosition:
        return fn(&removeCounted);
    default:
        return nullptr;
    }
}

// Draws only the group's last object (a level-of-detail choice), through
// the iterate methods; the iterator holds the position drawn.
TQ3Status startWithLast(TQ3GroupObject group, TQ3GroupPosition* iterator, TQ3Object* object, TQ3ViewObject)
{
    ++g_seen.started;
    *object = nullptr;
    if (Q3Group_GetLastPosition(group, iterator) != kQ3Success || *iterator == nullptr)
        return kQ3Success;
    return Q3Group_GetPositionObject(group, *iterator, object);
}

TQ3Status endAfterOne(TQ3GroupObject, TQ3GroupPosition* iterator, TQ3Object* object, TQ3ViewObject)
{
    ++g_seen.ended;
    g_seen.iterated.push_back(*object);
    Q3Object_Dispose(*object); // the reference startWithLast took
    *object = nullptr;
    *iterator = nullptr;
    return kQ3Success;
}

TQ3XFunctionPointer lastOnlyMetaHandler(TQ3XMethodType type)
{
    switch (type) {
    case kQ3XMethodType_GroupStartIterate:
        return fn(&startWithLast);
    case kQ3XMethodType_GroupEndIterate:
        return fn(&endAfterOne);
    default:
        return nullptr;
    }
}

TQ3Status endRead(TQ3GroupObject)
{
    ++g_seen.endRead;
    return g_seen.failEndRead ? kQ3Failure : kQ3Success;
}

TQ3XFunctionPointer layerMetaHandler(TQ3XMethodType type)
{
    return type == kQ3XMethodType_GroupEndRead ? fn(&endRead) : nullptr;
}

TQ3GeometryObject newTriangle(float x)
{
    TQ3TriangleData data{};
    data.vertices[0].point = {x, 0, 0};
    data.vertices[1].point = {x + 1, 0, 0};
    data.vertices[2].point = {x, 1, 0};
    return Q3Triangle_New(&data);
}

TQ3GeometryObject newBoxAt(float x)
{
    TQ3BoxData data{};
    data.origin = {x, 0, 0};
    data.orientation = {1, 0, 0};
    data.majorAxis = {0, 1, 0};
    data.minorAxis = {0, 0, 1};
    return Q3Box_New(&data);
}

unsigned long countOf(TQ3GroupObject group)
{
    unsigned long n = 0;
    EXPECT_EQ(Q3Group_CountObjects(group, &n), kQ3Success);
    return n;
}

class CustomGroupApiTest : public OwningApiTest {
protected:
    void SetUp() override
    {
        OwningApiTest::SetUp();
        forgetWhatMethodsSaw();
    }

    /// Registers a class; the test unregisters it (after disposing its
    /// objects) through unregister().
    TQ3XObjectClass registerClass(TQ3ObjectType parent, const char* name, TQ3XMetaHandler metaHandler,
                                  unsigned long instanceSize = 0, TQ3ObjectType* type = nullptr)
    {
        std::string copy = name;
        TQ3ObjectType made = 0;
        TQ3XObjectClass registered =
            Q3XObjectHierarchy_RegisterClass(parent, &made, copy.data(), metaHandler, nullptr, 0, instanceSize);
        EXPECT_NE(registered, nullptr) << name;
        if (type != nullptr)
            *type = made;
        return registered;
    }

    void unregister(TQ3XObjectClass registered)
    {
        EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(registered), kQ3Success);
    }
};

TEST_F(CustomGroupApiTest, RegistersUnderEveryGroupClassAndKeepsItsParentsRules)
{
    struct Case {
        TQ3ObjectType parent;
        const char* name;
        bool takesBox, takesLight, takesString, drawable;
    };
    const Case cases[] = {
        {kQ3ShapeTypeGroup, "Test:PlainGroup", true, true, true, false},
        {kQ3GroupTypeDisplay, "Test:DisplayGroup", true, true, false, true},
        {kQ3DisplayGroupTypeOrdered, "Test:OrderedGroup", true, true, false, true},
        {kQ3DisplayGroupTypeIOProxy, "Test:ProxyGroup", true, true, false, true},
        {kQ3GroupTypeLight, "Test:LightGroup", false, true, false, false},
        {kQ3GroupTypeInfo, "Test:InfoGroup", false, false, true, false},
    };
    TQ3GeometryObject box = own(newBox());
    TQ3LightData lightData{};
    lightData.isOn = kQ3True;
    lightData.brightness = 1.0f;
    lightData.color = {1, 1, 1};
    TQ3LightObject light = own(Q3AmbientLight_New(&lightData));
    TQ3StringObject text = own(Q3CString_New("a string"));
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        TQ3ObjectType type = 0;
        TQ3XObjectClass registered = registerClass(c.parent, c.name, nullptr, 0, &type);
        ASSERT_NE(registered, nullptr);
        TQ3Object group = Q3XObjectHierarchy_NewObject(registered, nullptr);
        ASSERT_NE(group, nullptr);
        EXPECT_EQ(Q3Object_GetLeafType(group), type);
        EXPECT_EQ(Q3Object_IsType(group, c.parent), kQ3True);
        EXPECT_EQ(Q3Object_IsType(group, kQ3ShapeTypeGroup), kQ3True);
        EXPECT_EQ(Q3Object_IsDrawable(group), c.drawable ? kQ3True : kQ3False);
        const std::pair<TQ3Object, bool> members[] = {{box, c.takesBox}, {light, c.takesLight}, {text, c.takesString}};
        unsigned long expected = 0;
        for (const auto& [object, takes] : members) {
            if (takes) {
                EXPECT_NE(Q3Group_AddObject(group, object), nullptr);
                ++expected;
            } else {
                EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(group, object), nullptr), kQ3ErrorInvalidObjectForGroup);
            }
        }
        EXPECT_EQ(countOf(group), expected);
        // Its duplicate is of the class, with the same objects.
        TQ3Object copy = Q3Object_Duplicate(group);
        ASSERT_NE(copy, nullptr);
        EXPECT_EQ(Q3Object_GetLeafType(copy), type);
        EXPECT_EQ(countOf(copy), expected);
        // No unregistering while groups of the class live.
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3XObjectHierarchy_UnregisterClass(registered), kQ3Failure),
                        kQ3ErrorObjectClassInUse);
        Q3Object_Dispose(copy);
        Q3Object_Dispose(group);
        unregister(registered);
    }
}

TEST_F(CustomGroupApiTest, TheAcceptMethodDecidesWhatTheGroupHolds)
{
    TQ3XObjectClass registered = registerClass(kQ3ShapeTypeGroup, "Test:Triangles", triangleMetaHandler);
    TQ3Object group = Q3XObjectHierarchy_NewObject(registered, nullptr);
    ASSERT_NE(group, nullptr);
    TQ3GeometryObject triangle = own(newTriangle(0));
    TQ3GeometryObject box = own(newBox());
    TQ3GroupPosition position = Q3Group_AddObject(group, triangle);
    EXPECT_NE(position, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(group, box), nullptr), kQ3ErrorInvalidObjectForGroup);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_SetPositionObject(group, position, box), kQ3Failure),
                    kQ3ErrorInvalidObjectForGroup);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObjectAfter(group, position, box), nullptr), kQ3ErrorInvalidObjectForGroup);
    EXPECT_EQ(g_seen.accepted, 1);
    EXPECT_EQ(g_seen.refused, 3);
    EXPECT_EQ(countOf(group), 1u);
    // Whatever the method says, a group never holds itself.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(group, group), nullptr), kQ3ErrorInvalidObjectForGroup);
    Q3Object_Dispose(group);
    unregister(registered);
}

TEST_F(CustomGroupApiTest, PositionDataAreMadeCopiedAndDeletedByTheClass)
{
    TQ3XObjectClass registered = registerClass(kQ3GroupTypeDisplay, "Test:Recorded", recordingMetaHandler,
                                               sizeof(GroupRecord));
    TQ3Object group = Q3XObjectHierarchy_NewObject(registered, nullptr);
    ASSERT_NE(group, nullptr);
    auto* own = static_cast<GroupRecord*>(Q3XObjectClass_GetPrivate(registered, group));
    ASSERT_NE(own, nullptr);
    own->tag = 7;
    TQ3GeometryObject box = newBox();
    TQ3GeometryObject triangle = newTriangle(0);
    TQ3GroupPosition first = Q3Group_AddObject(group, box);
    TQ3GroupPosition second = Q3Group_AddObject(group, triangle);
    ASSERT_NE(first, nullptr);
    ASSERT_NE(second, nullptr);
    EXPECT_EQ(g_seen.made, 2);
    EXPECT_EQ(g_seen.initData, own); // the group's data for the class
    const auto* atFirst = static_cast<const PositionRecord*>(Q3XGroup_GetPositionPrivate(group, first));
    const auto* atSecond = static_cast<const PositionRecord*>(Q3XGroup_GetPositionPrivate(group, second));
    ASSERT_NE(atFirst, nullptr);
    ASSERT_NE(atSecond, nullptr);
    EXPECT_EQ(atFirst->serial, 1);
    EXPECT_EQ(atFirst->type, kQ3GeometryTypeBox);
    EXPECT_EQ(atSecond->serial, 2);
    EXPECT_EQ(atSecond->type, kQ3GeometryTypeTriangle);

    // Setting a position's object keeps the position and its data.
    TQ3GeometryObject other = newTriangle(3);
    EXPECT_EQ(Q3Group_SetPositionObject(group, first, other), kQ3Success);
    EXPECT_EQ(Q3XGroup_GetPositionPrivate(group, first), atFirst);
    EXPECT_EQ(atFirst->serial, 1);
    EXPECT_EQ(g_seen.made, 2);

    // A failing new method: nothing added, nothing else made or deleted.
    TQ3PointData pointData{};
    TQ3GeometryObject point = Q3Point_New(&pointData);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_AddObject(group, point), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_EQ(countOf(group), 2u);
    EXPECT_EQ(g_seen.deleted, 0);

    // A duplicate's positions are copied by the copy method; the
    // original's stay as they were.
    TQ3Object copy = Q3Object_Duplicate(group);
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(g_seen.copied, 2);
    TQ3GroupPosition copyFirst = nullptr;
    ASSERT_EQ(Q3Group_GetFirstPosition(copy, &copyFirst), kQ3Success);
    const auto* copied = static_cast<const PositionRecord*>(Q3XGroup_GetPositionPrivate(copy, copyFirst));
    ASSERT_NE(copied, nullptr);
    EXPECT_EQ(copied->serial, 101);
    EXPECT_EQ(copied->type, kQ3GeometryTypeBox);
    EXPECT_EQ(atFirst->serial, 1);

    // Removing a position deletes its data; disposing the groups deletes
    // the rest.
    TQ3Object removed = Q3Group_RemovePosition(group, second);
    EXPECT_EQ(removed, triangle);
    Q3Object_Dispose(removed);
    EXPECT_EQ(g_seen.deleted, 1);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XGroup_GetPositionPrivate(group, second), nullptr), kQ3ErrorInvalidPositionForGroup);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XGroup_GetPositionPrivate(group, nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XGroup_GetPositionPrivate(group, copyFirst), nullptr),
                    kQ3ErrorInvalidPositionForGroup);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XGroup_GetPositionPrivate(box, first), nullptr), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(copy);
    EXPECT_EQ(g_seen.deleted, 3);
    Q3Object_Dispose(group);
    EXPECT_EQ(g_seen.deleted, 4);
    unregister(registered);
    for (TQ3Object object : {box, triangle, other, point})
        Q3Object_Dispose(object);
}

TEST_F(CustomGroupApiTest, GroupsOfQ3sClassesKeepNoPositionData)
{
    TQ3GroupObject group = own(Q3DisplayGroup_New());
    TQ3GroupPosition position = Q3Group_AddObject(group, own(newBox()));
    ASSERT_NE(position, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XGroup_GetPositionPrivate(group, position), nullptr), kQ3ErrorInvalidObjectClass);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3XGroup_GetPositionPrivate(nullptr, position), nullptr), kQ3ErrorNULLParameter);
}

TEST_F(CustomGroupApiTest, ReplacedCallsReachTheClassAndQ3sOwnBehaviourThroughIt)
{
    TQ3XObjectClass registered = registerClass(kQ3ShapeTypeGroup, "Test:Stack", stackMetaHandler);
    TQ3Object group = Q3XObjectHierarchy_NewObject(registered, nullptr);
    ASSERT_NE(group, nullptr);
    TQ3GeometryObject a = own(newBoxAt(0));
    TQ3GeometryObject b = own(newTriangle(0));
    TQ3GeometryObject c = own(newBoxAt(2));
    for (TQ3Object object : {a, b, c})
        EXPECT_NE(Q3Group_AddObject(group, object), nullptr);
    EXPECT_EQ(g_seen.added, 3);
    // The stack order: last added first.
    const std::vector<TQ3Object> order = membersOf(group);
    EXPECT_EQ(order, (std::vector<TQ3Object>{c, b, a}));
    disposeAll(order);
    TQ3GroupPosition position = nullptr;

    // The untyped count goes to the OfType method with kQ3ObjectTypeShared.
    unsigned long n = 0;
    EXPECT_EQ(Q3Group_CountObjects(group, &n), kQ3Success);
    EXPECT_EQ(n, 103u);
    EXPECT_EQ(g_seen.countedType, kQ3ObjectTypeShared);
    EXPECT_EQ(Q3Group_CountObjectsOfType(group, kQ3GeometryTypeBox, &n), kQ3Success);
    EXPECT_EQ(n, 102u);
    EXPECT_EQ(g_seen.countedType, kQ3GeometryTypeBox);
    EXPECT_EQ(g_seen.counted, 2);
    // Q3 still checks the output pointer before calling the method.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_CountObjects(group, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_EQ(g_seen.counted, 2);

    // The class refuses to be emptied, with its own error.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_EmptyObjects(group), kQ3Failure), kQ3ErrorAccessRestricted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Group_EmptyObjectsOfType(group, kQ3GeometryTypeBox), kQ3Failure),
                    kQ3ErrorAccessRestricted);
    EXPECT_EQ(g_seen.emptied, 2);
    EXPECT_EQ(Q3Group_CountObjectsOfType(group, kQ3ObjectTypeShared, &n), kQ3Success);
    EXPECT_EQ(n, 103u);

    // Removal goes through the class, which removes through Q3.
    ASSERT_EQ(Q3Group_GetFirstPosition(group, &position), kQ3Success);
    TQ3Object removed = Q3Group_RemovePosition(group, position);
    EXPECT_EQ(removed, c);
    Q3Object_Dispose(removed);
    EXPECT_EQ(g_seen.removed, 1);

    // A group of Q3's class is untouched by any of this.
    TQ3GroupObject plain = own(Q3Group_New());
    EXPECT_NE(Q3Group_AddObject(plain, a), nullptr);
    EXPECT_NE(Q3Group_AddObject(plain, b), nullptr);
    EXPECT_EQ(Q3Group_CountObjects(plain, &n), kQ3Success);
    EXPECT_EQ(n, 2u);
    EXPECT_EQ(g_seen.added, 3);
    Q3Object_Dispose(group);
    unregister(registered);
}

TEST_F(CustomGroupApiTest, ADisplayGroupClassDrawsWhatItsIterateMethodsPassBack)
{
    TQ3XObjectClass lastOnly = registerClass(kQ3GroupTypeDisplay, "Test:LastOnly", lastOnlyMetaHandler);
    TQ3XObjectClass plainClass = registerClass(kQ3GroupTypeDisplay, "Test:AllOfThem", nullptr);
    TQ3Object chooser = Q3XObjectHierarchy_NewObject(lastOnly, nullptr);
    TQ3Object plain = Q3XObjectHierarchy_NewObject(plainClass, nullptr);
    ASSERT_NE(chooser, nullptr);
    ASSERT_NE(plain, nullptr);
    TQ3GeometryObject near = own(newBoxAt(0));
    TQ3GeometryObject far = own(newBoxAt(5));
    for (TQ3Object group : {chooser, plain}) {
        EXPECT_NE(Q3Group_AddObject(group, near), nullptr);
        EXPECT_NE(Q3Group_AddObject(group, far), nullptr);
    }
    // The unit box at x: [x, x+1] in x, [0, 1] in y and z.
    const TQ3BoundingBox chosen = boundsOf([&](TQ3ViewObject view) { Q3Object_Submit(chooser, view); });
    EXPECT_EQ(chosen.isEmpty, kQ3False);
    EXPECT_FLOAT_EQ(chosen.min.x, 5.0f);
    EXPECT_FLOAT_EQ(chosen.max.x, 6.0f);
    EXPECT_GE(g_seen.started, 1);
    EXPECT_EQ(g_seen.ended, g_seen.started);
    ASSERT_FALSE(g_seen.iterated.empty());
    for (TQ3Object drawn : g_seen.iterated)
        EXPECT_EQ(drawn, far);
    // Without the iterate methods every object draws, as in its parent.
    const TQ3BoundingBox all = boundsOf([&](TQ3ViewObject view) { Q3Object_Submit(plain, view); });
    EXPECT_FLOAT_EQ(all.min.x, 0.0f);
    EXPECT_FLOAT_EQ(all.max.x, 6.0f);
    Q3Object_Dispose(chooser);
    Q3Object_Dispose(plain);
    unregister(lastOnly);
    unregister(plainClass);
}

TEST_F(CustomGroupApiTest, PickHitsNameThePositionTheIterateMethodsDrew)
{
    TQ3XObjectClass lastOnly = registerClass(kQ3GroupTypeDisplay, "Test:PickLast", lastOnlyMetaHandler);
    TQ3Object chooser = Q3XObjectHierarchy_NewObject(lastOnly, nullptr);
    ASSERT_NE(chooser, nullptr);
    // Two triangles on the ray's line (the z axis through x = y = 0.25):
    // only the last is drawn, so only it is hit.
    TQ3GeometryObject first = own(newTriangle(0));
    TQ3GeometryObject last = own(newTriangle(0));
    EXPECT_NE(Q3Group_AddObject(chooser, first), nullptr);
    const TQ3GroupPosition lastPosition = Q3Group_AddObject(chooser, last);
    ASSERT_NE(lastPosition, nullptr);
    TQ3WorldRayPickData ray{};
    ray.data.sort = kQ3PickSortNearToFar;
    ray.data.mask = kQ3PickDetailMaskObject | kQ3PickDetailMaskPath;
    ray.data.numHitsToReturn = kQ3ReturnAllHits;
    ray.ray.origin = {0.25f, 0.25f, 5};
    ray.ray.direction = {0, 0, -1};
    TQ3PickObject pick = Q3WorldRayPick_New(&ray); // its hits hold the group: disposed before unregistering
    ASSERT_EQ(Q3View_StartPicking(view(), pick), kQ3Success);
    TQ3ViewStatus status;
    do {
        Q3Object_Submit(chooser, view());
        status = Q3View_EndPicking(view());
    } while (status == kQ3ViewStatusRetraverse);
    EXPECT_EQ(status, kQ3ViewStatusDone);
    unsigned long hits = 0;
    ASSERT_EQ(Q3Pick_GetNumHits(pick, &hits), kQ3Success);
    ASSERT_EQ(hits, 1u);
    TQ3Object hit = nullptr;
    ASSERT_EQ(Q3Pick_GetPickDetailData(pick, 0, kQ3PickDetailMaskObject, &hit), kQ3Success);
    EXPECT_EQ(hit, last);
    Q3Object_Dispose(hit);
    TQ3HitPath path{};
    ASSERT_EQ(Q3Pick_GetPickDetailData(pick, 0, kQ3PickDetailMaskPath, &path), kQ3Success);
    EXPECT_EQ(path.rootGroup, chooser);
    ASSERT_EQ(path.depth, 1u);
    EXPECT_EQ(path.positions[0], lastPosition);
    EXPECT_EQ(Q3HitPath_EmptyData(&path), kQ3Success);
    Q3Object_Dispose(pick);
    Q3Object_Dispose(chooser);
    unregister(lastOnly);
}

TEST_F(CustomGroupApiTest, AGroupClassRoundTripsThrough3DMFUnderItsName)
{
    TQ3ObjectType type = 0;
    TQ3XObjectClass registered = registerClass(kQ3GroupTypeDisplay, "Test:LayerGroup", layerMetaHandler, 0, &type);
    TQ3Object group = Q3XObjectHierarchy_NewObject(registered, nullptr);
    ASSERT_NE(group, nullptr);
    TQ3GeometryObject box = own(newBoxAt(0));
    TQ3GeometryObject triangle = own(newTriangle(2));
    EXPECT_NE(Q3Group_AddObject(group, box), nullptr);
    EXPECT_NE(Q3Group_AddObject(group, triangle), nullptr);
    const TQ3DisplayGroupState state = kQ3DisplayGroupStateMaskIsDrawn | kQ3DisplayGroupStateMaskIsInline |
                                       kQ3DisplayGroupStateMaskIsPicked | kQ3DisplayGroupStateMaskIsWritten;
    EXPECT_EQ(Q3DisplayGroup_SetState(group, state), kQ3Success);

    for (TQ3FileMode mode : {TQ3FileMode(kQ3FileModeNormal | kQ3FileModeText), TQ3FileMode(kQ3FileModeNormal),
                             TQ3FileMode(kQ3FileModeStream)}) {
        SCOPED_TRACE(mode);
        g_seen.endRead = 0;
        const std::vector<unsigned char> bytes = writeObjects({group}, mode);
        if (mode & kQ3FileModeText) {
            const std::string text(bytes.begin(), bytes.end());
            EXPECT_NE(text.find("BeginGroup"), std::string::npos);
            EXPECT_NE(text.find("Test:LayerGroup"), std::string::npos) << text;
        }
        const std::vector<TQ3Object> read = readAll(bytes);
        ASSERT_EQ(read.size(), 1u);
        EXPECT_EQ(Q3Object_GetLeafType(read[0]), type);
        EXPECT_EQ(g_seen.endRead, 1);
        EXPECT_EQ(countOf(read[0]), 2u);
        unsigned long boxes = 0;
        EXPECT_EQ(Q3Group_CountObjectsOfType(read[0], kQ3GeometryTypeBox, &boxes), kQ3Success);
        EXPECT_EQ(boxes, 1u);
        TQ3DisplayGroupState readState = 0;
        EXPECT_EQ(Q3DisplayGroup_GetState(read[0], &readState), kQ3Success);
        EXPECT_EQ(readState, state);
        disposeAll(read);
    }

    // A failing end-read method fails the read.
    const std::vector<unsigned char> text = writeObjects({group}, kQ3FileModeNormal | kQ3FileModeText);
    g_seen.failEndRead = true;
    EXPECT_READ_ERROR(text, kQ3ErrorInvalidMetafileObject);
    g_seen.failEndRead = false;

    // Not registered: a display group with the same objects, and a warning
    // naming the class; the unknown object is kept and written back.
    Q3Object_Dispose(group);
    unregister(registered);
    std::vector<TQ3Object> read;
    EXPECT_Q3_WARNING(read = readAll(text), kQ3WarningUnknownObject);
    consume(q3test::Kind::Warning, kQ3WarningInvalidSubObjectForObject, "the display group in its place", __FILE__,
            __LINE__);
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(Q3Object_IsType(read[0], kQ3GroupTypeDisplay), kQ3True);
    EXPECT_EQ(countOf(read[0]), 2u);
    const std::vector<unsigned char> again = writeObjects({read[0]}, kQ3FileModeNormal | kQ3FileModeText);
    const std::string written(again.begin(), again.end());
    EXPECT_NE(written.find("Test:LayerGroup"), std::string::npos) << written;
    disposeAll(read);
}

TEST_F(CustomGroupApiTest, AGroupClassWithoutReadMethodReadsNoDataOfItsOwn)
{
    // A class registered under the name a file uses: with no read method,
    // the group is made as Q3XObjectHierarchy_NewObject makes it.
    TQ3ObjectType type = 0;
    TQ3XObjectClass registered = registerClass(kQ3ShapeTypeGroup, "Test:Folder", nullptr, 0, &type);
    const std::string file = "3DMetafile ( 1 6 Normal )\n"
                             "BeginGroup ( Test:Folder ( ) )\n"
                             "  CString ( \"inside\" )\n"
                             "EndGroup ( )\n";
    const std::vector<TQ3Object> read = readAll(bytesOf(file));
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(Q3Object_GetLeafType(read[0]), type);
    EXPECT_EQ(countOf(read[0]), 1u);
    disposeAll(read);
    unregister(registered);
}

} // namespace
