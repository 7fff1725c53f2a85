// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The thirteen Q3Marker_* calls and Q3Bitmap_Empty/GetImageSize against
// QD3DGeometry.h and QD3D.h: the TQ3MarkerData rules in their order, the
// bitmap copied (never shared with the caller), every per-field call and
// the bound (the location). The drawing is checked by the markers scene.

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DView.h"

#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

using namespace q3test;

class MarkerApiTest : public OwningApiTest {
protected:
    void SetUp() override
    {
        OwningApiTest::SetUp();
        // 10 x 3 pixels, two bytes a row (one spare bit per row at the end).
        m_bits = {0xFF, 0xC0, 0x80, 0x40, 0xFF, 0xC0};
        m_data = TQ3MarkerData{{1, 2, 3}, -5, 4, {m_bits.data(), 10, 3, 2, kQ3EndianBig}, nullptr};
    }
    std::vector<TQ3Object> notMarkers()
    {
        const TQ3PointData point{{0, 0, 0}, nullptr};
        return {own(Q3AttributeSet_New()), view(), own(Q3Point_New(&point))};
    }
    std::vector<unsigned char> m_bits;
    TQ3MarkerData m_data{};
};

TEST_F(MarkerApiTest, NewCopiesTheBitsThatGetDataAndGetBitmapReturn)
{
    TQ3AttributeSet set = own(colorSet(1, 0, 0));
    m_data.markerAttributeSet = set;
    TQ3GeometryObject marker = own(Q3Marker_New(&m_data));
    ASSERT_NE(marker, nullptr);
    EXPECT_EQ(Q3Geometry_GetType(marker), kQ3GeometryTypeMarker);
    m_bits[0] = 0; // the caller's bits after New
    TQ3MarkerData out{};
    ASSERT_EQ(Q3Marker_GetData(marker, &out), kQ3Success);
    EXPECT_NE(out.bitmap.image, m_bits.data());
    EXPECT_EQ(out.bitmap.image[0], 0xFF);
    EXPECT_EQ(out.bitmap.image[5], 0xC0);
    EXPECT_EQ(out.bitmap.width, 10u);
    EXPECT_EQ(out.bitmap.rowBytes, 2u);
    EXPECT_EQ(out.xOffset, -5);
    EXPECT_EQ(out.yOffset, 4);
    EXPECT_EQ(out.markerAttributeSet, set);
    EXPECT_EQ(referenceCount(set), 3u);
    ASSERT_EQ(Q3Marker_EmptyData(&out), kQ3Success);
    EXPECT_EQ(out.bitmap.image, nullptr);
    EXPECT_EQ(out.markerAttributeSet, nullptr);
    EXPECT_EQ(Q3Marker_EmptyData(&out), kQ3Success);

    TQ3Bitmap bitmap{};
    ASSERT_EQ(Q3Marker_GetBitmap(marker, &bitmap), kQ3Success);
    EXPECT_EQ(bitmap.height, 3u);
    EXPECT_EQ(bitmap.image[2], 0x80);
    bitmap.image[2] = 0; // the caller's copy
    ASSERT_EQ(Q3Bitmap_Empty(&bitmap), kQ3Success);
    EXPECT_EQ(bitmap.image, nullptr);
    EXPECT_EQ(Q3Bitmap_Empty(&bitmap), kQ3Success);
    ASSERT_EQ(Q3Marker_GetBitmap(marker, &bitmap), kQ3Success);
    EXPECT_EQ(bitmap.image[2], 0x80);
    Q3Bitmap_Empty(&bitmap);
    EXPECT_Q3_ERROR(Q3Bitmap_Empty(nullptr), kQ3ErrorNULLParameter);
    EXPECT_EQ(Q3Bitmap_GetImageSize(10, 3), 6u);
    EXPECT_EQ(Q3Bitmap_GetImageSize(8, 3), 3u);
    EXPECT_EQ(Q3Bitmap_GetImageSize(0, 3), 0u);
    EXPECT_EQ(Q3Bitmap_GetImageSize(~0UL, ~0UL), 0u);
}

TEST_F(MarkerApiTest, TheRulesAreCheckedInTheirOrder)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Marker_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    TQ3MarkerData data = m_data;
    data.bitmap.image = nullptr;
    data.location.x = kNaN;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Marker_New(&data), nullptr), kQ3ErrorNULLParameter);
    for (float bad : kNonFinite) {
        data = m_data;
        data.location.z = bad;
        data.bitmap.width = 0;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Marker_New(&data), nullptr), kQ3ErrorInvalidData);
    }
    data = m_data;
    data.bitmap.width = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Marker_New(&data), nullptr), kQ3ErrorInvalidData);
    data = m_data;
    data.bitmap.height = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Marker_New(&data), nullptr), kQ3ErrorInvalidData);
    data = m_data;
    data.bitmap.width = 17; // needs three bytes a row
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Marker_New(&data), nullptr), kQ3ErrorInvalidData);
    data = m_data;
    data.bitmap.bitOrder = static_cast<TQ3Endian>(2);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Marker_New(&data), nullptr), kQ3ErrorInvalidData);
    data = m_data;
    data.bitmap.rowBytes = kQ3GeometryMaxArrayCount; // times 3 rows: never read
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Marker_New(&data), nullptr), kQ3ErrorParameterOutOfRange);
    data = m_data;
    data.markerAttributeSet = view();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Marker_New(&data), nullptr), kQ3ErrorInvalidObjectType);
    data.markerAttributeSet = deadObject();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Marker_New(&data), nullptr), kQ3ErrorInvalidObject);
    // Submit checks the view before the data.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Marker_Submit(&data, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Marker_Submit(&m_data, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Marker_Submit(nullptr, view()), kQ3Failure), kQ3ErrorNULLParameter);
    // Little-endian bits are as good.
    m_data.bitmap.bitOrder = kQ3EndianLittle;
    EXPECT_NE(own(Q3Marker_New(&m_data)), nullptr);
}

TEST_F(MarkerApiTest, PerFieldCallsReadWriteAndChangeNothingOnFailure)
{
    TQ3GeometryObject marker = own(Q3Marker_New(&m_data));
    const unsigned long edit = Q3Shared_GetEditIndex(marker);
    TQ3Point3D p{};
    long offset = 0;
    ASSERT_EQ(Q3Marker_GetPosition(marker, &p), kQ3Success);
    EXPECT_TRUE(samePoint(p, m_data.location));
    ASSERT_EQ(Q3Marker_GetXOffset(marker, &offset), kQ3Success);
    EXPECT_EQ(offset, -5);
    ASSERT_EQ(Q3Marker_GetYOffset(marker, &offset), kQ3Success);
    EXPECT_EQ(offset, 4);

    for (float bad : kNonFinite) {
        const TQ3Point3D q{bad, 0, 0};
        EXPECT_Q3_ERROR(Q3Marker_SetPosition(marker, &q), kQ3ErrorInvalidData);
    }
    TQ3Bitmap bad{m_bits.data(), 10, 3, 1, kQ3EndianBig};
    EXPECT_Q3_ERROR(Q3Marker_SetBitmap(marker, &bad), kQ3ErrorInvalidData);
    bad.image = nullptr;
    EXPECT_Q3_ERROR(Q3Marker_SetBitmap(marker, &bad), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Marker_SetBitmap(marker, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Marker_SetPosition(marker, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Marker_GetPosition(marker, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Marker_GetXOffset(marker, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Marker_GetYOffset(marker, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Marker_GetBitmap(marker, nullptr), kQ3ErrorNULLParameter);
    for (TQ3Object wrong : notMarkers()) {
        EXPECT_Q3_ERROR(Q3Marker_GetPosition(wrong, &p), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3Marker_SetXOffset(wrong, 1), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3Marker_SetYOffset(wrong, 1), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3Marker_GetData(wrong, &m_data), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3Marker_SetData(wrong, &m_data), kQ3ErrorInvalidObjectType);
    }
    EXPECT_Q3_ERROR(Q3Marker_SetXOffset(nullptr, 1), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Marker_SetYOffset(strayHandle(), 1), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3Marker_EmptyData(nullptr), kQ3ErrorNULLParameter);
    TQ3MarkerData badData = m_data;
    badData.bitmap.height = 0;
    EXPECT_Q3_ERROR(Q3Marker_SetData(marker, &badData), kQ3ErrorInvalidData);
    EXPECT_EQ(Q3Shared_GetEditIndex(marker), edit);
    ASSERT_EQ(Q3Marker_GetPosition(marker, &p), kQ3Success);
    EXPECT_TRUE(samePoint(p, m_data.location));

    const TQ3Point3D moved{-1, -2, -3};
    ASSERT_EQ(Q3Marker_SetPosition(marker, &moved), kQ3Success);
    ASSERT_EQ(Q3Marker_SetXOffset(marker, -2147483647L - 1), kQ3Success);
    ASSERT_EQ(Q3Marker_SetYOffset(marker, 77), kQ3Success);
    const unsigned char one = 0x01;
    const TQ3Bitmap single{const_cast<unsigned char*>(&one), 8, 1, 1, kQ3EndianLittle};
    ASSERT_EQ(Q3Marker_SetBitmap(marker, &single), kQ3Success);
    TQ3MarkerData out{};
    ASSERT_EQ(Q3Marker_GetData(marker, &out), kQ3Success);
    EXPECT_TRUE(samePoint(out.location, moved));
    EXPECT_EQ(out.xOffset, -2147483647L - 1);
    EXPECT_EQ(out.yOffset, 77);
    EXPECT_EQ(out.bitmap.width, 8u);
    EXPECT_EQ(out.bitmap.bitOrder, kQ3EndianLittle);
    EXPECT_EQ(out.bitmap.image[0], 0x01);
    Q3Marker_EmptyData(&out);
    EXPECT_GT(Q3Shared_GetEditIndex(marker), edit);

    ASSERT_EQ(Q3Marker_SetData(marker, &m_data), kQ3Success);
    ASSERT_EQ(Q3Marker_GetXOffset(marker, &offset), kQ3Success);
    EXPECT_EQ(offset, -5);
}

TEST_F(MarkerApiTest, TheBoundIsTheLocationAndAMarkerIsItsOwnDecomposition)
{
    TQ3GeometryObject marker = own(Q3Marker_New(&m_data));
    const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) { Q3Geometry_Submit(marker, v); });
    EXPECT_TRUE(samePoint(box.min, m_data.location));
    EXPECT_TRUE(samePoint(box.max, m_data.location));
    ASSERT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
    EXPECT_EQ(Q3Geometry_GetDecomposed(marker, view()), nullptr);
    TQ3BoundingBox ignored;
    EXPECT_EQ(Q3View_EndBoundingBox(view(), &ignored), kQ3ViewStatusDone);
}

} // namespace
