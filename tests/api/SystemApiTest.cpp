// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "Q3ApiTest.h"

#include "QD3DSet.h"

#include <cstdlib>
#include <cstring>

namespace {

using q3test::Q3ApiTest;
using SystemApiTest = Q3ApiTest;

TEST(SystemApiUninitialized, EveryCallBeforeInitializeFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    EXPECT_EQ(Q3AttributeSet_New(), nullptr);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_EQ(Q3Exit(), kQ3Failure);
    EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNotInitialized);
    EXPECT_STRNE(Q3Error_GetMessage(), "");
}

// Q3Initialize pins Mesa's environment (docs/threads.md: it is the call made at
// program start, before threads). Checked in a fresh process ("threadsafe" death
// tests re-execute the test binary), since pinning happens once per process.
TEST(SystemApiEnvironment, InitializePinsTheMesaEnvironmentBeforeAnyRendering)
{
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(
        {
            setenv("GALLIUM_DRIVER", "softpipe", 1);
            setenv("LP_NO_RAST", "1", 1);
            Q3Initialize();
            const char* driver = getenv("GALLIUM_DRIVER");
            const bool pinned = driver != nullptr && std::strcmp(driver, "llvmpipe") == 0 &&
                                getenv("LP_NO_RAST") == nullptr;
            Q3Exit();
            std::exit(pinned ? 0 : 1);
        },
        ::testing::ExitedWithCode(0), "");
}

TEST_F(SystemApiTest, InitializeNestsAndPostsANotice)
{
    EXPECT_Q3_NOTICE(EXPECT_EQ(Q3Initialize(), kQ3Success), kQ3NoticeSystemAlreadyInitialized);
    EXPECT_EQ(Q3Notice_Get(nullptr), kQ3NoticeSystemAlreadyInitialized);
    EXPECT_EQ(Q3Exit(), kQ3Success);
    EXPECT_EQ(Q3IsInitialized(), kQ3True);
}

TEST_F(SystemApiTest, GetVersionReportsOnePointSix)
{
    unsigned long major = 0, minor = 0;
    EXPECT_EQ(Q3GetVersion(&major, &minor), kQ3Success);
    EXPECT_EQ(major, 1u);
    EXPECT_EQ(minor, 6u);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GetVersion(nullptr, &minor), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GetVersion(&major, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
}

TEST_F(SystemApiTest, ErrorGetReturnsFirstAndLatestOfThePreviousCallOnly)
{
    EXPECT_Q3_ERROR(Q3Object_Dispose(nullptr), kQ3ErrorNULLParameter);
    TQ3Error first = kQ3ErrorNone;
    EXPECT_EQ(Q3Error_Get(&first), kQ3ErrorNULLParameter);
    EXPECT_EQ(first, kQ3ErrorNULLParameter);
    // A successful call clears what the failed one posted.
    TQ3AttributeSet set = Q3AttributeSet_New();
    ASSERT_NE(set, nullptr);
    EXPECT_EQ(Q3Error_Get(&first), kQ3ErrorNone);
    EXPECT_EQ(first, kQ3ErrorNone);
    EXPECT_STREQ(Q3Error_GetMessage(), "");
    Q3Object_Dispose(set);
}

TEST_F(SystemApiTest, IsFatalErrorIsTrueOnlyForTheFatalCodes)
{
    EXPECT_EQ(Q3Error_IsFatalError(kQ3ErrorInternalError), kQ3True);
    EXPECT_EQ(Q3Error_IsFatalError(kQ3ErrorNoRecovery), kQ3True);
    EXPECT_EQ(Q3Error_IsFatalError(kQ3ErrorLastFatalError), kQ3True);
    EXPECT_EQ(Q3Error_IsFatalError(kQ3ErrorNotInitialized), kQ3False);
    EXPECT_EQ(Q3Error_IsFatalError(kQ3ErrorNone), kQ3False);
}

TEST_F(SystemApiTest, CallbacksReceiveTheirReferenceAndFirstAndLastCodes)
{
    static long seenReference = 0;
    static TQ3Error seenFirst = kQ3ErrorNone;
    struct Local {
        static void method(TQ3Error first, TQ3Error, long reference)
        {
            seenFirst = first;
            seenReference = reference;
        }
    };
    Q3Error_Register(&Local::method, 1234);
    Q3Object_Dispose(nullptr);
    EXPECT_EQ(seenReference, 1234);
    EXPECT_EQ(seenFirst, kQ3ErrorNULLParameter);
    forgetPosted(); // our fixture's callback was replaced for this call
}

TEST_F(SystemApiTest, ExitReportsObjectsStillAlive)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    ASSERT_NE(set, nullptr);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), 1u);
    EXPECT_Q3_WARNING(EXPECT_EQ(Q3Exit(), kQ3Success), kQ3WarningPossibleMemoryLeak);
    EXPECT_STRNE(Q3Warning_GetMessage(), "");
    ASSERT_EQ(Q3Initialize(), kQ3Success);
    // The object survived the shutdown and is still usable.
    EXPECT_EQ(Q3Object_GetLeafType(set), kQ3SetTypeAttribute);
    EXPECT_EQ(Q3Object_Dispose(set), kQ3Success);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), 0u);
}

} // namespace
