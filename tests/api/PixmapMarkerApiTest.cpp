// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The thirteen Q3PixmapMarker_* calls against QD3DGeometry.h: the
// TQ3PixmapMarkerData rules in their order, the storage referenced (never
// copied) with Apple's reference counting, every per-field call, the bound
// (the position) and Duplicate. The drawing is checked by
// PixmapMarkerRenderTest.cpp.

#include "GeometryTestSupport.h"
#include "MarkerTestSupport.h"
#include "OwningApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DStorage.h"
#include "QD3DView.h"

#include <climits>
#include <functional>
#include <vector>

namespace {

using namespace q3test;

class PixmapMarkerApiTest : public MarkerApiTestBase {
protected:
    void SetUp() override
    {
        OwningApiTest::SetUp();
        // 3 x 2 pixels of ARGB32, 16 bytes a row (4 spare).
        m_bytes.assign(32, 0);
        for (unsigned i = 0; i < m_bytes.size(); ++i)
            m_bytes[i] = static_cast<unsigned char>(i + 1);
        m_storage = own(Q3MemoryStorage_New(m_bytes.data(), static_cast<unsigned long>(m_bytes.size())));
        m_data = TQ3PixmapMarkerData{{1, 2, 3},
                                     -5,
                                     4,
                                     {m_storage, 3, 2, 16, 32, kQ3PixelTypeARGB32, kQ3EndianBig, kQ3EndianLittle},
                                     nullptr};
    }
    std::vector<TQ3Object> notPixmapMarkers()
    {
        const TQ3PointData point{{0, 0, 0}, nullptr};
        return {own(Q3AttributeSet_New()), view(), own(Q3Point_New(&point)), m_storage};
    }
    TQ3StorageObject deadStorage()
    {
        TQ3StorageObject storage = Q3MemoryStorage_New(m_bytes.data(), 32);
        Q3Object_Dispose(storage);
        return storage;
    }
    std::vector<unsigned char> m_bytes;
    TQ3StorageObject m_storage = nullptr;
    TQ3PixmapMarkerData m_data{};
};

TEST_F(PixmapMarkerApiTest, NewReferencesTheStorageThatGetDataAndGetPixmapReturn)
{
    TQ3AttributeSet set = own(colorSet(1, 0, 0));
    m_data.pixmapMarkerAttributeSet = set;
    EXPECT_EQ(referenceCount(m_storage), 1u);
    TQ3GeometryObject marker = Q3PixmapMarker_New(&m_data);
    ASSERT_NE(marker, nullptr);
    EXPECT_EQ(Q3Geometry_GetType(marker), kQ3GeometryTypePixmapMarker);
    EXPECT_EQ(Q3Object_GetLeafType(marker), kQ3GeometryTypePixmapMarker);
    EXPECT_EQ(referenceCount(m_storage), 2u);
    EXPECT_EQ(referenceCount(set), 2u);

    TQ3PixmapMarkerData out{};
    ASSERT_EQ(Q3PixmapMarker_GetData(marker, &out), kQ3Success);
    EXPECT_TRUE(samePoint(out.position, m_data.position));
    EXPECT_EQ(out.xOffset, -5);
    EXPECT_EQ(out.yOffset, 4);
    EXPECT_EQ(out.pixmap.image, m_storage); // the same storage, not a copy
    EXPECT_EQ(out.pixmap.width, 3u);
    EXPECT_EQ(out.pixmap.height, 2u);
    EXPECT_EQ(out.pixmap.rowBytes, 16u);
    EXPECT_EQ(out.pixmap.pixelSize, 32u);
    EXPECT_EQ(out.pixmap.pixelType, kQ3PixelTypeARGB32);
    EXPECT_EQ(out.pixmap.bitOrder, kQ3EndianBig);
    EXPECT_EQ(out.pixmap.byteOrder, kQ3EndianLittle);
    EXPECT_EQ(out.pixmapMarkerAttributeSet, set);
    EXPECT_EQ(referenceCount(m_storage), 3u);
    EXPECT_EQ(referenceCount(set), 3u);
    ASSERT_EQ(Q3PixmapMarker_EmptyData(&out), kQ3Success);
    EXPECT_EQ(out.pixmap.image, nullptr);
    EXPECT_EQ(out.pixmapMarkerAttributeSet, nullptr);
    EXPECT_EQ(referenceCount(m_storage), 2u);
    EXPECT_EQ(referenceCount(set), 2u);
    EXPECT_EQ(Q3PixmapMarker_EmptyData(&out), kQ3Success);

    TQ3StoragePixmap pixmap{};
    ASSERT_EQ(Q3PixmapMarker_GetPixmap(marker, &pixmap), kQ3Success);
    EXPECT_EQ(pixmap.image, m_storage);
    EXPECT_EQ(pixmap.rowBytes, 16u);
    EXPECT_EQ(pixmap.byteOrder, kQ3EndianLittle);
    EXPECT_EQ(referenceCount(m_storage), 3u);
    Q3Object_Dispose(pixmap.image);
    EXPECT_EQ(referenceCount(m_storage), 2u);

    Q3Object_Dispose(marker);
    EXPECT_EQ(referenceCount(m_storage), 1u);
    EXPECT_EQ(referenceCount(set), 1u);
}

TEST_F(PixmapMarkerApiTest, TheRulesAreCheckedInTheirOrder)
{
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapMarker_New(nullptr), nullptr), kQ3ErrorNULLParameter);
    // The fixture's data with one change.
    const auto refusedWith = [&](TQ3Error code, const std::function<void(TQ3PixmapMarkerData&)>& change) {
        TQ3PixmapMarkerData data = m_data;
        change(data);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapMarker_New(&data), nullptr), code);
    };
    using Data = TQ3PixmapMarkerData;
    refusedWith(kQ3ErrorNULLParameter, [](Data& d) {
        d.pixmap.image = nullptr;
        d.position.x = kNaN;
    });
    for (float bad : kNonFinite)
        refusedWith(kQ3ErrorInvalidData, [&](Data& d) {
            d.position.y = bad;
            d.pixmap.pixelSize = 16; // a later rule with another code
        });
    for (int badType : {-1, 6, INT_MAX})
        refusedWith(kQ3ErrorInvalidData, [&](Data& d) {
            d.pixmap.pixelType = static_cast<TQ3PixelType>(badType);
            d.pixmap.pixelSize = 7;
        });
    refusedWith(kQ3ErrorInvalidData, [](Data& d) {
        d.pixmap.byteOrder = static_cast<TQ3Endian>(2);
        d.pixmap.pixelSize = 7;
    });
    refusedWith(kQ3ErrorInvalidData, [](Data& d) {
        d.pixmap.bitOrder = static_cast<TQ3Endian>(-1);
        d.pixmap.pixelSize = 7;
    });
    for (unsigned long size : {0UL, 8UL, 16UL, 24UL, 33UL})
        refusedWith(kQ3ErrorUnsupportedPixelDepth, [&](Data& d) {
            d.pixmap.pixelSize = size;
            d.pixmap.width = 0; // a later rule
        });
    refusedWith(kQ3ErrorInvalidData, [](Data& d) { d.pixmap.width = 0; });
    refusedWith(kQ3ErrorInvalidData, [](Data& d) { d.pixmap.height = 0; });
    refusedWith(kQ3ErrorInvalidData, [](Data& d) { d.pixmap.width = 5; });    // 20 bytes do not fit in 16
    refusedWith(kQ3ErrorInvalidData, [](Data& d) { d.pixmap.width = ~0UL; }); // would overflow width * 4
    refusedWith(kQ3ErrorParameterOutOfRange, [&](Data& d) {
        d.pixmap.rowBytes = kQ3GeometryMaxArrayCount; // times 2 rows; the storage is never asked
        d.pixmap.image = deadStorage();
    });
    refusedWith(kQ3ErrorParameterOutOfRange, [](Data& d) { d.pixmap.height = ~0UL; });
    TQ3PixmapMarkerData data = m_data;
    data.pixmap.image = deadStorage();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapMarker_New(&data), nullptr), kQ3ErrorInvalidObject);
    data.pixmap.image = strayHandle();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapMarker_New(&data), nullptr), kQ3ErrorInvalidObject);
    data.pixmap.image = own(Q3AttributeSet_New());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapMarker_New(&data), nullptr), kQ3ErrorInvalidObjectType);
    // 2 rows of 16 bytes need 32; the last row's padding counts too.
    data = m_data;
    data.pixmap.image = own(Q3MemoryStorage_New(m_bytes.data(), 31));
    data.pixmapMarkerAttributeSet = view(); // a later rule
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapMarker_New(&data), nullptr), kQ3ErrorInvalidData);
    data = m_data;
    data.pixmapMarkerAttributeSet = view();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapMarker_New(&data), nullptr), kQ3ErrorInvalidObjectType);
    data.pixmapMarkerAttributeSet = deadObject();
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapMarker_New(&data), nullptr), kQ3ErrorInvalidObject);
    EXPECT_EQ(referenceCount(m_storage), 1u); // every failure gave its reference back
    // Submit checks the view before the data.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapMarker_Submit(&data, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapMarker_Submit(&m_data, view()), kQ3Failure), kQ3ErrorViewNotStarted);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapMarker_Submit(nullptr, view()), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapMarker_Submit(&m_data, nullptr), kQ3Failure), kQ3ErrorNULLParameter);

    // Every pixel type of QD3D.h with its size, in both orders, and exactly
    // the row length it needs.
    const struct {
        TQ3PixelType type;
        unsigned long bits;
    } kinds[] = {{kQ3PixelTypeRGB32, 32}, {kQ3PixelTypeARGB32, 32},    {kQ3PixelTypeRGB16, 16},
                 {kQ3PixelTypeARGB16, 16}, {kQ3PixelTypeRGB16_565, 16}, {kQ3PixelTypeRGB24, 24}};
    for (const auto& kind : kinds)
        for (TQ3Endian order : {kQ3EndianBig, kQ3EndianLittle}) {
            data = m_data;
            data.pixmap.pixelType = kind.type;
            data.pixmap.pixelSize = kind.bits;
            data.pixmap.byteOrder = order;
            data.pixmap.bitOrder = order;
            data.pixmap.rowBytes = 3 * kind.bits / 8;
            EXPECT_NE(own(Q3PixmapMarker_New(&data)), nullptr) << kind.type;
            data.pixmap.rowBytes -= 1;
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3PixmapMarker_New(&data), nullptr), kQ3ErrorInvalidData);
        }
}

TEST_F(PixmapMarkerApiTest, PerFieldCallsReadWriteAndChangeNothingOnFailure)
{
    TQ3GeometryObject marker = own(Q3PixmapMarker_New(&m_data));
    const unsigned long edit = Q3Shared_GetEditIndex(marker);
    TQ3StoragePixmap bad = m_data.pixmap;
    bad.rowBytes = 11;
    EXPECT_Q3_ERROR(Q3PixmapMarker_SetPixmap(marker, &bad), kQ3ErrorInvalidData);
    bad = m_data.pixmap;
    bad.pixelSize = 24;
    EXPECT_Q3_ERROR(Q3PixmapMarker_SetPixmap(marker, &bad), kQ3ErrorUnsupportedPixelDepth);
    bad = m_data.pixmap;
    bad.height = 3; // 48 bytes, the storage holds 32
    EXPECT_Q3_ERROR(Q3PixmapMarker_SetPixmap(marker, &bad), kQ3ErrorInvalidData);
    bad = m_data.pixmap;
    bad.image = deadStorage();
    EXPECT_Q3_ERROR(Q3PixmapMarker_SetPixmap(marker, &bad), kQ3ErrorInvalidObject);
    bad.image = view();
    EXPECT_Q3_ERROR(Q3PixmapMarker_SetPixmap(marker, &bad), kQ3ErrorInvalidObjectType);
    bad.image = nullptr;
    EXPECT_Q3_ERROR(Q3PixmapMarker_SetPixmap(marker, &bad), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3PixmapMarker_SetPixmap(marker, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3PixmapMarker_GetPixmap(marker, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3PixmapMarker_GetData(marker, nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3PixmapMarker_SetData(marker, nullptr), kQ3ErrorNULLParameter);
    TQ3StoragePixmap pixmapOut{};
    for (TQ3Object wrong : notPixmapMarkers()) {
        EXPECT_Q3_ERROR(Q3PixmapMarker_GetPixmap(wrong, &pixmapOut), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3PixmapMarker_SetPixmap(wrong, &m_data.pixmap), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3PixmapMarker_GetData(wrong, &m_data), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(Q3PixmapMarker_SetData(wrong, &m_data), kQ3ErrorInvalidObjectType);
    }
    // A marker is not a pixmap marker, nor the other way round.
    const unsigned char bit = 0x80;
    const TQ3MarkerData markerData{{0, 0, 0}, 0, 0, {const_cast<unsigned char*>(&bit), 1, 1, 1, kQ3EndianBig},
                                   nullptr};
    TQ3GeometryObject plain = own(Q3Marker_New(&markerData));
    TQ3Point3D p{};
    EXPECT_Q3_ERROR(Q3PixmapMarker_GetPosition(plain, &p), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Marker_GetPosition(marker, &p), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3PixmapMarker_EmptyData(nullptr), kQ3ErrorNULLParameter);
    TQ3PixmapMarkerData badData = m_data;
    badData.pixmap.height = 0;
    EXPECT_Q3_ERROR(Q3PixmapMarker_SetData(marker, &badData), kQ3ErrorInvalidData);
    EXPECT_EQ(Q3Shared_GetEditIndex(marker), edit);
    EXPECT_EQ(referenceCount(m_storage), 2u);
    ASSERT_EQ(Q3PixmapMarker_GetPixmap(marker, &pixmapOut), kQ3Success);
    EXPECT_EQ(pixmapOut.height, 2u);
    Q3Object_Dispose(pixmapOut.image);

    expectPlacementCalls(kPixmapMarkerPlacement, marker, m_data.position, -5, 4, notPixmapMarkers(), LONG_MIN);
    const unsigned char rgb24[] = {10, 20, 30, 40, 50, 60};
    TQ3StorageObject other = own(Q3MemoryStorage_New(rgb24, 6));
    const TQ3StoragePixmap replacement{other, 2, 1, 6, 24, kQ3PixelTypeRGB24, kQ3EndianLittle, kQ3EndianBig};
    ASSERT_EQ(Q3PixmapMarker_SetPixmap(marker, &replacement), kQ3Success);
    EXPECT_EQ(referenceCount(m_storage), 1u); // the old storage was released
    EXPECT_EQ(referenceCount(other), 2u);
    TQ3PixmapMarkerData out{};
    ASSERT_EQ(Q3PixmapMarker_GetData(marker, &out), kQ3Success);
    EXPECT_TRUE(samePoint(out.position, TQ3Point3D{-1, -2, -3}));
    EXPECT_EQ(out.xOffset, LONG_MIN);
    EXPECT_EQ(out.yOffset, 77);
    EXPECT_EQ(out.pixmap.image, other);
    EXPECT_EQ(out.pixmap.width, 2u);
    EXPECT_EQ(out.pixmap.pixelType, kQ3PixelTypeRGB24);
    EXPECT_EQ(out.pixmap.bitOrder, kQ3EndianLittle);
    Q3PixmapMarker_EmptyData(&out);
    EXPECT_GT(Q3Shared_GetEditIndex(marker), edit);

    ASSERT_EQ(Q3PixmapMarker_SetData(marker, &m_data), kQ3Success);
    EXPECT_EQ(referenceCount(other), 1u);
    EXPECT_EQ(referenceCount(m_storage), 2u);
    long offset = 0;
    ASSERT_EQ(Q3PixmapMarker_GetXOffset(marker, &offset), kQ3Success);
    EXPECT_EQ(offset, -5);
}

TEST_F(PixmapMarkerApiTest, EmptyDataChecksEveryHandleBeforeReleasingAny)
{
    TQ3GeometryObject marker = own(Q3PixmapMarker_New(&m_data));
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    ASSERT_EQ(Q3Geometry_SetAttributeSet(marker, set), kQ3Success);
    TQ3PixmapMarkerData out{};
    ASSERT_EQ(Q3PixmapMarker_GetData(marker, &out), kQ3Success);
    EXPECT_EQ(referenceCount(set), 3u);
    const TQ3StorageObject storage = out.pixmap.image;
    out.pixmap.image = strayHandle();
    EXPECT_Q3_ERROR(Q3PixmapMarker_EmptyData(&out), kQ3ErrorInvalidObject);
    EXPECT_EQ(out.pixmapMarkerAttributeSet, set);
    EXPECT_EQ(referenceCount(set), 3u);
    out.pixmap.image = set;
    EXPECT_Q3_ERROR(Q3PixmapMarker_EmptyData(&out), kQ3ErrorInvalidObjectType);
    out.pixmap.image = storage;
    ASSERT_EQ(Q3PixmapMarker_EmptyData(&out), kQ3Success);
    EXPECT_EQ(referenceCount(set), 2u);
    EXPECT_EQ(referenceCount(m_storage), 2u);
}

TEST_F(PixmapMarkerApiTest, TheBoundIsThePositionAndAPixmapMarkerIsItsOwnDecomposition)
{
    TQ3GeometryObject marker = own(Q3PixmapMarker_New(&m_data));
    // Bounding does not read the pixels: a storage that shrank later is fine.
    ASSERT_EQ(Q3MemoryStorage_Set(m_storage, m_bytes.data(), 4), kQ3Success);
    const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(marker, v), kQ3Success); });
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_TRUE(samePoint(box.min, m_data.position));
    EXPECT_TRUE(samePoint(box.max, m_data.position));
    // Immediate mode checks the data, the storage's size included.
    const TQ3BoundingBox immediate = boundsOf(
        [&](TQ3ViewObject v) { EXPECT_Q3_ERROR(Q3PixmapMarker_Submit(&m_data, v), kQ3ErrorInvalidData); });
    EXPECT_EQ(immediate.isEmpty, kQ3True);
    EXPECT_EQ(decomposedIn(view(), marker), nullptr);
}

TEST_F(PixmapMarkerApiTest, DuplicateCopiesTheFieldsAndDuplicatesTheStorage)
{
    TQ3GeometryObject marker = own(Q3PixmapMarker_New(&m_data));
    TQ3GeometryObject copy = own(Q3Object_Duplicate(marker));
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(Q3Geometry_GetType(copy), kQ3GeometryTypePixmapMarker);
    TQ3PixmapMarkerData out{};
    ASSERT_EQ(Q3PixmapMarker_GetData(copy, &out), kQ3Success);
    EXPECT_TRUE(samePoint(out.position, m_data.position));
    EXPECT_EQ(out.xOffset, m_data.xOffset);
    EXPECT_EQ(out.pixmap.rowBytes, 16u);
    EXPECT_NE(out.pixmap.image, m_storage);
    EXPECT_EQ(Q3Storage_GetType(out.pixmap.image), kQ3StorageTypeMemory);
    unsigned char bytes[32] = {};
    unsigned long read = 0;
    ASSERT_EQ(Q3Storage_GetData(out.pixmap.image, 0, 32, bytes, &read), kQ3Success);
    EXPECT_EQ(read, 32u);
    EXPECT_EQ(bytes[0], 1);
    EXPECT_EQ(bytes[31], 32);
    Q3PixmapMarker_EmptyData(&out);
    EXPECT_EQ(referenceCount(m_storage), 2u);
}

} // namespace
