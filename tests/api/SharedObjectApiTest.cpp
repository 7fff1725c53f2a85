// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Q3Object_IsWritable, edit tracking (Q3Shared_ClearEditTracking,
// Q3Shared_GetEditTrackingState) and Q3GetReleaseVersion, with bad input.

#include "Q3ApiTest.h"

#include "QD3DDrawContext.h"
#include "QD3DGeometry.h"
#include "QD3DIO.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DStorage.h"
#include "QD3DView.h"

namespace {

using q3test::Q3ApiTest;

TQ3GeometryObject newBox()
{
    const TQ3BoxData data{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, nullptr, nullptr};
    return Q3Box_New(&data);
}

class SharedObjectApiTest : public Q3ApiTest {
protected:
    void SetUp() override
    {
        Q3ApiTest::SetUp();
        m_box = newBox();
        m_file = Q3File_New();
        ASSERT_NE(m_box, nullptr);
        ASSERT_NE(m_file, nullptr);
    }
    void TearDown() override
    {
        Q3Object_Dispose(m_box);
        Q3Object_Dispose(m_file);
        Q3ApiTest::TearDown();
    }
    TQ3GeometryObject m_box = nullptr;
    TQ3FileObject m_file = nullptr;
};

TEST_F(SharedObjectApiTest, GetReleaseVersionIsOnePointSixFinal)
{
    unsigned long release = 0;
    ASSERT_EQ(Q3GetReleaseVersion(&release), kQ3Success);
    EXPECT_EQ(release, 0x01608000ul);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3GetReleaseVersion(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
}

TEST_F(SharedObjectApiTest, ObjectsWithA3DMFFormAreWritable)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    TQ3RendererObject renderer = Q3Renderer_NewFromType(kQ3RendererTypeInteractive);
    TQ3StorageObject storage = Q3MemoryStorage_New(nullptr, 0);
    TQ3ViewObject view = Q3View_New();
    EXPECT_EQ(Q3Object_IsWritable(m_box, m_file), kQ3True);
    EXPECT_EQ(Q3Object_IsWritable(set, m_file), kQ3True);
    EXPECT_EQ(Q3Object_IsWritable(renderer, m_file), kQ3False);
    EXPECT_EQ(Q3Object_IsWritable(storage, m_file), kQ3False);
    EXPECT_EQ(Q3Object_IsWritable(view, m_file), kQ3False);
    EXPECT_EQ(Q3Object_IsWritable(m_file, m_file), kQ3False);
    Q3Object_Dispose(set);
    Q3Object_Dispose(renderer);
    Q3Object_Dispose(storage);
    Q3Object_Dispose(view);
}

TEST_F(SharedObjectApiTest, IsWritableRejectsBadObjectsAndFiles)
{
    TQ3GeometryObject dead = newBox();
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_IsWritable(nullptr, m_file), kQ3False), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_IsWritable(dead, m_file), kQ3False), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_IsWritable(m_box, nullptr), kQ3False), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_IsWritable(m_box, dead), kQ3False), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_IsWritable(m_box, m_box), kQ3False), kQ3ErrorInvalidObjectType);
}

TEST_F(SharedObjectApiTest, EditTrackingRecordsEditsSinceItWasCleared)
{
    EXPECT_EQ(Q3Shared_GetEditTrackingState(m_box), kQ3False); // a new object
    TQ3ColorRGB red{1.0f, 0.0f, 0.0f};
    TQ3AttributeSet set = Q3AttributeSet_New();
    ASSERT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &red), kQ3Success);
    EXPECT_EQ(Q3Shared_GetEditTrackingState(set), kQ3True);

    const unsigned long index = Q3Shared_GetEditIndex(set);
    ASSERT_EQ(Q3Shared_ClearEditTracking(set), kQ3Success);
    EXPECT_EQ(Q3Shared_GetEditTrackingState(set), kQ3False);
    EXPECT_EQ(Q3Shared_GetEditIndex(set), index); // clearing is not an edit

    ASSERT_EQ(Q3Geometry_SetAttributeSet(m_box, set), kQ3Success);
    EXPECT_EQ(Q3Shared_GetEditTrackingState(m_box), kQ3True);
    ASSERT_EQ(Q3Shared_ClearEditTracking(m_box), kQ3Success);
    ASSERT_EQ(Q3Shared_Edited(m_box), kQ3Success);
    EXPECT_EQ(Q3Shared_GetEditTrackingState(m_box), kQ3True);

    // A failed edit is no edit.
    ASSERT_EQ(Q3Shared_ClearEditTracking(m_box), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Box_SetData(m_box, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_EQ(Q3Shared_GetEditTrackingState(m_box), kQ3False);
    Q3Object_Dispose(set);
}

TEST_F(SharedObjectApiTest, EditTrackingRejectsBadObjects)
{
    TQ3ViewObject view = Q3View_New();
    TQ3GeometryObject dead = newBox();
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shared_ClearEditTracking(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shared_ClearEditTracking(dead), kQ3Failure), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shared_ClearEditTracking(view), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shared_GetEditTrackingState(nullptr), kQ3False), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shared_GetEditTrackingState(dead), kQ3False), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Shared_GetEditTrackingState(view), kQ3False), kQ3ErrorInvalidObjectType);
    Q3Object_Dispose(view);
}

} // namespace
