// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "core/AttributeSet.h"
#include "core/ErrorManager.h"
#include "core/Object.h"
#include "style/SubdivisionStyle.h"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace q3 {
namespace {

TEST(CoreClassInfo, TypeAtLevelWalksFromTheRoot)
{
    AttributeSet set;
    EXPECT_EQ(set.classInfo().typeAtLevel(1), kQ3ObjectTypeShared);
    EXPECT_EQ(set.classInfo().typeAtLevel(2), kQ3SharedTypeSet);
    EXPECT_EQ(set.classInfo().typeAtLevel(3), kQ3SetTypeAttribute);
    EXPECT_EQ(set.classInfo().typeAtLevel(4), kQ3ObjectTypeInvalid);
    EXPECT_EQ(set.classInfo().typeAtLevel(0), kQ3ObjectTypeInvalid);
    EXPECT_TRUE(set.isType(kQ3ObjectTypeShared));
    EXPECT_FALSE(set.isType(kQ3SharedTypeShape));
}

TEST(CoreRegistry, MakeSharedRegistersAndLastReleaseUnregisters)
{
    const unsigned long before = liveObjectCount();
    TQ3Object handle = nullptr;
    {
        Ref<AttributeSet> set = makeShared<AttributeSet>();
        handle = set->handle();
        EXPECT_EQ(liveObjectCount(), before + 1);
        EXPECT_EQ(&lookupObject(handle, "h"), set.get());
        Ref<AttributeSet> second = set;
        EXPECT_EQ(set->referenceCount(), 2u);
    }
    EXPECT_EQ(liveObjectCount(), before);
    try {
        lookupObject(handle, "h");
        FAIL() << "a released handle was accepted";
    } catch (const Error& error) {
        EXPECT_EQ(error.code(), kQ3ErrorInvalidObject);
    }
}

TEST(CoreRegistry, LookupRejectsNullStrayAndWrongClass)
{
    int notAnObject = 0;
    auto codeOf = [](auto&& call) {
        try {
            call();
        } catch (const Error& error) {
            return error.code();
        }
        return kQ3ErrorNone;
    };
    EXPECT_EQ(codeOf([] { lookupObject(nullptr, "h"); }), kQ3ErrorNULLParameter);
    EXPECT_EQ(codeOf([&] { lookupObject(reinterpret_cast<TQ3Object>(&notAnObject), "h"); }),
              kQ3ErrorInvalidObject);
    Ref<AttributeSet> set = makeShared<AttributeSet>();
    EXPECT_EQ(codeOf([&] { lookup<SubdivisionStyle>(set->handle(), "h"); }), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(&lookup<AttributeSet>(set->handle(), "h"), set.get());
}

TEST(CoreSharedObject, EveryEditGivesANewEditIndex)
{
    Ref<AttributeSet> set = makeShared<AttributeSet>();
    const unsigned long first = set->editIndex();
    set->markEdited();
    const unsigned long second = set->editIndex();
    EXPECT_NE(first, second);
    Ref<AttributeSet> other = makeShared<AttributeSet>();
    EXPECT_NE(other->editIndex(), second);
}

// The orderings themselves are for ThreadSanitizer to check; this checks the
// counting: references taken and dropped on several threads at once balance,
// and whichever thread drops the last one deletes the object.
TEST(CoreSharedObject, ReferencesTakenAndDroppedOnSeveralThreadsBalance)
{
    constexpr int kThreads = 4;
    constexpr int kCopies = 20000;
    const unsigned long before = liveObjectCount();
    Ref<AttributeSet> set = makeShared<AttributeSet>();
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([held = set] {
            for (int i = 0; i < kCopies; ++i) {
                Ref<AttributeSet> copy = held;
                EXPECT_GE(copy->referenceCount(), 2u);
            }
        });
    set.reset();
    for (std::thread& thread : threads)
        thread.join();
    EXPECT_EQ(liveObjectCount(), before);
}

TEST(CoreErrorManager, BeginCallForgetsThePreviousCallsPosts)
{
    errors::beginCall();
    errors::postError(kQ3ErrorInvalidData, "first");
    errors::postError(kQ3ErrorNULLParameter, "second");
    TQ3Error first = kQ3ErrorNone;
    EXPECT_EQ(errors::latestError(&first), kQ3ErrorNULLParameter);
    EXPECT_EQ(first, kQ3ErrorInvalidData);
    EXPECT_STREQ(errors::errorMessage(), "second");
    errors::beginCall();
    EXPECT_EQ(errors::latestError(&first), kQ3ErrorNone);
    EXPECT_EQ(first, kQ3ErrorNone);
}

TEST(CoreErrorManager, PostsStayOnTheThreadThatMadeThem)
{
    errors::beginCall();
    std::thread other([] {
        errors::beginCall();
        errors::postWarning(kQ3WarningParameterOutOfRange, "elsewhere");
    });
    other.join();
    EXPECT_EQ(errors::latestWarning(nullptr), kQ3WarningNone);
}

} // namespace
} // namespace q3
