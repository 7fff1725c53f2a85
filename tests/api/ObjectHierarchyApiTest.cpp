// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The class hierarchy queries of QD3D.h: every class Q3 registers has a
// name that leads back to it, the renderer menu a Qut front end builds, and
// bad input.

#include "Q3ApiTest.h"

#include "QD3DRenderer.h"

#include <algorithm>
#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace {

using q3test::Q3ApiTest;
using ObjectHierarchyApiTest = Q3ApiTest;

std::vector<TQ3ObjectType> subclasses(TQ3ObjectType parent)
{
    TQ3SubClassData data{};
    EXPECT_EQ(Q3ObjectHierarchy_GetSubClassData(parent, &data), kQ3Success);
    std::vector<TQ3ObjectType> types(data.classTypes, data.classTypes + data.numClasses);
    EXPECT_EQ(Q3ObjectHierarchy_EmptySubClassData(&data), kQ3Success);
    EXPECT_EQ(data.classTypes, nullptr);
    EXPECT_EQ(data.numClasses, 0u);
    return types;
}

std::string nameOf(TQ3ObjectType type)
{
    TQ3ObjectClassNameString name;
    std::memset(name, 0x7F, sizeof name);
    EXPECT_EQ(Q3ObjectHierarchy_GetStringFromType(type, name), kQ3Success);
    return name;
}

TEST_F(ObjectHierarchyApiTest, TheRendererMenuListsBothRenderers)
{
    // What every Qut front end does to build its renderer menu.
    TQ3SubClassData renderers{};
    ASSERT_EQ(Q3ObjectHierarchy_GetSubClassData(kQ3SharedTypeRenderer, &renderers), kQ3Success);
    std::vector<std::string> menu;
    for (unsigned long n = 0; n < renderers.numClasses; ++n) {
        TQ3ObjectClassNameString name = "";
        if (Q3RendererClass_GetNickNameString(renderers.classTypes[n], name) == kQ3Failure || name[0] == '\0') {
            ASSERT_EQ(Q3ObjectHierarchy_GetStringFromType(renderers.classTypes[n], name), kQ3Success);
        }
        menu.push_back(name);
    }
    ASSERT_EQ(Q3ObjectHierarchy_EmptySubClassData(&renderers), kQ3Success);
    std::sort(menu.begin(), menu.end());
    EXPECT_EQ(menu, (std::vector<std::string>{"Interactive", "Wireframe"}));

    EXPECT_EQ(nameOf(kQ3RendererTypeInteractive), "InteractiveRenderer");
    EXPECT_EQ(nameOf(kQ3RendererTypeWireFrame), "WireframeRenderer");
}

TEST_F(ObjectHierarchyApiTest, ClassesWithA3DMFFormAreNamedAsInFiles)
{
    EXPECT_EQ(nameOf(kQ3GeometryTypeBox), "Box");
    EXPECT_EQ(nameOf(kQ3GeometryTypeTriMesh), "TriMesh");
    EXPECT_EQ(nameOf(kQ3GeometryTypeNURBCurve), "NURBCurve");
    EXPECT_EQ(nameOf(kQ3SetTypeAttribute), "AttributeSet");
    EXPECT_EQ(nameOf(kQ3DrawContextTypePixmap), "PixmapDrawContext");
    TQ3ObjectType type = kQ3ObjectTypeInvalid;
    TQ3ObjectClassNameString box = "Box";
    ASSERT_EQ(Q3ObjectHierarchy_GetTypeFromString(box, &type), kQ3Success);
    EXPECT_EQ(type, kQ3GeometryTypeBox);
    EXPECT_EQ(Q3ObjectHierarchy_IsNameRegistered("TriMesh"), kQ3True);
    EXPECT_EQ(Q3ObjectHierarchy_IsNameRegistered("trimesh"), kQ3False); // names compare exactly
    EXPECT_EQ(Q3ObjectHierarchy_IsTypeRegistered(kQ3GeometryTypeTriMesh), kQ3True);
}

TEST_F(ObjectHierarchyApiTest, EveryClassBelowTheRootHasAUniqueNameThatLeadsBackToIt)
{
    // Walk the whole tree from the two first-level classes.
    std::vector<TQ3ObjectType> pending{kQ3ObjectTypeShared, kQ3ObjectTypeView};
    std::set<TQ3ObjectType> seen;
    std::set<std::string> names;
    while (!pending.empty()) {
        const TQ3ObjectType type = pending.back();
        pending.pop_back();
        ASSERT_TRUE(seen.insert(type).second) << type << " reached twice";
        EXPECT_EQ(Q3ObjectHierarchy_IsTypeRegistered(type), kQ3True);
        const std::string name = nameOf(type);
        ASSERT_FALSE(name.empty());
        EXPECT_TRUE(names.insert(name).second) << name << " names two classes";
        EXPECT_EQ(Q3ObjectHierarchy_IsNameRegistered(name.c_str()), kQ3True);
        TQ3ObjectClassNameString copy;
        std::strcpy(copy, name.c_str());
        TQ3ObjectType back = kQ3ObjectTypeInvalid;
        ASSERT_EQ(Q3ObjectHierarchy_GetTypeFromString(copy, &back), kQ3Success);
        EXPECT_EQ(back, type) << name;
        const std::vector<TQ3ObjectType> children = subclasses(type);
        EXPECT_TRUE(std::is_sorted(children.begin(), children.end()));
        pending.insert(pending.end(), children.begin(), children.end());
    }
    EXPECT_GT(seen.size(), 60u);
    EXPECT_TRUE(seen.count(kQ3GeometryTypeNURBPatch));
    EXPECT_TRUE(seen.count(kQ3StorageTypeMemory));

    // A leaf has no subclasses: an empty list, no array.
    TQ3SubClassData leaf{};
    ASSERT_EQ(Q3ObjectHierarchy_GetSubClassData(kQ3GeometryTypeBox, &leaf), kQ3Success);
    EXPECT_EQ(leaf.numClasses, 0u);
    EXPECT_EQ(leaf.classTypes, nullptr);
    EXPECT_EQ(Q3ObjectHierarchy_EmptySubClassData(&leaf), kQ3Success);
}

TEST_F(ObjectHierarchyApiTest, UnknownTypesAndNamesFailAndLeaveTheOutputs)
{
    const TQ3ObjectType unknown = Q3_OBJECT_TYPE('n', 'o', 'n', 'e');
    for (TQ3ObjectType type : {unknown, TQ3ObjectType(kQ3ObjectTypeInvalid), TQ3ObjectType(-1)}) {
        EXPECT_EQ(Q3ObjectHierarchy_IsTypeRegistered(type), kQ3False);
        TQ3ObjectClassNameString name = "left";
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3ObjectHierarchy_GetStringFromType(type, name), kQ3Failure),
                        kQ3ErrorInvalidParameter);
        EXPECT_STREQ(name, "left");
        TQ3SubClassData data{7, nullptr};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3ObjectHierarchy_GetSubClassData(type, &data), kQ3Failure),
                        kQ3ErrorInvalidParameter);
        EXPECT_EQ(data.numClasses, 7u);
    }
    for (const char* bad : {"", "NoSuchClass", "Box "}) {
        TQ3ObjectClassNameString name;
        std::strcpy(name, bad);
        TQ3ObjectType type = 12345;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3ObjectHierarchy_GetTypeFromString(name, &type), kQ3Failure),
                        kQ3ErrorInvalidParameter);
        EXPECT_EQ(type, 12345);
        EXPECT_EQ(Q3ObjectHierarchy_IsNameRegistered(bad), kQ3False);
    }
}

TEST_F(ObjectHierarchyApiTest, NullPointersFail)
{
    TQ3ObjectType type = 0;
    TQ3ObjectClassNameString name = "Box";
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ObjectHierarchy_GetTypeFromString(nullptr, &type), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ObjectHierarchy_GetTypeFromString(name, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ObjectHierarchy_GetStringFromType(kQ3GeometryTypeBox, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ObjectHierarchy_IsNameRegistered(nullptr), kQ3False), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ObjectHierarchy_GetSubClassData(kQ3SharedTypeRenderer, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ObjectHierarchy_EmptySubClassData(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_EQ(type, 0);
}

TEST_F(ObjectHierarchyApiTest, EveryCallNeedsQ3Initialize)
{
    ASSERT_EQ(Q3Exit(), kQ3Success);
    TQ3ObjectClassNameString name = "Box";
    TQ3ObjectType type = 0;
    TQ3SubClassData data{};
    EXPECT_EQ(Q3ObjectHierarchy_GetTypeFromString(name, &type), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3ObjectHierarchy_GetStringFromType(kQ3GeometryTypeBox, name), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3ObjectHierarchy_IsTypeRegistered(kQ3GeometryTypeBox), kQ3False);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3ObjectHierarchy_IsNameRegistered("Box"), kQ3False);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3ObjectHierarchy_GetSubClassData(kQ3SharedTypeRenderer, &data), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3ObjectHierarchy_EmptySubClassData(&data), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(type, 0);
    EXPECT_STREQ(name, "Box");
    ASSERT_EQ(Q3Initialize(), kQ3Success);
    forgetPosted(); // the NotInitialized errors, checked above
}

} // namespace
