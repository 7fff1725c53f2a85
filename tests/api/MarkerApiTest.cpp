// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The thirteen Q3Marker_* calls and Q3Bitmap_Empty/GetImageSize against
// QD3DGeometry.h and QD3D.h: the TQ3MarkerData rules in their order, the
// bitmap copied (never shared with the caller), every per-field call and
// the bound (the location). The drawing is checked by the markers scene.

#include "GeometryTestSupport.h"
#include "MarkerTestSupport.h"
#include "OwningApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DView.h"

#include <cstdlib>
#include <cstring>
#include <functional>
#include <vector>

namespace {

using namespace q3test;

class MarkerApiTest : public MarkerApiTestBase {
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
    // The fixture's data with one change; each case stands alone.
    const auto refusedWith = [&](TQ3Error code, const std::function<void(TQ3MarkerData&)>& change) {
        TQ3MarkerData data = m_data;
        change(data);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Marker_New(&data), nullptr), code);
    };
    for (float bad : kNonFinite)
        refusedWith(kQ3ErrorInvalidData, [&](TQ3MarkerData& d) {
            d.location.z = bad;
            d.bitmap.width = 0;
        });
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Marker_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    refusedWith(kQ3ErrorNULLParameter, [](TQ3MarkerData& d) {
        d.bitmap.image = nullptr;
        d.location.x = kNaN;
    });
    refusedWith(kQ3ErrorInvalidData, [](TQ3MarkerData& d) { d.bitmap.width = 0; });
    refusedWith(kQ3ErrorInvalidData, [](TQ3MarkerData& d) { d.bitmap.height = 0; });
    refusedWith(kQ3ErrorInvalidData, [](TQ3MarkerData& d) { d.bitmap.width = 17; }); // needs three bytes a row
    refusedWith(kQ3ErrorInvalidData, [](TQ3MarkerData& d) { d.bitmap.bitOrder = static_cast<TQ3Endian>(2); });
    refusedWith(kQ3ErrorParameterOutOfRange, [](TQ3MarkerData& d) {
        d.bitmap.rowBytes = kQ3GeometryMaxArrayCount; // times 3 rows: never read
    });
    TQ3MarkerData data = m_data;
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
    TQ3Bitmap bad{m_bits.data(), 10, 3, 1, kQ3EndianBig};
    EXPECT_Q3_ERROR(Q3Marker_SetBitmap(marker, &bad), kQ3ErrorInvalidData);
    bad.image = nullptr;
    EXPECT_Q3_ERROR(Q3Marker_SetBitmap(marker, &bad), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Marker_SetBitmap(marker, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Marker_GetBitmap(marker, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Marker_EmptyData(nullptr), kQ3ErrorNULLParameter);
    for (TQ3Object wrong : notMarkers()) {
        EXPECT_Q3_ERROR(Q3Marker_GetData(wrong, &m_data), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3Marker_SetData(wrong, &m_data), kQ3ErrorInvalidObjectType);
    }
    TQ3MarkerData badData = m_data;
    badData.bitmap.height = 0;
    EXPECT_Q3_ERROR(Q3Marker_SetData(marker, &badData), kQ3ErrorInvalidData);
    EXPECT_EQ(Q3Shared_GetEditIndex(marker), edit);

    expectPlacementCalls(kMarkerPlacement, marker, m_data.location, -5, 4, notMarkers(), -2147483647L - 1);
    const unsigned char one = 0x01;
    const TQ3Bitmap single{const_cast<unsigned char*>(&one), 8, 1, 1, kQ3EndianLittle};
    ASSERT_EQ(Q3Marker_SetBitmap(marker, &single), kQ3Success);
    TQ3MarkerData out{};
    ASSERT_EQ(Q3Marker_GetData(marker, &out), kQ3Success);
    EXPECT_TRUE(samePoint(out.location, TQ3Point3D{-1, -2, -3}));
    EXPECT_EQ(out.xOffset, -2147483647L - 1);
    EXPECT_EQ(out.yOffset, 77);
    EXPECT_EQ(out.bitmap.width, 8u);
    EXPECT_EQ(out.bitmap.bitOrder, kQ3EndianLittle);
    EXPECT_EQ(out.bitmap.image[0], 0x01);
    Q3Marker_EmptyData(&out);
    EXPECT_GT(Q3Shared_GetEditIndex(marker), edit);

    ASSERT_EQ(Q3Marker_SetData(marker, &m_data), kQ3Success);
    long offset = 0;
    ASSERT_EQ(Q3Marker_GetXOffset(marker, &offset), kQ3Success);
    EXPECT_EQ(offset, -5);
}

TEST_F(MarkerApiTest, TheBoundIsTheLocationAndAMarkerIsItsOwnDecomposition)
{
    TQ3GeometryObject marker = own(Q3Marker_New(&m_data));
    const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) { Q3Geometry_Submit(marker, v); });
    EXPECT_TRUE(samePoint(box.min, m_data.location));
    EXPECT_TRUE(samePoint(box.max, m_data.location));
    EXPECT_EQ(decomposedIn(view(), marker), nullptr);
}

} // namespace
